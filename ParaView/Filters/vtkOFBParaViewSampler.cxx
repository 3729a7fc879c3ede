#include "vtkOFBParaViewSampler.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include <cstring>

vtkStandardNewMacro(vtkOFBParaViewSampler);

//------------------------------------------------------------------------------
vtkOFBParaViewSampler::vtkOFBParaViewSampler() = default;

//------------------------------------------------------------------------------
vtkOFBParaViewSampler::~vtkOFBParaViewSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBParaViewSampler::SetInputArrayToProcess(
  int idx, int port, int connection, int fieldAssociation, const char* name)
{
  if (name && *name != '\0' && std::strcmp(name, "None") != 0)
  {
    this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
    return;
  }
  vtkInformationVector* arrays = this->GetInformation()->Get(INPUT_ARRAYS_TO_PROCESS());
  if (arrays && idx >= 0 && idx < arrays->GetNumberOfInformationObjects())
  {
    vtkInformation* choice = arrays->GetInformationObject(idx);
    if (choice->GetNumberOfKeys() > 0)
    {
      choice->Clear();
      this->Modified();
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBParaViewSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
