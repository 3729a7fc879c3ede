// vtkOFBParticleAdvector's pathlines through an unsteady field (an input that reports
// TIME_STEPS): the two time steps around the particles' time, interpolated linearly
// in time, as vtkParticleTracer does.
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleAdvectorInternals.h"
#include "vtkOFBParticleExchange.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace
{
/// A 64-bit FNV-1a hash of the values of an array (through doubles for any layout).
uint64_t HashValues(vtkDataArray* array, uint64_t h)
{
  if (!array)
  {
    return h;
  }
  const vtkIdType n = array->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = array->GetComponent(
      i / array->GetNumberOfComponents(), static_cast<int>(i % array->GetNumberOfComponents()));
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof(bits));
    h = (h ^ bits) * 0x100000001b3ULL;
  }
  return h ^ static_cast<uint64_t>(n);
}
}

//------------------------------------------------------------------------------
uint64_t vtkOFBParticleAdvector::HashGeometry(vtkPolyData* surface)
{
  uint64_t h = 0xcbf29ce484222325ULL;
  h = HashValues(surface->GetPoints() ? surface->GetPoints()->GetData() : nullptr, h);
  h = HashValues(surface->GetPolys()->GetOffsetsArray(), h);
  h = HashValues(surface->GetPolys()->GetConnectivityArray(), h);
  h = HashValues(surface->GetStrips()->GetOffsetsArray(), h);
  h = HashValues(surface->GetStrips()->GetConnectivityArray(), h);
  return h;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::KeepField(vtkPolyData* surface, vtkDataArray* vectors, bool rebuilt)
{
  vtkInternals& in = *this->Internals;
  const double time = surface->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP())
    ? surface->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP())
    : 0.0;
  const vtkIdType n = in.FieldPerCell ? surface->GetNumberOfCells() : surface->GetNumberOfPoints();
  std::vector<double> field(3 * static_cast<size_t>(n));
  double largest = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    vectors->GetTuple(i, &field[3 * i]);
    const double* v = &field[3 * i];
    largest = std::max(largest, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  if (rebuilt || in.FieldNew.size() != field.size())
  {
    in.FieldOld = field;
    in.TimeOld = time;
    in.SpeedOld = std::sqrt(largest);
  }
  else if (time != in.TimeNew)
  {
    // The next step: the newer field becomes the older one.
    in.FieldOld.swap(in.FieldNew);
    in.TimeOld = in.TimeNew;
    in.SpeedOld = in.SpeedNew;
  }
  in.FieldNew.swap(field);
  in.TimeNew = time;
  in.SpeedNew = std::sqrt(largest);
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::IsUnsteady(vtkInformationVector** inputVector) const
{
  vtkInformation* info = inputVector[0]->GetInformationObject(0);
  return info && info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) &&
    info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) > 0;
}

//------------------------------------------------------------------------------
int vtkOFBParticleAdvector::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // An unsteady input is asked for the time step at or after the requested time
  // (the upper one of the two around it; the lower one is kept from the update
  // before), clamped to its range.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (!inInfo || !this->IsUnsteady(inputVector))
  {
    return 1;
  }
  const double t = vtkOFBParticleAdvector::RequestedTime(outputVector, 0.0);
  const double* steps = inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const int n = inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* upper = std::lower_bound(steps, steps + n, std::isfinite(t) ? t : steps[0]);
  const vtkInternals& in = *this->Internals;
  if (in.Started && in.Unsteady && std::isfinite(t) && t > in.TimeNew &&
    in.ParticleTime <= in.TimeNew)
  {
    // Going on forward: the step after the newest one read, one step at a time
    // (RequestData continues executing until the requested time).
    const double* next = std::upper_bound(steps, steps + n, in.TimeNew);
    upper = std::min(upper, next);
  }
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(),
    upper == steps + n ? steps[n - 1] : *upper);
  return 1;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBParticleAdvector::PlanUnsteadySteps(double time)
{
  // Steps of at most StepSize cells for the fastest point of either field: of the whole
  // surface in a distributed run, so that every process steps the same durations.
  vtkInternals& in = *this->Internals;
  const double span = time - in.ParticleTime;
  double speed = std::max(in.SpeedOld, in.SpeedNew);
  if (this->Exchange)
  {
    speed = this->Exchange->AllReduceMaximum(speed);
  }
  in.StepSpeed = speed;
  if (!(span > 0.0) || !(speed > 0.0))
  {
    in.StepDuration = 0.0;
    return 0;
  }
  const double longest = this->StepSize * in.CellSize / speed;
  const double steps = std::min(std::ceil(span / longest - 1e-9), 1e7);
  const auto n = std::max<vtkIdType>(1, static_cast<vtkIdType>(steps));
  in.StepDuration = span / static_cast<double>(n);
  return n;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::PrepareUnsteadyStep(vtkIdType k)
{
  // The field at the middle of step k, linear in time between the two steps around
  // it (held constant outside them), and the stepper moving by field x duration.
  vtkInternals& in = *this->Internals;
  const double t = in.ParticleTime + (static_cast<double>(k) + 0.5) * in.StepDuration;
  const double gap = in.TimeNew - in.TimeOld;
  const double w = gap > 0.0 ? std::min(1.0, std::max(0.0, (t - in.TimeOld) / gap)) : 1.0;
  in.Blend.resize(in.FieldNew.size());
  for (size_t i = 0; i < in.Blend.size(); ++i)
  {
    in.Blend[i] = (1.0 - w) * in.FieldOld[i] + w * in.FieldNew[i];
  }
  if (in.FieldPerCell)
  {
    in.Walker.SetCellVectors(in.Blend.data());
  }
  else
  {
    in.Walker.SetPointVectors(in.Blend.data());
  }
  vtkOFBParticleStepper& stepper = in.System.Stepper;
  stepper.Normalize = false;
  stepper.Scale = 1.0;
  stepper.Length = in.StepDuration;
  stepper.StopSpeed = 1e-12 * in.StepSpeed;
}
