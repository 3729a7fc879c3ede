/**
 * @class   vtkOFBSampleSources
 * @brief   What each sample of an OFB build was made from, to re-sample its attributes alone
 *
 * vtkOFBSampler keeps one: a build records, per sample, the triangle it lies on
 * and its barycentric coordinates (w1, w2) in that triangle (12 bytes a sample),
 * with the structure of the output (frame, cell offsets, depths, cell indices)
 * and its sample normals, and a key of the geometry it was built from. When the
 * next input has the same geometry (Matches), the sampler gives the output that
 * structure again (shared, not copied: vtkOFB::GetStructureMTime does not change)
 * and re-interpolates the attributes alone (Resample): the colours, the vector
 * field and the other point and cell arrays, as the backend that built it does;
 * the normals, which depend on the geometry alone, are those of the build.
 *
 * The geometry key: the points (their coordinates), the polygons and strips
 * (offsets and connectivity), the input point normals, the resolution and the
 * backend. The points' and cells' arrays and their modification times are
 * compared first; where they differ (a reader gives new arrays for each time
 * step), a 64-bit hash of their content is.
 *
 * Not for applications: the header is installed (not wrapped) for the backends
 * of other modules, which record into it (RecordSamples).
 *
 * @sa vtkOFBSampler vtkOFBSamplerBackend
 */

#ifndef vtkOFBSampleSources_h
#define vtkOFBSampleSources_h

#include "vtkOFBCoreModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <cstdint> // for Key
#include <vector>  // for members

class vtkDataArray;
class vtkOFB;
class vtkOFBSurface;
class vtkPolyData;

class VTKOFBCORE_EXPORT vtkOFBSampleSources : public vtkObject
{
public:
  static vtkOFBSampleSources* New();
  vtkTypeMacro(vtkOFBSampleSources, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The key of a geometry: the objects and modification times of its arrays, and
   * the hash of their content (0 until computed).
   */
  struct Key
  {
    const void* Arrays[6] = { nullptr, nullptr, nullptr, nullptr, nullptr, nullptr };
    vtkMTimeType Times[6] = { 0, 0, 0, 0, 0, 0 };
    vtkIdType Sizes[3] = { 0, 0, 0 };
    uint64_t Hash = 0;
    int Resolution = 0;
    const void* Backend = nullptr;
  };

  /// The key of `input` at `resolution` for `backend` (its content hash not computed).
  static Key MakeKey(vtkPolyData* input, int resolution, const void* backend);

  /**
   * Whether the kept build was made from the geometry of `key` (computing its
   * content hash when the arrays or their times differ from the kept ones).
   */
  bool Matches(vtkPolyData* input, Key& key);

  /**
   * Room for the sources of n samples, in sample order (after the sort of each
   * cell): the triangle of each, and its barycentrics (w1, w2) in it. A backend
   * writes them during the build; false if they cannot be allocated.
   */
  bool RecordSamples(vtkIdType n);
  vtkTypeUInt32* GetTriangles() { return this->Triangles.data(); }
  float* GetW1() { return this->W1.data(); }
  float* GetW2() { return this->W2.data(); }

  /**
   * Keep the structure and the normals of `output`, built from `surface`, the
   * geometry of `key`, with its sources recorded (RecordSamples); and the
   * surface's triangles and their input cells.
   */
  void Keep(vtkOFB* output, vtkPolyData* input, Key& key, const vtkOFBSurface& surface);

  /**
   * Whether the kept build has the input cell of each of its triangles (it had
   * cell arrays to pass), which a re-sampling of cell arrays needs.
   */
  bool HasTriangleCells() const;

  /**
   * Give `output` the kept structure and the arrays of `surface` (the attributes
   * of an input of the same geometry, see vtkOFBSampler::PrepareAttributes: its
   * triangles and their cells are the kept ones) interpolated from the kept
   * sources. False when nothing is kept.
   */
  bool Resample(const vtkOFBSurface& surface, vtkOFB* output);

  /// Forget the kept build (and free its sources).
  void Reset();

  /// Whether a build is kept.
  bool HasBuild() const { return this->Structure != nullptr; }

  /// Bytes of the kept sources (12 a sample).
  vtkIdType GetSourceBytes() const;

protected:
  vtkOFBSampleSources();
  ~vtkOFBSampleSources() override;

private:
  vtkOFBSampleSources(const vtkOFBSampleSources&) = delete;
  void operator=(const vtkOFBSampleSources&) = delete;

  /// A 64-bit hash of the content of the arrays of `input` that make its geometry.
  static uint64_t HashGeometry(vtkPolyData* input);

  std::vector<vtkTypeUInt32> Triangles; // per sample, renumbered (see Keep)
  std::vector<float> W1, W2;
  /// The point ids (3) and the input cell of each renumbered triangle.
  std::vector<vtkIdType> Corners, Cells;
  /// The memory of the tables of a re-sampling, kept for the next one.
  std::vector<char>& Table(size_t k);

  std::vector<std::vector<char>> Tables;
  vtkSmartPointer<vtkOFB> Structure;
  vtkSmartPointer<vtkDataArray> Normals;
  Key Kept;
};

#endif
