// Private header of vtkOFBLIC: the contrast stretches and the high-pass filter of the
// enhanced pass (EnhancedLIC).
#ifndef vtkOFBLICEnhance_h
#define vtkOFBLICEnhance_h

#include "vtkOFB.h"
#include "vtkOFBLICCache.h"
#include "vtkOFBLICReduction.h"
#include "vtkOFBLICTracer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <vector>

/**
 * The smallest and largest unmasked values into lo and hi; false if there are none.
 * With a `reduction`, the samples it excludes are left out and lo and hi are those of
 * every process.
 */
inline bool vtkOFBLICRange(const float* values,
  vtkIdType n,
  const unsigned char* mask,
  float& lo,
  float& hi,
  vtkOFBLICReduction* reduction = nullptr)
{
  const unsigned char* excluded = reduction ? reduction->Excluded : nullptr;
  vtkSMPThreadLocal<float> localMin(std::numeric_limits<float>::max());
  vtkSMPThreadLocal<float> localMax(std::numeric_limits<float>::lowest());
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      // Local copies: through the references the compiler stores them every sample (they
      // could alias values).
      float a = localMin.Local();
      float b = localMax.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        const float v = values[i];
        const bool use = !mask[i] && !(excluded && excluded[i]);
        a = use && v < a ? v : a;
        b = use && v > b ? v : b;
      }
      localMin.Local() = a;
      localMax.Local() = b;
    });
  lo = std::numeric_limits<float>::max();
  hi = std::numeric_limits<float>::lowest();
  for (float v : localMin)
  {
    lo = std::min(lo, v);
  }
  for (float v : localMax)
  {
    hi = std::max(hi, v);
  }
  if (reduction)
  {
    reduction->Range(lo, hi);
  }
  return lo <= hi;
}

/// values = clamp((values - m) * scale, 0, 1) at every sample (masked samples' values are
/// never read again: streamlines stop there and the output masks them).
inline void vtkOFBLICMapToUnit(float* values, vtkIdType n, double m, double scale)
{
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
 * Stretch the unmasked values as VTK's contrast enhancement does: with min and max their
 * range, min + low * range -> 0 and max - high * range -> 1, clamped. Nothing where the
 * values are all equal.
 */
inline void vtkOFBLICStretch(float* values,
  vtkIdType n,
  const unsigned char* mask,
  double low,
  double high,
  vtkOFBLICReduction* reduction = nullptr)
{
  float lo, hi;
  if (!vtkOFBLICRange(values, n, mask, lo, hi, reduction) || !(hi > lo))
  {
    return;
  }
  const double range = hi - lo;
  const double m = lo + low * range;
  vtkOFBLICMapToUnit(values, n, m, 1.0 / std::max(1e-12, (hi - high * range) - m));
}

/**
 * Stretch the unmasked values so that the fraction `tail` of them lies below 0 and the
 * same fraction above 1 (then clamped): the quantiles `tail` and 1 - `tail` go to 0 and 1.
 * Unlike the range, they do not depend on a few extreme values (the LIC of the few
 * samples whose streamline is short, at a boundary or a sink, is an average of few noise
 * values). The quantiles are read from a histogram of 4096 bins over the range, counted
 * in integers, so the result does not depend on the number of threads. Nothing where
 * the values are all equal.
 */
inline void vtkOFBLICStretchTails(float* values,
  vtkIdType n,
  const unsigned char* mask,
  double tail,
  vtkOFBLICReduction* reduction = nullptr)
{
  const unsigned char* excluded = reduction ? reduction->Excluded : nullptr;
  float lo, hi;
  if (!vtkOFBLICRange(values, n, mask, lo, hi, reduction) || !(hi > lo))
  {
    return;
  }
  constexpr int Bins = 4096;
  const double binScale = Bins / (static_cast<double>(hi) - lo);
  vtkSMPThreadLocal<std::vector<vtkIdType>> localCounts;
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType>& counts = localCounts.Local();
      counts.resize(Bins, 0);
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double at = (values[i] - lo) * binScale; // NaN (from a noise array) fails
        if (!mask[i] && !(excluded && excluded[i]) && at >= 0.0)
        {
          ++counts[std::min(Bins - 1, static_cast<int>(at))];
        }
      }
    });
  std::vector<vtkIdType> counts(Bins, 0);
  for (const std::vector<vtkIdType>& local : localCounts)
  {
    for (std::size_t b = 0; b < local.size(); ++b)
    {
      counts[b] += local[b];
    }
  }
  if (reduction)
  {
    reduction->Counts(counts.data(), Bins);
  }
  vtkIdType total = 0;
  for (vtkIdType c : counts)
  {
    total += c;
  }
  // The value below which `fraction` of the values lie, interpolated within its bin.
  auto quantile = [&](double fraction)
  {
    const double rank = fraction * total;
    double below = 0.0;
    for (int b = 0; b < Bins; ++b)
    {
      if (below + counts[b] >= rank && counts[b] > 0)
      {
        return lo + (b + (rank - below) / counts[b]) / binScale;
      }
      below += counts[b];
    }
    return static_cast<double>(hi);
  };
  const double m = quantile(tail);
  const double top = quantile(1.0 - tail);
  if (!(top > m))
  {
    return;
  }
  vtkOFBLICMapToUnit(values, n, m, 1.0 / (top - m));
}

