/**
 * @class   vtkOFBPyramid
 * @brief   Mipmap stack of a vtkOFB: coarser OFBs whose sample arrays are filtered by IDW
 *
 * vtkOFBPyramid builds the OFB mipmap hierarchy of the paper "Sample-based Surface
 * Coloring" (section 4.2). Level 0 is the OFB given with SetInputOFB (not copied).
 * Level k (k >= 1) samples the surface given with SetSurface (or SetLevelSurface) with
 * vtkOFBSampler at half the resolution of level k-1, on a frame derived from level 0's
 * (the box level 0's frame was computed from: the same on every process where level 0's
 * frame is, as for pieces sampled on the whole surface's frame by vtkOFBPSampler), and every sample
 * array of level k is computed from the samples of level k-1 by distance-weighted averaging
 * (Resample), so that colours are low-pass filtered level by level. Levels stop at
 * MinimumResolution cells on the longest side or at MaximumNumberOfLevels.
 *
 * UpdateLevels() rebuilds the levels when the surface, the structure of level 0 or a
 * setting changed, and recomputes their arrays when level 0 was modified (its MTime)
 * since the last computation (only the arrays modified since, where their MTimes tell:
 * UpdateModifiedArrays()); UpdateArrays() recomputes all of them. (vtkOFBPyramid is a
 * helper object, not a pipeline algorithm: nothing updates it but these calls.) Both run on the CPU
 * (vtkSMPTools).
 *
 * Subclasses may compute an array on each level's own samples instead of filtering it
 * from the finer level (ComputeLevelArrays, IsComputedArray): vtkOFBLICPyramid
 * (OFB::FlowPaths) computes a LIC on every level, so that it keeps its streaks when the
 * filtered LIC would average to grey. vtkOFBPolyDataMapper::SetPyramid takes one.
 *
 * @sa vtkOFB vtkOFBSampler vtkOFBPolyDataMapper
 */

#ifndef vtkOFBPyramid_h
#define vtkOFBPyramid_h

#include "vtkOFBCoreModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members
#include "vtkTimeStamp.h"    // for members
#include "vtkWeakPointer.h"  // for LastInputOFB

#include <set>     // for FilterAllLevels
#include <string>  // for FilterAllLevels
#include <utility> // for TakeCachedLevels
#include <vector>  // for Levels

class vtkDataArray;
class vtkOFB;
class vtkPolyData;

