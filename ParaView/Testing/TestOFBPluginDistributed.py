"""The OFB plugin's filters on a surface distributed by ParaView, against one process.

mpiexec -np N pvbatch --symmetric TestOFBPluginDistributed.py PLUGIN REFERENCE_DIR [PARTITIONS]

Every process runs this script (--symmetric). The surface (a sphere with a tangent field)
is distributed by RedistributeDataSet (into PARTITIONS pieces when given: fewer than the
processes leaves the last ones with an empty piece), and GhostCellsGenerator makes the ghost
cells that OFB LIC and OFB Particles ask for through the pipeline. Each process samples its piece
(OFB Sampler: one frame from the bounds of all pieces), computes the LIC, paints a stroke,
advances particles from fixed seeds (steady, and pathlines through a time series read by
ParaView's PVD reader) and probes the LIC back onto its piece of the mesh;
ParaView composites the image of the probed pieces (IceT).

On one process the script writes the reference (distributed.json and distributed.png in
REFERENCE_DIR); on more it compares with that reference:

- owned samples (vtkGhostType 0), summed over the processes: equal;
- the LIC over the owned samples: mean and standard deviation within LIC_TOLERANCE;
- painted owned samples: within PAINT_TOLERANCE (relative);
- particles and pathlines: equal count, none output twice, every end point within
  ENDPOINT_TOLERANCE of one process's, every process's pathlines at the time asked for;
- the composited image: mean |difference| below IMAGE_MEAN_TOLERANCE (of 255) and at most
  IMAGE_PIXEL_FRACTION of the surface's pixels off by more than 48.
"""
import json
import os
import sys

import numpy as np
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkParallelCore import vtkCommunicator

import ofbParaViewTesting

LIC_TOLERANCE = 0.005
PAINT_TOLERANCE = 0.01
IMAGE_MEAN_TOLERANCE = 2.0
IMAGE_PIXEL_FRACTION = 0.01
SIZE = 300
# 1e-3 cells: the sampler's cells are at least 1/96 of the sphere's diameter (1.0).
ENDPOINT_TOLERANCE = 1e-3 / 96

plugin, reference_dir = sys.argv[1], sys.argv[2]
partitions = int(sys.argv[3]) if len(sys.argv) > 3 else 0
LoadPlugin(plugin, ns=globals())
controller, rank, ranks = ofbParaViewTesting.processes()
# Every process reaches every check with the same values (they are reduced).
say, check = ofbParaViewTesting.reporter("%d ranks" % ranks, rank)


def total(values):
    """The sums of `values` over all processes."""
    local = vtkDoubleArray()
    local.SetNumberOfTuples(len(values))
    for i, value in enumerate(values):
        local.SetValue(i, float(value))
    result = vtkDoubleArray()
    controller.AllReduce(local, result, vtkCommunicator.SUM_OP)
    return [result.GetValue(i) for i in range(len(values))]


def local_data(proxy, port=0):
    return proxy.GetClientSideObject().GetOutputDataObject(port)


def samples(data):
    """The sample arrays of an OFB (a vtkDataObject to Python: its points' attributes)."""
    return data.GetAttributesAsFieldData(data.POINT)


def sample_array(data, name, components=1):
    """Sample array `name` of an OFB as numpy (none on an empty piece, which has no arrays)."""
    array = samples(data).GetArray(name)
    if array is None and data.GetNumberOfElements(data.POINT) == 0:
        return np.zeros((0, components) if components > 1 else 0)
    return vtk_to_numpy(array)


def owned(data):
    """The mask of this process's owned samples of an OFB."""
    count = data.GetNumberOfElements(data.POINT)
    ghosts = samples(data).GetArray("vtkGhostType")
    if ghosts is None:
        return np.ones(count, dtype=bool)
    return vtk_to_numpy(ghosts) == 0


# A sphere with the field of a rotation about z, tilted so that streamlines cross the
# piece borders in every direction.
sphere = Sphere(ThetaResolution=128, PhiResolution=64, Radius=0.5)
field = Calculator(Input=sphere, ResultArrayName="Field",
                   Function="(-coordsY+0.3*coordsZ)*iHat+coordsX*jHat-0.3*coordsX*kHat")
ghosted = ofbParaViewTesting.distributed_surface(field, partitions)

