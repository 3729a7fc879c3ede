"""The OFB writer (File > Save Data) on a surface distributed by ParaView, against one process.

mpiexec -np N pvbatch --symmetric TestOFBWriterDistributed.py PLUGIN MESH OUTPUT_DIR [PARTITIONS]

Every process runs this script (--symmetric). The mesh file MESH (read on the first
process) is distributed by RedistributeDataSet (PARTITIONS pieces when given: fewer pieces
than processes leaves the last ones with an empty piece), GhostCellsGenerator gives each
piece its ghost cells, each process samples its piece (OFB Sampler: one frame for all
pieces), OFB Paint Strokes paints a band across the middle of the mesh, and OFB Probe hands
its mesh and OFB to the writer. (A mesh file rather than ParaView's Sphere: the Sphere's
pieces put the points of its seam at coordinates that differ in the last bits from one
process's, so its distributed surface is not one process's surface.) The script saves the probe
with SaveData as OUTPUT_DIR/<N>/writer.gltf (ParaView offers the OFB writer on every number
of processes) and as writer.obj (+ .mtl, .png) through the writer by name; then it
writes bad.obj with an array the OFB lacks, which must write nothing on any process.

On one process the files are the reference (OUTPUT_DIR/1). On more processes the first
process compares its files with them:
- one file set, written once: writer.obj, .mtl, .png and .gltf, no other file and no
  staging folder left;
- the .obj: the same number of points and faces as one process's, the same cells (their
  centroids, sorted, equal within 1e-6), and the colour the texture gives each cell (the
  texel at the centroid of its texture coordinates) equal to one process's for all but
  0.5 % of the cells, none by more than MAX_DIFFERENCE grey levels; the texture has paint
  (red cells);
- the .mtl: one process's, byte for byte;
- the .gltf: one mesh, the same number of vertices and indices as one process's, the
  texture embedded as a PNG.
The .obj and .gltf bytes differ from one process's: they list the cells in the order of
the pieces. The script prints which files are byte-equal.
"""
import base64
import json
import os
import sys

import numpy as np
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGReader

import ofbParaViewTesting

MAX_DIFFERENCE = 8  # grey levels, a cell's colour against one process's
MAX_DIFFERING = 0.005  # fraction of the cells whose colour differs at all

plugin, mesh_file, output = sys.argv[1], sys.argv[2], sys.argv[3]
partitions = int(sys.argv[4]) if len(sys.argv) > 4 else 0
LoadPlugin(plugin, ns=globals())
controller, rank, ranks = ofbParaViewTesting.processes()
name = "%d%s" % (ranks, "-%dpieces" % partitions if partitions else "")
folder = os.path.join(output, name)
reference = os.path.join(output, "1")
if rank == 0:
    os.makedirs(folder, exist_ok=True)
    for old in os.listdir(folder):
        os.remove(os.path.join(folder, old))
controller.Barrier()
say, check = ofbParaViewTesting.reporter(name, rank)

source = OpenDataFile(mesh_file)
ghosted = ofbParaViewTesting.distributed_surface(source, partitions)
sampler = OFBSampler(Input=ghosted, Resolution=64)
bounds = source.GetDataInformation().GetBounds()
low, high = np.array(bounds[0::2]), np.array(bounds[1::2])
centre = 0.5 * (low + high)
band = PolyLineSource(Points=list(np.ravel([[x, centre[1], centre[2]]
                                            for x in np.linspace(low[0], high[0], 32)])))
paint = OFBPaintStrokes(Input=sampler, Strokes=band)
paint.BrushRadius = 0.1 * float(np.linalg.norm(high - low))
paint.BrushColor = [1.0, 0.0, 0.0, 1.0]
probe = OFBProbe(Input=ghosted, OFB=paint)
probe.UpdatePipeline()

SaveData(os.path.join(folder, "writer.gltf"), proxy=probe, TextureSize=256)
writer = servermanager.writers.OFBTexturedMeshWriter(
    Input=probe, FileName=os.path.join(folder, "writer.obj"), TextureSize=256)
writer.UpdatePipeline()
# Bad input on every process (an array the OFB lacks): an error, nothing written, and
# every process goes on (no process waits for another).
bad = servermanager.writers.OFBTexturedMeshWriter(
    Input=probe, FileName=os.path.join(folder, "bad.obj"), ArrayName="NoSuchArray")
bad.UpdatePipeline()
controller.Barrier()

if rank == 0:
    files = sorted(os.listdir(folder))
    check(files == ["writer.gltf", "writer.mtl", "writer.obj", "writer.png"],
          "one file set written, nothing else left: %s" % files)


