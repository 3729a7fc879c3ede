#include "vtkOFBBuilder.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkOFBGLSampler.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkTimerLog.h"

#include <cstdlib>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBBuilder);
vtkCxxSetObjectMacro(vtkOFBBuilder, RenderWindow, vtkRenderWindow);

//------------------------------------------------------------------------------
vtkOFBBuilder::vtkOFBBuilder()
  : Backend(Auto)
  , LastBackend(Auto)
  , RenderWindow(nullptr)
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
    case CPU:
      return "CPU";
    case OpenGL:
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
int vtkOFBBuilder::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->LastBackend = Auto;
  vtkOpenGLRenderWindow* window = nullptr;
  vtkSmartPointer<vtkRenderWindow> ownWindow;
  std::string why;
  bool useGL = false;
  if (this->Backend != CPU)
  {
    window = vtkOpenGLRenderWindow::SafeDownCast(this->RenderWindow);
    if (!window && this->Backend == OpenGL)
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
    if (window)
    {
      useGL = vtkOFBGLSampler::IsSupported(window, why);
      if (useGL && this->Backend == Auto && vtkOFBGLSampler::IsSoftwareRenderer(window))
      {
        useGL = false; // the multi-threaded CPU sampler beats a software rasterizer
      }
    }
    if (!useGL && this->Backend == OpenGL)
    {
      vtkWarningMacro("The OpenGL backend cannot be used (" << why
                                                            << "); building on the CPU instead.");
    }
  }
  if (useGL && this->BuildWithOpenGL(window, inputVector, outputVector))
  {
    this->LastBackend = OpenGL;
    return 1;
  }
  this->LastBackend = CPU;
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
bool vtkOFBBuilder::BuildWithOpenGL(
  vtkOpenGLRenderWindow* window, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkOFB* output = vtkOFB::GetData(outputVector);
  output->Initialize();
  this->NumberOfSkippedTriangles = 0;
  this->LastBuildTime = 0.0;
  const double start = vtkTimerLog::GetUniversalTime();
  this->UpdateProgress(0.0);
  vtkOFBSurface surface;
  if (!this->PrepareSurface(input, surface) || !this->SetUpFrame(surface, output))
  {
    // Invalid input or too much memory: reported; the CPU path would report it again.
    output->Initialize();
    return true;
  }
  const vtkIdType* dims = output->GetDimensions();
  const double cellSize = output->GetCellSize();
  const double limit = 1024.0 * 1024.0 * static_cast<double>(this->MemoryLimit);
  this->UpdateProgress(0.1);
  // Bytes per sample of the build: from the estimate's formula with one sample.
  const double perSample = this->EstimateBytes(surface, dims, cellSize, 1.0) -
    this->EstimateBytes(surface, dims, cellSize, 0.0);
  std::vector<vtkTypeUInt32> triangles;
  std::vector<float> barycentrics;
  std::string error;
  window->PushContext();
  const bool sampled = vtkOFBGLSampler::Sample(
    window, surface, output, limit, perSample, triangles, barycentrics, error);
  window->PopContext();
  if (!sampled)
  {
    vtkWarningMacro("The OpenGL build failed (" << error << "); building on the CPU instead.");
    output->Initialize();
    return false;
  }
  this->UpdateProgress(0.7);
  const vtkIdType n = output->GetNumberOfSamples();
  std::vector<float> w1(n), w2(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    w1[i] = barycentrics[2 * i];
    w2[i] = barycentrics[2 * i + 1];
  }
  barycentrics.clear();
  if (!output->BuildCellIndex() ||
    !this->InterpolateAttributes(surface, output, triangles.data(), w1.data(), w2.data()))
  {
    output->Initialize();
    return true;
  }
  this->LastBuildTime = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
  this->UpdateProgress(1.0);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << vtkOFBBuilder::GetBackendAsString(this->Backend) << "\n";
  os << indent << "LastBackend: " << vtkOFBBuilder::GetBackendAsString(this->LastBackend) << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
}
