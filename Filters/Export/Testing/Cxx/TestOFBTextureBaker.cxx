// vtkOFBTextureBaker: OFB sample arrays baked into UV textures, against the OFB's own
// lookups; padding; a real UV atlas (spot); bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBPainter.h"
#include "vtkOFBProbeFilter.h"
#include "vtkOFBSampler.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <vector>

using namespace vtkofbtest;

namespace
{
/// The textured plane of the tests.
vtkSmartPointer<vtkPolyData> Plane()
{
  return MakeTexturedPlane(8);
}

/// Paint random dabs on `ofb`, and add a float array "X", the x of each sample.
void PaintAndMarkX(vtkOFB* ofb, double radius, double bound)
{
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(radius);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(3);
  for (int k = 0; k < 10; ++k)
  {
    painter->GetBrush()->SetColor(random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0));
    const double p[3] = { random->GetNextRangeValue(-bound, bound),
      random->GetNextRangeValue(-bound, bound),
      random->GetNextRangeValue(-bound, bound) };
    const vtkIdType id = ofb->FindClosestSample(p, HUGE_VAL);
    double x[3];
    ofb->GetSamplePosition(id, x);
    painter->Dab(x);
  }
  AddCoordinateArray(ofb, "X", 0);
}

vtkImageData* Bake(vtkOFBTextureBaker* baker, vtkPolyData* mesh, vtkOFB* ofb, int w, int h)
{
  baker->SetInputData(mesh);
  baker->SetOFBData(ofb);
  baker->SetTextureSize(w, h);
  baker->Update();
  return baker->GetOutput();
}
}

//------------------------------------------------------------------------------
TEST(TextureBaker, PlaneTexelsAreTheClosestSamples)
{
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 128);
  PaintAndMarkX(ofb, 0.4, 0.9);
  vtkNew<vtkOFBTextureBaker> baker;
  vtkImageData* image = Bake(baker, plane, ofb, 64, 48);
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 64);
  ASSERT_EQ(dims[1], 48);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  ASSERT_NE(colors, nullptr);
  EXPECT_STREQ(colors->GetName(), "Colors");
  EXPECT_EQ(baker->GetNumberOfBakedTexels(), 64 * 48);
  auto* samples = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  int painted = 0;
  for (int j = 0; j < 48; ++j)
  {
    for (int i = 0; i < 64; ++i)
    {
      // Texel (i, j) is texture coordinate ((i + 0.5) / w, (j + 0.5) / h).
      const double x[3] = { -1.0 + 2.0 * (i + 0.5) / 64, -1.0 + 2.0 * (j + 0.5) / 48, 0.0 };
      const vtkIdType id = ofb->FindClosestSample(x);
      ASSERT_GE(id, 0);
      const vtkIdType t = j * 64 + i;
      for (int c = 0; c < 4; ++c)
      {
        ASSERT_EQ(colors->GetValue(4 * t + c), samples->GetValue(4 * id + c)) << i << " " << j;
      }
      painted += colors->GetValue(4 * t + 1) != 255;
      EXPECT_EQ(image->GetPointData()->GetArray("vtkValidPointMask")->GetComponent(t, 0), 1.0);
    }
  }
  EXPECT_GT(painted, 100);
}

//------------------------------------------------------------------------------
TEST(TextureBaker, DefaultBakesTheActiveScalarsElseThePaint)
{
  // A sampled field that is the active scalars (as a mesh's active cell scalars become)
  // is what the baker writes by default; without active scalars, the paint.
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  PaintAndMarkX(ofb, 0.4, 0.9);
  ofb->GetSampleData()->SetActiveScalars("X");
  vtkNew<vtkOFBTextureBaker> baker;
  vtkImageData* image = Bake(baker, plane, ofb, 16, 16);
  vtkDataArray* baked = image->GetPointData()->GetScalars();
  ASSERT_NE(baked, nullptr);
  EXPECT_STREQ(baked->GetName(), "X");
  EXPECT_EQ(baked->GetNumberOfComponents(), 1);

  ofb->GetSampleData()->SetActiveScalars(nullptr);
  baker->Modified();
  image = Bake(baker, plane, ofb, 16, 16);
  baked = image->GetPointData()->GetScalars();
  ASSERT_NE(baked, nullptr);
  EXPECT_STREQ(baked->GetName(), vtkOFB::ColorsArrayName());
  EXPECT_EQ(baked->GetNumberOfComponents(), 4);
}