def cells_and_colours(directory):
    """The .obj's cell centroids (sorted) and the colour the texture gives each."""
    reader = vtkOBJReader()
    reader.SetFileName(os.path.join(directory, "writer.obj"))
    reader.Update()
    mesh = reader.GetOutput()
    image = vtkPNGReader()
    image.SetFileName(os.path.join(directory, "writer.png"))
    image.Update()
    width, height, _ = image.GetOutput().GetDimensions()
    texels = vtk_to_numpy(image.GetOutput().GetPointData().GetScalars())
    texels = texels.reshape(height, width, -1)[:, :, :3].astype(np.int64)
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    tcoords = vtk_to_numpy(mesh.GetPointData().GetTCoords()).astype(np.float64)
    polys = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())
    offsets = vtk_to_numpy(mesh.GetPolys().GetOffsetsArray())
    centroids, colours = [], []
    for c in range(len(offsets) - 1):
        ids = polys[offsets[c]:offsets[c + 1]]
        centroids.append(points[ids].mean(axis=0))
        u, v = tcoords[ids].mean(axis=0)
        i = min(width - 1, max(0, int(u * width)))
        j = min(height - 1, max(0, int(v * height)))
        colours.append(texels[j, i])
    centroids, colours = np.array(centroids), np.array(colours)
    order = np.lexsort(np.round(centroids, 6).T[::-1])
    return mesh.GetNumberOfPoints(), centroids[order], colours[order]


def gltf_counts(directory):
    """The .gltf's number of meshes, vertices and indices, and its embedded texture."""
    with open(os.path.join(directory, "writer.gltf")) as stream:
        gltf = json.load(stream)
    primitive = gltf["meshes"][0]["primitives"][0]
    vertices = gltf["accessors"][primitive["attributes"]["POSITION"]]["count"]
    indices = gltf["accessors"][primitive["indices"]]["count"]
    textures = []
    for image in gltf.get("images", []):
        view = gltf["bufferViews"][image["bufferView"]]
        data = base64.b64decode(gltf["buffers"][view["buffer"]]["uri"].split(",", 1)[1])
        start = view.get("byteOffset", 0)
        textures.append(data[start:start + view["byteLength"]])
    return (len(gltf["meshes"]), vertices, indices), textures


def compare():
    """The checks of the first process on more than one (AssertionError on a failure)."""
    points, centroids, colours = cells_and_colours(folder)
    ref_points, ref_centroids, ref_colours = cells_and_colours(reference)
    check(points == ref_points and len(centroids) == len(ref_centroids),
          ".obj: %d points, %d faces; one process %d, %d"
          % (points, len(centroids), ref_points, len(ref_centroids)))
    check(np.abs(centroids - ref_centroids).max() < 1e-6, ".obj: the same cells")
    difference = np.abs(colours - ref_colours).max(axis=1)
    differing = float((difference > 0).mean())
    say("%s: cell colours against one process: %.3f %% differ, by at most %d"
        % (name, 100 * differing, difference.max()))
    check(differing <= MAX_DIFFERING and difference.max() <= MAX_DIFFERENCE,
          "the colours of the cells are one process's")
    red = (colours[:, 0] > 200) & (colours[:, 1] < 60) & (colours[:, 2] < 60)
    check(red.sum() > 0, ".obj: painted cells in the texture: %d" % red.sum())
    same = {ext: open(os.path.join(folder, "writer" + ext), "rb").read() ==
            open(os.path.join(reference, "writer" + ext), "rb").read()
            for ext in (".obj", ".mtl", ".png", ".gltf")}
    say("%s: byte-equal to one process's: %s" % (name, same))
    check(same[".mtl"], ".mtl: one process's")
    (counts, textures), (ref_counts, ref_textures) = gltf_counts(folder), gltf_counts(reference)
    check(counts == ref_counts and counts[0] == 1,
          ".gltf: meshes, vertices, indices %s; one process %s" % (counts, ref_counts))
    check(len(textures) == 1 and textures[0][:8] == b"\x89PNG\r\n\x1a\n",
          ".gltf: the texture embedded as a PNG")
    say("%s: .gltf texture byte-equal to one process's: %s" % (name, textures == ref_textures))


# The first process checks; every process ends with its verdict (no process left waiting).
passed = [1]
if rank == 0 and ranks == 1 and not partitions:
    say("wrote the one-process reference")
elif rank == 0:
    try:
        compare()
    except Exception as error:
        print("AssertionError:", error, flush=True)
        passed = [0]
verdict = vtkIntArray()
verdict.InsertNextValue(passed[0])
controller.Broadcast(verdict, 0)
if not verdict.GetValue(0):
    raise AssertionError("%s: the writer's files differ from one process's" % name)
if rank == 0 and (ranks > 1 or partitions):
    say("all writer checks passed on %s" % name)
