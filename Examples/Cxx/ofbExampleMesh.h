/**
 * @file   ofbExampleMesh.h
 * @brief  The one way the example applications read a mesh (OBJ, PLY, STL, VTP)
 *
 * VTK 9.1's readers and filters trust the file: a face index past the points crashes
 * vtkPolyDataNormals, a PLY face index past the vertices or a truncated PLY crashes
 * vtkPLYReader, and a PLY header claiming 10^9 vertices keeps it busy for minutes. So the
 * file is checked before VTK's reader sees it, and the data before any filter does:
 *
 * - the path is a regular file;
 * - PLY: the header is complete, every element count is at most MaximumMeshElements and
 *   the body is long enough for them (a binary property takes its size, an ASCII value at
 *   least two bytes) before anything else is read; then the body is walked element by
 *   element (at most MaximumPLYFileBytes): every list fits in the file and every face's
 *   vertex index lies in [0, vertices);
 * - OBJ: every face, line and point element's vertex, texture coordinate and normal index
 *   refers to one the file has (vtkOBJReader crashes on a texture coordinate or normal
 *   index past the end);
 * - binary STL: 84 + 50 x (its triangle count) bytes exactly (an ASCII STL starts with
 *   "solid");
 * - after reading: no error event from the reader, finite point coordinates, every cell's
 *   point ids in [0, number of points), and at least one polygon.
 */
#ifndef ofbExampleMesh_h
#define ofbExampleMesh_h

#include "vtkSmartPointer.h"

#include <string>

class vtkPolyData;

namespace ofbexample
{
/// The most elements (vertices, faces, ...) a PLY header may claim: 2^28.
constexpr long long MaximumMeshElements = 1LL << 28;
/// The largest PLY file walked before reading: 4 GiB.
constexpr long long MaximumPLYFileBytes = 1LL << 32;

/// The mesh at `path` (.obj, .ply, .stl or .vtp by its extension, or by `format` when
/// given: one of those extensions, found from the content by ofbExampleData), checked as
/// above; null with `message` the reason ("cannot read 'PATH': ...").
vtkSmartPointer<vtkPolyData> ReadMeshChecked(const std::string& path,
  std::string& message,
  const std::string& format = std::string());

/// Finite points, every cell's point ids in [0, number of points) and at least one
/// polygon or strip; false with `problem` the reason.
bool CheckPolyData(vtkPolyData* mesh, std::string& problem);

/// Whether the PLY file at `path` is complete: its header, counts and body pass the
/// checks above (used to check a PLY file just written); false with `message` the reason.
bool CheckPLYFile(const std::string& path, std::string& message);

/// `mesh` as triangles with point normals (points kept, not split), or nullptr and a
/// `message` naming `path` when it has no triangles or a filter fails.
vtkSmartPointer<vtkPolyData> TrianglesWithNormals(vtkPolyData* mesh,
  const std::string& path,
  std::string& message);

/// As ReadMeshChecked, as triangles (lines and vertices dropped) with point normals (not
/// split at sharp edges: the points stay those of the file).
vtkSmartPointer<vtkPolyData> ReadSurfaceChecked(const std::string& path, std::string& message);
}

#endif