//------------------------------------------------------------------------------
TEST(TextureBaker, PaddingFillsAroundUVIslands)
{
  // The texture coordinates cover [0.25, 0.75]^2 only.
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkDataArray* tc = plane->GetPointData()->GetTCoords();
  for (vtkIdType p = 0; p < tc->GetNumberOfTuples(); ++p)
  {
    tc->SetComponent(p, 0, 0.25 + 0.5 * tc->GetComponent(p, 0));
    tc->SetComponent(p, 1, 0.25 + 0.5 * tc->GetComponent(p, 1));
  }
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetArrayName("Normals");
  baker->SetPadding(3);
  vtkImageData* image = Bake(baker, plane, ofb, 40, 40);
  vtkDataArray* normals = image->GetPointData()->GetArray("Normals");
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  ASSERT_NE(normals, nullptr);
  EXPECT_EQ(baker->GetNumberOfBakedTexels(), 20 * 20); // texels 10..29 in each direction
  for (int j = 0; j < 40; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      const vtkIdType t = j * 40 + i;
      const int ring = std::max({ 10 - i, i - 29, 10 - j, j - 29, 0 });
      EXPECT_EQ(mask->GetComponent(t, 0), ring == 0 ? 1.0 : 0.0) << i << " " << j;
      // Covered and padded texels hold the plane's normal, the others zero.
      EXPECT_NEAR(normals->GetComponent(t, 2), ring <= 3 ? 1.0 : 0.0, 1e-6) << i << " " << j;
    }
  }
}

//------------------------------------------------------------------------------
TEST(TextureBaker, TrianglesBetweenTexelCentresGetTheTexelUnderTheirCentroid)
{
  // A triangle on three corners of each quad of the plane, shrunk in UV space to a speck
  // that holds no texel centre: it still bakes the texel under it (the sample at its
  // centroid), and only that one.
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 128);
  PaintAndMarkX(ofb, 0.4, 0.9);
  const int size = 256;
  vtkNew<vtkPolyData> specks;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  std::vector<std::array<int, 2>> expected;
  auto iter = vtk::TakeSmartPointer(plane->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* ids;
    iter->GetCurrentCell(npts, ids);
    ASSERT_GE(npts, 3);
    double centre[2] = { 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      double uv[2];
      plane->GetPointData()->GetTCoords()->GetTuple(ids[k], uv);
      centre[0] += uv[0] / 3.0;
      centre[1] += uv[1] / 3.0;
    }
    // The speck's texel: the one whose centre is closest to the centroid; the speck is
    // moved into the texel's quarter away from its centre so it covers no centre.
    const int i = std::min(size - 1, static_cast<int>(centre[0] * size));
    const int j = std::min(size - 1, static_cast<int>(centre[1] * size));
    expected.push_back({ i, j });
    const double u = (i + 0.7) / size;
    const double v = (j + 0.7) / size;
    vtkIdType corner[3];
    for (int k = 0; k < 3; ++k)
    {
      double x[3];
      plane->GetPoint(ids[k], x);
      corner[k] = points->InsertNextPoint(x);
      const double d = 0.1 / size;
      tcoords->InsertNextTuple2(u + (k == 1 ? d : 0.0), v + (k == 2 ? d : 0.0));
    }
    triangles->InsertNextCell(3, corner);
  }
  specks->SetPoints(points);
  specks->SetPolys(triangles);
  specks->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetPadding(0);
  baker->SetArrayName("X");
  vtkImageData* image = Bake(baker, specks, ofb, size, size);
  vtkDataArray* x = image->GetPointData()->GetArray("X");
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(baker->GetNumberOfBakedTexels(), static_cast<vtkIdType>(expected.size()));
  vtkIdType t = 0;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++t)
  {
    // The triangle's centroid in space: the value baked is the closest sample's x.
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      points->GetPoint(3 * t + k, p);
      for (int c = 0; c < 3; ++c)
      {
        centroid[c] += p[c] / 3.0;
      }
    }
    const vtkIdType id = ofb->FindClosestSample(centroid);
    double y[3];
    ofb->GetSamplePosition(id, y);
    const vtkIdType texel = static_cast<vtkIdType>(expected[t][1]) * size + expected[t][0];
    EXPECT_EQ(mask->GetComponent(texel, 0), 1.0) << t;
    EXPECT_NEAR(x->GetComponent(texel, 0), y[0], 1e-6) << t;
  }
}

