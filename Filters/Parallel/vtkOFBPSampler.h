/**
 * @class   vtkOFBPSampler
 * @brief   vtkOFBSampler for a surface distributed over processes: one frame for all pieces
 *
 * Each process samples its piece of the surface on the frame of the whole surface: the
 * bounds of every piece are combined (an all-reduce of six doubles through the
 * controller) before the frame is computed, so that every process scan-converts its
 * triangles on the same three grids. A triangle's samples depend on the triangle and the
 * frame alone, so the samples of the pieces together are those of one process sampling
 * the whole surface (for a surface whose triangles are each in one piece).
 *
 * Ghost cells (a "vtkGhostType" cell array, as vtkExtractPolyDataPiece, ParaView's
 * RedistributeDataSet or vtkPDistributedDataFilter give them) are sampled too: their
 * samples get the cell array's value in the sample array "vtkGhostType" (non-zero: a
 * ghost sample, which another process owns), also when PassCellArrays is off, and the
 * point array "vtkGhostType" is not interpolated. A downstream vtkOFBPLIC reads ghost
 * samples across the piece border; the owned samples (ghost value 0) are the piece's
 * share of the whole OFB. Ghost cells also make the computed normals of the border
 * points those of the whole surface.
 *
 * A process whose piece is empty (no polygons or strips) takes part in the reduction
 * and outputs an OFB with the common frame and no samples, without error.
 *
 * With no controller, or one of a single process, it is vtkOFBSampler. The controller is
 * vtkMultiProcessController::GetGlobalController() unless set. Every process must
 * update the sampler the same number of times (each update is one collective call).
 *
 * @sa vtkOFBSampler vtkOFBPLIC vtkOFBPPaintFilter
 */

#ifndef vtkOFBPSampler_h
#define vtkOFBPSampler_h

#include "vtkOFBParallelModule.h" // for export macro
#include "vtkOFBSampler.h"

class vtkMultiProcessController;

class VTKOFBPARALLEL_EXPORT vtkOFBPSampler : public vtkOFBSampler
{
public:
  static vtkOFBPSampler* New();
  vtkTypeMacro(vtkOFBPSampler, vtkOFBSampler);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that share the surface (default: the global controller at
   * construction). Null or a single process: no communication.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  /**
   * The bounds the last update's frame was computed from (those of every process's
   * piece), or an invalid box (min > max) before any update.
   */
  void GetGlobalBounds(double bounds[6]) const;

  /**
   * The frame bounds of a surface distributed over `controller`'s processes: the box of
   * every process's `local` bounds (an all-reduce of six doubles). A process without
   * cells passes an invalid box (min > max, as vtkMath::UninitializeBounds or
   * vtkBoundingBox make it), which adds nothing; where no process has cells, `global` is
   * invalid (min > max). A collective call: every process of `controller` must make
   * it. Null or a single process: `global` is `local`. This is the frame rule of
   * vtkOFBPSampler, for others that build a piece's OFB on the whole surface's frame
   * (the OFB Surface representation of the ParaView plugin).
   */
  static void AllReduceBounds(vtkMultiProcessController* controller,
    const double local[6],
    double global[6]);

protected:
  vtkOFBPSampler();
  ~vtkOFBPSampler() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkSmartPointer<vtkPolyData> GetSurface(vtkDataObject* input) override;
  void GetFrameBounds(const double surfaceBounds[6], double bounds[6]) override;

  vtkMultiProcessController* Controller;

private:
  vtkOFBPSampler(const vtkOFBPSampler&) = delete;
  void operator=(const vtkOFBPSampler&) = delete;

  double GlobalBounds[6];
  bool UseGlobalBounds = false;
  bool GhostCellsOnly = false;
};

#endif
