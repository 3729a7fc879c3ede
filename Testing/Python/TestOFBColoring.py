#!/usr/bin/env python3
"""vtkOFBColoring from Python: one object shared by a vtkOFBPolyDataMapper and a
vtkOFBMapToColors drives both (a setting changed once re-executes the filter and is a
change of the mapper; Print shows it), and SetColoring(None) is refused with an error.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages.
"""

import sys
import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkFiltersSources import vtkSphereSource


def sphere_ofb_with_lic():
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    builder = vtkofb.vtkOFBBuilder()
    builder.SetBackendToCPU()
    builder.SetResolution(32)
    builder.SetInputConnection(sphere.GetOutputPort())
    builder.Update()
    ofb = builder.GetOutput()
    n = ofb.GetNumberOfSamples()
    colors = numpy_support.numpy_to_vtk(
        np.tile(np.array([[200, 120, 40, 255]], dtype=np.uint8), (n, 1)), deep=True)
    colors.SetName("Colors")
    ofb.GetSampleData().AddArray(colors)
    lic = numpy_support.numpy_to_vtk((np.arange(n) % 7 / 6.0).astype(np.float32), deep=True)
    lic.SetName("LIC")
    ofb.GetSampleData().AddArray(lic)
    return ofb


def output_colors(colors_filter):
    colors_filter.Update()
    out = colors_filter.GetOutput().GetSampleData().GetArray(colors_filter.GetOutputArrayName())
    return numpy_support.vtk_to_numpy(out).copy()


class SharedColoring(unittest.TestCase):

    def test_enumerators_and_convenience_setters(self):
        coloring = vtkofb.vtkOFBColoring()
        self.assertEqual(coloring.GetColorSource(), vtkofb.vtkOFBColoring.COLOR_SOURCE_PAINT)
        coloring.SetColorSourceToScalars()
        self.assertEqual(coloring.GetColorSource(), vtkofb.vtkOFBColoring.COLOR_SOURCE_SCALARS)
        coloring.SetLICColorModeToMap()
        self.assertEqual(coloring.GetLICColorMode(), vtkofb.vtkOFBColoring.COLOR_MODE_MAP)
        self.assertAlmostEqual(coloring.GetLICIntensity(), 1.0)
        self.assertEqual(coloring.GetIntensityArrayName(), "LIC")

    def test_shared_by_mapper_and_map_to_colors(self):
        ofb = sphere_ofb_with_lic()
        mapper = vtkofb.vtkOFBPolyDataMapper()
        colors = vtkofb.vtkOFBMapToColors()
        colors.SetInputData(ofb)
        colors.SetColoring(mapper.GetColoring())
        self.assertIs(colors.GetColoring(), mapper.GetColoring())
        mapper.GetColoring().IntensityModulationOn()
        first = output_colors(colors)
        self.assertEqual(first.shape, (ofb.GetNumberOfSamples(), 4))

        mapper_time = mapper.GetMTime()
        colors.GetColoring().SetLICIntensity(0.3)   # once, through the filter's holder
        self.assertAlmostEqual(mapper.GetColoring().GetLICIntensity(), 0.3)
        self.assertGreater(mapper.GetMTime(), mapper_time)
        second = output_colors(colors)
        self.assertFalse(np.array_equal(first, second), "the filter re-executed")
        self.assertIn("LICIntensity: 0.3", str(mapper))
        self.assertIn("LICIntensity: 0.3", str(colors))

    def test_set_coloring_none_is_refused(self):
        for holder in (vtkofb.vtkOFBPolyDataMapper(), vtkofb.vtkOFBMapToColors()):
            errors = []
            holder.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
            before = holder.GetColoring()
            holder.SetColoring(None)
            self.assertEqual(len(errors), 1)
            self.assertIs(holder.GetColoring(), before)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