/// The share of the first pass's tails that its stretch before the high-pass clips: the
/// quantiles 0.1 % and 99.9 % go to 0 and 1.
constexpr double vtkOFBLICStretchTail = 0.001;

/// The share of the enhanced LIC's result that its final stretch clips at each end.
constexpr double vtkOFBLICFinalStretchTail = 0.02;

/// The high-pass's gain: a sample plus this times its difference to its neighbours' mean.
constexpr double vtkOFBLICHighPassGain = 3.0;

/**
 * The high-pass of vtkOFBLICHighPass over one OFB and its cache: the mean over the
 * samples within 1.5 cells, those of the sample's own grid in the 3 x 3 cells around
 * its cell (no other cell of the grid is that near), else, where fewer than three are
 * (the grid sees the surface at a grazing angle), those of all three grids.
 */
struct vtkOFBLICHighPassWork
{
  static constexpr int K = vtkOFBLICCache::MaxNeighbours;

  vtkOFB* Input;
  vtkOFBLICCache& Cache;
  const float* Values;
  float* Out;
  const unsigned char* Mask;
  const vtkOFBLICSample* Samples;
  unsigned char* NeighbourCount;
  vtkTypeInt16* NeighbourOffsets;
  const vtkIdType* Dims;
  const vtkTypeUInt32* Offsets;
  const float* Depths;
  double CellSize;
  double Radius;

  vtkOFBLICHighPassWork(vtkOFB* input, vtkOFBLICCache& cache)
    : Input(input)
    , Cache(cache)
    , Values(cache.Values.data())
    , Out(cache.Scratch.data())
    , Mask(cache.Mask.data())
    , Samples(cache.Samples.data())
    , NeighbourCount(cache.NeighbourCount.data())
    , NeighbourOffsets(cache.NeighbourOffsets.data())
    , Dims(input->GetDimensions())
    , Offsets(input->GetCellOffsets()->GetPointer(0))
    , Depths(input->GetDepths()->GetPointer(0))
    , CellSize(input->GetCellSize())
    , Radius(1.5 * input->GetCellSize())
  {
  }

  void HighPass(vtkIdType i, double sum, int count) const
  {
    const double mean = count ? sum / count : this->Values[i];
    const double v = this->Values[i] + vtkOFBLICHighPassGain * (this->Values[i] - mean);
    this->Out[i] = static_cast<float>(std::min(1.0, std::max(0.0, v)));
  }

  /// The 3 x 3 cells around cell (iu, iv) of grid a that hold samples, in the order
  /// Search visits them: where each starts, how many it holds and its planar distance.
  struct Block
  {
    vtkIdType First[9];
    vtkIdType Count[9];
    double Planar[9];
    int Size = 0;
  };