sampler = OFBSampler(Input=ghosted, Resolution=96)
sampler.Vectors = ["POINTS", "Field"]
lic = OFBLIC(Input=sampler, NumberOfSteps=10, NumberOfGhostLevels=12)
lic.UpdatePipeline()
data = local_data(lic)
mask = owned(data)
values = sample_array(data, "LIC")[mask].astype(np.float64)
count, lic_sum, lic_sum2 = total([mask.sum(), values.sum(), (values ** 2).sum()])
lic_mean = lic_sum / count
lic_std = np.sqrt(max(lic_sum2 / count - lic_mean ** 2, 0.0))
ghost_samples = total([(~mask).sum()])[0]
say("samples %d (ghost %d), LIC mean %.5f std %.5f" % (count, ghost_samples, lic_mean, lic_std))

equator = PolyLineSource(Points=[0.5 * c for a in np.linspace(0, 2 * np.pi, 64)
                                 for c in (np.cos(a), np.sin(a), 0.0)])
paint = OFBPaintStrokes(Input=sampler, Strokes=equator)
paint.BrushRadius = 0.08
paint.BrushColor = [1.0, 0.0, 0.0, 1.0]
paint.UpdatePipeline()
data = local_data(paint)
colors = sample_array(data, "Colors", 4)
red = (colors[:, 0] > 200) & (colors[:, 1] < 60) & (colors[:, 2] < 60)
painted = total([(red & owned(data)).sum()])[0]
say("painted samples %d" % painted)

# The painted OFB saved as an .ofb file (one file from every process's owned samples) and
# read back by OFB Reader on every process: the first owns every sample, the others
# hold them as ghosts; probing any piece of the mesh with it gives the paint again.
ofb_name = "painted.ofb" if ranks == 1 else "painted-%d%s.ofb" % (
    ranks, "-of-%d" % partitions if partitions else "")
ofb_path = os.path.join(reference_dir, ofb_name)
if rank == 0 and os.path.exists(ofb_path):
    os.remove(ofb_path)
controller.Barrier()
SaveData(ofb_path, proxy=paint)
reread = OFBReader(FileName=ofb_path)
reread.UpdatePipeline()
read_data = local_data(reread)
read_owned, read_all = total([owned(read_data).sum(), read_data.GetNumberOfElements(
    read_data.POINT)])
piece_probe = OFBProbe(Input=ghosted, OFB=paint)
file_probe = OFBProbe(Input=ghosted, OFB=reread)


def probed_colors(probe):
    """The probed colours of the piece's own points (not ghosts)."""
    mesh = local_data(probe)
    if mesh.GetNumberOfPoints() == 0:
        return np.zeros((0, 4))
    colors = vtk_to_numpy(mesh.GetPointData().GetArray("Colors"))
    ghosts = mesh.GetPointData().GetArray("vtkGhostType")
    return colors if ghosts is None else colors[vtk_to_numpy(ghosts) == 0]


probes_differ = total([int(not np.array_equal(probed_colors(piece_probe),
                                              probed_colors(file_probe)))])[0]
say("OFB file: %d samples owned, %d held, probes differ on %d processes"
    % (read_owned, read_all, probes_differ))

# 40 seeds on the sphere (a Fibonacci spiral), the same on every process.
k = np.arange(40) + 0.5
z = 1.0 - 2.0 * k / 40
r = np.sqrt(1.0 - z * z)
seeds = PolyPointSource(Points=list((0.5 * np.column_stack(
    (r * np.cos(np.pi * (3 - np.sqrt(5)) * k), r * np.sin(np.pi * (3 - np.sqrt(5)) * k), z)))
    .ravel()))
particles = OFBParticles(Input=ghosted, OFB=sampler, Seeds=seeds, FootprintRadius=2.0,
                         NumberOfTimeSteps=30, StepSize=1.5)
particles.Vectors = ["POINTS", "Field"]
particles.UpdatePipeline(20.0)
ends = local_data(particles, 1)
ids = vtk_to_numpy(ends.GetPointData().GetArray("Id")) if ends.GetNumberOfPoints() else []
points = vtk_to_numpy(ends.GetPoints().GetData()) if ends.GetNumberOfPoints() else []
# Per seed: how many processes output its particle, and where it ended.
per_seed = np.zeros((40, 4))
for i, point in zip(ids, points):
    per_seed[i] += [1.0, point[0], point[1], point[2]]
per_seed = np.array(total(list(per_seed.ravel()))).reshape(40, 4)
particle_count = int(per_seed[:, 0].sum())
say("particles %d" % particle_count)

