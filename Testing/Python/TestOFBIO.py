#!/usr/bin/env python3
"""vtkOFBWriter and vtkOFBReader from Python: an exact round trip, and an empty
output with an error on a file that is not an OFB.

Usage: python3 TestOFBIO.py [project-root]
(with the build's lib/python3.11/dist-packages on PYTHONPATH). The optional project
root adds a check on a foreign file of Testing/Data.
"""

import os
import sys
import tempfile
import unittest

import vtkofb
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkFiltersSources import vtkSphereSource

PROJECT_ROOT = None


def watch_errors(algorithm):
    """Collect the error messages of an algorithm (instead of printing them)."""
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        errors.append(message)

    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    return errors


def make_ofb():
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    sampler = vtkofb.vtkOFBSampler()
    sampler.SetInputConnection(sphere.GetOutputPort())
    sampler.SetResolution(40)
    sampler.Update()
    return sampler


def read(path):
    reader = vtkofb.vtkOFBReader()
    errors = watch_errors(reader)
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput(), errors


class TestOFBIO(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory(prefix="vtkofb-io-py-")

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def assert_empty_with_error(self, path, expected=""):
        ofb, errors = read(path)
        self.assertTrue(errors, "no error reading " + path)
        self.assertIn(expected, errors[0])
        self.assertEqual(ofb.GetNumberOfSamples(), 0)
        self.assertEqual(ofb.GetNumberOfCells(), 0)
        self.assertEqual(ofb.GetSampleData().GetNumberOfArrays(), 0)

    def test_round_trip(self):
        sampler = make_ofb()
        ofb = sampler.GetOutput()
        n = ofb.GetNumberOfSamples()
        self.assertGreater(n, 1000)

        writer = vtkofb.vtkOFBWriter()
        errors = watch_errors(writer)
        writer.SetInputConnection(sampler.GetOutputPort())
        writer.SetFileName(self.path("sphere.ofb"))
        self.assertEqual(writer.Write(), 1)
        self.assertEqual(errors, [])
        self.assertEqual(os.listdir(self.dir.name), ["sphere.ofb"])
        self.assertTrue(vtkofb.vtkOFBReader.CanReadFile(self.path("sphere.ofb")))

        back, errors = read(self.path("sphere.ofb"))
        self.assertEqual(errors, [])
        self.assertEqual(back.GetNumberOfSamples(), n)
        self.assertEqual(back.GetNumberOfCells(), ofb.GetNumberOfCells())
        self.assertEqual(back.GetCellSize(), ofb.GetCellSize())
        self.assertEqual(back.GetOrigin(), ofb.GetOrigin())
        self.assertEqual(back.GetDimensions(), ofb.GetDimensions())
        for axis in range(3):
            self.assertEqual(back.GetNumberOfSamples(axis), ofb.GetNumberOfSamples(axis))
        sd, sdb = ofb.GetSampleData(), back.GetSampleData()
        self.assertEqual(sdb.GetNumberOfArrays(), sd.GetNumberOfArrays())
        self.assertEqual(sdb.GetScalars().GetName(), sd.GetScalars().GetName())
        self.assertEqual(sdb.GetNormals().GetName(), sd.GetNormals().GetName())
        for i in list(range(0, n, 97)) + [n - 1]:
            self.assertEqual(back.GetDepths().GetValue(i), ofb.GetDepths().GetValue(i))
            self.assertEqual(back.GetCellIndex().GetValue(i), ofb.GetCellIndex().GetValue(i))
            self.assertEqual(sdb.GetScalars().GetTuple(i), sd.GetScalars().GetTuple(i))
            self.assertEqual(sdb.GetNormals().GetTuple(i), sd.GetNormals().GetTuple(i))
            x, y = [0.0] * 3, [0.0] * 3
            self.assertTrue(back.GetSamplePosition(i, x))
            self.assertTrue(ofb.GetSamplePosition(i, y))
            self.assertEqual(x, y)

    def test_garbage_and_missing_files(self):
        garbage = self.path("garbage.ofb")
        with open(garbage, "wb") as f:
            f.write(os.urandom(4096))
        self.assert_empty_with_error(garbage, "not an OFB file")
        self.assert_empty_with_error(self.path("missing.ofb"), "does not exist")
        if PROJECT_ROOT:
            obj = os.path.join(PROJECT_ROOT, "Testing", "Data", "stanford-bunny.obj")
            self.assert_empty_with_error(obj, "not an OFB file")

    def test_corrupted_file(self):
        sampler = make_ofb()
        writer = vtkofb.vtkOFBWriter()
        writer.SetInputConnection(sampler.GetOutputPort())
        writer.SetFileName(self.path("sphere.ofb"))
        self.assertEqual(writer.Write(), 1)
        with open(self.path("sphere.ofb"), "rb") as f:
            data = bytearray(f.read())
        data[len(data) // 2] ^= 0x10
        with open(self.path("flipped.ofb"), "wb") as f:
            f.write(data)
        self.assert_empty_with_error(self.path("flipped.ofb"), "flipped.ofb")
        with open(self.path("short.ofb"), "wb") as f:
            f.write(data[: len(data) // 3])
        self.assert_empty_with_error(self.path("short.ofb"))


if __name__ == "__main__":
    if len(sys.argv) > 1:
        PROJECT_ROOT = sys.argv[1]
    unittest.main(argv=sys.argv[:1], verbosity=2)
