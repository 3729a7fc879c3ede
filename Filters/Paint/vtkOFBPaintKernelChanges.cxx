// vtkOFBPaintKernel's change tracking: the bitmap of the samples a call changed, turned
// into sorted ranges joined across their smallest gaps (CollectChanged), and the undo
// flags.
#include "vtkOFBPaintKernel.h"
#include "vtkOFBPaintKernelWork.h"
#include "vtkOFBRuns.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <vector>

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::MarkChanged(vtkTypeUInt32 id)
{
  this->ChangedWords[id >> 6].fetch_or(vtkTypeUInt64(1) << (id & 63), std::memory_order_relaxed);
  this->ChangedChunks.fetch_or(ChunkBit(id >> 6), std::memory_order_relaxed);
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::ClearRecorded(const std::vector<vtkOFBColorRecord>& colors,
  const std::vector<vtkOFBNormalRecord>& normals)
{
  for (const auto& r : colors)
  {
    this->Flags[r.Id] &= static_cast<unsigned char>(~COLOR_RECORDED);
  }
  for (const auto& r : normals)
  {
    this->Flags[r.Id] &= static_cast<unsigned char>(~NORMAL_RECORDED);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPaintKernel::CollectChangedWords(vtkIdType firstWord,
  vtkIdType lastWord,
  std::vector<std::pair<vtkIdType, vtkIdType>>& ranges)
{
  vtkIdType count = 0;
  for (vtkIdType w = firstWord; w < lastWord; ++w)
  {
    vtkTypeUInt64 bits = this->ChangedWords[w].load(std::memory_order_relaxed);
    if (!bits)
    {
      continue;
    }
    this->ChangedWords[w].store(0, std::memory_order_relaxed);
    while (bits)
    {
      // The next run of set bits: [first, last).
      const int low = vtkOFBTrailingZeros(bits);
      const vtkTypeUInt64 shifted = bits >> low;
      const int length = ~shifted ? vtkOFBTrailingZeros(~shifted) : 64 - low;
      const vtkIdType first = (w << 6) + low;
      const vtkIdType last = first + length;
      count += length;
      if (!ranges.empty() && ranges.back().second == first)
      {
        ranges.back().second = last;
      }
      else
      {
        ranges.emplace_back(first, last);
      }
      bits = low + length >= 64 ? 0 : bits & (~vtkTypeUInt64(0) << (low + length));
    }
  }
  return count;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPaintKernel::CollectChanged(std::vector<std::pair<vtkIdType, vtkIdType>>& ranges,
  size_t maxRanges)
{
  // Chunks of words in parallel: each chunk's runs of changed samples and a histogram
  // of the gaps between them. Joining runs across their gaps, smallest first by a
  // threshold doubled from 64 samples until at most maxRanges remain, gives the same
  // ranges as joining across every gap up to the final threshold at once: the
  // histogram picks that threshold, and the chunks join their runs in parallel.
  // Chunks are joined in order, so the result does not depend on the number of
  // threads.
  // Only the chunks flagged as changed are read (a dab or two of a stroke changes a
  // few of them; the whole bitmap is a megabyte at 8 M samples).
  ranges.clear();
  const vtkIdType words = this->NumberOfChangedWords;
  constexpr vtkIdType ChunkWords = vtkIdType(1) << ChangedChunkShift;
  constexpr int Buckets = 64;
  Scratch& work = *this->Work;
  std::vector<vtkIdType>& changedChunks = work.ChangedChunkList;
  changedChunks.clear();
  const vtkTypeUInt64 chunkBits = this->ChangedChunks.exchange(0, std::memory_order_relaxed);
  for (vtkIdType c = 0; c < this->NumberOfChangedChunks; ++c)
  {
    if (chunkBits & ChunkBit(c << ChangedChunkShift))
    {
      changedChunks.push_back(c);
    }
  }
  const auto chunks = static_cast<vtkIdType>(changedChunks.size());
  std::vector<std::vector<std::pair<vtkIdType, vtkIdType>>>& parts = work.ChangedParts;
  parts.resize(static_cast<size_t>(chunks));
  work.ChangedCounts.assign(static_cast<size_t>(chunks), 0);
  work.GapHistograms.assign(static_cast<size_t>(chunks * Buckets), 0);
  vtkSMPTools::For(0,
    chunks,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType k = first; k < last; ++k)
      {
        const vtkIdType c = changedChunks[k];
        std::vector<std::pair<vtkIdType, vtkIdType>>& runs = parts[k];
        runs.clear();
        work.ChangedCounts[k] =
          this->CollectChangedWords(c * ChunkWords, std::min(words, (c + 1) * ChunkWords), runs);
        vtkIdType* histogram = work.GapHistograms.data() + k * Buckets;
        for (size_t i = 1; i < runs.size(); ++i)
        {
          ++histogram[vtkOFBCeilLog2(runs[i].first - runs[i - 1].second)];
        }
      }
    });
  // The gaps between chunks (a run that spans two chunks has none), and the totals.
  vtkIdType histogram[Buckets] = {};
  vtkIdType count = 0;
  vtkIdType runs = 0;
  vtkIdType previousEnd = -1;
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    count += work.ChangedCounts[c];
    for (int b = 0; b < Buckets; ++b)
    {
      histogram[b] += work.GapHistograms[c * Buckets + b];
    }
    if (parts[c].empty())
    {
      continue;
    }
    runs += static_cast<vtkIdType>(parts[c].size());
    if (previousEnd >= 0)
    {
      const vtkIdType gap = parts[c].front().first - previousEnd;
      if (gap > 0)
      {
        ++histogram[vtkOFBCeilLog2(gap)];
      }
      else
      {
        --runs; // joined with the previous chunk's last run
      }
    }
    previousEnd = parts[c].back().second;
  }
  // The threshold: gaps of at most `join` samples are joined (0: none).
  vtkIdType join = 0;
  if (maxRanges > 0 && runs > static_cast<vtkIdType>(maxRanges))
  {
    int log2Join = 6;
    auto rangesAfter = [&histogram](int log2Gap)
    {
      vtkIdType wider = 0; // gaps > 2^log2Gap
      for (int b = log2Gap + 1; b < Buckets; ++b)
      {
        wider += histogram[b];
      }
      return wider + 1;
    };
    while (log2Join < Buckets - 1 && rangesAfter(log2Join) > static_cast<vtkIdType>(maxRanges))
    {
      ++log2Join;
    }
    join = vtkIdType(1) << log2Join;
  }
  if (join > 0)
  {
    // In place (the chunks' vectors keep their memory from call to call).
    vtkSMPTools::For(0,
      chunks,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType c = first; c < last; ++c)
        {
          vtkOFBJoinRuns(parts[c], join);
        }
      });
  }
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    for (const auto& r : parts[c])
    {
      if (!ranges.empty() && r.first - ranges.back().second <= join)
      {
        ranges.back().second = r.second;
      }
      else
      {
        ranges.push_back(r);
      }
    }
  }
  return count;
}
