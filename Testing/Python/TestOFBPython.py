#!/usr/bin/env python3
"""Python tests of the vtkofb package: classes, pipeline, queries, numpy access,
bad input and the builder's backend fallback.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages;
the optional argument is the source directory (for Testing/Data). ctest does both.
"""

import math
import os
import sys
import unittest

import numpy as np

import vtkofb
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand, vtkIdList
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader

SOURCE_DIR = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))

CLASSES = ("vtkOFB", "vtkOFBAlgorithm", "vtkOFBSampler", "vtkOFBBuilder",
           "vtkOFBToPolyData", "vtkOFBSamplePicker", "vtkOFBWriter", "vtkOFBReader",
           "vtkOFBPyramid", "vtkOFBPolyDataMapper", "vtkOFBColoring", "vtkOFBMapToColors",
           "vtkOFBProbeFilter", "vtkOFBTextureBaker",
           "vtkOFBTextureProjector", "vtkOFBDecalPatch", "vtkOFBImageComparison")


class Events:
    """Counts the error and warning events of the objects it watches; an observer
    also keeps VTK from printing the message."""

    def __init__(self, *objects):
        self.errors = 0
        self.warnings = 0
        for obj in objects:
            obj.AddObserver(vtkCommand.ErrorEvent, self._error)
            obj.AddObserver(vtkCommand.WarningEvent, self._warning)

    def _error(self, obj, event):
        self.errors += 1

    def _warning(self, obj, event):
        self.warnings += 1


def sphere_source(radius=1.0, resolution=64):
    sphere = vtkSphereSource()
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(2 * resolution)
    sphere.SetPhiResolution(resolution)
    return sphere


def positions(ofb):
    """Positions of every sample, (n, 3), through GetSamplePosition."""
    n = ofb.GetNumberOfSamples()
    out = np.empty((n, 3))
    x = [0.0, 0.0, 0.0]
    for i in range(n):
        ofb.GetSamplePosition(i, x)
        out[i] = x
    return out


