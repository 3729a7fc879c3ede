"""The OFB Surface representation on a surface that ParaView distributes, against one process.

    python3 TestOFBSurfaceDistributed.py N MPIEXEC PVBATCH PARAVIEW_PYTHON KEEP_OPEN PLUGIN DIR
        [--empty-last]

runs (with Debian's python3 and vtkOFB's Python package on PYTHONPATH, for the image
comparison) `MPIEXEC -np N PVBATCH --symmetric` on this script, which then renders:

    pvbatch --symmetric TestOFBSurfaceDistributed.py PLUGIN DIR [--empty-last]

Every process runs the pvbatch part. A sphere with a tangent field is distributed by
RedistributeDataSet, GhostCellsGenerator adds ghost cells, and the surface is shown with
the "OFB Surface" representation and its LIC (blended with the solid colour). ParaView
composites the pieces' images (IceT). Then the same surface carries an OFB: OFB Probe's,
of OFB Sampler and OFB LIC (the distributed filters), shown as it is by the
representation. Written to DIR: surface-N.png (the LIC), far-N.png (the same from
farther), probe-N.png (the input OFB's LIC), pieces-N.png (the pieces, each in its own
colour) and surface-N.json (every process's OFB frames).

The one-process run is the reference; on N > 1 processes the driver checks:

- (a) every process's OFB frame (origin, cell size, cells) is the one-process frame, for
  the OFB the representation builds and for the input's;
- (b) both composited images pass vtkOFBImageComparison (the LIC-aware comparison of the
  LIC image tests) against the one-process images;
- (c) no seam: the mean |difference| from the one-process image within SEAM_BAND pixels
  of the piece borders is at most SEAM_TOLERANCE levels (of 255) above that elsewhere on
  the surface;
- (d) the pyramid's coarser levels, which the default lookup (Automatic: Smooth for a LIC)
  reads where a pixel covers more than a cell: the mean |difference| from the one-process
  image on the silhouette ring that (c) leaves out, and over the whole surface in a view
  FAR_SCALE times farther (far-N.png), are at most LEVELS_TOLERANCE levels (of 255).

With --empty-last the last process's piece is emptied after the distribution (a
programmable filter): the run must not hang (every process takes part in the collective
calls at every render), every process has the same valid frame, and the other pieces
show their LIC (surface-N-empty.png, surface-N-empty.json).
"""
import json
import os
import subprocess
import sys

import ofbParaViewTesting

SIZE = 300
RESOLUTION = 96
STEPS = 10
GHOST_LAYERS = 8
SEAM_BAND = 3
SEAM_TOLERANCE = 0.5
FAR_SCALE = 4.0
LEVELS_TOLERANCE = 1.0


