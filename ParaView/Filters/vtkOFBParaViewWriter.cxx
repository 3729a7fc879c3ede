#include "vtkOFBParaViewWriter.h"

#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBParaViewGather.h"
#include "vtkOFBSamplePack.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBParaViewWriter);
vtkCxxSetObjectMacro(vtkOFBParaViewWriter, Controller, vtkMultiProcessController);

namespace
{
constexpr const char* SharePrefix = "vtkOFBShare_";
}

//------------------------------------------------------------------------------
vtkOFBParaViewWriter::vtkOFBParaViewWriter()
  : Controller(nullptr)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOFBParaViewWriter::~vtkOFBParaViewWriter()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
int vtkOFBParaViewWriter::FillInputPortInformation(int, vtkInformation* info)
{
  // Any data object, so that ParaView offers the writer for an OFB (its domains do not
  // know the type): WriteData refuses what is not an OFB.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkOFBParaViewWriter::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (vtkofbparaview::RequestOwnPiece(this->Controller, request, inputVector))
  {
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkOFBParaViewWriter::WriteData()
{
  vtkMultiProcessController* controller = this->Controller;
  vtkOFB* ofb = vtkOFB::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    if (!ofb)
    {
      this->ReportWriteError("the input is not an OFB", vtkErrorCode::UserError);
      return;
    }
    this->Superclass::WriteData();
    return;
  }

  // Every process's owned samples on the first process, which merges and writes them;
  // then one broadcast of the result. Every process makes every call, whatever its piece.
  int notOFB = ofb ? 0 : 1;
  int anyNotOFB = 0;
  controller->AllReduce(&notOFB, &anyNotOFB, 1, vtkCommunicator::MAX_OP);
  if (anyNotOFB)
  {
    this->ReportWriteError("the input is not an OFB", vtkErrorCode::UserError);
    return;
  }
  vtkNew<vtkPolyData> share;
  vtkOFBSamplePack::Pack(ofb, share->GetFieldData(), SharePrefix);
  std::vector<vtkSmartPointer<vtkPolyData>> shares;
  int result = 1;
  std::string problem;
  if (!vtkofbparaview::GatherShares(controller, share, shares))
  {
    result = 0;
    problem = "gathering the pieces failed";
  }
  else if (controller->GetLocalProcessId() == 0)
  {
    std::vector<vtkOFBSamplePack::PackRef> packs;
    for (const auto& s : shares)
    {
      for (const auto& pack : vtkOFBSamplePack::FindPacks(s->GetFieldData(), SharePrefix))
      {

        packs.push_back(pack);
      }
    }
    vtkSmartPointer<vtkOFB> merged = vtkOFBSamplePack::Merge(packs, problem);
    shares.clear();
    if (!merged && problem.empty())
    {
      merged = vtkSmartPointer<vtkOFB>::New(); // no process has a frame: an empty OFB
    }
    if (merged)
    {
      vtkNew<vtkOFBWriter> writer;
      writer->SetFileName(this->FileName);
      writer->SetInputData(merged);
      result = writer->Write();
      this->SetErrorCode(writer->GetErrorCode());
    }
    else
    {
      result = 0;
    }
  }
  controller->Broadcast(&result, 1, 0);
  if (!result && controller->GetLocalProcessId() == 0 && !problem.empty())
  {
    this->ReportWriteError(problem, vtkErrorCode::UserError);
  }
  else if (!result && this->GetErrorCode() == vtkErrorCode::NoError)
  {
    this->SetErrorCode(vtkErrorCode::UserError);
  }
}

//------------------------------------------------------------------------------
void vtkOFBParaViewWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
