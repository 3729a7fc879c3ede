// The preparation of vtkOFBParticleAdvector's inputs: the surface and its field, the
// OFB to paint, the seeds and the colouring (RequestData calls these before stepping).
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleAdvectorInternals.h"

#include "vtkOFBBrush.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformationVector.h"
#include "vtkLookupTable.h"
#include "vtkOFB.h"
#include "vtkOFBArrayLength.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBParticleExchange.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
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

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::CheckSettings()
{
  if (!(this->StepSize > 0.0) || !std::isfinite(this->StepSize))
  {
    vtkErrorMacro("StepSize must be positive and finite (cells), not " << this->StepSize << ".");
    return false;
  }
  if (!this->Brush)
  {
    vtkErrorMacro("No brush: call SetBrush with a vtkOFBBrush.");
    return false;
  }
  // NaN passes the setters' clamps: a NaN radius painted nothing without a word.
  const double strength = this->Brush->GetStrength();
  const double smear = this->Brush->GetSmearAmount();
  const double values[6] = {
    this->FootprintRadius, this->Color[0], this->Color[1], this->Color[2], strength, smear
  };
  if (!std::all_of(values, values + 6, [](double v) { return std::isfinite(v); }))
  {
    vtkErrorMacro("FootprintRadius, Color and the brush's Strength and SmearAmount must be "
                  "finite (they are "
      << this->FootprintRadius << "; " << this->Color[0] << ", " << this->Color[1] << ", "
      << this->Color[2] << "; " << strength << "; " << smear << ").");
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
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* vectors = this->FindSurfaceVectors(surface, inputVector, association);
  if (!vectors)
  {
    return false;
  }
  if (surface == in.SurfaceObject && ContentTime(surface) == in.SurfaceTime &&
    vectors == in.VectorArray && vectors->GetMTime() == in.VectorTime)
  {
    return true;
  }

  // A cell field holds on its cells' triangles (as the sampler's cell arrays do):
  // each triangle carries its cell's vector.
  const bool perCell = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  if (!perCell && association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("The vector field must be a point or cell array.");
    return false;
  }
  const vtkIdType numValues = perCell ? surface->GetNumberOfCells() : surface->GetNumberOfPoints();
  for (vtkIdType i = 0; i < numValues; ++i)
  {
    double v[3];
    vectors->GetTuple(i, v);
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    {
      vtkErrorMacro("The vector field has a non-finite value at " << (perCell ? "cell " : "point ")
                                                                  << i << ".");
      return false;
    }
  }
  if (in.Unsteady && in.Started && in.SurfaceObject && perCell == in.FieldPerCell &&
    numValues == static_cast<vtkIdType>(in.FieldNew.size() / 3) &&
    vtkOFBParticleAdvector::HashGeometry(surface) == in.GeometryHash)
  {
    // A new time step of the same surface: the field alone changes, the particles
    // go on (vtkOFBParticleAdvectorTime.cxx).
    this->KeepField(surface, vectors, false);
    in.SurfaceObject = surface;
    in.SurfaceTime = ContentTime(surface);
    in.VectorArray = vectors;
    in.VectorTime = vectors->GetMTime();
    return true;
  }
  if (!this->BuildWalker(surface, vectors, perCell))
  {
    return false;
  }
  in.SurfaceObject = surface;
  in.SurfaceTime = ContentTime(surface);
  in.VectorArray = vectors;
  in.VectorTime = vectors->GetMTime();
  if (in.Unsteady)
  {
    in.GeometryHash = vtkOFBParticleAdvector::HashGeometry(surface);
    this->KeepField(surface, vectors, true);
  }
  rebuilt = true;
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBParticleAdvector::FindSurfaceVectors(vtkPolyData* surface,
  vtkInformationVector** inputVector,
  int& association)
{
  if (!surface || surface->GetNumberOfPoints() == 0 ||
    surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input surface has no polygons: no particles.");
    return nullptr;
  }
  // Before the cell vectors are averaged or the surface triangulated: both read the
  // cells' points.
  std::string error;
  if (!vtkOFBCheckCellPointIds(surface, error))
  {
    vtkErrorMacro("The input surface (port 0) is invalid: " << error << ".");
    return nullptr;
  }
  association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
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
    return nullptr;
  }
  if (vectors->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The vector field '" << (vectors->GetName() ? vectors->GetName() : "") << "' has "
                                       << vectors->GetNumberOfComponents()
                                       << " components, not 3.");
    return nullptr;
  }
  const vtkIdType needed = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
    ? surface->GetNumberOfCells()
    : surface->GetNumberOfPoints();
  if (vectors->GetNumberOfTuples() < needed)
  {
    vtkErrorMacro("The vector field " << vtkOFBArrayLength(vectors,
                    needed,
                    association == vtkDataObject::FIELD_ASSOCIATION_CELLS ? "cells." : "points."));
    return nullptr;
  }
  return vectors;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::BuildWalker(vtkPolyData* surface, vtkDataArray* vectors, bool perCell)
{
  vtkInternals& in = *this->Internals;
  vtkSmartPointer<vtkPolyData> triangles = surface;
  // The input cell of each polygon given to the walker, for a cell field: polygons
  // follow the vertices and lines in vtkPolyData's cell ids, and the triangle filter
  // carries an id array from each polygon or strip to its triangles.
  std::vector<vtkIdType> polygonCells;
  if (surface->GetNumberOfStrips() > 0 || surface->GetPolys()->IsHomogeneous() != 3)
  {
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(surface);
    copy->GetCellData()->Initialize();
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("vtkOFBInputCellIds");
    ids->SetNumberOfTuples(surface->GetNumberOfCells());
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
    {
      ids->SetValue(c, c);
    }
    copy->GetCellData()->AddArray(ids);
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->SetInputData(copy);
    triangulate->Update();
    triangles = triangulate->GetOutput();
    auto* triangleIds =
      vtkIdTypeArray::SafeDownCast(triangles->GetCellData()->GetArray("vtkOFBInputCellIds"));
    if (perCell &&
      (!triangleIds || triangleIds->GetNumberOfTuples() != triangles->GetNumberOfCells()))
    {
      vtkErrorMacro(
        "The triangulation lost the cells of its triangles: cannot use the cell field.");
      return false;
    }
    if (triangleIds)
    {
      polygonCells.assign(
        triangleIds->GetPointer(0), triangleIds->GetPointer(0) + triangleIds->GetNumberOfTuples());
    }
  }
  else
  {
    const vtkIdType first = surface->GetNumberOfVerts() + surface->GetNumberOfLines();
    polygonCells.resize(surface->GetNumberOfPolys());
    for (size_t p = 0; p < polygonCells.size(); ++p)
    {
      polygonCells[p] = first + static_cast<vtkIdType>(p);
    }
  }
  in.FieldPerCell = perCell;
  std::string error;
  if (!in.Walker.Build(triangles,
        perCell ? nullptr : vectors,
        error,
        polygonCells.data(),
        vtkOFBParticleAdvector::MergeTolerance(surface)))
  {
    vtkErrorMacro("The input surface cannot carry particles: " << error << ".");
    return false;
  }
  if (perCell)
  {
    const vtkIdType numValues = surface->GetNumberOfCells();
    std::vector<double> field(3 * static_cast<size_t>(numValues));
    for (vtkIdType c = 0; c < numValues; ++c)
    {
      vectors->GetTuple(c, &field[3 * c]);
    }
    in.Walker.SetCellVectors(field.data());
  }
  if (!(in.Walker.GetMaximumSpeed() > 0.0))
  {
    vtkErrorMacro("The vector field is zero everywhere: no particle can move.");
    return false;
  }
  this->FindOwnedTriangles(surface, polygonCells);
  in.Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  in.Locator->SetDataSet(in.Walker.GetTriangles());
  in.Locator->BuildLocator();
  in.Surface = triangles;
  return true;
}

//------------------------------------------------------------------------------
double vtkOFBParticleAdvector::MergeTolerance(vtkPolyData* surface)
{
  // Points a rounding error apart are one point of the surface: the pieces of a surface
  // made apart (a source's pieces under MPI, each computing its seam points) repeat
  // their seam points a few units in the last place apart, and a seam that is not one
  // would be a boundary where particles stop. 1e-9 of the coordinates' scale is far
  // above such rounding and far below any triangle.
  double bounds[6];
  surface->GetBounds(bounds);
  double scale = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    scale = std::max({ scale,
      bounds[2 * j + 1] - bounds[2 * j],
      std::abs(bounds[2 * j]),
      std::abs(bounds[2 * j + 1]) });
  }
  return std::isfinite(scale) ? 1e-9 * scale : 0.0;
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
bool vtkOFBParticleAdvector::StartParticles(vtkDataSet* seeds)
{
  const bool ok = this->CheckStart(seeds);
  if (this->Exchange && this->Exchange->AllReduceMaximum(ok ? 0.0 : 1.0) > 0.0)
  {
    if (ok)
    {
      vtkErrorMacro("Another process could not start the particles: no particles.");
    }
    return false;
  }
  if (!ok)
  {
    return false;
  }
  return this->StartCheckedParticles(seeds);
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::CheckStart(vtkDataSet* seeds)
{
  // What the particles will hold: per seed its point and colour; per particle (seeds x
  // ChainLength) its state, its trail (TrailLength positions, and as many output points
  // and ids), its footprint and output point. In doubles: the product can exceed 2^63.
  vtkInternals& in = *this->Internals;
  if (this->Exchange && (!seeds || this->Lifetime > 0))
  {
    vtkErrorMacro("Distributed particles need seed points (port 2) and no Lifetime: a "
                  "random seed or reseed is drawn from each process's own piece.");
    return false;
  }
  // A step longer than a few times the surface's extent walks the surface over and over
  // (seconds a step for 1e6 cells, without end for 1e300): an error.
  double bounds[6];
  in.SurfaceObject->GetBounds(bounds);
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] }) / in.CellSize;
  if (this->StepSize > 4.0 * std::max(1.0, extent))
  {
    vtkErrorMacro("StepSize " << this->StepSize << " cells is more than four times the "
                              << "surface's extent (" << extent << " cells): no particles.");
    return false;
  }
  const double numberOfSeeds =
    static_cast<double>(seeds ? seeds->GetNumberOfPoints() : this->NumberOfParticles);
  const double particles = numberOfSeeds * this->ChainLength;
  const double bytes = numberOfSeeds * (sizeof(vtkOFBSurfacePoint) + 4 * sizeof(float)) +
    particles *
      (sizeof(vtkOFBParticleSystem::Particle) + 256.0 +
        this->TrailLength * (sizeof(glm::dvec3) + 3 * sizeof(float) + sizeof(vtkIdType)));
  if (bytes > 1048576.0 * static_cast<double>(this->MemoryLimit))
  {
    vtkErrorMacro("The particles would take about "
      << static_cast<vtkIdType>(bytes / 1048576.0) << " MiB (" << numberOfSeeds << " seeds x "
      << this->ChainLength << " in a chain, trails of " << this->TrailLength
      << " positions), more than MemoryLimit (" << this->MemoryLimit << " MiB): no particles.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::StartCheckedParticles(vtkDataSet* seeds)
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  system.Walker = &in.Walker;
  vtkOFBParticleStepper& stepper = system.Stepper;
  stepper.Walker = &in.Walker;
  stepper.Integrator = this->Integrator;
  stepper.Normalize = this->NormalizeVectors;
  stepper.Sign = this->Direction == BACKWARD ? -1.0 : 1.0;
  stepper.Scale = 1.0 /
    (this->Exchange ? this->Exchange->AllReduceMaximum(in.Walker.GetMaximumSpeed())
                    : in.Walker.GetMaximumSpeed());
  stepper.StopSpeed = 1e-12 * in.Walker.GetMaximumSpeed();
  stepper.Length = this->StepSize * in.CellSize;
  stepper.Tolerance = this->ErrorTolerance * in.CellSize;
  system.Setup.ChainLength = this->ChainLength;
  system.Setup.ChainSpacing = this->ChainSpacing;
  system.Setup.Lifetime = this->Lifetime;
  system.Setup.TrailLength = this->TrailLength;
  system.Setup.RandomSeed = this->RandomSeed;
  system.Setup.RandomSeeds = seeds == nullptr;
  if (seeds && this->Exchange)
  {
    this->LocateSeedsOverProcesses(seeds);
  }
  else if (seeds)
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
  in.Owned.clear();
  if (this->Exchange)
  {
    in.Owned.resize(system.Particles.size());
    for (size_t i = 0; i < system.Particles.size(); ++i)
    {
      in.Owned[i] = in.SeedOwned[system.Particles[i].Seed];
    }
  }
  in.Started = true;
  in.ResetRequested = false;
  in.SeedObject = seeds;
  in.SeedTime = seeds ? ContentTime(seeds) : 0;
  return true;
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
  if (colors && colors->GetNumberOfTuples() < seeds->GetNumberOfPoints())
  {
    if (this->ColorMode == COLOR_FROM_SEEDS)
    {
      vtkWarningMacro("The seed colour array "
        << vtkOFBArrayLength(colors, seeds->GetNumberOfPoints(), "seeds")
        << ": not used, the seeds take the constant colour.");
    }
    colors = nullptr;
  }
  else if (this->ColorMode == COLOR_FROM_SEEDS && !colors)
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
    double centroid[3];
    cell = this->CanonicalTriangle(closest, cell, false, centroid);
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
  if (!scalars || scalars->GetNumberOfTuples() < surface->GetNumberOfPoints())
  {
    vtkWarningMacro("No surface point array '"
      << (this->ScalarArrayName ? this->ScalarArrayName : "(active scalars)")
      << "' of one tuple a point to colour by: the particles keep their colour.");
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
