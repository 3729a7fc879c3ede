#include "vtkOFBParaViewProbe.h"

#include "vtkInformation.h"
#include "vtkInformationDataObjectKey.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkOFBParaViewProbe);
vtkInformationKeyMacro(vtkOFBParaViewProbe, OFB, DataObject);

//------------------------------------------------------------------------------
vtkOFBParaViewProbe::vtkOFBParaViewProbe() = default;

//------------------------------------------------------------------------------
vtkOFBParaViewProbe::~vtkOFBParaViewProbe() = default;

//------------------------------------------------------------------------------
vtkOFB* vtkOFBParaViewProbe::GetOFB(vtkDataObject* data)
{
  return data ? vtkOFB::SafeDownCast(data->GetInformation()->Get(OFB())) : nullptr;
}

//------------------------------------------------------------------------------
int vtkOFBParaViewProbe::RequestData(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  vtkPolyData* output = vtkPolyData::GetData(outInfo, 0);
  const int ok = this->Superclass::RequestData(request, inInfo, outInfo);
  vtkOFB* ofb = vtkOFB::GetData(inInfo[1], 0);
  if (output)
  {
    if (ok && ofb && output->GetNumberOfPoints() > 0)
    {
      output->GetInformation()->Set(OFB(), ofb);
    }
    else
    {
      output->GetInformation()->Remove(OFB());
    }
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkOFBParaViewProbe::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
