/**
 * @class   vtkOFBModifiedRanges
 * @brief   The sample ranges of a vtkOFB marked modified, with their times (private)
 *
 * What vtkOFB::MarkSamplesModified records and GetSampleRangesModifiedSince reads:
 * a list of marks, compacted as it grows so that its size stays bounded while the
 * newest marks stay exact (see vtkOFB::MarkSamplesModified).
 */

#ifndef vtkOFBModifiedRanges_h
#define vtkOFBModifiedRanges_h

#include "vtkType.h"

#include <vector>

class vtkIdTypeArray;

class vtkOFBModifiedRanges
{
public:
  /// Record that samples [first, last) (a non-empty range) changed now.
  void Mark(vtkIdType first, vtkIdType last);

  /// Append to `ranges` (2 components) the sorted, merged ranges marked after `t`,
  /// clamped to the `n` samples.
  void GetRangesSince(vtkMTimeType t, vtkIdType n, vtkIdTypeArray* ranges) const;

  void Clear() { this->Ranges.clear(); }

private:
  struct Range
  {
    vtkIdType First;
    vtkIdType Last;
    vtkMTimeType Time;
  };
  std::vector<Range> Ranges;
};

#endif
