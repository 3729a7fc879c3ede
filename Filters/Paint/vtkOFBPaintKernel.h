/**
 * @file   vtkOFBPaintKernel.h
 * @brief  Private: the per-sample work of vtkOFBPainter (waves, blending, change tracking)
 *
 * vtkOFBPaintKernel holds what a painter keeps per painted OFB: one bit per sample
 * changed by the current call (a bitmap small enough to stay in cache, set a word
 * at a time), one flag byte per sample whose previous value the current undo step
 * holds (touched only while undo is recorded), and the initial colours and normals,
 * copied block by block the first time a block changes (what the Erase blend mode
 * restores).
 *
 * Paint() applies a list of dabs with the result of applying them one after the
 * other: dabs are grouped into waves (a dab goes one wave after the last earlier
 * dab whose sphere, or smear source sphere, it overlaps), the dabs of a wave
 * touch disjoint samples and run in parallel with vtkSMPTools, the waves run in
 * order.
 */

#ifndef vtkOFBPaintKernel_h
#define vtkOFBPaintKernel_h

#include "vtkOFBBrush.h"
#include "vtkType.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

class vtkOFB;
class vtkFloatArray;
class vtkUnsignedCharArray;

/// One dab, with the brush settings that may vary per dab already resolved.
struct vtkOFBDab
{
  double Center[3];
  double Radius;   // world units, > 0
  float Color[4];  // RGBA in [0, 1]
  double Strength; // in [0, 1], pressure included
  bool HasPrevious;
  double Previous[3]; // smear source
  bool HasNormal;
  double Normal[3]; // normal at the centre (normal-aware painting)
};

/// Settings shared by all dabs of one call (the brush's, see vtkOFBBrush).
struct vtkOFBPaintSettings
{
  vtkOFBBrush::FalloffType Falloff = vtkOFBBrush::FALLOFF_SMOOTH;
  vtkOFBBrush::BlendModeType BlendMode = vtkOFBBrush::BLEND_MIX;
  vtkOFBBrush::TargetType Target = vtkOFBBrush::TARGET_COLOR;
  double SmearAmount = 1.0;
  double BumpDepth = 0.5;
  bool NormalAware = false;
  double CosMaxAngle = 0.0;
  bool RecordUndo = true;          // false: keep no previous values (an UndoLimit of 0)
  std::vector<double> CustomTable; // Custom falloff sampled at x = i / (size - 1)
};

/// The previous value of a sample, kept by an undo step.
struct vtkOFBColorRecord
{
  vtkTypeUInt32 Id;
  unsigned char Value[4];
};
struct vtkOFBNormalRecord
{
  vtkTypeUInt32 Id;
  float Value[3];
};

class vtkOFBPaintKernel
{
public:
  vtkOFBPaintKernel();
  ~vtkOFBPaintKernel();
  vtkOFBPaintKernel(const vtkOFBPaintKernel&) = delete;
  vtkOFBPaintKernel& operator=(const vtkOFBPaintKernel&) = delete;

  /// Flag bits of a sample: its previous value is in the current undo step.
  enum : unsigned char
  {
    COLOR_RECORDED = 2,
    NORMAL_RECORDED = 4
  };
  static constexpr int InitialBlockShift = 12; // 4096 samples per initial-value block

  /// Size the per-sample data for `ofb` (clears it, drops the initial values).
  void Reset(vtkOFB* ofb, vtkUnsignedCharArray* colors, vtkFloatArray* normals);

  /// Point at new "Colors" / "Normals" arrays of the same OFB (created on demand).
  void SetArrays(vtkUnsignedCharArray* colors, vtkFloatArray* normals);

  /// Drop the initial values (the next change of a block takes them anew).
  void ResetInitialValues();

  /**
   * Paint `dabs` in order. The previous values of samples not yet recorded in
   * the current undo step are appended to `colorUndo` / `normalUndo`. `progress`
   * (may be empty) is called with a fraction in [0, 1] now and then (within large
   * dabs, and between dabs of calls of many dabs); when it returns false the call
   * stops before its next dab (or wave of parallel dabs).
   */
  void Paint(const std::vector<vtkOFBDab>& dabs,
    const vtkOFBPaintSettings& settings,
    std::vector<vtkOFBColorRecord>& colorUndo,
    std::vector<vtkOFBNormalRecord>& normalUndo,
    const std::function<bool(double)>& progress);

  /**
   * The sorted [first, last) ranges of the samples changed since the last call of
   * this function; clears their changed bits. Returns the number of samples changed.
   * Runs of changed samples are joined across the gaps between them, the smallest
   * first (gaps of up to 64 samples, then 128, ...), until at most `maxRanges`
   * remain; 0 keeps every run.
   */
  vtkIdType CollectChanged(std::vector<std::pair<vtkIdType, vtkIdType>>& ranges,
    size_t maxRanges = 0);

