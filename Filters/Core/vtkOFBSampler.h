/**
 * @class   vtkOFBSampler
 * @brief   Build a vtkOFB from a surface on the CPU (vtkSMPTools)
 *
 * Input: any vtkDataSet or vtkCompositeDataSet. A vtkPolyData is sampled as it is
 * (no copy); any other dataset (vtkUnstructuredGrid, vtkImageData, ...) through its
 * outer surface as vtkDataSetSurfaceFilter extracts it, with its point and cell
 * arrays. A composite dataset (vtkMultiBlockDataSet, vtkPartitionedDataSetCollection,
 * ...) gives one OFB on one frame over all its blocks: the blocks are merged into one
 * surface by vtkOFBMergeBlocks (points shared by blocks merged, so that patch borders
 * are no seams), and the samples get the int array "BlockIndex", the flat index of
 * their block (as vtkDataObjectTreeIterator numbers blocks). An array that some blocks
 * lack is filled there with NaN (float and double arrays) or 0 (integer arrays); empty
 * blocks and blocks that are not datasets are left out (the latter with a warning).
 * For other merge settings, run vtkOFBMergeBlocks before the sampler.
 *
 * vtkOFBSampler scan-converts the triangles of a vtkPolyData into the three grids
 * of a vtkOFB (paper "Sample-based Surface Coloring", sections 4 and 8). Each
 * triangle goes to the grid of the axis closest to its face normal and is sampled
 * at the cell centres it covers, with a top-left fill rule (in raster, y-down
 * coordinates, as Mesa's OpenGL rasterizer) on a fixed-point lattice of 1/256
 * cell (the subpixel precision of GPU rasterizers), so that a shared edge gives
 * neither a hole nor a duplicate and the OpenGL backend of vtkOFBBuilder covers
 * the same cell centres. Depth is the triangle's plane at the cell centre and
 * attributes are interpolated from barycentric coordinates. Cells are sorted by
 * depth (ties by triangle id), so the result does not depend on the number of
 * threads.
 *
 * Sample arrays: "Colors" (RGBA unsigned char, the paint: the input's point
 * colours if it has unsigned-char RGB(A) scalars, else DefaultColor), "Normals"
 * (the input point normals, else area-weighted normals computed here), the vector
 * field chosen with SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
 * name) (or the input's active point vectors) projected into the tangent plane,
 * and, with PassPointArrays, every other point array, interpolated.
 *
 * With PassCellArrays, every cell array of the input becomes a sample array of
 * the same name too: a sample takes the value of the input cell its triangle
 * came from (the polygon or strip a triangle was cut from), not interpolated.
 * When a point array and a cell array have the same name, ArrayPrecedence says
 * which one the samples get. Cell arrays named "Colors", "Normals" or as the
 * vector field are left out. When the input has no point vector field (none
 * chosen with SetInputArrayToProcess, no active point vectors) and its cell data
 * has active 3-component vectors, these become the samples' active vectors
 * (projected into the tangent plane with ProjectVectors), so that vtkOFBLIC
 * finds them. Likewise, when the input has no active point scalars and its cell
 * data has active scalars other than colours (RGB or RGBA bytes), these become the
 * samples' active scalars (the paint,
 * "Colors", stays a sample array of that name); otherwise the samples' active
 * scalars are the paint. A NaN in a cell array is a NaN in the samples of that cell
 * (the colouring shows it in the lookup table's NaN colour).
 *
 * Polygons and strips are triangulated; lines and vertices are ignored with a
 * warning; zero-area triangles are skipped. Empty input, non-finite coordinates,
 * a surface without triangles, a resolution below 3 or above 65536, a surface of
 * 2^32 points or triangles or more, and a build whose memory would exceed
 * MemoryLimit give an error and an empty output.
 *
 * Rebuilding (an update after a change of input or setting) writes over the
 * memory of the previous output where nothing else holds its arrays (see
 * vtkOFB::Recycle) and over the CPU backend's build buffers (a few hundred bytes
 * per triangle of the last input), which it keeps between updates;
 * ReleaseBuffers() frees them.
 *
 * The scan conversion itself is done by a backend (vtkOFBSamplerBackend): the
 * CPU one here, the OpenGL one too in vtkOFBBuilder.
 *
 * @sa vtkOFB vtkOFBBuilder vtkOFBSamplerBackend
 */

