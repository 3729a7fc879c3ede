#!/usr/bin/env python3
"""Surface LIC with vtkOFB: a plain VTK pipeline, one step after the other.

    reader -> field computed here -> vtkOFBSampler -> vtkOFBLIC -> vtkOFBPolyDataMapper -> PNG

The vector field is the tangential part of a rotation about a tilted axis through the
centre of the mesh (the sampler projects it into the tangent plane of every sample).
The LIC is computed once, on the surface (not on the screen), and shown as the
intensity of the surface colour: a scalar (the flow's speed) through a lookup table, or
grey.

Run (from a build tree; Debian's python3 has VTK's modules):
    PYTHONPATH=build/lib/python3.11/dist-packages /usr/bin/python3 \
        Examples/Python/surface_lic.py Testing/Data/stanford-bunny.obj lic.png
Options: --resolution (OFB cells on the longest side), --steps, --grain, --noise
(uniform, gaussian, perlin), --color (speed or grey), --lookup (idw, nearest,
nearestmipmapped: how the mapper reads the OFB), --size (pixels), --up (the mesh's
up axis), --azimuth and --elevation (degrees), --check (exit
with an error unless the LIC and the image look right; the ctest uses it).
Headless: prefix with  xvfb-run -a .
"""

import argparse
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkRenderingCore import vtkActor

import vtkofb
from ofb_example_view import add_view_options, read_surface, render_offscreen, save_png

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="surface to show (.obj, .ply, .stl or .vtp)")
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
parser.add_argument("--check", action="store_true")
args = parser.parse_args()

# 1. Read the surface.
mesh = read_surface(args.mesh)

# 2. The vector field: a rotation about a tilted axis through the centre of the mesh,
#    and a scalar to colour by (its speed).
points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
bounds = np.array(mesh.GetBounds()).reshape(3, 2)
center = bounds.mean(axis=1)
axis = np.array([0.4, 1.0, 0.3])
axis /= np.linalg.norm(axis)
flow = np.cross(axis, points - center).astype(np.float32)
flow_array = numpy_support.numpy_to_vtk(flow, deep=True)
flow_array.SetName("Flow")
mesh.GetPointData().SetVectors(flow_array)
speed_array = numpy_support.numpy_to_vtk(np.linalg.norm(flow, axis=1), deep=True)
speed_array.SetName("Speed")
mesh.GetPointData().AddArray(speed_array)

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
mapper.SetIntensityArrayName("LIC")
mapper.IntensityModulationOn()
if args.color == "speed":
    lut = vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.Build()
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(speed_array.GetRange())
    mapper.SetColorSourceToScalars()
    mapper.SetScalarArrayName("Speed")
    # VTK surface LIC's colour modes: "map" multiplies the colour by LIC + MapModeBias,
    # "blend" mixes the LIC grey in by LICIntensity (VTK's default 0.8).
    if args.mode == "map":
        mapper.SetLICColorModeToMap()
        mapper.SetMapModeBias(0.1)
    else:
        mapper.SetLICColorModeToBlend()
        mapper.SetLICIntensity(0.8)
else:
    mapper.SetLICColorModeToBlend()
    mapper.SetLICIntensity(1.0)          # the LIC alone

actor = vtkActor()
actor.SetMapper(mapper)

# 6. Render off screen (ofb_example_view.py: a renderer, the camera on the side) and
#    write the image.
window = render_offscreen(actor, args)
image = save_png(window, args.png)

# 7. With --check: the LIC is in [0, 1] and not flat; the surface fills the image, drawn
# from the OFB.
if args.check:
    values = numpy_support.vtk_to_numpy(lic.GetOutput().GetSampleData().GetArray("LIC"))
    covered = np.mean(np.any(np.abs(image.astype(int) - [25, 25, 38]) > 8, axis=1))
    print(f"LIC in [{values.min():.3f}, {values.max():.3f}], std {values.std():.3f}; "
          f"surface on {100 * covered:.0f} % of the image")
    if not (values.min() >= 0.0 and values.max() <= 1.0 and values.std() > 0.05
            and covered > 0.2 and mapper.GetLastRenderUsedOFB()):
        sys.exit("check failed")
