// Private header of vtkOFBLIC: the contrast stretch and the high-pass filter of the
// enhanced pass (EnhancedLIC).
#ifndef vtkOFBLICEnhance_h
#define vtkOFBLICEnhance_h

#include "vtkOFB.h"
#include "vtkOFBLICCache.h"
#include "vtkOFBLICTracer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <vector>

/// Stretch the unmasked values: m + low * range -> 0, M - high * range -> 1, clamped.
inline void vtkOFBLICStretch(float* values,
  vtkIdType n,
  const unsigned char* mask,
  double low,
  double high)
{
  vtkSMPThreadLocal<float> localMin(std::numeric_limits<float>::max());
  vtkSMPThreadLocal<float> localMax(std::numeric_limits<float>::lowest());
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      float& lo = localMin.Local();
      float& hi = localMax.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (!mask[i])
        {
          lo = std::min(lo, values[i]);
          hi = std::max(hi, values[i]);
        }
      }
    });
  float lo = std::numeric_limits<float>::max();
  float hi = std::numeric_limits<float>::lowest();
  for (float v : localMin)
  {
    lo = std::min(lo, v);
  }
  for (float v : localMax)
  {
    hi = std::max(hi, v);
  }
  if (!(hi > lo))
  {
    return;
  }
  const double range = hi - lo;
  const double m = lo + low * range;
  const double scale = 1.0 / std::max(1e-12, (hi - high * range) - m);
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        values[i] = static_cast<float>(std::min(1.0, std::max(0.0, (values[i] - m) * scale)));
      }
    });
}

/**
 * The first pass's result in cache.Values stretched and high-pass filtered, in place.
 * The neighbours of each sample are found once per packed samples (geometry and mask)
 * and kept in the cache (vtkOFBLICCache::NeighbourCount, NeighbourOffsets): a later
 * enhanced re-convolution (a new AnimationPhase) then sums the kept neighbours in the
 * same order, in one pass over the samples, instead of searching again (the same
 * values, bit for bit); only the samples whose neighbours do not fit
 * (vtkOFBLICCache::SearchedSamples, about 1 % on the horse) are searched every time.
 */
