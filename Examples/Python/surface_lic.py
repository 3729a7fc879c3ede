#!/usr/bin/env python3
"""Surface LIC with vtkOFB: a plain VTK pipeline, one step after the other.

    reader -> field computed here -> vtkOFBSampler -> vtkOFBLIC -> vtkOFBPolyDataMapper -> PNG

The input is a mesh or a simulation result (.vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl,
.obj, .ply; the C++ applications' inputs) with --block and --time / --time-step. The vector
field is --field (a point or cell array of 3 components), else the tangential part of a
rotation about a tilted axis through the centre of the mesh (the sampler projects it into
the tangent plane of every sample).
The LIC is computed once, on the surface (not on the screen), and shown as the
intensity of the surface colour: a scalar (the flow's speed) through a lookup table, or
grey.

Run (from a build tree; Debian's python3 has VTK's modules):
    PYTHONPATH=build/lib/python3.11/dist-packages /usr/bin/python3 \
        Examples/Python/surface_lic.py Testing/Data/stanford-bunny.obj lic.png
Options: --resolution (OFB cells on the longest side), --steps, --grain, --noise
(uniform, gaussian, perlin), --color (speed or grey), --lookup (idw, nearest,
nearestmipmapped: how the mapper reads the OFB), --size (pixels), --up (the mesh's
up axis), --azimuth and --elevation (degrees), --export FILE.obj (the LIC in colour as
an OBJ with its .mtl and a PNG texture that any viewer reads: vtkOFBMapToColors writes
the colours the mapper shows, vtkOFBTextureAtlas gives the mesh texture coordinates,
vtkOFBTextureBaker bakes them; the OBJ read back by plain VTK is drawn into
PNG-stem_exported.png), --check (exit with an error unless the LIC and the images look
right; the ctest uses it).
Headless: prefix with  xvfb-run -a .
"""

import argparse
import os
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkImagingCore import vtkImageExtractComponents
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkOBJWriter
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkTexture

import vtkofb
from ofb_example_view import (add_data_options, add_view_options, read_data_or_exit,
                              render_offscreen, save_png)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="data to show (.vtp .vtu .vtm .pvd .vtk .stl .obj .ply)")
add_data_options(parser, "the vector field: a point or cell array of 3 components (default: "
                         "a rotation)")
parser.add_argument("png", help="image to write")
parser.add_argument("--resolution", type=int, default=512)
parser.add_argument("--steps", type=int, default=20)
parser.add_argument("--grain", type=float, default=1.0)
parser.add_argument("--noise", choices=["uniform", "gaussian", "perlin"], default="gaussian")
parser.add_argument("--color", choices=["speed", "grey"], default="speed")
parser.add_argument("--mode", choices=["map", "blend"], default="map",
                    help="how the LIC combines with the speed colouring (VTK's ColorMode)")
parser.add_argument("--lookup", choices=["idw", "nearest", "nearestmipmapped"], default="idw",
                    help="how the display reads the OFB: inverse-distance weights, the "
                         "nearest sample, or the nearest in the mipmap level as fine as a "
                         "pixel (for large OFBs seen whole)")
add_view_options(parser)
parser.add_argument("--export", metavar="FILE.obj",
                    help="write the LIC in colour as a textured OBJ (with .mtl and .png)")
parser.add_argument("--check", action="store_true")
args = parser.parse_args()

# 1. Read the surface (its blocks merged, at the chosen time step) and the field.
mesh, field, field_on_cells = read_data_or_exit(args.mesh, args, vectors=True)

# 2. The vector field (--field, on points or cells, else a rotation about a tilted axis
#    through the centre of the mesh) and a scalar to colour by (its speed).
if field is not None:
    attributes = mesh.GetCellData() if field_on_cells else mesh.GetPointData()
    # The sampler takes cell vectors when the points have none active.
    other = mesh.GetPointData() if field_on_cells else mesh.GetCellData()
    other.SetActiveAttribute(-1, vtkDataSetAttributes.VECTORS)
    attributes.SetVectors(field)
    flow = numpy_support.vtk_to_numpy(field).astype(np.float64).reshape(-1, 3)
