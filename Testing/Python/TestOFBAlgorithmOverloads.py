#!/usr/bin/env python3
"""Every public algorithm of vtkOFB keeps vtkAlgorithm's port overloads in Python:
SetInputData(port, data) (or SetInputConnection(port, output)) and GetOutput(port)
for each of its output ports. A subclass that declares SetInputData(data) or
GetOutput() alone hides the overloads taking a port; this test calls them on each
class.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages;
the optional argument is the source directory. ctest does both.
"""

import os
import sys
import tempfile
import unittest

import vtkofb
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource


def sphere_with_field():
    source = vtkSphereSource()
    source.SetThetaResolution(32)
    source.SetPhiResolution(16)
    source.Update()
    sphere = source.GetOutput()
    field = vtkDoubleArray()
    field.SetName("Field")
    field.SetNumberOfComponents(3)
    for i in range(sphere.GetNumberOfPoints()):
        x, y, _ = sphere.GetPoint(i)
        field.InsertNextTuple3(-y, x, 0.0)
    sphere.GetPointData().SetVectors(field)
    return source, sphere


class AlgorithmOverloadsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.source, cls.sphere = sphere_with_field()
        sampler = vtkofb.vtkOFBSampler()
        sampler.SetInputData(0, cls.sphere)
        sampler.SetResolution(64)
        sampler.Update()
        cls.ofb = sampler.GetOutput(0)

    def check_input(self, algorithm, port, data):
        algorithm.SetInputData(port, data)
        self.assertIs(algorithm.GetInputDataObject(port, 0), data)

    def check_outputs(self, algorithm, types):
        self.assertEqual(algorithm.GetNumberOfOutputPorts(), len(types))
        for port, expected in enumerate(types):
            self.assertIsInstance(algorithm.GetOutput(port), expected,
                                  "%s output %d" % (algorithm.GetClassName(), port))

    def test_sampler(self):
        sampler = vtkofb.vtkOFBSampler()
        self.check_input(sampler, 0, self.sphere)
        sampler.SetResolution(32)
        sampler.Update()
        self.check_outputs(sampler, [vtkofb.vtkOFB])
        self.assertGreater(sampler.GetOutput(0).GetNumberOfSamples(), 0)

    def test_builder(self):
        builder = vtkofb.vtkOFBBuilder()
        builder.SetBackendToCPU()
        builder.SetInputConnection(0, self.source.GetOutputPort())
        builder.SetResolution(32)
        builder.Update()
        self.check_outputs(builder, [vtkofb.vtkOFB])
        self.assertGreater(builder.GetOutput(0).GetNumberOfSamples(), 0)

    def test_writer_and_reader(self):
        with tempfile.TemporaryDirectory() as folder:
            name = os.path.join(folder, "sphere.ofb")
            writer = vtkofb.vtkOFBWriter()
            self.check_input(writer, 0, self.ofb)
            self.assertIs(writer.GetInput(0), self.ofb)
            writer.SetFileName(name)
            self.assertEqual(writer.Write(), 1)
            reader = vtkofb.vtkOFBReader()
            reader.SetFileName(name)
            reader.Update()
            self.check_outputs(reader, [vtkofb.vtkOFB])
            self.assertEqual(reader.GetOutput(0).GetNumberOfSamples(), self.ofb.GetNumberOfSamples())

    def test_to_poly_data(self):
        points = vtkofb.vtkOFBToPolyData()
        self.check_input(points, 0, self.ofb)
        points.Update()
        self.check_outputs(points, [vtkPolyData])
        self.assertEqual(points.GetOutput(0).GetNumberOfPoints(), self.ofb.GetNumberOfSamples())

    def test_paint_filter(self):
        paint = vtkofb.vtkOFBPaintFilter()
        self.check_input(paint, 0, self.ofb)
        self.check_input(paint, 1, self.sphere)
        self.check_outputs(paint, [vtkofb.vtkOFB])

    def test_texture_projector(self):
        projector = vtkofb.vtkOFBTextureProjector()
        self.check_input(projector, 0, self.ofb)
        self.check_input(projector, 1, self.sphere)
        self.check_input(projector, 2, vtkImageData())
        self.check_outputs(projector, [vtkofb.vtkOFB])

    def test_decal_patch(self):
        patch = vtkofb.vtkOFBDecalPatch()
        self.check_input(patch, 0, self.sphere)
        self.check_outputs(patch, [vtkPolyData])

    def test_lic(self):
        lic = vtkofb.vtkOFBLIC()
        self.check_input(lic, 0, self.ofb)
        self.check_outputs(lic, [vtkofb.vtkOFB])

    def test_map_to_colors(self):
        colors = vtkofb.vtkOFBMapToColors()
        self.check_input(colors, 0, self.ofb)
        self.check_outputs(colors, [vtkofb.vtkOFB])

    def test_particle_advector(self):
        advector = vtkofb.vtkOFBParticleAdvector()
        self.check_input(advector, 0, self.sphere)
        self.check_input(advector, 1, self.ofb)
        seeds = vtkPolyData()
        seeds.DeepCopy(self.sphere)
        self.check_input(advector, 2, seeds)
        advector.SetStepsPerUpdate(2)
        advector.Step()
        self.check_outputs(advector, [vtkofb.vtkOFB, vtkPolyData, vtkPolyData])
        self.assertIs(advector.GetOutput(1), advector.GetParticles())
        self.assertIs(advector.GetOutput(2), advector.GetTrails())
        self.assertGreater(advector.GetOutput(1).GetNumberOfPoints(), 0)

    def test_probe(self):
        probe = vtkofb.vtkOFBProbeFilter()
        self.check_input(probe, 0, self.sphere)
        self.check_input(probe, 1, self.ofb)
        self.assertIs(probe.GetOFB(), self.ofb)
        probe.Update()
        self.check_outputs(probe, [vtkPolyData])
        self.assertEqual(probe.GetOutput(0).GetNumberOfPoints(), self.sphere.GetNumberOfPoints())

    def test_texture_atlas(self):
        atlas = vtkofb.vtkOFBTextureAtlas()
        self.check_input(atlas, 0, self.sphere)
        self.check_input(atlas, 1, self.ofb)
        self.check_outputs(atlas, [vtkPolyData])

    def test_texture_baker(self):
        baker = vtkofb.vtkOFBTextureBaker()
        self.check_input(baker, 0, self.sphere)
        self.check_input(baker, 1, self.ofb)
        self.check_outputs(baker, [vtkImageData])

    def test_mapper(self):
        mapper = vtkofb.vtkOFBPolyDataMapper()
        mapper.SetInputConnection(0, self.source.GetOutputPort())
        self.assertIs(mapper.GetInputConnection(0, 0).GetProducer(), self.source)
        mapper.SetOFBData(self.ofb)
        self.assertIs(mapper.GetOFB(), self.ofb)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
