// vtkOFBTextureProjector: a mesh's UV texture into an OFB's colours (nearest and bilinear
// texels, alpha and opacity, a round trip through vtkOFBTextureBaker on spot), bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureBaker.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vtkofbtest;

namespace
{
/// The textured plane of the tests.
vtkSmartPointer<vtkPolyData> Plane()
{
  return MakeTexturedPlane(5);
}

/// A w x h image of `components` unsigned char components, texel (i, j) from `value`.
template<typename Value>
vtkSmartPointer<vtkImageData> Image(int w, int h, int components, Value value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
  auto* texels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      for (int c = 0; c < components; ++c)
      {
        texels->SetTypedComponent(j * w + i, c, value(i, j, c));
      }
    }
  }
  return image;
}

vtkOFB* Project(vtkOFBTextureProjector* projector,
  vtkOFB* ofb,
  vtkPolyData* mesh,
  vtkImageData* image)
{
  projector->SetInputData(ofb);
  projector->SetMeshData(mesh);
  projector->SetTextureData(image);
  projector->Update();
  return projector->GetOutput();
}

vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}
}

//------------------------------------------------------------------------------
TEST(TextureProjector, NearestTexelsOnAPlane)
{
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  std::vector<int> values(7 * 5 * 3);
  for (int& v : values)
  {
    v = static_cast<int>(random->GetNextRangeValue(0.0, 255.0));
  }
  auto image = Image(7, 5, 3, [&](int i, int j, int c) { return values[(j * 7 + i) * 3 + c]; });
  std::vector<unsigned char> before(
    Colors(ofb)->GetPointer(0), Colors(ofb)->GetPointer(0) + 4 * ofb->GetNumberOfSamples());
  vtkNew<vtkOFBTextureProjector> projector;
  projector->InterpolateTextureOff();
  vtkOFB* out = Project(projector, ofb, plane, image);
  ASSERT_EQ(out->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  EXPECT_EQ(projector->GetNumberOfProjectedSamples(), ofb->GetNumberOfSamples());
  EXPECT_EQ(out->GetSampleData()->GetScalars(), Colors(out));
  EXPECT_EQ(out->GetSampleData()->GetArray("Normals"), ofb->GetSampleData()->GetArray("Normals"));
  int checked = 0;
  for (vtkIdType s = 0; s < out->GetNumberOfSamples(); ++s)
  {
    double x[3];
    out->GetSamplePosition(s, x);
    const double u = 7.0 * (x[0] + 1.0) / 2.0, v = 5.0 * (x[1] + 1.0) / 2.0;
    if (std::abs(u - std::round(u)) < 1e-6 || std::abs(v - std::round(v)) < 1e-6)
    {
      continue; // on a texel boundary
    }
    const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(Colors(out)->GetValue(4 * s + c), values[(j * 7 + i) * 3 + c]) << s;
    }
    ASSERT_EQ(Colors(out)->GetValue(4 * s + 3), 255);
    ++checked;
  }
  EXPECT_GT(checked, out->GetNumberOfSamples() * 9 / 10);
  // The input is untouched.
  EXPECT_TRUE(std::equal(before.begin(), before.end(), Colors(ofb)->GetPointer(0)));
}

//------------------------------------------------------------------------------
TEST(TextureProjector, BilinearAlphaAndOpacity)
{
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 64);
  // Grey 0 and 255 side by side, clamped: bilinear across the middle half.
  auto ramp = Image(2, 1, 1, [](int i, int, int) { return i == 0 ? 0 : 255; });
  vtkNew<vtkOFBTextureProjector> bilinear;
  bilinear->RepeatTextureOff();
  vtkOFB* out = Project(bilinear, ofb, plane, ramp);
  for (vtkIdType s = 0; s < out->GetNumberOfSamples(); ++s)
  {
    double x[3];
    out->GetSamplePosition(s, x);
    const double u = (x[0] + 1.0) / 2.0;
    const double expected = 255.0 * std::min(1.0, std::max(0.0, 2.0 * u - 0.5));
    ASSERT_NEAR(Colors(out)->GetValue(4 * s), expected, 1.0) << u;
    ASSERT_EQ(Colors(out)->GetValue(4 * s), Colors(out)->GetValue(4 * s + 2));
  }
  // Red, opaque, on the left; blue, transparent, on the right; at half opacity.
  auto halves = Image(2,
    1,
    4,
    [](int i, int, int c) { return i == 0 ? (c == 0 || c == 3 ? 255 : 0) : (c == 2 ? 255 : 0); });
  vtkNew<vtkOFBTextureProjector> composite;
  composite->InterpolateTextureOff();
  composite->SetOpacity(0.5);
  out = Project(composite, ofb, plane, halves);
  for (vtkIdType s = 0; s < out->GetNumberOfSamples(); ++s)
  {
    double x[3];
    out->GetSamplePosition(s, x);
    const unsigned char* c = Colors(out)->GetPointer(4 * s);
    if (x[0] < -1e-6)
    {
      ASSERT_EQ(c[0], 255); // white half covered by red: (255, 128, 128)
      ASSERT_EQ(c[1], 128);
      ASSERT_EQ(c[2], 128);
    }
    else if (x[0] > 1e-6)
    {
      ASSERT_EQ(c[0], 255); // untouched white
      ASSERT_EQ(c[1], 255);
      ASSERT_EQ(c[2], 255);
    }
  }
}

