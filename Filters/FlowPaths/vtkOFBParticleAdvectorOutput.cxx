#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleAdvectorInternals.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

#include "vtkSMPTools.h"

static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "trail points are written as glm::dvec3");

// The footprints painted at each step and the particle and trail outputs of
// vtkOFBParticleAdvector. Their arrays are kept from step to step and written
// through their pointers: a step allocates only when a count grows.

namespace
{
template<typename T>
vtkSmartPointer<T> Named(const char* name, int components)
{
  auto array = vtkSmartPointer<T>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  return array;
}

vtkSmartPointer<vtkPoints> DoublePoints()
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  return points;
}

double* PointsOf(vtkPoints* points, vtkIdType n)
{
  if (points->GetNumberOfPoints() != n)
  {
    points->SetNumberOfPoints(n);
  }
  points->Modified();
  return static_cast<double*>(points->GetVoidPointer(0));
}

template<typename A>
auto* ValuesOf(A* array, vtkIdType n)
{
  if (array->GetNumberOfTuples() != n)
  {
    array->SetNumberOfTuples(n);
  }
  array->Modified();
  return array->GetPointer(0);
}

}

//------------------------------------------------------------------------------
vtkOFBParticleArrays::vtkOFBParticleArrays()
  : DabPoints(DoublePoints())
  , DabRadius(Named<vtkDoubleArray>("Radius", 1))
  , DabColor(Named<vtkFloatArray>("Color", 4))
  , DabStrength(Named<vtkDoubleArray>("Strength", 1))
  , DabPrevious(Named<vtkDoubleArray>("PreviousPosition", 3))
  , Points(DoublePoints())
  , Verts(vtkSmartPointer<vtkCellArray>::New())
  , VertOffsets(Named<vtkIdTypeArray>(nullptr, 1))
  , VertConnectivity(Named<vtkIdTypeArray>(nullptr, 1))
  , Velocity(Named<vtkDoubleArray>("Velocity", 3))
  , Age(Named<vtkIntArray>("Age", 1))
  , Ids(Named<vtkIdTypeArray>("Id", 1))
  , Chain(Named<vtkIntArray>("ChainIndex", 1))
  , Color(Named<vtkUnsignedCharArray>("Color", 4))
  , TrailPoints(DoublePoints())
  , Lines(vtkSmartPointer<vtkCellArray>::New())
  , LineOffsets(Named<vtkIdTypeArray>(nullptr, 1))
  , LineConnectivity(Named<vtkIdTypeArray>(nullptr, 1))
  , TrailIds(Named<vtkIdTypeArray>("Id", 1))
{
}

