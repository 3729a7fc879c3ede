#!/usr/bin/env python3
"""Python tests of vtkOFBLIC: the wrapped class in a pipeline, the LIC read through
numpy, determinism for a seed, and bad input (an error event and an empty output).

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages;
ctest does both.
"""

import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkFiltersSources import vtkSphereSource


class Events:
    """Counts error and warning events (an observer also keeps VTK from printing)."""

    def __init__(self, obj):
        self.errors = 0
        self.warnings = 0
        obj.AddObserver(vtkCommand.ErrorEvent, self._error)
        obj.AddObserver(vtkCommand.WarningEvent, self._warning)

    def _error(self, obj, event):
        self.errors += 1

    def _warning(self, obj, event):
        self.warnings += 1


def sphere_with_rotation(field=True):
    source = vtkSphereSource()
    source.SetThetaResolution(96)
    source.SetPhiResolution(48)
    source.Update()
    mesh = source.GetOutput()
    if field:
        points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData())
        flow = np.cross([0.0, 0.0, 1.0], points).astype(np.float32)
        array = numpy_support.numpy_to_vtk(flow, deep=True)
        array.SetName("Flow")
        mesh.GetPointData().SetVectors(array)
    return mesh


def lic_of(mesh, seed=1):
    sampler = vtkofb.vtkOFBSampler()
    sampler.SetInputData(mesh)
    sampler.SetResolution(128)
    lic = vtkofb.vtkOFBLIC()
    lic.SetInputConnection(sampler.GetOutputPort())
    lic.SetNoiseGeneratorSeed(seed)
    events = Events(lic)
    lic.Update()
    return lic, events


class LIC(unittest.TestCase):
    def test_pipeline_gives_lic_in_unit_range(self):
        lic, events = lic_of(sphere_with_rotation())
        self.assertEqual(events.errors, 0)
        out = lic.GetOutput()
        self.assertIsInstance(out, vtkofb.vtkOFB)
        values = numpy_support.vtk_to_numpy(out.GetSampleData().GetArray("LIC"))
        mask = numpy_support.vtk_to_numpy(out.GetSampleData().GetArray("LICMask"))
        self.assertEqual(len(values), out.GetNumberOfSamples())
        self.assertGreater(len(values), 1000)
        self.assertGreaterEqual(values.min(), 0.0)
        self.assertLessEqual(values.max(), 1.0)
        self.assertGreater(values.std(), 0.05)
        # Only the poles (zero speed on the axis) may be masked.
        self.assertLess(mask.mean(), 0.01)

    def test_same_seed_same_result(self):
        a = numpy_support.vtk_to_numpy(
            lic_of(sphere_with_rotation(), 3)[0].GetOutput().GetSampleData().GetArray("LIC"))
        b = numpy_support.vtk_to_numpy(
            lic_of(sphere_with_rotation(), 3)[0].GetOutput().GetSampleData().GetArray("LIC"))
        c = numpy_support.vtk_to_numpy(
            lic_of(sphere_with_rotation(), 4)[0].GetOutput().GetSampleData().GetArray("LIC"))
        self.assertTrue(np.array_equal(a, b))
        self.assertFalse(np.array_equal(a, c))

    def test_settings_keep_vtk_names(self):
        lic = vtkofb.vtkOFBLIC()
        self.assertEqual(lic.GetNumberOfSteps(), 20)
        self.assertEqual(lic.GetStepSize(), 1.0)
        self.assertTrue(lic.GetNormalizeVectors())
        self.assertTrue(lic.GetEnhancedLIC())
        self.assertEqual(lic.GetNoiseType(), vtkofb.vtkOFBLIC.NOISE_TYPE_GAUSSIAN)
        self.assertAlmostEqual(lic.GetMaxNoiseValue(), 0.8)
        # How the LIC combines with colour is the display's: vtkOFBColoring's.
        self.assertFalse(hasattr(lic, "GetLICIntensity"))
        self.assertAlmostEqual(vtkofb.vtkOFBColoring().GetLICIntensity(), 1.0)
        lic.SetEnhanceContrast(vtkofb.vtkOFBLIC.ENHANCE_CONTRAST_BOTH)
        self.assertEqual(lic.GetEnhanceContrast(), 4)

    def test_no_vectors_is_an_error_with_an_empty_output(self):
        lic, events = lic_of(sphere_with_rotation(field=False))
        self.assertEqual(events.errors, 1)
        self.assertEqual(lic.GetOutput().GetNumberOfSamples(), 0)


if __name__ == "__main__":
    unittest.main(argv=[__file__])
