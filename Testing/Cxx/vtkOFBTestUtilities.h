// Helpers shared by the GoogleTest units: test meshes and OFB construction.
#ifndef vtkOFBTestUtilities_h
#define vtkOFBTestUtilities_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBReadMesh.h"
#include "vtkOFBSampler.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <string>

namespace vtkofbtest
{
/// Path of a file in the project's Testing/Data.
inline std::string DataPath(const std::string& name)
{
  return std::string(VTKOFB_DATA_DIR) + "/" + name;
}

/// Read an .obj or .ply mesh of Testing/Data; null if it cannot be read.
inline vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& name)
{
  return ReadMeshFile(DataPath(name));
}

/// The point of the unit sphere at longitude theta and colatitude phi (radians).
inline void OnSphere(double theta, double phi, double p[3])
{
  p[0] = std::sin(phi) * std::cos(theta);
  p[1] = std::sin(phi) * std::sin(theta);
  p[2] = std::cos(phi);
}

/// An RGBA colour with random red, green and blue bytes from `random`, and `alpha`.
inline void RandomColor(vtkMinimalStandardRandomSequence* random,
  unsigned char alpha,
  unsigned char c[4])
{
  for (int k = 0; k < 3; ++k)
  {
    c[k] = static_cast<unsigned char>(random->GetNextRangeValue(0, 255));
  }
  c[3] = alpha;
}

/// A finely triangulated sphere (merged seam points), radius `radius` at the origin.
inline vtkSmartPointer<vtkPolyData> MakeSphere(double radius = 1.0, int resolution = 256)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(2 * resolution);
  sphere->SetPhiResolution(resolution);
  sphere->LatLongTessellationOn();
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(sphere->GetOutputPort());
  clean->Update();
  vtkSmartPointer<vtkPolyData> out = clean->GetOutput();
  return out;
}

/// Records the error and warning events of the objects it observes.
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings) += text + "\n";
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  std::string Errors;
  std::string Warnings;
};

/// A 2 x 2 plane at z = 0, normal +z, of `resolution` x `resolution` quads, whose texture
/// coordinates map [0, 1]^2 onto [-1, 1]^2.
inline vtkSmartPointer<vtkPolyData> MakeTexturedPlane(int resolution)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(resolution, resolution);
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->Update();
  vtkSmartPointer<vtkPolyData> out = plane->GetOutput();
  return out;
}

/**
 * A shallow copy of `mesh` with one more polygon, a triangle of points 0, 1 and `badId`
 * (past the end or negative), as a hostile file (an OBJ with `f 1 2 99999`) or a
 * hand-built vtkCellArray gives: vtkPolyData does not refuse it.
 */
inline vtkSmartPointer<vtkPolyData> WithBadPointId(vtkPolyData* mesh, vtkIdType badId)
{
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(mesh->GetPolys());
  const vtkIdType ids[3] = { 0, 1, badId };
  polys->InsertNextCell(3, ids);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  out->SetPolys(polys);
  return out;
}

/// MakeTexturedPlane(4) split into triangles: 25 points, with texture coordinates.
inline vtkSmartPointer<vtkPolyData> MakeTexturedTrianglePlane()
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(MakeTexturedPlane(4));
  triangles->Update();
  vtkSmartPointer<vtkPolyData> out = triangles->GetOutput();
  return out;
}

/// Point ids that MakeTexturedTrianglePlane's 25 points do not have: one past the end, far
/// past it, and negative (for WithBadPointId).
constexpr vtkIdType BadPlanePointIds[] = { 25, 99999, -1 };

/// Add a float sample array `name` holding value(x) at each sample's position x.
template<typename F>
inline void AddSampleArray(vtkOFB* ofb, const char* name, F value)
{
  vtkNew<vtkFloatArray> values;
  values->SetName(name);
  values->SetNumberOfValues(ofb->GetNumberOfSamples());
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    values->SetValue(i, static_cast<float>(value(x)));
  }
  ofb->GetSampleData()->AddArray(values);
}

/// Add a float sample array `name` holding coordinate `axis` of each sample's position.
inline void AddCoordinateArray(vtkOFB* ofb, const char* name, int axis)
{
  AddSampleArray(ofb, name, [axis](const double x[3]) { return x[axis]; });
}

/// Build an OFB of `mesh` on the CPU at `resolution`.
inline vtkSmartPointer<vtkOFB> Build(vtkPolyData* mesh, int resolution)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetResolution(resolution);
  sampler->Update();
  vtkSmartPointer<vtkOFB> ofb = sampler->GetOutput();
  return ofb;
}

/// The mean of the points of cell `c` of `mesh`.
inline void CellCentre(vtkPolyData* mesh, vtkIdType c, double centre[3])
{
  vtkIdType npts;
  const vtkIdType* pts;
  mesh->GetCellPoints(c, npts, pts);
  centre[0] = centre[1] = centre[2] = 0.0;
  for (vtkIdType k = 0; k < npts; ++k)
  {
    double p[3];
    mesh->GetPoint(pts[k], p);
    for (int j = 0; j < 3; ++j)
    {
      centre[j] += p[j] / npts;
    }
  }
}

/// The quadrant of a point about the z axis: 0..3 from the signs of x (1) and y (2).
inline int Quadrant(const double x[3])
{
  return (x[0] >= 0.0 ? 1 : 0) + (x[1] >= 0.0 ? 2 : 0);
}

/// `mesh` cut into four polydata blocks by the quadrants of its cell centres (block q
/// holds quadrant q, with its own points and the point and cell data).
inline vtkSmartPointer<vtkMultiBlockDataSet> CutIntoQuadrants(vtkPolyData* mesh)
{
  vtkNew<vtkIdList> ids[4];
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    double centre[3];
    CellCentre(mesh, c, centre);
    ids[Quadrant(centre)]->InsertNextId(c);
  }
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  for (int q = 0; q < 4; ++q)
  {
    vtkNew<vtkPolyData> block;
    block->AllocateEstimate(ids[q]->GetNumberOfIds(), 3);
    block->GetPointData()->CopyAllocate(mesh->GetPointData());
    block->GetCellData()->CopyAllocate(mesh->GetCellData());
    block->CopyCells(mesh, ids[q]);
    blocks->SetBlock(q, block);
  }
  return blocks;
}
}

#endif