# Pathlines: a time series (written by the first process, read by ParaView's PVD reader and
# distributed as the sphere above) of a sphere off the axis of a rotation whose axis turns
# with time, so that the pieces' largest speeds differ; the particles follow it at 0.2,
# then straight to 1.0 (the filter reads the four steps between), on every process.
series_dir = os.path.join(reference_dir, "series-%d%s" % (ranks, "-of-%d" % partitions
                                                          if partitions else ""))
if rank == 0:
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk

    os.makedirs(series_dir, exist_ok=True)
    ball = vtkSphereSource()
    ball.SetThetaResolution(64)
    ball.SetPhiResolution(32)
    ball.SetRadius(0.5)
    ball.SetCenter(0.35, 0.1, 0.0)
    ball.Update()
    entries = []
    for step in range(11):
        t = 0.1 * step
        mesh = ball.GetOutput().NewInstance()
        mesh.DeepCopy(ball.GetOutput())
        x = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
        axis = 2.0 * np.array([np.sin(t), 0.0, np.cos(t)])
        velocity = numpy_to_vtk(np.ascontiguousarray(np.cross(axis, x)), deep=1)
        velocity.SetName("Velocity")
        mesh.GetPointData().AddArray(velocity)
        name = "step-%02d.vtp" % step
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(os.path.join(series_dir, name))
        writer.SetInputData(mesh)
        writer.Write()
        entries.append('<DataSet timestep="%.17g" file="%s"/>' % (t, name))
    with open(os.path.join(series_dir, "series.pvd"), "w") as stream:
        stream.write('<VTKFile type="Collection"><Collection>%s</Collection></VTKFile>\n'
                     % "".join(entries))
controller.Barrier()
series = PVDReader(FileName=os.path.join(series_dir, "series.pvd"))
series_pieces = RedistributeDataSet(Input=series)
if partitions:
    series_pieces.NumberOfPartitions = partitions
series_ghosted = GhostCellsGenerator(Input=ExtractSurface(Input=series_pieces), BuildIfRequired=1)
series_sampler = OFBSampler(Input=series_ghosted, Resolution=96)
pathline_seeds = PolyPointSource(Points=list((0.5 * np.column_stack(
    (r * np.cos(np.pi * (3 - np.sqrt(5)) * k), r * np.sin(np.pi * (3 - np.sqrt(5)) * k), z))
    + [0.35, 0.1, 0.0]).ravel()))
pathlines = OFBParticles(Input=series_ghosted, OFB=series_sampler, Seeds=pathline_seeds,
                         FootprintRadius=2.0, StepSize=1.5)
pathlines.Vectors = ["POINTS", "Velocity"]
for t in (0.0, 0.2, 1.0):
    pathlines.UpdatePipeline(t)
path_ends = local_data(pathlines, 1)
path_time = path_ends.GetInformation().Get(path_ends.DATA_TIME_STEP())
path_ids = (vtk_to_numpy(path_ends.GetPointData().GetArray("Id"))
            if path_ends.GetNumberOfPoints() else [])
path_points = vtk_to_numpy(path_ends.GetPoints().GetData()) if path_ends.GetNumberOfPoints() else []
path_per_seed = np.zeros((40, 4))
for i, point in zip(path_ids, path_points):
    path_per_seed[i] += [1.0, point[0], point[1], point[2]]
path_per_seed = np.array(total(list(path_per_seed.ravel()))).reshape(40, 4)
path_count = int(path_per_seed[:, 0].sum())
path_timed = total([int(path_time == 1.0)])[0]
say("pathline particles %d, at t = 1.0 on %d processes" % (path_count, path_timed))

# The image: the LIC probed back onto the mesh, composited by ParaView.
probe = OFBProbe(Input=ghosted, OFB=lic)
view = ofbParaViewTesting.black_view(SIZE)
view.CameraParallelScale = 0.6
display = Show(probe, view)
ColorBy(display, ("POINTS", "LIC"))
lut = GetColorTransferFunction("LIC")
lut.ApplyPreset("Grayscale", True)
lut.RescaleTransferFunction(0.0, 1.0)
image_name = "distributed.png" if ranks == 1 else "distributed-%d%s.png" % (
    ranks, "-of-%d" % partitions if partitions else "")
image_path = os.path.join(reference_dir, image_name)
SaveScreenshot(image_path, view, ImageResolution=[SIZE, SIZE])

result = {"samples": count, "lic_mean": lic_mean, "lic_std": lic_std, "painted": painted,
          "particles": particle_count, "ends": per_seed[:, 1:].tolist(),
          "pathline_particles": path_count, "pathline_ends": path_per_seed[:, 1:].tolist()}
