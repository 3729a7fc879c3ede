#!/usr/bin/env python3
"""Exporting a painting: vtkOFB's paint saved in files any VTK, ParaView or 3-D tool reads.

    reader -> vtkOFBSampler -> paint (vtkOFBPainter) -> vtkOFBProbeFilter -> vtkPLYWriter
                             [vtkOFBTextureAtlas ->] -> vtkOFBTextureBaker -> vtkOBJWriter
                                                                         -> vtkGLTFExporter

The OFB holds paint finer than the mesh's triangles. Two ways out of it:
  * vtkOFBProbeFilter gives every point of the mesh the colour of the OFB there (a PLY with
    vertex colours): as fine as the mesh's points, no finer;
  * vtkOFBTextureBaker writes the paint into the mesh's UV texture (an OBJ with its .mtl
    and .png, and the same as a glTF 2.0 file): as fine as the texture, whatever the
    triangles. A mesh without texture
    coordinates (a scan, an isosurface) first gets some from vtkOFBTextureAtlas: charts
    projected on the OFB's own grids, a texel a cell, at most --texture texels a side.
The script paints polka dots and a thin spiral stripe on a mesh (Spot the cow, which has
texture coordinates, or any .obj, .ply, .stl or .vtp), writes both files into
--output-dir, and renders three views
side by side: the OFB itself (vtkOFBPolyDataMapper), the PLY's vertex colours and the
OBJ's texture (both with plain VTK, as any viewer would show them).

Run (from a build tree; Debian's python3 has VTK's modules):
    PYTHONPATH=build/lib/python3.11/dist-packages /usr/bin/python3 \\
        Examples/Python/export_painting.py Testing/Data/spot.obj export.png
    (or Testing/Data/stanford-bunny.obj: texture coordinates made by the atlas)
Data (the C++ applications' inputs and options): .vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl,
.obj or .ply, by content; --block LIST, --time T or --time-step N; --field NAME starts the
paint from that point or cell array in colour (blue to red).
Options: --resolution (OFB cells on the longest side), --texture (texels a side; for an
atlas the most, a texel a cell where that fits),
--output-dir (where spot_painted.ply, .obj, .mtl and .png go), --size (pixels a view),
--up, --azimuth, --elevation, --check (exit with an error unless the files read back
and the texture shows the stripe the vertex colours lose; the ctest uses it).
Headless: prefix with  xvfb-run -a .
"""

import argparse
import colorsys
import math
import os
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkImagingCore import vtkImageExtractComponents
from vtkmodules.vtkIOExport import vtkGLTFExporter
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkOBJWriter
from vtkmodules.vtkIOImport import vtkGLTFImporter
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkTexture, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations)

import vtkofb
from ofb_example_view import (add_data_options, add_view_options, frame_camera, paint_field,
                              read_data_or_exit, vivid_share)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="surface (.vtp .vtu .vtm .pvd .vtk .stl .obj .ply), with or "
                                 "without texture coordinates")
parser.add_argument("png", help="picture of the three views to write")
parser.add_argument("--resolution", type=int, default=1024)
parser.add_argument("--texture", type=int, default=1024)
parser.add_argument("--output-dir", default=".")
add_view_options(parser, azimuth=-50.0)
parser.add_argument("--check", action="store_true")
add_data_options(parser, "start the paint from this point or cell array in colour "
                         "(blue to red)")
args = parser.parse_args()

# 1. Read the mesh and sample it into an OFB.
mesh = read_data_or_exit(args.mesh, args)[0]
sampler = vtkofb.vtkOFBSampler()
sampler.SetInputData(mesh)
sampler.SetResolution(args.resolution)
sampler.Update()
if args.field:
    paint_field(sampler.GetOutput(), args.field)
ofb = sampler.GetOutput()
cell = ofb.GetCellSize()


def sample_position(i):
    x = [0.0, 0.0, 0.0]
    ofb.GetSamplePosition(i, x)
    return x


# 2. Paint: polka dots, then a spiral stripe of 1.5 cells, thinner than the triangles.
painter = vtkofb.vtkOFBPainter()
painter.SetOFB(ofb)
brush = painter.GetBrush()
bounds = mesh.GetBounds()
centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
size = max(bounds[2 * k + 1] - bounds[2 * k] for k in range(3))
rng = np.random.default_rng(5)
dots = vtkPoints()
for i in rng.integers(0, ofb.GetNumberOfSamples(), 40):
    dots.InsertNextPoint(sample_position(int(i)))
