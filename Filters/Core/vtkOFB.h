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
#include "vtkFloatArray.h"      // for inline access
#include "vtkOFBCoreModule.h"   // for export macro
#include "vtkPointData.h"       // for inline access
#include "vtkSmartPointer.h"    // for members
#include "vtkTypeUInt32Array.h" // for inline access
#include "vtkWrappingHints.h"   // for VTK_SIZEHINT

#include "vtkTimeStamp.h"   // for StructureTime
#include "vtkWeakPointer.h" // for the recycled structure

#include <algorithm> // for std::lower_bound
#include <cmath>     // for std::floor
#include <vector>    // for ModifiedRanges

/// A hint to fetch the cache line at `p` ahead of use (`VTKOFB_PREFETCH_WRITE`: to be
/// written); nothing where the compiler has no such builtin. On x86 the hint is a
/// volatile instruction: GCC takes __builtin_prefetch for free of side effects, so a
/// caller's prefetch functor that it does not inline is deleted as a call that does
/// nothing, with its prefetches.
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#define VTKOFB_PREFETCH(p)                                                                         \
  __asm__ __volatile__("prefetcht0 %0" : : "m"(*reinterpret_cast<const char*>(p)))
#if defined(__PRFCHW__)
#define VTKOFB_PREFETCH_WRITE(p)                                                                   \
  __asm__ __volatile__("prefetchw %0" : : "m"(*reinterpret_cast<const char*>(p)))
#else
#define VTKOFB_PREFETCH_WRITE(p) VTKOFB_PREFETCH(p)
#endif
#elif defined(__GNUC__) || defined(__clang__)
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

class VTKOFBCORE_EXPORT vtkOFB : public vtkDataObject
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
  bool SetFrame(const double origin[3],
    double cellSize,
    const vtkIdType dims[3],
    bool zeroOffsets = true);

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
  vtkSmartPointer<vtkDataArray> TakeSpareArray(const char* name,
    int dataType,
    int numberOfComponents,
    vtkIdType numberOfTuples);
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
  const double* GetOrigin() const VTK_SIZEHINT(3)
  {
    return this->Origin;
  }
  void GetOrigin(double o[3]) const;
  double GetCellSize() const
  {
    return this->CellSize;
  }
  const vtkIdType* GetDimensions() const VTK_SIZEHINT(3)
  {
    return this->Dimensions;
  }
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
  vtkIdType GetNumberOfCells() const
  {
    return this->CellBase[3];
  }
  ///@}

  /**
   * Global index of the first cell of grid `axis` (0..3; 3 gives the total; 0 for an
   * axis out of that range).
   */
  vtkIdType GetGridCellBase(int axis) const
  {
    return axis >= 0 && axis <= 3 ? this->CellBase[axis] : 0;
  }

  ///@{
  /**
   * Sample counts: over the three grids, per grid, and the first sample of a grid
   * (0 for an axis out of 0..2, 0..3 for the first sample).
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
  vtkTypeUInt32Array* GetCellOffsets()
  {
    return this->CellOffsets;
  }
  vtkFloatArray* GetDepths()
  {
    return this->Depths;
  }
  vtkTypeUInt32Array* GetCellIndex()
  {
    return this->CellIndex;
  }
  ///@}

  /**
   * Sample attributes, one tuple per sample.
   */
  vtkPointData* GetSampleData()
  {
    return this->SampleData;
  }

  ///@{
  /**
   * Names of the sample arrays that the filters share: "Colors", the paint (RGBA
   * unsigned char), and "Normals", the sample normals (3 floats). The sampler writes
   * them, the painter and the filters read and write them, the mapper draws them.
   */
  static const char* ColorsArrayName()
  {
    return "Colors";
  }
  static const char* NormalsArrayName()
  {
    return "Normals";
  }
  ///@}

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
  template<typename Functor>
  void ForEachSampleInSphere(const double center[3], double radius, Functor&& f) const;

  /**
   * As above; `prefetch(vtkIdType first, vtkIdType last)` is called a row ahead with
   * the range of sample ids that `f` will soon be offered, so that the caller can
   * prefetch its own arrays indexed by sample id (the query prefetches its own).
   */
  template<typename Functor, typename Prefetch>
  void ForEachSampleInSphere(const double center[3],
    double radius,
    Functor&& f,
    Prefetch&& prefetch) const;

  /**
   * Many sphere queries in one call, with the result of calling
   * ForEachSampleInSphere on each in turn: `sphere(vtkIdType k, double center[3],
   * double& radius)` sets sphere k of [0, n), and `f(vtkIdType k, vtkIdType id,
   * double squaredDistance)` is called for its samples, spheres in increasing k, each
   * sphere's samples in ForEachSampleInSphere's order; `sphere(k)` may be called before
   * `f` is done with sphere k - 2, never earlier. The spheres are software-pipelined:
   * while sphere k is visited, sphere k + 1's samples and sphere k + 2's cell offsets
   * are on their way from memory, which is what many small spheres (particle
   * footprints, small brushes) wait for one by one. `prefetch` as above.
   */
  template<typename Sphere, typename Functor, typename Prefetch>
  void ForEachSampleInSpheres(vtkIdType n, Sphere&& sphere, Functor&& f, Prefetch&& prefetch) const;
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
  vtkMTimeType GetStructureMTime() const
  {
    return this->StructureTime.GetMTime();
  }
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
  int GetDataObjectType() override
  {
    return VTK_DATA_OBJECT;
  }

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
  /// One row of cells [u0, u1] of a sphere query on grid `a` (vtkOFBSphereQuery.txx).
  struct SphereRow
  {
    vtkIdType RowBase; // global id of cell u = 0 of the row
    vtkIdType U0, U1;
    vtkIdType First, Last; // the samples of cells [U0, U1] (set by FetchSphereRow)
    double UCentre;        // the centre's u, world units relative to cell 0's centre
    double D;              // the centre's depth relative to the origin
    double DV2;            // squared distance of the row from the centre in v
    double DHigh;
    double R2;
    float DLow;
    int UAxis;
    // The OFB's arrays, taken once per sphere and grid (not per row).
    const vtkTypeUInt32* Offsets;
    const float* Depths;
    const vtkTypeUInt32* CellOf; // null without a cell index
  };
  /// The cells of grid `a` under a sphere's bounding box, and what its rows share.
  struct SphereGrid
  {
    vtkIdType U0, U1, V0, V1, NU;
    double CU; // the centre's u in cell units
    double InverseCellSize;
    double CV; // the centre's v, world units
    int VAxis;
    SphereRow Base;
  };
  /// False if the sphere's box misses grid `a`.
  bool BeginSphereGrid(int a, const double center[3], double radius, SphereGrid& grid) const;
  /// Row `iv` of the grid, only the cells under the circle's chord (its cell offsets
  /// prefetched); false if it misses.
  bool SphereChord(const SphereGrid& grid, vtkIdType iv, SphereRow& row) const;
  /// Read the row's sample range, prefetch its depths and cell indices, and hand its
  /// first samples (up to 512) to the caller's `prefetch(first, last)`.
  template<typename Prefetch>
  void FetchSphereRow(SphereRow& row, Prefetch& prefetch) const;
  template<typename Functor>
  void ForEachSampleInRow(const SphereRow& row, bool indexed, Functor& f) const;
  template<typename Functor>
  void ForEachSampleInRowScan(const SphereRow& row, Functor& f) const;
  template<typename Functor>
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
#include "vtkOFBSphereQuery.txx" // IWYU pragma: export
#endif

#endif
