#include "vtkOFBStrokePath.h"

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
/// Steps of a walk, in cells.
constexpr double StepCells = 2.0;
/// The cosine of the largest turn between the normals of two consecutive samples.
constexpr double LargestTurnCosine = -0.5;
}

//------------------------------------------------------------------------------
vtkOFBStrokePath::vtkOFBStrokePath(vtkOFB* ofb)
  : OFB(ofb)
{
  if (!ofb || ofb->GetNumberOfSamples() == 0 || !(ofb->GetCellSize() > 0.0))
  {
    return;
  }
  this->Valid = true;
  this->Step = StepCells * ofb->GetCellSize();
  double b[6];
  ofb->GetBounds(b);
  this->Diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  vtkFloatArray* normals =
    vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray(vtkOFB::NormalsArrayName()));
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() >= ofb->GetNumberOfSamples())
  {
    this->Normals = normals;
  }
}

//------------------------------------------------------------------------------
glm::dvec3 vtkOFBStrokePath::Position(vtkIdType id) const
{
  double x[3] = { 0.0, 0.0, 0.0 };
  this->OFB->GetSamplePosition(id, x);
  return glm::dvec3(x[0], x[1], x[2]);
}

//------------------------------------------------------------------------------
bool vtkOFBStrokePath::Facing(vtkIdType a, vtkIdType b) const
{
  if (!this->Normals)
  {
    return true;
  }
  const float* na = this->Normals->GetPointer(3 * a);
  const float* nb = this->Normals->GetPointer(3 * b);
  const double dot = double(na[0]) * nb[0] + double(na[1]) * nb[1] + double(na[2]) * nb[2];
  const double la = double(na[0]) * na[0] + double(na[1]) * na[1] + double(na[2]) * na[2];
  const double lb = double(nb[0]) * nb[0] + double(nb[1]) * nb[1] + double(nb[2]) * nb[2];
  // Samples without a normal (zero length) face every way.
  return !(dot < LargestTurnCosine * std::sqrt(la * lb));
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBStrokePath::Snap(const double x[3], double onSurface[3]) const
{
  std::copy(x, x + 3, onSurface);
  if (!this->Valid)
  {
    return -1;
  }
  // Search spheres of growing radius: the first one with a sample holds the closest.
  double b[6];
  this->OFB->GetBounds(b);
  double outside = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = std::max({ b[2 * k] - x[k], x[k] - b[2 * k + 1], 0.0 });
    outside += d * d;
  }
  const double farthest = std::sqrt(outside) + this->Diagonal;
  vtkIdType id = -1;
  for (double r = std::sqrt(3.0) * this->OFB->GetCellSize(); id < 0; r *= 4.0)
  {
    const bool last = !(r < farthest);
    id = this->OFB->FindClosestSample(x, last ? std::numeric_limits<double>::infinity() : r);
    if (last)
    {
      break;
    }
  }
  if (id >= 0)
  {
    this->OFB->GetSamplePosition(id, onSurface);
  }
  return id;
}

//------------------------------------------------------------------------------
bool vtkOFBStrokePath::Trace(vtkIdType from, vtkIdType to, std::vector<glm::dvec3>& path) const
{
  glm::dvec3 p = this->Position(from);
  const glm::dvec3 target = this->Position(to);
  path.push_back(p);
  if (from == to)
  {
    return true;
  }
  // Each step gets closer to the target by at least a thousandth of a step, so a walk
  // ends; the bound on the steps is far above any path that does.
  const double h = this->Step;
  double distance = glm::length(target - p);
  const double most = 64.0 + 16.0 * (distance + this->Diagonal) / h;
  vtkIdType current = from;
  for (double steps = 0.0; steps < most; ++steps)
  {
    if (distance <= h)
    {
      path.push_back(target);
      return true;
    }
    vtkIdType best = -1;
    double bestDistance = distance - 1e-3 * h;
    const double c[3] = { p.x, p.y, p.z };
    this->OFB->ForEachSampleInSphere(c,
      h,
      [&](vtkIdType id, double)
      {
        const double d = glm::length(target - this->Position(id));
        if (d < bestDistance && this->Facing(current, id))
        {
          bestDistance = d;
          best = id;
        }
      });
    if (best < 0)
    {
      break;
    }
    current = best;
    p = this->Position(best);
    distance = bestDistance;
    path.push_back(p);
  }
  path.push_back(target);
  return false;
}

//------------------------------------------------------------------------------
double vtkOFBStrokePath::Length(const std::vector<glm::dvec3>& path, size_t first, size_t last)
{
  double length = 0.0;
  for (size_t i = first + 1; i <= last && i < path.size(); ++i)
  {
    length += glm::length(path[i] - path[i - 1]);
  }
  return length;
}