else:
    attributes = mesh.GetPointData()
    points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    bounds = np.array(mesh.GetBounds()).reshape(3, 2)
    center = bounds.mean(axis=1)
    axis = np.array([0.4, 1.0, 0.3])
    axis /= np.linalg.norm(axis)
    flow = np.cross(axis, points - center).astype(np.float32)
    flow_array = numpy_support.numpy_to_vtk(flow, deep=True)
    flow_array.SetName("Flow")
    attributes.SetVectors(flow_array)
speed_array = numpy_support.numpy_to_vtk(np.linalg.norm(flow, axis=1), deep=True)
speed_array.SetName("Speed")
attributes.AddArray(speed_array)

# 3. The OFB: samples of the surface on three grids, with the field and the speed.
sampler = vtkofb.vtkOFBSampler()
sampler.SetInputData(mesh)
sampler.SetResolution(args.resolution)

# 4. The LIC at every sample (VTK surface LIC's settings and names).
lic = vtkofb.vtkOFBLIC()
lic.SetInputConnection(sampler.GetOutputPort())
lic.SetNumberOfSteps(args.steps)
lic.SetStepSize(1.0)                     # in OFB cells
lic.SetNoiseGrainSize(args.grain)        # in OFB cells
lic.SetNoiseType({"uniform": vtkofb.vtkOFBLIC.NOISE_TYPE_UNIFORM,
                  "gaussian": vtkofb.vtkOFBLIC.NOISE_TYPE_GAUSSIAN,
                  "perlin": vtkofb.vtkOFBLIC.NOISE_TYPE_PERLIN}[args.noise])
lic.SetNoiseGeneratorSeed(1)
lic.EnhancedLICOn()
lic.SetEnhanceContrast(vtkofb.vtkOFBLIC.ENHANCE_CONTRAST_LIC)
lic.Update()
print(f"{lic.GetOutput().GetNumberOfSamples()} samples, LIC in "
      f"{lic.GetLastExecutionTime():.0f} ms")

# 5. The mapper colours every fragment from the OFB; the "LIC" array is the intensity.
mapper = vtkofb.vtkOFBPolyDataMapper()
mapper.SetInputData(mesh)
mapper.SetOFBConnection(lic.GetOutputPort())
{"idw": mapper.SetLookupModeToInverseDistance,
 "nearest": mapper.SetLookupModeToNearest,
 "nearestmipmapped": mapper.SetLookupModeToNearestMipmapped}[args.lookup]()
coloring = mapper.GetColoring()     # vtkOFBColoring: shared with the export below
coloring.SetIntensityArrayName("LIC")
coloring.IntensityModulationOn()
if args.color == "speed":
    lut = vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.Build()
    coloring.SetLookupTable(lut)
    coloring.SetScalarRange(speed_array.GetRange())
    coloring.SetColorSourceToScalars()
    coloring.SetScalarArrayName("Speed")
    # VTK surface LIC's colour modes: "map" multiplies the colour by LIC + MapModeBias,
    # "blend" mixes the LIC grey in by LICIntensity (VTK's default 0.8).
    if args.mode == "map":
        coloring.SetLICColorModeToMap()
        coloring.SetMapModeBias(0.1)
    else:
        coloring.SetLICColorModeToBlend()
        coloring.SetLICIntensity(0.8)
else:
    coloring.SetLICColorModeToBlend()
    coloring.SetLICIntensity(1.0)          # the LIC alone

actor = vtkActor()
actor.SetMapper(mapper)

# 6. Render off screen (ofb_example_view.py: a renderer, the camera on the side) and
#    write the image.
window = render_offscreen(actor, args)
image = save_png(window, args.png)

