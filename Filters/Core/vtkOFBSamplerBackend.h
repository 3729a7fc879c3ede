/**
 * @class   vtkOFBSamplerBackend
 * @brief   The interface of an OFB construction backend (for vtkOFBSampler and subclasses)
 *
 * vtkOFBSampler validates and prepares its input (vtkOFBSurface), computes the
 * frame and hands both to a backend in a Job; the backend sets the frame of the
 * output, places and sorts the samples and fills their arrays. Two backends
 * exist: the CPU one that vtkOFBSampler uses (vtkSMPTools) and the OpenGL one
 * that vtkOFBBuilder adds. Backends report failures as text in the job; the
 * sampler reports them as its own errors or warnings, where observers of the
 * algorithm see them.
 *
 * The class also holds what the backends share: the memory estimate of a build
 * and its one check against the limit (CheckMemoryLimit), and the interpolation
 * of the sample arrays from the triangle and barycentric coordinates of each
 * sample (InterpolateAttributes), so that both backends give the same samples.
 *
 * Not for applications: the header is installed (not wrapped) so that modules
 * other than OFB::Core can provide backends.
 *
 * @sa vtkOFBSampler vtkOFBSurface
 */

#ifndef vtkOFBSamplerBackend_h
#define vtkOFBSamplerBackend_h

#include "vtkOFBCoreModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for Job

class vtkAlgorithm;
class vtkOFB;
class vtkOFBSampleSources;
class vtkOFBSurface;

class VTKOFBCORE_EXPORT vtkOFBSamplerBackend : public vtkObject
{
public:
  vtkTypeMacro(vtkOFBSamplerBackend, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * One build: what the sampler gives the backend, and why it failed.
   */
  struct Job
  {
    /// The prepared surface (not empty, every triangle of non-zero area).
    const vtkOFBSurface* Surface = nullptr;
    /// The empty output; the backend sets its frame (vtkOFB::SetFrame) from the fields below.
    vtkOFB* Output = nullptr;
    double Origin[3] = { 0.0, 0.0, 0.0 };
    double CellSize = 0.0;
    vtkIdType Dimensions[3] = { 0, 0, 0 };
    /// Most bytes the build may take (vtkOFBSampler::MemoryLimit).
    double MemoryLimit = 0.0;
    /// Told the progress (between 0.05 and 0.85) and asked whether to abort; may be null.
    vtkAlgorithm* Algorithm = nullptr;
    /// Why the build failed or the backend is unavailable (empty when already reported).
    std::string Error;
    /**
     * Where the backend records the triangle and barycentrics of each sample
     * (vtkOFBSampleSources::RecordSamples), for a later re-sampling of the
     * attributes alone; null: not recorded.
     */
    vtkOFBSampleSources* Sources = nullptr;
  };

  enum Result
  {
    RESULT_BUILT = 0,      ///< the output holds the OFB
    RESULT_FAILED = 1,     ///< bad input or a limit: the output must stay empty
    RESULT_UNAVAILABLE = 2 ///< the backend cannot build this one: build it with another
  };

  /**
   * Build the OFB of `job.Surface` into `job.Output`.
   */
  virtual Result Sample(Job& job) = 0;

  /**
   * Name of the backend in messages ("CPU", "OpenGL").
   */
  virtual const char* GetBackendName() const = 0;

  /**
   * Bytes of the backend's own buffers for a surface of `points` points and
   * `triangles` triangles giving `samples` samples (beyond the prepared surface
   * and the output, see EstimateBytes).
   */
  virtual double EstimateWorkBytes(vtkIdType points, vtkIdType triangles, double samples) const = 0;

  /**
   * Free the buffers the backend keeps from build to build (none by default).
   */
  virtual void ReleaseBuffers() {}

  /**
   * Estimated bytes of a build of `surface` on a frame of `dims` cells giving
   * `samples` samples: the prepared surface, the output and this backend's
   * buffers.
   */
  double EstimateBytes(const vtkOFBSurface& surface, const vtkIdType dims[3], double samples) const;

  /**
   * Estimated bytes of a build before the surface is prepared, from the input's
   * numbers of points and triangles only: the prepared surface and this backend's
   * per-point and per-triangle buffers (a lower bound of EstimateBytes).
   */
  double EstimateBytes(vtkIdType points, vtkIdType triangles) const;

  /**
   * Bytes of a prepared surface of `points` points and `triangles` triangles and of
   * its preparation's temporaries (`vectorComponents` per point for a copied vector
   * field).
   */
  static double EstimateSurfaceBytes(vtkIdType points, vtkIdType triangles, int vectorComponents);

  /**
   * Bytes of an output of `dims` cells and `samples` samples of the arrays of
   * `surface`, with the per-sample temporaries of a build (triangle and
   * barycentrics) and the per-cell counters.
   */
  static double EstimateOutputBytes(const vtkOFBSurface& surface,
    const vtkIdType dims[3],
    double samples);

  /**
   * Estimated number of samples of `surface` for cells of `cellSize`: from the
   * projected area and perimeter of each triangle on its grid.
   */
  static double EstimateSamples(const vtkOFBSurface& surface, double cellSize);

  /**
   * The one memory check of a build: false, with the message in `error`, when
   * `bytes` exceed `limit` (both in bytes).
   */
  static bool CheckMemoryLimit(double bytes, double limit, std::string& error);

protected:
  vtkOFBSamplerBackend();
  ~vtkOFBSamplerBackend() override;

  /**
   * Fill the sample arrays of `output` (its samples already placed and sorted)
   * from the triangle and barycentric coordinates (w1, w2) of each sample:
   * colours, normals, the projected vector field and the other point arrays, as
   * the CPU backend computes them.
   */
  static bool InterpolateAttributes(const vtkOFBSurface& surface,
    vtkOFB* output,
    const vtkTypeUInt32* triangles,
    const float* w1,
    const float* w2);

private:
  vtkOFBSamplerBackend(const vtkOFBSamplerBackend&) = delete;
  void operator=(const vtkOFBSamplerBackend&) = delete;
};

#endif