//------------------------------------------------------------------------------
TEST(TextureBaker, BakesSpotsUVAtlas)
{
  // A real atlas: islands, seams (points split in UV space). Every vertex's texel holds
  // about the vertex's own x (a flipped or shifted mapping would not).
  vtkSmartPointer<vtkPolyData> spot = ReadMesh("spot.obj");
  vtkSmartPointer<vtkOFB> ofb = Build(spot, 256);
  PaintAndMarkX(ofb, 0.1, 0.5);
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetArrayName("X");
  baker->SetLookupModeToSmooth();
  const int size = 512;
  vtkImageData* image = Bake(baker, spot, ofb, size, size);
  vtkDataArray* xs = image->GetPointData()->GetArray("X");
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  ASSERT_NE(xs, nullptr);
  EXPECT_GT(baker->GetNumberOfBakedTexels(), size * size / 4);
  vtkDataArray* tc = spot->GetPointData()->GetTCoords();
  int checked = 0, close = 0;
  for (vtkIdType p = 0; p < spot->GetNumberOfPoints(); ++p)
  {
    const int i = static_cast<int>(std::floor(tc->GetComponent(p, 0) * size));
    const int j = static_cast<int>(std::floor(tc->GetComponent(p, 1) * size));
    if (i < 0 || j < 0 || i >= size || j >= size || mask->GetComponent(j * size + i, 0) != 1.0)
    {
      continue; // a vertex on an island's border: its texel centre may lie outside
    }
    double x[3];
    spot->GetPoint(p, x);
    // A texel centre is up to 0.7 texel from the vertex: a few hundredths in the most
    // stretched parts of the atlas.
    const double error = std::abs(xs->GetComponent(j * size + i, 0) - x[0]);
    EXPECT_LT(error, 0.08) << "point " << p;
    close += error < 0.02;
    ++checked;
  }
  EXPECT_GT(checked, spot->GetNumberOfPoints() / 2);
  EXPECT_GT(close, 0.95 * checked);
  // The paint too (the default array).
  vtkNew<vtkOFBTextureBaker> colors;
  vtkImageData* painted = Bake(colors, spot, ofb, 256, 256);
  EXPECT_STREQ(painted->GetPointData()->GetScalars()->GetName(), "Colors");
  EXPECT_EQ(painted->GetPointData()->GetScalars()->GetNumberOfComponents(), 4);
}

//------------------------------------------------------------------------------
TEST(TextureBaker, BadInput)
{
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  vtkNew<MessageObserver> o;
  auto expectError =
    [&](vtkOFBTextureBaker* baker, vtkPolyData* mesh, vtkOFB* source, const char* words)
  {
    o->Clear();
    o->Watch(baker);
    Bake(baker, mesh, source, baker->GetTextureSize()[0], baker->GetTextureSize()[1]);
    EXPECT_NE(o->Errors.find(words), std::string::npos) << o->Errors;
    EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 0);
  };
  {
    vtkNew<vtkSphereSource> sphere; // no texture coordinates
    sphere->Update();
    vtkNew<vtkOFBTextureBaker> baker;
    expectError(baker, sphere->GetOutput(), ofb, "texture coordinates");
  }
  {
    vtkNew<vtkOFBTextureBaker> baker;
    expectError(baker, plane, vtkNew<vtkOFB>(), "empty");
  }
  for (int size : { 0, -3, 20000 })
  {
    vtkNew<vtkOFBTextureBaker> baker;
    baker->SetTextureSize(size, 16);
    expectError(baker, plane, ofb, "TextureSize");
  }
  for (double radius : { 0.0, std::nan(""), HUGE_VAL })
  {
    vtkNew<vtkOFBTextureBaker> baker;
    baker->SetTextureSize(16, 16);
    baker->SetRadius(radius);
    expectError(baker, plane, ofb, "Radius");
  }
  {
    vtkNew<vtkOFBTextureBaker> baker;
    baker->SetTextureSize(16, 16);
    baker->SetArrayName("NoSuchArray");
    expectError(baker, plane, ofb, "NoSuchArray");
  }
  // NaN and huge texture coordinates: those triangles are skipped, the others baked.
  vtkDataArray* tc = plane->GetPointData()->GetTCoords();
  tc->SetComponent(0, 0, std::nan(""));
  tc->SetComponent(1, 1, 1e30);
  o->Clear();
  vtkNew<vtkOFBTextureBaker> baker;
  o->Watch(baker);
  Bake(baker, plane, ofb, 32, 32);
  EXPECT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_GT(baker->GetNumberOfBakedTexels(), 32 * 32 / 2);
  EXPECT_LT(baker->GetNumberOfBakedTexels(), 32 * 32);
}

