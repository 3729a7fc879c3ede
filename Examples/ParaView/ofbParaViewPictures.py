"""The OFB plugin in paraview.simple: the pipe's surface LIC and the painted bunny.

    pvbatch ofbParaViewPictures.py --plugin <OFB.so> --data Testing/Data --output <folder>

Writes <folder>/ofb-paraview-pipe.png (a pipe with a bump and a swirling flow: OFB
Sampler -> OFB LIC -> OFB Probe, shown in grey by its LIC) and
<folder>/ofb-paraview-bunny.png (the Stanford bunny: OFB Sampler -> OFB Paint Strokes
with three coloured strokes -> OFB Probe, shown by its paint), each checked for what it
must show. The OFB Probe's output is coloured like any ParaView surface; where the OFB
Surface representation is available it is used instead (the OFB's own resolution rather
than the mesh's points).
"""
import argparse
import math
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import *
from vtkmodules.util import numpy_support

# The pipe of the Python examples (Examples/Python/ofb_pipe.py).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from ofb_pipe import pipe_with_bump  # noqa: E402


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", default="OFB", help="the plugin's file, or its name")
parser.add_argument("--data", default="Testing/Data", help="folder with stanford-bunny.obj")
parser.add_argument("--output", default=".", help="folder for the pictures")
parser.add_argument("--size", type=int, default=600, help="picture width and height")
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())


def source_of(data):
    """A ParaView source whose output is `data` (pvbatch: one process)."""
    producer = TrivialProducer()
    producer.GetClientSideObject().SetOutput(data)
    producer.UpdatePipeline()
    return producer


def show(probe, array, view, **coloring):
    """Shows the probe's surface: the OFB Surface representation where there is one,
    else the surface coloured by `array`."""
    display = Show(probe, view)
    if "OFB Surface" in display.GetProperty("Representation").Available:
        display.SetRepresentationType("OFB Surface")
    ColorBy(display, ("POINTS", array))
    for name, value in coloring.items():
        setattr(display, name, value)
    return display


def picture(view, path):
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[args.size, args.size])
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    rgb = numpy_support.vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return rgb[:, :3].astype(float)


os.makedirs(args.output, exist_ok=True)

# --- The pipe: surface LIC of its flow, in grey.
pipe = source_of(pipe_with_bump(384, 384))
sampler = OFBSampler(Input=pipe, Resolution=512)
sampler.Vectors = ["POINTS", "Flow"]
lic = OFBLIC(Input=sampler)
probe = OFBProbe(Input=pipe, OFB=lic)
view = CreateView("RenderView")
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.1, 0.1, 0.15]
display = show(probe, "LIC", view)
lut = GetColorTransferFunction("LIC")
lut.ApplyPreset("Grayscale", True)
lut.RescaleTransferFunction(0.0, 1.0)
display.SetScalarBarVisibility(view, False)
view.CameraPosition = [6.5, -5.0, 3.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraParallelScale = 2.3
rgb = picture(view, os.path.join(args.output, "ofb-paraview-pipe.png"))
surface = np.abs(rgb - np.array([0.1, 0.1, 0.15]) * 255).sum(axis=1) > 6
grey = rgb[surface].mean(axis=1)
print("pipe: %.2f of the picture is surface, grey std %.1f" % (surface.mean(), grey.std()))
assert surface.mean() > 0.2, "the pipe fills the picture"
assert grey.std() > 20, "the LIC shows streaks, not a flat grey"
Delete(display)

# --- The bunny: three strokes of paint.
bunny = OpenDataFile(os.path.join(args.data, "stanford-bunny.obj"))
bunny = ExtractSurface(Input=bunny)
bunny.UpdatePipeline()
bounds = bunny.GetDataInformation().GetBounds()
centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
size = max(bounds[2 * k + 1] - bounds[2 * k] for k in range(3))
bunny_sampler = OFBSampler(Input=bunny, Resolution=512)
painted = bunny_sampler
strokes = []
for color, height in (([0.9, 0.2, 0.1, 1.0], -0.15), ([0.1, 0.5, 0.9, 1.0], 0.0),
                      ([0.95, 0.8, 0.1, 1.0], 0.15)):
    # A ring around the bunny at this height; its points are moved onto the surface.
    ring = [coordinate for a in np.linspace(0.0, 2.0 * math.pi, 96)
            for coordinate in (centre[0] + 0.6 * size * math.cos(a),
                               centre[1] + height * size,
                               centre[2] + 0.6 * size * math.sin(a))]
    line = PolyLineSource(Points=ring)
    painted = OFBPaintStrokes(Input=painted, Strokes=line, BrushRadius=0.03 * size,
                              BrushColor=color, FollowSurface=1)
bunny_probe = OFBProbe(Input=bunny, OFB=painted)
view.CameraPosition = [centre[0] + 0.3 * size, centre[1] + 0.2 * size, centre[2] + 2.2 * size]
view.CameraFocalPoint = centre
view.CameraViewUp = [0.0, 1.0, 0.0]
display = show(bunny_probe, "Colors", view, MapScalars=0)
rgb = picture(view, os.path.join(args.output, "ofb-paraview-bunny.png"))
red = (rgb[:, 0] > 150) & (rgb[:, 1] < 100) & (rgb[:, 2] < 90)
blue = (rgb[:, 2] > 150) & (rgb[:, 0] < 90)
print("bunny: %.3f red, %.3f blue pixels" % (red.mean(), blue.mean()))
assert red.mean() > 0.002 and blue.mean() > 0.002, "the strokes show on the bunny"
print("wrote ofb-paraview-pipe.png and ofb-paraview-bunny.png in", args.output)
