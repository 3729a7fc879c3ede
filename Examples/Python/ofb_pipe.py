"""The pipe of the LIC tests (vtkOFBLICTestHelpers.h, MakePipeWithBump) for the Python and
ParaView examples: imported by lic_defaults.py, Examples/ParaView/ofbParaViewPictures.py,
ParaView/Representation/Examples/ofb_surface.py and Testing/Benchmarks/
ofbParaViewLICBenchmark.py. It needs numpy and VTK's Python modules (Debian's VTK or
ParaView's)."""
import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


def pipe_with_bump(around=256, along=256, field="Flow"):
    """A wall of radius 1 and length 4 along z (around x along quads, two triangles
    each) with an outward bump of height 0.35 on the +x side at mid-length, and a flow
    (point vectors named `field`) along the axis at speed 1 that turns about it at
    1.2 + 0.6 sin(1.5 z) radians per unit."""
    z = np.linspace(-2.0, 2.0, along + 1)[:, None]
    theta = 2.0 * np.pi * np.arange(around)[None, :] / around
    d_theta = np.remainder(theta + np.pi, 2.0 * np.pi) - np.pi
    r = 1.0 + 0.35 * np.exp(-(z * z + d_theta * d_theta) / 0.25)
    x = np.stack(np.broadcast_arrays(r * np.cos(theta), r * np.sin(theta), z), axis=-1)
    omega = 1.2 + 0.6 * np.sin(1.5 * z)
    v = np.stack(np.broadcast_arrays(-omega * x[..., 1], omega * x[..., 0], 1.0), axis=-1)
    points = vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(x.reshape(-1, 3), deep=True))
    flow = numpy_support.numpy_to_vtk(v.reshape(-1, 3).astype(np.float32), deep=True)
    flow.SetName(field)
    j, i = np.meshgrid(np.arange(along), np.arange(around), indexing="ij")
    a = j * around + i
    b = j * around + (i + 1) % around
    c, d = a + around, b + around
    triangles = np.stack([np.stack([a, b, d], -1), np.stack([a, d, c], -1)], axis=2)
    cells = np.hstack([np.full((triangles.size // 3, 1), 3), triangles.reshape(-1, 3)])
    polys = vtkCellArray()
    polys.SetCells(cells.shape[0], numpy_support.numpy_to_vtkIdTypeArray(
        cells.astype(np.int64).ravel(), deep=True))
    pipe = vtkPolyData()
    pipe.SetPoints(points)
    pipe.SetPolys(polys)
    pipe.GetPointData().SetVectors(flow)
    return pipe