inline void vtkOFBLICHighPass(vtkOFB* input, vtkOFBLICCache& cache)
{
  vtkOFBLICBuffer<float>& values = cache.Values;
  const unsigned char* mask = cache.Mask.data();
  const vtkOFBLICSample* samples = cache.Samples.data();
  const vtkIdType n = static_cast<vtkIdType>(values.size());
  vtkOFBLICStretch(values.data(), n, mask, 0.0, 0.0);
  vtkOFBLICBuffer<float>& out = cache.Scratch;
  out.resize(n);
  constexpr int K = vtkOFBLICCache::MaxNeighbours;
  constexpr unsigned char Searched = vtkOFBLICCache::SearchNeighbours;
  const bool build =
    cache.NeighboursKey != cache.SamplesKey || cache.NeighbourCount.size() != values.size();
  if (build)
  {
    cache.NeighboursKey = vtkOFBLICCacheKey();
    cache.NeighbourCount.resize(n);
    cache.NeighbourOffsets.resize(static_cast<std::size_t>(n) * K);
    cache.SearchedSamples.clear();
  }
  unsigned char* neighbourCount = cache.NeighbourCount.data();
  vtkTypeInt16* neighbourOffsets = cache.NeighbourOffsets.data();
  // The mean over the samples within 1.5 cells: those of the sample's own grid, in the
  // 3 x 3 cells around its cell (no other cell of the grid is that near), else, where
  // fewer than three are (the grid sees the surface at a grazing angle), those of all
  // three grids.
  const double cellSize = input->GetCellSize();
  const double radius = 1.5 * cellSize;
  const vtkIdType* dims = input->GetDimensions();
  const vtkTypeUInt32* offsets = input->GetCellOffsets()->GetPointer(0);
  const float* depths = input->GetDepths()->GetPointer(0);
  auto highPass = [&](vtkIdType i, double sum, int count)
  {
    const double mean = count ? sum / count : values[i];
    out[i] = static_cast<float>(values[i] + 4.0 * (values[i] - mean));
  };
  // The search of sample i of grid a in cell (iu, iv); the neighbours kept where they
  // fit (at most K, each within an int16 of i), else false.
  auto search = [&](vtkIdType i, int a, vtkIdType iu, vtkIdType iv)
  {
    const vtkIdType nu = dims[(a + 1) % 3];
    const vtkIdType nv = dims[(a + 2) % 3];
    const vtkIdType row = input->GetGridCellBase(a) + iv * nu;
    vtkTypeInt16* kept = neighbourOffsets + K * i;
    bool fits = true;
    double sum = 0.0;
    int count = 0;
    for (vtkIdType dv = -1; dv <= 1; ++dv)
    {
      for (vtkIdType du = -1; du <= 1; ++du)
      {
        if (iv + dv < 0 || iv + dv >= nv || iu + du < 0 || iu + du >= nu)
        {
          continue;
        }
        const vtkIdType cell = row + dv * nu + iu + du;
        const double planar = static_cast<double>(du * du + dv * dv) * cellSize * cellSize;
        for (vtkIdType j = offsets[cell], last = offsets[cell + 1]; j < last; ++j)
        {
          const double dd = static_cast<double>(depths[j]) - depths[i];
          if (j != i && !mask[j] && planar + dd * dd <= radius * radius)
          {
            if (count < K && std::abs(j - i) <= 32767)
            {
              kept[count] = static_cast<vtkTypeInt16>(j - i);
            }
            else
            {
              fits = false;
            }
            sum += values[j];
            ++count;
          }
        }
      }
    }
    if (count < 3)
    {
      fits = false;
      const glm::dvec3 c = vtkOFBLICTracer::Vec(samples[i].Position);
      sum = 0.0;
      count = 0;
      input->ForEachSampleInSphere(&c.x,
        radius,
        [&](vtkIdType j, double)
        {
          if (j != i && !mask[j])
          {
            sum += values[j];
            ++count;
          }
        });
    }
    highPass(i, sum, count);
    return fits ? count : -1;
  };
  if (!build)
  {
    vtkSMPTools::For(0,
      n,
      4096,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const unsigned char known = neighbourCount[i];
          if (mask[i])
          {
            out[i] = values[i];
          }
          else if (known != Searched)
          {
            const vtkTypeInt16* kept = neighbourOffsets + K * i;
            double sum = 0.0;
            for (int k = 0; k < known; ++k)
            {
              sum += values[i + kept[k]];
            }
            highPass(i, sum, known);
          }
        }
      });
    const std::vector<vtkOFBLICCache::SearchedSample>& searched = cache.SearchedSamples;
    vtkSMPTools::For(0,
      static_cast<vtkIdType>(searched.size()),
      256,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          const vtkOFBLICCache::SearchedSample& e = searched[k];
          search(e.Id, e.Axis, e.U, e.V);
        }
      });
  }
  else
  {
    vtkIdType rowBase[4] = { 0, 0, 0, 0 };
    for (int a = 0; a < 3; ++a)
    {
      rowBase[a + 1] = rowBase[a] + dims[(a + 2) % 3];
    }
    vtkSMPThreadLocal<std::vector<vtkOFBLICCache::SearchedSample>> localSearched;
    vtkSMPTools::For(0,
      rowBase[3],
      16,
      [&](vtkIdType beginRow, vtkIdType endRow)
      {
        std::vector<vtkOFBLICCache::SearchedSample>& list = localSearched.Local();
        for (vtkIdType r = beginRow; r < endRow; ++r)
        {
          const int a = r < rowBase[1] ? 0 : (r < rowBase[2] ? 1 : 2);
          const vtkIdType nu = dims[(a + 1) % 3];
          const vtkIdType iv = r - rowBase[a];
          const vtkIdType row = input->GetGridCellBase(a) + iv * nu;
          for (vtkIdType iu = 0; iu < nu; ++iu)
          {
            for (vtkIdType i = offsets[row + iu], end = offsets[row + iu + 1]; i < end; ++i)
            {
              if (mask[i])
              {
                out[i] = values[i];
                continue;
              }
              const int count = search(i, a, iu, iv);
              neighbourCount[i] = count >= 0 ? static_cast<unsigned char>(count) : Searched;
              if (count < 0)
              {
                list.push_back({ i, a, iu, iv });
              }
            }
          }
        }
      });
    for (const auto& list : localSearched)
    {
      cache.SearchedSamples.insert(cache.SearchedSamples.end(), list.begin(), list.end());
    }
    cache.NeighboursKey = cache.SamplesKey;
  }
  values.swap(out);
  vtkOFBLICStretch(values.data(), n, mask, 0.0, 0.0);
}

#endif
