"""The plumbing the Python examples share, kept out of their pipelines: reading a surface, the view options,
an off-screen window that frames the surface, its picture written as a PNG (and returned
as an array, for the examples' --check), and how much of a picture is vivid colour.

The examples import it from their own folder (Python puts a script's folder on sys.path).
"""

import os
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations)


def read_surface(path):
    """The surface of an .obj (the default), .ply, .stl or .vtp file; exits with a message
    when it has no polygons."""
    readers = {".ply": vtkPLYReader, ".stl": vtkSTLReader, ".vtp": vtkXMLPolyDataReader}
    reader = readers.get(os.path.splitext(path)[1].lower(), vtkOBJReader)()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    if mesh.GetNumberOfPolys() == 0:
        sys.exit(f"{path}: no polygons")
    return mesh


def add_view_options(parser, azimuth=0.0):
    """--size, --up, --azimuth and --elevation, as the examples' help describes them."""
    parser.add_argument("--size", type=int, default=600, help="image width and height (pixels)")
    parser.add_argument("--up", choices=["x", "y", "z"], default="y",
                        help="the mesh's up axis (the bunny's is y, the horse's z)")
    parser.add_argument("--azimuth", type=float, default=azimuth, help="degrees")
    parser.add_argument("--elevation", type=float, default=10.0, help="degrees")


def render_offscreen(actor, args, background=(0.1, 0.1, 0.15)):
    """Render `actor` off screen, seen from the side (up axis `args.up`, turned by
    `args.azimuth` and `args.elevation`) and filling most of a square of `args.size`
    pixels. Returns the window."""
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(*background)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(args.size, args.size)
    window.AddRenderer(renderer)
    frame_camera(renderer, args, 1.4)
    window.Render()
    return window


def frame_camera(renderer, args, dolly):
    """Point the renderer's camera at its props from the side (up axis `args.up`, turned
    by `args.azimuth` and `args.elevation`), reset it and move it closer by `dolly`."""
    up = "xyz".index(args.up)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetPosition(*[1.0 if k == (up + 1) % 3 else 0.0 for k in range(3)])
    camera.SetViewUp(*[1.0 if k == up else 0.0 for k in range(3)])
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    renderer.ResetCamera()
    camera.Dolly(dolly)
    renderer.ResetCameraClippingRange()


def save_png(window, path):
    """Write the window's picture to `path`; returns its pixels, (n, 3) uint8 RGB."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"wrote {path}")
    return numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3]


def vivid_share(rgb, saturation=0.4):
    """The share of pixels of (n, 3) uint8 RGB whose HSV saturation exceeds `saturation`."""
    c = rgb.astype(float) / 255.0
    high = c.max(axis=1)
    return float(np.mean((high - c.min(axis=1)) / np.maximum(high, 1e-6) > saturation))
