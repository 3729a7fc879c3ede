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

// The footprints painted at each step and the particle and trail outputs of
// vtkOFBParticleAdvector.

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::PaintFootprints()
{
  vtkInternals& in = *this->Internals;
  const vtkOFBParticleSystem& system = in.System;
  const bool smear = this->SmearAmount > 0.0;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkFloatArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(4);
  vtkNew<vtkDoubleArray> strength;
  strength->SetName("Strength");
  vtkNew<vtkDoubleArray> previous;
  previous->SetName("PreviousPosition");
  previous->SetNumberOfComponents(3);
  for (const auto& p : system.Particles)
  {
    if (!p.Painted)
    {
      continue;
    }
    const double w = system.ChainWeight(p.Chain);
    points->InsertNextPoint(p.Position[0], p.Position[1], p.Position[2]);
    radius->InsertNextValue(this->FootprintRadius * in.CellSize * w);
    const float rgba[4] = { p.Color[0], p.Color[1], p.Color[2], 1.f };
    color->InsertNextTypedTuple(rgba);
    strength->InsertNextValue(this->Opacity * p.Color[3] * w);
    if (smear)
    {
      previous->InsertNextTuple3(p.Previous[0], p.Previous[1], p.Previous[2]);
    }
  }
  vtkPolyData* footprints = in.Footprints;
  footprints->Initialize();
  footprints->SetPoints(points);
  footprints->GetPointData()->AddArray(radius);
  footprints->GetPointData()->AddArray(color);
  footprints->GetPointData()->AddArray(strength);
  if (smear)
  {
    footprints->GetPointData()->AddArray(previous);
  }
  if (!in.Target || !this->Paint || points->GetNumberOfPoints() == 0 ||
    !(this->FootprintRadius > 0.0) || in.Target->GetNumberOfSamples() == 0)
  {
    return;
  }
  vtkOFBBrush* brush = in.Brush;
  brush->SetFalloff(this->Falloff);
  brush->SetBlendMode(this->BlendMode);
  if (smear)
  {
    brush->SetTargetToSmear();
    brush->SetSmearAmount(this->SmearAmount);
  }
  else
  {
    brush->SetTargetToColor();
  }
  if (in.Painter->GetOFB() != in.Target)
  {
    in.Painter->SetOFB(in.Target);
  }
  in.Painter->Dabs(footprints);
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::FillParticles(vtkPolyData* output)
{
  const vtkOFBParticleSystem& system = this->Internals->System;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> age;
  age->SetName("Age");
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("Id");
  vtkNew<vtkIntArray> chain;
  chain->SetName("ChainIndex");
  vtkNew<vtkUnsignedCharArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(4);
  const vtkIdType n = static_cast<vtkIdType>(system.Particles.size());
  for (vtkIdType i = 0; i < n; ++i)
  {
    const auto& p = system.Particles[i];
    if (p.Status == vtkOFBParticleSystem::Waiting)
    {
      continue;
    }
    points->InsertNextPoint(p.Position[0], p.Position[1], p.Position[2]);
    const glm::dvec3 v = system.Velocity(p);
    velocity->InsertNextTuple3(v[0], v[1], v[2]);
    age->InsertNextValue(p.Age);
    ids->InsertNextValue(i);
    chain->InsertNextValue(p.Chain);
    const double a = this->Opacity * p.Color[3] * system.ChainWeight(p.Chain);
    const unsigned char rgba[4] = { static_cast<unsigned char>(255.f * p.Color[0] + 0.5f),
      static_cast<unsigned char>(255.f * p.Color[1] + 0.5f),
      static_cast<unsigned char>(255.f * p.Color[2] + 0.5f),
      static_cast<unsigned char>(255.0 * a + 0.5) };
    color->InsertNextTypedTuple(rgba);
  }
  vtkNew<vtkCellArray> verts;
  const vtkIdType count = points->GetNumberOfPoints();
  verts->AllocateExact(count, count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    verts->InsertNextCell(1, &i);
  }
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->AddArray(velocity);
  output->GetPointData()->SetVectors(velocity);
  output->GetPointData()->AddArray(age);
  output->GetPointData()->AddArray(ids);
  output->GetPointData()->AddArray(chain);
  output->GetPointData()->AddArray(color);
  output->GetPointData()->SetScalars(color);
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::FillTrails(vtkPolyData* output)
{
  const vtkOFBParticleSystem& system = this->Internals->System;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("Id");
  std::vector<glm::dvec3> trail(system.Setup.TrailLength);
  std::vector<vtkIdType> cell(system.Setup.TrailLength);
  const vtkIdType n = static_cast<vtkIdType>(system.Particles.size());
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (system.Particles[i].Status == vtkOFBParticleSystem::Waiting)
    {
      continue;
    }
    const int count = system.GetTrail(i, trail.data());
    if (count < 2)
    {
      continue;
    }
    for (int k = 0; k < count; ++k)
    {
      cell[k] = points->InsertNextPoint(trail[k][0], trail[k][1], trail[k][2]);
    }
    lines->InsertNextCell(count, cell.data());
    ids->InsertNextValue(i);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(ids);
}