  void GetBlock(int a, vtkIdType iu, vtkIdType iv, Block& block) const
  {
    const vtkIdType nu = this->Dims[(a + 1) % 3];
    const vtkIdType nv = this->Dims[(a + 2) % 3];
    const vtkIdType row = this->Input->GetGridCellBase(a) + iv * nu;
    block.Size = 0;
    for (vtkIdType dv = -1; dv <= 1; ++dv)
    {
      for (vtkIdType du = -1; du <= 1; ++du)
      {
        if (iv + dv < 0 || iv + dv >= nv || iu + du < 0 || iu + du >= nu)
        {
          continue;
        }
        const vtkIdType cell = row + dv * nu + iu + du;
        const vtkIdType first = this->Offsets[cell];
        const vtkIdType count = this->Offsets[cell + 1] - first;
        if (count > 0)
        {
          block.First[block.Size] = first;
          block.Count[block.Size] = count;
          block.Planar[block.Size] =
            static_cast<double>(du * du + dv * dv) * this->CellSize * this->CellSize;
          ++block.Size;
        }
      }
    }
  }

  /// Search the neighbours of sample i in the cells of `block` (the 3 x 3 around its
  /// cell, GetBlock) and filter it: every sample of those cells tested. The number of
  /// neighbours, kept where they fit (at most K, each within an int16 of i), else -1;
  /// `ids` receives every neighbour in the order summed.
  int Search(vtkIdType i, const Block& block, std::vector<vtkTypeInt32>& ids) const
  {
    vtkTypeInt16* kept = this->NeighbourOffsets + K * i;
    const double r2 = this->Radius * this->Radius;
    bool fits = true;
    double sum = 0.0;
    int count = 0;
    ids.clear();
    for (int c = 0; c < block.Size; ++c)
    {
      for (vtkIdType j = block.First[c], last = j + block.Count[c]; j < last; ++j)
      {
        const double dd = static_cast<double>(this->Depths[j]) - this->Depths[i];
        if (j != i && !this->Mask[j] && block.Planar[c] + dd * dd <= r2)
        {
          if (count < K && std::abs(j - i) <= 32767)
          {
            kept[count] = static_cast<vtkTypeInt16>(j - i);
          }
          else
          {
            fits = false;
          }
          ids.push_back(static_cast<vtkTypeInt32>(j));
          sum += this->Values[j];
          ++count;
        }
      }
    }
    if (count < 3)
    {
      fits = false;
      this->SearchAllGrids(i, sum, count, ids);
    }
    this->HighPass(i, sum, count);
    return fits ? count : -1;
  }

  /// The neighbours of sample i in all three grids (into `ids`, replacing them).
  void SearchAllGrids(vtkIdType i, double& sum, int& count, std::vector<vtkTypeInt32>& ids) const
  {
    const double* o = this->Input->GetOrigin();
    const double h = this->Input->GetCellSize();
    const float* x = this->Samples[i].Position;
    const glm::dvec3 c(o[0] + h * x[0], o[1] + h * x[1], o[2] + h * x[2]);
    sum = 0.0;
    count = 0;
    ids.clear();
    this->Input->ForEachSampleInSphere(&c.x,
      this->Radius,
      [&](vtkIdType j, double)
      {
        if (j != i && !this->Mask[j])
        {
          ids.push_back(static_cast<vtkTypeInt32>(j));
          sum += this->Values[j];
          ++count;
        }
      });
  }

