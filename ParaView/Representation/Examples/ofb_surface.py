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

# The pipe of the LIC tests (Examples/Python/ofb_pipe.py), made where the source runs.
PIPE = """
import sys
sys.path.insert(0, %r)
from ofb_pipe import pipe_with_bump
output.ShallowCopy(pipe_with_bump(256, 256))
""" % os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples",
                   "Python")


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