def render(plugin, out_dir, empty_last):
    """The pvbatch part, on every process."""
    from paraview.simple import (Calculator, ColorBy, ExtractSurface,
                                 GetColorTransferFunction, GhostCellsGenerator, Hide,
                                 LoadPlugin, ProcessIdScalars, ProgrammableFilter,
                                 RedistributeDataSet,
                                 SaveScreenshot, Show, Sphere)
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController

    LoadPlugin(plugin, ns=globals())
    ofb = globals()  # the plugin's filters, added by LoadPlugin
    controller = vtkMultiProcessController.GetGlobalController()
    rank = controller.GetLocalProcessId()
    ranks = controller.GetNumberOfProcesses()

    # The sphere and the field of TestOFBPluginDistributed.py: streamlines cross the piece
    # borders in every direction.
    sphere = Sphere(ThetaResolution=128, PhiResolution=64, Radius=0.5)
    field = Calculator(Input=sphere, ResultArrayName="Field",
                       Function="(-coordsY+0.3*coordsZ)*iHat+coordsX*jHat-0.3*coordsX*kHat")
    pieces = RedistributeDataSet(Input=field)
    surface = ExtractSurface(Input=pieces)
    ghosted = GhostCellsGenerator(Input=surface, BuildIfRequired=0,
                                  MinimumNumberOfGhosts=GHOST_LAYERS)
    name = "surface-%d" % ranks
    if empty_last:
        name += "-empty"
        ghosted = ProgrammableFilter(Input=ghosted, Script="""
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonCore import vtkPoints
controller = vtkMultiProcessController.GetGlobalController()
source, output = self.GetInputDataObject(0, 0), self.GetOutputDataObject(0)
if controller.GetLocalProcessId() != controller.GetNumberOfProcesses() - 1:
    output.ShallowCopy(source)
else:
    # No cells, the arrays kept (as a Threshold that selects nothing here).
    output.SetPoints(vtkPoints())
    output.GetPointData().CopyAllocate(source.GetPointData(), 0)
    output.GetCellData().CopyAllocate(source.GetCellData(), 0)
""")

    view = ofbParaViewTesting.black_view(SIZE)

    display = Show(ghosted, view)
    display.SetRepresentationType("OFB Surface")
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = [0.9, 0.8, 0.6]
    display.OFBResolution = RESOLUTION
    display.OFBLIC = 1
    display.SelectOFBInputVectors = ["POINTS", "Field"]
    display.OFBNumberOfSteps = STEPS
    SaveScreenshot(os.path.join(out_dir, name + ".png"), view, ImageResolution=[SIZE, SIZE])
    # Far: the sphere FAR_SCALE times smaller, where the Smooth lookup reads the pyramid's
    # coarser levels everywhere.
    near = list(view.CameraPosition)
    view.CameraPosition = [FAR_SCALE * c for c in near]
    SaveScreenshot(os.path.join(out_dir, "far-" + name[len("surface-"):] + ".png"), view,
                   ImageResolution=[SIZE, SIZE])
    view.CameraPosition = near

    def frames_of(shown):
        """Every process's OFB frame of `shown`, on every process (each fills its row)."""
        shown.SMProxy.UpdatePropertyInformation()
        information = shown.SMProxy.GetProperty("OFBFrame")
        local = vtkDoubleArray()
        local.SetNumberOfTuples(7 * ranks)
        local.Fill(0.0)
        for i in range(7):
            local.SetValue(7 * rank + i, information.GetElement(i))
        gathered = vtkDoubleArray()
        controller.AllReduce(local, gathered, vtkCommunicator.SUM_OP)
        return [[gathered.GetValue(7 * r + i) for i in range(7)] for r in range(ranks)]

    result = {"ranks": ranks, "frames": frames_of(display)}
    if not empty_last:
        # An OFB that the input carries: OFB Probe's, of OFB Sampler and OFB LIC (the
        # distributed filters), shown as it is.
        Hide(ghosted, view)
        sampler = ofb["OFBSampler"](Input=ghosted, Resolution=RESOLUTION)
        sampler.Vectors = ["POINTS", "Field"]
        lic = ofb["OFBLIC"](Input=sampler, NumberOfSteps=STEPS, NumberOfGhostLevels=GHOST_LAYERS)
        probe = ofb["OFBProbe"](Input=ghosted, OFB=lic)
        probe_display = Show(probe, view)
        probe_display.SetRepresentationType("OFB Surface")
        probe_display.ColorArrayName = ["POINTS", ""]
        probe_display.DiffuseColor = [0.9, 0.8, 0.6]
        probe_display.OFBLIC = 1
        SaveScreenshot(os.path.join(out_dir, "probe-%d.png" % ranks), view,
                       ImageResolution=[SIZE, SIZE])
        result["probe_frames"] = frames_of(probe_display)
        Hide(probe, view)
    if rank == 0:
        with open(os.path.join(out_dir, name + ".json"), "w") as stream:
            json.dump(result, stream)
        print("rendered on %d ranks, frames %s" % (ranks, result["frames"]), flush=True)
    if empty_last:
        return

    # The pieces, each process's in its colour, unlit: where they meet is the border.
    ids = ProcessIdScalars(Input=surface)
    piece_display = Show(ids, view)
    piece_display.SetRepresentationType("Surface")
    ColorBy(piece_display, ("POINTS", "ProcessId"))
    lut = GetColorTransferFunction("ProcessId")
    lut.ApplyPreset("Rainbow Uniform", True)
    lut.RescaleTransferFunction(0.0, 2.0)
    piece_display.Ambient = 1.0
    piece_display.Diffuse = 0.0
    piece_display.Interpolation = "Flat"
    SaveScreenshot(os.path.join(out_dir, "pieces-%d.png" % ranks), view,
                   ImageResolution=[SIZE, SIZE])


