// glprobe: opens a VTK render window (the same vtkXOpenGLRenderWindow the benchmarks
// use), renders once and prints the OpenGL vendor, renderer and version that VTK got,
// so that a benchmark run can show it did not fall back to Mesa llvmpipe.
// Built by scripts/device/pack.sh; run by scripts/device/run.sh on the target machine.
#include "vtkActor.h"
#include "vtkAutoInit.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <iostream>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

int main()
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(256, 256);
  window->AddRenderer(renderer);
  window->Render();
  const char* caps = window->ReportCapabilities();
  std::cout << (caps ? caps : "(no capabilities reported)") << std::endl;
  return window->SupportsOpenGL() ? 0 : 1;
}