  /// Filter every sample with the kept neighbours (the offsets, or the ids of those
  /// whose offsets did not fit), summed in the order of the search.
  void FromKeptNeighbours(vtkIdType n) const
  {
    constexpr unsigned char Searched = vtkOFBLICCache::SearchNeighbours;
    vtkSMPTools::For(0,
      n,
      4096,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const unsigned char known = this->NeighbourCount[i];
          if (this->Mask[i])
          {
            this->Out[i] = this->Values[i];
          }
          else if (known != Searched)
          {
            const vtkTypeInt16* kept = this->NeighbourOffsets + K * i;
            double sum = 0.0;
            for (int k = 0; k < known; ++k)
            {
              sum += this->Values[i + kept[k]];
            }
            this->HighPass(i, sum, known);
          }
        }
      });
    const std::vector<vtkOFBLICCache::SearchedSample>& searched = this->Cache.SearchedSamples;
    const vtkTypeInt32* ids = this->Cache.SearchedIds.data();
    vtkSMPTools::For(0,
      static_cast<vtkIdType>(searched.size()),
      1024,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          const vtkOFBLICCache::SearchedSample& e = searched[k];
          double sum = 0.0;
          for (vtkIdType m = e.First; m < e.First + e.Count; ++m)
          {
            sum += this->Values[ids[m]];
          }
          this->HighPass(e.Id, sum, static_cast<int>(e.Count));
        }
      });
  }

  /// The samples of [first, first + count) (sorted by depth) within `r2` of a sample at
  /// depth d, as [lo, hi): a range, since the distance grows with the depth difference.
  /// The search starts at g, the sample of the same layer as the searching sample (its
  /// place in its own cell), where it usually is: the neighbouring cells of a grid see
  /// the same layers of the surface, so the loops below mostly stop at once, and their
  /// branches are predictable where testing every sample of the cell was not.
  static void LayerRange(const float* depths,
    double d,
    double planar,
    double r2,
    vtkIdType g,
    vtkIdType first,
    vtkIdType end,
    vtkIdType& lo,
    vtkIdType& hi)
  {
    auto within = [&](vtkIdType j)
    {
      const double dd = static_cast<double>(depths[j]) - d;
      return planar + dd * dd <= r2;
    };
    if (!within(g))
    {
      // The range, if any, lies on the side of g where d is.
      const vtkIdType step = depths[g] < d ? 1 : -1;
      for (g += step; g >= first && g < end && !within(g); g += step)
      {
        if ((depths[g] < d) != (step > 0))
        {
          break; // past d without a sample within: none
        }
      }
      if (g < first || g >= end || !within(g))
      {
        lo = hi = first;
        return;
      }
    }
    lo = g;
    while (lo > first && within(lo - 1))
    {
      --lo;
    }
    hi = g + 1;
    while (hi < end && within(hi))
    {
      ++hi;
    }
  }

  /// Search's filter of sample i in cell block `block` (layer: its place in its cell)
  /// where its neighbours fit in the kept offsets, and the number kept; -1 where they do
  /// not (nothing written then; Search handles it).
  int SearchBlock(vtkIdType i, vtkIdType layer, const Block& block) const
  {
    const float* depths = this->Depths;
    const unsigned char* mask = this->Mask;
    const float* values = this->Values;
    const double r2 = this->Radius * this->Radius;
    const double d = depths[i];
    vtkTypeInt16* kept = this->NeighbourOffsets + K * i;
    double sum = 0.0;
    int count = 0;
    for (int c = 0; c < block.Size; ++c)
    {
      const vtkIdType first = block.First[c];
      const vtkIdType n = block.Count[c];
      vtkIdType lo = first;
      vtkIdType hi = first;
      if (n == 1)
      {
        const double dd = static_cast<double>(depths[first]) - d;
        hi += block.Planar[c] + dd * dd <= r2 ? 1 : 0;
      }
      else
      {
        LayerRange(
          depths, d, block.Planar[c], r2, first + std::min(layer, n - 1), first, first + n, lo, hi);
      }
      for (vtkIdType j = lo; j < hi; ++j)
      {
        if (j == i || mask[j])
        {
          continue;
        }
        if (count == K || std::abs(j - i) > 32767)
        {
          return -1;
        }
        kept[count++] = static_cast<vtkTypeInt16>(j - i);
        sum += values[j];
      }
    }
    if (count < 3)
    {
      return -1;
    }
    this->HighPass(i, sum, count);
    return count;
  }

  /// Filter every sample by searching its neighbours, cell by cell of the three grids
  /// (SearchBlock, else Search), and keep them (the ids in SearchedSamples and SearchedIds
  /// where they do not fit).
  void SearchingNeighbours()
  {
    constexpr unsigned char Searched = vtkOFBLICCache::SearchNeighbours;
    vtkIdType rowBase[4] = { 0, 0, 0, 0 };
    for (int a = 0; a < 3; ++a)
    {
      rowBase[a + 1] = rowBase[a] + this->Dims[(a + 2) % 3];
    }
    struct Local
    {
      std::vector<vtkOFBLICCache::SearchedSample> Samples;
      std::vector<vtkTypeInt32> Ids;
      std::vector<vtkTypeInt32> Found;
    };
    vtkSMPThreadLocal<Local> locals;
    vtkSMPTools::For(0,
      rowBase[3],
      16,
      [&](vtkIdType beginRow, vtkIdType endRow)
      {
        Local& local = locals.Local();
        Block block;
        for (vtkIdType r = beginRow; r < endRow; ++r)
        {
          const int a = r < rowBase[1] ? 0 : (r < rowBase[2] ? 1 : 2);
          const vtkIdType nu = this->Dims[(a + 1) % 3];
          const vtkIdType iv = r - rowBase[a];
          const vtkIdType row = this->Input->GetGridCellBase(a) + iv * nu;
          for (vtkIdType iu = 0; iu < nu; ++iu)
          {
            const vtkIdType begin = this->Offsets[row + iu];
            const vtkIdType end = this->Offsets[row + iu + 1];
            if (begin == end)
            {
              continue;
            }
            this->GetBlock(a, iu, iv, block);
            for (vtkIdType i = begin; i < end; ++i)
            {
              if (this->Mask[i])
              {
                this->Out[i] = this->Values[i];
                continue;
              }
              int count = this->SearchBlock(i, i - begin, block);
              if (count < 0)
              {
                count = this->Search(i, block, local.Found);
              }
              this->NeighbourCount[i] = count >= 0 ? static_cast<unsigned char>(count) : Searched;
              if (count < 0)
              {
                local.Samples.push_back({ i,
                  static_cast<vtkIdType>(local.Ids.size()),
                  static_cast<vtkIdType>(local.Found.size()) });
                local.Ids.insert(local.Ids.end(), local.Found.begin(), local.Found.end());
              }
            }
          }
        }
      });
    for (const Local& local : locals)
    {
      const vtkIdType base = static_cast<vtkIdType>(this->Cache.SearchedIds.size());
      for (vtkOFBLICCache::SearchedSample e : local.Samples)
      {
        e.First += base;
        this->Cache.SearchedSamples.push_back(e);
      }
      this->Cache.SearchedIds.insert(
        this->Cache.SearchedIds.end(), local.Ids.begin(), local.Ids.end());
    }
    this->Cache.NeighboursKey = this->Cache.SamplesKey;
  }
};

