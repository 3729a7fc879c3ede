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

#include "vtkTimeStamp.h" // for StructureTime

#include <memory> // for std::unique_ptr

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
  vtkIdType GetNumberOfSpareArrays() const;

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
   * the depth range [d - r, d + r] of each; no allocation (vtkOFBSphereQuery.h).
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
   * Exclusive writers. A writer that holds raw pointers into the OFB's arrays for the
   * length of a call (vtkOFBPainter during a paint call, whose progress observers run
   * application code) takes the OFB with `BeginExclusiveWrite(owner)` and gives it back
   * with `EndExclusiveWrite(owner)`. While it is held, a second writer's
   * BeginExclusiveWrite returns false, and `Initialize()`, `Recycle()`, `SetFrame()`,
   * `AllocateSamples()`, `ShallowCopy()` and `DeepCopy()` refuse with an error and
   * change nothing (they would free the arrays under the writer). Thread-safe.
   */
#ifndef __VTK_WRAP__
  bool BeginExclusiveWrite(const void* owner);
  void EndExclusiveWrite(const void* owner);
#endif
  bool IsBeingWritten() const;
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
   * The samples as the data object's points: GetAttributesAsFieldData(POINT) is
   * GetSampleData() and GetNumberOfElements(POINT) the number of samples, so that code
   * that lists a data object's point arrays (ParaView's information panel and array
   * menus, vtkAlgorithm::GetInputArrayToProcess on an OFB input) sees the sample arrays.
   * Other types are vtkDataObject's.
   */
  vtkFieldData* GetAttributesAsFieldData(int type) override;
  vtkIdType GetNumberOfElements(int type) override;
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

  double Origin[3];
  double CellSize;
  vtkIdType Dimensions[3];
  vtkIdType CellBase[4];

  vtkSmartPointer<vtkTypeUInt32Array> CellOffsets;
  vtkSmartPointer<vtkFloatArray> Depths;
  vtkSmartPointer<vtkTypeUInt32Array> CellIndex;
  vtkSmartPointer<vtkPointData> SampleData;
  vtkTimeStamp StructureTime;

private:
  vtkOFB(const vtkOFB&) = delete;
  void operator=(const vtkOFB&) = delete;

  // The sphere queries read the frame and the arrays directly.
  friend class vtkOFBSphereQuery;

  /// Initialize() but for the spares (see Recycle()).
  void Reset();
  /// False, with an error naming `what`, while an exclusive writer holds the OFB.
  bool CheckNotBeingWritten(const char* what);

  // The spare arrays and the structure that Recycle() let go, and the modified ranges.
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#ifndef __VTK_WRAP__
#include "vtkOFBSphereQuery.h" // IWYU pragma: export
#endif

#endif