class SpherePipeline(unittest.TestCase):
    """vtkSphereSource -> vtkOFBBuilder (CPU) -> vtkOFBToPolyData."""

    RESOLUTION = 128

    @classmethod
    def setUpClass(cls):
        cls.source = sphere_source()
        cls.builder = vtkofb.vtkOFBBuilder()
        cls.builder.SetBackendToCPU()
        cls.builder.SetResolution(cls.RESOLUTION)
        cls.builder.SetInputConnection(cls.source.GetOutputPort())
        cls.events = Events(cls.builder)
        cls.points = vtkofb.vtkOFBToPolyData()
        cls.points.SetInputConnection(cls.builder.GetOutputPort())
        cls.points.Update()
        cls.ofb = cls.builder.GetOutput()
        cls.cloud = cls.points.GetOutput()
        cls.surface = cls.source.GetOutput()

    def test_build_succeeds_on_the_cpu(self):
        self.assertEqual(self.events.errors, 0)
        self.assertEqual(self.events.warnings, 0)
        self.assertEqual(self.builder.GetLastBackend(), vtkofb.vtkOFBBuilder.BACKEND_CPU)
        self.assertEqual(vtkofb.vtkOFBBuilder.GetBackendAsString(vtkofb.vtkOFBBuilder.BACKEND_CPU), "CPU")
        self.assertIsInstance(self.ofb, vtkofb.vtkOFB)
        self.assertGreater(self.builder.GetLastBuildTime(), 0.0)

    def test_frame(self):
        s = self.ofb.GetCellSize()
        self.assertGreater(s, 0.0)
        dims = self.ofb.GetDimensions()
        # A sphere's box is a cube: every side gets the resolution.
        self.assertEqual(tuple(dims), (self.RESOLUTION,) * 3)
        bounds = [0.0] * 6
        self.ofb.GetBounds(bounds)
        for a in range(3):
            self.assertLess(bounds[2 * a], -1.0)
            self.assertGreater(bounds[2 * a + 1], 1.0)
            self.assertAlmostEqual(bounds[2 * a + 1] - bounds[2 * a], dims[a] * s, places=9)

    def test_sample_counts_add_up(self):
        n = self.ofb.GetNumberOfSamples()
        per_grid = [self.ofb.GetNumberOfSamples(a) for a in range(3)]
        self.assertGreater(n, 0)
        self.assertEqual(sum(per_grid), n)
        for a in range(3):
            self.assertGreater(per_grid[a], 0)
            # By symmetry each grid takes about a third of the sphere.
            self.assertAlmostEqual(per_grid[a] / n, 1.0 / 3.0, delta=0.05)
            self.assertEqual(self.ofb.GetGridFirstSample(a), sum(per_grid[:a]))
            # A closed convex surface crosses every ray through it twice.
            self.assertEqual(self.ofb.GetDepthComplexity(a), 2)
        self.assertEqual(self.ofb.GetDepthComplexity(), 2)
        self.assertEqual(self.ofb.GetSampleData().GetNumberOfTuples(), n)
        self.assertGreater(self.ofb.GetBytesPerSample(), 0.0)
        self.assertGreater(self.ofb.GetActualMemorySize(), 0)

    def test_point_cloud(self):
        n = self.ofb.GetNumberOfSamples()
        self.assertEqual(self.cloud.GetNumberOfPoints(), n)
        self.assertEqual(self.cloud.GetNumberOfVerts(), n)
        axis = numpy_support.vtk_to_numpy(self.cloud.GetPointData().GetArray("GridAxis"))
        counts = np.bincount(axis, minlength=3)
        self.assertEqual(list(counts), [self.ofb.GetNumberOfSamples(a) for a in range(3)])
        for name in ("Colors", "Normals"):
            self.assertIsNotNone(self.cloud.GetPointData().GetArray(name), name)
        points = numpy_support.vtk_to_numpy(self.cloud.GetPoints().GetData())
        np.testing.assert_allclose(points, positions(self.ofb), atol=1e-6)

    def test_sample_positions(self):
        x = [0.0, 0.0, 0.0]
        self.assertTrue(self.ofb.GetSamplePosition(0, x))
        self.assertFalse(self.ofb.GetSamplePosition(-1, x))
        self.assertFalse(self.ofb.GetSamplePosition(self.ofb.GetNumberOfSamples(), x))
        self.assertEqual(self.ofb.GetSampleAxis(-1), -1)
        p = positions(self.ofb)
        r = np.linalg.norm(p, axis=1)
        # Samples lie on the polygonal sphere: inside the unit sphere, close to it.
        self.assertLessEqual(r.max(), 1.0 + 1e-5)
        self.assertGreater(r.min(), 0.99)
        for a in range(3):
            first = self.ofb.GetGridFirstSample(a)
            self.assertEqual(self.ofb.GetSampleAxis(first), a)

    def surface_points(self):
        """Vertices and triangle centroids of the input sphere: points of the surface."""
        pts = numpy_support.vtk_to_numpy(self.surface.GetPoints().GetData()).astype(float)
        polys = numpy_support.vtk_to_numpy(self.surface.GetPolys().GetConnectivityArray())
        triangles = polys.reshape(-1, 3)
        centroids = pts[triangles].mean(axis=1)
        return np.vstack([pts[::7], centroids[::11]])

    def test_find_closest_sample_within_sqrt3_cells(self):
        s = self.ofb.GetCellSize()
        bound = math.sqrt(3.0) * s
        worst = 0.0
        y = [0.0, 0.0, 0.0]
        for x in self.surface_points():
            i = self.ofb.FindClosestSample(tuple(x))
            self.assertGreaterEqual(i, 0, "no sample near %s" % (x,))
            self.assertTrue(self.ofb.GetSamplePosition(i, y))
            worst = max(worst, math.dist(x, y))
        self.assertLessEqual(worst, bound)
        # FindSample at a sample's position, with its grid's axis as the normal,
        # returns that sample.
        x = [0.0, 0.0, 0.0]
        for i in range(0, self.ofb.GetNumberOfSamples(), 97):
            self.ofb.GetSamplePosition(i, x)
            normal = [0.0, 0.0, 0.0]
            normal[self.ofb.GetSampleAxis(i)] = 1.0
            self.assertEqual(self.ofb.FindSample(x, normal), i)
        # Far from the surface there is none.
        self.assertEqual(self.ofb.FindClosestSample((0.0, 0.0, 0.0)), -1)
        self.assertEqual(self.ofb.FindClosestSample((5.0, 5.0, 5.0)), -1)

    def test_find_samples_in_sphere(self):
        s = self.ofb.GetCellSize()
        p = positions(self.ofb)
        ids = vtkIdList()
        for center, radius in (((0.0, 0.0, 1.0), 3.0 * s), ((0.6, 0.0, 0.8), 5.0 * s),
                               ((-0.577, 0.577, 0.577), 2.0 * s), ((0.0, 0.0, 0.0), 0.5)):
            self.ofb.FindSamplesInSphere(center, radius, ids)
            found = sorted(ids.GetId(k) for k in range(ids.GetNumberOfIds()))
            expected = np.nonzero(np.linalg.norm(p - np.array(center), axis=1) <= radius)[0]
            # Brute force agrees, up to float rounding at the boundary.
            near_edge = np.abs(np.linalg.norm(p - np.array(center), axis=1) - radius) < 1e-6
            differ = set(found) ^ set(expected.tolist())
            self.assertTrue(differ <= set(np.nonzero(near_edge)[0].tolist()), differ)
            self.assertEqual(len(found), len(set(found)))
            if radius < 0.5:
                self.assertGreater(len(found), 0)
            else:
                self.assertEqual(len(found), 0)  # the centre of the sphere: no surface there

    def test_arrays_through_numpy(self):
        n = self.ofb.GetNumberOfSamples()
        data = self.ofb.GetSampleData()
        colors = numpy_support.vtk_to_numpy(data.GetScalars())
        self.assertEqual(colors.shape, (n, 4))
        self.assertEqual(colors.dtype, np.uint8)
        self.assertTrue((colors == 255).all())  # default paint: opaque white
        normals = numpy_support.vtk_to_numpy(data.GetNormals())
        self.assertEqual(normals.shape, (n, 3))
        np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-3)
        # Normals of a sphere point away from its centre.
        self.assertGreater(float(np.einsum("ij,ij->i", normals, positions(self.ofb)).min()), 0.9)
        offsets = numpy_support.vtk_to_numpy(self.ofb.GetCellOffsets())
        self.assertEqual(len(offsets), self.ofb.GetNumberOfCells() + 1)
        self.assertEqual(int(offsets[0]), 0)
        self.assertEqual(int(offsets[-1]), n)
        self.assertTrue((np.diff(offsets.astype(np.int64)) >= 0).all())
        depths = numpy_support.vtk_to_numpy(self.ofb.GetDepths())
        self.assertEqual(len(depths), n)
        self.assertTrue(np.isfinite(depths).all())
        # Each cell is sorted by depth.
        starts = offsets[:-1].astype(np.int64)
        inner = np.ones(n, dtype=bool)
        inner[starts[starts < n]] = False
        self.assertTrue((np.diff(depths)[inner[1:]] >= 0).all())
        cells = numpy_support.vtk_to_numpy(self.ofb.GetCellIndex())
        self.assertEqual(len(cells), n)
        self.assertTrue((np.diff(cells.astype(np.int64)) >= 0).all())


