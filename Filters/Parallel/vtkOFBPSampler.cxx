#include "vtkOFBPSampler.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkOFB.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>

vtkStandardNewMacro(vtkOFBPSampler);
vtkCxxSetObjectMacro(vtkOFBPSampler, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkOFBPSampler::vtkOFBPSampler()
  : Controller(nullptr)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
  this->GlobalBounds[0] = this->GlobalBounds[2] = this->GlobalBounds[4] = 1.0;
  this->GlobalBounds[1] = this->GlobalBounds[3] = this->GlobalBounds[5] = -1.0;
}

//------------------------------------------------------------------------------
vtkOFBPSampler::~vtkOFBPSampler()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
void vtkOFBPSampler::GetGlobalBounds(double bounds[6]) const
{
  std::copy(this->GlobalBounds, this->GlobalBounds + 6, bounds);
}

//------------------------------------------------------------------------------
void vtkOFBPSampler::AllReduceBounds(vtkMultiProcessController* controller,
  const double local[6],
  double global[6])
{
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    std::copy(local, local + 6, global);
    return;
  }
  // The minimum as the maximum of its negative: one MAX reduction of six doubles. An
  // invalid box on an axis (min > max) takes no part.
  double send[6];
  double received[6];
  for (int k = 0; k < 3; ++k)
  {
    const bool valid = local[2 * k] <= local[2 * k + 1];
    send[2 * k] = valid ? -local[2 * k] : -VTK_DOUBLE_MAX;
    send[2 * k + 1] = valid ? local[2 * k + 1] : -VTK_DOUBLE_MAX;
  }
  controller->AllReduce(send, received, 6, vtkCommunicator::MAX_OP);
  for (int k = 0; k < 3; ++k)
  {
    global[2 * k] = -received[2 * k];
    global[2 * k + 1] = received[2 * k + 1];
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBPSampler::GetSurface(vtkDataObject* input)
{
  vtkSmartPointer<vtkPolyData> surface = this->Superclass::GetSurface(input);
  const char* ghosts = vtkDataSetAttributes::GhostArrayName();
  vtkDataArray* pointGhosts = surface->GetPointData()->GetArray(ghosts);
  vtkDataArray* cellGhosts = surface->GetCellData()->GetArray(ghosts);
  if (!pointGhosts && !(cellGhosts && this->GhostCellsOnly))
  {
    return surface;
  }
  // A copy that shares everything but the attribute lists: the point ghosts are not
  // interpolated, and with PassCellArrays off the cell ghosts are the only cell array.
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(surface);
  copy->GetPointData()->RemoveArray(ghosts);
  if (cellGhosts && this->GhostCellsOnly)
  {
    copy->GetCellData()->Initialize();
    copy->GetCellData()->AddArray(cellGhosts);
  }
  return copy;
}

//------------------------------------------------------------------------------
void vtkOFBPSampler::GetFrameBounds(const double surfaceBounds[6], double bounds[6])
{
  std::copy(this->UseGlobalBounds ? this->GlobalBounds : surfaceBounds,
    (this->UseGlobalBounds ? this->GlobalBounds : surfaceBounds) + 6,
    bounds);
}

//------------------------------------------------------------------------------
int vtkOFBPSampler::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    this->UseGlobalBounds = false;
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0]);
  const bool cellGhosts = vtkDataObject::GetData(inputVector[0]) &&
    vtkPolyData::SafeDownCast(input) &&
    vtkPolyData::SafeDownCast(input)->GetCellData()->GetArray(
      vtkDataSetAttributes::GhostArrayName());
  this->GhostCellsOnly = !this->PassCellArrays && cellGhosts;
  vtkSmartPointer<vtkPolyData> surface = this->GetSurface(input);

  // The bounds of this piece's polygons and strips (those of the points its cells use),
  // combined with every other piece's: one collective call on every process, whatever
  // follows.
  const bool empty = surface->GetNumberOfPoints() == 0 ||
    surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0;
  double local[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  if (!empty)
  {
    surface->GetBounds(local);
  }
  double bounds[6];
  vtkOFBPSampler::AllReduceBounds(controller, local, bounds);
  if (!std::equal(bounds, bounds + 6, this->GlobalBounds))
  {
    // Another frame: the structure kept for re-sampling attributes does not fit it.
    this->ReleaseBuffers();
  }
  std::copy(bounds, bounds + 6, this->GlobalBounds);

  int result = 1;
  if (empty)
  {
    // Nothing to sample here: the common frame without samples.
    vtkOFB* output = vtkOFB::GetData(outputVector);
    output->Initialize();
    vtkOFBSurface none;
    vtkOFBSamplerBackend::Job job;
    this->UseGlobalBounds = true;
    if (bounds[0] <= bounds[1] && this->ComputeFrame(none, job))
    {
      if (!output->SetFrame(job.Origin, job.CellSize, job.Dimensions) ||
        !output->AllocateSamples(0))
      {
        output->Initialize();
      }
    }
  }
  else
  {
    const bool passCells = this->PassCellArrays;
    this->PassCellArrays = passCells || cellGhosts;
    this->UseGlobalBounds = true;
    result = this->Superclass::RequestData(request, inputVector, outputVector);
    this->PassCellArrays = passCells;
  }
  this->UseGlobalBounds = false;
  this->GhostCellsOnly = false;
  return result;
}

//------------------------------------------------------------------------------
void vtkOFBPSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "GlobalBounds: (" << this->GlobalBounds[0] << ", " << this->GlobalBounds[1]
     << ", " << this->GlobalBounds[2] << ", " << this->GlobalBounds[3] << ", "
     << this->GlobalBounds[4] << ", " << this->GlobalBounds[5] << ")\n";
}
