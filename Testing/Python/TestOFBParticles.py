#!/usr/bin/env python3
"""Python test of vtkOFBParticleAdvector: the wrapped class in a pipeline, its
outputs and arrays, painting an OFB, and bad input.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages;
the optional argument is the source directory. ctest does both.
"""

import sys
import unittest

import vtkofb
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray
from vtkmodules.vtkFiltersSources import vtkSphereSource


def rotating_sphere():
    source = vtkSphereSource()
    source.SetThetaResolution(64)
    source.SetPhiResolution(32)
    source.Update()
    sphere = source.GetOutput()
    field = vtkDoubleArray()
    field.SetNumberOfComponents(3)
    for i in range(sphere.GetNumberOfPoints()):
        x, y, _ = sphere.GetPoint(i)
        field.InsertNextTuple3(-y, x, 0.0)
    sphere.GetPointData().SetVectors(field)
    return source, sphere


class ParticleAdvectorTest(unittest.TestCase):
    def test_pipeline(self):
        source, sphere = rotating_sphere()
        sampler = vtkofb.vtkOFBSampler()
        sampler.SetInputData(sphere)
        sampler.SetResolution(128)
        advector = vtkofb.vtkOFBParticleAdvector()
        advector.SetInputData(sphere)
        advector.SetOFBConnection(sampler.GetOutputPort())
        advector.SetNumberOfParticles(50)
        advector.SetStepsPerUpdate(10)
        advector.Step()
        self.assertEqual(advector.GetCurrentStep(), 10)
        particles = advector.GetParticles()
        self.assertEqual(particles.GetNumberOfPoints(), 50)
        for name in ("Velocity", "Age", "Id", "ChainIndex", "Color"):
            self.assertIsNotNone(particles.GetPointData().GetArray(name), name)
        self.assertEqual(advector.GetTrails().GetNumberOfCells(), 50)
        painted = advector.GetOutput()
        self.assertEqual(painted.GetNumberOfSamples(), sampler.GetOutput().GetNumberOfSamples())
        colors = painted.GetSampleData().GetArray("Colors")
        red = sum(1 for i in range(colors.GetNumberOfTuples())
                  if colors.GetTuple4(i)[:3] == (255.0, 0.0, 0.0))
        self.assertGreater(red, 50)
        advector.UpdateTimeStep(4.0)
        self.assertEqual(advector.GetCurrentStep(), 4)

    def test_bad_step_size(self):
        _, sphere = rotating_sphere()
        advector = vtkofb.vtkOFBParticleAdvector()
        advector.SetInputData(sphere)
        advector.SetStepSize(0.0)
        errors = []
        advector.AddObserver(vtkCommand.ErrorEvent, lambda o, e: errors.append(e))
        advector.Update()
        self.assertTrue(errors)
        self.assertEqual(advector.GetParticles().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
