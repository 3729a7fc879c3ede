// Surfaces whose cells name points that do not exist (an id past the end, a negative
// id) given to vtkOFBParticleAdvector, with point and with cell vectors: an error naming
// the surface and the bad id, empty outputs, never a read out of bounds
// (vtkOFBInputChecks.h).
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleTestUtilities.h"
#include "vtkPointData.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <string>

using namespace vtkofbtest;

namespace
{
/// A 2 x 2 plane of 4 x 4 quads (25 points), triangulated or not, with the field (1, 0.3, 0)
/// on its points or its cells.
vtkSmartPointer<vtkPolyData> FlowPlane(bool triangles, bool onCells)
{
  vtkSmartPointer<vtkPolyData> mesh = MakeTexturedPlane(4);
  if (triangles)
  {
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(mesh);
    triangulate->Update();
    mesh = triangulate->GetOutput();
  }
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  field->SetNumberOfComponents(3);
  const vtkIdType n = onCells ? mesh->GetNumberOfCells() + 1 : mesh->GetNumberOfPoints();
  field->SetNumberOfTuples(n); // (on cells, one for the bad cell added after)
  for (vtkIdType i = 0; i < n; ++i)
  {
    field->SetTuple3(i, 1.0, 0.3, 0.0);
  }
  if (onCells)
  {
    mesh->GetCellData()->SetVectors(field);
  }
  else
  {
    mesh->GetPointData()->SetVectors(field);
  }
  return mesh;
}
}

//------------------------------------------------------------------------------
TEST(BadPointIds, ParticleAdvectorRefusesThem)
{
  for (vtkIdType badId : { vtkIdType(25), vtkIdType(99999), vtkIdType(-1) })
  {
    for (bool triangles : { true, false })
    {
      for (bool onCells : { false, true })
      {
        vtkNew<vtkOFBParticleAdvector> advector;
        vtkNew<MessageObserver> o;
        o->Watch(advector);
        advector->SetInputData(WithBadPointId(FlowPlane(triangles, onCells), badId));
        advector->SetNumberOfParticles(10);
        advector->Update();
        EXPECT_NE(o->Errors.find("point id " + std::to_string(badId)), std::string::npos)
          << o->Errors;
        EXPECT_EQ(advector->GetOutput()->GetNumberOfSamples(), 0);
        EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 0);
        EXPECT_EQ(advector->GetTrails()->GetNumberOfPoints(), 0);
      }
    }
  }
}
