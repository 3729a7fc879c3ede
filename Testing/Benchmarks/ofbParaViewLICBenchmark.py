"""ofbParaViewLICBenchmark: the OFB Surface representation with LIC against ParaView's
own Surface LIC representation, on the same surface and field, in one pvbatch run.

    pvbatch --force-offscreen-rendering ofbParaViewLICBenchmark.py PLUGIN [options]
    mpirun -np 2 pvbatch --force-offscreen-rendering ofbParaViewLICBenchmark.py PLUGIN ...

PLUGIN is the plugin's OFB.so. Options:
  --meshes LIST       pipe,bunny (default both)
  --bunny PATH        the bunny (default Testing/Data/stanford-bunny.obj, from the
                      project's root)
  --pipe-cells N      the pipe's quads around and along (default 256)
  --size PIXELS       the view's width and height (default 400)
  --frames N          orbit frames, 360/N degrees apart (default 12)
  --pan PIXELS        the pan of the stability measure (default 40)
  --ofb-resolution N  the OFB Surface's OFB Resolution (default 1024)
  --ofb-lookup MODE   the OFB Surface's OFB Lookup Mode (default Automatic: Smooth
                      for a LIC)
  --images DIR        also write the pan pairs as PNGs there
  --min-ofb-pan R     exit with an error when the OFB's pan correlation is under R
                      (default: no check; the ctest smoke run uses it)

For each mesh and representation, in a view of its own (created and rendered empty
first, so the OpenGL context exists before the clock starts):
- first image: seconds from Show (the source already updated) to the end of the first
  Render, the representation's LIC included;
- orbit: the median seconds of a Render after the camera's azimuth turns by 360/N
  degrees, over N frames (perspective projection);
- pan stability: parallel projection; an image, the camera and its focal point moved
  along the view plane's horizontal by PIXELS pixels' worth of world length, a second
  image; the second shifted back by PIXELS in screen space, so that both show the same
  surface point at each pixel (exact for a parallel projection), the Pearson
  correlation of the high-passed grey levels (grey minus a 9 x 9 box blur applied
  twice) over the pixels inside the surface in both images (the background is a key
  colour, the mask eroded by 10 pixels from the silhouette). 1 is a LIC pattern that
  sticks to the surface.
Each is printed for both representations and as the ratio OFB / ParaView; a Markdown
table ends the output. Both show the LIC alone (white surface, LIC intensity 1, Blend)
with their default LIC settings. Every Render ends with the render window's
WaitForCompletion, so the GPU's work is inside the measured time.

Under MPI the sources are made on rank 0 and spread over the ranks by
RedistributeDataSet; ParaView composites the images (IceT). The script runs on rank 0;
nothing in it depends on the number of ranks.
Not a test: run it by hand (docs/benchmarks.md); ctest runs it at tiny sizes
(OFB.ParaView.LICBenchmark) with --min-ofb-pan.
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

import numpy as np
from paraview import servermanager
from paraview.simple import (CreateView, Delete, Hide, LoadPlugin,
                             ProgrammableSource, RedistributeDataSet, Render, SaveScreenshot,
                             Show)

# One connection to the X display (under xvfb-run) for the whole run, so that the server
# does not reset between two views' windows (the plugin tests' support module).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir,
                                os.pardir, "ParaView", "Testing"))
import ofbParaViewTesting  # noqa: E402

ofbParaViewTesting.keep_display_open()

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("plugin", help="the plugin (OFB.so)")
parser.add_argument("--meshes", default="pipe,bunny")
parser.add_argument("--bunny", default="Testing/Data/stanford-bunny.obj")
parser.add_argument("--pipe-cells", type=int, default=256)
parser.add_argument("--size", type=int, default=400)
parser.add_argument("--frames", type=int, default=12)
parser.add_argument("--pan", type=int, default=40)
parser.add_argument("--ofb-resolution", type=int, default=1024)
parser.add_argument("--ofb-lookup", default="Automatic")
parser.add_argument("--images", default=None)
parser.add_argument("--min-ofb-pan", type=float, default=None)
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False)
RANKS = servermanager.ActiveConnection.GetNumberOfDataPartitions()
KEY = np.array([255, 0, 255])  # the background: a colour a grey LIC never has

# Made on piece 0 only, so that RedistributeDataSet spreads one surface over the ranks.
PIECE_ZERO = """
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
piece = self.GetOutputInformation(0).Get(sddp.UPDATE_PIECE_NUMBER())
"""

# The pipe of the LIC tests (Examples/Python/ofb_pipe.py), its field named "Field".
PIPE = PIECE_ZERO + """
import sys
sys.path.insert(0, %r)
from ofb_pipe import pipe_with_bump
if not piece:
    output.ShallowCopy(pipe_with_bump(%%d, %%d, "Field"))