def borders(pieces, mask):
    """The pixels of the surface within SEAM_BAND pixels of a change of piece colour."""
    import numpy as np

    edge = np.zeros(mask.shape, dtype=bool)
    for axis in (0, 1):
        change = np.abs(np.diff(pieces, axis=axis)).max(axis=2) > 40
        inside = mask[1:, :] & mask[:-1, :] if axis == 0 else mask[:, 1:] & mask[:, :-1]
        change &= inside
        if axis == 0:
            edge[1:, :] |= change
            edge[:-1, :] |= change
        else:
            edge[:, 1:] |= change
            edge[:, :-1] |= change
    band = edge.copy()
    for _ in range(SEAM_BAND):
        grown = band.copy()
        grown[1:, :] |= band[:-1, :]
        grown[:-1, :] |= band[1:, :]
        grown[:, 1:] |= band[:, :-1]
        grown[:, :-1] |= band[:, 1:]
        band = grown
    return band & mask


def check_empty_last(count, out_dir, mine, check):
    """--empty-last: one valid frame on every process, the other pieces' LIC shown."""
    import numpy as np

    frames = np.array(mine["frames"])
    check(frames[0][3] > 0 and (frames[0][4:] > 2).all(),
          "rank 0 has a frame: %s" % frames[0].tolist())
    for rank, frame in enumerate(frames):
        check((frame == frames[0]).all(), "(a) rank %d's OFB frame %s is rank 0's%s"
              % (rank, frame.tolist(), " (its piece is empty)" if rank == count - 1 else ""))
    lic = ofbParaViewTesting.png_pixels(
        os.path.join(out_dir, "surface-%d-empty.png" % count)).mean(axis=2)
    mask = lic > 2
    padded = np.pad(lic, 1, mode="edge")
    local = sum(padded[1 + dy:1 + dy + lic.shape[0], 1 + dx:1 + dx + lic.shape[1]]
                for dy in (-1, 0, 1) for dx in (-1, 0, 1)) / 9.0
    energy = float(((lic - local)[mask] ** 2).mean()) if mask.any() else 0.0
    check(mask.mean() > 0.2 and energy > 20.0, "the other pieces show their LIC: %.2f of the "
          "image, high-pass energy %.1f" % (mask.mean(), energy))


