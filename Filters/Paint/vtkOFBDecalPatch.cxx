#include "vtkOFBDecalPatch.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBTriangleWalker.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"

#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBDecalPatch);

/// The walker and the locator of the last input surface.
struct vtkOFBDecalPatch::vtkInternals
{
  vtkOFBTriangleWalker Walker;
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  vtkPolyData* Input = nullptr;
  vtkMTimeType Time = 0;
};

namespace
{
/// A grid point on the surface and the direction carried to it (unit, in the 2-D frame
/// of its triangle).
struct Node
{
  vtkOFBSurfacePoint Point;
  glm::dvec2 Direction;
};

/// A 3-D vector in the 2-D frame of triangle t (its tangential part).
glm::dvec2 To2D(const vtkOFBTriangleWalker& walker, vtkIdType t, const glm::dvec3& v)
{
  return glm::dvec2(glm::dot(v, walker.To3D(t, glm::dvec2(1.0, 0.0))),
    glm::dot(v, walker.To3D(t, glm::dvec2(0.0, 1.0))));
}

/**
 * The nodes at the distances `offsets` (increasing, > 0) from `start` along its
 * direction (`sign` -1: against it), the direction carried along; a walk that stops on
 * a boundary leaves the remaining nodes there.
 */
void Trace(const vtkOFBTriangleWalker& walker,
  const Node& start,
  double sign,
  const std::vector<double>& offsets,
  std::vector<Node>& out)
{
  Node node = start;
  double done = 0.0;
  bool stopped = false;
  for (double s : offsets)
  {
    if (!stopped)
    {
      glm::dmat2 frame(1.0);
      const vtkOFBTriangleWalker::WalkResult result =
        walker.Walk(node.Point, sign * (s - done) * node.Direction, &frame);
      const glm::dvec2 carried = frame * node.Direction;
      node.Direction = carried / glm::length(carried);
      done = s;
      stopped = result != vtkOFBTriangleWalker::WALK_INSIDE;
    }
    out.push_back(node);
  }
}

/**
 * The `count + 1` nodes of a line of the grid through `centre` (the middle of the line),
 * `length` long along the centre's direction, in order from its start to its end.
 */
std::vector<Node> Line(const vtkOFBTriangleWalker& walker,
  const Node& centre,
  double length,
  int count)
{
  std::vector<double> ahead, behind;
  for (int i = 0; i <= count; ++i)
  {
    const double s = (static_cast<double>(i) / count - 0.5) * length;
    if (s > 0.0)
    {
      ahead.push_back(s);
    }
    else if (s < 0.0)
    {
      behind.insert(behind.begin(), -s);
    }
  }
  std::vector<Node> before, after;
  Trace(walker, centre, -1.0, behind, before);
  Trace(walker, centre, 1.0, ahead, after);
  std::vector<Node> line(before.rbegin(), before.rend());
  if (count % 2 == 0)
  {
    line.push_back(centre);
  }
  line.insert(line.end(), after.begin(), after.end());
  return line;
}
}

//------------------------------------------------------------------------------
vtkOFBDecalPatch::vtkOFBDecalPatch()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkOFBDecalPatch::~vtkOFBDecalPatch() = default;