/**
 * The first pass's result in cache.Values stretched (its quantiles vtkOFBLICStretchTail
 * and 1 - vtkOFBLICStretchTail to 0 and 1, clamped), high-pass filtered and clamped to
 * [0, 1], in place: the second pass's input.
 * The neighbours of each sample are found once per packed samples (geometry and mask)
 * and kept in the cache (vtkOFBLICCache::NeighbourCount, NeighbourOffsets): a later
 * enhanced re-convolution (a new AnimationPhase) then sums the kept neighbours in the
 * same order, in one pass over the samples, instead of searching again (the same
 * values, bit for bit); the samples whose neighbours do not fit in offsets (about 1 %
 * on the horse) keep their neighbours' ids (vtkOFBLICCache::SearchedSamples and
 * SearchedIds), so that no re-convolution searches again.
 */
inline void vtkOFBLICHighPass(vtkOFB* input,
  vtkOFBLICCache& cache,
  vtkOFBLICReduction* reduction = nullptr)
{
  vtkOFBLICBuffer<float>& values = cache.Values;
  const vtkIdType n = static_cast<vtkIdType>(values.size());
  // As VTK's enhanced LIC: the first pass stretched to [0, 1], then high-passed and
  // clamped to [0, 1], so that the second pass convolves values of the full range. The
  // first pass is an average of many noise values, so of a narrow range (about 0.35 to
  // 0.45 with the default noise); the stretch maps its quantiles, not its extremes (see
  // vtkOFBLICStretchTails), so the result does not depend on a few samples. Masked
  // samples' values are never read again (streamlines stop there; the output masks them).
  vtkOFBLICStretchTails(values.data(), n, cache.Mask.data(), vtkOFBLICStretchTail, reduction);
  cache.Scratch.resize(n);
  const bool build =
    cache.NeighboursKey != cache.SamplesKey || cache.NeighbourCount.size() != values.size();
  if (build)
  {
    cache.NeighboursKey = vtkOFBLICCacheKey();
    cache.NeighbourCount.resize(n);
    cache.NeighbourOffsets.resize(static_cast<std::size_t>(n) * vtkOFBLICCache::MaxNeighbours);
    cache.SearchedSamples.clear();
    cache.SearchedIds.clear();
  }
  vtkOFBLICHighPassWork work(input, cache); // after the resizes: it holds raw pointers
  if (build)
  {
    work.SearchingNeighbours();
  }
  else
  {
    work.FromKeptNeighbours(n);
  }
  values.swap(cache.Scratch);
}

#endif
