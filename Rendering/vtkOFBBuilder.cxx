#include "vtkOFBBuilder.h"

#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"

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
int vtkOFBBuilder::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (this->Backend == OpenGL)
  {
    vtkWarningMacro("The OpenGL backend is not available in this version of vtkOFB; "
                    "building on the CPU instead.");
  }
  this->LastBackend = CPU;
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkOFBBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << vtkOFBBuilder::GetBackendAsString(this->Backend) << "\n";
  os << indent << "LastBackend: " << vtkOFBBuilder::GetBackendAsString(this->LastBackend) << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
}
