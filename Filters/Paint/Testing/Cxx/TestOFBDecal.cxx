// vtkOFBDecalPatch: the surface-aligned grid of a decal (paper Fig. 12) on a plane (the
// flat grid exactly) and a sphere (geodesic spacing), a stamp through
// vtkOFBTextureProjector, bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

using namespace vtkofbtest;

namespace
{
vtkPolyData* Patch(vtkOFBDecalPatch* decal, vtkPolyData* surface)
{
  decal->SetInputData(surface);
  decal->Update();
  return decal->GetOutput();
}
}

//------------------------------------------------------------------------------
TEST(DecalPatch, PlaneGivesTheFlatGrid)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(20, 20);
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->Update();
  vtkNew<vtkOFBDecalPatch> decal;
  decal->SetCenter(0.1, 0.2, 0.3); // moved onto the plane
  decal->SetDirection(1.0, 1.0, 0.5);
  decal->SetWidth(1.0);
  decal->SetHeight(0.5);
  decal->SetResolution(8, 4);
  vtkPolyData* patch = Patch(decal, plane->GetOutput());
  ASSERT_EQ(patch->GetNumberOfPoints(), 9 * 5);
  EXPECT_EQ(patch->GetNumberOfPolys(), 2 * 8 * 4);
  const double s = std::sqrt(0.5);
  const double u[3] = { s, s, 0.0 }, v[3] = { -s, s, 0.0 }; // v = n x u
  vtkDataArray* tc = patch->GetPointData()->GetTCoords();
  ASSERT_NE(tc, nullptr);
  for (int j = 0; j <= 4; ++j)
  {
    for (int i = 0; i <= 8; ++i)
    {
      const vtkIdType id = j * 9 + i;
      double x[3];
      patch->GetPoint(id, x);
      for (int c = 0; c < 3; ++c)
      {
        const double expected = (c == 0 ? 0.1 : (c == 1 ? 0.2 : 0.0)) + (i / 8.0 - 0.5) * u[c] +
          (j / 4.0 - 0.5) * 0.5 * v[c];
        ASSERT_NEAR(x[c], expected, 1e-6) << i << " " << j; // float rates in the walker
      }
      EXPECT_DOUBLE_EQ(tc->GetComponent(id, 0), i / 8.0);
      EXPECT_DOUBLE_EQ(tc->GetComponent(id, 1), j / 4.0);
    }
  }
  // The triangles turn as the plane's normal (+z).
  double a[3], b[3], c[3];
  patch->GetPoint(0, a);
  patch->GetPoint(1, b);
  patch->GetPoint(10, c);
  double ab[3], ac[3], n[3];
  vtkMath::Subtract(b, a, ab);
  vtkMath::Subtract(c, a, ac);
  vtkMath::Cross(ab, ac, n);
  EXPECT_GT(n[2], 0.0);
}

//------------------------------------------------------------------------------
TEST(DecalPatch, SphereGridFollowsTheSurface)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 64);
  vtkNew<vtkOFBDecalPatch> decal;
  decal->SetCenter(0.0, 0.0, 1.5);
  decal->SetDirection(1.0, 0.0, 0.0);
  decal->SetWidth(1.0);
  decal->SetHeight(1.0);
  decal->SetResolution(10, 10);
  vtkPolyData* patch = Patch(decal, sphere);
  ASSERT_EQ(patch->GetNumberOfPoints(), 121);
  auto point = [&](int i, int j)
  {
    double x[3];
    patch->GetPoint(j * 11 + i, x);
    return std::array<double, 3>{ x[0], x[1], x[2] };
  };
  // The central row and column end half a width along great circles from the top.
  const double s = std::sin(0.5), c = std::cos(0.5);
  const std::array<double, 3> ends[4] = { point(10, 5), point(0, 5), point(5, 10), point(5, 0) };
  const double expected[4][3] = { { s, 0, c }, { -s, 0, c }, { 0, s, c }, { 0, -s, c } };
  for (int k = 0; k < 4; ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(ends[k][a], expected[k][a], 5e-3) << k;
    }
  }
  // Every point on the sphere; neighbours along each column a tenth apart (geodesic).
  for (int j = 0; j <= 10; ++j)
  {
    for (int i = 0; i <= 10; ++i)
    {
      const std::array<double, 3> x = point(i, j);
      EXPECT_NEAR(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), 1.0, 1e-3);
      if (j > 0)
      {
        const std::array<double, 3> y = point(i, j - 1);
        const double d = std::sqrt(vtkMath::Distance2BetweenPoints(x.data(), y.data()));
        EXPECT_NEAR(d, 0.1, 1e-3) << i << " " << j;
      }
    }
  }
}

