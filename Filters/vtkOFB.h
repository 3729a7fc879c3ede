/**
 * @class   vtkOFB
 * @brief   Orthogonal Fragment Buffer: surface samples on three axis-aligned grids
 *
 * vtkOFB stores a surface as samples taken along the rays through the cell centres
 * of three axis-aligned grids (paper "Sample-based Surface Coloring", section 4).
 *
 * The frame is an axis-aligned box with origin `GetOrigin()` and cubic cells of
 * edge `GetCellSize()` (world units); `GetDimensions()` gives the number of cells
 * of the box along x, y and z. Grid `a` (0 = X, 1 = Y, 2 = Z) is the plane spanned
 * by axes `u = (a+1)%3` and `v = (a+2)%3`; it has `dims[u] x dims[v]` cells,
 * row-major with u fastest. A sample of grid `a` lies on the ray through the
 * centre of its cell, at `depth` (world units) from the plane `x[a] = origin[a]`.
 *
 * Storage is compressed: one prefix-sum array `CellOffsets` over the cells of the
 * three grids (X first, then Y, then Z; one entry per cell plus one), a depth per
 * sample, and the global cell index of each sample (so an index gives a position
 * in O(1)). Within a cell, samples are sorted by increasing depth. Sample
 * attributes live in `GetSampleData()`, a vtkPointData with one tuple per sample:
 * the paint colours (RGBA unsigned char, the active scalars), normals (the active
 * normals), the tangent vector field (the active vectors) and every interpolated
 * point array of the source surface.
 *
 * All queries are const and thread-safe. They return -1 (or nothing) where no
 * sample qualifies, including on an empty OFB.
 *
 * @sa vtkOFBSampler vtkOFBBuilder vtkOFBWriter vtkOFBReader vtkOFBToPolyData
 */

#ifndef vtkOFB_h
#define vtkOFB_h

#include "vtkDataObject.h"
#include "vtkOFBFiltersModule.h" // for export macro
#include "vtkSmartPointer.h"     // for members
#include "vtkTypeUInt32Array.h"  // for inline access
#include "vtkWrappingHints.h"     // for VTK_SIZEHINT
#include "vtkFloatArray.h"       // for inline access
#include "vtkPointData.h"        // for inline access

#include "vtkTimeStamp.h"        // for StructureTime
#include "vtkWeakPointer.h"      // for the recycled structure

#include <algorithm> // for std::lower_bound
#include <vector>    // for ModifiedRanges
#include <cmath>     // for std::floor

/// A hint to fetch the cache line at `p` ahead of use (`VTKOFB_PREFETCH_WRITE`: to be
/// written); nothing where the compiler has no such builtin.
#if defined(__GNUC__) || defined(__clang__)
#define VTKOFB_PREFETCH(p) __builtin_prefetch(p)
#define VTKOFB_PREFETCH_WRITE(p) __builtin_prefetch((p), 1)
#else
#define VTKOFB_PREFETCH(p) ((void)(p))
#define VTKOFB_PREFETCH_WRITE(p) ((void)(p))
#endif

class vtkIdList;
class vtkIdTypeArray;
class vtkInformation;
class vtkInformationVector;

