// GoogleTest: the LIC is attached to the surface. The bunny's LIC is rendered from a
// camera, then after a 40-pixel pan and after a 20-degree rotation; at the same surface
// points (OFB sample positions projected with each camera, visible in both views) the
// high-pass images must correlate at 0.9 or more. A screen-space texture would not: the
// control compares the same pixels instead of the same surface points.
#include "vtkOFBLICRenderHelpers.h"

#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkOFBPyramid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vtkofbtest;

namespace
{
constexpr int Size = 512;
constexpr int Radius = 3; // of the box blur that the high pass subtracts

/// One rendered view: the high-pass grey image, the depth buffer and the camera.
struct View
{
  std::vector<float> HighPass;
  std::vector<float> Depth;
  std::vector<unsigned char> Interior; // surface pixels Radius + 1 away from any background
  double Matrix[16];
  double CameraPosition[3];
};

/// Box blur of radius r (separable, clamped at the image border).
std::vector<float> BoxBlur(const std::vector<float>& in, int r)
{
  std::vector<float> tmp(in.size()), out(in.size());
  for (int pass = 0; pass < 2; ++pass)
  {
    const std::vector<float>& src = pass == 0 ? in : tmp;
    std::vector<float>& dst = pass == 0 ? tmp : out;
    for (int y = 0; y < Size; ++y)
    {
      for (int x = 0; x < Size; ++x)
      {
        double sum = 0.0;
        for (int k = -r; k <= r; ++k)
        {
          const int xx = pass == 0 ? std::min(Size - 1, std::max(0, x + k)) : x;
          const int yy = pass == 1 ? std::min(Size - 1, std::max(0, y + k)) : y;
          sum += src[yy * Size + xx];
        }
        dst[y * Size + x] = static_cast<float>(sum / (2 * r + 1));
      }
    }
  }
  return out;
}

View Capture(LICScene& scene)
{
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(scene.Window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  const int nc = rgb->GetNumberOfComponents();
  std::vector<float> grey(Size * Size);
  for (int i = 0; i < Size * Size; ++i)
  {
    const unsigned char* p = rgb->GetPointer(nc * i);
    grey[i] = (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f;
  }
  View v;
  const std::vector<float> blur = BoxBlur(grey, Radius);
  v.HighPass.resize(grey.size());
  for (size_t i = 0; i < grey.size(); ++i)
  {
    v.HighPass[i] = grey[i] - blur[i];
  }
  v.Depth.resize(Size * Size);
  scene.Window->GetZbufferData(0, 0, Size - 1, Size - 1, v.Depth.data());
  std::vector<float> background(Size * Size);
  for (int i = 0; i < Size * Size; ++i)
  {
    background[i] = v.Depth[i] >= 0.99999f ? 1.0f : 0.0f;
  }
  const std::vector<float> near = BoxBlur(background, Radius + 1);
  v.Interior.resize(Size * Size);
  for (int i = 0; i < Size * Size; ++i)
  {
    v.Interior[i] = near[i] == 0.0f;
  }
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
  std::copy(&m->Element[0][0], &m->Element[0][0] + 16, v.Matrix);
  camera->GetPosition(v.CameraPosition);
  return v;
}

/// Pixel coordinates (x, y; origin bottom left) of world point x if it is visible in view v.
bool Project(const View& v, const double x[3], const double n[3], double p[2])
{
  const double* m = v.Matrix;
  double c[4];
  for (int r = 0; r < 4; ++r)
  {
    c[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
  if (c[3] <= 0.0)
  {
    return false;
  }
  p[0] = (c[0] / c[3] + 1.0) * 0.5 * Size - 0.5;
  p[1] = (c[1] / c[3] + 1.0) * 0.5 * Size - 0.5;
  const double z = (c[2] / c[3] + 1.0) * 0.5;
  const int ix = static_cast<int>(std::lround(p[0]));
  const int iy = static_cast<int>(std::lround(p[1]));
  if (ix < 1 || iy < 1 || ix >= Size - 1 || iy >= Size - 1 || !v.Interior[iy * Size + ix])
  {
    return false;
  }
  double toEye[3] = {
    v.CameraPosition[0] - x[0], v.CameraPosition[1] - x[1], v.CameraPosition[2] - x[2]
  };
  vtkMath::Normalize(toEye);
  return vtkMath::Dot(toEye, n) > 0.4 && std::fabs(v.Depth[iy * Size + ix] - z) < 2e-3;
}

/// Bilinear value of the high-pass image at pixel coordinates p.
double HighPassAt(const View& v, const double p[2])
{
  const int x0 = static_cast<int>(std::floor(p[0]));
  const int y0 = static_cast<int>(std::floor(p[1]));
  const double fx = p[0] - x0;
  const double fy = p[1] - y0;
  auto at = [&](int x, int y) { return v.HighPass[y * Size + x]; };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
    fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

/// Correlation of the high pass of a and b at the same surface points (the samples of
/// `ofb`), and at the same pixels (the control).
void Compare(vtkOFB* ofb, const View& a, const View& b, Correlation& surface, Correlation& pixels)
{
  vtkDataArray* normals = ofb->GetSampleData()->GetNormals();
  std::vector<double> sa, sb, pa, pb;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3], n[3], p[2], q[2];
    ofb->GetSamplePosition(i, x);
    normals->GetTuple(i, n);
    if (Project(a, x, n, p) && Project(b, x, n, q))
    {
      sa.push_back(HighPassAt(a, p));
      sb.push_back(HighPassAt(b, q));
      pa.push_back(HighPassAt(a, p));
      pb.push_back(HighPassAt(b, p));
    }
  }
  surface = Pearson(sa, sb);
  pixels = Pearson(pa, pb);
}
}

namespace
{
/// The bunny (into `bunny`) and its OFB at `resolution` with the tangential part of a
/// rotation about a tilted axis through its centre; null if the mesh cannot be read.
vtkSmartPointer<vtkOFB> RotatingBunny(int resolution, vtkSmartPointer<vtkPolyData>& bunny)
{
  bunny = ReadMesh("stanford-bunny.obj");
  if (!bunny)
  {
    return nullptr;
  }
  double center[3];
  Center(bunny, center);
  const double axis[3] = { 0.4, 1.0, 0.3 };
  return BuildWithField(bunny, resolution, RotationAbout(axis, center));
}

/// The rotating bunny's OFB at 128 cells and its LIC (2 x 8 steps, streamlines kept for
/// animation, phase 0), updated; Output is null if the mesh cannot be read.
struct AnimatedBunnyLIC
{
  vtkSmartPointer<vtkPolyData> Bunny;
  vtkSmartPointer<vtkOFB> Input;
  vtkNew<vtkOFBLIC> LIC;
  vtkOFB* Output = nullptr;

  AnimatedBunnyLIC()
  {
    this->Input = RotatingBunny(128, this->Bunny);
    if (!this->Input)
    {
      return;
    }
    this->LIC->SetInputData(this->Input);
    this->LIC->SetNumberOfSteps(8);
    this->LIC->AnimateOn();
    this->LIC->SetAnimationPhase(0.0);
    this->LIC->Update();
    this->Output = this->LIC->GetOutput();
  }
};
}

//------------------------------------------------------------------------------
TEST(LICView, GrainMovesWithTheSurface)
{
  vtkSmartPointer<vtkPolyData> bunny;
  vtkSmartPointer<vtkOFB> ofb = RotatingBunny(256, bunny);
  ASSERT_NE(ofb, nullptr);
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->SetNoiseGrainSize(2.0);
  lic->Update();
  vtkOFB* out = lic->GetOutput();
  ASSERT_GT(out->GetNumberOfSamples(), 0);

  LICScene scene(bunny, out, Size);
  // Unlit: the headlight turns with the camera and would change the shading's own
  // high frequencies (the bunny's bumps); the measure is about the LIC's grain.
  scene.Actor->GetProperty()->SetAmbient(1.0);
  scene.Actor->GetProperty()->SetDiffuse(0.0);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  scene.Renderer->ResetCamera();
  camera->Dolly(1.5);
  const View first = Capture(scene);
  ASSERT_TRUE(scene.Mapper->GetLastRenderUsedOFB());

  // Pan by 40 pixels: move the camera along its right vector by 40 pixels' worth of the
  // focal plane.
  double dir[3], up[3], right[3], pos[3], focal[3];
  camera->GetDirectionOfProjection(dir);
  camera->GetViewUp(up);
  vtkMath::Cross(dir, up, right);
  vtkMath::Normalize(right);
  const double pixel = 2.0 * camera->GetDistance() *
    std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) / Size;
  camera->GetPosition(pos);
  camera->GetFocalPoint(focal);
  for (int k = 0; k < 3; ++k)
  {
    pos[k] += 40.0 * pixel * right[k];
    focal[k] += 40.0 * pixel * right[k];
  }
  camera->SetPosition(pos);
  camera->SetFocalPoint(focal);
  const View panned = Capture(scene);

  // Rotate by 20 degrees about the focal point.
  camera->Azimuth(20.0);
  const View rotated = Capture(scene);

  Correlation surface, pixels;
  Compare(out, first, panned, surface, pixels);
  std::cout << "pan 40 px: same surface point " << surface.Value << ", same pixel " << pixels.Value
            << " (" << surface.Pairs << " points)\n";
  EXPECT_GT(surface.Pairs, 10000);
  EXPECT_GE(surface.Value, 0.9);
  EXPECT_LT(pixels.Value, 0.5); // the measure tells a screen-attached texture apart
  Compare(out, panned, rotated, surface, pixels);
  std::cout << "rotation 20 degrees: same surface point " << surface.Value << ", same pixel "
            << pixels.Value << " (" << surface.Pairs << " points)\n";
  EXPECT_GT(surface.Pairs, 10000);
  EXPECT_GE(surface.Value, 0.9);
}

// Animation: a re-convolution with another AnimationPhase changes only the LIC array of
// the output (the structure and the other arrays stay shared, the structure time kept);
// the mapper then uploads that array alone (4 bytes a sample), not the whole OFB.
TEST(LICView, AnimationUploadsOnlyTheLIC)
{
  AnimatedBunnyLIC animated;
  ASSERT_NE(animated.Output, nullptr);
  vtkOFBLIC* lic = animated.LIC;
  vtkOFB* out = animated.Output;
  const vtkIdType n = out->GetNumberOfSamples();
  ASSERT_GT(n, 0);
  auto* licArray = vtkFloatArray::SafeDownCast(out->GetSampleData()->GetArray("LIC"));
  ASSERT_NE(licArray, nullptr);
  const std::vector<float> before(licArray->GetPointer(0), licArray->GetPointer(0) + n);

  LICScene scene(animated.Bunny, out, 200);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  ASSERT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  scene.Window->Render(); // nothing changed: nothing uploaded
  const vtkIdType first = scene.Mapper->GetUploadedBytes();
  ASSERT_GT(first, 4 * n);

  lic->SetAnimationPhase(0.25);
  lic->Update();
  ASSERT_EQ(lic->GetOutput(), out);
  EXPECT_EQ(out->GetDepths(), animated.Input->GetDepths());
  licArray = vtkFloatArray::SafeDownCast(out->GetSampleData()->GetArray("LIC"));
  ASSERT_NE(licArray, nullptr);
  ASSERT_EQ(licArray->GetNumberOfTuples(), n);
  vtkIdType differing = 0;
  const float* after = licArray->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    differing += after[i] != before[i] ? 1 : 0;
  }
  EXPECT_GT(differing, n / 2); // the phase moved the streaks
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetUploadedBytes() - first, (n + 3) / 4 * 4) << "a byte a sample";
}

