// Private header of vtkOFBLIC: the streamline tracer and the convolution of one sample
// (paper "Sample-based Surface Coloring", section 6.2.3, Eq. 4).
#ifndef vtkOFBLICTracer_h
#define vtkOFBLICTracer_h

#include "vtkOFB.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

/**
 * Traces a streamline forward and backward from a sample over the surface the OFB
 * samples, reading a per-sample input (the noise, or the first pass's result) at the
 * samples it meets, and returns the kernel-weighted mean of what it read (Eq. 4).
 *
 * A step moves the 3-D position by the field of the current sample (in its tangent
 * plane, StepSize cells long when normalized), looks up the sample there
 * (as vtkOFB::FindSample: in the grid of the current sample, else in the grid most
 * aligned with its normal, else
 * vtkOFB::FindClosestSample within sqrt(3) cells over all three grids, so that a
 * streamline crosses from one grid to another and over edges of the surface) and
 * projects the position onto that sample's tangent plane, which keeps it on the
 * surface. A streamline stops at a masked sample, where no sample is near (the border
 * of an open surface), or where the normal turns by more than 120 degrees in one step
 * (a jump to another sheet of a thin part).
 *
 * Every member is read-only while convolving: one tracer serves all threads.
 */
class vtkOFBLICTracer
{
public:
  const vtkOFB* OFB = nullptr;
  const float* Positions = nullptr; // 3 per sample, world coordinates
  const float* Normals = nullptr;   // 3 per sample, unit
  const float* Field = nullptr;     // 3 per sample, tangent, scaled to the step
  const unsigned char* Mask = nullptr;
  int NumberOfSteps = 0;
  double Step = 0.0;           // world units
  double SearchRadius = 0.0;   // world units
  double FieldRadius = 0.0;    // world units; > 0: inverse-distance field, else nearest
  std::vector<double> Weights; // 2 * NumberOfSteps + 1, index NumberOfSteps is t = 0

  // The OFB's frame and storage, read directly in the inner loop.
  const vtkTypeUInt32* CellIndex = nullptr;
  const vtkTypeUInt32* Offsets = nullptr;
  const float* Depths = nullptr;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double CellSize = 0.0;
  vtkIdType Dimensions[3] = { 0, 0, 0 };
  vtkIdType CellBase[4] = { 0, 0, 0, 0 };

  /// Take the frame and storage of `ofb` (which the tracer then only reads).
  void SetOFB(vtkOFB* ofb)
  {
    this->OFB = ofb;
    this->CellIndex = ofb->GetCellIndex()->GetPointer(0);
    this->Offsets = ofb->GetCellOffsets()->GetPointer(0);
    this->Depths = ofb->GetDepths()->GetPointer(0);
    ofb->GetOrigin(this->Origin);
    this->CellSize = ofb->GetCellSize();
    ofb->GetDimensions(this->Dimensions);
    for (int a = 0; a < 4; ++a)
    {
      this->CellBase[a] = ofb->GetGridCellBase(a);
    }
  }

  /**
   * The sample of grid `a` closest in depth to q in the cell under q, within one cell
   * (vtkOFB::FindSample for a known grid, with a linear scan: cells hold few samples).
   */
  vtkIdType FindInGrid(int a, const glm::dvec3& q) const
  {
    const int u = (a + 1) % 3;
    const int v = (a + 2) % 3;
    const double fu = std::floor((q[u] - this->Origin[u]) / this->CellSize);
    const double fv = std::floor((q[v] - this->Origin[v]) / this->CellSize);
    if (!(fu >= 0.0 && fv >= 0.0 && fu < this->Dimensions[u] && fv < this->Dimensions[v]))
    {
      return -1;
    }
    const vtkIdType cell = this->CellBase[a] + static_cast<vtkIdType>(fv) * this->Dimensions[u] +
      static_cast<vtkIdType>(fu);
    const double d = q[a] - this->Origin[a];
    vtkIdType best = -1;
    double bestDistance = this->CellSize;
    for (vtkIdType i = this->Offsets[cell], end = this->Offsets[cell + 1]; i < end; ++i)
    {
      const double distance = std::fabs(this->Depths[i] - d);
      if (distance <= bestDistance)
      {
        bestDistance = distance;
        best = i;
      }
    }
    return best;
  }

