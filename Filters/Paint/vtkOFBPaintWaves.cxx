#include "vtkOFBPaintWaves.h"

#include "vtkOFBPaintKernel.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace
{
// Morton code of a point in units of the largest dab reach (21 bits per axis).
vtkTypeUInt64 MortonCode(const glm::dvec3& q)
{
  auto spread = [](double v)
  {
    // Clamped in double first: NaN (an infinite centre) and values out of range have no
    // integer.
    vtkTypeUInt64 x = static_cast<vtkTypeUInt64>(v > 0.0 ? std::min(v, 2097151.0) : 0.0);
    x = (x | (x << 32)) & 0x1f00000000ffffull;
    x = (x | (x << 16)) & 0x1f0000ff0000ffull;
    x = (x | (x << 8)) & 0x100f00f00f00f00full;
    x = (x | (x << 4)) & 0x10c30c30c30c30c3ull;
    x = (x | (x << 2)) & 0x1249249249249249ull;
    return x;
  };
  return spread(q.x) | (spread(q.y) << 1) | (spread(q.z) << 2);
}

// The hash cell coordinate of v (in cell units) as an integer, clamped in double to
// +-2^60 (NaN to 0) so that the conversion and the neighbour offsets cannot overflow.
std::int64_t CellCoordinate(double v)
{
  constexpr double limit = 1152921504606846976.0; // 2^60
  const double f = std::floor(v);
  return static_cast<std::int64_t>(
    f > -limit ? (f < limit ? f : limit) : (f <= -limit ? -limit : 0.0));
}
}

//------------------------------------------------------------------------------
void vtkOFBPaintWaves::Compute(const std::vector<vtkOFBDab>& dabs, bool smear)
{
  // Each dab's bounding sphere covers what it writes and, for a smear, what it reads.
  const size_t n = dabs.size();
  auto& centre = this->Centre;
  auto& reach = this->Reach;
  centre.resize(n);
  reach.resize(n);
  double maxReach = 0.0;
  glm::dvec3 low(VTK_DOUBLE_MAX);
  for (size_t j = 0; j < n; ++j)
  {
    const vtkOFBDab& d = dabs[j];
    glm::dvec3 c(d.Center[0], d.Center[1], d.Center[2]);
    double r = d.Radius;
    if (smear && d.HasPrevious)
    {
      const glm::dvec3 p(d.Previous[0], d.Previous[1], d.Previous[2]);
      r += 0.5 * glm::length(c - p);
      c = 0.5 * (c + p);
    }
    centre[j] = c;
    reach[j] = r;
    maxReach = std::max(maxReach, r);
    low = glm::min(low, c);
  }
  // Spatial hash of cells of edge 4 * maxReach: two overlapping dabs' centres are at
  // most 2 * maxReach, half a cell, apart, so the other centre lies in the dab's own
  // cell or the neighbour on the nearer side along each axis (8 cells, not 27).
  // Buckets list their dabs in increasing order.
  const double h = 4.0 * maxReach;
  const double invH = 1.0 / h;
  size_t tableSize = 1;
  while (tableSize < 2 * n)
  {
    tableSize <<= 1;
  }
  auto cellOf = [&](const glm::dvec3& c)
  {
    return glm::i64vec3(
      CellCoordinate(c.x * invH), CellCoordinate(c.y * invH), CellCoordinate(c.z * invH));
  };
  auto hashOf = [&](const glm::i64vec3& k)
  {
    const vtkTypeUInt64 v = static_cast<vtkTypeUInt64>(k.x) * 73856093ull ^
      static_cast<vtkTypeUInt64>(k.y) * 19349663ull ^ static_cast<vtkTypeUInt64>(k.z) * 83492791ull;
    return static_cast<size_t>(v & (tableSize - 1));
  };
  auto& bucketOf = this->BucketOf;
  auto& bucketStart = this->BucketStart;
  bucketOf.resize(n);
  bucketStart.assign(tableSize + 1, 0);
  for (size_t j = 0; j < n; ++j)
  {
    bucketOf[j] = hashOf(cellOf(centre[j]));
    ++bucketStart[bucketOf[j] + 1];
  }
  for (size_t b = 0; b < tableSize; ++b)
  {
    bucketStart[b + 1] += bucketStart[b];
  }
  this->Fill.assign(bucketStart.begin(), bucketStart.end() - 1);
  this->Members.resize(n);
  for (size_t j = 0; j < n; ++j)
  {
    this->Members[this->Fill[bucketOf[j]]++] = static_cast<int>(j);
  }
  auto& wave = this->Wave;
  wave.assign(n, 0);
  int numberOfWaves = n > 0 ? 1 : 0;
  for (size_t j = 0; j < n; ++j)
  {
    const glm::dvec3 q = centre[j] * invH;
    const glm::i64vec3 k = cellOf(centre[j]);
    const glm::i64vec3 side(q.x - std::floor(q.x) < 0.5 ? -1 : 1,
      q.y - std::floor(q.y) < 0.5 ? -1 : 1,
      q.z - std::floor(q.z) < 0.5 ? -1 : 1);
    int w = 0;
    for (int corner = 0; corner < 8; ++corner)
    {
      const glm::i64vec3 offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      const size_t b = hashOf(k + offset * side);
      for (int m = bucketStart[b]; m < bucketStart[b + 1]; ++m)
      {
        const int i = this->Members[m];
        if (i >= static_cast<int>(j))
        {
          break;
        }
        const double reachSum = reach[i] + reach[j];
        const glm::dvec3 dc = centre[i] - centre[j];
        if (wave[i] + 1 > w && glm::dot(dc, dc) <= reachSum * reachSum)
        {
          w = wave[i] + 1;
        }
      }
    }
    wave[j] = w;
    numberOfWaves = std::max(numberOfWaves, w + 1);
  }
  this->Sort(numberOfWaves, low, maxReach);
}

