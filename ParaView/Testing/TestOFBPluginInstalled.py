"""The OFB plugin from an unpacked package: it loads and samples a sphere.

pvbatch TestOFBPluginInstalled.py <OFB.so of the unpacked package>
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Sphere

LoadPlugin(sys.argv[1], ns=globals())
sphere = Sphere()
sampler = OFBSampler(Input=sphere, Resolution=64)
probe = OFBProbe(Input=sphere, OFB=sampler)
mesh = servermanager.Fetch(probe)
colors = mesh.GetPointData().GetArray("Colors")
assert sampler.GetDataInformation().GetNumberOfPoints() > 1000, "no samples"
assert colors is not None and colors.GetNumberOfTuples() == mesh.GetNumberOfPoints(), "no colours"
print("the installed OFB plugin works:", sampler.GetDataInformation().GetNumberOfPoints(),
      "samples")