class Classes(unittest.TestCase):
    def test_package_exposes_every_class(self):
        for name in CLASSES:
            self.assertTrue(hasattr(vtkofb, name), name)
            obj = getattr(vtkofb, name)()
            self.assertEqual(obj.GetClassName(), name)
        self.assertTrue(vtkofb.vtkOFB().IsA("vtkDataObject"))
        self.assertTrue(vtkofb.vtkOFBBuilder().IsA("vtkOFBSampler"))
        self.assertTrue(vtkofb.vtkOFBSampler().IsA("vtkOFBAlgorithm"))
        self.assertTrue(vtkofb.vtkOFBToPolyData().IsA("vtkPolyDataAlgorithm"))
        self.assertTrue(hasattr(vtkofb, "__version__"))

    def test_defaults(self):
        builder = vtkofb.vtkOFBBuilder()
        self.assertEqual(builder.GetResolution(), 1024)
        self.assertEqual(builder.GetBackend(), vtkofb.vtkOFBBuilder.BACKEND_AUTO)
        self.assertEqual(builder.GetLastBackend(), vtkofb.vtkOFBBuilder.BACKEND_AUTO)
        empty = vtkofb.vtkOFB()
        self.assertEqual(empty.GetNumberOfSamples(), 0)
        self.assertEqual(empty.GetCellSize(), 0.0)
        self.assertEqual(empty.FindClosestSample((0.0, 0.0, 0.0)), -1)
        ids = vtkIdList()
        ids.InsertNextId(7)
        empty.FindSamplesInSphere((0.0, 0.0, 0.0), 1.0, ids)
        self.assertEqual(ids.GetNumberOfIds(), 0)

    def test_copies(self):
        builder = vtkofb.vtkOFBBuilder()
        builder.SetBackendToCPU()
        builder.SetResolution(32)
        source = sphere_source(resolution=16)  # a pipeline does not keep its sources alive
        builder.SetInputConnection(source.GetOutputPort())
        builder.Update()
        ofb = builder.GetOutput()
        shallow, deep = vtkofb.vtkOFB(), vtkofb.vtkOFB()
        shallow.ShallowCopy(ofb)
        deep.DeepCopy(ofb)
        for copy in (shallow, deep):
            self.assertEqual(copy.GetNumberOfSamples(), ofb.GetNumberOfSamples())
            self.assertEqual(copy.GetCellSize(), ofb.GetCellSize())
        self.assertIs(shallow.GetDepths(), ofb.GetDepths())
        self.assertIsNot(deep.GetDepths(), ofb.GetDepths())
        # The output can be passed along as a data object.
        self.assertIsNotNone(vtkofb.vtkOFB.GetData(builder.GetOutputInformation(0)))

    def test_sample_picker_holds_an_ofb(self):
        picker = vtkofb.vtkOFBSamplePicker()
        self.assertIsNone(picker.GetOFB())
        ofb = vtkofb.vtkOFB()
        picker.SetOFB(ofb)
        self.assertIs(picker.GetOFB(), ofb)
        self.assertEqual(picker.GetSampleId(), -1)
        picker.SetTolerance(5.0)
        self.assertEqual(picker.GetTolerance(), 1.0)


