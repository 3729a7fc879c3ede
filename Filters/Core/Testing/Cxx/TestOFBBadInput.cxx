// Bad input to the CPU sampler: a clear error and an empty output, never a crash.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTimerLog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace vtkofbtest;

namespace
{
/// Build with `resolution` and return the errors; the output must be empty on error.
std::string BuildErrors(vtkPolyData* input,
  int resolution,
  vtkIdType limitMiB = 8192,
  vtkIdType* samples = nullptr,
  std::string* warnings = nullptr)
{
  vtkNew<vtkOFBSampler> sampler;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(sampler);
  sampler->SetInputData(input);
  sampler->SetResolution(resolution);
  sampler->SetMemoryLimit(limitMiB);
  sampler->Update();
  const std::string errors = observer->Errors;
  if (warnings)
  {
    *warnings = observer->Warnings;
  }
  if (samples)
  {
    *samples = sampler->GetOutput()->GetNumberOfSamples();
  }
  if (!errors.empty())
  {
    EXPECT_EQ(sampler->GetOutput()->GetNumberOfSamples(), 0);
    EXPECT_EQ(sampler->GetOutput()->GetNumberOfCells(), 0);
  }
  observer->Delete();
  return errors;
}

vtkSmartPointer<vtkPolyData> Triangle(double x0, double y0, double z0)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(x0, y0, z0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, ids);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}
}

TEST(BadInput, EmptyPolyData)
{
  vtkNew<vtkPolyData> empty;
  EXPECT_NE(BuildErrors(empty, 64).find("empty"), std::string::npos);
}

TEST(BadInput, NaNAndInfCoordinates)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(BuildErrors(Triangle(nan, 0, 0), 64).find("non-finite"), std::string::npos);
  EXPECT_NE(BuildErrors(Triangle(0, inf, 0), 64).find("non-finite"), std::string::npos);
  EXPECT_NE(BuildErrors(Triangle(0, 0, -inf), 64).find("non-finite"), std::string::npos);
}

TEST(BadInput, CoordinatesWhoseExtentOverflowsAreNamedAsSuch)
{
  // Finite doubles (a float vtkPoints would turn them into infinities) whose extent is not.
  vtkSmartPointer<vtkPolyData> huge = Triangle(0, 0, 0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(-1e308, 0, 0);
  points->InsertNextPoint(1e308, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  huge->SetPoints(points);
  const std::string errors = BuildErrors(huge, 64);
  EXPECT_NE(errors.find("overflow"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("degenerate"), std::string::npos) << errors;
}

TEST(BadInput, OnlyLinesAndVertices)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[2] = { 0, 1 };
  lines->InsertNextCell(2, ids);
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell(1, ids);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->SetVerts(verts);
  std::string warnings;
  const std::string errors = BuildErrors(poly, 64, 8192, nullptr, &warnings);
  EXPECT_NE(errors.find("no polygons"), std::string::npos);
  EXPECT_NE(warnings.find("Ignoring 1 lines and 1 vertices"), std::string::npos);
}

TEST(BadInput, ZeroAreaTrianglesAreSkipped)
{
  vtkSmartPointer<vtkPolyData> poly = Triangle(0, 0, 0);
  // Add a degenerate triangle (collinear points) and one with a repeated point.
  poly->GetPoints()->InsertNextPoint(2, 0, 0);
  const vtkIdType collinear[3] = { 0, 1, 3 };
  const vtkIdType repeated[3] = { 1, 1, 2 };
  poly->GetPolys()->InsertNextCell(3, collinear);
  poly->GetPolys()->InsertNextCell(3, repeated);
  vtkIdType samples = 0;
  std::string warnings;
  EXPECT_EQ(BuildErrors(poly, 64, 8192, &samples, &warnings), "");
  EXPECT_GT(samples, 0);
  EXPECT_NE(warnings.find("Skipped 2 zero-area triangles"), std::string::npos);

  // Only zero-area triangles: nothing to sample.
  vtkSmartPointer<vtkPolyData> flat = Triangle(0, 0, 0);
  flat->GetPoints()->SetPoint(2, 2, 0, 0);
  EXPECT_NE(BuildErrors(flat, 64).find("no triangle of non-zero area"), std::string::npos);
}

TEST(BadInput, ResolutionOutOfRange)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  EXPECT_NE(BuildErrors(sphere, 0).find("Resolution"), std::string::npos);
  EXPECT_NE(BuildErrors(sphere, -5).find("Resolution"), std::string::npos);
  EXPECT_NE(BuildErrors(sphere, 2).find("Resolution"), std::string::npos);
  EXPECT_NE(BuildErrors(sphere, 1 << 20).find("Resolution"), std::string::npos);
  EXPECT_EQ(BuildErrors(sphere, 3), "");
}

TEST(BadInput, MemoryLimitStopsBeforeAllocating)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  // 65536^2 cells per grid: tens of GiB. The error must come at once, before any
  // allocation of that size (which would take seconds or fail).
  const double start = vtkTimerLog::GetUniversalTime();
  const std::string errors = BuildErrors(sphere, 65536, 256);
  const double seconds = vtkTimerLog::GetUniversalTime() - start;
  EXPECT_NE(errors.find("memory limit"), std::string::npos);
  EXPECT_LT(seconds, 5.0) << "the limit must be checked before allocating";
  // The same surface within the limit builds.
  EXPECT_EQ(BuildErrors(sphere, 128, 256), "");
}

