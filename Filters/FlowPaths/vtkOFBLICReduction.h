/**
 * @class   vtkOFBLICReduction
 * @brief   How vtkOFBLIC combines its statistics with those of other processes
 *
 * vtkOFBLIC stretches its values by statistics over all samples (the range, and a
 * histogram of 4096 bins for the quantiles of EnhancedLIC). On a distributed OFB each
 * process holds a piece of the surface, and the statistics must be those of the whole
 * surface for every piece to get the values of one process. A reduction, set by a
 * distributed subclass (vtkOFBPLIC), makes them so: `Range` replaces this process's range
 * with that of all processes, `Counts` its histogram counts with their sums, and
 * `Excluded` names the samples left out of the statistics (ghost samples, which another
 * process owns and counts). Called once per statistic, never per sample.
 *
 * @sa vtkOFBLIC vtkOFBPLIC
 */

#ifndef vtkOFBLICReduction_h
#define vtkOFBLICReduction_h

#include "vtkType.h" // for vtkIdType

class vtkOFBLICReduction
{
public:
  virtual ~vtkOFBLICReduction() = default;

  /// lo and hi of this process's samples in, of every process's samples out.
  virtual void Range(float& lo, float& hi) = 0;

  /// This process's counts of `bins` bins in, their sums over every process out.
  virtual void Counts(vtkIdType* counts, int bins) = 0;

  /// One flag per sample, non-zero for a sample left out of the statistics; or null.
  const unsigned char* Excluded = nullptr;
};

#endif
// VTK-HeaderTest-Exclude: vtkOFBLICReduction.h