""" % os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples", "Python")

# The bunny with a rotation about the axis (0.3, 1, 0.2) through its bounds' centre c:
# axis x (p - c).
BUNNY = PIECE_ZERO + """
import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkIOGeometry import vtkOBJReader
if not piece:
    reader = vtkOBJReader()
    reader.SetFileName(%r)
    reader.Update()
    mesh = reader.GetOutput()
    p = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    centre = 0.5 * (p.min(axis=0) + p.max(axis=0))
    v = np.cross(np.array([0.3, 1.0, 0.2]), p - centre).astype(np.float32)
    rotation = numpy_support.numpy_to_vtk(v, deep=True)
    rotation.SetName("Field")
    mesh.GetPointData().SetVectors(rotation)
    output.ShallowCopy(mesh)
"""


def surface(name):
    """The mesh with its vector field "Field", and the camera that frames it."""
    if name == "pipe":
        source = ProgrammableSource(OutputDataSetType="vtkPolyData",
                                    Script=PIPE % (args.pipe_cells, args.pipe_cells))
    else:
        source = ProgrammableSource(OutputDataSetType="vtkPolyData",
                                    Script=BUNNY % os.path.abspath(args.bunny))
    if RANKS > 1:
        source = RedistributeDataSet(Input=source)
    source.UpdatePipeline()
    bounds = source.GetDataInformation().GetBounds()
    centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
    if name == "pipe":
        camera = ([7.0, 0.0, 5.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0])
    else:
        camera = ([centre[0], centre[1], centre[2] + 3.0 * (bounds[1] - bounds[0])], centre,
                  [0.0, 1.0, 0.0])
    if "Field" not in source.PointData.keys():
        raise RuntimeError("the %s has no vector field" % name)
    return source, camera, source.GetDataInformation().GetNumberOfCells()


def render(view):
    Render(view)
    view.GetRenderWindow().WaitForCompletion()


def configure(display, kind):
    """The LIC alone on a white surface, each representation's default LIC settings."""
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [1.0, 1.0, 1.0]
    if kind == "paraview":
        display.SetRepresentationType("Surface LIC")
        display.SelectInputVectors = ["POINTS", "Field"]
        display.ColorMode = "Blend"
        display.LICIntensity = 1.0
    else:
        display.SetRepresentationType("OFB Surface")
        display.OFBResolution = args.ofb_resolution
        display.OFBLIC = 1
        display.SelectOFBInputVectors = ["POINTS", "Field"]
        display.OFBLICColorMode = "Blend"
        display.OFBLICIntensity = 1.0
        display.OFBLookupMode = args.ofb_lookup


def set_camera(view, camera):
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = camera
    view.ResetCamera()


def capture(view, path):
    SaveScreenshot(path, view, ImageResolution=[args.size, args.size])
    return ofbParaViewTesting.png_pixels(path)


def box_blur(image, radius):
    """The mean over a (2 radius + 1)^2 box, edges clamped."""
    padded = np.pad(image, radius, mode="edge")
    total = np.cumsum(np.cumsum(padded, axis=0), axis=1)
    total = np.pad(total, ((1, 0), (1, 0)))
    n = 2 * radius + 1
    window = total[n:, n:] - total[:-n, n:] - total[n:, :-n] + total[:-n, :-n]
    return window / (n * n)


def erode(mask, radius):
    return box_blur(mask.astype(np.float64), radius) > 1.0 - 1e-9


def high_pass(rgb):
    grey = rgb.mean(axis=2)
    return grey - box_blur(box_blur(grey, 4), 4)


def pan_correlation(view, camera, kind, name, folder):
    """The correlation of the high-passed images at the same surface points across a pan."""
    view.CameraParallelProjection = 1
    set_camera(view, camera)
    render(view)
    first = capture(view, os.path.join(folder, "%s-%s-0.png" % (name, kind)))
    cam = view.GetActiveCamera()
    position, focal = np.array(cam.GetPosition()), np.array(cam.GetFocalPoint())
    right = np.cross(np.array(cam.GetDirectionOfProjection()), np.array(cam.GetViewUp()))
    right /= np.linalg.norm(right)
    step = right * args.pan * 2.0 * cam.GetParallelScale() / args.size
    cam.SetPosition(*(position + step))
    cam.SetFocalPoint(*(focal + step))
    render(view)
    second = capture(view, os.path.join(folder, "%s-%s-1.png" % (name, kind)))
    view.CameraParallelProjection = 0
    # The camera moved right by `pan` pixels: a point at column x is at x - pan after it.
    p = args.pan
    a, b = first[:, p:], second[:, :-p]
    inside_a = np.any(np.abs(a - KEY) > 8, axis=2)
    inside_b = np.any(np.abs(b - KEY) > 8, axis=2)
    agreement = np.sum(inside_a & inside_b) / np.maximum(1, np.sum(inside_a | inside_b))
    mask = erode(inside_a, 10) & erode(inside_b, 10)
    ha, hb = high_pass(a)[mask], high_pass(b)[mask]
    ha, hb = ha - ha.mean(), hb - hb.mean()
    correlation = float(np.sum(ha * hb) / np.sqrt(np.sum(ha * ha) * np.sum(hb * hb)))
    return correlation, agreement, int(mask.sum())