class VTKOFBCORE_EXPORT vtkOFBPyramid : public vtkObject
{
public:
  static vtkOFBPyramid* New();
  vtkTypeMacro(vtkOFBPyramid, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Level 0 of the pyramid (kept by reference, not copied). Default none.
   */
  void SetInputOFB(vtkOFB* ofb);
  vtkGetObjectMacro(InputOFB, vtkOFB);
  ///@}

  ///@{
  /**
   * The surface that the coarser levels sample (normally the one level 0 was built from).
   * Default none.
   */
  void SetSurface(vtkPolyData* surface);
  vtkGetObjectMacro(Surface, vtkPolyData);
  ///@}

  ///@{
  /**
   * The surface that the coarser levels sample instead of Surface, where set (default
   * none): a piece of a distributed surface with its ghost cells, so that the levels have
   * ghost samples as level 0 has, while a renderer sets Surface to the piece it draws
   * (vtkOFBPolyDataMapper sets Surface at every render).
   */
  void SetLevelSurface(vtkPolyData* surface);
  vtkGetObjectMacro(LevelSurface, vtkPolyData);
  ///@}

  ///@{
  /**
   * Most levels, level 0 included (1..16, default 8).
   */
  vtkSetClampMacro(MaximumNumberOfLevels, int, 1, 16);
  vtkGetMacro(MaximumNumberOfLevels, int);
  ///@}

  ///@{
  /**
   * Coarsest resolution: no level has fewer cells than this on its longest side
   * (3..65536, default 8).
   */
  vtkSetClampMacro(MinimumResolution, int, 3, 65536);
  vtkGetMacro(MinimumResolution, int);
  ///@}

  ///@{
  /**
   * Radius of the filter that computes level k from level k-1, in cells of level k
   * (default 1.5, that is three cells of the finer level; at least sqrt(3) cells of
   * level k-1 are always used so that every sample finds a neighbour).
   */
  vtkSetClampMacro(FilterRadius, double, 0.5, 8.0);
  vtkGetMacro(FilterRadius, double);
  ///@}

  ///@{
  /**
   * Memory for the filtered levels of recent contents of a level-0 array, in MiB (default
   * 128; 0 keeps none). When UpdateModifiedArrays() filters an array again (a LIC
   * re-convolved with a new AnimationPhase) whose values are bit for bit those of one
   * filtered before on the same levels, the coarser levels take the arrays kept from then
   * instead of filtering again: an animation that loops over the same phases filters
   * each phase once (at the bunny's 1024 cells a LIC's levels take 2.6 MB, a filtering
   * about a second on 2 cores). The least recently used are dropped first; everything is
   * dropped when the levels are rebuilt, when all arrays are filtered again (which keeps
   * its own results) and when samples are filtered again in place (painting).
   */
  vtkSetClampMacro(FilterCacheSize, int, 0, 1048576);
  vtkGetMacro(FilterCacheSize, int);
  ///@}

  /**
   * How many times an array's levels were taken from the filter cache since creation.
   */
  vtkGetMacro(NumberOfFilterCacheHits, vtkIdType);

  /**
   * Bring the levels up to date. Returns false (with an error) when there is no input
   * OFB or surface, or a level cannot be sampled; level 0 alone is then available.
   */
  bool UpdateLevels();

  /**
   * Recompute the sample arrays of levels 1.. from level 0 now.
   */
  void UpdateArrays();

  /**
   * Recompute only the arrays of levels 1.. whose level-0 array was modified (its
   * MTime) or added since the last computation, as UpdateLevels() does when the
   * structure is unchanged: a LIC re-convolution filters the LIC array alone. Where none
   * is newer (values changed in place, e.g. by painting, with only the OFB Modified()),
   * only the samples of each level that may read one of level 0's samples marked
   * modified since (vtkOFB::MarkSamplesModified) are filtered again, every array, and
   * they are marked modified on their level, so that a renderer uploads them alone; the
   * values are those of a full recomputation. Everything is recomputed where no sample
   * was marked, where more than a quarter of level 0 was, or where a level-0 array is
   * missing from the coarser levels.
   */
  void UpdateModifiedArrays();

  /**
   * Number of levels, level 0 included (0 without an input OFB).
   */
  int GetNumberOfLevels() const;

  /**
   * Level `k` (0 is the input OFB), or null.
   */
  vtkOFB* GetLevel(int k) const;

  ///@{
  /**
   * When the levels were last rebuilt, and when their arrays were last computed.
   */
  vtkMTimeType GetStructureTime() const { return this->StructureTime.GetMTime(); }
  vtkMTimeType GetArraysTime() const { return this->ArraysTime.GetMTime(); }
  ///@}

  /**
   * When all arrays of the levels were last computed (UpdateArrays(), also where
   * UpdateModifiedArrays() recomputed everything); GetArraysTime() is at least as late.
   */
  vtkMTimeType GetAllArraysTime() const { return this->AllArraysTime.GetMTime(); }

  /**
   * Transfer every sample array of `source` to the samples of `target` by distance-
   * weighted averaging over the source samples within `radius` (world units) whose
   * normal does not face away from the target sample's normal, with the smooth compact
   * weight (1 - t^2 / r^2)^2 of the distance t (a low-pass filter: unlike Shepard's
   * 1/t^p weights it does not favour the nearest sample, so patterns finer than the
   * target average out instead of aliasing). A target sample with no such neighbour takes
   * its closest source sample within 2 `radius`, else keeps zeros. Arrays of the target
   * with the same name are replaced. Integer arrays are rounded. Returns false on
   * invalid arguments.
   */
  static bool Resample(vtkOFB* source, vtkOFB* target, double radius);

  /**
   * Whether the sample array `name` of the coarser levels is computed on each level's own
   * samples (by a subclass: vtkOFBLICPyramid's "LIC") instead of filtered from the finer
   * level; the levels of such an array are independent textures, not low-passed copies
   * (vtkOFBPolyDataMapper blends them keeping their contrast). The in-place filtering of
   * changed samples leaves it as it is. Default false.
   */
  virtual bool IsComputedArray(const std::string& name) const;

  /**
   * The mean of level 0's array `name` (its first component clamped to [0, 1], NaN as 0)
   * over the owned samples of every process sharing a distributed surface, where a
   * distributed subclass computed it for the array's current values (true); false
   * otherwise (the default): the caller computes the mean of the samples it has.
   * vtkOFBPolyDataMapper keeps this mean when it blends levels computed on their own.
   */
  virtual bool GetSharedMean(const std::string& name, double& mean);

protected:
  vtkOFBPyramid();
  ~vtkOFBPyramid() override;

  vtkOFB* InputOFB;
  vtkPolyData* Surface;
  vtkPolyData* LevelSurface;
  int MaximumNumberOfLevels;
  int MinimumResolution;
  double FilterRadius;

  std::vector<vtkSmartPointer<vtkOFB>> Levels; // levels 1..
  vtkTimeStamp StructureTime;
  vtkTimeStamp ArraysTime;
  vtkTimeStamp AllArraysTime;
  vtkWeakPointer<vtkOFB> LastInputOFB; // the level 0 the levels were built from
  /// What the filtering of a level 1.. keeps: the sampler's normals (3 floats a sample,
  /// empty without), the facing test's target normals at every filtering; and which
  /// samples found no source within the filter radius (1 byte a sample; they read the
  /// closest within twice the radius).
  struct LevelState
  {
    std::vector<float> ReferenceNormals;
    std::vector<unsigned char> FellBack;
  };
  std::vector<LevelState> States; // levels 1..

  /// A level-0 array's filtered levels 1.., kept for its values' hash (FilterCacheSize).
  struct CachedFiltering
  {
    vtkTypeUInt64 Hash;
    std::string Name;
    vtkMTimeType Structure; // StructureTime when they were filtered
    std::vector<vtkSmartPointer<vtkDataArray>> Levels;
    size_t Bytes;
  };
  std::vector<CachedFiltering> FilterCache; // least recently used first
  int FilterCacheSize;
  vtkIdType NumberOfFilterCacheHits;

  /// The levels of `names` from the cache where their level-0 values were filtered
  /// before (the names are removed from `names`); `hashes` gets every name's hash.
  void TakeCachedLevels(std::set<std::string>& names,
    std::vector<std::pair<std::string, vtkTypeUInt64>>& hashes);
  /// Keep the levels of the arrays just filtered, within FilterCacheSize.
  void CacheLevels(const std::vector<std::pair<std::string, vtkTypeUInt64>>& hashes);

  /**
   * Called after the arrays `names` (all where null) of levels 1.. were filtered from
   * level 0, when all levels' arrays are computed (not after an in-place filtering of
   * changed samples): a subclass computes some arrays on each level's own samples instead
   * of filtering them (vtkOFBLICPyramid: a LIC per level). The default does nothing.
   */
  virtual void ComputeLevelArrays(const std::set<std::string>* names);

  /**
   * Filter the arrays `names` (all where null) of level `k` (1..) from `source` instead of
   * level k - 1, as UpdateArrays() filters them (the facing test's normals and the
   * fallback record of the level's sampling): a distributed subclass gives level k - 1
   * merged with the other processes' samples. False where the level or source is missing
   * or empty.
   */
  bool FilterLevel(int k, vtkOFB* source, const std::set<std::string>* names);

  /**
   * How far (world units) from a sample of level `k` (1..) its filtering reads the
   * samples of level k - 1: twice the filter radius (the fallback's reach); 0 where the
   * levels lack k.
   */
  double GetFilterReach(int k) const;

  /// UpdateModifiedArrays for values changed in place; false where it must do all.
  bool FilterChangedSamples();
  /// Filter the arrays in `names` (a std::set<std::string>, all where null) of every level.
  void FilterAllLevels(const std::set<std::string>* names);

private:
  vtkOFBPyramid(const vtkOFBPyramid&) = delete;
  void operator=(const vtkOFBPyramid&) = delete;
};

#endif
