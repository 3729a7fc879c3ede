#include "vtkOFBPPaintFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <vector>

vtkStandardNewMacro(vtkOFBPPaintFilter);
vtkCxxSetObjectMacro(vtkOFBPPaintFilter, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkOFBPPaintFilter::vtkOFBPPaintFilter()
  : Controller(nullptr)
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
  vtkOFB* input = vtkOFB::GetData(inputVector[0]);
  if (controller && controller->GetNumberOfProcesses() > 1 && input &&
    input->GetNumberOfSamples() == 0)
  {
    // An empty piece: nothing to paint, but the gather is collective.
    this->GetStrokes(vtkPolyData::GetData(inputVector[1]));
    this->NumberOfChangedSamples = 0;
    vtkOFB* output = vtkOFB::GetData(outputVector);
    output->ShallowCopy(input);
    return 1;
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkOFBPPaintFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