vtkOFBParticleArrays::~vtkOFBParticleArrays() = default;

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::PaintFootprints()
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleArrays& arrays = in.Arrays;
  const vtkOFBParticleSystem& system = in.System;
  vtkOFBBrush* brush = this->Brush;
  const bool smear = brush->GetTarget() == vtkOFBBrush::TARGET_SMEAR;
  const double opacity = brush->GetStrength();
  vtkIdType count = 0;
  for (const auto& p : system.Particles)
  {
    count += p.Painted ? 1 : 0;
  }
  double* x = PointsOf(arrays.DabPoints, count);
  double* radius = ValuesOf(arrays.DabRadius.Get(), count);
  float* color = ValuesOf(arrays.DabColor.Get(), count);
  double* strength = ValuesOf(arrays.DabStrength.Get(), count);
  double* previous = smear ? ValuesOf(arrays.DabPrevious.Get(), count) : nullptr;
  vtkIdType k = 0;
  for (const auto& p : system.Particles)
  {
    if (!p.Painted)
    {
      continue;
    }
    const double w = system.ChainWeight(p.Chain);
    std::copy_n(&p.Position[0], 3, x + 3 * k);
    radius[k] = this->FootprintRadius * in.CellSize * w;
    std::copy_n(p.Color, 3, color + 4 * k);
    color[4 * k + 3] = 1.f;
    strength[k] = opacity * p.Color[3] * w;
    if (previous)
    {
      std::copy_n(&p.Previous[0], 3, previous + 3 * k);
    }
    ++k;
  }
  vtkPolyData* footprints = in.Footprints;
  vtkPointData* pd = footprints->GetPointData();
  if (!pd->HasArray("Radius"))
  {
    pd->AddArray(arrays.DabRadius);
    pd->AddArray(arrays.DabColor);
    pd->AddArray(arrays.DabStrength);
  }
  if (smear != static_cast<bool>(pd->HasArray("PreviousPosition")))
  {
    if (smear)
    {
      pd->AddArray(arrays.DabPrevious);
    }
    else
    {
      pd->RemoveArray("PreviousPosition");
    }
  }
  footprints->Modified();
  if (!in.Target || !this->Paint || count == 0 || !(this->FootprintRadius > 0.0) ||
    in.Target->GetNumberOfSamples() == 0)
  {
    return;
  }
  in.Painter->SetBrush(brush);
  if (in.Painter->GetOFB() != in.Target)
  {
    in.Painter->SetOFB(in.Target);
  }
  in.Painter->Dabs(footprints);
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::ClearFootprints()
{
  vtkPolyData* footprints = this->Internals->Footprints;
  footprints->GetPointData()->Initialize();
  this->Internals->Arrays.DabPoints->SetNumberOfPoints(0);
  footprints->Modified();
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::FillParticles(vtkPolyData* output)
{
  const vtkOFBParticleSystem& system = this->Internals->System;
  vtkOFBParticleArrays& arrays = this->Internals->Arrays;
  const vtkIdType n = static_cast<vtkIdType>(system.Particles.size());
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    count += system.Particles[i].Status != vtkOFBParticleSystem::WAITING && this->OutputsParticle(i)
      ? 1
      : 0;
  }
  double* x = PointsOf(arrays.Points, count);
  double* velocity = ValuesOf(arrays.Velocity.Get(), count);
  int* age = ValuesOf(arrays.Age.Get(), count);
  vtkIdType* ids = ValuesOf(arrays.Ids.Get(), count);
  int* chain = ValuesOf(arrays.Chain.Get(), count);
  unsigned char* color = ValuesOf(arrays.Color.Get(), count);
  vtkIdType* offsets = ValuesOf(arrays.VertOffsets.Get(), count + 1);
  vtkIdType* connectivity = ValuesOf(arrays.VertConnectivity.Get(), count);
  // Where each particle goes: its index among the released ones.
  std::vector<vtkIdType>& slots = this->Internals->Slots;
  slots.resize(n);
  vtkIdType k = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    slots[i] = k;
    k += system.Particles[i].Status != vtkOFBParticleSystem::WAITING && this->OutputsParticle(i)
      ? 1
      : 0;
  }
  const double opacity = this->Brush->GetStrength();
  vtkSMPTools::For(0,
    n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const auto& p = system.Particles[i];
        if (p.Status == vtkOFBParticleSystem::WAITING || !this->OutputsParticle(i))
        {
          continue;
        }
        const vtkIdType j = slots[i];
        std::copy_n(&p.Position[0], 3, x + 3 * j);
        const glm::dvec3 v = system.Velocity(p);
        std::copy_n(&v[0], 3, velocity + 3 * j);
        age[j] = p.Age;
        ids[j] = i;
        chain[j] = p.Chain;
        const double a = opacity * p.Color[3] * system.ChainWeight(p.Chain);
        const unsigned char rgba[4] = { static_cast<unsigned char>(255.f * p.Color[0] + 0.5f),
          static_cast<unsigned char>(255.f * p.Color[1] + 0.5f),
          static_cast<unsigned char>(255.f * p.Color[2] + 0.5f),
          static_cast<unsigned char>(255.0 * a + 0.5) };
        std::copy_n(rgba, 4, color + 4 * j);
        offsets[j] = j;
        connectivity[j] = j;
      }
    });
  offsets[count] = count;
  arrays.Verts->SetData(arrays.VertOffsets, arrays.VertConnectivity);
  output->SetPoints(arrays.Points);
  output->SetVerts(arrays.Verts);
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(arrays.Velocity);
  pd->SetVectors(arrays.Velocity);
  pd->AddArray(arrays.Age);
  pd->AddArray(arrays.Ids);
  pd->AddArray(arrays.Chain);
  pd->AddArray(arrays.Color);
  pd->SetScalars(arrays.Color);
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::FillTrails(vtkPolyData* output)
{
  const vtkOFBParticleSystem& system = this->Internals->System;
  vtkOFBParticleArrays& arrays = this->Internals->Arrays;
  const vtkIdType n = static_cast<vtkIdType>(system.Particles.size());
  // Trails of two points or more: where each one's line and points start.
  std::vector<vtkIdType>& slots = this->Internals->Slots;
  slots.resize(2 * n);
  vtkIdType numLines = 0;
  vtkIdType numPoints = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int count = system.TrailCount[i];
    slots[2 * i] = numLines;
    slots[2 * i + 1] = numPoints;
    if (system.Particles[i].Status != vtkOFBParticleSystem::WAITING && count >= 2 &&
      this->OutputsParticle(i))
    {
      ++numLines;
      numPoints += count;
    }
  }
  double* x = PointsOf(arrays.TrailPoints, numPoints);
  vtkIdType* offsets = ValuesOf(arrays.LineOffsets.Get(), numLines + 1);
  vtkIdType* connectivity = ValuesOf(arrays.LineConnectivity.Get(), numPoints);
  vtkIdType* ids = ValuesOf(arrays.TrailIds.Get(), numLines);
  vtkSMPTools::For(0,
    n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (system.Particles[i].Status == vtkOFBParticleSystem::WAITING ||
          system.TrailCount[i] < 2 || !this->OutputsParticle(i))
        {
          continue;
        }
        const vtkIdType line = slots[2 * i];
        const vtkIdType point = slots[2 * i + 1];
        const int count = system.GetTrail(i, reinterpret_cast<glm::dvec3*>(x + 3 * point));
        offsets[line] = point;
        ids[line] = i;
        for (int k = 0; k < count; ++k)
        {
          connectivity[point + k] = point + k;
        }
      }
    });
  offsets[numLines] = numPoints;
  arrays.Lines->SetData(arrays.LineOffsets, arrays.LineConnectivity);
  output->SetPoints(arrays.TrailPoints);
  output->SetLines(arrays.Lines);
  output->GetCellData()->AddArray(arrays.TrailIds);
}
