// Private header: runs [first, last) of sample ids, sorted, joined across small gaps (the
// changed samples of a painter's call, of a pyramid level's partial filtering).
#ifndef vtkOFBRuns_h
#define vtkOFBRuns_h

#include "vtkType.h"

#include <cstddef>
#include <utility>
#include <vector>

/// Join the sorted, disjoint `runs` separated by at most `gap` samples, in place.
inline void vtkOFBJoinRuns(std::vector<std::pair<vtkIdType, vtkIdType>>& runs, vtkIdType gap)
{
  if (runs.empty())
  {
    return;
  }
  std::size_t out = 0;
  for (std::size_t i = 1; i < runs.size(); ++i)
  {
    if (runs[i].first - runs[out].second <= gap)
    {
      runs[out].second = runs[i].second;
    }
    else
    {
      runs[++out] = runs[i];
    }
  }
  runs.resize(out + 1);
}

#endif
