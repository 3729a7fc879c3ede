#include "vtkOFBParaViewSampler.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFBParaViewArrayChoice.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkOFBParaViewSampler);

//------------------------------------------------------------------------------
vtkOFBParaViewSampler::vtkOFBParaViewSampler() = default;

//------------------------------------------------------------------------------
vtkOFBParaViewSampler::~vtkOFBParaViewSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBParaViewSampler::SetInputArrayToProcess(int idx,
  int port,
  int connection,
  int fieldAssociation,
  const char* name)
{
  if (!vtkofbparaview::IsNoArray(name))
  {
    this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
  }
  else if (vtkofbparaview::ClearArrayChoice(this, idx))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBParaViewSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
