#!/usr/bin/env python3
"""Decals with vtkOFB: an image stamped on a surface so that it follows the surface.

    reader -> vtkOFBSampler -> vtkOFBTextureProjector (x N) -> vtkOFBPolyDataMapper -> PNG
                 vtkOFBDecalPatch (one a decal) -^

A decal is the paper's surface-aligned brush (Fig. 12): vtkOFBDecalPatch traces a grid
over the surface from a centre along a direction (distances along the surface, the
direction carried across the triangles), with texture coordinates; vtkOFBTextureProjector
writes the image into the OFB's colours on that patch, composited by the image's alpha.
The badge made here (a ring, a disc and an arrow along the decal's direction, transparent
around) is stamped at a few places of the mesh, of a few sizes, over its curvature (the
bunny's ears, back and flank): each stays round and points along the mesh's up axis.

Run (from a build tree; Debian's python3 has VTK's modules):
    PYTHONPATH=build/lib/python3.11/dist-packages /usr/bin/python3 \\
        Examples/Python/decal_stamp.py Testing/Data/stanford-bunny.obj decals.png
Data (the C++ applications' inputs and options): .vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl,
.obj or .ply, by content; --block LIST, --time T or --time-step N; --field NAME starts the
paint from that point or cell array in colour (blue to red).
Options: --resolution (OFB cells on the longest side), --decals (how many), --size,
--up, --azimuth, --elevation, --check (exit with an error unless every decal was
stamped and the picture shows them; the ctest uses it). Headless: prefix with xvfb-run -a.
"""

import argparse
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkActor

import vtkofb
from ofb_example_view import (add_data_options, add_view_options, read_data_or_exit,
                              paint_field, render_offscreen, save_png, vivid_share)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="surface to decorate (.vtp .vtu .vtm .pvd .vtk .stl .obj "
                                 ".ply)")
parser.add_argument("png", help="image to write")
parser.add_argument("--resolution", type=int, default=1024)
parser.add_argument("--decals", type=int, default=7)
add_view_options(parser, azimuth=30.0)
parser.add_argument("--check", action="store_true")
add_data_options(parser, "start the paint from this point or cell array in colour "
                         "(blue to red)")
args = parser.parse_args()

# 1. The surface and its OFB.
mesh = read_data_or_exit(args.mesh, args)[0]
sampler = vtkofb.vtkOFBSampler()
sampler.SetInputData(mesh)
sampler.SetResolution(args.resolution)
sampler.Update()
if args.field:
    paint_field(sampler.GetOutput(), args.field)
ofb = sampler.GetOutput()

# 2. The badge: 256 x 256 RGBA, row 0 at the bottom (v = 0), transparent outside.
n = 256
v, u = np.mgrid[0:n, 0:n]
x, y = (u + 0.5) / n * 2.0 - 1.0, (v + 0.5) / n * 2.0 - 1.0
r = np.hypot(x, y)
rgba = np.zeros((n, n, 4), np.uint8)
rgba[r < 1.0] = (20, 40, 120, 255)                     # ring
rgba[r < 0.78] = (250, 200, 40, 255)                   # disc
arrow = (x > -0.5) & (x < 0.6) & (np.abs(y) < 0.42 * (0.6 - x) / 1.1)
shaft = (x > -0.55) & (x < 0.0) & (np.abs(y) < 0.12)
rgba[(arrow | shaft) & (r < 0.78)] = (200, 30, 30, 255)  # arrow along +u
badge = vtkImageData()
badge.SetDimensions(n, n, 1)
badge.GetPointData().SetScalars(numpy_support.numpy_to_vtk(rgba.reshape(-1, 4), deep=True))

# 3. The decals: centres on the side the camera sees, spread out (each the candidate
#    farthest from those chosen), the mesh's up axis as their direction.
up = "xyz".index(args.up)
direction = [1.0 if k == up else 0.0 for k in range(3)]
side, third = (up + 1) % 3, (up + 2) % 3
towards_camera = np.zeros(3)
towards_camera[side] = np.cos(np.radians(args.azimuth))
towards_camera[third] = np.sin(np.radians(args.azimuth))
normals = numpy_support.vtk_to_numpy(ofb.GetSampleData().GetArray("Normals"))
rng = np.random.default_rng(3)
candidates = rng.integers(ofb.GetNumberOfSamples(), size=4000)
candidates = candidates[normals[candidates] @ towards_camera > 0.7]


def sample_position(i):
    x = [0.0, 0.0, 0.0]
    ofb.GetSamplePosition(int(i), x)
    return np.array(x)


positions = np.array([sample_position(i) for i in candidates])
chosen = [positions[0]]
while len(chosen) < args.decals:
    distance = np.min([np.linalg.norm(positions - c, axis=1) for c in chosen], axis=0)
    chosen.append(positions[np.argmax(distance)])
size = mesh.GetLength() / np.sqrt(3.0)
stage = sampler
stamped = []
for centre in chosen:
    width = size * rng.uniform(0.12, 0.25)
    decal = vtkofb.vtkOFBDecalPatch()
    decal.SetInputData(mesh)
    decal.SetCenter(*centre)
    decal.SetDirection(direction)
    decal.SetWidth(width)
    decal.SetHeight(width)
    decal.SetResolution(48, 48)
    projector = vtkofb.vtkOFBTextureProjector()
    projector.SetInputConnection(stage.GetOutputPort())
    projector.SetMeshConnection(decal.GetOutputPort())
    projector.SetTextureData(badge)
    projector.RepeatTextureOff()       # the decal's edge texels at its edges
    projector.SetMaximumDistance(1.0)  # cells: the patch's rim does not spread
    stage = projector
    stamped.append(projector)
stage.Update()
counts = [p.GetNumberOfProjectedSamples() for p in stamped]
print(f"{len(counts)} decals, {sum(counts)} samples stamped ({min(counts)} to {max(counts)} a decal)")

# 4. Show the OFB on the surface.
mapper = vtkofb.vtkOFBPolyDataMapper()
mapper.SetInputData(mesh)
mapper.SetOFBConnection(stage.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
window = render_offscreen(actor, args)
image = save_png(window, args.png)

if args.check:
    share = vivid_share(image)
    print(f"vivid colour on {100 * share:.1f} % of the picture")
    if min(counts) == 0 or share < 0.01 or not mapper.GetLastRenderUsedOFB():
        sys.exit("check failed")
    print("check passed")
