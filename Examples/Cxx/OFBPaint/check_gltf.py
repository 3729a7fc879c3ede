#!/usr/bin/env python3
"""OFBPaint's glTF export, read back as another program would: vtkGLTFImporter (VTK's own
reader of glTF 2.0) into an offscreen window, and the picture must show the mesh with a
texture and at least MIN_RED reddish pixels (the demo strokes' red wave).

    /usr/bin/python3 check_gltf.py painted.gltf [MIN_RED] [view.png]
"""

import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOImport import vtkGLTFImporter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations)

path = sys.argv[1]
min_red = int(sys.argv[2]) if len(sys.argv) > 2 else 100
renderer = vtkRenderer()
window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(400, 400)
window.AddRenderer(renderer)
importer = vtkGLTFImporter()
importer.SetFileName(path)
importer.SetRenderWindow(window)
importer.Update()
actors = renderer.GetActors()
if actors.GetNumberOfItems() != 1:
    sys.exit(f"{path}: {actors.GetNumberOfItems()} meshes read, not 1")
actor = actors.GetLastActor()
textures = actor.GetProperty().GetNumberOfTextures() + (actor.GetTexture() is not None)
if textures == 0:
    sys.exit(f"{path}: the mesh has no texture")
renderer.ResetCamera()
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
if len(sys.argv) > 3:
    writer = vtkPNGWriter()
    writer.SetFileName(sys.argv[3])
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
rgb = numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3]
rgb = rgb.astype(int)
red = int(((rgb[:, 0] > 60) & (rgb[:, 0] > 2 * rgb[:, 1]) & (rgb[:, 0] > 2 * rgb[:, 2])).sum())
foreground = int((rgb.sum(axis=1) > 30).sum())
print(f"{path}: 1 textured mesh, {foreground} pixels of it, {red} reddish")
if foreground < 0.1 * rgb.shape[0] or red < min_red:
    sys.exit("check failed")
print("check passed")