# 7. With --export: what the mapper shows, as a textured OBJ. vtkOFBMapToColors takes the
#    mapper's colouring (the same vtkOFBColoring) and writes it per sample ("DisplayColors");
#    vtkOFBTextureAtlas gives the triangles texture coordinates (a tile each, a texel an
#    OFB cell); the baker writes the colours into the atlas; the OBJ writer writes the
#    .obj, the .mtl and the texture as a PNG (RGB: opaque).
exported = None
if args.export:
    colors = vtkofb.vtkOFBMapToColors()
    colors.SetInputConnection(lic.GetOutputPort())
    colors.SetColoring(coloring)
    triangles = vtkTriangleFilter()
    triangles.SetInputData(mesh)
    atlas = vtkofb.vtkOFBTextureAtlas()
    atlas.SetInputConnection(triangles.GetOutputPort())
    atlas.SetOFBConnection(lic.GetOutputPort())
    atlas.Update()
    baker = vtkofb.vtkOFBTextureBaker()
    baker.SetInputConnection(atlas.GetOutputPort())
    baker.SetOFBConnection(colors.GetOutputPort())
    # (no SetArrayName: the baker bakes the active scalars, vtkOFBMapToColors's output)
    baker.SetTextureSize(atlas.GetAtlasSize())
    rgb = vtkImageExtractComponents()
    rgb.SetInputConnection(baker.GetOutputPort())
    rgb.SetComponents(0, 1, 2)
    obj = vtkOBJWriter()
    obj.SetInputConnection(0, atlas.GetOutputPort())
    obj.SetInputConnection(1, rgb.GetOutputPort())
    obj.SetFileName(args.export)
    if not obj.Write():
        sys.exit(f"cannot write {args.export}")
    width, height = atlas.GetAtlasSize()
    print(f"wrote {args.export} with a {width} x {height} texture "
          f"({baker.GetNumberOfBakedTexels()} texels baked)")

    # Read back as any program would, drawn by a plain vtkPolyDataMapper with the texture.
    stem = os.path.splitext(args.export)[0]
    obj_in = vtkOBJReader()
    obj_in.SetFileName(args.export)
    png_in = vtkPNGReader()
    png_in.SetFileName(stem + ".png")
    texture = vtkTexture()
    texture.SetInputConnection(png_in.GetOutputPort())
    texture.InterpolateOn()
    plain = vtkPolyDataMapper()
    plain.SetInputConnection(obj_in.GetOutputPort())
    plain.ScalarVisibilityOff()
    textured = vtkActor()
    textured.SetMapper(plain)
    textured.SetTexture(texture)
    exported = save_png(render_offscreen(textured, args),
                        os.path.splitext(args.png)[0] + "_exported.png")

# 8. With --check: the LIC is in [0, 1] and not flat; the surface fills the image, drawn
# from the OFB; the exported OBJ looks like it (mean difference over the pixels where
# either shows the surface).
if args.check and exported is not None:
    surface = np.any(np.abs(image.astype(int) - [25, 25, 38]) > 8, axis=1)
    surface |= np.any(np.abs(exported.astype(int) - [25, 25, 38]) > 8, axis=1)
    difference = np.abs(image.astype(int) - exported.astype(int))[surface].mean()
    print(f"the exported OBJ's picture differs from the OFB's by {difference:.1f} levels "
          f"on average")
    if not difference < 12.0:
        sys.exit("check failed: the export does not look like the display")
if args.check:
    values = numpy_support.vtk_to_numpy(lic.GetOutput().GetSampleData().GetArray("LIC"))
    covered = np.mean(np.any(np.abs(image.astype(int) - [25, 25, 38]) > 8, axis=1))
    print(f"LIC in [{values.min():.3f}, {values.max():.3f}], std {values.std():.3f}; "
          f"surface on {100 * covered:.0f} % of the image")
    if not (values.min() >= 0.0 and values.max() <= 1.0 and values.std() > 0.05
            and covered > 0.2 and mapper.GetLastRenderUsedOFB()):
        sys.exit("check failed")
