#!/usr/bin/env python3
"""vtkOFBImageReader and vtkOFBImageWriter from Python: OpenImageIO loaded only at the
first image, a surface LIC baked into a 32-bit float OpenEXR texture that reads back bit
for bit, a 16-bit PNG round trip, and the errors of a missing file and of an extension
no format has.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages;
ctest does both.
"""

import os
import tempfile
import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, VTK_UNSIGNED_SHORT, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource


def watch_errors(algorithm):
    """Collect the error messages of an algorithm (instead of printing them)."""
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        errors.append(message)

    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    return errors


def read(path):
    reader = vtkofb.vtkOFBImageReader()
    errors = watch_errors(reader)
    reader.SetFileName(path)
    reader.Update()
    return reader, errors


def write(image, path):
    writer = vtkofb.vtkOFBImageWriter()
    errors = watch_errors(writer)
    writer.SetInputData(image)
    writer.SetFileName(path)
    return writer.Write(), errors


def pixels(image):
    return numpy_support.vtk_to_numpy(image.GetPointData().GetScalars())


def openimageio_loaded():
    with open("/proc/self/maps") as maps:
        return "libOpenImageIO" in maps.read()


# Before any test: importing vtkofb loads no OpenImageIO (its ~270 libraries would slow
# every program's start); the first image does.
LOADED_AT_IMPORT = openimageio_loaded()


class TestOFBImageIO(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory(prefix="vtkofb-image-py-")

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def test_openimageio_loaded_at_the_first_image(self):
        self.assertFalse(LOADED_AT_IMPORT)
        image = vtkImageData()
        image.SetDimensions(2, 2, 1)
        image.AllocateScalars(VTK_UNSIGNED_SHORT, 1)
        self.assertEqual(write(image, self.path("a.png")), (1, []))
        self.assertTrue(openimageio_loaded())

    def test_lic_bake_to_openexr_bit_for_bit(self):
        source = vtkSphereSource()
        source.SetThetaResolution(64)
        source.SetPhiResolution(32)
        source.Update()
        mesh = source.GetOutput()
        points = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData())
        flow = numpy_support.numpy_to_vtk(
            np.cross([0.0, 0.0, 1.0], points).astype(np.float32), deep=True)
        flow.SetName("Flow")
        mesh.GetPointData().SetVectors(flow)
        sampler = vtkofb.vtkOFBSampler()
        sampler.SetInputData(mesh)
        sampler.SetResolution(96)
        lic = vtkofb.vtkOFBLIC()
        lic.SetInputConnection(sampler.GetOutputPort())
        lic.Update()
        ofb = lic.GetOutput()
        self.assertEqual(ofb.GetSampleData().GetArray("LIC").GetDataTypeAsString(), "float")

        atlas = vtkofb.vtkOFBTextureAtlas()
        atlas.SetInputData(mesh)
        atlas.SetOFBData(ofb)
        atlas.SetMaximumTextureSize(256)
        atlas.Update()
        baker = vtkofb.vtkOFBTextureBaker()
        baker.SetInputConnection(atlas.GetOutputPort())
        baker.SetOFBData(ofb)
        baker.SetArrayName("LIC")
        baker.SetTextureSize(*atlas.GetAtlasSize())
        baker.Update()
        baked = baker.GetOutput()
        values = pixels(baked)
        self.assertEqual(values.dtype, np.float32)
        self.assertGreater(baker.GetNumberOfBakedTexels(), 1000)
        # Finer than any 8- or 16-bit texture.
        self.assertGreater(len(np.unique(values)), 1000)

        ok, errors = write(baked, self.path("lic.exr"))
        self.assertEqual((ok, errors), (1, []))
        reader, errors = read(self.path("lic.exr"))
        self.assertEqual(errors, [])
        self.assertEqual(reader.GetFormatName(), "openexr")
        self.assertEqual(reader.GetFileBitsPerSample(), 32)
        back = reader.GetOutput()
        self.assertEqual(back.GetDimensions(), baked.GetDimensions())
        self.assertTrue(np.array_equal(pixels(back).view(np.uint32), values.view(np.uint32)))

    def test_sixteen_bit_png(self):
        image = vtkImageData()
        image.SetDimensions(5, 3, 1)
        image.AllocateScalars(VTK_UNSIGNED_SHORT, 3)
        ramp = (np.arange(45, dtype=np.uint16) * 1457 + 3).reshape(15, 3)
        pixels(image)[:] = ramp
        ok, errors = write(image, self.path("ramp.png"))
        self.assertEqual((ok, errors), (1, []))
        reader, errors = read(self.path("ramp.png"))
        self.assertEqual(errors, [])
        back = pixels(reader.GetOutput())
        self.assertEqual(back.dtype, np.uint16)
        self.assertTrue(np.array_equal(back, ramp))

    def test_errors(self):
        reader, errors = read(self.path("missing.exr"))
        self.assertEqual(len(errors), 1)
        self.assertIn("No such file", errors[0])
        self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)
        image = vtkImageData()
        image.SetDimensions(2, 2, 1)
        image.AllocateScalars(VTK_UNSIGNED_SHORT, 1)
        ok, errors = write(image, self.path("x.notaformat"))
        self.assertEqual(ok, 0)
        self.assertIn("no image format has the extension", errors[0])
        self.assertFalse(os.path.exists(self.path("x.notaformat")))


if __name__ == "__main__":
    unittest.main(argv=[__file__])
