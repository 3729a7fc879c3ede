#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleAdvectorInternals.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellDataToPointData.h"
#include "vtkDataSetAttributes.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLookupTable.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkOFBParticleAdvector);

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::duration d)
{
  return std::chrono::duration<double>(d).count();
}

// When the content of a data set last changed: its points, cells and point data
// (not the data object's own time, which the pipeline's requests move on).
vtkMTimeType ContentTime(vtkDataSet* data)
{
  vtkMTimeType t = data->GetPointData()->GetMTime();
  if (auto* points =
        data->IsA("vtkPointSet") ? static_cast<vtkPointSet*>(data)->GetPoints() : nullptr)
  {
    t = std::max(t, points->GetMTime());
  }
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    for (vtkCellArray* cells :
      { poly->GetVerts(), poly->GetLines(), poly->GetPolys(), poly->GetStrips() })
    {
      t = cells ? std::max(t, cells->GetMTime()) : t;
    }
  }
  return t;
}

vtkMTimeType ContentTime(vtkOFB* ofb)
{
  return std::max({ ofb->GetStructureMTime(),
    ofb->GetSampleData()->GetMTime(),
    ofb->GetCellOffsets()->GetMTime() });
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
  , Opacity(1.0)
  , FootprintRadius(2.5)
  , Falloff(vtkOFBBrush::Constant)
  , BlendMode(vtkOFBBrush::Mix)
  , SmearAmount(0.0)
  , Paint(true)
  , ColorPeriod(60)
  , SeedColorArrayName(nullptr)
  , ScalarArrayName(nullptr)
  , TrailLength(16)
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(3);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
  this->Internals->Painter = vtkSmartPointer<vtkOFBPainter>::New();
  this->Internals->Brush = vtkSmartPointer<vtkOFBBrush>::New();
  this->Internals->Painter->SetBrush(this->Internals->Brush);
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
void vtkOFBParticleAdvector::SetInputData(vtkDataObject* surface)
{
  this->SetInputDataInternal(0, surface);
}

void vtkOFBParticleAdvector::SetOFBInputData(vtkOFB* ofb)
{
  this->SetInputDataInternal(1, ofb);
}

void vtkOFBParticleAdvector::SetOFBInputConnection(vtkAlgorithmOutput* output)
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
  vtkInformationVector**,
  vtkInformationVector* outInfo)
{
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
int vtkOFBParticleAdvector::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInternals& in = *this->Internals;
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0], 0);
  vtkOFB* inputOFB = inputVector[1]->GetNumberOfInformationObjects() > 0
    ? vtkOFB::GetData(inputVector[1], 0)
    : nullptr;
  vtkDataSet* seeds = inputVector[2]->GetNumberOfInformationObjects() > 0
    ? vtkDataSet::GetData(inputVector[2], 0)
    : nullptr;
  vtkOFB* outOFB = vtkOFB::GetData(outputVector, 0);
  vtkPolyData* outParticles = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* outTrails = vtkPolyData::GetData(outputVector, 2);
  outOFB->Initialize();
  outParticles->Initialize();
  outTrails->Initialize();

  bool rebuilt = false;
  if (!this->CheckSettings() || !this->PrepareSurface(surface, inputVector, rebuilt))
  {
    in.Started = false;
    this->ClearFootprints();
    in.SurfaceObject = nullptr;
    in.PendingSteps = 0;
    return 1;
  }
  const bool targetChanged = this->PrepareOFB(inputOFB, surface);
  const bool settingsChanged = this->NeedsRestart(seeds); // always: it records them
  const bool restart = settingsChanged || rebuilt || targetChanged;
  if (restart)
  {
    this->StartParticles(seeds);
  }

  // How far to go: the steps asked for by Step(), else the requested time.
  vtkOFBParticleSystem& system = in.System;
  vtkIdType target = system.CurrentStep;
  if (in.PendingSteps > 0)
  {
    target += in.PendingSteps;
  }
  else
  {
    for (int i = 0; i < 3; ++i)
    {
      vtkInformation* info = outputVector->GetInformationObject(i);
      if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
      {
        const double t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
        target = std::isfinite(t) && t > 0.0 ? static_cast<vtkIdType>(std::floor(t + 1e-9)) : 0;
        break;
      }
    }
    if (target < system.CurrentStep)
    {
      this->StartParticles(seeds);
    }
  }
  in.PendingSteps = 0;

  this->PrepareColoring(surface);
  const vtkIdType first = system.CurrentStep;
  // Without painting, only the last step's footprints are kept: the steps go in
  // chunks (each batch of particles makes a chunk's steps in a row), about 20 per
  // update.
  const bool painting = in.Target && this->Paint && this->FootprintRadius > 0.0;
  const vtkIdType chunk = painting ? 1 : std::max<vtkIdType>(1, (target - first) / 20);
  in.AdvectionTime = 0.0;
  in.PaintingTime = 0.0;
  for (vtkIdType step = first; step < target;)
  {
    const vtkIdType count = std::min(chunk, target - step);
    const auto start = Clock::now();
    system.Advance(in.Coloring, count);
    const auto moved = Clock::now();
    in.AdvectionTime += Seconds(moved - start);
    step += count;
    if (painting || step == target)
    {
      this->PaintFootprints();
      in.PaintingTime += Seconds(Clock::now() - moved);
    }
    if (target - first > 1)
    {
      this->UpdateProgress(static_cast<double>(step - first) / (target - first));
    }
  }

  const auto outputStart = Clock::now();
  if (in.Target)
  {
    outOFB->ShallowCopy(in.Target);
  }
  this->FillParticles(outParticles);
  this->FillTrails(outTrails);
  in.OutputTime = Seconds(Clock::now() - outputStart);
  const double time = static_cast<double>(system.CurrentStep);
  for (int i = 0; i < 3; ++i)
  {
    vtkDataObject* output = vtkDataObject::GetData(outputVector, i);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::CheckSettings()
{
  if (!(this->StepSize > 0.0) || !std::isfinite(this->StepSize))
  {
    vtkErrorMacro("StepSize must be positive and finite (cells), not " << this->StepSize << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::PrepareSurface(vtkPolyData* surface,
  vtkInformationVector** inputVector,
  bool& rebuilt)
{
  vtkInternals& in = *this->Internals;
  if (!surface || surface->GetNumberOfPoints() == 0 ||
    surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input surface has no polygons: no particles.");
    return false;
  }
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* vectors = this->GetInputArrayToProcess(0, inputVector, association);
  if (!vectors && surface->GetCellData()->GetVectors() && !surface->GetPointData()->GetVectors())
  {
    vectors = surface->GetCellData()->GetVectors();
    association = vtkDataObject::FIELD_ASSOCIATION_CELLS;
  }
  if (!vectors)
  {
    vtkErrorMacro("The input surface has no vector field (the array chosen with "
                  "SetInputArrayToProcess, by default the active point vectors).");
    return false;
  }
  if (vectors->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The vector field '" << (vectors->GetName() ? vectors->GetName() : "") << "' has "
                                       << vectors->GetNumberOfComponents()
                                       << " components, not 3.");
    return false;
  }
  if (surface == in.SurfaceObject && ContentTime(surface) == in.SurfaceTime &&
    vectors == in.VectorArray && vectors->GetMTime() == in.VectorTime)
  {
    return true;
  }

  // Cell vectors: averaged to the points.
  vtkSmartPointer<vtkDataArray> pointVectors = vectors;
  if (association == vtkDataObject::FIELD_ASSOCIATION_CELLS)
  {
    vtkWarningMacro("The vector field is given on cells: it is averaged to the points.");
    vtkNew<vtkPolyData> cells;
    cells->CopyStructure(surface);
    vtkSmartPointer<vtkDataArray> named = vectors;
    if (!vectors->GetName())
    {
      named.TakeReference(vectors->NewInstance());
      named->ShallowCopy(vectors);
      named->SetName("Vectors");
    }
    cells->GetCellData()->AddArray(named);
    vtkNew<vtkCellDataToPointData> toPoints;
    toPoints->SetInputData(cells);
    toPoints->Update();
    pointVectors = toPoints->GetOutput()->GetPointData()->GetArray(named->GetName());
  }
  else if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("The vector field must be a point or cell array.");
    return false;
  }
  const vtkIdType numPoints = surface->GetNumberOfPoints();
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double v[3];
    pointVectors->GetTuple(i, v);
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    {
      vtkErrorMacro("The vector field has a non-finite value at point " << i << ".");
      return false;
    }
  }

  vtkSmartPointer<vtkPolyData> triangles = surface;
  if (surface->GetNumberOfStrips() > 0 || surface->GetPolys()->IsHomogeneous() != 3)
  {
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->SetInputData(surface);
    triangulate->Update();
    triangles = triangulate->GetOutput();
  }
  std::string error;
  if (!in.Walker.Build(triangles, pointVectors, error))
  {
    vtkErrorMacro("The input surface cannot carry particles: " << error << ".");
    return false;
  }
  if (!(in.Walker.GetMaximumSpeed() > 0.0))
  {
    vtkErrorMacro("The vector field is zero everywhere: no particle can move.");
    return false;
  }
  in.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  in.Locator->SetDataSet(in.Walker.GetTriangles());
  in.Locator->BuildLocator();
  in.Surface = triangles;
  in.SurfaceObject = surface;
  in.SurfaceTime = ContentTime(surface);
  in.VectorArray = vectors;
  in.VectorTime = vectors->GetMTime();
  rebuilt = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::PrepareOFB(vtkOFB* inputOFB, vtkPolyData* surface)
{
  vtkInternals& in = *this->Internals;
  if (this->OFB)
  {
    in.Target = this->OFB;
  }
  else if (inputOFB)
  {
    if (!in.Copy || inputOFB != in.OFBObject || ContentTime(inputOFB) != in.OFBTime)
    {
      in.Copy = vtkSmartPointer<vtkOFB>::New();
      in.Copy->DeepCopy(inputOFB);
      in.OFBObject = inputOFB;
      in.OFBTime = ContentTime(inputOFB);
      in.LastTarget = nullptr; // a new copy: restart
    }
    in.Target = in.Copy;
  }
  else
  {
    in.Copy = nullptr;
    in.OFBObject = nullptr;
    in.Target = nullptr;
  }
  if (in.Target && in.Target->GetCellSize() > 0.0)
  {
    in.CellSize = in.Target->GetCellSize();
  }
  else
  {
    double bounds[6];
    surface->GetBounds(bounds);
    const double longest =
      std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
    in.CellSize = longest > 0.0 ? longest / 1024.0 : 1.0;
  }
  const bool changed = in.Target != in.LastTarget || in.CellSize != in.LastCellSize;
  in.LastTarget = in.Target;
  in.LastCellSize = in.CellSize;
  return changed;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::NeedsRestart(vtkDataSet* seeds)
{
  vtkInternals& in = *this->Internals;
  const vtkOFBParticleMotionKey key{ this->Integrator,
    this->StepSize,
    this->ErrorTolerance,
    this->NormalizeVectors,
    this->Direction,
    this->Lifetime,
    this->NumberOfParticles,
    this->RandomSeed,
    this->MaximumSeedDistance,
    this->ChainLength,
    this->ChainSpacing,
    this->TrailLength,
    this->SeedColorArrayName ? this->SeedColorArrayName : "" };
  const bool restart = !in.Started || in.ResetRequested || !(key == in.Motion) ||
    seeds != in.SeedObject || (seeds && ContentTime(seeds) != in.SeedTime);
  in.Motion = key;
  return restart;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::StartParticles(vtkDataSet* seeds)
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  system.Walker = &in.Walker;
  vtkOFBParticleStepper& stepper = system.Stepper;
  stepper.Walker = &in.Walker;
  stepper.Integrator = this->Integrator;
  stepper.Normalize = this->NormalizeVectors;
  stepper.Sign = this->Direction == BACKWARD ? -1.0 : 1.0;
  stepper.Scale = 1.0 / in.Walker.GetMaximumSpeed();
  stepper.StopSpeed = 1e-12 * in.Walker.GetMaximumSpeed();
  stepper.Length = this->StepSize * in.CellSize;
  stepper.Tolerance = this->ErrorTolerance * in.CellSize;
  system.Setup.ChainLength = this->ChainLength;
  system.Setup.ChainSpacing = this->ChainSpacing;
  system.Setup.Lifetime = this->Lifetime;
  system.Setup.TrailLength = this->TrailLength;
  system.Setup.RandomSeed = this->RandomSeed;
  system.Setup.RandomSeeds = seeds == nullptr;
  if (seeds)
  {
    this->LocateSeeds(seeds);
  }
  else
  {
    system.MakeRandomSeeds(this->NumberOfParticles);
    for (size_t i = 0; i < system.Seeds.size(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        system.SeedColors[4 * i + c] = static_cast<float>(this->Color[c]);
      }
    }
  }
  system.Start();
  in.Started = true;
  in.ResetRequested = false;
  in.SeedObject = seeds;
  in.SeedTime = seeds ? ContentTime(seeds) : 0;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::LocateSeeds(vtkDataSet* seeds)
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  system.Seeds.clear();
  system.SeedColors.clear();
  vtkDataArray* colors = this->SeedColorArrayName
    ? seeds->GetPointData()->GetArray(this->SeedColorArrayName)
    : seeds->GetPointData()->GetScalars();
  if (this->ColorMode == COLOR_FROM_SEEDS && !colors)
  {
    vtkWarningMacro("No seed colour array '"
      << (this->SeedColorArrayName ? this->SeedColorArrayName : "(active scalars)")
      << "': the seeds take the constant colour.");
  }
  const double radius = this->MaximumSeedDistance * in.CellSize;
  vtkIdType nonFinite = 0;
  vtkIdType far = 0;
  for (vtkIdType i = 0; i < seeds->GetNumberOfPoints(); ++i)
  {
    double x[3];
    seeds->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      ++nonFinite;
      continue;
    }
    double closest[3];
    vtkIdType cell = -1;
    int subId = 0;
    double dist2 = 0.0;
    if (!in.Locator->FindClosestPointWithinRadius(x, radius, closest, cell, subId, dist2) ||
      cell < 0)
    {
      ++far;
      continue;
    }
    system.Seeds.push_back(in.Walker.Locate(cell, closest));
    float rgba[4] = { static_cast<float>(this->Color[0]),
      static_cast<float>(this->Color[1]),
      static_cast<float>(this->Color[2]),
      1.f };
    if (colors)
    {
      const int n = colors->GetNumberOfComponents();
      const double scale = colors->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
      float c[4];
      for (int k = 0; k < std::min(n, 4); ++k)
      {
        c[k] = static_cast<float>(std::min(1.0, std::max(0.0, scale * colors->GetComponent(i, k))));
      }
      rgba[0] = c[0];
      rgba[1] = n >= 3 ? c[1] : c[0];
      rgba[2] = n >= 3 ? c[2] : c[0];
      rgba[3] = n == 4 ? c[3] : (n == 2 ? c[1] : 1.f);
    }
    system.SeedColors.insert(system.SeedColors.end(), rgba, rgba + 4);
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite << " seed point(s) with non-finite coordinates rejected.");
  }
  if (far > 0)
  {
    vtkWarningMacro(<< far << " seed point(s) farther than MaximumSeedDistance ("
                    << this->MaximumSeedDistance << " cells) from the surface rejected.");
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::PrepareColoring(vtkPolyData* surface)
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem::Coloring& coloring = in.Coloring;
  coloring.Mode = this->ColorMode;
  coloring.Period = this->ColorPeriod;
  for (int c = 0; c < 3; ++c)
  {
    coloring.Constant[c] = static_cast<float>(this->Color[c]);
  }
  coloring.Scalars = nullptr;
  coloring.Table.clear();
  if (this->ColorMode != COLOR_BY_SCALAR)
  {
    return;
  }
  vtkDataArray* scalars = this->ScalarArrayName
    ? surface->GetPointData()->GetArray(this->ScalarArrayName)
    : surface->GetPointData()->GetScalars();
  if (!scalars)
  {
    vtkWarningMacro("No surface point array '"
      << (this->ScalarArrayName ? this->ScalarArrayName : "(active scalars)")
      << "' to colour by: the particles keep their colour.");
    return;
  }
  vtkSmartPointer<vtkScalarsToColors> lut = this->LookupTable;
  if (!lut)
  {
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetHueRange(0.667, 0.0);
    table->SetRange(scalars->GetRange(0));
    table->Build();
    lut = table;
  }
  const double* range = lut->GetRange();
  coloring.Range[0] = range[0];
  coloring.Range[1] = range[1];
  // A table of the map, so that the parallel step reads it without calling VTK.
  const int size = 1024;
  coloring.Table.resize(3 * size);
  for (int k = 0; k < size; ++k)
  {
    double rgb[3];
    lut->GetColor(range[0] + (k + 0.5) / size * (range[1] - range[0]), rgb);
    for (int c = 0; c < 3; ++c)
    {
      coloring.Table[3 * k + c] = static_cast<float>(rgb[c]);
    }
  }
  in.ScalarArray = scalars;
  coloring.Scalars = scalars;
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
  os << indent << "Opacity: " << this->Opacity << "\n";
  os << indent << "FootprintRadius: " << this->FootprintRadius << " cells\n";
  os << indent << "Falloff: " << vtkOFBBrush::GetFalloffAsString(this->Falloff) << "\n";
  os << indent << "BlendMode: " << vtkOFBBrush::GetBlendModeAsString(this->BlendMode) << "\n";
  os << indent << "SmearAmount: " << this->SmearAmount << "\n";
  os << indent << "Paint: " << (this->Paint ? "On" : "Off") << "\n";
  os << indent << "ColorPeriod: " << this->ColorPeriod << " steps\n";
  os << indent
     << "SeedColorArrayName: " << (this->SeedColorArrayName ? this->SeedColorArrayName : "(none)")
     << "\n";
  os << indent << "ScalarArrayName: " << (this->ScalarArrayName ? this->ScalarArrayName : "(none)")
     << "\n";
  os << indent << "LookupTable: " << this->LookupTable << "\n";
  os << indent << "TrailLength: " << this->TrailLength << "\n";
  os << indent << "CurrentStep: " << this->GetCurrentStep() << "\n";
  os << indent << "LastAdvectionTime: " << this->GetLastAdvectionTime() << " s\n";
  os << indent << "LastPaintingTime: " << this->GetLastPaintingTime() << " s\n";
  os << indent << "LastOutputTime: " << this->GetLastOutputTime() << " s\n";
}
