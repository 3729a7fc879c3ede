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

#include <string>
#include <vector>

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

protected:
  vtkOFBGLSampler();
  ~vtkOFBGLSampler() override;

private:
  vtkOFBGLSampler(const vtkOFBGLSampler&) = delete;
  void operator=(const vtkOFBGLSampler&) = delete;

  /**
   * Rasterize `surface` into `output`, whose frame is already set, in the current
   * context of `window`. On success the output has its offsets, samples and
   * depths, and `triangles` and `barycentrics` (2 per sample) hold what attribute
   * interpolation needs. `error` explains a failure (context, limits,
   * allocation); the memory of the samples is checked against `job`'s limit once
   * their number is known.
   */
  bool Rasterize(vtkOpenGLRenderWindow* window,
    Job& job,
    std::vector<vtkTypeUInt32>& triangles,
    std::vector<float>& barycentrics);

  vtkWeakPointer<vtkOpenGLRenderWindow> RenderWindow;
};

#endif
