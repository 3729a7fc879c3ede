#include "vtkOFBPParticleAdvector.h"

#include "vtkCommunicator.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkOFB.h"
#include "vtkOFBParticleExchange.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkOFBPParticleAdvector);
vtkCxxSetObjectMacro(vtkOFBPParticleAdvector, Controller, vtkMultiProcessController);

namespace
{
/// vtkOFBParticleExchange through a vtkMultiProcessController.
class ControllerExchange : public vtkOFBParticleExchange
{
public:
  explicit ControllerExchange(vtkMultiProcessController* controller)
    : Controller(controller)
  {
  }

  int GetRank() override { return this->Controller->GetLocalProcessId(); }

  void AllGather(const std::vector<double>& local, std::vector<double>& all) override
  {
    const int size = this->Controller->GetNumberOfProcesses();
    const vtkIdType count = static_cast<vtkIdType>(local.size());
    std::vector<vtkIdType> counts(size), offsets(size);
    this->Controller->AllGather(&count, counts.data(), 1);
    vtkIdType total = 0;
    for (int r = 0; r < size; ++r)
    {
      offsets[r] = total;
      total += counts[r];
    }
    all.resize(total);
    const double none = 0.0;
    double sink = 0.0;
    this->Controller->AllGatherV(local.empty() ? &none : local.data(),
      all.empty() ? &sink : all.data(),
      count,
      counts.data(),
      offsets.data());
  }

  void AllReduceMinimum(std::vector<double>& values) override
  {
    std::vector<double> local = values;
    if (!values.empty())
    {
      this->Controller->AllReduce(local.data(),
        values.data(),
        static_cast<vtkIdType>(values.size()),
        vtkCommunicator::MIN_OP);
    }
  }

  double AllReduceMaximum(double value) override
  {
    double global = value;
    this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MAX_OP);
    return global;
  }

private:
  vtkMultiProcessController* Controller;
};
}

//------------------------------------------------------------------------------
vtkOFBPParticleAdvector::vtkOFBPParticleAdvector()
  : Controller(nullptr)
  , NumberOfGhostLevels(2)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOFBPParticleAdvector::~vtkOFBPParticleAdvector()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
int vtkOFBPParticleAdvector::RequestUpdateExtent(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (inInfo)
  {
    const int downstream =
      outInfo ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) : 0;
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
      std::max({ downstream, this->NumberOfGhostLevels, this->RequiredGhostLevels }));
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBPParticleAdvector::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  // Every process makes the same collective calls; a process with an empty piece makes
  // them with nothing to contribute. Whether the input is unsteady (pathlines), agreed on
  // by the processes with a piece: one whose piece is empty takes theirs.
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0], 0);
  const int local = surface && surface->GetNumberOfPolys() + surface->GetNumberOfStrips() > 0;
  const int unsteady = this->IsUnsteady(inputVector) ? 1 : 0;
  const int mine[3] = { local ? unsteady : 1, local ? -unsteady : 0, -local };
  int all[3] = { 0, 0, 0 };
  controller->AllReduce(mine, all, 3, vtkCommunicator::MIN_OP);
  const bool anyUnsteady = all[1] < 0;
  if (all[2] < 0 && all[0] != -all[1])
  {
    vtkErrorMacro("The processes' pieces disagree on time: some have time steps (pathlines), "
                  "others not: no particles.");
    for (int i = 0; i < 3; ++i)
    {
      vtkDataObject::GetData(outputVector, i)->Initialize();
    }
    return 1;
  }
  this->NumberOfHandOffs = 0;
  ControllerExchange exchange(controller);
  this->Exchange = &exchange;
  int result = 1;
  if (local)
  {
    result = this->Superclass::RequestData(request, inputVector, outputVector);
  }
  else
  {
    for (int i = 0; i < 3; ++i)
    {
      vtkDataObject::GetData(outputVector, i)->Initialize();
    }
    vtkDataSet* seeds = inputVector[2]->GetNumberOfInformationObjects() > 0
      ? vtkDataSet::GetData(inputVector[2], 0)
      : nullptr;
    if (!this->AskForDeeperGhostCells(request, inputVector, false))
    {
      this->ParticipateWithoutPiece(request, seeds, outputVector, anyUnsteady);
    }
  }
  this->Exchange = nullptr;
  return result;
}

//------------------------------------------------------------------------------
void vtkOFBPParticleAdvector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfGhostLevels: " << this->NumberOfGhostLevels << "\n";
  os << indent << "RequiredGhostLevels: " << this->RequiredGhostLevels << "\n";
}
