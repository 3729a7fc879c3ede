#include "vtkOFBPPaintFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCommunicator.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBStrokeExchange.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <vector>

namespace
{
/// The collective calls of the paint filter, through the controller.
class ControllerExchange : public vtkOFBStrokeExchange
{
public:
  explicit ControllerExchange(vtkMultiProcessController* controller)
    : Controller(controller)
  {
  }

  void AllReduceMinimum(std::vector<double>& values) override
  {
    if (values.empty())
    {
      return; // empty on every process
    }
    std::vector<double> reduced(values.size());
    this->Controller->AllReduce(values.data(),
      reduced.data(),
      static_cast<vtkIdType>(values.size()),
      vtkCommunicator::MIN_OP);
    values.swap(reduced);
    ++this->Calls;
  }

  void AllGather(const std::vector<double>& local, std::vector<double>& all) override
  {
    all.resize(local.size() * static_cast<size_t>(this->GetNumberOfProcesses()));
    if (local.empty())
    {
      return; // empty on every process
    }
    this->Controller->AllGather(local.data(), all.data(), static_cast<vtkIdType>(local.size()));
    ++this->Calls;
  }

  int GetNumberOfProcesses() const override { return this->Controller->GetNumberOfProcesses(); }

  vtkIdType Calls = 0;

private:
  vtkMultiProcessController* Controller;
};
}

vtkStandardNewMacro(vtkOFBPPaintFilter);
vtkCxxSetObjectMacro(vtkOFBPPaintFilter, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkOFBPPaintFilter::vtkOFBPPaintFilter()
  : Controller(nullptr)
  , NumberOfStrokeReductions(0)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOFBPPaintFilter::~vtkOFBPPaintFilter()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBPPaintFilter::GetStrokes(vtkPolyData* strokes)
{
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return strokes;
  }
  auto local = vtkSmartPointer<vtkPolyData>::New();
  if (strokes)
  {
    local->ShallowCopy(strokes);
  }
  std::vector<vtkSmartPointer<vtkDataObject>> all;
  if (!controller->AllGather(local, all))
  {
    vtkErrorMacro("Gathering the strokes of every process failed: this process's strokes only.");
    return strokes;
  }
  // In the order of the processes; pieces without points left out (vtkAppendPolyData
  // keeps only the arrays that every input has).
  vtkNew<vtkAppendPolyData> append;
  int inputs = 0;
  for (const auto& piece : all)
  {
    auto* polyData = vtkPolyData::SafeDownCast(piece);
    if (polyData && polyData->GetNumberOfPoints() > 0)
    {
      append->AddInputData(polyData);
      ++inputs;
    }
  }
  auto gathered = vtkSmartPointer<vtkPolyData>::New();
  if (inputs > 0)
  {
    append->Update();
    gathered->ShallowCopy(append->GetOutput());
  }
  return gathered;
}

//------------------------------------------------------------------------------
int vtkOFBPPaintFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = this->Controller;
  this->NumberOfStrokeReductions = 0;
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  // Whether any process has samples: if none has, every process reports the error.
  vtkOFB* input = vtkOFB::GetData(inputVector[0]);
  const vtkIdType local = input ? input->GetNumberOfSamples() : 0;
  vtkIdType global = 0;
  controller->AllReduce(&local, &global, 1, vtkCommunicator::SUM_OP);
  if (global == 0)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  ControllerExchange exchange(controller);
  this->Exchange = &exchange;
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->Exchange = nullptr;
  this->NumberOfStrokeReductions = exchange.Calls;
  return result;
}

//------------------------------------------------------------------------------
void vtkOFBPPaintFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfStrokeReductions: " << this->NumberOfStrokeReductions << "\n";
}
