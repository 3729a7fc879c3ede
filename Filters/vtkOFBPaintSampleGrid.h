/**
 * @file   vtkOFBPaintSampleGrid.h
 * @brief  Private: the sphere query of vtkOFBPaintKernel on raw pointers
 */

#ifndef vtkOFBPaintSampleGrid_h
#define vtkOFBPaintSampleGrid_h

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkTypeUInt32Array.h"

#include <algorithm>
#include <cmath>

namespace vtkofbpaint
{
/**
 * The OFB's storage as raw pointers, taken once per Paint() call, and the sphere
 * query of vtkOFB::ForEachSampleInSphere specialised for painting: per row of a
 * grid only the cells under the circle's chord are visited (not the bounding
 * square), a cell's first sample at depth >= d - r is found by a linear scan
 * when the cell holds few samples (binary search otherwise), and the next row's
 * offsets are prefetched. The samples and squared distances passed to `f` are
 * those of vtkOFB::ForEachSampleInSphere, in the same order.
 */
struct SampleGrid
{
  const vtkTypeUInt32* Offsets = nullptr;
  const float* Depths = nullptr;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double CellSize = 0.0;
  vtkIdType Dimensions[3] = { 0, 0, 0 };
  vtkIdType CellBase[3] = { 0, 0, 0 };

  void Set(vtkOFB* ofb)
  {
    this->Offsets = ofb->GetCellOffsets()->GetPointer(0);
    this->Depths = ofb->GetDepths()->GetPointer(0);
    ofb->GetOrigin(this->Origin);
    this->CellSize = ofb->GetCellSize();
    ofb->GetDimensions(this->Dimensions);
    for (int a = 0; a < 3; ++a)
    {
      this->CellBase[a] = ofb->GetGridCellBase(a);
    }
  }

  template <typename Functor>
  void ForEachInSphere(const double center[3], double radius, Functor&& f) const
  {
    if (this->CellSize <= 0.0 || !(radius >= 0.0))
    {
      return;
    }
    for (int a = 0; a < 3; ++a)
    {
      this->ForEachInGrid(a, center, radius, f);
    }
  }

  template <typename Functor>
  void ForEachInGrid(int a, const double center[3], double radius, Functor& f) const
  {
    const vtkTypeUInt32* offsets = this->Offsets;
    const float* depths = this->Depths;
    const double s = this->CellSize;
    const double r2 = radius * radius;
    const int ua = (a + 1) % 3;
    const int va = (a + 2) % 3;
    const vtkIdType nu = this->Dimensions[ua];
    const vtkIdType nv = this->Dimensions[va];
    const double lu = (center[ua] - radius - this->Origin[ua]) / s - 0.5;
    const double hu = (center[ua] + radius - this->Origin[ua]) / s - 0.5;
    const double lv = (center[va] - radius - this->Origin[va]) / s - 0.5;
    const double hv = (center[va] + radius - this->Origin[va]) / s - 0.5;
    if (!(hu >= 0.0 && hv >= 0.0 && lu <= nu - 1 && lv <= nv - 1))
    {
      return;
    }
    const vtkIdType u0 = static_cast<vtkIdType>(std::ceil(std::max(lu, 0.0)));
    const vtkIdType u1 = static_cast<vtkIdType>(std::floor(std::min(hu, nu - 1.0)));
    const vtkIdType v0 = static_cast<vtkIdType>(std::ceil(std::max(lv, 0.0)));
    const vtkIdType v1 = static_cast<vtkIdType>(std::floor(std::min(hv, nv - 1.0)));
    const double d = center[a] - this->Origin[a];
    const float dLow = static_cast<float>(d - radius);
    const double dHigh = d + radius;
    const double cu = (center[ua] - this->Origin[ua]) / s - 0.5; // centre in cell units
    for (vtkIdType iv = v0; iv <= v1; ++iv)
    {
      const double dv = this->Origin[va] + (iv + 0.5) * s - center[va];
      const double dv2 = dv * dv;
      if (dv2 > r2)
      {
        continue;
      }
      const vtkIdType rowBase = this->CellBase[a] + iv * nu;
      if (iv < v1)
      {
        __builtin_prefetch(offsets + rowBase + nu + u0);
      }
      // The chord of the circle on this row, one cell wider on each side than
      // exact arithmetic needs: the distance test below decides.
      const double half = std::sqrt(r2 - dv2) / s;
      const vtkIdType cu0 = std::max(u0, static_cast<vtkIdType>(std::floor(cu - half)));
      const vtkIdType cu1 = std::min(u1, static_cast<vtkIdType>(std::ceil(cu + half)));
      for (vtkIdType iu = cu0; iu <= cu1; ++iu)
      {
        const double du = this->Origin[ua] + (iu + 0.5) * s - center[ua];
        const double duv2 = du * du + dv2;
        if (duv2 > r2)
        {
          continue;
        }
        const vtkIdType cell = rowBase + iu;
        vtkIdType i = offsets[cell];
        const vtkIdType end = offsets[cell + 1];
        if (end - i > 8)
        {
          i = static_cast<vtkIdType>(std::lower_bound(depths + i, depths + end, dLow) - depths);
        }
        else
        {
          while (i < end && depths[i] < dLow)
          {
            ++i;
          }
        }
        for (; i < end; ++i)
        {
          if (depths[i] > dHigh)
          {
            break;
          }
          const double dd = depths[i] - d;
          const double dist2 = duv2 + dd * dd;
          if (dist2 <= r2)
          {
            f(i, dist2);
          }
        }
      }
    }
  }
};
}

#endif
