#!/usr/bin/env python3
"""Painting with vtkOFB from a script: strokes as polylines, painted by pipeline filters.

    reader -> vtkOFBBuilder -> vtkOFBPaintFilter (colour) -> vtkOFBPaintFilter (smear)
           -> vtkOFBPaintFilter (bumps) -> vtkOFBPolyDataMapper -> PNG (and .ofb)

The strokes are made here: rings around the mesh at a few heights, each point found by
casting a ray from outside towards the mesh's vertical axis (vtkOBBTree), with point
arrays the paint filter reads: "Color" (a hue that turns along the ring), "Radius"
(world units) and "Pressure" (which scales the radius and the strength). A second
filter smears the rings with strokes from top to bottom (the paper's Eq. 3), a third
presses a groove into the normals (section 9.2.1) that the mapper shades with
UsePaintedNormals. Each filter's output is a painted copy; the OFB before it is not
changed, so the script can keep, compare and save every stage.

Run (from a build tree; Debian's python3 has VTK's modules):
    PYTHONPATH=build/lib/python3.11/dist-packages /usr/bin/python3 \
        Examples/Python/paint_strokes.py Testing/Data/stanford-bunny.obj paint.png
Data (the C++ applications' inputs and options): .vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl,
.obj or .ply, by content; --block LIST, --time T or --time-step N; --field NAME starts the
paint from that point or cell array in colour (blue to red).
Options: --resolution (OFB cells on the longest side), --rings, --size (pixels),
--up (the mesh's up axis), --azimuth and --elevation (degrees), --save FILE.ofb (the
painted OFB, for OFBPaint --load or vtkOFBReader), --check (exit with an error unless
the painting and the image look right; the ctest uses it).
Headless: prefix with  xvfb-run -a .
"""

import argparse
import colorsys
import math
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersGeneral import vtkOBBTree
from vtkmodules.vtkRenderingCore import vtkActor

import vtkofb
from ofb_example_view import (add_data_options, add_view_options, read_data_or_exit,
                              paint_field, render_offscreen, save_png, vivid_share)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="surface to paint (.vtp .vtu .vtm .pvd .vtk .stl .obj "
                                 ".ply)")
parser.add_argument("png", help="image to write")
parser.add_argument("--resolution", type=int, default=512)
parser.add_argument("--rings", type=int, default=5)
add_view_options(parser, azimuth=20.0)
parser.add_argument("--save", help="write the painted OFB to this .ofb file")
parser.add_argument("--check", action="store_true")
add_data_options(parser, "start the paint from this point or cell array in colour "
                         "(blue to red)")
args = parser.parse_args()

# 1. Read the surface.
mesh = read_data_or_exit(args.mesh, args)[0]

# 2. The OFB (built on the GPU where VTK's OpenGL context allows it, else on the CPU).
builder = vtkofb.vtkOFBBuilder()
builder.SetInputData(mesh)
builder.SetResolution(args.resolution)
builder.Update()
if args.field:
    paint_field(builder.GetOutput(), args.field)
cell = builder.GetOutput().GetCellSize()
built = numpy_support.vtk_to_numpy(builder.GetOutput().GetSampleData().GetArray("Colors")).copy()

# 3. Strokes on the surface: a ray from outside towards the vertical axis hits the
#    surface first where a brush would touch it. A ray that misses ends the polyline.
up = "xyz".index(args.up)
u, v = (up + 1) % 3, (up + 2) % 3
bounds = np.array(mesh.GetBounds()).reshape(3, 2)
center = bounds.mean(axis=1)
reach = 2.0 * np.linalg.norm(bounds[:, 1] - bounds[:, 0])
tree = vtkOBBTree()
tree.SetDataSet(mesh)
tree.BuildLocator()


def surface_point(height, angle):
    """The first surface point on the ray at `height` coming in at `angle`, or None."""
    outside, inside = center.copy(), center.copy()
    outside[up] = inside[up] = height
    outside[u] += reach * math.cos(angle)
    outside[v] += reach * math.sin(angle)
    hits = vtkPoints()
    tree.IntersectWithLine(outside.tolist(), inside.tolist(), hits, None)
    return hits.GetPoint(0) if hits.GetNumberOfPoints() > 0 else None


class Strokes:
    """Polylines with the per-point arrays vtkOFBPaintFilter reads."""

    def __init__(self):
        self.points = vtkPoints()
        self.lines = vtkCellArray()
        self.arrays = {}
        self.current = []

    def add(self, x, **values):
        if x is None:
            self.end()
            return
        self.current.append(self.points.InsertNextPoint(x))
        for name, value in values.items():
            if name not in self.arrays:
                array = vtkFloatArray() if name == "Color" else vtkDoubleArray()
                array.SetName(name)
                array.SetNumberOfComponents(len(value) if name == "Color" else 1)
                self.arrays[name] = array
            self.arrays[name].InsertNextTuple(value if name == "Color" else (value,))

    def end(self):
        if len(self.current) > 1:
            self.lines.InsertNextCell(len(self.current), self.current)
        self.current = []

    def polydata(self):
        self.end()
        data = vtkPolyData()
        data.SetPoints(self.points)
        data.SetLines(self.lines)
        for array in self.arrays.values():
            data.GetPointData().AddArray(array)
        return data


