#include "vtkOFBAlgorithm.h"

#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkOFBAlgorithm);

//------------------------------------------------------------------------------
vtkOFBAlgorithm::vtkOFBAlgorithm()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkOFBAlgorithm::~vtkOFBAlgorithm() = default;

//------------------------------------------------------------------------------
vtkOFB* vtkOFBAlgorithm::GetOutput()
{
  return this->GetOutput(0);
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBAlgorithm::GetOutput(int port)
{
  return vtkOFB::SafeDownCast(this->GetOutputDataObject(port));
}

//------------------------------------------------------------------------------
void vtkOFBAlgorithm::SetInputData(vtkDataObject* input)
{
  this->SetInputData(0, input);
}

//------------------------------------------------------------------------------
void vtkOFBAlgorithm::SetInputData(int port, vtkDataObject* input)
{
  this->SetInputDataInternal(port, input);
}

//------------------------------------------------------------------------------
vtkTypeBool vtkOFBAlgorithm::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inInfo, outInfo);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    return this->RequestInformation(request, inInfo, outInfo);
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    return this->RequestUpdateExtent(request, inInfo, outInfo);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    const int result = this->RequestData(request, inInfo, outInfo);
    // Free the memory of the previous outputs that RequestData did not reuse.
    for (int i = 0; i < outInfo->GetNumberOfInformationObjects(); ++i)
    {
      if (vtkOFB* ofb = vtkOFB::GetData(outInfo, i))
      {
        ofb->ReleaseSpareArrays();
      }
    }
    return result;
  }
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

//------------------------------------------------------------------------------
int vtkOFBAlgorithm::RequestDataObject(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outInfo)
{
  for (int i = 0; i < this->GetNumberOfOutputPorts(); ++i)
  {
    vtkInformation* info = outInfo->GetInformationObject(i);
    if (!vtkOFB::GetData(info))
    {
      vtkOFB* ofb = vtkOFB::New();
      info->Set(vtkDataObject::DATA_OBJECT(), ofb);
      ofb->Delete();
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBAlgorithm::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBAlgorithm::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBAlgorithm::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBAlgorithm::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBAlgorithm::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
