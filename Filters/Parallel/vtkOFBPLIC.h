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
 * - Exchanged samples (GhostSamples EXCHANGE or GATHER). Instead of the input's ghost
 *   samples, the LIC reads the owned samples of the other processes that its streamlines
 *   reach: each process sends to each other one the owned samples within
 *   GetRequiredGhostDepth() (plus ExchangeMargin cells) of the box of that process's
 *   owned samples, and computes the LIC of its owned samples merged with those it
 *   received, in one process's order (vtkOFBPLICExchange). The owned samples then get
 *   one process's LIC whatever the input's ghost depth. The input's ghost samples take
 *   the value of the received sample of their cell nearest in depth (0.5 where none was
 *   received: they lie beyond what the owned samples' streamlines reach). GATHER sends
 *   every owned sample to every process. The merged samples are kept while the input's
 *   structure and the arrays the LIC reads are unchanged on every process (an all-reduce
 *   of one int decides it): another AnimationPhase, noise or kernel then sends nothing
 *   and re-convolves the kept streamlines. vtkOFBLICPyramid's levels use LevelGhostSamples
 *   (default EXCHANGE): a coarse level's streamlines are 2^k times longer than level 0's,
 *   deeper than the ghost cells made for level 0.
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
#include "vtkWeakPointer.h"       // for ExchangedInput

#include <string> // for ReadArrayNames
#include <vector> // for ReadArrayNames

class vtkMultiProcessController;
class vtkOFB;
struct vtkOFBPLICExchange;

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

  /// Where the samples that the LIC reads beyond the owned ones come from (GhostSamples).
  enum GhostSampleSources
  {
    GHOST_SAMPLES_INPUT = 0,    ///< the input's ghost samples (as deep as its ghost cells)
    GHOST_SAMPLES_EXCHANGE = 1, ///< the owned samples of other processes the LIC reaches
    GHOST_SAMPLES_GATHER = 2    ///< the owned samples of every process (an all-gather)
  };

  ///@{
  /**
   * Where the samples that the owned samples' LIC reads beyond the owned ones come from
   * (GHOST_SAMPLES_INPUT, GHOST_SAMPLES_EXCHANGE or GHOST_SAMPLES_GATHER; default INPUT).
   */
  vtkSetClampMacro(GhostSamples, int, GHOST_SAMPLES_INPUT, GHOST_SAMPLES_GATHER);
  vtkGetMacro(GhostSamples, int);
  ///@}

  ///@{
  /**
   * GhostSamples of the LICs of vtkOFBLICPyramid's coarser levels computed with this
   * LIC's settings (CopySettingsToLevel; default GHOST_SAMPLES_EXCHANGE). Under MPI their
   * updates then always make collective calls: compute the levels' LICs on every process
   * together (vtkOFBLICPyramid::DeferLevelLICs, vtkOFBPLICPyramid).
   */
  vtkSetClampMacro(LevelGhostSamples, int, GHOST_SAMPLES_INPUT, GHOST_SAMPLES_GATHER);
  vtkGetMacro(LevelGhostSamples, int);
  ///@}

  ///@{
  /**
   * Cells added to GetRequiredGhostDepth() for the exchange radius (default 4: the
   * tiles of CacheStreamlines, whose streamlines start at another sample of the tile).
   */
  vtkSetClampMacro(ExchangeMargin, double, 0.0, 1.0e6);
  vtkGetMacro(ExchangeMargin, double);
  ///@}

  ///@{
  /**
   * What the last update exchanged (GhostSamples EXCHANGE or GATHER; 0 otherwise): the
   * samples and bytes this process sent and received, and the seconds the exchange took.
   */
  vtkGetMacro(LastSentSamples, vtkIdType);
  vtkGetMacro(LastReceivedSamples, vtkIdType);
  vtkGetMacro(LastSentBytes, vtkIdType);
  vtkGetMacro(LastReceivedBytes, vtkIdType);
  vtkGetMacro(LastExchangeTime, double);
  ///@}

  /// The controller and LevelGhostSamples (as GhostSamples) to a level's vtkOFBPLIC.
  void CopySettingsToLevel(vtkOFBLIC* level) override;

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

  /// RequestData with the statistics (and the field's scale) of every process.
  int RequestCollective(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  /// RequestData on the owned samples merged with those exchanged (GhostSamples).
  int RequestExchanged(vtkInformation* request, vtkOFB* input, vtkOFB* output);

  /// The sample arrays that the LIC of `input` reads: the field, the normals, the noise.
  std::vector<std::string> ReadArrayNames(vtkOFB* input);

  /**
   * Whether the last exchange holds for `input` (this process): the same input, whose
   * structure and arrays `names` were not modified since, at the same radius. Every
   * process must agree to reuse it (the samples of the others may have changed).
   */
  bool CanReuseExchange(vtkOFB* input, const std::vector<std::string>& names, double radius);

  /// The largest tangential field magnitude of the input's unmasked samples (0 if none).
  double LargestFieldMagnitude(vtkOFB* input);

  vtkMultiProcessController* Controller;
  int NumberOfGhostLevels;
  int GhostSamples;
  int LevelGhostSamples;
  double ExchangeMargin;
  vtkIdType LastSentSamples;
  vtkIdType LastReceivedSamples;
  vtkIdType LastSentBytes;
  vtkIdType LastReceivedBytes;
  double LastExchangeTime;

  // The last exchange, kept while its input is unchanged: the LIC of the same merged OFB
  // then keeps its packed samples, noise and streamlines (another AnimationPhase only
  // convolves again).
  vtkOFBPLICExchange* Exchange;
  vtkWeakPointer<vtkOFB> ExchangedInput;
  bool ExchangedNone; // the input had no samples
  std::vector<std::string> ExchangedNames;
  double ExchangedRadius;
  vtkMTimeType ExchangedTime;

private:
  vtkOFBPLIC(const vtkOFBPLIC&) = delete;
  void operator=(const vtkOFBPLIC&) = delete;
};

#endif
