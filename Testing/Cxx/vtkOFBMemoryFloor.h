/**
 * @file   vtkOFBMemoryFloor.h
 * @brief  Benchmarks only: the cache lines a batch of small dabs touches, and what
 *         touching that many random lines costs on this machine
 *
 * Many small dabs far apart are bound by memory, not arithmetic: each dab reads a
 * few rows of each grid, every row a separate place in the OFB's arrays.
 * CountFootprintLines counts, through vtkOFB::ForEachSampleInSpheres, the rows the
 * dabs meet and the cache lines of their samples; RandomLineFloor times a
 * read-modify-write of as many random cache lines of a buffer as large as the OFB's
 * arrays, spread over the threads of vtkSMPTools with a prefetch distance of 16:
 * the floor for any painting of those dabs that touches the same lines.
 */

#ifndef vtkOFBMemoryFloor_h
#define vtkOFBMemoryFloor_h

#include "vtkOFB.h"
#include "vtkOFBPrefetch.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vtkofb_bench
{
/// What a batch of dabs touches.
struct FootprintLines
{
  double Rows = 0.0;  // rows of cells with samples, per dab
  double Hits = 0.0;  // samples within the dab, per dab
  double Lines = 0.0; // cache lines, per dab (see below)
};

/**
 * Per dab of `centres` with `radius`: the rows with samples it meets on the three
 * grids and the cache lines it touches: for each row the 64-byte lines of its
 * samples in three 4-byte arrays (depths, cell index, colours), one line of cell
 * offsets and one of changed bits (a lower bound: a row's offsets may straddle two).
 */
inline FootprintLines CountFootprintLines(vtkOFB* ofb, vtkPoints* centres, double radius)
{
  FootprintLines result;
  const vtkIdType n = centres->GetNumberOfPoints();
  if (n == 0)
  {
    return result;
  }
  double rows = 0.0, hits = 0.0, lines = 0.0;
  ofb->ForEachSampleInSpheres(
    n,
    [&](vtkIdType k, double c[3], double& r)
    {
      centres->GetPoint(k, c);
      r = radius;
    },
    [&](vtkIdType, vtkIdType, double) { hits += 1.0; },
    [&](vtkIdType first, vtkIdType last)
    {
      rows += 1.0;
      lines += 3.0 * static_cast<double>((4 * (last - 1)) / 64 - (4 * first) / 64 + 1) + 2.0;
    });
  result.Rows = rows / n;
  result.Hits = hits / n;
  result.Lines = lines / n;
  return result;
}

/**
 * Median seconds (of `repetitions`) for the threads of the current vtkSMPTools
 * scope to read and write one byte of each of `lines` random cache lines of a
 * buffer of `bytes` (in 2 MiB pages where the system gives them).
 */
inline double RandomLineFloor(size_t lines, size_t bytes, int repetitions)
{
  const size_t numberOfLines = std::max<size_t>(bytes / 64, 1);
  // Not value-initialized: the pages are first touched after the madvise.
  std::unique_ptr<unsigned char[]> buffer(
    new unsigned char[numberOfLines * 64 + (size_t(1) << 21)]);
  unsigned char* base = reinterpret_cast<unsigned char*>(
    (reinterpret_cast<uintptr_t>(buffer.get()) + (uintptr_t(1) << 21) - 1) &
    ~((uintptr_t(1) << 21) - 1));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(base, numberOfLines * 64, MADV_HUGEPAGE);
#endif
  std::fill(base, base + numberOfLines * 64, static_cast<unsigned char>(1));
  std::vector<uint32_t> index(lines);
  std::mt19937 random(7u);
  for (auto& i : index)
  {
    i = static_cast<uint32_t>(random() % numberOfLines);
  }
  std::vector<double> seconds;
  for (int r = 0; r < repetitions; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    vtkSMPTools::For(0,
      static_cast<vtkIdType>(lines),
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType i = first; i < last; ++i)
        {
          if (i + 16 < last)
          {
            VTKOFB_PREFETCH_WRITE(base + 64 * size_t(index[i + 16]));
          }
          base[64 * size_t(index[i])] += 1;
        }
      });
    seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}
}

#endif
