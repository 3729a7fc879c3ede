// Reading a test or benchmark mesh (.ply with vtkPLYReader, else vtkOBJReader);
// shared by the tests (vtkOFBTestUtilities.h) and the benchmark programs.
#ifndef vtkOFBReadMesh_h
#define vtkOFBReadMesh_h

#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"

#include <string>

namespace vtkofbtest
{
/// The surface in `path`, or null if it cannot be read or has no polygons.
inline vtkSmartPointer<vtkPolyData> ReadMeshFile(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".ply")
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  else
  {
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  return mesh && mesh->GetNumberOfPolys() > 0 ? mesh : nullptr;
}

/// As ReadMeshFile, with point normals (not split at sharp edges); null likewise.
inline vtkSmartPointer<vtkPolyData> ReadMeshFileWithNormals(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshFile(path);
  if (!mesh)
  {
    return nullptr;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}
}

#endif