//------------------------------------------------------------------------------
int vtkOFBDecalPatch::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOFBDecalPatch::CheckSettings()
{
  for (double c : this->Center)
  {
    if (!std::isfinite(c))
    {
      vtkErrorMacro("Center is not finite.");
      return false;
    }
  }
  for (double size : { this->Width, this->Height })
  {
    if (!(size > 0.0) || !std::isfinite(size))
    {
      vtkErrorMacro("Width " << this->Width << " and Height " << this->Height
                             << " must be positive and finite.");
      return false;
    }
  }
  const glm::dvec3 d(this->Direction[0], this->Direction[1], this->Direction[2]);
  if (!(glm::length(d) > 0.0) || !std::isfinite(glm::length(d)))
  {
    vtkErrorMacro("Direction has no length or is not finite.");
    return false;
  }
  for (int r : this->Resolution)
  {
    if (r < 1 || r > 1024)
    {
      vtkErrorMacro("Resolution " << this->Resolution[0] << " x " << this->Resolution[1]
                                  << " is outside [1, 1024].");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkOFBDecalPatch::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  if (!input || !this->CheckSettings())
  {
    return 1;
  }
  // Before the triangulation, which reads the cells' points.
  std::string error;
  if (!vtkOFBCheckCellPointIds(input, error))
  {
    vtkErrorMacro("The surface (input port 0) is invalid: " << error << ".");
    return 1;
  }
  vtkInternals& cache = *this->Internals;
  if (cache.Input != input || cache.Time != input->GetMTime() || !cache.Locator)
  {
    cache.Input = nullptr;
    // (Points repeated per face, as an OBJ with texture coordinates has them, are joined
    // by the walker.)
    vtkSmartPointer<vtkPolyData> triangles = input;
    if (input->GetNumberOfStrips() > 0 || input->GetPolys()->IsHomogeneous() != 3)
    {
      vtkNew<vtkTriangleFilter> triangulate;
      triangulate->PassVertsOff();
      triangulate->PassLinesOff();
      triangulate->SetInputData(input);
      triangulate->Update();
      triangles = triangulate->GetOutput();
    }
    if (!cache.Walker.Build(triangles, nullptr, error))
    {
      vtkErrorMacro("The surface cannot carry a decal: " << error << ".");
      return 1;
    }
    cache.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    cache.Locator->SetDataSet(cache.Walker.GetTriangles());
    cache.Locator->BuildLocator();
    cache.Input = input;
    cache.Time = input->GetMTime();
  }
  const vtkOFBTriangleWalker& walker = cache.Walker;

  // The centre on the surface, and the direction in its triangle's plane.
  double closest[3], dist2 = 0.0;
  vtkIdType cell = -1;
  int subId = 0;
  cache.Locator->FindClosestPoint(this->Center, closest, cell, subId, dist2);
  if (cell < 0)
  {
    vtkErrorMacro("No point of the surface is near the Center.");
    return 1;
  }
  Node centre{ walker.Locate(cell, closest), glm::dvec2(0.0) };
  const glm::dvec3 d(this->Direction[0], this->Direction[1], this->Direction[2]);
  const glm::dvec2 d2 = To2D(walker, centre.Point.Triangle, d);
  if (!(glm::length(d2) > 1e-6 * glm::length(d)))
  {
    vtkErrorMacro("Direction is along the surface normal at the centre: no direction to lay "
                  "the decal in.");
    return 1;
  }
  centre.Direction = d2 / glm::length(d2);

  // The central row along the direction, then a column through each of its points along
  // the perpendicular of the carried direction.
  const int nu = this->Resolution[0], nv = this->Resolution[1];
  const std::vector<Node> row = Line(walker, centre, this->Width, nu);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nu + 1) * (nv + 1));
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(points->GetNumberOfPoints());
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(points->GetNumberOfPoints());
  for (int i = 0; i <= nu; ++i)
  {
    const vtkIdType t = row[i].Point.Triangle;
    const glm::dvec3 u = walker.To3D(t, row[i].Direction);
    const glm::dvec2 v2 = To2D(walker, t, glm::cross(walker.GetNormal(t), u));
    const std::vector<Node> column =
      Line(walker, Node{ row[i].Point, v2 / glm::length(v2) }, this->Height, nv);
    for (int j = 0; j <= nv; ++j)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * (nu + 1) + i;
      const glm::dvec3 x = walker.Position(column[j].Point);
      const glm::dvec3 n = walker.GetNormal(column[j].Point.Triangle);
      points->SetPoint(id, x.x, x.y, x.z);
      tcoords->SetTuple2(id, static_cast<double>(i) / nu, static_cast<double>(j) / nv);
      normals->SetTuple3(id, n.x, n.y, n.z);
    }
    this->UpdateProgress(0.9 * (i + 1) / (nu + 1));
  }

  // Two triangles a quad, turning as the surface's normal does (u, then v).
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (nu + 1) + i;
      const vtkIdType b = a + 1, c = a + nu + 2, e = a + nu + 1;
      const vtkIdType first[3] = { a, b, c };
      const vtkIdType second[3] = { a, c, e };
      polys->InsertNextCell(3, first);
      polys->InsertNextCell(3, second);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetTCoords(tcoords);
  output->GetPointData()->SetNormals(normals);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBDecalPatch::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
     << this->Center[2] << ")\n";
  os << indent << "Direction: (" << this->Direction[0] << ", " << this->Direction[1] << ", "
     << this->Direction[2] << ")\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
}
