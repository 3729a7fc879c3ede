/**
 * @class   vtkOFBPLICPyramid
 * @brief   vtkOFBLICPyramid of a piece of a distributed surface: levels as one process's
 *
 * Each process builds the levels of its piece (vtkOFBPyramid: sampled from the piece with
 * its ghost cells, SetLevelSurface, on frames derived from level 0's, the same on every
 * process). Near the piece borders two things of a coarse level k read farther than the
 * ghost cells reach, 2^k times farther than level 0's: the filtering of its arrays from
 * level k - 1, and its LIC. With DeferLevelLICs on (its LICs computed by every process
 * together, ComputeLevelLICs), this pyramid makes both read the samples of one process:
 *
 * - before the LIC of level k, the arrays of level k are filtered again from level k - 1
 *   merged with the owned samples of the other processes within the filter's reach of
 *   this process's owned samples (vtkOFBPyramid::FilterLevel, GetFilterReach), where a
 *   non-computed array of level 0 or the levels' structure changed since the last time;
 * - the LIC of each level is a vtkOFBPLIC with GhostSamples from the LIC's
 *   LevelGhostSamples (default exchange: the owned samples of the other processes that
 *   its streamlines reach).
 *
 * The owned samples of every level then have one process's values (up to float rounding
 * with CacheStreamlines off). The mean of level 0's "LIC" over every process's owned
 * samples (an all-reduce of 2 doubles) is computed with the levels' LICs and given by
 * GetSharedMean(), for vtkOFBPolyDataMapper's blend of levels.
 *
 * Every collective call is made in ComputeLevelLICs(), which every process calls with the
 * same number of levels (a process whose piece is empty too). With no controller, or one
 * process, it is vtkOFBLICPyramid. Colours painted into level 0 in place are filtered on
 * each piece alone (near the borders the levels' colours are those of the piece's samples).
 *
 * @sa vtkOFBLICPyramid vtkOFBPLIC vtkOFBPSampler
 */

#ifndef vtkOFBPLICPyramid_h
#define vtkOFBPLICPyramid_h

#include "vtkOFBLICPyramid.h"
#include "vtkOFBParallelModule.h" // for export macro
#include "vtkTimeStamp.h"         // for RefilterTime
#include "vtkWeakPointer.h"       // for MeanArray

class vtkDataArray;
class vtkMultiProcessController;

class VTKOFBPARALLEL_EXPORT vtkOFBPLICPyramid : public vtkOFBLICPyramid
{
public:
  static vtkOFBPLICPyramid* New();
  vtkTypeMacro(vtkOFBPLICPyramid, vtkOFBLICPyramid);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that share the surface (default: the global controller at
   * construction). Null or a single process: vtkOFBLICPyramid.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * Whether the levels' arrays are filtered again from the finer levels merged with the
   * other processes' samples before their LICs (default on). Off: each piece's levels
   * are filtered from its own samples (near the borders their field and normals differ
   * from one process's by the filtering of fewer samples).
   */
  vtkSetMacro(ExchangeFilterSources, bool);
  vtkGetMacro(ExchangeFilterSources, bool);
  vtkBooleanMacro(ExchangeFilterSources, bool);
  ///@}

  ///@{
  /**
   * What the last ComputeLevelLICs() exchanged for the filtering (this process: bytes
   * sent and received, seconds of the exchanges and the filtering), and the number of
   * levels it filtered again (0 where no array changed).
   */
  vtkGetMacro(LastFilterSentBytes, vtkIdType);
  vtkGetMacro(LastFilterReceivedBytes, vtkIdType);
  vtkGetMacro(LastRefilterTime, double);
  vtkGetMacro(LastRefilteredLevels, int);
  ///@}

  /// The mean of "LIC" over every process's owned samples, where computed for its values.
  bool GetSharedMean(const std::string& name, double& mean) override;

protected:
  vtkOFBPLICPyramid();
  ~vtkOFBPLICPyramid() override;

  void BeginLevelLICs(int levels) override;
  void PrepareLevelLIC(int k, vtkOFB* level) override;

  /// Whether a non-computed array of level 0 or the structure changed since the last
  /// filtering with exchanged sources (this process).
  bool NeedsRefilter();

  vtkMultiProcessController* Controller;
  bool ExchangeFilterSources;
  bool Refilter;
  vtkTimeStamp RefilterTime;
  vtkIdType LastFilterSentBytes;
  vtkIdType LastFilterReceivedBytes;
  double LastRefilterTime;
  int LastRefilteredLevels;
  double Mean;
  vtkWeakPointer<vtkDataArray> MeanArray; // the array Mean is of, and its MTime then
  vtkMTimeType MeanTime;

private:
  vtkOFBPLICPyramid(const vtkOFBPLICPyramid&) = delete;
  void operator=(const vtkOFBPLICPyramid&) = delete;
};

#endif