  /// Eq. 4 at sample i over the per-sample values `input`.
  float Convolve(vtkIdType i, const float* input) const
  {
    const int n = this->NumberOfSteps;
    double acc = this->Weights[n] * input[i];
    double weights = this->Weights[n];
    for (int dir = 1; dir >= -1; dir -= 2)
    {
      glm::dvec3 p = Vec(this->Positions, i);
      vtkIdType j = i;
      for (int s = 1; s <= n; ++s)
      {
        j = this->Advance(p, j, dir);
        if (j < 0)
        {
          break;
        }
        const double w = this->Weights[n + dir * s];
        acc += w * input[j];
        weights += w;
      }
    }
    return weights > 1e-9 ? static_cast<float>(acc / weights) : input[i];
  }

  /**
   * One step from position p at sample j in direction dir (+1 forward, -1 backward):
   * p becomes the new position on the surface; returns the new sample, or -1 where
   * the streamline stops.
   */
  vtkIdType Advance(glm::dvec3& p, vtkIdType j, int dir) const
  {
    const glm::dvec3 nj = Vec(this->Normals, j);
    glm::dvec3 q = p + (dir * this->Step) * this->FieldAt(p, j);
    // The grid of sample j first (the surface mostly goes on in the same grid), then the
    // grid of its normal, then all three.
    const vtkIdType cellJ = this->CellIndex[j];
    const int axis = cellJ < this->CellBase[1] ? 0 : (cellJ < this->CellBase[2] ? 1 : 2);
    vtkIdType k = this->FindInGrid(axis, q);
    const int normalAxis = Dominant(nj);
    if (k < 0 && normalAxis != axis)
    {
      k = this->FindInGrid(normalAxis, q);
    }
    if (k < 0)
    {
      k = this->OFB->FindClosestSample(&q.x, this->SearchRadius);
    }
    if (k < 0 || this->Mask[k])
    {
      return -1;
    }
    const glm::dvec3 nk = Vec(this->Normals, k);
    if (glm::dot(nj, nk) < -0.5)
    {
      return -1;
    }
    q -= glm::dot(q - Vec(this->Positions, k), nk) * nk;
    p = q;
    return k;
  }

  /**
   * The field at p on the surface near sample j: the sample's own vector, or with
   * FieldRadius > 0 the Shepard-weighted mean of the unmasked samples within FieldRadius
   * whose normal is within 60 degrees of j's, projected into j's tangent plane and given
   * the length of j's vector.
   */
  glm::dvec3 FieldAt(const glm::dvec3& p, vtkIdType j) const
  {
    const glm::dvec3 vj = Vec(this->Field, j);
    if (this->FieldRadius <= 0.0)
    {
      return vj;
    }
    const glm::dvec3 nj = Vec(this->Normals, j);
    const double eps = 1e-4 * this->CellSize * this->CellSize;
    glm::dvec3 sum(0.0);
    this->OFB->ForEachSampleInSphere(&p.x,
      this->FieldRadius,
      [&](vtkIdType k, double d2)
      {
        if (!this->Mask[k] && glm::dot(Vec(this->Normals, k), nj) > 0.5)
        {
          sum += Vec(this->Field, k) / (d2 + eps);
        }
      });
    sum -= glm::dot(sum, nj) * nj;
    const double length = glm::length(sum);
    return length > 0.0 ? sum * (glm::length(vj) / length) : vj;
  }

  /// The axis of the largest component of n (the grid vtkOFB::FindSample searches).
  static int Dominant(const glm::dvec3& n)
  {
    const glm::dvec3 a = glm::abs(n);
    return a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
  }

  static glm::dvec3 Vec(const float* a, vtkIdType i)
  {
    return glm::dvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
  }
};

#endif