class VTKOFBFILTERS_EXPORT vtkOFB : public vtkDataObject
{
public:
  static vtkOFB* New();
  vtkTypeMacro(vtkOFB, vtkDataObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Remove every sample and reset the frame to an empty one.
   */
  void Initialize() override;

  /**
   * Set the frame and allocate the cell offsets of the three grids (all zero).
   * `origin` is the low corner of the box, `cellSize` (> 0) the edge of a cell in
   * world units and `dims` the number of cells along x, y and z (each >= 1).
   * Returns false, leaving the OFB empty, on invalid values or a failed allocation.
   * Builders call this, then `AllocateSamples`, then fill the arrays. A builder
   * that writes every offset itself may pass `zeroOffsets` false to leave them
   * uninitialized.
   */
  bool SetFrame(
    const double origin[3], double cellSize, const vtkIdType dims[3], bool zeroOffsets = true);

  ///@{
  /**
   * Rebuilding in place. `Recycle()` empties the OFB as `Initialize()` does but
   * keeps the arrays that nothing else references (cell offsets, depths, cell
   * indices, sample arrays) as spares: the next `SetFrame` and `AllocateSamples`
   * reuse their memory when it is large enough, and a builder takes sample arrays
   * with `TakeSpareArray`. A rebuild then writes over memory the process already
   * has instead of having the system clear fresh pages. `ReleaseSpareArrays()`
   * (and `Initialize()`, `ShallowCopy()`, `DeepCopy()`) frees the spares left;
   * vtkOFBAlgorithm calls it after each RequestData.
   */
  void Recycle();
  void ReleaseSpareArrays();
  ///@}

  /**
   * Called by the pipeline before an algorithm produces new data in this OFB:
   * Recycle() (as vtkImageData, which keeps its memory for reuse). vtkOFBAlgorithm
   * releases the spares its RequestData did not take.
   */
  void PrepareForNewData() override;

  /// The number of spare arrays (see Recycle()).
  vtkIdType GetNumberOfSpareArrays() const { return static_cast<vtkIdType>(this->Spares.size()); }

#ifndef __VTK_WRAP__
  /**
   * A spare array (see Recycle()) named `name`, of type `dataType`, with
   * `numberOfComponents` components and room for `numberOfTuples` tuples, resized
   * to them (its values are stale); null when there is none.
   */
  vtkSmartPointer<vtkDataArray> TakeSpareArray(
    const char* name, int dataType, int numberOfComponents, vtkIdType numberOfTuples);
#endif

  /**
   * Allocate `n` samples (depths and cell indices) once the cell offsets are final.
   * Clears the sample data. Returns false on a failed allocation.
   */
  bool AllocateSamples(vtkIdType n);

  /**
   * Recompute the cell index of every sample from the cell offsets. Call this
   * after filling `GetCellOffsets()` and `AllocateSamples()`. Returns false if the
   * offsets are not a valid prefix sum ending at the number of samples.
   */
  bool BuildCellIndex();

  ///@{
  /**
   * The frame: low corner of the box (world units), cell edge (world units) and
   * number of cells along x, y and z. An empty OFB has cell size 0.
   */
  const double* GetOrigin() const VTK_SIZEHINT(3) { return this->Origin; }
  void GetOrigin(double o[3]) const;
  double GetCellSize() const { return this->CellSize; }
  const vtkIdType* GetDimensions() const VTK_SIZEHINT(3) { return this->Dimensions; }
  void GetDimensions(vtkIdType d[3]) const;
  void GetBounds(double bounds[6]) const;
  ///@}

  /**
   * Number of cells of grid `axis` along its u and v axes.
   */
  void GetGridDimensions(int axis, vtkIdType& nu, vtkIdType& nv) const;

  ///@{
  /**
   * Cell counts: per grid, and over the three grids.
   */
  vtkIdType GetNumberOfGridCells(int axis) const;
  vtkIdType GetNumberOfCells() const { return this->CellBase[3]; }
  ///@}

  /**
   * Global index of the first cell of grid `axis` (0..3; 3 gives the total).
   */
  vtkIdType GetGridCellBase(int axis) const { return this->CellBase[axis]; }

  ///@{
  /**
   * Sample counts: over the three grids, per grid, and the first sample of a grid.
   */
  vtkIdType GetNumberOfSamples() const;
  vtkIdType GetNumberOfSamples(int axis) const;
  vtkIdType GetGridFirstSample(int axis) const;
  ///@}

  ///@{
  /**
   * Depth complexity: the most samples in one cell of grid `axis`, or of any grid.
   */
  vtkIdType GetDepthComplexity(int axis) const;
  vtkIdType GetDepthComplexity() const;
  ///@}

  ///@{
  /**
   * The storage arrays. CellOffsets has GetNumberOfCells()+1 entries; Depths and
   * CellIndex have one entry per sample. Builders and readers fill them.
   */
  vtkTypeUInt32Array* GetCellOffsets() { return this->CellOffsets; }
  vtkFloatArray* GetDepths() { return this->Depths; }
  vtkTypeUInt32Array* GetCellIndex() { return this->CellIndex; }
  ///@}

  /**
   * Sample attributes, one tuple per sample.
   */
  vtkPointData* GetSampleData() { return this->SampleData; }

  /**
   * Grid (0, 1, 2) of a sample, or -1 for an invalid id.
   */
  int GetSampleAxis(vtkIdType id) const;

  ///@{
  /**
   * Position of sample `id` in world coordinates. Returns false (x unchanged) for
   * an invalid id.
   */
  bool GetSamplePosition(vtkIdType id, double x[3]) const;
  ///@}

  /**
   * Closest sample to `x` in the grid whose axis is most aligned with the normal
   * `n`, looking only in the cell under `x` and at depths in [d - s, d + s]
   * (binary search). Returns -1 if there is none (paper, section 4.1).
   */
  vtkIdType FindSample(const double x[3], const double n[3]) const;

  ///@{
  /**
   * Closest sample to `x` over the three grids within `radius` (world units).
   * The one-argument form uses sqrt(3) cells, the paper's bound on the distance
   * from a surface point to its nearest sample; `radius` may be infinite. Returns
   * -1 if there is none.
   */
  vtkIdType FindClosestSample(const double x[3]) const;
  vtkIdType FindClosestSample(const double x[3], double radius) const;
  ///@}

  /**
   * Fill `ids` with every sample within `radius` (world units) of `center`. Any
   * radius >= 0 works, up to infinity (every sample); a NaN radius finds nothing.
   */
  void FindSamplesInSphere(const double center[3], double radius, vtkIdList* ids) const;

#ifndef __VTK_WRAP__
  /**
   * Call `f(vtkIdType id, double squaredDistance)` for every sample within `radius`
   * of `center`, grid by grid (axis 0, 1, 2), row by row, cell by cell in order of
   * depth. Candidates are the cells under the sphere's projection on each grid and
   * the depth range [d - r, d + r] of each; no allocation.
   */
  template <typename Functor>
  void ForEachSampleInSphere(const double center[3], double radius, Functor&& f) const;

  /**
   * As above; `prefetch(vtkIdType first, vtkIdType last)` is called a row ahead with
   * the range of sample ids that `f` will soon be offered, so that the caller can
   * prefetch its own arrays indexed by sample id (the query prefetches its own).
   */
  template <typename Functor, typename Prefetch>
  void ForEachSampleInSphere(
    const double center[3], double radius, Functor&& f, Prefetch&& prefetch) const;
#endif

  ///@{
  /**
   * Change tracking, so that a renderer uploads only what changed.
   * `MarkSamplesModified(first, last)` records that the attributes of samples
   * [first, last) changed (painting, particles, LIC). It does not call Modified():
   * whoever changes samples calls Modified() once per stroke or step.
   * `GetSampleRangesModifiedSince(t, ranges)` fills `ranges` (2 components:
   * first, last) with the sorted, merged ranges marked after time `t` (a
   * vtkTimeStamp value such as the time of a consumer's last upload); when the
   * samples were reallocated after `t` (GetStructureMTime() > t) it gives the
   * whole range. Beyond 256 entries, the marks older than the newest 192 are
   * merged into at most 32 ranges across their smallest gaps (conservatively: a
   * merged range may include unchanged samples), so a consumer that reads after
   * every change still gets the newest marks exactly.
   * Not thread-safe: mark from one thread.
   */
  void MarkSamplesModified(vtkIdType first, vtkIdType last);
  void MarkAllSamplesModified();
  void GetSampleRangesModifiedSince(vtkMTimeType t, vtkIdTypeArray* ranges) const;
  vtkMTimeType GetStructureMTime() const { return this->StructureTime.GetMTime(); }
  ///@}

  ///@{
  /**
   * Memory of the sample storage and attributes, in KiB (vtkDataObject convention),
   * and in bytes per sample.
   */
  unsigned long GetActualMemorySize() override;
  double GetBytesPerSample();
  ///@}

  ///@{
  /**
   * Copy another OFB: shallow copies share the arrays, deep copies duplicate them.
   */
  void ShallowCopy(vtkDataObject* src) override;
  void DeepCopy(vtkDataObject* src) override;
  ///@}

  /**
   * Not a vtkDataSet: report VTK_DATA_OBJECT.
   */
  int GetDataObjectType() override { return VTK_DATA_OBJECT; }

  ///@{
  /**
   * Retrieve an instance from an information object or vector.
   */
  static vtkOFB* GetData(vtkInformation* info);
  static vtkOFB* GetData(vtkInformationVector* v, int i = 0);
  ///@}

protected:
  vtkOFB();
  ~vtkOFB() override;

  /// Initialize() but for the spares (see Recycle()).
  void Reset();

  /**
   * Set `cell` to the global index of the cell of grid `axis` under point x (the
   * cell whose square contains x projected on the grid); false, `cell` unchanged,
   * if x projects outside the grid.
   */
  bool LocateCell(int axis, const double x[3], vtkIdType& cell) const;

  /**
   * Shallow or deep copy of another OFB (error if `src` is not one).
   */
  void CopyFrom(vtkDataObject* src, bool deep);

  /**
   * Index of the first sample of [begin, end) whose depth is >= d.
   */
  vtkIdType LowerBound(vtkIdType begin, vtkIdType end, float d) const
  {
    const float* depths = this->Depths->GetPointer(0);
    return static_cast<vtkIdType>(std::lower_bound(depths + begin, depths + end, d) - depths);
  }

#ifndef __VTK_WRAP__
  /// One row of cells [u0, u1] of ForEachSampleInSphere's grid `a` (see there).
  struct SphereRow
  {
    vtkIdType RowBase; // global id of cell u = 0 of the row
    vtkIdType U0, U1;
    double UCentre; // the centre's u, world units relative to cell 0's centre
    double D;       // the centre's depth relative to the origin
    double DV2;     // squared distance of the row from the centre in v
    double DHigh;
    double R2;
    float DLow;
    int UAxis;
  };
  template <typename Functor>
  void ForEachSampleInRowScan(const SphereRow& row, Functor& f) const;
  template <typename Functor>
  void ForEachSampleInRowCells(const SphereRow& row, Functor& f) const;
#endif

  double Origin[3];
  double CellSize;
  vtkIdType Dimensions[3];
  vtkIdType CellBase[4];

  vtkSmartPointer<vtkTypeUInt32Array> CellOffsets;
  vtkSmartPointer<vtkFloatArray> Depths;
  vtkSmartPointer<vtkTypeUInt32Array> CellIndex;
  vtkSmartPointer<vtkPointData> SampleData;
  std::vector<vtkSmartPointer<vtkDataArray>> Spares; // see Recycle()

  struct ModifiedRange
  {
    vtkIdType First;
    vtkIdType Last;
    vtkMTimeType Time;
  };
  std::vector<ModifiedRange> ModifiedRanges;
  vtkTimeStamp StructureTime;

  // The structure that Recycle() let go: a shallow copy of the same arrays in the same
  // frame (a filter re-executing over an unchanged input) keeps its StructureTime, so
  // that consumers (the mapper's uploads) see only the arrays that changed.
  struct RecycledStructure
  {
    vtkWeakPointer<vtkTypeUInt32Array> CellOffsets;
    vtkWeakPointer<vtkFloatArray> Depths;
    vtkWeakPointer<vtkTypeUInt32Array> CellIndex;
    double Origin[3];
    vtkIdType Dimensions[3];
    double CellSize;
    vtkTimeStamp Time;
  };
  RecycledStructure Recycled;

private:
  vtkOFB(const vtkOFB&) = delete;
  void operator=(const vtkOFB&) = delete;
};

#ifndef __VTK_WRAP__
template <typename Functor>
void vtkOFB::ForEachSampleInSphere(const double center[3], double radius, Functor&& f) const
{
  this->ForEachSampleInSphere(center, radius, f, [](vtkIdType, vtkIdType) {});
}

template <typename Functor, typename Prefetch>
void vtkOFB::ForEachSampleInSphere(
  const double center[3], double radius, Functor&& f, Prefetch&& prefetch) const
{
  if (this->CellSize <= 0.0 || !(radius >= 0.0) || this->GetNumberOfSamples() == 0)
  {
    return;
  }
  const vtkTypeUInt32* offsets = this->CellOffsets->GetPointer(0);
  const vtkTypeUInt32* cellOf = this->CellIndex->GetPointer(0);
  const float* depths = this->Depths->GetPointer(0);
  const bool indexed = this->CellIndex->GetNumberOfValues() == this->GetNumberOfSamples();
  const double s = this->CellSize;
  const double r2 = radius * radius;
  for (int a = 0; a < 3; ++a)
  {
    const int ua = (a + 1) % 3;
    const int va = (a + 2) % 3;
    const vtkIdType nu = this->Dimensions[ua];
    const vtkIdType nv = this->Dimensions[va];
    // Cells whose centre lies within the projected box [c - r, c + r], clamped to the
    // grid before they become integers (a huge or infinite radius covers the grid).
    const double lu = (center[ua] - radius - this->Origin[ua]) / s - 0.5;
    const double hu = (center[ua] + radius - this->Origin[ua]) / s - 0.5;
    const double lv = (center[va] - radius - this->Origin[va]) / s - 0.5;
    const double hv = (center[va] + radius - this->Origin[va]) / s - 0.5;
    if (!(hu >= 0.0 && hv >= 0.0 && lu <= nu - 1 && lv <= nv - 1))
    {
      continue;
    }
    const vtkIdType u0 = static_cast<vtkIdType>(std::ceil(std::max(lu, 0.0)));
    const vtkIdType u1 = static_cast<vtkIdType>(std::floor(std::min(hu, nu - 1.0)));
    const vtkIdType v0 = static_cast<vtkIdType>(std::ceil(std::max(lv, 0.0)));
    const vtkIdType v1 = static_cast<vtkIdType>(std::floor(std::min(hv, nv - 1.0)));
    SphereRow base;
    base.D = center[a] - this->Origin[a];
    base.R2 = r2;
    base.DLow = static_cast<float>(base.D - radius);
    base.DHigh = base.D + radius;
    base.UCentre = center[ua];
    base.UAxis = ua;
    const double cu = (center[ua] - this->Origin[ua]) / s - 0.5; // centre in cell units
    // Row iv: only the cells under the circle's chord, one cell wider on each side
    // than exact arithmetic needs (the distance test decides), clamped before they
    // become integers as above. False if the row misses the sphere.
    auto chord = [&](vtkIdType iv, SphereRow& row)
    {
      row = base;
      const double dv = this->Origin[va] + (iv + 0.5) * s - center[va];
      row.DV2 = dv * dv;
      if (row.DV2 > r2)
      {
        return false;
      }
      row.RowBase = this->CellBase[a] + iv * nu;
      const double half = std::sqrt(r2 - row.DV2) / s;
      row.U0 = static_cast<vtkIdType>(std::max(static_cast<double>(u0), std::floor(cu - half)));
      row.U1 = static_cast<vtkIdType>(std::min(static_cast<double>(u1), std::ceil(cu + half)));
      return row.U0 <= row.U1;
    };
    // Rows are computed two ahead (their offsets prefetched) and their samples are
    // prefetched one ahead: a dab's rows lie far apart in memory.
    SphereRow ring[3];
    bool valid[3] = { false, false, false };
    for (vtkIdType iv = v0; iv <= std::min(v1, v0 + 1); ++iv)
    {
      valid[iv % 3] = chord(iv, ring[iv % 3]);
    }
    for (vtkIdType iv = v0; iv <= v1; ++iv)
    {
      if (iv + 2 <= v1)
      {
        SphereRow& ahead = ring[(iv + 2) % 3];
        valid[(iv + 2) % 3] = chord(iv + 2, ahead);
        if (valid[(iv + 2) % 3])
        {
          VTKOFB_PREFETCH(offsets + ahead.RowBase + ahead.U0);
          VTKOFB_PREFETCH(offsets + ahead.RowBase + ahead.U1 + 1);
        }
      }
      if (iv + 1 <= v1 && valid[(iv + 1) % 3])
      {
        const SphereRow& next = ring[(iv + 1) % 3];
        const vtkIdType first = offsets[next.RowBase + next.U0];
        const vtkIdType last =
          std::min<vtkIdType>(offsets[next.RowBase + next.U1 + 1], first + 512);
        for (vtkIdType i = first; i < last; i += 16)
        {
          VTKOFB_PREFETCH(depths + i);
          VTKOFB_PREFETCH(cellOf + i);
        }
        if (first < last)
        {
          VTKOFB_PREFETCH(depths + last - 1);
          VTKOFB_PREFETCH(cellOf + last - 1);
          prefetch(first, last);
        }
      }
      if (!valid[iv % 3])
      {
        continue;
      }
      const SphereRow& row = ring[iv % 3];
      // A row's samples are consecutive: where its cells hold few samples each, one
      // linear pass over them all beats a search of each cell's depth range.
      const vtkIdType cells = row.U1 - row.U0 + 1;
      const vtkIdType samples = offsets[row.RowBase + row.U1 + 1] - offsets[row.RowBase + row.U0];
      if (indexed && samples <= 6 * cells)
      {
        this->ForEachSampleInRowScan(row, f);
      }
      else
      {
        this->ForEachSampleInRowCells(row, f);
      }
    }
  }
}

template <typename Functor>
void vtkOFB::ForEachSampleInRowScan(const SphereRow& row, Functor& f) const
{
  // Every sample of the row's cells, tested without a branch into a small batch of
  // hits, then handed to `f` in order. The squared distance is computed as in
  // ForEachSampleInRowCells, to the bit.
  const vtkTypeUInt32* offsets = this->CellOffsets->GetPointer(0);
  const vtkTypeUInt32* cellOf = this->CellIndex->GetPointer(0);
  const float* depths = this->Depths->GetPointer(0);
  const double s = this->CellSize;
  const double ou = this->Origin[row.UAxis];
  constexpr int Batch = 64;
  vtkIdType hit[Batch];
  double hitD2[Batch];
  vtkIdType i = offsets[row.RowBase + row.U0];
  const vtkIdType end = offsets[row.RowBase + row.U1 + 1];
  while (i < end)
  {
    const vtkIdType stop = std::min(end, i + Batch);
    int n = 0;
    for (; i < stop; ++i)
    {
      const double iu = static_cast<double>(static_cast<vtkIdType>(cellOf[i]) - row.RowBase);
      const double du = ou + (iu + 0.5) * s - row.UCentre;
      const double duv2 = du * du + row.DV2;
      const double dd = depths[i] - row.D;
      const double dist2 = duv2 + dd * dd;
      hit[n] = i;
      hitD2[n] = dist2;
      n += dist2 <= row.R2;
    }
    for (int k = 0; k < n; ++k)
    {
      f(hit[k], hitD2[k]);
    }
  }
}

template <typename Functor>
void vtkOFB::ForEachSampleInRowCells(const SphereRow& row, Functor& f) const
{
  // Cell by cell: a cell's first sample at depth >= d - r by a linear scan over the
  // few samples of a typical cell, a binary search over many.
  const vtkTypeUInt32* offsets = this->CellOffsets->GetPointer(0);
  const float* depths = this->Depths->GetPointer(0);
  const double s = this->CellSize;
  const double ou = this->Origin[row.UAxis];
  for (vtkIdType iu = row.U0; iu <= row.U1; ++iu)
  {
    const double du = ou + (iu + 0.5) * s - row.UCentre;
    const double duv2 = du * du + row.DV2;
    if (duv2 > row.R2)
    {
      continue;
    }
    const vtkIdType cell = row.RowBase + iu;
    vtkIdType i = offsets[cell];
    const vtkIdType end = offsets[cell + 1];
    if (end - i > 8)
    {
      i = this->LowerBound(i, end, row.DLow);
    }
    else
    {
      while (i < end && depths[i] < row.DLow)
      {
        ++i;
      }
    }
    for (; i < end; ++i)
    {
      if (depths[i] > row.DHigh)
      {
        break;
      }
      const double dd = depths[i] - row.D;
      const double dist2 = duv2 + dd * dd;
      if (dist2 <= row.R2)
      {
        f(i, dist2);
      }
    }
  }
}
#endif

#endif