brush.SetRadius(0.03 * size)
brush.SetFalloffToSharp()
for k in range(dots.GetNumberOfPoints()):
    brush.SetColor(*colorsys.hsv_to_rgb(k / 40.0, 0.85, 0.95), 1.0)
    painter.Dab(dots.GetPoint(k))
up = "xyz".index(args.up)
a, b = (up + 1) % 3, (up + 2) % 3
brush.SetRadius(1.5 * cell)
brush.SetFalloffToConstant()
brush.SetColor(0.1, 0.1, 0.6, 1.0)
previous = None
turns, steps = 7, 2400
for s in range(steps):
    t = s / steps
    p = list(centre)
    p[up] = bounds[2 * up] + t * (bounds[2 * up + 1] - bounds[2 * up])
    p[a] += size * math.cos(2 * math.pi * turns * t)
    p[b] += size * math.sin(2 * math.pi * turns * t)
    q = sample_position(ofb.FindClosestSample(p, float("inf")))
    if previous is None or math.dist(q, previous) > 0.05 * size:  # lift over jumps
        painter.EndStroke()
        painter.BeginStroke()
    painter.StrokeTo(q)
    previous = q
painter.EndStroke()

# 3. Export: vertex colours (PLY) and the baked texture (OBJ + MTL + PNG).
os.makedirs(args.output_dir, exist_ok=True)
stem = os.path.join(args.output_dir,
                    os.path.splitext(os.path.basename(args.mesh))[0] + "_painted")
probe = vtkofb.vtkOFBProbeFilter()
probe.SetInputData(mesh)
probe.SetOFBData(ofb)
ply = vtkPLYWriter()
ply.SetInputConnection(probe.GetOutputPort())
ply.SetFileName(stem + ".ply")
ply.SetArrayName("Colors")
ply.EnableAlphaOn()
ply.Write()
textured = mesh
texture_size = (args.texture, args.texture)
atlas = None
if mesh.GetPointData().GetTCoords() is None:
    # No texture coordinates: an atlas of charts on the OFB's grids gives some.
    atlas = vtkofb.vtkOFBTextureAtlas()
    atlas.SetInputData(mesh)
    atlas.SetOFBData(ofb)
    atlas.SetMaximumTextureSize(args.texture)
    atlas.Update()
    if atlas.GetAtlasSize()[0] == 0:
        sys.exit(f"{args.mesh}: no texture atlas fits {args.texture} texels a side")
    textured = atlas.GetOutput()
    texture_size = tuple(atlas.GetAtlasSize())
    print(f"texture coordinates made: {atlas.GetNumberOfCharts()} charts in "
          f"{texture_size[0]} x {texture_size[1]} texels, "
          f"{atlas.GetEffectiveTexelsPerCell():g} texel a cell")
baker = vtkofb.vtkOFBTextureBaker()
baker.SetInputData(textured)
baker.SetOFBData(ofb)
baker.SetTextureSize(*texture_size)
rgb = vtkImageExtractComponents()  # the paint is opaque: an RGB texture (an alpha channel
rgb.SetInputConnection(baker.GetOutputPort())  # makes viewers draw the mesh as translucent)
rgb.SetComponents(0, 1, 2)
obj = vtkOBJWriter()
obj.SetInputData(0, textured)
obj.SetInputConnection(1, rgb.GetOutputPort())
obj.SetFileName(stem + ".obj")
obj.Write()
# The same textured mesh as glTF 2.0 (one .gltf, the PNG embedded): vtkGLTFExporter writes
# a scene, here one actor with the baked image as its texture (never rendered).
rgb.Update()
gltf_texture = vtkTexture()
gltf_texture.SetInputData(rgb.GetOutput())
gltf_mapper = vtkPolyDataMapper()
gltf_mapper.SetInputData(textured)
gltf_mapper.ScalarVisibilityOff()
gltf_actor = vtkActor()
gltf_actor.SetMapper(gltf_mapper)
gltf_actor.SetTexture(gltf_texture)
gltf_scene = vtkRenderer()
gltf_scene.AddActor(gltf_actor)
gltf_window = vtkRenderWindow()
gltf_window.AddRenderer(gltf_scene)
gltf = vtkGLTFExporter()
gltf.SetRenderWindow(gltf_window)
gltf.SetFileName(stem + ".gltf")
gltf.InlineDataOn()
gltf.Write()
print(f"wrote {stem}.ply (vertex colours, {probe.GetOutput().GetNumberOfPoints()} points), "
      f"{stem}.obj/.mtl/.png and {stem}.gltf ({baker.GetNumberOfBakedTexels()} texels baked)")

