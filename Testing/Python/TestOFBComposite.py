#!/usr/bin/env python3
"""A vtkMultiBlockDataSet from Python: sampled into one OFB with the samples' "BlockIndex"
(flat indices), merged by vtkOFBMergeBlocks with NaN for an array a block lacks, and drawn
by vtkOFBPolyDataMapper with a block hidden through vtkCompositeDataDisplayAttributes,
picked with vtkOFBSamplePicker and coloured by block.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages.
"""

import sys
import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkFiltersSources import vtkPlaneSource


def tile(x0, value=None):
    """A unit square of 8 x 8 quads at z = 0 from (x0, 0); a cell array "Pressure" if given."""
    plane = vtkPlaneSource()
    plane.SetOrigin(x0, 0.0, 0.0)
    plane.SetPoint1(x0 + 1.0, 0.0, 0.0)
    plane.SetPoint2(x0, 1.0, 0.0)
    plane.SetResolution(8, 8)
    plane.Update()
    out = plane.GetOutput()
    if value is not None:
        pressure = numpy_support.numpy_to_vtk(
            np.full(out.GetNumberOfCells(), value, dtype=np.float64), deep=True)
        pressure.SetName("Pressure")
        out.GetCellData().AddArray(pressure)
    return out


def three_tiles():
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, tile(0.0, 1.0))
    blocks.SetBlock(1, tile(1.0))
    blocks.SetBlock(2, tile(2.0, 3.0))
    return blocks


class CompositeInput(unittest.TestCase):

    def test_one_ofb_with_block_index_and_fill(self):
        sampler = vtkofb.vtkOFBSampler()
        sampler.SetInputData(three_tiles())
        sampler.SetResolution(96)
        sampler.Update()
        ofb = sampler.GetOutput()
        self.assertGreater(ofb.GetNumberOfSamples(), 1000)
        sd = ofb.GetSampleData()
        block = numpy_support.vtk_to_numpy(sd.GetArray("BlockIndex"))
        pressure = numpy_support.vtk_to_numpy(sd.GetArray("Pressure"))
        self.assertEqual(set(np.unique(block)), {1, 2, 3})
        self.assertTrue(np.all(pressure[block == 1] == 1.0))
        self.assertTrue(np.all(np.isnan(pressure[block == 2])))
        self.assertTrue(np.all(pressure[block == 3] == 3.0))
        self.assertEqual(vtkofb.vtkOFBMergeBlocks.BlockIndexArrayName(), "BlockIndex")

    def test_merge_blocks(self):
        merge = vtkofb.vtkOFBMergeBlocks()
        merge.SetInputData(three_tiles())
        merge.Update()
        out = merge.GetOutput()
        self.assertEqual(out.GetNumberOfCells(), 3 * 64)
        self.assertEqual(out.GetNumberOfPoints(), 81 + 72 + 72)  # shared edges merged
        merge.MergePointsOff()
        merge.Update()
        self.assertEqual(merge.GetOutput().GetNumberOfPoints(), 3 * 81)

    def test_render_with_a_hidden_block(self):
        from vtkmodules.vtkRenderingCore import (vtkActor, vtkCompositeDataDisplayAttributes,
                                                 vtkRenderWindow, vtkRenderer,
                                                 vtkWindowToImageFilter)
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (object factories)
        blocks = three_tiles()
        builder = vtkofb.vtkOFBBuilder()
        builder.SetBackendToCPU()
        builder.SetInputData(blocks)
        builder.SetResolution(96)
        builder.Update()
        ofb = builder.GetOutput()
        # Paint every sample red.
        n = ofb.GetNumberOfSamples()
        colors = numpy_support.vtk_to_numpy(ofb.GetSampleData().GetArray("Colors"))
        colors[:] = np.array([255, 0, 0, 255], dtype=np.uint8)
        ofb.MarkAllSamplesModified()
        ofb.Modified()
        self.assertEqual(colors.shape, (n, 4))

        mapper = vtkofb.vtkOFBPolyDataMapper()
        mapper.SetInputDataObject(blocks)
        mapper.SetOFB(ofb)
        attributes = vtkCompositeDataDisplayAttributes()
        attributes.SetBlockVisibility(blocks.GetBlock(1), False)
        mapper.SetCompositeDataDisplayAttributes(attributes)
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().LightingOff()
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        renderer.SetBackground(0.0, 0.0, 0.0)
        camera = renderer.GetActiveCamera()  # the three tiles fill the window
        camera.ParallelProjectionOn()
        camera.SetFocalPoint(1.5, 0.5, 0.0)
        camera.SetPosition(1.5, 0.5, 5.0)
        camera.SetViewUp(0.0, 1.0, 0.0)
        camera.SetParallelScale(0.5)
        renderer.ResetCameraClippingRange()
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(150, 50)
        window.AddRenderer(renderer)
        window.Render()
        self.assertTrue(mapper.GetLastRenderUsedOFB())
        capture = vtkWindowToImageFilter()
        capture.SetInput(window)
        capture.ReadFrontBufferOff()
        capture.Update()
        image = numpy_support.vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars())
        image = image.reshape(50, 150, -1)
        row = image[25]
        # Left and right tiles red, the middle (hidden) one background.
        self.assertGreater(int(row[20][0]), 200)
        self.assertLess(int(row[20][1]), 30)
        self.assertEqual(list(row[75][:3]), [0, 0, 0])
        self.assertGreater(int(row[130][0]), 200)
        bounds = actor.GetBounds()
        self.assertAlmostEqual(bounds[0], 0.0)
        self.assertAlmostEqual(bounds[1], 3.0)

        # The sample under a pixel of the right tile is of block 3.
        picker = vtkofb.vtkOFBSamplePicker()
        picker.SetOFB(ofb)
        sample = picker.Pick(130, 25, renderer)
        self.assertGreaterEqual(sample, 0)
        self.assertEqual(ofb.GetSampleData().GetArray("BlockIndex").GetTuple1(sample), 3)

        # Coloured by block: the block index through the colouring's lookup table.
        attributes.RemoveBlockVisibilities()
        coloring = mapper.GetColoring()
        coloring.SetColorSourceToScalars()
        coloring.SetScalarArrayName("BlockIndex")
        coloring.SetScalarRange(1.0, 3.0)
        window.Render()
        capture.Modified()
        capture.Update()
        image = numpy_support.vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars())
        row = image.reshape(50, 150, -1)[25]
        left, middle, right = (tuple(int(c) for c in row[x][:3]) for x in (20, 75, 130))
        self.assertNotEqual(left, middle)
        self.assertNotEqual(middle, right)
        self.assertNotEqual(left, right)
        self.assertNotEqual(middle, (0, 0, 0))  # visible again


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
