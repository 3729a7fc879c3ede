"""The OFB Surface representation from paraview.simple: the pipe and the bunny with LIC.

    pvbatch ofb_surface.py PLUGIN OUTPUT_DIR [--bunny MESH] [--size PIXELS]

PLUGIN is the plugin's OFB.so (build-pv/lib/paraview-5.11/plugins/OFB/OFB.so). Writes
into OUTPUT_DIR:
- pipe.png: the pipe with a bump of the LIC tests and its swirling flow ("Flow"),
  coloured by the flow's speed through a colour map, with the LIC mapped into the colour;
- bunny.png: the Stanford bunny (--bunny, default Testing/Data/stanford-bunny.obj from the
  project's root) coloured by its height, with the LIC of a rotation about a tilted axis
  blended into it;
- bunny-paint.png: the bunny by its paint (the solid colour), no LIC.
Without python3-paraview installed, put its unpacked files on PYTHONPATH (see
docs/paraview.md). Headless: prefix with  xvfb-run -a .
"""

import argparse
import os

from paraview.simple import (Calculator, ColorBy, CreateView, Elevation, GetColorTransferFunction,
                             LoadPlugin, OpenDataFile, ProgrammableSource, SaveScreenshot, Show)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("plugin", help="the plugin (OFB.so)")
parser.add_argument("output", help="folder of the images")
parser.add_argument("--bunny", default="Testing/Data/stanford-bunny.obj")
parser.add_argument("--size", type=int, default=600)
args = parser.parse_args()
os.makedirs(args.output, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

# The pipe of the LIC tests: radius 1, length 4 along z, a bump on +x at mid-length, a flow
# along the axis at speed 1 turning about it at 1.2 + 0.6 sin(1.5 z) radians per unit.
PIPE = """
import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
around, along = 256, 256
z = np.linspace(-2.0, 2.0, along + 1)[:, None]
theta = 2.0 * np.pi * np.arange(around)[None, :] / around
d_theta = np.remainder(theta + np.pi, 2.0 * np.pi) - np.pi
r = 1.0 + 0.35 * np.exp(-(z * z + d_theta * d_theta) / 0.25)
x = np.stack(np.broadcast_arrays(r * np.cos(theta), r * np.sin(theta), z), axis=-1)
omega = 1.2 + 0.6 * np.sin(1.5 * z)
v = np.stack(np.broadcast_arrays(-omega * x[..., 1], omega * x[..., 0], 1.0), axis=-1)
points = vtkPoints()
points.SetData(numpy_support.numpy_to_vtk(x.reshape(-1, 3), deep=True))
flow = numpy_support.numpy_to_vtk(v.reshape(-1, 3).astype(np.float32), deep=True)
flow.SetName("Flow")
j, i = np.meshgrid(np.arange(along), np.arange(around), indexing="ij")
a = j * around + i
b = j * around + (i + 1) % around
c, d = a + around, b + around
triangles = np.stack([np.stack([a, b, d], -1), np.stack([a, d, c], -1)], axis=2)
cells = np.hstack([np.full((triangles.size // 3, 1), 3), triangles.reshape(-1, 3)])
polys = vtkCellArray()
polys.SetCells(cells.shape[0], numpy_support.numpy_to_vtkIdTypeArray(
    cells.astype(np.int64).ravel(), deep=True))
output.SetPoints(points)
output.SetPolys(polys)
output.GetPointData().SetVectors(flow)
"""


def render_view(size):
    view = CreateView("RenderView")
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    return view


# 1. The pipe: speed through the colour map, the LIC mapped into it.
pipe = ProgrammableSource(OutputDataSetType="vtkPolyData", Script=PIPE)
speed = Calculator(Input=pipe, ResultArrayName="Speed", Function="mag(Flow)")
view = render_view(args.size)
display = Show(speed, view)
display.SetRepresentationType("OFB Surface")
ColorBy(display, ("POINTS", "Speed"))
display.RescaleTransferFunctionToDataRange(True, False)
GetColorTransferFunction("Speed").ApplyPreset("Viridis (matplotlib)", True)
display.OFBResolution = 1024
display.OFBLIC = 1
display.SelectOFBInputVectors = ["POINTS", "Flow"]
display.OFBLICColorMode = "Map"
view.CameraPosition = [7.0, 0.0, 5.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
SaveScreenshot(os.path.join(args.output, "pipe.png"), view, ImageResolution=[args.size] * 2)

# 2. The bunny: its height through the colour map, the LIC of a rotation blended into it.
bunny = OpenDataFile(args.bunny)
bunny.UpdatePipeline()
bounds = bunny.GetDataInformation().GetBounds()
centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
height = Elevation(Input=bunny, LowPoint=[centre[0], bounds[2], centre[2]],
                   HighPoint=[centre[0], bounds[3], centre[2]])
# The rotation about the axis (0.3, 1, 0.2) through the centre: axis x (p - centre).
px, py, pz = ("(coords%s-%.6g)" % (axis, c) for axis, c in zip("XYZ", centre))
rotation = Calculator(Input=height, ResultArrayName="Rotation",
                      Function="(%s*%s-0.2*%s)*iHat + (0.2*%s-0.3*%s)*jHat + (0.3*%s-%s*%s)*kHat"
                      % ("1", pz, py, px, pz, py, "1", px))
view = render_view(args.size)
display = Show(rotation, view)
display.SetRepresentationType("OFB Surface")
ColorBy(display, None)
display.DiffuseColor = [0.85, 0.55, 0.3]
view.CameraPosition = [centre[0], centre[1], centre[2] + 3.0 * (bounds[1] - bounds[0])]
view.CameraFocalPoint = centre
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
SaveScreenshot(os.path.join(args.output, "bunny-paint.png"), view, ImageResolution=[args.size] * 2)

ColorBy(display, ("POINTS", "Elevation"))
display.RescaleTransferFunctionToDataRange(True, False)
display.OFBLIC = 1
display.SelectOFBInputVectors = ["POINTS", "Rotation"]
display.OFBLICColorMode = "Blend"
display.OFBLICIntensity = 0.5
SaveScreenshot(os.path.join(args.output, "bunny.png"), view, ImageResolution=[args.size] * 2)
print("wrote pipe.png, bunny-paint.png and bunny.png in", args.output)
