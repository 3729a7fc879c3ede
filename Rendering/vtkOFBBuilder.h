/**
 * @class   vtkOFBBuilder
 * @brief   Build a vtkOFB from a surface, on the GPU through VTK's OpenGL context or on the CPU
 *
 * vtkOFBBuilder is the construction entry point of vtkOFB. It has every setting
 * of vtkOFBSampler (Resolution, MemoryLimit, colours, arrays) and adds the choice
 * of backend:
 *
 * - `CPU`: vtkOFBSampler's multi-threaded scan conversion (vtkSMPTools).
 * - `OpenGL`: rasterization in the context of a VTK render window (SetRenderWindow).
 *   Not available in this version: asking for it falls back to the CPU with a
 *   warning.
 * - `Auto` (default): the OpenGL backend on hardware renderers when available,
 *   else the CPU.
 *
 * GetLastBackend() tells which backend built the current output.
 *
 * @sa vtkOFBSampler vtkOFB
 */

#ifndef vtkOFBBuilder_h
#define vtkOFBBuilder_h

#include "vtkOFBRenderingModule.h" // for export macro
#include "vtkOFBSampler.h"

class vtkRenderWindow;

class VTKOFBRENDERING_EXPORT vtkOFBBuilder : public vtkOFBSampler
{
public:
  static vtkOFBBuilder* New();
  vtkTypeMacro(vtkOFBBuilder, vtkOFBSampler);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BackendType
  {
    Auto = 0,
    CPU = 1,
    OpenGL = 2
  };

  ///@{
  /**
   * Construction backend: Auto (default), CPU or OpenGL.
   */
  vtkSetClampMacro(Backend, int, Auto, OpenGL);
  vtkGetMacro(Backend, int);
  void SetBackendToAuto() { this->SetBackend(Auto); }
  void SetBackendToCPU() { this->SetBackend(CPU); }
  void SetBackendToOpenGL() { this->SetBackend(OpenGL); }
  ///@}

  ///@{
  /**
   * Render window whose OpenGL context the OpenGL backend uses (default none).
   */
  void SetRenderWindow(vtkRenderWindow* renWin);
  vtkGetObjectMacro(RenderWindow, vtkRenderWindow);
  ///@}

  /**
   * Backend (CPU or OpenGL) that built the current output; Auto before any build.
   */
  vtkGetMacro(LastBackend, int);

  /**
   * Name of a backend value.
   */
  static const char* GetBackendAsString(int backend);

protected:
  vtkOFBBuilder();
  ~vtkOFBBuilder() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Backend;
  int LastBackend;
  vtkRenderWindow* RenderWindow;

private:
  vtkOFBBuilder(const vtkOFBBuilder&) = delete;
  void operator=(const vtkOFBBuilder&) = delete;
};

#endif
