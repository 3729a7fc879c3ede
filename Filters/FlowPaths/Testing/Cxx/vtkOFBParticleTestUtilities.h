// Helpers of the surface particle tests: generated surfaces and vector fields.
#ifndef vtkOFBParticleTestUtilities_h
#define vtkOFBParticleTestUtilities_h

#include "vtkCleanPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkOFBParticleAdvector.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace vtkofbtest
{
/// Set point vectors "Field" (active) from f(x, v).
inline void SetField(vtkPolyData* mesh, const std::function<void(const double*, double*)>& f)
{
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  field->SetNumberOfComponents(3);
  field->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3], v[3];
    mesh->GetPoint(i, x);
    f(x, v);
    field->SetTuple(i, v);
  }
  mesh->GetPointData()->SetVectors(field);
}

/// v = w x (x - c): rotation about the axis w through c.
inline void SetRotationField(vtkPolyData* mesh, const double w[3], const double c[3])
{
  SetField(mesh,
    [&](const double* x, double* v)
    {
      const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
      v[0] = w[1] * r[2] - w[2] * r[1];
      v[1] = w[2] * r[0] - w[0] * r[2];
      v[2] = w[0] * r[1] - w[1] * r[0];
    });
}

/// A closed torus about the z axis (ring radius R, tube radius r), triangles.
inline vtkSmartPointer<vtkPolyData> MakeTorus(double R, double r, int resolution)
{
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(R);
  torus->SetCrossSectionRadius(r);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(2 * resolution);
  source->SetVResolution(resolution);
  source->GenerateTextureCoordinatesOff();
  source->SetScalarModeToNone();
  vtkNew<vtkCleanPolyData> clean; // the seams' points differ by rounding
  clean->SetTolerance(1e-6);
  clean->SetInputConnection(source->GetOutputPort());
  clean->Update();
  vtkSmartPointer<vtkPolyData> out = clean->GetOutput();
  out->GetPointData()->Initialize();
  return out;
}

/// Largest distance of the points of `points` to the surface `mesh`.
inline double MaximumDistanceToSurface(vtkPolyData* mesh, vtkPoints* points)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  double worst = 0.0;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3], closest[3], d2;
    vtkIdType cell;
    int sub;
    points->GetPoint(i, x);
    locator->FindClosestPoint(x, closest, cell, sub, d2);
    worst = std::max(worst, std::sqrt(d2));
  }
  return worst;
}

/// Seed points given as coordinates.
inline vtkSmartPointer<vtkPolyData> MakeSeeds(const std::vector<std::array<double, 3>>& xs)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& x : xs)
  {
    points->InsertNextPoint(x.data());
  }
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  seeds->SetPoints(points);
  return seeds;
}
}

#endif
