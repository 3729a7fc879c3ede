#!/usr/bin/env python3
"""Surface LIC at any zoom: the mapper's lookups side by side, from far and close up.

    reader -> rotation field -> vtkOFBSampler -> vtkOFBLIC -> vtkOFBPolyDataMapper
                                                   \\-> vtkOFBLICPyramid (a LIC per level)

Writes two pictures of the same LIC (grey, LICIntensity 1):
- FAR.png: the whole surface small in the window, where many OFB cells share a pixel.
  Left: NearestMipmapped (the LIC filtered down a vtkOFBPyramid: its mean, grey);
  right: Smooth over a vtkOFBLICPyramid (a LIC on every level, levels blended by the
  pixel's footprint: streaks about a pixel wide).
- NEAR.png: a close-up where a cell covers several pixels. Left: Nearest (every cell a
  block); middle: Smooth (interpolated along the surface); right: Smooth on an OFB
  recomputed at the resolution and noise grain that vtkOFBViewResolution gives for the
  close-up (about one cell a pixel).

Run (from a build tree; Debian's python3 has VTK's modules):
    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 \\
        Examples/Python/lic_zoom.py Testing/Data/stanford-bunny.obj far.png near.png
Options: --resolution (OFB cells on the longest side, default 1024), --size (pixels of
one panel), --zoom (the close-up's camera zoom), --maximum-resolution (of the recomputed
OFB).
"""

import argparse

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations)

import vtkofb
from ofb_example_view import read_surface, save_png

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", help="surface (.obj, .ply, .stl or .vtp)")
parser.add_argument("far", help="picture from far to write")
parser.add_argument("near", help="close-up picture to write")
parser.add_argument("--resolution", type=int, default=1024)
parser.add_argument("--size", type=int, default=400, help="pixels of one panel")
parser.add_argument("--zoom", type=float, default=16.0, help="the close-up's camera zoom")
parser.add_argument("--maximum-resolution", type=int, default=2048)
args = parser.parse_args()

# The surface and a rotation field about a tilted axis through its centre.
mesh = read_surface(args.mesh)
points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
center = np.array(mesh.GetBounds()).reshape(3, 2).mean(axis=1)
axis = np.array([0.4, 1.0, 0.3])
axis /= np.linalg.norm(axis)
flow = numpy_support.numpy_to_vtk(np.cross(axis, points - center).astype(np.float32), deep=True)
flow.SetName("Flow")
mesh.GetPointData().SetVectors(flow)


def make_lic(resolution, grain):
    """The sampler and LIC of the mesh at `resolution`, noise grain `grain` cells."""
    sampler = vtkofb.vtkOFBSampler()
    sampler.SetInputData(mesh)
    sampler.SetResolution(resolution)
    lic = vtkofb.vtkOFBLIC()
    lic.SetInputConnection(sampler.GetOutputPort())
    lic.SetNoiseGrainSize(grain)
    lic.SetNoiseGeneratorSeed(1)
    lic.Update()
    return sampler, lic


def make_actor(lic, lookup, level_lic=False):
    """An actor showing the LIC grey with the lookup `lookup` (a mapper's SetLookupModeTo...
    name); with `level_lic`, over a vtkOFBLICPyramid."""
    mapper = vtkofb.vtkOFBPolyDataMapper()
    mapper.SetInputData(mesh)
    mapper.SetOFBConnection(lic.GetOutputPort())
    getattr(mapper, "SetLookupModeTo" + lookup)()
    if level_lic:
        pyramid = vtkofb.vtkOFBLICPyramid()
        pyramid.SetLIC(lic)
        mapper.SetPyramid(pyramid)
    coloring = mapper.GetColoring()
    coloring.SetIntensityArrayName("LIC")
    coloring.IntensityModulationOn()
    coloring.SetLICColorModeToBlend()
    coloring.SetLICIntensity(1.0)
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def window_of(actors, zoom):
    """A window of len(actors) panels side by side, the same camera in each."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(args.size * len(actors), args.size)
    window.SetMultiSamples(0)
    camera = None
    for k, actor in enumerate(actors):
        renderer = vtkRenderer()
        renderer.SetViewport(k / len(actors), 0.0, (k + 1) / len(actors), 1.0)
        renderer.SetBackground(0.1, 0.1, 0.15)
        renderer.AddActor(actor)
        window.AddRenderer(renderer)
        if camera is None:
            camera = renderer.GetActiveCamera()
            renderer.ResetCamera()
            camera.Zoom(zoom)
            renderer.ResetCameraClippingRange()
        else:
            renderer.SetActiveCamera(camera)
            renderer.ResetCameraClippingRange()
    window.Render()
    return window


sampler, lic = make_lic(args.resolution, 1.0)
print(f"{lic.GetOutput().GetNumberOfSamples()} samples at {args.resolution} cells, LIC in "
      f"{lic.GetLastExecutionTime():.0f} ms")

# From far: the whole surface, about 5 cells a pixel.
level_lic = make_actor(lic, "Smooth", True)
far = window_of([make_actor(lic, "NearestMipmapped"), level_lic], 1.0)
pyramid = level_lic.GetMapper().GetPyramid()
print(f"{pyramid.GetNumberOfLevels()} levels, their LICs in "
      f"{1000 * pyramid.GetLastLevelLICTime():.0f} ms")
save_png(far, args.far)

# Close up: the same OFB read nearest and smooth, and an OFB computed for the view.
near = window_of([make_actor(lic, "Nearest"), make_actor(lic, "Smooth")], args.zoom)
view = vtkofb.vtkOFBViewResolution()
view.SetMaximumResolution(args.maximum_resolution)
view.Compute(near.GetRenderers().GetFirstRenderer(), mesh)
print(f"close-up: resolution {view.GetResolution()} and noise grain "
      f"{view.GetNoiseGrainSize():.2f} cells for about one cell a pixel")
sampler2, lic2 = make_lic(view.GetResolution(), view.GetNoiseGrainSize())
print(f"{lic2.GetOutput().GetNumberOfSamples()} samples, LIC in "
      f"{lic2.GetLastExecutionTime():.0f} ms")
near = window_of([make_actor(lic, "Nearest"), make_actor(lic, "Smooth"),
                  make_actor(lic2, "Smooth")], args.zoom)
save_png(near, args.near)
