/**
 * @class   vtkOFBGLSampler
 * @brief   The OpenGL backend of vtkOFBBuilder, in a render window's context (private)
 *
 * In the context of an OpenGL 4.3+ render window: a geometry shader routes each
 * triangle to the viewport of its grid in a framebuffer without attachments; the
 * fragment shader counts samples per cell with SSBO atomics; a compute shader
 * scans the counts into cell offsets; a second draw fills depth, triangle and
 * barycentric coordinates of every sample; a compute shader sorts each cell by
 * (depth, triangle). The results are read back into the vtkOFB (offsets,
 * depths) and the sample arrays are interpolated on the CPU exactly as the CPU
 * backend does (vtkOFBSamplerBackend::InterpolateAttributes). GL state is
 * restored afterwards.
 *
 * A context that cannot do it, a frame larger than its viewports, a GPU
 * allocation failure or more samples than the memory limit make the backend
 * RESULT_UNAVAILABLE: vtkOFBSampler then builds on the CPU.
 */

#ifndef vtkOFBGLSampler_h
#define vtkOFBGLSampler_h

#include "vtkOFBSamplerBackend.h"
#include "vtkType.h"
#include "vtkWeakPointer.h" // for RenderWindow

#include <memory> // for std::unique_ptr
#include <string>

class vtkOFB;
class vtkOFBSurface;
class vtkOpenGLRenderWindow;

class vtkOFBGLSampler : public vtkOFBSamplerBackend
{
public:
  static vtkOFBGLSampler* New();
  vtkTypeMacro(vtkOFBGLSampler, vtkOFBSamplerBackend);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The render window whose context builds (not kept alive: its owner, the
   * builder, holds it during the build; default none).
   */
  void SetRenderWindow(vtkOpenGLRenderWindow* window);
  vtkOpenGLRenderWindow* GetRenderWindow() const { return this->RenderWindow; }

  Result Sample(Job& job) override;
  const char* GetBackendName() const override { return "OpenGL"; }
  double EstimateWorkBytes(vtkIdType points, vtkIdType triangles, double samples) const override;

  /**
   * Whether the window's context can build an OFB (OpenGL 4.3 with three
   * viewports); makes the context current. `why` says what is missing.
   */
  static bool IsSupported(vtkOpenGLRenderWindow* window, std::string& why);

  /**
   * Whether the context's renderer is a software one (llvmpipe, softpipe, ...).
   */
  static bool IsSoftwareRenderer(vtkOpenGLRenderWindow* window);

  ///@{
  /**
   * Whether Sample() times its phases (default off: each phase then ends with a
   * glFinish, which serialises CPU and GPU and slows the build a little).
   */
  vtkSetMacro(MeasurePhases, bool);
  vtkGetMacro(MeasurePhases, bool);
  ///@}

  /**
   * The phases of the last build, in milliseconds of wall-clock time, as
   * "name ms" pairs separated by commas ("compile 0.4, upload 1.2, ..."); empty
   * when MeasurePhases was off.
   */
  const std::string& GetLastPhaseTimes() const { return this->LastPhaseTimes; }

protected:
  vtkOFBGLSampler();
  ~vtkOFBGLSampler() override;

private:
  vtkOFBGLSampler(const vtkOFBGLSampler&) = delete;
  void operator=(const vtkOFBGLSampler&) = delete;

  /// Where the read-back triangles and barycentric weights go (defined in the .cxx).
  struct Readback;
  /// The compiled build programs of the last context (defined in the .cxx).
  struct ProgramCache;

  /**
   * Rasterize `surface` into `output`, whose frame is already set, in the current
   * context of `window`. On success the output has its offsets, samples and
   * depths, and `readback` holds the triangle and the two weights of each sample
   * that attribute interpolation needs (in the job's sample sources when it
   * records them). `error` explains a failure (context, limits, allocation); the
   * memory of the samples is checked against `job`'s limit once their number is
   * known.
   */
  bool Rasterize(vtkOpenGLRenderWindow* window, Job& job, Readback& readback);

  /// Ends the current phase `name` (after a glFinish when `gpu`) when MeasurePhases is on.
  void EndPhase(const char* name, bool gpu);

  vtkWeakPointer<vtkOpenGLRenderWindow> RenderWindow;
  std::unique_ptr<ProgramCache> Programs;
  bool MeasurePhases = false;
  std::string LastPhaseTimes;
  double PhaseStart = 0.0;
};

#endif
