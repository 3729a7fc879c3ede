"""OFB Paint Strokes with FollowSurface on a surface distributed by ParaView, against one
process.

mpiexec -np N pvbatch --symmetric TestOFBPluginStrokes.py PLUGIN REFERENCE_DIR

Every process runs this script (--symmetric). The surface, an open pipe, is distributed
by RedistributeDataSet, and each process samples its piece (OFB Sampler: one frame from
the bounds of all pieces). A stroke given by a poly-line source (on the first process
only) goes around the pipe a third of a turn per segment, where the chords would cross
the inside, then down a helix, and ends at a point inside the pipe; OFB Paint Strokes
(vtkOFBPPaintFilter, FollowSurface on) places its path over the owned samples of every
process.

On one process the script writes the reference (strokes.json in REFERENCE_DIR): the
colours of the owned samples (vtkGhostType 0), as counts of each distinct colour. On more
processes it compares: the counts must be equal, colour for colour, and more than one
process must own painted samples.
"""
import json
import os
import sys

import numpy as np
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray

import ofbParaViewTesting

plugin, reference_dir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())
controller, rank, ranks = ofbParaViewTesting.processes()
# Every process reaches every check with the same values (they are gathered).
say, check = ofbParaViewTesting.reporter("%d ranks" % ranks, rank)


def gather(rows):
    """Every process's rows (n x 5 doubles), concatenated on every process."""
    local = vtkDoubleArray()
    local.SetNumberOfComponents(5)
    for row in rows:
        local.InsertNextTuple(row)
    result = vtkDoubleArray()
    controller.AllGatherV(local, result)  # the lengths differ
    return vtk_to_numpy(result).reshape(-1, 5) if result.GetNumberOfTuples() else np.zeros((0, 5))


# An open pipe along y (radius 0.3, length 1.6) of 96 x 48 quads: a plane rolled up.
plane = Plane(Origin=[0.0, 0.0, 0.0], Point1=[1.0, 0.0, 0.0], Point2=[0.0, 1.0, 0.0],
              XResolution=96, YResolution=48)
pipe = Calculator(Input=plane, CoordinateResults=1,
                  Function="0.3*cos(2*3.141592653589793*coordsX)*iHat"
                           "+(1.6*coordsY-0.8)*jHat"
                           "+0.3*sin(2*3.141592653589793*coordsX)*kHat")
surface = ExtractSurface(Input=RedistributeDataSet(Input=pipe))
sampler = OFBSampler(Input=surface, Resolution=96)


def around(y, angle, radius=0.3):
    return [radius * np.cos(angle), y, radius * np.sin(angle)]


points = []
for i in range(4):  # a ring of three segments, each a third of a turn
    points += around(0.35, 0.3 + 2.0 * np.pi * i / 3.0)
for i in range(1, 21):  # a helix down the pipe
    points += around(0.35 - 1.0 * i / 20.0, 0.3 + 3.0 * np.pi * i / 20.0)
points += around(-0.7, 0.5, 0.05)  # inside the pipe: moved onto the wall
stroke = PolyLineSource(Points=[float(c) for c in points])
paint = OFBPaintStrokes(Input=sampler, Strokes=stroke)
paint.BrushRadius = 0.04
paint.BrushColor = [1.0, 0.0, 0.0, 1.0]
paint.UpdatePipeline()

data = paint.GetClientSideObject().GetOutputDataObject(0)
before = sampler.GetClientSideObject().GetOutputDataObject(0)
arrays = data.GetAttributesAsFieldData(data.POINT)
count = data.GetNumberOfElements(data.POINT)
rows = []
if count:
    colors = vtk_to_numpy(arrays.GetArray("Colors")).astype(np.float64)
    unpainted = vtk_to_numpy(
        before.GetAttributesAsFieldData(before.POINT).GetArray("Colors")).astype(np.float64)
    ghosts = arrays.GetArray("vtkGhostType")
    mine = np.ones(count, dtype=bool) if ghosts is None else vtk_to_numpy(ghosts) == 0
    painted = np.any(colors != unpainted, axis=1)
    rows = np.column_stack((colors, painted))[mine]
all_rows = gather(rows)
owners = gather([[rank, int(np.sum(rows[:, 4])) if len(rows) else 0, 0, 0, 0]])
painted_by = [int(r[1]) for r in owners]
colours, counts = np.unique(all_rows[:, :4], axis=0, return_counts=True)
table = sorted([list(map(int, c)) + [int(n)] for c, n in zip(colours, counts)])
owned = int(len(all_rows))
painted = int(np.sum(all_rows[:, 4]))
say("%d ranks: %d owned samples, %d painted (owned by each process: %s), %d distinct colours"
    % (ranks, owned, painted, painted_by, len(table)))

path = os.path.join(reference_dir, "strokes.json")
if ranks == 1:
    check(painted > 300, "the stroke paints %d samples" % painted)
    if rank == 0:
        with open(path, "w") as f:
            json.dump({"owned": owned, "painted": painted, "colours": table}, f)
    say("wrote the one-process reference")
else:
    with open(path) as f:
        reference = json.load(f)
    check(owned == reference["owned"],
          "owned samples %d, one process %d" % (owned, reference["owned"]))
    check(painted == reference["painted"],
          "painted samples %d, one process %d" % (painted, reference["painted"]))
    differ = sum(1 for a, b in zip(table, reference["colours"]) if a != b) + abs(
        len(table) - len(reference["colours"]))
    check(table == reference["colours"],
          "the colours of the owned samples equal one process's (%d of %d counts differ)"
          % (differ, len(reference["colours"])))
    check(sum(1 for n in painted_by if n > 0) > 1, "the stroke crosses piece borders")
    say("all stroke checks passed on %d ranks" % ranks)