TEST(BadInput, ChosenVectorArrayMissingOrWrongShape)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  vtkNew<vtkOFBSampler> sampler;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(sampler);
  sampler->SetInputData(sphere);
  sampler->SetResolution(32);
  sampler->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Nope");
  sampler->Update();
  EXPECT_NE(observer->Errors.find("vector field"), std::string::npos);
  EXPECT_EQ(sampler->GetOutput()->GetNumberOfSamples(), 0);
  observer->Delete();
}

TEST(BadInput, PointArraysShorterThanThePoints)
{
  // vtkPolyData does not enforce one tuple a point. A short vector field is an error (its
  // interpolation would read past its end); a short colour or other point array is left
  // out with a warning naming it.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  const vtkIdType n = sphere->GetNumberOfPoints();
  auto shortArray = [n](const char* name, int components, int type)
  {
    vtkSmartPointer<vtkDataArray> a =
      vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(n / 2);
    a->Fill(1.0);
    return a;
  };
  vtkSmartPointer<vtkDataArray> vectors = shortArray("Flow", 3, VTK_FLOAT);
  sphere->GetPointData()->SetVectors(vectors);
  std::string errors = BuildErrors(sphere, 32);
  EXPECT_NE(errors.find("'Flow'"), std::string::npos) << errors;
  EXPECT_NE(errors.find("tuples"), std::string::npos) << errors;

  sphere->GetPointData()->RemoveArray("Flow");
  sphere->GetPointData()->SetScalars(shortArray("Colors", 3, VTK_UNSIGNED_CHAR));
  sphere->GetPointData()->AddArray(shortArray("Pressure", 1, VTK_DOUBLE));
  vtkNew<vtkOFBSampler> sampler;
  vtkNew<MessageObserver> observer;
  observer->Watch(sampler);
  sampler->SetInputData(sphere);
  sampler->SetResolution(32);
  sampler->Update();
  EXPECT_TRUE(observer->Errors.empty()) << observer->Errors;
  EXPECT_NE(observer->Warnings.find("'Colors'"), std::string::npos) << observer->Warnings;
  EXPECT_NE(observer->Warnings.find("'Pressure'"), std::string::npos) << observer->Warnings;
  vtkOFB* ofb = sampler->GetOutput();
  ASSERT_GT(ofb->GetNumberOfSamples(), 0);
  EXPECT_EQ(ofb->GetSampleData()->GetArray("Pressure"), nullptr);
  // The samples take DefaultColor (opaque white by default), not the short array's values.
  vtkDataArray* colors = ofb->GetSampleData()->GetArray("Colors");
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->GetRange(0)[0], 255.0);
}
