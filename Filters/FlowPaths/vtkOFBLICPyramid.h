/**
 * @class   vtkOFBLICPyramid
 * @brief   Mipmap pyramid of a vtkOFB whose LIC is computed on every level
 *
 * vtkOFBLICPyramid is a vtkOFBPyramid whose coarser levels hold a LIC computed on their
 * own samples instead of the LIC of level 0 filtered down. A filtered LIC averages its
 * streaks with their neighbours across the flow and fades to grey where many cells share a
 * pixel; a LIC computed on level k, with the noise grain, the step length and the mask in
 * that level's cells, has streaks as wide as level k's cells. vtkOFBPolyDataMapper reads
 * the two levels around a pixel's footprint and blends them (LOOKUP_SMOOTH, or
 * LOOKUP_MIPMAPPED): seen from far, the display shows streaks about a pixel wide at any
 * zoom, as an image-space LIC does, and no line where the level changes.
 *
 * The LIC of every level runs a LIC of the class of the one given with SetLIC (a
 * vtkOFBPLIC gives vtkOFBPLIC levels: contrast stretches over every process's samples,
 * and the samples of other processes that the level's streamlines reach exchanged, see
 * vtkOFBPLIC::LevelGhostSamples), with its settings (normally the filter that computed
 * level 0's LIC; it is not run here, its settings are read at every computation, with
 * vtkOFBLIC::CopySettingsToLevel), on the level's samples, whose field, normals and other
 * arrays are level 0's filtered down (vtkOFBPyramid). Its "LIC" and "LICMask" replace the
 * filtered ones. They are computed when the levels' arrays are: when the levels are
 * rebuilt, and when level 0's "LIC" array changes (a new LIC, another AnimationPhase). Each
 * level keeps its vtkOFBLIC, so that with CacheStreamlines a new phase re-convolves the
 * kept streamlines of every level instead of tracing them again; the filter cache
 * (FilterCacheSize) keeps the levels' LICs of recent phases as it keeps filtered arrays.
 *
 * Cost: the levels hold about a third of level 0's samples together; the LIC of the
 * pyramid costs about half of level 0's, on top of the pyramid's sampling and filtering
 * (docs/lic.md gives the measured times). Without a LIC set, the pyramid is a
 * plain vtkOFBPyramid.
 *
 * @sa vtkOFBPyramid vtkOFBLIC vtkOFBPolyDataMapper
 */

#ifndef vtkOFBLICPyramid_h
#define vtkOFBLICPyramid_h

#include "vtkOFBFlowPathsModule.h" // for export macro
#include "vtkOFBPyramid.h"
#include "vtkSmartPointer.h" // for LevelLICs

#include <vector> // for LevelLICs

class vtkOFBLIC;

class VTKOFBFLOWPATHS_EXPORT vtkOFBLICPyramid : public vtkOFBPyramid
{
public:
  static vtkOFBLICPyramid* New();
  vtkTypeMacro(vtkOFBLICPyramid, vtkOFBPyramid);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The LIC whose settings every level's LIC uses (kept by reference; its settings are
   * read when the levels' LICs are computed). Default none: the LIC is filtered down as
   * any other array.
   */
  void SetLIC(vtkOFBLIC* lic);
  vtkGetObjectMacro(LIC, vtkOFBLIC);
  ///@}

  ///@{
  /**
   * When on, the levels' LICs are left to ComputeLevelLICs(): UpdateLevels() and the
   * arrays' updates filter the LIC down like any array and only record that the levels'
   * LICs are pending (GetLevelLICsPending()). For a distributed LIC (vtkOFBPLIC, whose
   * update makes collective calls), whose levels' LICs must be computed on every process
   * at once: the caller updates the levels on every process, then calls
   * ComputeLevelLICs() on every process together (vtkOFBSurfaceRepresentation under MPI).
   * Use it with FilterCacheSize 0: the cache would keep, and give back, the filtered LIC.
   * Default off: the levels' LICs are computed with the levels' arrays.
   */
  vtkSetMacro(DeferLevelLICs, bool);
  vtkGetMacro(DeferLevelLICs, bool);
  vtkBooleanMacro(DeferLevelLICs, bool);
  ///@}

  /**
   * Whether the levels' LICs wait for ComputeLevelLICs() (DeferLevelLICs on, the levels'
   * arrays computed since the last ComputeLevelLICs()).
   */
  vtkGetMacro(LevelLICsPending, bool);

  /**
   * Compute the LICs of levels 1 .. `numberOfLevels` - 1 now (-1: this pyramid's levels).
   * A level that this pyramid lacks (a process whose piece is empty, or whose levels
   * could not be built) runs its LIC on an empty OFB, so that a distributed LIC makes the
   * same collective calls on every process: every process calls it with the same
   * `numberOfLevels` (the largest of the processes' GetNumberOfLevels()). Clears
   * LevelLICsPending; the levels' arrays count as recomputed (GetArraysTime()).
   */
  void ComputeLevelLICs(int numberOfLevels = -1);

  /**
   * The LIC that computed level `k` (1 .. the levels of the last computation - 1), or
   * null: its timings and, for a vtkOFBPLIC, what it exchanged.
   */
  vtkOFBLIC* GetLevelLIC(int k) const;

  /**
   * How many times the LICs of the levels were computed since creation (each time all
   * coarser levels), for tests and benchmarks.
   */
  vtkGetMacro(NumberOfLevelLICComputations, vtkIdType);

  /**
   * Seconds that the last computation of the levels' LICs took.
   */
  vtkGetMacro(LastLevelLICTime, double);

  /**
   * True for "LIC" and "LICMask" when a LIC is set.
   */
  bool IsComputedArray(const std::string& name) const override;

protected:
  vtkOFBLICPyramid();
  ~vtkOFBLICPyramid() override;

  void ComputeLevelArrays(const std::set<std::string>* names) override;

  /// The LICs of levels 1 .. levels - 1 (ComputeLevelLICs without the arrays' times).
  void RunLevelLICs(int levels);

  /**
   * Called by RunLevelLICs before the levels' LICs, with the number of levels they run
   * on (on every process where the LICs are distributed). The default does nothing.
   */
  virtual void BeginLevelLICs(int levels);

  /**
   * Called by RunLevelLICs before the LIC of level `k` (1..) runs: `level` is the level,
   * null where this pyramid lacks it (the LIC then runs on an empty OFB). The default
   * does nothing; vtkOFBPLICPyramid filters the level again from the finer level merged
   * with the other processes' samples.
   */
  virtual void PrepareLevelLIC(int k, vtkOFB* level);

  /// Copy the settings of `from` that compute a LIC into `to`.
  static void CopySettings(vtkOFBLIC* from, vtkOFBLIC* to);

  vtkOFBLIC* LIC;
  bool DeferLevelLICs;
  bool LevelLICsPending;
  std::vector<vtkSmartPointer<vtkOFBLIC>> LevelLICs; // levels 1..
  vtkIdType NumberOfLevelLICComputations;
  double LastLevelLICTime;

private:
  vtkOFBLICPyramid(const vtkOFBLICPyramid&) = delete;
  void operator=(const vtkOFBLICPyramid&) = delete;
};

#endif
