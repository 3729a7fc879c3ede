// Surfaces and strokes whose cells name points that do not exist (an id past the end,
// a negative id), and strokes with per-point arrays shorter than their points, given to
// the paint filters: an error naming the input and the bad id or array, an empty
// output, never a read out of bounds (vtkOFBInputChecks.h).
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkOFBBrush.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBPaintFilter.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace vtkofbtest;

namespace
{
void ExpectBadIdError(const std::string& errors, vtkIdType badId)
{
  EXPECT_NE(errors.find("point id " + std::to_string(badId)), std::string::npos) << errors;
}

/// Three stroke points over the plane, a polyline through `lineIds` and, with
/// `withVertex`, a vertex at `vertexId`.
vtkSmartPointer<vtkPolyData> Strokes(const std::vector<vtkIdType>& lineIds,
  bool withVertex = false,
  vtkIdType vertexId = 0)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-0.5, 0.0, 0.0);
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(0.5, 0.0, 0.0);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<vtkIdType>(lineIds.size()), lineIds.data());
  auto strokes = vtkSmartPointer<vtkPolyData>::New();
  strokes->SetPoints(points);
  strokes->SetLines(lines);
  if (withVertex)
  {
    vtkNew<vtkCellArray> verts;
    verts->InsertNextCell(1, &vertexId);
    strokes->SetVerts(verts);
  }
  return strokes;
}

/// Paint `strokes` into a copy of `ofb`; the errors.
std::string Paint(vtkOFB* ofb, vtkPolyData* strokes, vtkIdType& samples)
{
  vtkNew<vtkOFBPaintFilter> filter;
  vtkNew<MessageObserver> o;
  o->Watch(filter);
  filter->GetBrush()->SetRadius(0.2);
  filter->SetInputData(ofb);
  filter->SetStrokesData(strokes);
  filter->Update();
  samples = filter->GetOutput()->GetNumberOfSamples();
  return o->Errors;
}
}

//------------------------------------------------------------------------------
TEST(BadPointIds, DecalPatchRefusesThem)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedTrianglePlane();
  for (vtkIdType badId : BadPlanePointIds)
  {
    // Triangles (the walker reads them as they are) and quads (triangulated first).
    for (bool quads : { false, true })
    {
      vtkNew<vtkOFBDecalPatch> decal;
      vtkNew<MessageObserver> o;
      o->Watch(decal);
      decal->SetCenter(0.0, 0.0, 0.0);
      decal->SetDirection(1.0, 0.0, 0.0);
      decal->SetInputData(WithBadPointId(quads ? MakeTexturedPlane(4) : plane, badId));
      decal->Update();
      ExpectBadIdError(o->Errors, badId);
      EXPECT_EQ(decal->GetOutput()->GetNumberOfPoints(), 0);
    }
  }
}

//------------------------------------------------------------------------------
TEST(BadPointIds, TextureProjectorRefusesThem)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedTrianglePlane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (vtkIdType badId : BadPlanePointIds)
  {
    vtkNew<vtkOFBTextureProjector> projector;
    vtkNew<MessageObserver> o;
    o->Watch(projector);
    projector->SetInputData(ofb);
    projector->SetMeshData(WithBadPointId(plane, badId));
    projector->SetTextureData(image);
    projector->Update();
    ExpectBadIdError(o->Errors, badId);
    EXPECT_EQ(projector->GetOutput()->GetNumberOfSamples(), 0);
  }
}

//------------------------------------------------------------------------------
TEST(BadPointIds, PaintFilterRefusesStrokeIdsPastTheEndOrNegative)
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakeTexturedTrianglePlane(), 32);
  vtkIdType samples = -1;
  for (vtkIdType badId : { vtkIdType(3), vtkIdType(99999), vtkIdType(-1) })
  {
    // In the polyline (its first point, or a later one) and in a vertex.
    ExpectBadIdError(Paint(ofb, Strokes({ badId, 1, 2 }), samples), badId);
    EXPECT_EQ(samples, 0);
    ExpectBadIdError(Paint(ofb, Strokes({ 0, 1, badId }), samples), badId);
    EXPECT_EQ(samples, 0);
    ExpectBadIdError(Paint(ofb, Strokes({ 0, 1, 2 }, true, badId), samples), badId);
    EXPECT_EQ(samples, 0);
  }
  // A polyline without any point to name is bad input too, not an empty stroke.
  vtkSmartPointer<vtkPolyData> pointless = Strokes({ 0, 1 });
  pointless->SetPoints(vtkNew<vtkPoints>());
  ExpectBadIdError(Paint(ofb, pointless, samples), 0);
  EXPECT_EQ(samples, 0);
  // The good strokes paint.
  EXPECT_TRUE(Paint(ofb, Strokes({ 0, 1, 2 }, true, 1), samples).empty());
  EXPECT_EQ(samples, ofb->GetNumberOfSamples());
}

//------------------------------------------------------------------------------
TEST(BadPointIds, PaintFilterRefusesShortPerPointArrays)
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakeTexturedTrianglePlane(), 32);
  for (const char* name : { "Radius", "Color", "Strength", "Pressure" })
  {
    for (vtkIdType tuples : { 0, 2 })
    {
      vtkSmartPointer<vtkPolyData> strokes = Strokes({ 0, 1, 2 });
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      a->SetNumberOfComponents(std::string(name) == "Color" ? 3 : 1);
      a->SetNumberOfTuples(tuples);
      a->Fill(0.2);
      strokes->GetPointData()->AddArray(a);
      vtkIdType samples = -1;
      const std::string errors = Paint(ofb, strokes, samples);
      EXPECT_NE(
        errors.find("'" + std::string(name) + "' has " + std::to_string(tuples)), std::string::npos)
        << errors;
      EXPECT_EQ(samples, 0);
    }
  }
}
