#!/usr/bin/env python3
"""Write the simulation-like inputs of the applications' data tests into a directory.

Usage: make_data_inputs.py OUTDIR

A pipe (radius 1 about the y axis, y in [-2, 2], open ends) in every format the
applications read (ofbExampleData.h), with the arrays a flow solver writes:

  pipe.vtp        polygons; cell vectors "WSS" (wall shear stress, along the axis and
                  around it), cell scalars "WSSMagnitude", point scalars "Pressure"
  pipe.vtu        the same as an unstructured grid of hexahedra (a wall one cell thick),
                  point vectors "Velocity"
  pipe.vtk        legacy VTK polydata, point vectors "Flow"
  pipe.vtm        a multiblock of two blocks named "upstream" and "downstream" (y < 0,
                  y > 0), each with "WSS"
  series.pvd      three time steps (t = 0, 0.5, 1) of pipe-<n>.vtp, "WSS" growing in time
  pipe-strokes.txt  OFBPaint strokes: four points a quarter turn apart around the wall at
                  y = 0 (one given off the wall), radius 0.08, red
  wrong.xyz       not a data file (an unknown format)
"""
import math
import os
import sys

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, vtkCellArray, vtkMultiBlockDataSet,
                                           vtkPolyData, vtkUnstructuredGrid)
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
from vtkmodules.vtkIOXML import (vtkXMLMultiBlockDataWriter, vtkXMLPolyDataWriter,
                                 vtkXMLUnstructuredGridWriter)

AROUND, ALONG = 64, 32


def ring_point(i, j, radius=1.0):
    a = 2.0 * math.pi * i / AROUND
    return (radius * math.cos(a), -2.0 + 4.0 * j / ALONG, -radius * math.sin(a))


def pipe(j0=0, j1=ALONG, scale=1.0):
    """The wall between rows j0 and j1, with WSS (cells) and Pressure (points)."""
    points = vtkPoints()
    pressure = vtkDoubleArray()
    pressure.SetName("Pressure")
    for j in range(j0, j1 + 1):
        for i in range(AROUND):
            p = ring_point(i, j)
            points.InsertNextPoint(p)
            pressure.InsertNextValue(10.0 - p[1])
    polys = vtkCellArray()
    wss = vtkFloatArray()
    wss.SetName("WSS")
    wss.SetNumberOfComponents(3)
    magnitude = vtkFloatArray()
    magnitude.SetName("WSSMagnitude")
    for j in range(j1 - j0):
        for i in range(AROUND):
            a, b = j * AROUND + i, j * AROUND + (i + 1) % AROUND
            polys.InsertNextCell(4, (a, b, b + AROUND, a + AROUND))
            angle = 2.0 * math.pi * (i + 0.5) / AROUND
            # Along the axis and around it (the tangent (-sin, 0, -cos) of the wall).
            v = (-0.3 * math.sin(angle) * scale, scale * (1.0 + 0.5 * math.cos(angle)),
                 -0.3 * math.cos(angle) * scale)
            wss.InsertNextTuple3(*v)
            magnitude.InsertNextValue(math.sqrt(sum(c * c for c in v)))
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    mesh.GetCellData().AddArray(wss)
    mesh.GetCellData().AddArray(magnitude)
    mesh.GetPointData().AddArray(pressure)
    return mesh


def thick_pipe():
    """The wall as hexahedra between radius 1 and 1.1, with point vectors Velocity."""
    points = vtkPoints()
    velocity = vtkDoubleArray()
    velocity.SetName("Velocity")
    velocity.SetNumberOfComponents(3)
    for radius in (1.0, 1.1):
        for j in range(ALONG + 1):
            for i in range(AROUND):
                p = ring_point(i, j, radius)
                points.InsertNextPoint(p)
                velocity.InsertNextTuple3(-p[2], 1.0, p[0])
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    layer = (ALONG + 1) * AROUND
    for j in range(ALONG):
        for i in range(AROUND):
            a, b = j * AROUND + i, j * AROUND + (i + 1) % AROUND
            ids = (a, b, b + AROUND, a + AROUND)
            grid.InsertNextCell(VTK_HEXAHEDRON, 8, ids + tuple(k + layer for k in ids))
    grid.GetPointData().SetVectors(velocity)
    return grid


def write(writer, data, path):
    writer.SetInputData(data)
    writer.SetFileName(path)
    if not writer.Write():
        sys.exit("cannot write " + path)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write(vtkXMLPolyDataWriter(), pipe(), os.path.join(out, "pipe.vtp"))
    write(vtkXMLUnstructuredGridWriter(), thick_pipe(), os.path.join(out, "pipe.vtu"))

    legacy = pipe()
    flow = vtkDoubleArray()
    flow.SetName("Flow")
    flow.SetNumberOfComponents(3)
    for k in range(legacy.GetNumberOfPoints()):
        p = legacy.GetPoint(k)
        flow.InsertNextTuple3(-p[2], 0.5, p[0])
    legacy.GetPointData().SetVectors(flow)
    writer = vtkPolyDataWriter()
    writer.SetFileTypeToASCII()
    write(writer, legacy, os.path.join(out, "pipe.vtk"))

    blocks = vtkMultiBlockDataSet()
    for n, (name, rows) in enumerate((("upstream", (0, ALONG // 2)),
                                      ("downstream", (ALONG // 2, ALONG)))):
        blocks.SetBlock(n, pipe(*rows))
        blocks.GetMetaData(n).Set(vtkMultiBlockDataSet.NAME(), name)
    write(vtkXMLMultiBlockDataWriter(), blocks, os.path.join(out, "pipe.vtm"))

    entries = []
    for n, t in enumerate((0.0, 0.5, 1.0)):
        name = "pipe-%d.vtp" % n
        write(vtkXMLPolyDataWriter(), pipe(scale=1.0 + t), os.path.join(out, name))
        entries.append('    <DataSet timestep="%g" part="0" file="%s"/>' % (t, name))
    with open(os.path.join(out, "series.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                "  <Collection>\n" + "\n".join(entries) + "\n  </Collection>\n</VTKFile>\n")

    with open(os.path.join(out, "pipe-strokes.txt"), "w") as f:
        f.write("# Four points a quarter turn apart around the pipe's wall at y = 0 (the\n"
                "# second given 0.2 outside the wall): a ring, not four dabs.\n"
                "radius 0.08\ncolor 1 0 0\nstrength 1\nstroke\n"
                "1 0 0\n0 0 -1.2\n-1 0 0\n0 0 1\n1 0 0\nend\n")
    with open(os.path.join(out, "wrong.xyz"), "w") as f:
        f.write("this is not a mesh\n1 2 3\n")


if __name__ == "__main__":
    main()
