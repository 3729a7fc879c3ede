/**
 * @class   vtkOFBBuilder
 * @brief   Build a vtkOFB from a surface, on the GPU through VTK's OpenGL context or on the CPU
 *
 * vtkOFBBuilder is the construction entry point of vtkOFB. It takes the inputs of
 * vtkOFBSampler (any vtkDataSet, or a vtkCompositeDataSet as one OFB over all its
 * blocks with the samples' "BlockIndex"; both backends build from the same prepared
 * surface), has every setting of vtkOFBSampler (Resolution, MemoryLimit, colours,
 * arrays) and adds the choice of backend (a vtkOFBSamplerBackend that the sampler's build runs):
 *
 * - `BACKEND_CPU`: vtkOFBSampler's multi-threaded scan conversion (vtkSMPTools).
 * - `BACKEND_OPENGL`: rasterization in the context of a VTK render window (SetRenderWindow,
 *   or an offscreen window the builder makes itself when none is set). A geometry
 *   shader routes each triangle to the viewport of its grid in a framebuffer
 *   without attachments; the fragment shader counts samples per cell with SSBO
 *   atomics; a compute shader scans the counts; a second draw fills depths,
 *   triangles and barycentric coordinates; a compute shader sorts each cell by
 *   depth (no limit on depth complexity). The sample arrays are then interpolated
 *   from the barycentric coordinates by the same code as the CPU backend. Needs
 *   OpenGL 4.3 (IsSupported). GL state is restored afterwards.
 * - `BACKEND_AUTO` (default): the CPU, unless vtkSMPTools runs a single thread and a
 *   render window is set whose context supports the OpenGL backend on a hardware
 *   renderer. Measured (docs/benchmarks.md), the CPU sampler is faster from two
 *   threads on: the OpenGL backend reads every sample back (16 bytes) and
 *   interpolates the arrays on the CPU all the same, and on an NVIDIA H200 the
 *   CPU with 2 threads built 1.0-3.2x faster, with 16 threads 1.0-5.6x; on
 *   software renderers (llvmpipe) the CPU is 4-11x faster.
 *
 * Whenever OpenGL was asked for and cannot be used (no display, an old context, a
 * frame larger than the context's viewports, a GPU allocation failure), the
 * builder warns and builds on the CPU: it never silently produces nothing.
 * GetLastBackend() tells which backend built the current output.
 *
 * @sa vtkOFBSampler vtkOFB
 */

#ifndef vtkOFBBuilder_h
#define vtkOFBBuilder_h

#include "vtkOFBRenderingModule.h" // for export macro
#include "vtkOFBSampler.h"

#include "vtkSmartPointer.h" // for FindOpenGLWindow

#include <memory> // for std::unique_ptr

class vtkOpenGLRenderWindow;
class vtkRenderWindow;

class VTKOFBRENDERING_EXPORT vtkOFBBuilder : public vtkOFBSampler
{
public:
  static vtkOFBBuilder* New();
  vtkTypeMacro(vtkOFBBuilder, vtkOFBSampler);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BackendType
  {
    BACKEND_AUTO = 0,
    BACKEND_CPU = 1,
    BACKEND_OPENGL = 2
  };

  ///@{
  /**
   * Construction backend: BACKEND_AUTO (default), BACKEND_CPU or BACKEND_OPENGL.
   */
  vtkSetClampMacro(Backend, int, BACKEND_AUTO, BACKEND_OPENGL);
  vtkGetMacro(Backend, int);
  void SetBackendToAuto() { this->SetBackend(BACKEND_AUTO); }
  void SetBackendToCPU() { this->SetBackend(BACKEND_CPU); }
  void SetBackendToOpenGL() { this->SetBackend(BACKEND_OPENGL); }
  ///@}

  ///@{
  /**
   * Render window whose OpenGL context the OpenGL backend uses (default none).
   */
  void SetRenderWindow(vtkRenderWindow* renWin);
  vtkGetObjectMacro(RenderWindow, vtkRenderWindow);
  ///@}

  /**
   * Backend (BACKEND_CPU or BACKEND_OPENGL) that built the current output; BACKEND_AUTO
   * before any build.
   */
  vtkGetMacro(LastBackend, int);

  ///@{
  /**
   * Whether the OpenGL backend times its phases (default off; each phase then ends
   * with a glFinish). GetLastOpenGLPhaseTimes() gives the last OpenGL build's
   * phases in milliseconds ("compile 0.4, upload 1.2, ..."), empty when off.
   */
  void SetMeasureOpenGLPhases(bool measure);
  bool GetMeasureOpenGLPhases() const;
  vtkBooleanMacro(MeasureOpenGLPhases, bool);
  const char* GetLastOpenGLPhaseTimes() const;
  ///@}

  /**
   * Whether the context of `renWin` can run the OpenGL backend (OpenGL 4.3 with
   * compute shaders, SSBOs and 3 viewports). Makes the context current.
   */
  static bool IsSupported(vtkRenderWindow* renWin);

  /**
   * Name of a backend value.
   */
  static const char* GetBackendAsString(int backend);

protected:
  vtkOFBBuilder();
  ~vtkOFBBuilder() override;

  /**
   * Choose the render window of the OpenGL backend, then build as vtkOFBSampler
   * does, with the backend SelectBackend() gives.
   */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The OpenGL backend when RequestData found a window that can run it, else the
   * CPU backend.
   */
  vtkOFBSamplerBackend* SelectBackend() override;

  /**
   * The OpenGL render window to build in, or null to build on the CPU (with a
   * warning when OpenGL was asked for). `ownWindow` keeps an offscreen window
   * made here when none is set.
   */
  vtkOpenGLRenderWindow* FindOpenGLWindow(vtkSmartPointer<vtkRenderWindow>& ownWindow);

  int Backend;
  int LastBackend;
  vtkRenderWindow* RenderWindow;

private:
  vtkOFBBuilder(const vtkOFBBuilder&) = delete;
  void operator=(const vtkOFBBuilder&) = delete;

  // The OpenGL backend.
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
