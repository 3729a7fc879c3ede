/**
 * @class   vtkOFBStrokeExchange
 * @brief   The collective calls vtkOFBPaintFilter makes on a distributed OFB
 *
 * Set by a distributed subclass (vtkOFBPPaintFilter) for the time of its RequestData.
 * With one, the strokes' points move onto the closest sample of every process's owned
 * samples and their paths follow those samples (see vtkOFBStrokePath): each process
 * offers its own samples' candidates and the processes keep the best, so every process
 * places the same dabs as one process holding the whole OFB. Every method is a
 * collective call.
 *
 * @sa vtkOFBPaintFilter vtkOFBPPaintFilter
 */

#ifndef vtkOFBStrokeExchange_h
#define vtkOFBStrokeExchange_h

#include <vector> // for the buffers

class vtkOFBStrokeExchange
{
public:
  virtual ~vtkOFBStrokeExchange() = default;

  /// The element-wise minimum over every process, in place (the same length everywhere).
  virtual void AllReduceMinimum(std::vector<double>& values) = 0;

  /// Every process's `local` values (the same length everywhere) into `all`, one after
  /// the other in the order of the processes.
  virtual void AllGather(const std::vector<double>& local, std::vector<double>& all) = 0;

  /// The number of processes.
  virtual int GetNumberOfProcesses() const = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkOFBStrokeExchange.h