//------------------------------------------------------------------------------
TEST(TextureProjector, RoundTripThroughTheBaker)
{
  // Spot painted, its paint baked into a texture and projected back into the unpainted
  // OFB: the paint comes back but for texel-sized differences at its edges.
  vtkSmartPointer<vtkPolyData> spot = ReadMesh("spot.obj");
  vtkSmartPointer<vtkOFB> plain = Build(spot, 256);
  vtkNew<vtkOFB> painted;
  painted->DeepCopy(plain);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(painted);
  painter->GetBrush()->SetRadius(0.12);
  painter->GetBrush()->SetFalloffToConstant();
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  for (int k = 0; k < 12; ++k)
  {
    painter->GetBrush()->SetColor(random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0));
    double x[3];
    painted->GetSamplePosition(
      static_cast<vtkIdType>(random->GetNextRangeValue(0.0, painted->GetNumberOfSamples() - 1)), x);
    painter->Dab(x);
  }
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetInputData(spot);
  baker->SetOFBData(painted);
  baker->SetTextureSize(1024, 1024);
  baker->Update();
  vtkNew<vtkOFBTextureProjector> projector;
  vtkOFB* back = Project(projector, plain, spot, baker->GetOutput());
  vtkIdType paintedSamples = 0, close = 0, closePainted = 0;
  for (vtkIdType s = 0; s < back->GetNumberOfSamples(); ++s)
  {
    const unsigned char* a = Colors(painted)->GetPointer(4 * s);
    const unsigned char* b = Colors(back)->GetPointer(4 * s);
    int error = 0;
    for (int c = 0; c < 4; ++c)
    {
      error = std::max(error, std::abs(a[c] - b[c]));
    }
    const bool isPainted = a[0] != 255 || a[1] != 255 || a[2] != 255;
    paintedSamples += isPainted;
    close += error <= 8;
    closePainted += isPainted && error <= 8;
  }
  const vtkIdType n = back->GetNumberOfSamples();
  std::cout << "round trip: " << close << " of " << n << " samples within 8 levels, "
            << closePainted << " of " << paintedSamples << " painted ones\n";
  EXPECT_GT(paintedSamples, n / 50);
  EXPECT_GT(close, 0.97 * n);
  EXPECT_GT(closePainted, 0.9 * paintedSamples);
}

//------------------------------------------------------------------------------
TEST(TextureProjector, BadInput)
{
  vtkSmartPointer<vtkPolyData> plane = Plane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  auto image = Image(4, 4, 3, [](int, int, int) { return 100; });
  vtkNew<MessageObserver> o;
  auto expectError =
    [&](vtkOFB* in, vtkPolyData* mesh, vtkImageData* texture, double distance, const char* words)
  {
    o->Clear();
    vtkNew<vtkOFBTextureProjector> projector;
    o->Watch(projector);
    projector->SetMaximumDistance(distance);
    vtkOFB* out = Project(projector, in, mesh, texture);
    EXPECT_NE(o->Errors.find(words), std::string::npos) << words << ": " << o->Errors;
    EXPECT_EQ(out->GetNumberOfSamples(), 0);
  };
  expectError(vtkNew<vtkOFB>(), plane, image, 2.0, "no samples");
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(plane);
  bare->GetPointData()->SetTCoords(nullptr);
  expectError(ofb, bare, image, 2.0, "texture coordinates");
  // Unsigned char, unsigned short and float texels are taken; doubles (or ints) are not.
  auto doubles = vtkSmartPointer<vtkImageData>::New();
  doubles->SetDimensions(4, 4, 1);
  doubles->AllocateScalars(VTK_DOUBLE, 3);
  expectError(ofb, plane, doubles, 2.0, "unsigned char, unsigned short or float");
  auto five = Image(2, 2, 5, [](int, int, int) { return 0; });
  expectError(ofb, plane, five, 2.0, "unsigned char");
  for (double distance : { 0.0, -1.0, std::nan(""), HUGE_VAL })
  {
    expectError(ofb, plane, image, distance, "MaximumDistance");
  }
  // Non-finite and huge texture coordinates: no crash, defined colours.
  vtkNew<vtkPolyData> odd;
  odd->DeepCopy(plane);
  odd->GetPointData()->GetTCoords()->SetComponent(0, 0, std::nan(""));
  odd->GetPointData()->GetTCoords()->SetComponent(1, 1, 1e300);
  o->Clear();
  vtkNew<vtkOFBTextureProjector> projector;
  o->Watch(projector);
  vtkOFB* out = Project(projector, ofb, odd, image);
  EXPECT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_GT(projector->GetNumberOfProjectedSamples(), out->GetNumberOfSamples() / 2);
}
