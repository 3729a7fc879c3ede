/**
 * @class   vtkOFBPLIC
 * @brief   vtkOFBLIC on an OFB distributed over processes (vtkOFBPSampler's output)
 *
 * Each process computes the LIC of its piece's samples. Two things make the owned
 * samples' values those of one process computing the whole OFB:
 *
 * - Ghost samples. The filter asks its input for NumberOfGhostLevels ghost levels
 *   (UPDATE_NUMBER_OF_GHOST_LEVELS, which vtkOFBPSampler passes on to the surface's
 *   producer: vtkExtractPolyDataPiece, ParaView's RedistributeDataSet, ...). The ghost
 *   cells' samples (sample array "vtkGhostType" non-zero) are read by the streamlines
 *   and the high-pass like any sample. The ghost layer must be at least as deep as what
 *   a streamline reads: GetRequiredGhostDepth() world units, the length of the
 *   first pass's streamlines plus, with EnhancedLIC, the second pass's and the
 *   high-pass's reach. In levels of cells: that depth over the length of the surface's
 *   shortest edges across the piece borders.
 * - Global statistics. The contrast stretches (EnhancedLIC's quantile stretches,
 *   EnhanceContrast) use the range and histogram of the owned samples of every process
 *   (vtkOFBLICReduction: an all-reduce of 2 floats per range and of 4096 counts per
 *   histogram), so that every piece is stretched alike.
 *
 * The fast LIC (CacheStreamlines on) gives each sample a window of a longer streamline
 * traced from another sample of its tile; which sample seeds it depends on the samples
 * the tile holds, so near piece borders an owned sample may get a neighbour's
 * streamline instead of the one it gets on one process (both pass within
 * StreamlineReuseDistance of it): the values agree statistically, not sample by sample.
 * With CacheStreamlines off (every sample traces its own streamline) they agree sample by
 * sample up to float rounding. With NormalizeVectors off, the field is divided by the
 * largest tangential magnitude of every process's samples (an all-reduce of one double).
 *
 * A process with no samples takes part in the collective calls and outputs its empty
 * input with empty "LIC" and "LICMask" arrays. With no controller, or a single
 * process, it is vtkOFBLIC. Every process must update the filter the same number of
 * times with the same settings.
 *
 * @sa vtkOFBLIC vtkOFBPSampler vtkOFBLICReduction
 */

#ifndef vtkOFBPLIC_h
#define vtkOFBPLIC_h

#include "vtkOFBLIC.h"
#include "vtkOFBParallelModule.h" // for export macro

class vtkMultiProcessController;
class vtkOFB;

class VTKOFBPARALLEL_EXPORT vtkOFBPLIC : public vtkOFBLIC
{
public:
  static vtkOFBPLIC* New();
  vtkTypeMacro(vtkOFBPLIC, vtkOFBLIC);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that share the OFB (default: the global controller at construction).
   * Null or a single process: no communication.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * Ghost levels (rings of cells around each piece) asked of the input, at least
   * (a downstream request for more wins). Default 8; 0 asks for none (the LIC of the
   * samples near piece borders then stops at the border).
   */
  vtkSetClampMacro(NumberOfGhostLevels, int, 0, 1024);
  vtkGetMacro(NumberOfGhostLevels, int);
  ///@}

  /**
   * The depth of ghost samples (world units) that the owned samples' LIC reads at the
   * current settings on an OFB of cell size `cellSize`: StepSize x cellSize x
   * NumberOfSteps (x 1.5 with EnhancedLIC: its second pass runs NumberOfSteps / 2 steps
   * over the first pass's values) plus 3 cells of search and high-pass radius.
   */
  double GetRequiredGhostDepth(double cellSize);

protected:
  vtkOFBPLIC();
  ~vtkOFBPLIC() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The largest tangential field magnitude of the input's unmasked samples (0 if none).
  double LargestFieldMagnitude(vtkOFB* input);

  vtkMultiProcessController* Controller;
  int NumberOfGhostLevels;

private:
  vtkOFBPLIC(const vtkOFBPLIC&) = delete;
  void operator=(const vtkOFBPLIC&) = delete;
};

#endif
