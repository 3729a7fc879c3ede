"""What the OFB plugin's Python tests share (ParaView/Testing, Testing/Benchmarks).

    import ofbParaViewTesting as testing
    testing.keep_display_open()
    controller, rank, ranks = testing.processes()
    say, check = testing.reporter("%d ranks" % ranks, rank)
    ghosted = testing.distributed_surface(source)
    view = testing.black_view(300)
    check, failures = testing.collector()  # a driver's checks, all run

How the scripts find it: pvbatch, pvpython and python3 put a script's folder first on
sys.path, so a script beside this module imports it as it is, also when run through
ofbKeepDisplayOpen.py (which is beside it too); a script elsewhere (the benchmark) inserts
this folder. The GUI's --script runs a script without a file name or its folder on
sys.path: there PYTHONPATH names this folder (the tests' environment does).

Nothing here imports ParaView or VTK before it is called, so the drivers that run in
Debian's python3 import it too.
"""
import ctypes
import ctypes.util

_display = None


def keep_display_open():
    """Opens one connection to the X display, kept until the process ends, so that the X
    server (xvfb-run's) does not reset between two windows when the last client closes
    (docs/testing.md, "Tests that open windows"). The connection (a Display pointer), or
    None without Xlib or a display."""
    global _display
    if _display is None:
        try:
            xlib = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
            xlib.XOpenDisplay.restype = ctypes.c_void_p
            _display = xlib.XOpenDisplay(None)
        except OSError:
            _display = None
    return _display


def processes():
    """(controller, this process's rank, the number of processes) of the global MPI
    controller (pvbatch --symmetric under mpiexec; one process otherwise)."""
    from vtkmodules.vtkParallelCore import vtkMultiProcessController

    controller = vtkMultiProcessController.GetGlobalController()
    return controller, controller.GetLocalProcessId(), controller.GetNumberOfProcesses()


def reporter(label=None, rank=0):
    """(say, check) for a test script: say(*words) prints on rank 0 alone, flushed;
    check(condition, what) raises AssertionError("LABEL: what") when the condition is
    false, else says "ok (LABEL): what" ("ok: what" without a label). Every process must
    reach a check with the same condition (reduce or gather the values first)."""

    def say(*words):
        if rank == 0:
            print(*words, flush=True)

    def check(condition, what):
        if not condition:
            raise AssertionError("%s: %s" % (label, what) if label else what)
        say("ok (%s):" % label if label else "ok:", what)

    return say, check


def collector():
    """(check, failures) for a driver that runs all its checks before it fails:
    check(condition, what) prints "ok:     what" or "FAILED: what" and appends a failed
    one's `what` to the list `failures`."""
    failures = []

    def check(condition, what):
        print(("ok:     " if condition else "FAILED: ") + what, flush=True)
        if not condition:
            failures.append(what)

    return check, failures


def distributed_surface(source, partitions=0):
    """`source` spread over the processes by RedistributeDataSet (into `partitions` pieces
    when given: fewer than the processes leave the last ones with an empty piece), its
    surface (ExtractSurface) with one layer of ghost cells (GhostCellsGenerator), as the
    distributed tests give it to the OFB filters."""
    from paraview.simple import ExtractSurface, GhostCellsGenerator, RedistributeDataSet

    pieces = RedistributeDataSet(Input=source)
    if partitions:
        pieces.NumberOfPartitions = partitions
    return GhostCellsGenerator(Input=ExtractSurface(Input=pieces), BuildIfRequired=1)


def black_view(size=None, position=(1.2, -2.2, 1.0), focal_point=(0.0, 0.0, 0.0),
               view_up=(0.0, 0.0, 1.0), view=None):
    """A render view for pictures that are compared: a new one (or `view`), size x size
    pixels when a size is given, a black background (not the palette's), no orientation
    axes, the camera at `position` looking at `focal_point` (defaults: the sphere of
    radius 0.5 at the origin seen from the side and above)."""
    if view is None:
        from paraview.simple import CreateView

        view = CreateView("RenderView")
    if size:
        view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    view.CameraPosition = list(position)
    view.CameraFocalPoint = list(focal_point)
    view.CameraViewUp = list(view_up)
    return view


def png_image(path):
    """The PNG `path` as a vtkImageData; SystemExit where it cannot be read."""
    from vtkmodules.vtkIOImage import vtkPNGReader

    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        raise SystemExit("cannot read %s" % path)
    return image


def png_pixels(path):
    """The RGB of the PNG `path` as floats, shape (height, width, 3), the first row at the
    bottom (VTK's order); SystemExit where it cannot be read."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    image = png_image(path)
    width, height, _ = image.GetDimensions()
    data = vtk_to_numpy(image.GetPointData().GetScalars())
    return data.reshape(height, width, -1)[:, :, :3].astype(float)


def erode(mask, steps):
    """The boolean image `mask` less `steps` pixels at its border (a silhouette's
    anti-aliased ring)."""
    for _ in range(steps):
        inner = mask.copy()
        inner[1:, :] &= mask[:-1, :]
        inner[:-1, :] &= mask[1:, :]
        inner[:, 1:] &= mask[:, :-1]
        inner[:, :-1] &= mask[:, 1:]
        mask = inner
    return mask
