"""The OFB plugin's pipeline saved and restored as ParaView users do: a state file
(File > Save State / Load State) and a Python trace (Tools > Start Trace).

pvbatch TestOFBPluginState.py <OFB plugin> <output folder>

A sphere with a rotational field goes through OFB Sampler, OFB LIC, OFB Paint Strokes and
OFB Probe, and is shown twice in one view: the probe's output as Surface coloured by the
probed LIC, and the field as the OFB Surface representation with its own LIC, non-default
settings and a colour map. The picture and the settings are recorded; then

- the state is saved (.pvsm), the session reset and the state loaded: every OFB proxy's
  non-default settings and the picture must come back;
- the pipeline is built again while a Python trace records it (settings applied as the
  Properties panel applies them), the session reset and the trace run: the same
  settings and picture.

The pictures must equal the first one (mean |difference| below IMAGE_TOLERANCE of 255).
"""
import contextlib
import os
import sys

import numpy as np
from paraview import smtrace
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

IMAGE_TOLERANCE = 0.5
SIZE = 320

plugin, out = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what, flush=True)


@contextlib.contextmanager
def modified(proxy):
    """Sets properties of `proxy` as the Properties panel's Apply does: a trace (when one
    runs) records them."""
    item = smtrace.PropertiesModified(proxy) if smtrace.Trace.Output is not None else None
    yield proxy
    if item is not None:
        item.finalize()


def build():
    """The pipeline, its view and displays, with settings away from their defaults."""
    sphere = Sphere(registrationName="Ball", ThetaResolution=64, PhiResolution=32, Radius=0.5)
    field = Calculator(registrationName="Field", Input=sphere, ResultArrayName="Field",
                       Function="(-coordsY+0.3*coordsZ)*iHat+coordsX*jHat-0.3*coordsX*kHat")
    sampler = OFBSampler(registrationName="Sampler", Input=field, Resolution=80)
    with modified(sampler):
        sampler.Vectors = ["POINTS", "Field"]
    lic = OFBLIC(registrationName="LIC", Input=sampler, NumberOfSteps=12)
    stroke = PolyLineSource(registrationName="Stroke",
                            Points=[0.5, 0.0, 0.0, 0.0, 0.5, 0.0, -0.5, 0.0, 0.0])
    paint = OFBPaintStrokes(registrationName="Paint", Input=lic, Strokes=stroke)
    with modified(paint):
        paint.BrushRadius = 0.06
        paint.BrushColor = [0.1, 0.3, 1.0, 1.0]
    probe = OFBProbe(registrationName="Probe", Input=field, OFB=paint)

    view = CreateView("RenderView")
    view.ViewSize = [SIZE, SIZE]
    with modified(view):
        view.OrientationAxesVisibility = 0
        view.UseColorPaletteForBackground = 0
        view.Background = [0.0, 0.0, 0.0]

    probed = Show(probe, view)
    ColorBy(probed, ("POINTS", "LIC"))
    lut = GetColorTransferFunction("LIC")
    lut.ApplyPreset("Grayscale", True)
    lut.RescaleTransferFunction(0.0, 1.0)

    # The field beside it, as the OFB Surface representation with its own LIC.
    moved = Transform(registrationName="Moved", Input=field)
    with modified(moved):
        moved.Transform.Translate = [0.0, 1.1, 0.0]
    surface = Show(moved, view)
    surface.SetRepresentationType("OFB Surface")
    ColorBy(surface, ("POINTS", "Normals", "Z"))
    with modified(surface):
        surface.OFBResolution = 96
        surface.OFBLIC = 1
        surface.SelectOFBInputVectors = ["POINTS", "Field"]
        surface.OFBNumberOfSteps = 15
        surface.OFBLICIntensity = 0.6
        surface.OFBLookupMode = 1
    # The camera after the first render (which resets it), as a user places it.
    Render(view)
    view.CameraPosition = [1.4, -2.0, 0.9]
    view.CameraFocalPoint = [0.25, 0.0, 0.0]
    view.CameraViewUp = [0, 0, 1]
    view.CameraParallelScale = 0.9
    Render(view)
    return view


# The settings a state must restore: every proxy's, as recorded here.
SETTINGS = {
    "Sampler": ["Resolution", "Vectors"],
    "LIC": ["NumberOfSteps"],
    "Paint": ["BrushRadius", "BrushColor"],
}
DISPLAY_SETTINGS = ["Representation", "OFBResolution", "OFBLIC", "SelectOFBInputVectors",
                    "OFBNumberOfSteps", "OFBLICIntensity", "OFBLookupMode", "ColorArrayName"]


def settings(view):
    values = {}
    for name, properties in SETTINGS.items():
        proxy = FindSource(name)
        check(proxy is not None, "the pipeline has %s" % name)
        for p in properties:
            values["%s.%s" % (name, p)] = str(proxy.GetPropertyValue(p))
    display = GetDisplayProperties(FindSource("Moved"), view)
    for p in DISPLAY_SETTINGS:
        values["OFB Surface.%s" % p] = str(display.GetPropertyValue(p))
    return values


def picture(view, name):
    path = os.path.join(out, "state-%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=[SIZE, SIZE])
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)


def check_restored(what):
    """The settings and the picture of the active view against the first build's."""
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [SIZE, SIZE]
    restored = settings(view)
    for key, value in recorded.items():
        check(restored.get(key) == value, "%s: %s restored (%s)" % (what, key, value))
    compare(picture(view, what.replace(" ", "-")), reference, what)


def compare(image, reference, what):
    covered = (reference.sum(axis=1) > 0) | (image.sum(axis=1) > 0)
    difference = np.abs(image - reference).max(axis=1)[covered].mean()
    check(covered.mean() > 0.2 and difference < IMAGE_TOLERANCE,
          "%s: the picture again (mean |difference| %.3f on %.0f %% of the pixels)"
          % (what, difference, 100 * covered.mean()))


view = build()
reference = picture(view, "built")
recorded = settings(view)
print("settings:", recorded, flush=True)

# The OFB proxies and the representation through a state file.
state_path = os.path.join(out, "ofb-state.pvsm")
SaveState(state_path)
check(os.path.getsize(state_path) > 0, "state saved to %s" % state_path)
ResetSession()
check(FindSource("Sampler") is None, "the session is empty after ResetSession")
LoadState(state_path)
check_restored("state file")

# The same pipeline through a Python trace.
ResetSession()
smtrace.start_trace()
build()
trace = smtrace.stop_trace()
with open(os.path.join(out, "ofb-trace.py"), "w") as stream:
    stream.write(trace)
check("OFBSampler(" in trace and "OFBSurfaceRepresentation" not in trace and
      "'OFB Surface'" in trace, "the trace creates the OFB proxies and names the representation")
ResetSession()
exec(compile(trace, "ofb-trace.py", "exec"), {})
check_restored("Python trace")
print("all state and trace checks passed", flush=True)
