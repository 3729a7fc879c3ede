#include "vtkOFBParaViewReader.h"

#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

vtkStandardNewMacro(vtkOFBParaViewReader);

//------------------------------------------------------------------------------
vtkOFBParaViewReader::vtkOFBParaViewReader() = default;

//------------------------------------------------------------------------------
vtkOFBParaViewReader::~vtkOFBParaViewReader() = default;

//------------------------------------------------------------------------------
int vtkOFBParaViewReader::RequestInformation(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (!this->Superclass::RequestInformation(request, inInfo, outInfo))
  {
    return 0;
  }
  // Every piece executes (without this the pipeline gives the pieces after the first
  // an empty output).
  outInfo->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBParaViewReader::RequestData(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  const int result = this->Superclass::RequestData(request, inInfo, outInfo);
  vtkInformation* info = outInfo->GetInformationObject(0);
  vtkOFB* ofb = vtkOFB::GetData(outInfo, 0);
  const int piece = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  if (!ofb || piece <= 0 || ofb->GetNumberOfSamples() == 0)
  {
    return result;
  }
  // The same samples as the first piece's, which owns them.
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(ofb->GetNumberOfSamples());
  ghosts->FillValue(vtkDataSetAttributes::DUPLICATEPOINT);
  ofb->GetSampleData()->AddArray(ghosts);
  return result;
}

//------------------------------------------------------------------------------
void vtkOFBParaViewReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