def drive(argv):
    """The driver, run by Debian's python3 with vtkOFB's package: runs pvbatch, checks."""
    import numpy as np

    empty_last = argv[-1] == "--empty-last"
    if empty_last:
        argv = argv[:-1]
    count, mpiexec, pvbatch, paraview_python, keep_open, plugin, out_dir = argv
    count = int(count)
    os.makedirs(out_dir, exist_ok=True)
    # pvbatch with ParaView's Python, and without the main build's libraries on the
    # library path (the plugin's libraries of the same names are found through its RUNPATH).
    env = dict(os.environ, PYTHONPATH=paraview_python)
    env.pop("LD_LIBRARY_PATH", None)
    command = [mpiexec, "-np", str(count), pvbatch, "--symmetric",
               "--force-offscreen-rendering", keep_open, os.path.abspath(__file__),
               plugin, out_dir] + (["--empty-last"] if empty_last else [])
    print(" ".join(command), flush=True)
    run = subprocess.run(command, env=env, timeout=540)
    if run.returncode != 0:
        raise SystemExit("pvbatch on %d ranks exited with %d" % (count, run.returncode))
    if count == 1 and not empty_last:
        print("wrote the one-process reference in %s" % out_dir)
        return

    failures = []

    def check(condition, what):
        print(("ok     " if condition else "FAILED ") + what, flush=True)
        if not condition:
            failures.append(what)

    def load(name):
        with open(os.path.join(out_dir, name)) as stream:
            return json.load(stream)

    if empty_last:
        check_empty_last(count, out_dir, load("surface-%d-empty.json" % count), check)
        if failures:
            raise SystemExit("%d check(s) failed on %d ranks" % (len(failures), count))
        print("all surface checks passed on %d ranks with an empty piece" % count)
        return

    one, mine = load("surface-1.json"), load("surface-%d.json" % count)
    for key, what in (("frames", "OFB frame"), ("probe_frames", "input OFB's frame (OFB Probe)")):
        reference = np.array(one[key][0])
        check(reference[3] > 0, "the one-process %s: %s" % (what, reference.tolist()))
        for rank, frame in enumerate(mine[key]):
            frame = np.array(frame)
            same = (np.abs(frame[:4] - reference[:4]) <= 1e-9 * max(1.0, reference[3])).all() \
                and (frame[4:] == reference[4:]).all()
            check(same, "(a) rank %d's %s %s is the one-process frame"
                  % (rank, what, frame.tolist()))

    import vtkofb
    from vtkmodules.vtkIOImage import vtkPNGWriter

    def compare(name, what):
        comparison = vtkofb.vtkOFBImageComparison()
        png = ofbParaViewTesting.png_image
        comparison.SetImage(png(os.path.join(out_dir, "%s-%d.png" % (name, count))))
        comparison.SetBaseline(png(os.path.join(out_dir, "%s-1.png" % name)))
        passed = comparison.Compare()
        if comparison.GetDifferenceImage() is not None:
            writer = vtkPNGWriter()
            writer.SetFileName(os.path.join(out_dir, "%s-%d.diff.png" % (name, count)))
            writer.SetInputData(comparison.GetDifferenceImage())
            writer.Write()
        check(passed, "(b) %s against one process's (vtkOFBImageComparison): correlation %.4f "
              "(at least %.2f), low-pass difference %.2f (at most %.1f), outside %.4f %s"
              % (what, comparison.GetCorrelation(), comparison.GetCorrelationThreshold(),
                 comparison.GetLowPassDifference(), comparison.GetLowPassThreshold(),
                 comparison.GetImageDifferenceError(), comparison.GetErrorText()))

    compare("surface", "the composited image")
    compare("probe", "the composited image of the input OFB")
    lic = ofbParaViewTesting.png_pixels(os.path.join(out_dir, "surface-%d.png" % count))
    lic_one = ofbParaViewTesting.png_pixels(os.path.join(out_dir, "surface-1.png"))
    mask = (lic.max(axis=2) > 2) & (lic_one.max(axis=2) > 2)
    # Off the silhouette (the anti-aliased ring).
    mask = ofbParaViewTesting.erode(mask, 3)
    band = borders(
        ofbParaViewTesting.png_pixels(os.path.join(out_dir, "pieces-%d.png" % count)), mask)
    rest = mask & ~band
    check(band.sum() > 100 and rest.sum() > 1000, "the piece borders cross the view: %d border "
          "pixels, %d others" % (band.sum(), rest.sum()))
    grey = np.abs(lic.mean(axis=2) - lic_one.mean(axis=2))
    band_mean = grey[band].mean() if band.any() else 0.0
    rest_mean = grey[rest].mean() if rest.any() else 0.0
    check(band_mean <= rest_mean + SEAM_TOLERANCE,
          "(c) no seam: mean |difference| from one process %.2f at the piece borders, %.2f "
          "elsewhere (at most %.1f more at the borders)" % (band_mean, rest_mean,
                                                          SEAM_TOLERANCE))

    # (d) The coarser levels (the Smooth lookup of the default Automatic one): the ring of
    # the silhouette that (c) leaves out, and the far view, where every pixel reads them.
    whole = (lic.max(axis=2) > 2) | (lic_one.max(axis=2) > 2)
    ring = whole & ~mask
    far = ofbParaViewTesting.png_pixels(os.path.join(out_dir, "far-%d.png" % count)).mean(axis=2)
    far_one = ofbParaViewTesting.png_pixels(os.path.join(out_dir, "far-1.png")).mean(axis=2)
    far_mask = (far > 2) | (far_one > 2)
    ring_mean = grey[ring].mean() if ring.any() else 0.0
    far_mean = np.abs(far - far_one)[far_mask].mean() if far_mask.any() else 0.0
    check(ring.sum() > 100 and far_mask.sum() > 100, "the silhouette ring has %d pixels, the "
          "far view %d" % (ring.sum(), far_mask.sum()))
    check(ring_mean <= LEVELS_TOLERANCE and far_mean <= LEVELS_TOLERANCE,
          "(d) the pyramid's levels: mean |difference| from one process %.2f on the "
          "silhouette ring, %.2f in the far view (at most %.1f)"
          % (ring_mean, far_mean, LEVELS_TOLERANCE))
    if failures:
        raise SystemExit("%d check(s) failed on %d ranks" % (len(failures), count))
    print("all surface checks passed on %d ranks" % count)


if __name__ == "__main__":
    if len(sys.argv) in (3, 4) and sys.argv[3:] in ([], ["--empty-last"]):
        render(sys.argv[1], sys.argv[2], len(sys.argv) == 4)
    elif len(sys.argv) in (8, 9):
        drive(sys.argv[1:])
    else:
        raise SystemExit(__doc__)