// With NearestMipmapped, a new AnimationPhase filters the LIC down the pyramid and
// uploads the LIC of every level, nothing else (a byte a sample of all levels, each level
// in whole words).
TEST(LICView, NearestMipmappedAnimationUploadsOnlyTheLICOfEveryLevel)
{
  AnimatedBunnyLIC animated;
  ASSERT_NE(animated.Output, nullptr);
  vtkOFBLIC* lic = animated.LIC;
  vtkOFB* out = animated.Output;
  LICScene scene(animated.Bunny, out, 200);
  scene.Mapper->SetLookupModeToNearestMipmapped();
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  ASSERT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  scene.Window->Render();
  const vtkIdType first = scene.Mapper->GetUploadedBytes();

  // The same pyramid as the mapper's (its default levels).
  vtkNew<vtkOFBPyramid> pyramid;
  pyramid->SetInputOFB(out);
  pyramid->SetSurface(animated.Bunny);
  ASSERT_TRUE(pyramid->UpdateLevels());
  ASSERT_GT(pyramid->GetNumberOfLevels(), 2);
  vtkIdType samples = 0;
  for (int k = 0; k < pyramid->GetNumberOfLevels(); ++k)
  {
    samples += (pyramid->GetLevel(k)->GetNumberOfSamples() + 3) / 4 * 4;
  }
  ASSERT_GT(first, 8 * samples); // the first upload: depths, colours and the LIC

  lic->SetAnimationPhase(0.25);
  lic->Update();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetUploadedBytes() - first, samples);
}
