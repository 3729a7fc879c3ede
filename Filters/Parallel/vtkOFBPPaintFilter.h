/**
 * @class   vtkOFBPPaintFilter
 * @brief   vtkOFBPaintFilter on an OFB distributed over processes: every stroke on every piece
 *
 * The strokes painted are those of every process's strokes input (port 1), gathered
 * (an all-gather of the stroke polydata) and appended in the order of the processes,
 * so a stroke given on one process (a source that produces its data on the first piece
 * only, as a ParaView poly-line source does) reaches every process whose samples it
 * touches, and each process paints its own samples (owned and ghost). Give each stroke
 * on one process only: a stroke given on two is painted twice.
 *
 * With the painter's FollowSurface off, dabs are spaced along the strokes' straight
 * segments and every sample is painted as by one process painting the whole OFB. With
 * FollowSurface on (the default), stroke points are moved onto the closest sample and
 * the dabs follow the surface between them, on each process's own samples: a stroke that
 * leaves a piece (beyond its ghost samples) is placed on that piece's samples alone, so
 * its dabs there can differ from one process's.
 *
 * A process whose OFB has no samples takes part in the gather and outputs its empty
 * input without error. With no controller, or a single process, it is
 * vtkOFBPaintFilter. Every process must update the filter the same number of times.
 *
 * @sa vtkOFBPaintFilter vtkOFBPSampler
 */

#ifndef vtkOFBPPaintFilter_h
#define vtkOFBPPaintFilter_h

#include "vtkOFBPaintFilter.h"
#include "vtkOFBParallelModule.h" // for export macro

class vtkMultiProcessController;

class VTKOFBPARALLEL_EXPORT vtkOFBPPaintFilter : public vtkOFBPaintFilter
{
public:
  static vtkOFBPPaintFilter* New();
  vtkTypeMacro(vtkOFBPPaintFilter, vtkOFBPaintFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that share the OFB (default: the global controller at construction).
   * Null or a single process: no communication.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkOFBPPaintFilter();
  ~vtkOFBPPaintFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkSmartPointer<vtkPolyData> GetStrokes(vtkPolyData* strokes) override;

  vtkMultiProcessController* Controller;

private:
  vtkOFBPPaintFilter(const vtkOFBPPaintFilter&) = delete;
  void operator=(const vtkOFBPPaintFilter&) = delete;
};

#endif
