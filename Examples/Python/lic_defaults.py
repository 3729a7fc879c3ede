#!/usr/bin/env python3
"""Surface LIC with the default settings: a pipe with a bump and a swirling flow, seen close up
or whole, and the contrast of what is shown.

    pipe (made here) -> vtkOFBSampler -> vtkOFBLIC -> vtkOFBPolyDataMapper -> PNG

Every setting is the class default unless given on the command line, so that the same
command reproduces a picture exactly on a given build. Settings are passed by name, as
the classes spell them (the value goes to Set<Name>):
    --lic EnhanceContrast=1 --lic LowLICContrastEnhancementFactor=0.3    (vtkOFBLIC)
    --coloring LICIntensity=1                                              (vtkOFBColoring)
    --mapper LookupMode=3                                                  (vtkOFBPolyDataMapper)
    --sampler Resolution=512                                               (vtkOFBSampler)
The mapper shows the "LIC" array as the intensity of the surface's colour (the only
change from the colouring defaults: IntensityModulation on; the colour is the sampler's
default paint, white, so the picture is grey).

It prints the contrast of the LIC array (unmasked samples) and of the grey shown (pixels
that are not background): the 1st and 99th percentiles and the standard deviation, in
[0, 1].

Run (from a build tree):
    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 \\
        Examples/Python/lic_defaults.py pipe-close.png --view close
Options: --view close|far, --size (pixels), --around/--along (the pipe's quads), the
settings above, --check (exit with an error unless both the LIC and the grey shown span
at least 0.7 between their 1st and 99th percentiles and have a standard deviation of at
least 0.15; the ctest uses it).
"""

import argparse
import math
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations)

import vtkofb
from ofb_example_view import save_png
from ofb_pipe import pipe_with_bump

BACKGROUND = (0.1, 0.1, 0.15)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("png", help="image to write")
parser.add_argument("--view", choices=["close", "far"], default="far",
                    help="close: the bump, about 100 OFB cells across the picture; "
                         "far: the whole pipe")
parser.add_argument("--size", type=int, default=600, help="image width and height (pixels)")
parser.add_argument("--around", type=int, default=256, help="quads around the pipe")
parser.add_argument("--along", type=int, default=256, help="quads along the pipe")
for name, cls in [("sampler", "vtkOFBSampler"), ("lic", "vtkOFBLIC"),
                  ("coloring", "vtkOFBColoring"), ("mapper", "vtkOFBPolyDataMapper")]:
    parser.add_argument(f"--{name}", action="append", default=[], metavar="NAME=VALUE",
                        help=f"a setting of {cls} (Set<NAME>(VALUE)); repeatable")
parser.add_argument("--check", action="store_true")
args = parser.parse_args()


def make_pipe_with_bump(around, along):
    """The pipe of the LIC tests (ofb_pipe.py) tilted 30 degrees about x and 20 about y."""
    pipe = pipe_with_bump(around, along)
    tilt = vtkTransform()
    tilt.RotateY(20.0)
    tilt.RotateX(30.0)
    tilted = vtkTransformPolyDataFilter()
    tilted.SetInputData(pipe)
    tilted.SetTransform(tilt)  # rotates the vectors too
    tilted.Update()
    return tilted.GetOutput(), tilt


def parse_value(text):
    """An int, a float, or else the text itself."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def apply_settings(obj, settings):
    """obj.Set<NAME>(VALUE) for each NAME=VALUE; exits on an unknown name."""
    for setting in settings:
        name, _, value = setting.partition("=")
        setter = getattr(obj, "Set" + name, None)
        if setter is None or not value:
            sys.exit(f"{obj.GetClassName()} has no setting {name!r} (NAME=VALUE)")
        setter(parse_value(value))


def contrast(values):
    """1st and 99th percentiles and standard deviation of an array of values in [0, 1]."""
    p1, p99 = np.percentile(values, [1.0, 99.0])
    return p1, p99, float(np.std(values))


# 1. The pipe and its flow.
pipe, tilt = make_pipe_with_bump(args.around, args.along)

# 2. The OFB and the LIC, with the class defaults and the settings given.
sampler = vtkofb.vtkOFBSampler()
sampler.SetInputData(pipe)
apply_settings(sampler, args.sampler)
lic = vtkofb.vtkOFBLIC()
lic.SetInputConnection(sampler.GetOutputPort())
apply_settings(lic, args.lic)
lic.Update()
output = lic.GetOutput()
if output.GetNumberOfSamples() == 0:
    sys.exit("the LIC failed (see the error above)")
print(f"{output.GetNumberOfSamples()} samples, LIC in {lic.GetLastExecutionTime():.0f} ms")

# 3. The mapper shows the LIC as the intensity of the paint (white).
mapper = vtkofb.vtkOFBPolyDataMapper()
mapper.SetInputData(pipe)
mapper.SetOFBConnection(lic.GetOutputPort())
coloring = mapper.GetColoring()
coloring.SetIntensityArrayName("LIC")
coloring.IntensityModulationOn()
apply_settings(coloring, args.coloring)
apply_settings(mapper, args.mapper)
actor = vtkActor()
actor.SetMapper(mapper)

# 4. The view: the bump from outside, about 0.45 units across (close), or the whole pipe
#    from the bump's side (far).
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(*BACKGROUND)
window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetMultiSamples(0)
window.SetSize(args.size, args.size)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
bump = tilt.TransformPoint(1.35, 0.0, 0.0)
outward = tilt.TransformVector(0.8, 0.0, 0.6)
axis = tilt.TransformVector(0.0, 0.0, 1.0)
if args.view == "close":
    focus = bump
    distance = 0.45 / (2.0 * math.tan(math.radians(15.0)))
else:
    focus = (0.0, 0.0, 0.0)
    distance = 9.0
camera.SetFocalPoint(*focus)
camera.SetPosition(*[f + distance * o / np.linalg.norm(outward) for f, o in zip(focus, outward)])
camera.SetViewUp(*axis)
renderer.ResetCameraClippingRange()
window.Render()
image = save_png(window, args.png)

# 5. The contrast of the LIC array and of the grey shown.
values = numpy_support.vtk_to_numpy(output.GetSampleData().GetArray("LIC"))
masked = numpy_support.vtk_to_numpy(output.GetSampleData().GetArray("LICMask"))
lic_contrast = contrast(values[masked == 0])
background = np.round(np.array(BACKGROUND) * 255.0)
surface = np.any(np.abs(image.astype(float) - background) > 2.5, axis=1)
grey = image[surface].astype(float).mean(axis=1) / 255.0
shown_contrast = contrast(grey)
for what, (p1, p99, std) in [("LIC array", lic_contrast), ("grey shown", shown_contrast)]:
    print(f"{what}: 1st-99th percentile {p1:.3f}-{p99:.3f} (span {p99 - p1:.3f}), std {std:.3f}")
print(f"surface on {100.0 * surface.mean():.0f} % of the picture")
if args.check:
    good = all(p99 - p1 >= 0.7 and std >= 0.15 for p1, p99, std in (lic_contrast, shown_contrast))
    if not (good and surface.mean() > 0.2 and mapper.GetLastRenderUsedOFB()):
        sys.exit("check failed: the LIC shown has less than full contrast")
    print("check passed")