//------------------------------------------------------------------------------
void vtkOFBPaintWaves::Sort(int numberOfWaves, const glm::dvec3& low, double maxReach)
{
  // Dabs ordered by wave, then by index.
  const size_t n = this->Wave.size();
  auto& waveStarts = this->WaveStarts;
  auto& order = this->Order;
  waveStarts.assign(numberOfWaves + 1, 0);
  for (size_t j = 0; j < n; ++j)
  {
    ++waveStarts[this->Wave[j] + 1];
  }
  for (int w = 0; w < numberOfWaves; ++w)
  {
    waveStarts[w + 1] += waveStarts[w];
  }
  this->Fill.assign(waveStarts.begin(), waveStarts.end() - 1);
  order.resize(n);
  for (size_t j = 0; j < n; ++j)
  {
    order[this->Fill[this->Wave[j]]++] = static_cast<int>(j);
  }
  // Within a wave the order does not change the result (its dabs share no
  // sample): paint in Morton order of the centres, so that consecutive dabs read
  // neighbouring rows of the grids' offsets, depths and colours.
  auto& key = this->Key;
  key.resize(n);
  const double scale = 1.0 / std::max(maxReach, 1e-300);
  for (int w = 0; w < numberOfWaves; ++w)
  {
    const int begin = waveStarts[w];
    const int end = waveStarts[w + 1];
    if (end - begin <= 2)
    {
      continue;
    }
    for (int k = begin; k < end; ++k)
    {
      key[k] = { MortonCode((this->Centre[order[k]] - low) * scale), order[k] };
    }
    this->SortKeys(begin, end);
    for (int k = begin; k < end; ++k)
    {
      order[k] = key[k].second;
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBPaintWaves::SortKeys(int begin, int end)
{
  // Key[begin, end) by Morton code, then dab (a wave's dabs come in increasing order and
  // the sort is stable: the order of std::sort on the pairs): a least-significant-digit
  // radix sort over the codes' significant bits (about 30 for dabs spread over an OFB of
  // 2048 cells), cheaper than std::sort for the thousands of footprints of a particle
  // step; std::sort below 256 dabs.
  auto& key = this->Key;
  if (end - begin < 256)
  {
    std::sort(key.begin() + begin, key.begin() + end);
    return;
  }
  vtkTypeUInt64 all = 0;
  for (int k = begin; k < end; ++k)
  {
    all |= key[k].first;
  }
  constexpr int DigitBits = 11;
  constexpr size_t Digits = size_t(1) << DigitBits;
  auto& other = this->KeyScratch;
  other.resize(key.size());
  auto& count = this->DigitCount;
  for (int shift = 0; shift < 64 && (all >> shift) != 0; shift += DigitBits)
  {
    count.assign(Digits + 1, 0);
    for (int k = begin; k < end; ++k)
    {
      ++count[((key[k].first >> shift) & (Digits - 1)) + 1];
    }
    for (size_t d = 0; d < Digits; ++d)
    {
      count[d + 1] += count[d];
    }
    for (int k = begin; k < end; ++k)
    {
      other[begin + count[(key[k].first >> shift) & (Digits - 1)]++] = key[k];
    }
    std::copy(other.begin() + begin, other.begin() + end, key.begin() + begin);
  }
}