//------------------------------------------------------------------------------
TEST(TextureBaker, FeedsImagingFilters)
{
  // Downstream imaging filters read the scalars' type and components from the
  // pipeline information: an OFB from a connection (not yet built when the
  // information is asked) as well as one set as data.
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(plane);
  sampler->SetResolution(64);
  for (int connected = 0; connected < 2; ++connected)
  {
    vtkNew<vtkOFBTextureBaker> baker;
    baker->SetInputData(plane);
    if (connected)
    {
      baker->SetOFBConnection(sampler->GetOutputPort());
    }
    else
    {
      sampler->Update();
      baker->SetOFBData(sampler->GetOutput());
    }
    baker->SetTextureSize(32, 16);
    vtkNew<vtkImageExtractComponents> rgb;
    rgb->SetInputConnection(baker->GetOutputPort());
    rgb->SetComponents(0, 1, 2);
    vtkNew<MessageObserver> o;
    o->Watch(rgb);
    rgb->Update();
    EXPECT_TRUE(o->Errors.empty()) << o->Errors;
    vtkDataArray* scalars = rgb->GetOutput()->GetPointData()->GetScalars();
    ASSERT_NE(scalars, nullptr);
    EXPECT_EQ(scalars->GetNumberOfComponents(), 3);
    EXPECT_EQ(scalars->GetDataType(), VTK_UNSIGNED_CHAR);
    EXPECT_EQ(scalars->GetNumberOfTuples(), 32 * 16);
    EXPECT_EQ(scalars->GetComponent(0, 0), 255.0); // the sampler's default white
  }
}

//------------------------------------------------------------------------------
TEST(TextureBaker, MemoryLimitRefusesLargeTexturesBeforeAllocating)
{
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  vtkNew<vtkOFBTextureBaker> baker;
  EXPECT_EQ(baker->GetMemoryLimit(), 4096);
  // 16384 x 16384 RGBA: about 15 GiB, refused at once with the default limit.
  EXPECT_GT(vtkOFBTextureBaker::EstimateBakeBytes(16384, 16384, 4), vtkIdType(14) << 30);
  vtkNew<MessageObserver> o;
  o->Watch(baker);
  const auto start = std::chrono::steady_clock::now();
  Bake(baker, plane, ofb, 16384, 16384);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0);
  EXPECT_NE(o->Errors.find("MemoryLimit (4096 MiB)"), std::string::npos) << o->Errors;
  EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 0);
  // A lower limit refuses a smaller texture; under it the bake runs.
  baker->SetMemoryLimit(1);
  o->Clear();
  Bake(baker, plane, ofb, 256, 256);
  EXPECT_NE(o->Errors.find("MemoryLimit (1 MiB)"), std::string::npos) << o->Errors;
  baker->SetMemoryLimit(64);
  o->Clear();
  Bake(baker, plane, ofb, 256, 256);
  EXPECT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 256 * 256);
}

//------------------------------------------------------------------------------
TEST(TextureBaker, ExportFiltersWithoutInputs)
{
  vtkNew<vtkOFBTextureBaker> baker;
  vtkNew<vtkOFBTextureAtlas> atlas;
  vtkNew<vtkOFBProbeFilter> probe;
  vtkNew<vtkOFBMapToColors> map;
  for (vtkAlgorithm* algorithm : std::vector<vtkAlgorithm*>{ baker, atlas, probe, map })
  {
    vtkNew<MessageObserver> messages;
    messages->Watch(algorithm);
    messages->Watch(algorithm->GetExecutive());
    algorithm->Update();
    EXPECT_FALSE(messages->Errors.empty()) << algorithm->GetClassName();
  }
  // Only the mesh, or only the OFB.
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  for (int only = 0; only < 2; ++only)
  {
    vtkNew<vtkOFBTextureBaker> b;
    vtkNew<vtkOFBProbeFilter> p;
    vtkNew<vtkOFBTextureAtlas> a;
    for (vtkAlgorithm* algorithm : std::vector<vtkAlgorithm*>{ b, p, a })
    {
      vtkNew<MessageObserver> messages;
      messages->Watch(algorithm);
      messages->Watch(algorithm->GetExecutive());
      if (only == 0)
      {
        algorithm->SetInputDataObject(0, plane);
      }
      else
      {
        algorithm->SetInputDataObject(1, ofb);
      }
      algorithm->Update();
      EXPECT_FALSE(messages->Errors.empty()) << algorithm->GetClassName() << " " << only;
    }
  }
}
