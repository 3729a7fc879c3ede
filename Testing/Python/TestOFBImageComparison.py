#!/usr/bin/env python3
"""Python tests of vtkOFBImageComparison: a surface LIC rendered in a vtkRenderWindow
(a sphere with a rotation field, vtkOFBSampler, vtkOFBLIC, vtkOFBPolyDataMapper)
passes against a rerun of the same settings and fails against half the steps and
another noise seed; RegressionTest writes the rendered image when it fails; bad input
fails with an error event.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages
under xvfb-run; ctest does both.
"""

import os
import sys
import tempfile
import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

SIZE = 300


def sphere_with_rotation():
    source = vtkSphereSource()
    source.SetThetaResolution(128)
    source.SetPhiResolution(64)
    source.Update()
    mesh = source.GetOutput()
    points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData())
    axis = np.array([0.4, 1.0, 0.3])
    flow = np.cross(axis / np.linalg.norm(axis), points).astype(np.float32)
    array = numpy_support.numpy_to_vtk(flow, deep=True)
    array.SetName("Flow")
    mesh.GetPointData().SetVectors(array)
    return mesh


class Scene:
    """The LIC of the sphere shown as intensity, every object from scratch."""

    def __init__(self, steps=20, seed=1):
        self.mesh = sphere_with_rotation()
        sampler = vtkofb.vtkOFBSampler()
        sampler.SetInputData(self.mesh)
        sampler.SetResolution(256)
        self.lic = vtkofb.vtkOFBLIC()
        self.lic.SetInputConnection(sampler.GetOutputPort())
        self.lic.SetNumberOfSteps(steps)
        self.lic.SetNoiseGeneratorSeed(seed)
        self.lic.SetEnhanceContrast(vtkofb.vtkOFBLIC.ENHANCE_CONTRAST_LIC)
        self.lic.Update()
        self.mapper = vtkofb.vtkOFBPolyDataMapper()
        self.mapper.SetInputData(self.mesh)
        self.mapper.SetOFB(self.lic.GetOutput())
        self.mapper.SetLookupModeToInverseDistance()
        self.mapper.GetColoring().SetIntensityArrayName("LIC")
        self.mapper.GetColoring().IntensityModulationOn()
        actor = vtkActor()
        actor.SetMapper(self.mapper)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(actor)
        self.renderer.SetBackground(0.1, 0.1, 0.15)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(True)
        self.window.SetSize(SIZE, SIZE)
        self.window.SetMultiSamples(0)
        self.window.AddRenderer(self.renderer)
        self.renderer.ResetCamera()
        self.renderer.GetActiveCamera().Dolly(1.3)
        self.renderer.ResetCameraClippingRange()

    def grab(self):
        self.window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.ReadFrontBufferOff()
        grab.SetInputBufferTypeToRGB()
        grab.Update()
        image = vtkImageData()
        image.DeepCopy(grab.GetOutput())
        return image


class Events:
    """Counts error events (an observer also keeps VTK from printing)."""

    def __init__(self, obj):
        self.errors = 0
        obj.AddObserver(vtkCommand.ErrorEvent, self._error)

    def _error(self, obj, event):
        self.errors += 1


class ImageComparison(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.baseline = Scene().grab()

    def compare(self, image):
        comparison = vtkofb.vtkOFBImageComparison()
        comparison.SetImage(image)
        comparison.SetBaseline(self.baseline)
        comparison.SetBackgroundColor(0.1, 0.1, 0.15)
        passed = comparison.Compare()
        print(f"correlation {comparison.GetCorrelation():.4f}, low-pass difference "
              f"{comparison.GetLowPassDifference():.3f}")
        return passed, comparison

    def test_same_settings_pass(self):
        passed, comparison = self.compare(Scene().grab())
        self.assertTrue(passed, comparison.GetErrorText())
        self.assertGreaterEqual(comparison.GetCorrelation(), comparison.GetCorrelationThreshold())
        self.assertEqual(comparison.GetErrorText(), "")

    def test_half_the_steps_fail(self):
        passed, comparison = self.compare(Scene(steps=10).grab())
        self.assertFalse(passed)
        self.assertLess(comparison.GetCorrelation(), comparison.GetCorrelationThreshold())
        self.assertIn("texture", comparison.GetErrorText())

    def test_another_seed_fails(self):
        passed, comparison = self.compare(Scene(seed=2).grab())
        self.assertFalse(passed)
        self.assertLess(comparison.GetCorrelation(), 0.5)

    def test_regression_test_writes_the_image(self):
        scene = Scene()
        with tempfile.TemporaryDirectory() as directory:
            baseline = os.path.join(directory, "TestSphere.png")
            written = os.path.join(directory, "out", "TestSphere.png")
            os.mkdir(os.path.join(directory, "out"))
            comparison = vtkofb.vtkOFBImageComparison()
            events = Events(comparison)
            result = comparison.RegressionTest(scene.window, baseline,
                                               os.path.join(directory, "out"))
            self.assertEqual(result, vtkofb.vtkOFBImageComparison.FAILED)
            self.assertEqual(events.errors, 1)
            self.assertTrue(os.path.exists(written))
            os.replace(written, baseline)
            result = comparison.RegressionTest(scene.window, baseline,
                                               os.path.join(directory, "out"))
            self.assertEqual(result, vtkofb.vtkOFBImageComparison.PASSED,
                             comparison.GetErrorText())

    def test_bad_input_fails_with_an_error(self):
        comparison = vtkofb.vtkOFBImageComparison()
        events = Events(comparison)
        self.assertFalse(comparison.Compare())
        self.assertIn("no image", comparison.GetErrorText())
        comparison.SetImage(self.baseline)
        small = vtkImageData()
        small.SetDimensions(10, 20, 1)
        small.AllocateScalars(3, 3)  # VTK_UNSIGNED_CHAR, RGB
        comparison.SetBaseline(small)
        self.assertFalse(comparison.Compare())
        self.assertIn("the baseline 10 x 20", comparison.GetErrorText())
        self.assertEqual(events.errors, 2)
        self.assertIsNone(comparison.GetDifferenceImage())


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
