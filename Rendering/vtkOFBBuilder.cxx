#include "vtkOFBBuilder.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBGLSampler.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSMPTools.h"

#include <cstdlib>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBBuilder);
vtkCxxSetObjectMacro(vtkOFBBuilder, RenderWindow, vtkRenderWindow);

//------------------------------------------------------------------------------
struct vtkOFBBuilder::vtkInternals
{
  vtkNew<vtkOFBGLSampler> GLBackend;
};

//------------------------------------------------------------------------------
vtkOFBBuilder::vtkOFBBuilder()
  : Backend(BACKEND_AUTO)
  , LastBackend(BACKEND_AUTO)
  , RenderWindow(nullptr)
  , Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkOFBBuilder::~vtkOFBBuilder()
{
  this->SetRenderWindow(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkOFBBuilder::GetBackendAsString(int backend)
{
  switch (backend)
  {
    case BACKEND_CPU:
      return "CPU";
    case BACKEND_OPENGL:
      return "OpenGL";
    default:
      return "Auto";
  }
}

//------------------------------------------------------------------------------
bool vtkOFBBuilder::IsSupported(vtkRenderWindow* renWin)
{
  std::string why;
  return vtkOFBGLSampler::IsSupported(vtkOpenGLRenderWindow::SafeDownCast(renWin), why);
}

//------------------------------------------------------------------------------
int vtkOFBBuilder::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->LastBackend = BACKEND_AUTO;
  vtkSmartPointer<vtkRenderWindow> ownWindow;
  this->Internals->GLBackend->SetRenderWindow(this->FindOpenGLWindow(ownWindow));
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->Internals->GLBackend->SetRenderWindow(nullptr);
  this->LastBackend =
    this->GetLastBuildBackend() == this->Internals->GLBackend ? BACKEND_OPENGL : BACKEND_CPU;
  return result;
}

//------------------------------------------------------------------------------
void vtkOFBBuilder::SetMeasureOpenGLPhases(bool measure)
{
  if (this->Internals->GLBackend->GetMeasurePhases() != measure)
  {
    this->Internals->GLBackend->SetMeasurePhases(measure);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBBuilder::GetMeasureOpenGLPhases() const
{
  return this->Internals->GLBackend->GetMeasurePhases();
}

//------------------------------------------------------------------------------
const char* vtkOFBBuilder::GetLastOpenGLPhaseTimes() const
{
  return this->Internals->GLBackend->GetLastPhaseTimes().c_str();
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend* vtkOFBBuilder::SelectBackend()
{
  if (this->Internals->GLBackend->GetRenderWindow())
  {
    return this->Internals->GLBackend;
  }
  return this->Superclass::SelectBackend();
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkOFBBuilder::FindOpenGLWindow(vtkSmartPointer<vtkRenderWindow>& ownWindow)
{
  if (this->Backend == BACKEND_CPU)
  {
    return nullptr;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(this->RenderWindow);
  std::string why;
  if (!window && this->Backend == BACKEND_OPENGL)
  {
    // X11 builds need a display to make a context: without one, say so.
    const char* display = std::getenv("DISPLAY");
    if (display && *display)
    {
      ownWindow = vtk::TakeSmartPointer(vtkRenderWindow::New());
      ownWindow->SetOffScreenRendering(1);
      ownWindow->SetSize(8, 8);
      window = vtkOpenGLRenderWindow::SafeDownCast(ownWindow);
    }
    why = window ? "" : "no render window is set and no display is available to make one";
  }
  bool useGL = false;
  if (window)
  {
    useGL = vtkOFBGLSampler::IsSupported(window, why);
    if (useGL && this->Backend == BACKEND_AUTO &&
      (vtkSMPTools::GetEstimatedNumberOfThreads() > 1 ||
        vtkOFBGLSampler::IsSoftwareRenderer(window)))
    {
      useGL = false; // the CPU sampler is faster from two threads on (see the header)
    }
  }
  if (!useGL && this->Backend == BACKEND_OPENGL)
  {
    vtkWarningMacro(
      "The OpenGL backend cannot be used (" << why << "); building on the CPU instead.");
  }
  return useGL ? window : nullptr;
}

//------------------------------------------------------------------------------
void vtkOFBBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << vtkOFBBuilder::GetBackendAsString(this->Backend) << "\n";
  os << indent << "LastBackend: " << vtkOFBBuilder::GetBackendAsString(this->LastBackend) << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "MeasureOpenGLPhases: " << this->GetMeasureOpenGLPhases() << "\n";
}
