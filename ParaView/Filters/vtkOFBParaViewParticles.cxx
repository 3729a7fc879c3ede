#include "vtkOFBParaViewParticles.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFBParaViewArrayChoice.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vector>

vtkStandardNewMacro(vtkOFBParaViewParticles);

//------------------------------------------------------------------------------
vtkOFBParaViewParticles::vtkOFBParaViewParticles()
  : NumberOfTimeSteps(100)
{
}

//------------------------------------------------------------------------------
vtkOFBParaViewParticles::~vtkOFBParaViewParticles() = default;

//------------------------------------------------------------------------------
void vtkOFBParaViewParticles::SetInputArrayToProcess(int idx,
  int port,
  int connection,
  int fieldAssociation,
  const char* name)
{
  if (!vtkofbparaview::ChooseNoArray(this, idx, name))
  {
    this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
  }
}

//------------------------------------------------------------------------------
int vtkOFBParaViewParticles::RequestInformation(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (!this->Superclass::RequestInformation(request, inInfo, outInfo))
  {
    return 0;
  }
  vtkInformation* surface = inInfo[0]->GetInformationObject(0);
  if (surface && surface->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) &&
    surface->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) > 0)
  {
    return 1; // unsteady: the input's time steps
  }
  std::vector<double> steps(static_cast<size_t>(this->NumberOfTimeSteps));
  for (size_t i = 0; i < steps.size(); ++i)
  {
    steps[i] = static_cast<double>(i);
  }
  const double range[2] = { 0.0, steps.back() };
  for (int i = 0; i < outInfo->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* info = outInfo->GetInformationObject(i);
    info->Set(
      vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), static_cast<int>(steps.size()));
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBParaViewParticles::RequestUpdateExtent(vtkInformation* request,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (!this->Superclass::RequestUpdateExtent(request, inInfo, outInfo))
  {
    return 0;
  }
  // The whole set of seeds on every process.
  vtkInformation* seeds = inInfo[2]->GetInformationObject(0);
  if (seeds)
  {
    seeds->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    seeds->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    seeds->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBParaViewParticles::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
}
