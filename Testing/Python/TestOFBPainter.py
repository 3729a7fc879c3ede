#!/usr/bin/env python3
"""Painting through the Python wrapping: a dab, a stroke, undo, the paint filter.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages;
the optional argument is the source directory. ctest does both.
"""

import math
import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource


def sphere_ofb(resolution=64):
    source = vtkSphereSource()
    source.SetThetaResolution(64)
    source.SetPhiResolution(32)
    sampler = vtkofb.vtkOFBSampler()
    sampler.SetInputConnection(source.GetOutputPort())
    sampler.SetResolution(resolution)
    sampler.Update()
    ofb = vtkofb.vtkOFB()
    ofb.DeepCopy(sampler.GetOutput())
    return ofb


def colors(ofb):
    return numpy_support.vtk_to_numpy(ofb.GetSampleData().GetArray("Colors")).copy()


def positions(ofb):
    out = np.empty((ofb.GetNumberOfSamples(), 3))
    x = [0.0, 0.0, 0.0]
    for i in range(ofb.GetNumberOfSamples()):
        ofb.GetSamplePosition(i, x)
        out[i] = x
    return out


class PainterTest(unittest.TestCase):
    def test_dab_paints_inside_the_radius_only(self):
        ofb = sphere_ofb()
        before = colors(ofb)
        painter = vtkofb.vtkOFBPainter()
        painter.SetOFB(ofb)
        brush = painter.GetBrush()
        brush.SetColor(1.0, 0.0, 0.0)
        brush.SetRadius(0.2)
        brush.SetFalloffToConstant()
        changed = painter.Dab(0.0, 0.0, 0.5)
        self.assertGreater(changed, 0)
        after = colors(ofb)
        differs = np.any(after != before, axis=1)
        self.assertEqual(int(differs.sum()), changed)
        d = np.linalg.norm(positions(ofb) - np.array([0.0, 0.0, 0.5]), axis=1)
        self.assertTrue(np.all(d[differs] <= 0.2 + 1e-9))
        self.assertTrue(np.all(after[differs] == [255, 0, 0, 255]))
        # Undo restores the colours exactly.
        self.assertTrue(painter.CanUndo())
        self.assertEqual(painter.Undo(), changed)
        self.assertTrue(np.array_equal(colors(ofb), before))

    def test_mirror_paints_the_reflection(self):
        ofb = sphere_ofb()
        before = colors(ofb)
        painter = vtkofb.vtkOFBPainter()
        painter.SetOFB(ofb)
        painter.GetBrush().SetRadius(0.15)
        painter.GetBrush().SetFalloffToConstant()
        painter.GetBrush().SetColor(1.0, 0.0, 0.0)
        painter.MirrorXOn()
        painter.SetMirrorOrigin(0.0, 0.0, 0.0)
        self.assertGreater(painter.Dab(0.4, 0.0, 0.3), 0)
        differs = np.any(colors(ofb) != before, axis=1)
        x = positions(ofb)[differs, 0]
        # Painted around (0.4, 0, 0.3) and around its reflection (-0.4, 0, 0.3) only.
        self.assertGreater(int((x > 0.2).sum()), 10)
        self.assertGreater(int((x < -0.2).sum()), 10)
        self.assertEqual(int((np.abs(x) <= 0.2).sum()), 0)

    def test_stroke_and_bad_input(self):
        ofb = sphere_ofb()
        painter = vtkofb.vtkOFBPainter()
        painter.SetOFB(ofb)
        painter.GetBrush().SetRadius(0.1)
        painter.GetBrush().SetColor(0.0, 0.0, 1.0, 1.0)
        painter.BeginStroke()
        total = 0
        for i in range(11):
            a = math.pi * i / 10
            total += painter.StrokeTo((0.5 * math.cos(a), 0.5 * math.sin(a), 0.0), 1.0)
        painter.EndStroke()
        self.assertGreater(total, 0)
        self.assertGreater(painter.GetStrokeDabs().GetNumberOfPoints(), 30)
        errors = []
        painter.AddObserver(vtkCommand.ErrorEvent, lambda o, e: errors.append(e))
        self.assertEqual(painter.Dab(float("nan"), 0.0, 0.0), 0)
        self.assertEqual(len(errors), 1)

    def test_paint_filter(self):
        ofb = sphere_ofb()
        strokes = vtkPolyData()
        points = vtkPoints()
        points.InsertNextPoint(-0.3, 0.0, 0.4)
        points.InsertNextPoint(0.3, 0.0, 0.4)
        lines = vtkCellArray()
        lines.InsertNextCell(2)
        lines.InsertCellPoint(0)
        lines.InsertCellPoint(1)
        strokes.SetPoints(points)
        strokes.SetLines(lines)
        paint = vtkofb.vtkOFBPaintFilter()
        paint.SetInputData(ofb)
        paint.SetStrokesData(strokes)
        paint.GetBrush().SetRadius(0.15)
        paint.GetBrush().SetColor(0.0, 1.0, 0.0)
        paint.Update()
        self.assertGreater(paint.GetNumberOfChangedSamples(), 0)
        self.assertTrue(np.all(colors(ofb) == 255))  # the input is untouched
        self.assertFalse(np.all(colors(paint.GetOutput()) == 255))


if __name__ == "__main__":
    unittest.main(argv=[__file__])
