#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleAdvectorInternals.h"
#include "vtkOFBParticleExchange.h"

#include "vtkDataSetAttributes.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkScalarsToColors.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkOFBParticleAdvector);

namespace
{
using Clock = std::chrono::steady_clock;
double Milliseconds(Clock::duration d)
{
  return std::chrono::duration<double, std::milli>(d).count();
}
}

vtkCxxSetObjectMacro(vtkOFBParticleAdvector, LookupTable, vtkScalarsToColors);

//------------------------------------------------------------------------------
vtkOFBParticleAdvector::vtkOFBParticleAdvector()
  : OFB(nullptr)
  , LookupTable(nullptr)
  , Integrator(RK4)
  , StepSize(1.0)
  , ErrorTolerance(1e-3)
  , NormalizeVectors(true)
  , Direction(FORWARD)
  , StepsPerUpdate(1)
  , Lifetime(0)
  , NumberOfParticles(1000)
  , RandomSeed(0)
  , MaximumSeedDistance(10.0)
  , ChainLength(1)
  , ChainSpacing(1)
  , ColorMode(COLOR_CONSTANT)
  , Color{ 1.0, 0.0, 0.0 }
  , FootprintRadius(2.5)
  , Brush(vtkSmartPointer<vtkOFBBrush>::New())
  , Paint(true)
  , ColorPeriod(60)
  , SeedColorArrayName(nullptr)
  , ScalarArrayName(nullptr)
  , TrailLength(16)
  , MemoryLimit(4096)
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(3);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
  this->Brush->SetFalloffToConstant();
  this->Internals->Painter = vtkSmartPointer<vtkOFBPainter>::New();
  this->Internals->Painter->SetUndoLimit(0);
  this->Internals->Footprints = vtkSmartPointer<vtkPolyData>::New();
  this->Internals->Footprints->SetPoints(this->Internals->Arrays.DabPoints);
}

