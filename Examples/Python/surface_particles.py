#!/usr/bin/env python3
"""Surface particles as a plain VTK pipeline: a mesh or simulation result with its vector
field (--field, a point or cell array; else a rotation), its OFB,
vtkOFBParticleAdvector painting it, vtkOFBPolyDataMapper drawing it, and the
particles' trails as lines. Animated in a window, or headless with --image.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages:
    python3 Examples/Python/surface_particles.py [data file] [--image out.png]
The data file: .vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl, .obj or .ply (the C++
applications' inputs). Options: --field NAME, --block LIST, --time T, --time-step N (as the
C++ applications), --particles, --steps (before --image), --resolution (OFB cells on the longest
side), --check (with --image: exit with an error unless every particle is still there,
the OFB got paint and the image shows it; the ctest uses it).
"""

import argparse
import os
import sys

import numpy as np
from vtkmodules.util import numpy_support

import vtkofb
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals, vtkTriangleFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401 (interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factories)

from ofb_example_view import add_data_options, read_data_or_exit, vivid_share

HERE = os.path.dirname(os.path.abspath(__file__))


def read(path, args):
    """The data's surface with point normals and its --field as the active point or cell
    vectors (a cell field holds on its cells' triangles)."""
    mesh, field, on_cells = read_data_or_exit(path, args, vectors=True)
    if field is not None and on_cells:
        mesh.GetPointData().SetActiveAttribute(-1, vtkDataSetAttributes.VECTORS)
        mesh.GetCellData().SetActiveVectors(field.GetName())
    elif field is not None:
        mesh.GetPointData().SetActiveVectors(field.GetName())
    triangles = vtkTriangleFilter()
    triangles.SetInputData(mesh)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(triangles.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    return normals.GetOutput(), field is not None


def rotation_field(mesh, axis=(0.2, 1.0, 0.1)):
    cx, cy, cz = mesh.GetCenter()
    field = vtkDoubleArray()
    field.SetName("Field")
    field.SetNumberOfComponents(3)
    for i in range(mesh.GetNumberOfPoints()):
        x, y, z = mesh.GetPoint(i)
        r = (x - cx, y - cy, z - cz)
        field.InsertNextTuple3(axis[1] * r[2] - axis[2] * r[1], axis[2] * r[0] - axis[0] * r[2],
                               axis[0] * r[1] - axis[1] * r[0])
    mesh.GetPointData().SetVectors(field)


def check(advector, ofb, before, grab):
    """Every particle still there (no lifetime: none lost), paint where they went, and
    the painted surface in the image."""
    particles = advector.GetOutputDataObject(1)
    painted = np.count_nonzero(np.any(
        numpy_support.vtk_to_numpy(ofb.GetSampleData().GetArray("Colors")) != before, axis=1))
    colourful = vivid_share(
        numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3], 0.5)
    print("%d particles, %d samples painted, saturated colour on %.1f %% of the image"
          % (particles.GetNumberOfPoints(), painted, 100.0 * colourful))
    if not (particles.GetNumberOfPoints() == advector.GetNumberOfParticles()
            and painted > 0.05 * ofb.GetNumberOfSamples() and colourful > 0.02):
        sys.exit("check failed")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    add_data_options(parser, "the vector field: a point or cell array of 3 components "
                             "(default: a rotation)")
    parser.add_argument("mesh", nargs="?", help="data file (.vtp .vtu .vtm .pvd .vtk .stl "
                        ".obj .ply)",
                        default=os.path.join(HERE, "..", "..", "Testing", "Data", "horse.ply"))
    parser.add_argument("--particles", type=int, default=5000)
    parser.add_argument("--steps", type=int, default=100, help="steps before --image")
    parser.add_argument("--image", help="write this PNG after --steps steps and exit")
    parser.add_argument("--resolution", type=int, default=1024)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()

    mesh, has_field = read(args.mesh, args)
    if not has_field:
        rotation_field(mesh)

    sampler = vtkofb.vtkOFBSampler()
    sampler.SetInputData(mesh)
    sampler.SetResolution(args.resolution)
    sampler.Update()
    ofb = vtkofb.vtkOFB()  # held here, painted in place
    ofb.ShallowCopy(sampler.GetOutput())

    advector = vtkofb.vtkOFBParticleAdvector()
    advector.SetInputData(mesh)
    advector.SetOFB(ofb)
    advector.SetNumberOfParticles(args.particles)
    advector.SetColorModeToPeriodic()
    advector.SetColorPeriod(90)
    advector.SetFootprintRadius(2.0)
    advector.SetTrailLength(8)

    mapper = vtkofb.vtkOFBPolyDataMapper()
    mapper.SetInputData(mesh)
    mapper.SetOFB(ofb)
    actor = vtkActor()
    actor.SetMapper(mapper)
    trails = vtkPolyDataMapper()
    trails.SetInputConnection(advector.GetOutputPort(2))
    trails.ScalarVisibilityOff()
    trail_actor = vtkActor()
    trail_actor.SetMapper(trails)
    trail_actor.GetProperty().SetColor(1.0, 1.0, 1.0)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddActor(trail_actor)
    renderer.SetBackground(0.15, 0.17, 0.2)
    window = vtkRenderWindow()
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    cx, cy, cz = mesh.GetCenter()
    camera.SetFocalPoint(cx, cy, cz)
    camera.SetPosition(cx, cy - 1.0, cz)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()
    camera.Azimuth(-30.0)
    camera.Dolly(1.6)
    renderer.ResetCameraClippingRange()

    if args.image:
        window.SetOffScreenRendering(1)
        before = numpy_support.vtk_to_numpy(ofb.GetSampleData().GetArray("Colors")).copy()
        advector.SetStepsPerUpdate(args.steps)
        advector.Step()
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetFileName(args.image)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        print("Wrote %s after %d steps" % (args.image, advector.GetCurrentStep()))
        if args.check:
            check(advector, ofb, before, grab)
        return

    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.Initialize()

    def step(*_):
        advector.Step()
        window.Render()

    interactor.AddObserver("TimerEvent", step)
    interactor.CreateRepeatingTimer(30)
    window.Render()
    interactor.Start()


if __name__ == "__main__":
    main()