class BadInput(unittest.TestCase):
    def build(self, data, resolution=64, backend=None):
        builder = vtkofb.vtkOFBBuilder()
        if backend is None:
            builder.SetBackendToCPU()
        else:
            builder.SetBackend(backend)
        builder.SetResolution(resolution)
        if isinstance(data, vtkDataObject):
            builder.SetInputData(data)
        else:
            builder.SetInputConnection(data.GetOutputPort())
        events = Events(builder, builder.GetExecutive())
        points = vtkofb.vtkOFBToPolyData()
        points.SetInputConnection(builder.GetOutputPort())
        points.Update()
        return builder, events, points.GetOutput()

    def assertEmpty(self, builder, cloud):
        ofb = builder.GetOutput()
        self.assertEqual(ofb.GetNumberOfSamples(), 0)
        self.assertEqual(ofb.GetSampleData().GetNumberOfTuples(), 0)
        self.assertEqual(ofb.FindClosestSample((0.0, 0.0, 0.0)), -1)
        self.assertEqual(cloud.GetNumberOfPoints(), 0)

    def test_empty_polydata(self):
        builder, events, cloud = self.build(vtkPolyData())
        self.assertGreater(events.errors, 0)
        self.assertEmpty(builder, cloud)

    def test_resolution_zero(self):
        builder, events, cloud = self.build(sphere_source(resolution=16), resolution=0)
        self.assertGreater(events.errors, 0)
        self.assertEmpty(builder, cloud)

    def test_recovers_after_an_error(self):
        builder, events, cloud = self.build(sphere_source(resolution=16), resolution=0)
        self.assertGreater(events.errors, 0)
        builder.SetResolution(32)
        builder.Update()
        self.assertGreater(builder.GetOutput().GetNumberOfSamples(), 0)

    def test_opengl_request_falls_back_to_cpu_with_a_warning(self):
        # Without a render window and without a display the OpenGL backend cannot
        # make a context: the builder warns and builds on the CPU.
        source = sphere_source(resolution=16)
        cpu, cpu_events, _ = self.build(source, resolution=48)
        display = os.environ.pop("DISPLAY", None)
        try:
            gl, gl_events, cloud = self.build(source, resolution=48,
                                              backend=vtkofb.vtkOFBBuilder.BACKEND_OPENGL)
        finally:
            if display is not None:
                os.environ["DISPLAY"] = display
        self.assertEqual(gl.GetBackend(), vtkofb.vtkOFBBuilder.BACKEND_OPENGL)
        self.assertGreater(gl_events.warnings, 0)
        self.assertEqual(gl_events.errors, 0)
        self.assertEqual(cpu_events.warnings, 0)
        self.assertEqual(gl.GetLastBackend(), vtkofb.vtkOFBBuilder.BACKEND_CPU)
        self.assertGreater(gl.GetOutput().GetNumberOfSamples(), 0)
        self.assertEqual(gl.GetOutput().GetNumberOfSamples(), cpu.GetOutput().GetNumberOfSamples())
        self.assertEqual(cloud.GetNumberOfPoints(), gl.GetOutput().GetNumberOfSamples())

    @unittest.skipUnless(os.environ.get("DISPLAY"), "needs a display (run under xvfb-run)")
    def test_opengl_request_with_a_display(self):
        # With a display the OpenGL backend builds, or it warns and the CPU does:
        # never an empty output. Both backends agree on the sample count (0.1 %).
        source = sphere_source(resolution=16)
        cpu, _, _ = self.build(source, resolution=48)
        gl, gl_events, cloud = self.build(source, resolution=48,
                                          backend=vtkofb.vtkOFBBuilder.BACKEND_OPENGL)
        self.assertEqual(gl_events.errors, 0)
        self.assertIn(gl.GetLastBackend(), (vtkofb.vtkOFBBuilder.BACKEND_CPU, vtkofb.vtkOFBBuilder.BACKEND_OPENGL))
        if gl.GetLastBackend() == vtkofb.vtkOFBBuilder.BACKEND_CPU:
            self.assertGreater(gl_events.warnings, 0)
        n_cpu = cpu.GetOutput().GetNumberOfSamples()
        n_gl = gl.GetOutput().GetNumberOfSamples()
        self.assertGreater(n_gl, 0)
        self.assertLessEqual(abs(n_gl - n_cpu), 1e-3 * n_cpu)
        self.assertEqual(cloud.GetNumberOfPoints(), n_gl)