//------------------------------------------------------------------------------
vtkOFBParticleAdvector::~vtkOFBParticleAdvector()
{
  this->SetOFB(nullptr);
  this->SetLookupTable(nullptr);
  this->SetSeedColorArrayName(nullptr);
  this->SetScalarArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::SetOFB(vtkOFB* ofb)
{
  if (this->OFB == ofb)
  {
    return;
  }
  vtkOFB* old = this->OFB;
  this->OFB = ofb;
  if (ofb)
  {
    ofb->Register(this);
  }
  if (old)
  {
    old->UnRegister(this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::SetBrush(vtkOFBBrush* brush)
{
  if (this->Brush != brush)
  {
    this->Brush = brush;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFBBrush* vtkOFBParticleAdvector::GetBrush() const
{
  return this->Brush;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBParticleAdvector::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  return this->Brush ? std::max(t, this->Brush->GetMTime()) : t;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::SetInputData(vtkDataObject* surface)
{
  this->SetInputDataInternal(0, surface);
}

void vtkOFBParticleAdvector::SetInputData(int port, vtkDataObject* input)
{
  this->SetInputDataInternal(port, input);
}

void vtkOFBParticleAdvector::SetOFBData(vtkOFB* ofb)
{
  this->SetInputDataInternal(1, ofb);
}

void vtkOFBParticleAdvector::SetOFBConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkOFBParticleAdvector::SetSourceData(vtkPolyData* seeds)
{
  this->SetInputDataInternal(2, seeds);
}

void vtkOFBParticleAdvector::SetSourceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(2, output);
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBParticleAdvector::GetOutput()
{
  return vtkOFB::SafeDownCast(this->GetOutputDataObject(0));
}

vtkDataObject* vtkOFBParticleAdvector::GetOutput(int port)
{
  return this->GetOutputDataObject(port);
}

vtkPolyData* vtkOFBParticleAdvector::GetParticles()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkPolyData* vtkOFBParticleAdvector::GetTrails()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

vtkPolyData* vtkOFBParticleAdvector::GetFootprints()
{
  return this->Internals->Footprints;
}

vtkIdType vtkOFBParticleAdvector::GetCurrentStep() const
{
  return this->Internals->System.CurrentStep;
}

double vtkOFBParticleAdvector::GetCellSize() const
{
  return this->Internals->CellSize;
}

double vtkOFBParticleAdvector::GetLastAdvectionTime() const
{
  return this->Internals->AdvectionTime;
}

double vtkOFBParticleAdvector::GetLastPaintingTime() const
{
  return this->Internals->PaintingTime;
}

double vtkOFBParticleAdvector::GetLastOutputTime() const
{
  return this->Internals->OutputTime;
}

const char* vtkOFBParticleAdvector::GetColorModeAsString(int mode)
{
  switch (mode)
  {
    case COLOR_CONSTANT:
      return "Constant";
    case COLOR_FROM_SEEDS:
      return "FromSeeds";
    case COLOR_BY_SCALAR:
      return "ByScalar";
    case COLOR_PERIODIC:
      return "Periodic";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::Step()
{
  this->Internals->PendingSteps += this->StepsPerUpdate;
  // A time request left by an earlier update would take precedence otherwise.
  for (int i = 0; i < this->GetNumberOfOutputPorts(); ++i)
  {
    this->GetOutputInformation(i)->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  this->Modified();
  this->Update();
}

void vtkOFBParticleAdvector::Reset()
{
  this->Internals->ResetRequested = true;
  this->Internals->PendingSteps = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkOFBParticleAdvector::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  else if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkOFBParticleAdvector::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkOFB" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkOFBParticleAdvector::ProcessRequest(vtkInformation* request,
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
    return this->RequestData(request, inInfo, outInfo);
  }
  return this->Superclass::ProcessRequest(request, inInfo, outInfo);
}

int vtkOFBParticleAdvector::RequestDataObject(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outInfo)
{
  for (int i = 0; i < 3; ++i)
  {
    vtkInformation* info = outInfo->GetInformationObject(i);
    vtkDataObject* current = info->Get(vtkDataObject::DATA_OBJECT());
    if (i == 0 ? vtkOFB::SafeDownCast(current) != nullptr
               : vtkPolyData::SafeDownCast(current) != nullptr)
    {
      continue;
    }
    vtkSmartPointer<vtkDataObject> output;
    if (i == 0)
    {
      output = vtkSmartPointer<vtkOFB>::New();
    }
    else
    {
      output = vtkSmartPointer<vtkPolyData>::New();
    }
    info->Set(vtkDataObject::DATA_OBJECT(), output);
  }
  return 1;
}

int vtkOFBParticleAdvector::RequestInformation(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  if (this->IsUnsteady(inInfo))
  {
    // Pathlines: the time of the unsteady input (its steps and range).
    vtkInformation* source = inInfo[0]->GetInformationObject(0);
    for (int i = 0; i < 3; ++i)
    {
      vtkInformation* info = outInfo->GetInformationObject(i);
      info->CopyEntry(source, vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      info->CopyEntry(source, vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    }
    return 1;
  }
  // Time is the number of steps from the seeds, open-ended. Without a time range
  // the pipeline would not execute again for a new time request.
  const double range[2] = { 0.0, static_cast<double>(VTK_INT_MAX) };
  for (int i = 0; i < 3; ++i)
  {
    vtkInformation* info = outInfo->GetInformationObject(i);
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBParticleAdvector::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  for (int i = 0; i < 3; ++i)
  {
    vtkDataObject::GetData(outputVector, i)->Initialize();
  }
  vtkDataSet* seeds = inputVector[2]->GetNumberOfInformationObjects() > 0
    ? vtkDataSet::GetData(inputVector[2], 0)
    : nullptr;
  bool restart = false;
  vtkIdType target = 0;
  if (!this->PrepareUpdate(request, inputVector, seeds, restart) ||
    !this->PlanSteps(request, inputVector, outputVector, seeds, restart, target))
  {
    return 1;
  }
  this->PrepareColoring(vtkPolyData::GetData(inputVector[0], 0));
  this->AdvanceTo(target);
  this->WriteOutputs(outputVector);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::StopParticles()
{
  vtkInternals& in = *this->Internals;
  in.Started = false;
  this->ClearFootprints();
  in.PendingSteps = 0;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::PrepareUpdate(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkDataSet* seeds,
  bool& restart)
{
  // The surface, its field and the OFB; the particles started again when what places or
  // moves them changed (on every process when one does).
  vtkInternals& in = *this->Internals;
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0], 0);
  vtkOFB* inputOFB = inputVector[1]->GetNumberOfInformationObjects() > 0
    ? vtkOFB::GetData(inputVector[1], 0)
    : nullptr;
  const bool unsteady = this->IsUnsteady(inputVector);
  if (unsteady != in.Unsteady)
  {
    in.Unsteady = unsteady;
    in.SurfaceObject = nullptr; // rebuilt: restart
  }
  bool rebuilt = false;
  if (!this->CheckSettings() || !this->PrepareSurface(surface, inputVector, rebuilt))
  {
    this->StopParticles();
    in.SurfaceObject = nullptr;
    return false;
  }
  const bool targetChanged = this->PrepareOFB(inputOFB, surface);
  if (this->Exchange && this->AskForDeeperGhostCells(request, inputVector, true))
  {
    return false; // executes again on deeper ghost cells, with no output this time
  }
  const bool settingsChanged = this->NeedsRestart(seeds); // always: it records them
  restart = settingsChanged || rebuilt || targetChanged;
  if (this->Exchange)
  {
    // Every process starts again when one does (see ParticipateWithoutPiece).
    restart = this->Exchange->AllReduceMaximum(restart ? 1.0 : 0.0) > 0.0;
  }
  if (restart && !this->StartParticles(seeds))
  {
    this->StopParticles();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::PlanSteps(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector,
  vtkDataSet* seeds,
  bool restart,
  vtkIdType& target)
{
  // How far to go: the steps asked for by Step(), else the requested time.
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  target = system.CurrentStep;
  if (in.Unsteady)
  {
    if (!this->PlanPathlineSteps(request, inputVector, outputVector, seeds, restart))
    {
      this->StopParticles();
      return false;
    }
    target = system.CurrentStep + this->PlanUnsteadySteps(in.Goal);
  }
  else if (in.PendingSteps > 0)
  {
    target += in.PendingSteps;
  }
  else
  {
    target = vtkOFBParticleAdvector::RequestedStep(outputVector, target);
    if (target < system.CurrentStep && !this->StartParticles(seeds))
    {
      this->StopParticles();
      return false;
    }
  }
  in.PendingSteps = 0;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::PlanPathlineSteps(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector,
  vtkDataSet* seeds,
  bool restart)
{
  // Pathlines: from the particles' time to the requested one (time backwards: a
  // restart there); Step() has no effect.
  vtkInternals& in = *this->Internals;
  // Without a request, the unsteady input's time.
  const double requested = vtkOFBParticleAdvector::RequestedTime(outputVector, in.TimeNew);
  if (!std::isfinite(requested))
  {
    vtkErrorMacro("The requested time is not finite: no particles.");
    return false;
  }
  bool back = !restart && requested < in.ParticleTime;
  if (this->Exchange)
  {
    // Told to a process whose piece is empty (ParticipateWithoutPiece).
    back = this->Exchange->AllReduceMaximum(back ? 1.0 : 0.0) > 0.0;
  }
  if (back && !this->StartParticles(seeds))
  {
    return false;
  }
  if (restart || back)
  {
    // From the seeds at the requested time, with the field of the step just read.
    in.ParticleTime = requested;
    in.FieldOld = in.FieldNew;
    in.TimeOld = in.TimeNew;
    in.SpeedOld = in.SpeedNew;
  }
  // One input step at a time: up to the step just read when the requested time is
  // beyond it and the input has more, and then again (CONTINUE_EXECUTING, as
  // vtkParticleTracer does) with the next one.
  in.Goal = requested;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  const double* steps = inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const int numSteps = inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  if (in.TimeNew < requested && in.TimeNew > in.ParticleTime &&
    std::upper_bound(steps, steps + numSteps, in.TimeNew) != steps + numSteps)
  {
    in.Goal = in.TimeNew;
  }
  if (this->Exchange)
  {
    // The plan, the same on every process with a piece, told to one without.
    std::vector<double> plan = { in.Goal, in.TimeNew };
    this->Exchange->AllReduceMinimum(plan);
  }
  if (in.Goal < requested)
  {
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
  }
  else
  {
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::AdvanceTo(vtkIdType target)
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  const vtkIdType first = system.CurrentStep;
  if (this->Exchange)
  {
    // The same number of steps (and exchanges) on every process.
    target = first +
      static_cast<vtkIdType>(this->Exchange->AllReduceMaximum(static_cast<double>(target - first)));
  }
  // Without painting, only the last step's footprints are kept: the steps go in
  // chunks (each batch of particles makes a chunk's steps in a row), about 20 per
  // update.
  const bool painting = in.Target && this->Paint && this->FootprintRadius > 0.0;
  // A distributed run exchanges the particles after every step.
  const vtkIdType chunk =
    painting || in.Unsteady || this->Exchange ? 1 : std::max<vtkIdType>(1, (target - first) / 20);
  system.Active = this->Exchange && !in.Owned.empty() ? in.Owned.data() : nullptr;
  in.AdvectionTime = 0.0;
  in.PaintingTime = 0.0;
  for (vtkIdType step = first; step < target;)
  {
    const vtkIdType count = std::min(chunk, target - step);
    const auto start = Clock::now();
    if (in.Unsteady)
    {
      this->PrepareUnsteadyStep(step - first);
    }
    system.Advance(in.Coloring, count);
    if (this->Exchange)
    {
      this->ExchangeParticles();
    }
    const auto moved = Clock::now();
    in.AdvectionTime += Milliseconds(moved - start);
    step += count;
    if (painting || step == target)
    {
      this->PaintFootprints();
      in.PaintingTime += Milliseconds(Clock::now() - moved);
    }
    if (target - first > 1)
    {
      this->UpdateProgress(static_cast<double>(step - first) / (target - first));
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::WriteOutputs(vtkInformationVector* outputVector)
{
  vtkInternals& in = *this->Internals;
  const auto outputStart = Clock::now();
  if (in.Target)
  {
    vtkOFB::GetData(outputVector, 0)->ShallowCopy(in.Target);
  }
  this->FillParticles(vtkPolyData::GetData(outputVector, 1));
  this->FillTrails(vtkPolyData::GetData(outputVector, 2));
  in.OutputTime = Milliseconds(Clock::now() - outputStart);
  if (in.Unsteady)
  {
    in.ParticleTime = in.Goal;
  }
  const double time = in.Unsteady ? in.ParticleTime : static_cast<double>(in.System.CurrentStep);
  for (int i = 0; i < 3; ++i)
  {
    vtkDataObject* output = vtkDataObject::GetData(outputVector, i);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  }
}

//------------------------------------------------------------------------------
double vtkOFBParticleAdvector::RequestedTime(vtkInformationVector* outputVector, double otherwise)
{
  for (int i = 0; i < outputVector->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* info = outputVector->GetInformationObject(i);
    if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      return info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    }
  }
  return otherwise;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBParticleAdvector::RequestedStep(vtkInformationVector* outputVector,
  vtkIdType otherwise)
{
  // The first output that has a time request: its time in whole steps (a time of
  // steady particles is their number of steps from the seeds).
  for (int i = 0; i < 3; ++i)
  {
    vtkInformation* info = outputVector->GetInformationObject(i);
    if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      const double t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      // Clamped before the conversion, which overflows (undefined) beyond 2^63.
      return std::isfinite(t) && t > 0.0
        ? static_cast<vtkIdType>(std::min(std::floor(t + 1e-9), 9.0e18))
        : 0;
    }
  }
  return otherwise;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* integrators[] = { "Euler", "RK2", "RK4", "RK45" };
  os << indent << "OFB: " << this->OFB << "\n";
  os << indent << "Integrator: " << integrators[this->Integrator] << "\n";
  os << indent << "StepSize: " << this->StepSize << " cells\n";
  os << indent << "ErrorTolerance: " << this->ErrorTolerance << " cells\n";
  os << indent << "NormalizeVectors: " << (this->NormalizeVectors ? "On" : "Off") << "\n";
  os << indent << "Direction: " << (this->Direction == FORWARD ? "Forward" : "Backward") << "\n";
  os << indent << "StepsPerUpdate: " << this->StepsPerUpdate << "\n";
  os << indent << "Lifetime: " << this->Lifetime << " steps\n";
  os << indent << "NumberOfParticles: " << this->NumberOfParticles << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "MaximumSeedDistance: " << this->MaximumSeedDistance << " cells\n";
  os << indent << "ChainLength: " << this->ChainLength << "\n";
  os << indent << "ChainSpacing: " << this->ChainSpacing << " steps\n";
  os << indent << "ColorMode: " << GetColorModeAsString(this->ColorMode) << "\n";
  os << indent << "Color: " << this->Color[0] << " " << this->Color[1] << " " << this->Color[2]
     << "\n";
  os << indent << "FootprintRadius: " << this->FootprintRadius << " cells\n";
  os << indent << "Brush: " << this->Brush.GetPointer() << "\n";
  if (this->Brush)
  {
    this->Brush->PrintSelf(os, indent.GetNextIndent());
  }
  os << indent << "Paint: " << (this->Paint ? "On" : "Off") << "\n";
  os << indent << "ColorPeriod: " << this->ColorPeriod << " steps\n";
  os << indent
     << "SeedColorArrayName: " << (this->SeedColorArrayName ? this->SeedColorArrayName : "(none)")
     << "\n";
  os << indent << "ScalarArrayName: " << (this->ScalarArrayName ? this->ScalarArrayName : "(none)")
     << "\n";
  os << indent << "LookupTable: " << this->LookupTable << "\n";
  os << indent << "TrailLength: " << this->TrailLength << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "CurrentStep: " << this->GetCurrentStep() << "\n";
  os << indent << "LastAdvectionTime: " << this->GetLastAdvectionTime() << " ms\n";
  os << indent << "LastPaintingTime: " << this->GetLastPaintingTime() << " ms\n";
  os << indent << "LastOutputTime: " << this->GetLastOutputTime() << " ms\n";
}