reference_path = os.path.join(reference_dir, "distributed.json")


def compare_with_reference():
    """The checks of a run on more than one process against the one-process reference."""
    with open(reference_path) as stream:
        reference = json.load(stream)
    empty = total([int(local_data(ghosted).GetNumberOfCells() == 0)])[0]
    check(empty == (ranks - partitions if 0 < partitions < ranks else 0),
          "processes with an empty piece: %d" % empty)
    check(ghost_samples > 0, "ghost samples on the piece borders: %d" % ghost_samples)
    check(count == reference["samples"], "owned samples %d, one process %d"
          % (count, reference["samples"]))
    check(abs(lic_mean - reference["lic_mean"]) <= LIC_TOLERANCE and
          abs(lic_std - reference["lic_std"]) <= LIC_TOLERANCE,
          "LIC mean %.5f std %.5f, one process %.5f %.5f"
          % (lic_mean, lic_std, reference["lic_mean"], reference["lic_std"]))
    check(abs(painted - reference["painted"]) <= PAINT_TOLERANCE * reference["painted"],
          "painted samples %d, one process %d" % (painted, reference["painted"]))
    check(read_owned == count and read_all == count * ranks,
          "OFB file: %d samples, each owned once (one process: %d), held by every process"
          % (read_owned, count))
    check(probes_differ == 0, "OFB file: every piece probes to the paint of its own OFB")
    if rank == 0:
        reference_file = OFBReader(FileName=os.path.join(reference_dir, "painted.ofb"))
        reference_file.UpdatePipeline()
        mine_colors = sample_array(read_data, "Colors", 4)
        one_colors = sample_array(local_data(reference_file), "Colors", 4)
        check(np.array_equal(mine_colors, one_colors),
              "OFB file: the paint of every sample equal to one process's file")
    check(particle_count == reference["particles"], "particles %d, one process %d"
          % (particle_count, reference["particles"]))
    check(per_seed[:, 0].max() <= 1, "no particle output by two processes")
    offsets = np.abs(per_seed[:, 1:] - np.array(reference["ends"])).max(axis=1)
    check(offsets.max() <= ENDPOINT_TOLERANCE,
          "particles ending where one process's end: %d of %d (largest offset %.3g, tolerance %.3g)"
          % ((offsets <= ENDPOINT_TOLERANCE).sum(), len(offsets), offsets.max(),
             ENDPOINT_TOLERANCE))
    check(path_timed == ranks, "pathlines: every process's particles at t = 1.0")
    check(path_count == reference["pathline_particles"] and path_per_seed[:, 0].max() <= 1,
          "pathline particles %d, one process %d, none output twice"
          % (path_count, reference["pathline_particles"]))
    path_offsets = np.abs(path_per_seed[:, 1:] - np.array(reference["pathline_ends"])).max(axis=1)
    check(path_offsets.max() <= ENDPOINT_TOLERANCE,
          "pathlines ending where one process's end: %d of %d (largest offset %.3g)"
          % ((path_offsets <= ENDPOINT_TOLERANCE).sum(), len(path_offsets), path_offsets.max()))

    if rank == 0:
        from vtkmodules.vtkIOImage import vtkPNGReader

        def read(path):
            reader = vtkPNGReader()
            reader.SetFileName(path)
            reader.Update()
            return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)

        mine, one = read(image_path), read(os.path.join(reference_dir, "distributed.png"))
        surface_pixels = (one.sum(axis=1) > 0) | (mine.sum(axis=1) > 0)
        difference = np.abs(mine - one).max(axis=1)[surface_pixels]
        mean = difference.mean()
        off = (difference > 48).mean()
        check(surface_pixels.mean() > 0.2, "the sphere covers %.2f of the image"
              % surface_pixels.mean())
        check(mean <= IMAGE_MEAN_TOLERANCE and off <= IMAGE_PIXEL_FRACTION,
              "composited image: mean |difference| %.3f, %.4f of the pixels off by more than 48"
              % (mean, off))
    say("all distributed checks passed on %d ranks" % ranks)


# The script ends normally on every path (no sys.exit): pvbatch then closes its views
# before the interpreter ends.
if ranks == 1:
    if rank == 0:
        with open(reference_path, "w") as stream:
            json.dump(result, stream)
    say("wrote the one-process reference", reference_path)
else:
    compare_with_reference()
