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
 * segments. With FollowSurface on (the default), stroke points move onto the closest
 * sample and the dabs follow a path over the surface between them (vtkOFBPaintFilter),
 * here over the owned samples of every process: every process walks every path, and at
 * each step every process offers the best of its own samples and all keep the best of
 * all (four all-reduces a step; all paths advance together, so the number of steps is
 * that of the longest path). Ties go to the sample of smallest (cell, depth), as sample
 * ids on one process. Every process thus places the same dabs as one process holding
 * the whole OFB, and each paints its own samples (owned and ghost): the owned samples of
 * all processes are painted as by one process, value for value, whatever the ghost
 * levels, provided the processes share the frame (vtkOFBPSampler) and their owned
 * samples, normals included, are those of one process.
 *
 * A process whose OFB has no samples takes part in the gather and the walks and outputs
 * its empty input without error; if no process has samples, every process reports the
 * error. With no controller, or a single process, it is vtkOFBPaintFilter. Every process
 * must update the filter the same number of times with the same settings.
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

  /**
   * The all-reduces the last update made to place the strokes on the surface (with
   * FollowSurface, on more than one process): 1 for the frame, 1 per level of the
   * growing search spheres and 4 more for the points, then 4 per round of steps. 0
   * otherwise.
   */
  vtkGetMacro(NumberOfStrokeReductions, vtkIdType);

protected:
  vtkOFBPPaintFilter();
  ~vtkOFBPPaintFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkSmartPointer<vtkPolyData> GetStrokes(vtkPolyData* strokes) override;

  vtkMultiProcessController* Controller;
  vtkIdType NumberOfStrokeReductions;

private:
  vtkOFBPPaintFilter(const vtkOFBPPaintFilter&) = delete;
  void operator=(const vtkOFBPPaintFilter&) = delete;
};

#endif