  /**
   * Write `count` given colours (4 bytes each) into samples `ids` (each in range),
   * appending the previous values of samples not yet recorded in the current undo step to
   * `colorUndo` when `recordUndo`; marks the changed ones. Returns how many changed.
   */
  vtkIdType SetColors(const vtkIdType* ids,
    const unsigned char* rgba,
    vtkIdType count,
    bool recordUndo,
    std::vector<vtkOFBColorRecord>& colorUndo);

  /// Mark `ids` changed in this call (undo and redo).
  void MarkChanged(vtkTypeUInt32 id);

  /// Clear the "recorded in this step" flags of the given records.
  void ClearRecorded(const std::vector<vtkOFBColorRecord>& colors,
    const std::vector<vtkOFBNormalRecord>& normals);

  /// Bytes held (flags and initial values).
  vtkIdType GetMemory() const;

  vtkOFB* GetOFB() const { return this->OFB; }

private:
  struct DabWork;
  struct Scratch;

  /// What painting a colour dab needs, resolved before its samples are visited.
  struct ColorDab
  {
    float Source[4]; // the colour laid down (a smear's carried colour mixed in)
    double InverseRadius;
    double Strength;
    float Cone[3]; // the centre's normal, when Aware
    bool Aware;
  };
  struct LocalRecords;
  /// Paint dabs[order[0 .. count - 1]] in that order (one wave's share, or one dab).
  void PaintDabs(const std::vector<vtkOFBDab>& dabs,
    const int* order,
    vtkIdType count,
    const vtkOFBPaintSettings& settings,
    DabWork& work);
  /// False if the dab paints nothing (a smear with nothing to carry).
  bool ResolveColorDab(const vtkOFBDab& dab,
    const vtkOFBPaintSettings& settings,
    ColorDab& out) const;
  template<int Mode>
  void PaintColorsWith(const std::vector<vtkOFBDab>& dabs,
    const int* order,
    vtkIdType count,
    const vtkOFBPaintSettings& settings,
    DabWork& work);
  template<int Mode, int FalloffKind>
  void PaintColors(const std::vector<vtkOFBDab>& dabs,
    const int* order,
    vtkIdType count,
    const vtkOFBPaintSettings& settings,
    DabWork& work);
  void PaintNormals(const vtkOFBDab& dab,
    const vtkOFBPaintSettings& settings,
    const float* centreNormal,
    DabWork& work);
  bool SmearSource(const vtkOFBDab& dab, const vtkOFBPaintSettings& settings, float src[4]) const;
  bool CentreNormal(const vtkOFBDab& dab, double n[3]) const;
  const unsigned char* InitialColorBlock(vtkIdType block);
  const float* InitialNormalBlock(vtkIdType block);
  const unsigned char* InitialColor(vtkIdType id, DabWork& work);
  const float* InitialNormal(vtkIdType id, DabWork& work);
  void MarkChangedInWork(vtkIdType id, DabWork& work);
  void FlushChanged(DabWork& work);
  void ReportProgress(DabWork& work) const;
  vtkIdType CollectChangedWords(vtkIdType firstWord,
    vtkIdType lastWord,
    std::vector<std::pair<vtkIdType, vtkIdType>>& ranges);

  vtkOFB* OFB = nullptr;
  vtkUnsignedCharArray* Colors = nullptr;
  vtkFloatArray* Normals = nullptr;
  vtkIdType NumberOfSamples = 0;
  std::unique_ptr<unsigned char[]> Flags;                     // one thread per sample within a wave
  std::unique_ptr<std::atomic<vtkTypeUInt64>[]> ChangedWords; // bit i & 63 of word i >> 6
  vtkIdType NumberOfChangedWords = 0;
  // Chunks of 4096 words (262,144 samples); bit c & 63 of ChangedChunks is set when a
  // word of chunk c may be set (so that a call that changes a few samples reads a few
  // chunks, not the whole bitmap).
  static constexpr int ChangedChunkShift = 12;
  static vtkTypeUInt64 ChunkBit(vtkIdType word)
  {
    return vtkTypeUInt64(1) << ((word >> ChangedChunkShift) & 63);
  }
  std::atomic<vtkTypeUInt64> ChangedChunks{ 0 };
  vtkIdType NumberOfChangedChunks = 0;
  vtkIdType NumberOfInitialBlocks = 0;
  std::unique_ptr<std::atomic<unsigned char>[]> InitialColorState; // 0 none, 1 copying, 2 done
  std::unique_ptr<std::atomic<unsigned char>[]> InitialNormalState;
  std::vector<std::unique_ptr<unsigned char[]>> InitialColors;
  std::vector<std::unique_ptr<float[]>> InitialNormals;
  std::atomic<vtkIdType> InitialBlocksHeld{ 0 };
  std::unique_ptr<Scratch> Work; // buffers reused from call to call
};

#endif