# 4. Read both back, as another program would, and show them beside the OFB.
ply_in = vtkPLYReader()
ply_in.SetFileName(stem + ".ply")
obj_in = vtkOBJReader()
obj_in.SetFileName(stem + ".obj")
png_in = vtkPNGReader()
png_in.SetFileName(stem + ".png")
texture = vtkTexture()
texture.SetInputConnection(png_in.GetOutputPort())
texture.InterpolateOn()

views = []
ofb_mapper = vtkofb.vtkOFBPolyDataMapper()
ofb_mapper.SetInputData(mesh)
ofb_mapper.SetOFB(ofb)
views.append(ofb_mapper)
vertex_mapper = vtkPolyDataMapper()
vertex_mapper.SetInputConnection(ply_in.GetOutputPort())
vertex_mapper.SetColorModeToDirectScalars()
views.append(vertex_mapper)
texture_mapper = vtkPolyDataMapper()
texture_mapper.SetInputConnection(obj_in.GetOutputPort())
texture_mapper.ScalarVisibilityOff()
views.append(texture_mapper)

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(3 * args.size, args.size)
camera = None
for k, mapper in enumerate(views):
    actor = vtkActor()
    actor.SetMapper(mapper)
    if k == 1:
        # Points no triangle uses (the bunny has 1,113) may have no sample near them and
        # get alpha 0: never drawn, but VTK would draw the whole actor as translucent.
        actor.ForceOpaqueOn()
    if k == 2:
        actor.SetTexture(texture)
    renderer = vtkRenderer()
    renderer.SetViewport(k / 3.0, 0.0, (k + 1) / 3.0, 1.0)
    renderer.SetBackground(0.1, 0.1, 0.15)
    renderer.AddActor(actor)
    window.AddRenderer(renderer)
    if camera is None:
        frame_camera(renderer, args, 1.3)
        camera = renderer.GetActiveCamera()
    else:
        renderer.SetActiveCamera(camera)
        renderer.ResetCameraClippingRange()
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(args.png)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print(f"wrote {args.png} (left: the OFB, middle: the PLY's vertex colours, right: the OBJ's "
      f"texture)")

if args.check:
    w = 3 * args.size
    rgb = numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3]
    rgb = rgb.reshape(args.size, w, 3).astype(float)
    left, middle, right = (rgb[:, k * args.size:(k + 1) * args.size] for k in range(3))
    foreground = np.abs(left - [0.1 * 255, 0.1 * 255, 0.15 * 255]).sum(axis=2) > 30
    texture_error = np.abs(right - left)[foreground].mean()
    vertex_error = np.abs(middle - left)[foreground].mean()
    ply_in.Update()
    obj_in.Update()
    png_in.Update()
    colours = ply_in.GetOutput().GetPointData().GetScalars()
    problems = []
    if colours is None or colours.GetNumberOfComponents() != 4:
        problems.append("the PLY has no RGBA vertex colours")
    if obj_in.GetOutput().GetPointData().GetTCoords() is None:
        problems.append("the OBJ has no texture coordinates")
    if png_in.GetOutput().GetDimensions()[:2] != texture_size:
        problems.append("the texture PNG has the wrong size")
    # The glTF, read back by VTK's importer: one mesh, textured.
    gltf_in = vtkGLTFImporter()
    gltf_in.SetFileName(stem + ".gltf")
    gltf_in.SetRenderWindow(vtkRenderWindow())
    gltf_in.Update()
    imported = gltf_in.GetRenderer().GetActors()
    if imported.GetNumberOfItems() != 1 or \
            imported.GetLastActor().GetProperty().GetNumberOfTextures() == 0:
        problems.append("the glTF does not read back as one textured mesh")
    if foreground.mean() < 0.1:
        problems.append("the mesh covers too little of the view")
    if not texture_error < 12.0:
        problems.append(f"the texture is {texture_error:.1f} grey levels from the OFB's view")
    # A mesh made with UVs (spot) is coarser than the stripe: the texture keeps it, the
    # vertex colours lose it. A fine scan (the bunny) has vertices as dense as the cells.
    if atlas is None and not texture_error < 0.6 * vertex_error:
        problems.append(f"the texture ({texture_error:.1f} grey levels from the OFB's view) "
                        f"is not much closer than the vertex colours ({vertex_error:.1f})")
    if vivid_share(right.reshape(-1, 3).astype(np.uint8)) < 0.5 * vivid_share(
            left.reshape(-1, 3).astype(np.uint8)):
        problems.append("the texture lost the paint's colours")
    print(f"check: mean difference from the OFB's view: texture {texture_error:.1f}, "
          f"vertex colours {vertex_error:.1f} (grey levels)")
    if problems:
        sys.exit("check failed: " + "; ".join(problems))
    print("check passed")