class Bunny(unittest.TestCase):
    @unittest.skipUnless(os.environ.get("DISPLAY"), "needs a display (xvfb-run)")
    def test_paint_with_numpy_and_render_through_the_mapper(self):
        """A script paints the OFB through numpy and the mapper shows the paint."""
        from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderWindow, vtkRenderer,
                                                 vtkWindowToImageFilter)
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (object factories)
        sphere = vtkSphereSource()
        sphere.SetThetaResolution(32)
        sphere.SetPhiResolution(16)
        builder = vtkofb.vtkOFBBuilder()
        builder.SetInputConnection(sphere.GetOutputPort())
        builder.SetResolution(128)
        builder.SetBackendToCPU()
        builder.Update()
        ofb = builder.GetOutput()
        colors = numpy_support.vtk_to_numpy(ofb.GetSampleData().GetScalars())
        colors[:] = (255, 0, 0, 255)  # a view of the OFB's own array: paint it red
        ofb.MarkAllSamplesModified()
        ofb.Modified()
        mapper = vtkofb.vtkOFBPolyDataMapper()
        mapper.SetInputConnection(sphere.GetOutputPort())
        mapper.SetOFB(ofb)
        mapper.SetLookupModeToNearest()
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.0, 1.0, 0.0)  # green if the OFB were not used
        actor.GetProperty().SetAmbient(1.0)
        actor.GetProperty().SetDiffuse(0.0)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(64, 64)
        window.AddRenderer(renderer)
        window.Render()
        capture = vtkWindowToImageFilter()
        capture.SetInput(window)
        capture.ReadFrontBufferOff()
        capture.Update()
        image = numpy_support.vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars())
        centre = image.reshape(64, 64, -1)[32, 32]
        self.assertGreater(int(centre[0]), 200)
        self.assertLess(int(centre[1]), 50)

    def test_bundled_bunny(self):
        path = os.path.join(SOURCE_DIR, "Testing", "Data", "stanford-bunny.obj")
        self.assertTrue(os.path.isfile(path), path)
        reader = vtkOBJReader()
        reader.SetFileName(path)
        builder = vtkofb.vtkOFBBuilder()
        builder.SetBackendToCPU()
        builder.SetResolution(256)
        builder.SetInputConnection(reader.GetOutputPort())
        events = Events(builder)
        builder.Update()
        ofb = builder.GetOutput()
        self.assertEqual(events.errors, 0)
        self.assertGreater(reader.GetOutput().GetNumberOfPolys(), 60000)
        self.assertEqual(sum(ofb.GetNumberOfSamples(a) for a in range(3)),
                         ofb.GetNumberOfSamples())
        for a in range(3):
            self.assertGreater(ofb.GetNumberOfSamples(a), 0)
        self.assertGreaterEqual(ofb.GetDepthComplexity(), 2)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