//------------------------------------------------------------------------------
TEST(DecalPatch, StampsAnImageThroughTheProjector)
{
  // A 0.8 x 0.4 decal on top of a sphere, red on its left half, blue on its right.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 64);
  vtkSmartPointer<vtkOFB> ofb = Build(sphere, 128);
  vtkNew<vtkOFBDecalPatch> decal;
  decal->SetInputData(sphere);
  decal->SetCenter(0.0, 0.0, 1.0);
  decal->SetWidth(0.8);
  decal->SetHeight(0.4);
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 1, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* texels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  const unsigned char red[4] = { 255, 0, 0, 255 }, blue[4] = { 0, 0, 255, 255 };
  texels->SetTypedTuple(0, red);
  texels->SetTypedTuple(1, blue);
  vtkNew<vtkOFBTextureProjector> projector;
  projector->SetInputData(ofb);
  projector->SetMeshConnection(decal->GetOutputPort());
  projector->SetTextureData(image);
  projector->InterpolateTextureOff();
  projector->RepeatTextureOff(); // u = 1 on the right edge is the last texel, not the first
  projector->SetMaximumDistance(0.5);
  projector->Update();
  vtkOFB* out = projector->GetOutput();
  auto* colors = vtkUnsignedCharArray::SafeDownCast(out->GetSampleData()->GetArray("Colors"));
  const double cell = ofb->GetCellSize();
  vtkIdType painted = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfSamples(); ++i)
  {
    double x[3];
    out->GetSamplePosition(i, x);
    const unsigned char* rgba = colors->GetPointer(4 * i);
    const bool isRed = rgba[0] == 255 && rgba[1] == 0;
    const bool isBlue = rgba[2] == 255 && rgba[1] == 0;
    // Along the surface: the angles from the top in x and y are the geodesic offsets.
    const double gu = std::atan2(x[0], x[2]), gv = std::atan2(x[1], x[2]);
    if (isRed || isBlue)
    {
      ++painted;
      EXPECT_LT(std::abs(gu), 0.4 + 2.0 * cell) << i;
      EXPECT_LT(std::abs(gv), 0.2 + 2.0 * cell) << i;
      EXPECT_TRUE(isRed ? gu < cell : gu > -cell) << i;
    }
    else if (x[2] > 0.0 && std::abs(gu) < 0.35 && std::abs(gv) < 0.15)
    {
      ADD_FAILURE() << "sample " << i << " inside the decal was not stamped";
    }
  }
  // About the decal's area (0.32) in samples: a sphere's samples cover 4 pi.
  const double share = painted / static_cast<double>(out->GetNumberOfSamples());
  EXPECT_NEAR(share, 0.32 / (4.0 * vtkMath::Pi()), 0.006);
}

//------------------------------------------------------------------------------
TEST(DecalPatch, BadInput)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 16);
  vtkNew<MessageObserver> o;
  auto expectError =
    [&](const std::function<void(vtkOFBDecalPatch*)>& set, vtkPolyData* surface, const char* words)
  {
    o->Clear();
    vtkNew<vtkOFBDecalPatch> decal;
    o->Watch(decal);
    decal->SetCenter(0.0, 0.0, 1.0);
    decal->SetDirection(1.0, 0.0, 0.0);
    set(decal);
    vtkPolyData* patch = Patch(decal, surface);
    EXPECT_NE(o->Errors.find(words), std::string::npos) << words << ": " << o->Errors;
    EXPECT_EQ(patch->GetNumberOfPoints(), 0);
  };
  const double nan = std::nan("");
  expectError([&](vtkOFBDecalPatch* d) { d->SetCenter(nan, 0, 1); }, sphere, "Center");
  expectError([](vtkOFBDecalPatch* d) { d->SetWidth(0.0); }, sphere, "positive");
  expectError([&](vtkOFBDecalPatch* d) { d->SetHeight(nan); }, sphere, "positive");
  expectError([](vtkOFBDecalPatch* d) { d->SetHeight(HUGE_VAL); }, sphere, "positive");
  expectError([](vtkOFBDecalPatch* d) { d->SetDirection(0, 0, 0); }, sphere, "Direction");
  vtkNew<vtkPlaneSource> plane; // normal +z
  plane->Update();
  expectError([](vtkOFBDecalPatch* d) { d->SetDirection(0, 0, 1); }, plane->GetOutput(), "normal");
  expectError([](vtkOFBDecalPatch* d) { d->SetResolution(0, 4); }, sphere, "Resolution");
  expectError([](vtkOFBDecalPatch* d) { d->SetResolution(8, 100000); }, sphere, "Resolution");
  expectError([](vtkOFBDecalPatch*) {}, vtkNew<vtkPolyData>(), "cannot carry");
  // A decal larger than the sphere wraps around it without failing.
  o->Clear();
  vtkNew<vtkOFBDecalPatch> big;
  o->Watch(big);
  big->SetWidth(10.0);
  big->SetHeight(10.0);
  vtkPolyData* patch = Patch(big, sphere);
  EXPECT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_EQ(patch->GetNumberOfPoints(), 33 * 33);
}

//------------------------------------------------------------------------------
TEST(DecalPatch, MeshWithPointsRepeatedPerFace)
{
  // An OBJ with texture coordinates repeats its points per face (vtkOBJReader): the
  // patch merges them, or each walk would stop at the first edge it meets.
  vtkSmartPointer<vtkPolyData> spot = ReadMesh("spot.obj");
  ASSERT_EQ(spot->GetNumberOfPoints(), 3 * spot->GetNumberOfPolys());
  vtkNew<vtkOFBDecalPatch> decal;
  decal->SetCenter(0.45, 0.1, 0.1); // on the flank
  decal->SetDirection(0.0, 0.0, 1.0);
  decal->SetWidth(0.6);
  decal->SetHeight(0.4);
  decal->SetResolution(12, 8);
  vtkPolyData* patch = Patch(decal, spot);
  ASSERT_EQ(patch->GetNumberOfPoints(), 13 * 9);
  // The central row and column span about the width and the height (chords of a curved
  // flank, so a little less).
  double a[3], b[3];
  patch->GetPoint(4 * 13 + 0, a);
  patch->GetPoint(4 * 13 + 12, b);
  EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(a, b)), 0.6, 0.06);
  patch->GetPoint(0 * 13 + 6, a);
  patch->GetPoint(8 * 13 + 6, b);
  EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(a, b)), 0.4, 0.04);
}