def measure(source, camera, kind, name, folder):
    view = CreateView("RenderView")
    view.ViewSize = [args.size, args.size]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = list(KEY / 255.0)
    set_camera(view, camera)
    render(view)  # the OpenGL context, before the clock starts
    start = time.perf_counter()
    display = Show(source, view)
    configure(display, kind)
    render(view)
    first = time.perf_counter() - start
    names = (("NumberOfSteps", "StepSize", "EnhancedLIC", "NormalizeVectors")
             if kind == "paraview" else ("OFBResolution", "OFBNumberOfSteps", "OFBStepSize",
                                         "OFBEnhancedLIC", "OFBLookupMode"))
    print("%-6s %-9s %s" % (name, kind, ", ".join(
        "%s %s" % (n, display.GetPropertyValue(n)) for n in names)))
    frames = []
    for _ in range(args.frames):
        view.GetActiveCamera().Azimuth(360.0 / args.frames)
        start = time.perf_counter()
        render(view)
        frames.append(time.perf_counter() - start)
    correlation, agreement, pixels = pan_correlation(view, camera, kind, name, folder)
    Hide(source, view)
    Delete(view)
    return {"first": first, "orbit": statistics.median(frames), "pan": correlation,
            "agreement": agreement, "pixels": pixels}


folder = args.images or tempfile.mkdtemp(prefix="ofbParaViewLIC")
os.makedirs(folder, exist_ok=True)
probe = CreateView("RenderView")
probe.ViewSize = [64, 64]
render(probe)
renderer = [line for line in probe.GetRenderWindow().ReportCapabilities().splitlines()
            if "renderer string" in line]
Delete(probe)
print("ranks %d, %d x %d pixels, %d orbit frames, pan %d px, OFB resolution %d, lookup %s, %s"
      % (RANKS, args.size, args.size, args.frames, args.pan, args.ofb_resolution,
         args.ofb_lookup, renderer[0].strip() if renderer else "OpenGL renderer unknown"))
rows = []
for name in args.meshes.split(","):
    source, camera, cells = surface(name)
    results = {kind: measure(source, camera, kind, name, folder)
               for kind in ("paraview", "ofb")}
    for kind, r in results.items():
        print("%-6s %-9s first image %8.3f s  orbit frame %8.4f s  pan correlation %.3f"
              " (mask agreement %.3f, %d pixels)"
              % (name, kind, r["first"], r["orbit"], r["pan"], r["agreement"], r["pixels"]))
    pv, ofb = results["paraview"], results["ofb"]
    rows.append((name, cells, pv, ofb))

print()
print("| mesh | triangles | ranks | first image s (ParaView / OFB) | OFB / ParaView "
      "| orbit frame ms (ParaView / OFB) | OFB / ParaView | pan correlation (ParaView / OFB)"
      " | OFB / ParaView |")
print("|---|---|---|---|---|---|---|---|---|")
for name, cells, pv, ofb in rows:
    # A correlation near 0 makes the ratio meaningless: printed as such.
    pan_ratio = ("%.2f" % (ofb["pan"] / pv["pan"]) if abs(pv["pan"]) >= 0.1
                 else "n/a (ParaView's is ~0)")
    print("| %s | %d | %d | %.2f / %.2f | %.2f | %.1f / %.1f | %.2f | %.3f / %.3f | %s |"
          % (name, cells, RANKS, pv["first"], ofb["first"], ofb["first"] / pv["first"],
             1e3 * pv["orbit"], 1e3 * ofb["orbit"], ofb["orbit"] / pv["orbit"], pv["pan"],
             ofb["pan"], pan_ratio))
if args.min_ofb_pan is not None:
    for name, _, _, ofb in rows:
        if not ofb["pan"] >= args.min_ofb_pan:
            raise SystemExit("the OFB's pan correlation on the %s is %.3f, under %.3f"
                             % (name, ofb["pan"], args.min_ofb_pan))
print("ofbParaViewLICBenchmark done")
