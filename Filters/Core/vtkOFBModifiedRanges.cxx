#include "vtkOFBModifiedRanges.h"

#include "vtkIdTypeArray.h"
#include "vtkTimeStamp.h"

#include <algorithm>
#include <utility>

//------------------------------------------------------------------------------
void vtkOFBModifiedRanges::Mark(vtkIdType first, vtkIdType last)
{
  vtkTimeStamp now;
  now.Modified();
  this->Ranges.push_back({ first, last, now.GetMTime() });
  if (this->Ranges.size() <= 256)
  {
    return;
  }
  // Compact the oldest marks only: a consumer that uploads after every change
  // (the mapper, once per frame) then still sees the newest marks exactly.
  // Sort by time; the newest 192 stay as they are; the older ones are merged
  // (overlapping or adjacent ones first, then across their smallest gaps) into at
  // most 32 ranges, each with the newest time of what it merged (still older than
  // the kept ones).
  auto& ranges = this->Ranges;
  std::sort(
    ranges.begin(), ranges.end(), [](const Range& x, const Range& y) { return x.Time < y.Time; });
  const size_t older = ranges.size() - 192;
  std::vector<Range> kept(ranges.begin() + older, ranges.end());
  ranges.resize(older);
  std::sort(
    ranges.begin(), ranges.end(), [](const Range& x, const Range& y) { return x.First < y.First; });
  size_t out = 0;
  for (size_t i = 1; i < ranges.size(); ++i)
  {
    if (ranges[i].First <= ranges[out].Last)
    {
      ranges[out].Last = std::max(ranges[out].Last, ranges[i].Last);
      ranges[out].Time = std::max(ranges[out].Time, ranges[i].Time);
    }
    else
    {
      ranges[++out] = ranges[i];
    }
  }
  ranges.resize(out + 1);
  if (ranges.size() > 32)
  {
    // Close the smallest gaps first, so that a consumer that missed these marks
    // re-sends a few samples in between rather than everything.
    std::vector<vtkIdType> gaps(ranges.size() - 1);
    for (size_t i = 0; i + 1 < ranges.size(); ++i)
    {
      gaps[i] = ranges[i + 1].First - ranges[i].Last;
    }
    std::vector<vtkIdType> sorted = gaps;
    const size_t close = ranges.size() - 32;
    std::nth_element(sorted.begin(), sorted.begin() + (close - 1), sorted.end());
    const vtkIdType threshold = sorted[close - 1];
    size_t merged = 0;
    for (size_t i = 1; i < ranges.size(); ++i)
    {
      if (gaps[i - 1] <= threshold)
      {
        ranges[merged].Last = ranges[i].Last;
        ranges[merged].Time = std::max(ranges[merged].Time, ranges[i].Time);
      }
      else
      {
        ranges[++merged] = ranges[i];
      }
    }
    ranges.resize(merged + 1);
  }
  ranges.insert(ranges.end(), kept.begin(), kept.end());
}

//------------------------------------------------------------------------------
void vtkOFBModifiedRanges::GetRangesSince(vtkMTimeType t, vtkIdType n, vtkIdTypeArray* ranges) const
{
  std::vector<std::pair<vtkIdType, vtkIdType>> newer;
  for (const auto& r : this->Ranges)
  {
    if (r.Time > t)
    {
      newer.emplace_back(r.First, std::min(r.Last, n));
    }
  }
  std::sort(newer.begin(), newer.end());
  for (size_t i = 0; i < newer.size();)
  {
    vtkIdType first = newer[i].first, last = newer[i].second;
    for (++i; i < newer.size() && newer[i].first <= last; ++i)
    {
      last = std::max(last, newer[i].second);
    }
    const vtkIdType tuple[2] = { first, last };
    ranges->InsertNextTypedTuple(tuple);
  }
}
