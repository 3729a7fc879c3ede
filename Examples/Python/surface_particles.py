#!/usr/bin/env python3
"""Surface particles as a plain VTK pipeline: a mesh with a rotation field, its OFB,
vtkOFBParticleAdvector painting it, vtkOFBPolyDataMapper drawing it, and the
particles' trails as lines. Animated in a window, or headless with --image.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages:
    python3 Examples/Python/surface_particles.py [mesh.ply|mesh.obj] [--image out.png]
"""

import argparse
import os

import vtkofb
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401 (interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factories)

HERE = os.path.dirname(os.path.abspath(__file__))


def read(path):
    reader = vtkPLYReader() if path.endswith(".ply") else vtkOBJReader()
    reader.SetFileName(path)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(reader.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    return normals.GetOutput()


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


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mesh", nargs="?",
                        default=os.path.join(HERE, "..", "..", "Testing", "Data", "horse.ply"))
    parser.add_argument("--particles", type=int, default=5000)
    parser.add_argument("--steps", type=int, default=100, help="steps before --image")
    parser.add_argument("--image", help="write this PNG after --steps steps and exit")
    args = parser.parse_args()

    mesh = read(args.mesh)
    rotation_field(mesh)

    sampler = vtkofb.vtkOFBSampler()
    sampler.SetInputData(mesh)
    sampler.SetResolution(1024)
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

    if args.image:
        window.SetOffScreenRendering(1)
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
