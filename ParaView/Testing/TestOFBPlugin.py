"""The OFB plugin in ParaView: every filter and the writer through paraview.simple.

pvbatch TestOFBPlugin.py <OFB plugin> <output folder>

A sphere with a tangent (rotational) vector field is sampled, its LIC computed, strokes
painted, particles animated with the animation scene, colours probed back onto the mesh
and the result saved as a textured OBJ and glTF. Each step asserts on its result.
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy

import ofbParaViewTesting

plugin, out = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())


say, check = ofbParaViewTesting.reporter()


def point_array(proxy, name, port=0):
    data = servermanager.Fetch(proxy, idx=port)
    array = data.GetPointData().GetArray(name)
    check(array is not None, "%s has the point array %s" % (proxy.GetXMLLabel(), name))
    return vtk_to_numpy(array)


# A sphere (radius 0.5) with the field of a rotation about z: tangent everywhere but at
# the poles.
sphere = Sphere(ThetaResolution=96, PhiResolution=48, Radius=0.5)
field = Calculator(Input=sphere, ResultArrayName="Field", Function="-coordsY*iHat+coordsX*jHat")

# --- OFB Sampler: the OFB's samples are its points; the field is its active vectors.
sampler = OFBSampler(Input=field, Resolution=96)
sampler.Vectors = ["POINTS", "Field"]
sampler.UpdatePipeline()
info = sampler.GetDataInformation()
samples = info.GetNumberOfPoints()
check(samples > 10000, "OFB Sampler: %d samples at resolution 96" % samples)
arrays = sampler.PointData.keys()
check("Colors" in arrays and "Normals" in arrays and "Field" in arrays,
      "OFB Sampler: sample arrays %s" % arrays)
sampler.Resolution = 48
sampler.UpdatePipeline()
coarse = sampler.GetDataInformation().GetNumberOfPoints()
check(coarse < samples / 3, "OFB Sampler: resolution 48 gives %d samples, fewer" % coarse)
sampler.Resolution = 96
sampler.Vectors = ["POINTS", "None"]
sampler.UpdatePipeline()
check(sampler.GetDataInformation().GetNumberOfPoints() == samples,
      "OFB Sampler: no vector field chosen still samples")
sampler.Vectors = ["POINTS", "Field"]

# --- OFB Probe: the sample arrays back on the mesh's points.
probe = OFBProbe(Input=sphere, OFB=sampler)
colors = point_array(probe, "Colors")
check(colors.shape == (sphere.GetDataInformation().GetNumberOfPoints(), 4),
      "OFB Probe: RGBA at every mesh point")
check(np.all(colors[:, :3] == 255), "OFB Probe: the unpainted surface is white")
valid = point_array(probe, "vtkValidPointMask")
check(valid.mean() > 0.99, "OFB Probe: %.3f of the points found a sample" % valid.mean())

# --- OFB LIC: "LIC" and "LICMask" sample arrays; streaks, not noise.
lic = OFBLIC(Input=sampler, NumberOfSteps=15)
lic.UpdatePipeline()
check("LIC" in lic.PointData.keys() and "LICMask" in lic.PointData.keys(),
      "OFB LIC: LIC and LICMask sample arrays")
lic_range = lic.PointData["LIC"].GetRange()
check(0.0 <= lic_range[0] < lic_range[1] <= 1.0, "OFB LIC: LIC in [0, 1]: %s" % (lic_range,))
licprobe = OFBProbe(Input=sphere, OFB=lic)
licvalues = point_array(licprobe, "LIC")
check(licvalues.std() > 0.02, "OFB LIC: the probed LIC varies (std %.3f)" % licvalues.std())
lic.NumberOfSteps = 0
lic.UpdatePipeline()
plain = point_array(licprobe, "LIC")
check(not np.allclose(plain, licvalues), "OFB LIC: NumberOfSteps changes the result")
lic.NumberOfSteps = 15

# --- OFB Paint Strokes: a red polyline around the equator paints a band.
equator = PolyLineSource(Points=[0.5 * c for a in np.linspace(0, 2 * np.pi, 64)
                                 for c in (np.cos(a), np.sin(a), 0.0)])
paint = OFBPaintStrokes(Input=sampler, Strokes=equator)
paint.BrushRadius = 0.08
paint.BrushColor = [1.0, 0.0, 0.0, 1.0]
paintprobe = OFBProbe(Input=sphere, OFB=paint)
painted = point_array(paintprobe, "Colors")
points = vtk_to_numpy(servermanager.Fetch(paintprobe).GetPoints().GetData())
red = (painted[:, 0] > 200) & (painted[:, 1] < 60) & (painted[:, 2] < 60)
near = np.abs(points[:, 2]) < 0.03
far = np.abs(points[:, 2]) > 0.15
check(red[near].mean() > 0.9, "OFB Paint Strokes: %.2f of the points at the equator red"
      % red[near].mean())
check(not red[far].any(), "OFB Paint Strokes: no red away from the stroke")
check(np.all(point_array(probe, "Colors")[:, :3] == 255),
      "OFB Paint Strokes: its input OFB stays unpainted")

# --- OFB Particles: time-aware; the animation scene steps them.
particles = OFBParticles(Input=field, OFB=sampler, NumberOfParticles=40, FootprintRadius=2.0,
                         NumberOfTimeSteps=30)
particles.Vectors = ["POINTS", "Field"]
particles.UpdatePipelineInformation()
steps = list(particles.TimestepValues)
check(steps == [float(i) for i in range(30)], "OFB Particles: time steps 0..29")
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
check(scene.EndTime == 29.0, "OFB Particles: the animation scene ends at step 29")
scene.AnimationTime = 10.0
particles.UpdatePipeline(10.0)
age = point_array(particles, "Age", port=1)
check(len(age) == 40, "OFB Particles: 40 particles")
check(age.max() == 10, "OFB Particles: at time 10 the particles are 10 steps old")
scene.GoToNext()
check(GetTimeKeeper().Time == 11.0, "OFB Particles: next frame is time 11")
particles.UpdatePipeline(GetTimeKeeper().Time)
check(point_array(particles, "Age", port=1).max() == 11, "OFB Particles: one step more")
trails = servermanager.Fetch(particles, idx=2)
check(trails.GetNumberOfLines() == 40, "OFB Particles: a trail per particle")
footprints = OFBProbe(Input=sphere, OFB=OutputPort(particles, 0))
foot = point_array(footprints, "Colors")
check((foot[:, 1] < 128).any(), "OFB Particles: the footprints painted the OFB red")

# --- The writer (File > Save Data): a textured OBJ and a glTF of the painted sphere.
obj = os.path.join(out, "ofb-plugin-sphere.obj")
gltf = os.path.join(out, "ofb-plugin-sphere.gltf")
for path in (obj, gltf, obj[:-4] + ".mtl", obj[:-4] + ".png"):
    if os.path.exists(path):
        os.remove(path)
# .obj has ParaView's own writer too: the OFB writer is chosen by name (in the GUI: the
# file type "OFB textured mesh").
writer = servermanager.writers.OFBTexturedMeshWriter(Input=paintprobe, FileName=obj,
                                                     TextureSize=256)
writer.UpdatePipeline()
for path in (obj, obj[:-4] + ".mtl", obj[:-4] + ".png"):
    check(os.path.getsize(path) > 0, "writer: %s written" % os.path.basename(path))
mtl = open(obj[:-4] + ".mtl").read()
check("map_Kd ofb-plugin-sphere.png" in mtl, "writer: the material names the texture")
faces = sum(1 for line in open(obj) if line.startswith("f "))
check(faces == sphere.GetDataInformation().GetNumberOfCells(), "writer: %d faces" % faces)
check(not [n for n in os.listdir(out) if ".tmp-" in n], "writer: no staging left")
from vtkmodules.vtkIOImage import vtkPNGReader
texture = vtkPNGReader()
texture.SetFileName(obj[:-4] + ".png")
texture.Update()
texels = vtk_to_numpy(texture.GetOutput().GetPointData().GetScalars())
check(((texels[:, 0] > 200) & (texels[:, 1] < 60)).any(), "writer: red texels in the texture")
# The folder a killed write left (its process is gone) is removed by the next write.
stale = os.path.join(out, ".ofb-plugin-sphere.gltf.tmp-999999999-0")
os.makedirs(stale, exist_ok=True)
open(os.path.join(stale, "ofb-plugin-sphere.gltf"), "w").write("{")
SaveData(gltf, proxy=paintprobe, TextureSize=256)  # the only .gltf writer
check(not os.path.exists(stale), "writer: a killed write's staging folder removed")
text = open(gltf).read()
check('"mimeType":"image/png"' in text and ";base64," in text,
      "writer: the glTF embeds its texture")
# Bad input: a writer without an OFB writes nothing.
plain_mesh = os.path.join(out, "ofb-plugin-no-ofb.obj")
if os.path.exists(plain_mesh):
    os.remove(plain_mesh)
bad = servermanager.writers.OFBTexturedMeshWriter(Input=sphere, FileName=plain_mesh)
bad.UpdatePipeline()
check(not os.path.exists(plain_mesh), "writer: a mesh without an OFB writes no file")

# --- The OFB file (File > Save Data, File > Open): the painted OFB written and read back.
ofb_path = os.path.join(out, "ofb-plugin-painted.ofb")
if os.path.exists(ofb_path):
    os.remove(ofb_path)
SaveData(ofb_path, proxy=paint)
check(os.path.isfile(ofb_path) and os.path.getsize(ofb_path) > 96, "OFB file: written")
reread = OpenDataFile(ofb_path)
check(reread is not None and reread.GetXMLName() == "OFBReader",
      "OFB file: File > Open reads it with OFB Reader")
reread.UpdatePipeline()
samples_written = paint.GetDataInformation().GetNumberOfPoints()
check(reread.GetDataInformation().GetNumberOfPoints() == samples_written,
      "OFB file: %d samples read back" % samples_written)
check(set(paint.PointData.keys()) <= set(reread.PointData.keys()),
      "OFB file: every sample array read back: %s" % sorted(reread.PointData.keys()))
reprobe = OFBProbe(Input=sphere, OFB=reread)
check(np.array_equal(point_array(reprobe, "Colors"), painted),
      "OFB file: the file's OFB probes to the same paint")
# Bad input: a mesh is not an OFB (nothing written); a truncated file gives an empty OFB.
not_ofb = os.path.join(out, "ofb-plugin-mesh.ofb")
if os.path.exists(not_ofb):
    os.remove(not_ofb)
SaveData(not_ofb, proxy=sphere)
check(not os.path.exists(not_ofb), "OFB file: a mesh writes no .ofb file")
truncated = os.path.join(out, "ofb-plugin-truncated.ofb")
with open(ofb_path, "rb") as source, open(truncated, "wb") as target:
    target.write(source.read()[:-20])
broken = OFBReader(FileName=truncated)
broken.UpdatePipeline()
check(broken.GetDataInformation().GetNumberOfPoints() == 0,
      "OFB file: a truncated file reads as an empty OFB")

# --- What ParaView shows: the probed surface, coloured by the LIC.
view = CreateView("RenderView")
view.ViewSize = [400, 400]
display = Show(licprobe, view)
ColorBy(display, ("POINTS", "LIC"))
Render(view)
SaveScreenshot(os.path.join(out, "ofb-plugin-lic.png"), view)
check(os.path.getsize(os.path.join(out, "ofb-plugin-lic.png")) > 0, "render: screenshot")
print("all OFB plugin checks passed")