low, high = bounds[up][0], bounds[up][1]
rings = Strokes()
for r in range(args.rings):
    height = low + (high - low) * (r + 1) / (args.rings + 1)
    for k in range(241):
        t = k / 240.0
        rgb = colorsys.hsv_to_rgb((t + r / args.rings) % 1.0, 0.85, 0.95)
        rings.add(surface_point(height, 2.0 * math.pi * t), Color=rgb,
                  Radius=(6.0 + 2.0 * r) * cell * args.resolution / 256.0,
                  Pressure=0.6 + 0.4 * math.sin(6.0 * math.pi * t))
    rings.end()
smears = Strokes()
for k in range(6):
    angle = 2.0 * math.pi * (k + 0.5) / 6.0
    for j in range(121):
        smears.add(surface_point(high - (high - low) * j / 120.0, angle))
    smears.end()
groove = Strokes()
for k in range(181):
    groove.add(surface_point(low + 0.5 * (high - low), 2.0 * math.pi * k / 180.0))

# 4. Three paint filters, one after the other; each output is a painted copy.
paint = vtkofb.vtkOFBPaintFilter()
paint.SetInputConnection(builder.GetOutputPort())
paint.SetStrokesData(rings.polydata())
paint.GetBrush().SetFalloffToSmooth()
paint.GetBrush().SetStrength(0.9)

smear = vtkofb.vtkOFBPaintFilter()
smear.SetInputConnection(paint.GetOutputPort())
smear.SetStrokesData(smears.polydata())
smear.GetBrush().SetTargetToSmear()
smear.GetBrush().SetSmearAmount(0.9)
smear.GetBrush().SetRadiusInCells(6.0 * args.resolution / 256.0, builder.GetOutput())

bumps = vtkofb.vtkOFBPaintFilter()
bumps.SetInputConnection(smear.GetOutputPort())
bumps.SetStrokesData(groove.polydata())
bumps.GetBrush().SetTargetToNormal()
bumps.GetBrush().SetBumpDepth(-0.4)                # negative: pressed in
bumps.GetBrush().SetRadiusInCells(5.0 * args.resolution / 256.0, builder.GetOutput())
bumps.Update()
for name, f in (("colour", paint), ("smear", smear), ("bumps", bumps)):
    print(f"{name}: {f.GetNumberOfChangedSamples()} samples changed")

# 5. The mapper colours every fragment from the painted OFB and shades the bumps.
mapper = vtkofb.vtkOFBPolyDataMapper()
mapper.SetInputData(mesh)
mapper.SetOFBConnection(bumps.GetOutputPort())
mapper.UsePaintedNormalsOn()
actor = vtkActor()
actor.SetMapper(mapper)

# 6. Render off screen (ofb_example_view.py: a renderer, the camera on the side), write
#    the image, and the painted OFB if asked.
window = render_offscreen(actor, args)
image = save_png(window, args.png)
if args.save:
    ofb_writer = vtkofb.vtkOFBWriter()
    ofb_writer.SetInputConnection(bumps.GetOutputPort())
    ofb_writer.SetFileName(args.save)
    if not ofb_writer.Write():
        sys.exit(f"could not write {args.save}")
    print(f"wrote {args.save}")

# 7. With --check: every stage painted something and left its input as it was; the
# smear changed colours only where the rings had put colour; the groove changed normals,
# not colours; the image shows the rings' hues.
if args.check:
    def colors(algorithm):
        array = algorithm.GetOutput().GetSampleData().GetArray("Colors")
        return None if array is None else numpy_support.vtk_to_numpy(array).copy()

    painted, smeared, bumped = colors(paint), colors(smear), colors(bumps)
    normals_in = numpy_support.vtk_to_numpy(smear.GetOutput().GetSampleData().GetArray("Normals"))
    normals_out = numpy_support.vtk_to_numpy(bumps.GetOutput().GetSampleData().GetArray("Normals"))
    white = np.all(painted == built, axis=1)     # not painted
    smear_changed = np.any(smeared != painted, axis=1) if smeared is not None else None
    colourful = vivid_share(image)
    print(f"painted {np.count_nonzero(~white) if white is not None else 0} samples, smear "
          f"changed {np.count_nonzero(smear_changed) if smear_changed is not None else 0}, "
          f"groove moved {np.count_nonzero(np.any(normals_out != normals_in, axis=1))} normals; "
          f"saturated colour on {100 * colourful:.1f} % of the image")
    ok = (np.array_equal(colors(builder), built)     # the builder's OFB is not painted
          and np.count_nonzero(~white) == paint.GetNumberOfChangedSamples() > 0
          # (a sample the smear changes and a later dab of it changes back counts too)
          and 0 < np.count_nonzero(smear_changed) <= smear.GetNumberOfChangedSamples()
          and np.array_equal(smeared, bumped)        # the groove leaves colours alone
          and np.count_nonzero(np.any(normals_out != normals_in, axis=1))
          == bumps.GetNumberOfChangedSamples() > 0
          and colourful > 0.02 and mapper.GetLastRenderUsedOFB())
    if not ok:
        sys.exit("check failed")