#ifndef vtkOFBSampler_h
#define vtkOFBSampler_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBCoreModule.h"     // for export macro
#include "vtkOFBSamplerBackend.h" // for Job, Result
#include "vtkSmartPointer.h"      // for CPUBackend
#include "vtkWeakPointer.h"       // for LastBuildBackend

class vtkDataArray;
class vtkDataSet;
class vtkOFB;
class vtkOFBSampleSources;
class vtkPolyData;
class vtkOFBSurface;

class VTKOFBCORE_EXPORT vtkOFBSampler : public vtkOFBAlgorithm
{
public:
  static vtkOFBSampler* New();
  vtkTypeMacro(vtkOFBSampler, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of cells along the longest side of the frame (the input bounds padded
   * by one cell on every side). Valid range 3..65536; default 1024. The paper uses
   * 2048. Out-of-range values give an error at update time.
   */
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Most memory a build may take, in MiB (default 8192). The sampler estimates the
   * memory of the build (its copy of the surface, the backend's per-triangle
   * buffers, the grids, the samples and their arrays) before it allocates any of
   * it, and fails with an error when the estimate exceeds the limit: first from
   * the input's numbers of points and triangles, before the surface is copied,
   * then on the frame, and again as the backend counts its spans and samples.
   */
  vtkSetClampMacro(MemoryLimit, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MemoryLimit, vtkIdType);
  ///@}

  ///@{
  /**
   * Paint colour of the samples when the input has no point colours (or
   * UseInputColors is off), RGBA 0..255. Default opaque white.
   */
  vtkSetVector4Macro(DefaultColor, unsigned char);
  vtkGetVector4Macro(DefaultColor, unsigned char);
  ///@}

  ///@{
  /**
   * Take the initial paint from the input's unsigned-char RGB(A) point scalars
   * when present (default on).
   */
  vtkSetMacro(UseInputColors, bool);
  vtkGetMacro(UseInputColors, bool);
  vtkBooleanMacro(UseInputColors, bool);
  ///@}

  ///@{
  /**
   * Interpolate every other point array of the input into the samples (default on).
   */
  vtkSetMacro(PassPointArrays, bool);
  vtkGetMacro(PassPointArrays, bool);
  vtkBooleanMacro(PassPointArrays, bool);
  ///@}

  ///@{
  /**
   * Give the samples every cell array of the input, each sample the value of its
   * triangle's input cell (default on).
   */
  vtkSetMacro(PassCellArrays, bool);
  vtkGetMacro(PassCellArrays, bool);
  vtkBooleanMacro(PassCellArrays, bool);
  ///@}

  /// Which of a point array and a cell array of the same name the samples get.
  enum ArrayPrecedences
  {
    POINT_ARRAYS_FIRST = 0, ///< the point array, interpolated (the default)
    CELL_ARRAYS_FIRST = 1   ///< the cell array, per triangle's cell
  };

  ///@{
  /**
   * Whether a point array or a cell array of the input wins when both have the
   * same name (and PassPointArrays and PassCellArrays are on):
   * POINT_ARRAYS_FIRST (default) or CELL_ARRAYS_FIRST.
   */
  vtkSetClampMacro(ArrayPrecedence, int, POINT_ARRAYS_FIRST, CELL_ARRAYS_FIRST);
  vtkGetMacro(ArrayPrecedence, int);
  void SetArrayPrecedenceToPointArraysFirst() { this->SetArrayPrecedence(POINT_ARRAYS_FIRST); }
  void SetArrayPrecedenceToCellArraysFirst() { this->SetArrayPrecedence(CELL_ARRAYS_FIRST); }
  ///@}

  ///@{
  /**
   * Project the vector field into the tangent plane of each sample (default on).
   */
  vtkSetMacro(ProjectVectors, bool);
  vtkGetMacro(ProjectVectors, bool);
  vtkBooleanMacro(ProjectVectors, bool);
  ///@}

  /// When an update re-samples the attributes alone on the structure of the last build.
  enum StructureReuses
  {
    STRUCTURE_REUSE_OFF = 0,         ///< never: every update is a full build
    STRUCTURE_REUSE_TIME_SERIES = 1, ///< when the input reports time steps (the default)
    STRUCTURE_REUSE_ALWAYS = 2       ///< whenever the geometry is unchanged
  };

  ///@{
  /**
   * Re-sample the attributes alone when the geometry is unchanged since the last
   * build (see vtkOFBSampleSources): STRUCTURE_REUSE_TIME_SERIES (default: when
   * the input's pipeline information has TIME_STEPS), STRUCTURE_REUSE_ALWAYS, or
   * STRUCTURE_REUSE_OFF. The geometry is the input's points, polygons and strips
   * and point normals (their arrays and modification times, else a hash of their
   * content), the resolution and the backend. A re-sampling gives the output the
   * structure of the last build (shared: its GetStructureMTime does not change)
   * and the normals of its samples (shared too), and interpolates the colours,
   * the vector field and the other arrays from the triangle and barycentrics
   * that the build recorded for each sample: the same values as a full build. The
   * recording costs 12 bytes a sample, kept between updates while reuse is on.
   */
  vtkSetClampMacro(StructureReuse, int, STRUCTURE_REUSE_OFF, STRUCTURE_REUSE_ALWAYS);
  vtkGetMacro(StructureReuse, int);
  void SetStructureReuseToOff() { this->SetStructureReuse(STRUCTURE_REUSE_OFF); }
  void SetStructureReuseToTimeSeries() { this->SetStructureReuse(STRUCTURE_REUSE_TIME_SERIES); }
  void SetStructureReuseToAlways() { this->SetStructureReuse(STRUCTURE_REUSE_ALWAYS); }
  ///@}

  /**
   * Whether the last update re-sampled the attributes alone (true) or built the
   * OFB (false).
   */
  vtkGetMacro(LastUpdateResampled, bool);

  /**
   * Zero-area triangles skipped by the last build.
   */
  vtkGetMacro(NumberOfSkippedTriangles, vtkIdType);

  /**
   * Wall-clock time of the last update (ms): a build or a re-sampling.
   */
  vtkGetMacro(LastBuildTime, double);

  /**
   * Free the build buffers the CPU backend keeps between updates (triangle setups
   * and spans, a few hundred bytes per triangle) and the sources kept for
   * re-sampling (StructureReuse); the next update allocates them again (and builds).
   */
  void ReleaseBuffers();

  /**
   * Estimated bytes of a build of `dataSet` at the current settings on the CPU (the
   * copy of the surface, the per-triangle buffers, the grids and the estimated
   * samples), or -1 if the input is not valid. Only the surface is prepared (for
   * a dataset other than a vtkPolyData, extracted first).
   */
  double EstimateMemory(vtkDataObject* dataSet);

protected:
  vtkOFBSampler();
  ~vtkOFBSampler() override;

  /**
   * The build: the input checked and prepared (vtkOFBSurface), the frame
   * computed, then the backend given by SelectBackend() run; one that is
   * unavailable for this build gives way to the CPU backend, with a warning.
   */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The input port accepts any vtkDataSet or vtkCompositeDataSet.
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * The backend that builds the next output: the CPU backend here (subclasses
   * such as vtkOFBBuilder return another one).
   */
  virtual vtkOFBSamplerBackend* SelectBackend();

  /// The CPU backend (multi-threaded scan conversion with vtkSMPTools).
  vtkOFBSamplerBackend* GetCPUBackend() const { return this->CPUBackend; }

  /// The backend that built, or failed to build, the current output; null before any build.
  vtkOFBSamplerBackend* GetLastBuildBackend() const { return this->LastBuildBackend; }

  /**
   * The surface to sample: `input` itself if a vtkPolyData, the merged surface of
   * its blocks (vtkOFBMergeBlocks) if a composite dataset, else its outer surface
   * (vtkDataSetSurfaceFilter) with its point and cell arrays; an empty one for no input.
   * A distributed subclass (vtkOFBPSampler) adjusts its arrays.
   */
  virtual vtkSmartPointer<vtkPolyData> GetSurface(vtkDataObject* input);

  /**
   * The box the frame is computed from: `surfaceBounds` (the bounds of the points of
   * the surface's triangles) here; a distributed subclass returns the bounds of
   * every rank's surface, so that all ranks sample on one frame.
   */
  virtual void GetFrameBounds(const double surfaceBounds[6], double bounds[6]);

  /**
   * Compute the frame of a prepared surface at the current resolution into `job`
   * (from GetFrameBounds). Returns false after reporting an error.
   */
  bool ComputeFrame(const vtkOFBSurface& surface, vtkOFBSamplerBackend::Job& job);

  int Resolution;
  vtkIdType MemoryLimit;
  unsigned char DefaultColor[4];
  bool UseInputColors;
  bool PassPointArrays;
  bool PassCellArrays;
  int ArrayPrecedence;
  bool ProjectVectors;
  int StructureReuse;
  bool LastUpdateResampled;
  vtkIdType NumberOfSkippedTriangles;
  double LastBuildTime;

private:
  vtkOFBSampler(const vtkOFBSampler&) = delete;
  void operator=(const vtkOFBSampler&) = delete;

  /// Whether the build needs the input cell of each triangle (cell arrays to pass).
  bool NeedsTriangleCells(vtkPolyData* input) const;

  /**
   * Project the samples' active vectors into their tangent plane when they come
   * from a cell array (surface.CellVectorsIndex) and ProjectVectors is on.
   */
  void ProjectCellVectors(const vtkOFBSurface& surface, vtkOFB* output);

  /**
   * Whether the input has points, cells that name only existing points
   * (vtkOFBCheckCellPointIds), and polygons or strips (warning about lines and
   * vertices). Returns false after reporting an error.
   */
  bool CheckInputCells(vtkPolyData* input);

  /**
   * Check the memory of the build against MemoryLimit from the input's numbers of
   * points and triangles alone, before anything is copied (a lower bound of the
   * checks that follow). Returns false after reporting an error.
   */
  bool CheckInputMemory(vtkPolyData* input,
    vtkOFBSamplerBackend* backend,
    vtkOFBSamplerBackend::Job& job);

  ///@{
  /**
   * Validate and triangulate the input, compute normals and collect the arrays
   * (PrepareSurface), in these steps. Those returning bool return false after
   * reporting an error.
   */
  bool PrepareSurface(vtkPolyData* input, vtkOFBSurface& surface);
  bool PrepareAttributes(vtkPolyData* input, vtkDataArray* normals, vtkOFBSurface& surface);
  bool CopyPoints(vtkPolyData* input, vtkOFBSurface& surface);
  bool CollectTriangles(vtkPolyData* input, vtkOFBSurface& surface);
  vtkDataArray* PrepareNormals(vtkPolyData* input, vtkOFBSurface& surface);
  bool SelectVectors(vtkPolyData* input, vtkOFBSurface& surface, vtkDataArray*& vectors);
  vtkDataArray* SelectColors(vtkPolyData* input, vtkOFBSurface& surface);
  ///@}

  /**
   * Run `backend` on `job`; the CPU backend instead, with a warning, when it is
   * unavailable. Errors are reported; the output is empty unless RESULT_BUILT.
   */
  vtkOFBSamplerBackend::Result RunBackend(vtkOFBSamplerBackend* backend,
    vtkOFBSamplerBackend::Job& job);

  /**
   * Re-sample the attributes of `input` alone on the kept structure when its
   * geometry is that of the last build (StructureReuse): the triangles of that
   * build with the arrays of `input` (PrepareAttributes). Else set `job` up to
   * record the sources of the build. True when the update is done (re-sampled, or
   * failed with an error and an empty output).
   */
  bool ResampleAttributes(vtkInformation* inInfo,
    vtkPolyData* input,
    vtkOFBSamplerBackend::Job& job);

  vtkSmartPointer<vtkOFBSamplerBackend> CPUBackend;
  vtkSmartPointer<vtkOFBSampleSources> Sources;
  vtkWeakPointer<vtkOFBSamplerBackend> LastBuildBackend;
};

#endif
