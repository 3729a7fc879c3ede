// GoogleTest units of vtkOFBPolyDataMapper's LIC display: the two colour modes of VTK's
// surface LIC (blend, map) against their per-pixel formulas on a flat square, over the
// lookup-table colouring and over the paint, and the uploads of a re-convolved LIC array
// (only that array goes to the GPU). They open render windows (run under xvfb-run).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace
{
constexpr int Size = 128; // window pixels
constexpr int Blocks = 8; // blocks of constant LIC (along x) and scalar (along y)

// Block of a coordinate in [-1, 1], and how far (world units) it is from a block edge.
int BlockOf(double x, double& edgeDistance)
{
  const double t = (x + 1.0) * 0.5 * Blocks;
  const int b = std::min(Blocks - 1, std::max(0, static_cast<int>(std::floor(t))));
  edgeDistance = std::min(t - std::floor(t), std::ceil(t) - t) * 2.0 / Blocks;
  return b;
}

double LICOf(int bx)
{
  return 0.05 + 0.9 * bx / (Blocks - 1.0);
}

// Away from the edges of the lookup table's 256 bins, where the colour would be ambiguous.
double ScalarOf(int by)
{
  return -1.0 + 2.0 * (by + 0.5) / Blocks + 0.0039;
}

// The square [-1, 1]^2 seen from +z with a parallel camera that fits it to the window,
// lighting off (colour = ambient 1 x the fragment colour), with a "LIC" array constant per
// block column and a "Height" array constant per block row.
struct FlatScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkNew<vtkLookupTable> LUT;
  vtkSmartPointer<vtkOFB> OFB;
  vtkSmartPointer<vtkPolyData> Surface;
  vtkNew<vtkFloatArray> LIC;

  FlatScene()
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-1.0, -1.0, 0.0);
    plane->SetPoint1(1.0, -1.0, 0.0);
    plane->SetPoint2(-1.0, 1.0, 0.0);
    plane->Update();
    this->Surface = plane->GetOutput();
    this->OFB = vtkofbtest::Build(this->Surface, 128);
    const vtkIdType n = this->OFB->GetNumberOfSamples();
    vtkNew<vtkFloatArray> height;
    height->SetName("Height");
    height->SetNumberOfTuples(n);
    this->LIC->SetName("LIC");
    this->LIC->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      this->OFB->GetSamplePosition(i, x);
      double d;
      this->LIC->SetValue(i, static_cast<float>(LICOf(BlockOf(x[0], d))));
      height->SetValue(i, static_cast<float>(ScalarOf(BlockOf(x[1], d))));
    }
    this->OFB->GetSampleData()->AddArray(height);
    this->OFB->GetSampleData()->AddArray(this->LIC);
    vtkofbtest::Paint(this->OFB,
      [](const double x[3], unsigned char rgba[4])
      {
        double d;
        rgba[0] = static_cast<unsigned char>(40 + 25 * BlockOf(x[1], d));
        rgba[1] = 200;
        rgba[2] = static_cast<unsigned char>(230 - 20 * BlockOf(x[1], d));
        rgba[3] = 255;
      });

    this->LUT->SetHueRange(0.0, 0.6667);
    this->LUT->SetRange(-1.0, 1.0);
    this->LUT->Build();
    this->Mapper->SetInputData(this->Surface);
    this->Mapper->SetLookupModeToNearest(); // sample by sample, as vtkOFBMapToColors
    this->Mapper->SetOFB(this->OFB);
    this->Mapper->GetColoring()->SetLookupTable(this->LUT);
    this->Mapper->GetColoring()->SetScalarRange(-1.0, 1.0);
    this->Mapper->GetColoring()->SetScalarArrayName("Height");
    this->Mapper->GetColoring()->SetIntensityArrayName("LIC");
    this->Mapper->GetColoring()->IntensityModulationOn();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->LightingOff();
    this->Actor->GetProperty()->SetAmbient(1.0);
    this->Actor->GetProperty()->SetDiffuse(0.0);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(1.0);
    this->Renderer->ResetCameraClippingRange();
    this->Window->SetSize(Size, Size);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
  }

  /// Render, then compare every pixel away from the block edges with `expected(base
  /// colour, LIC)` (colours in [0, 1]); returns the number of pixels compared and sets
  /// `worst` to the largest difference in 0-255 units.
  int Compare(const std::function<void(const double base[3], double lic, double out[3])>& expected,
    bool scalars,
    double& worst)
  {
    this->Window->Render();
    EXPECT_TRUE(this->Mapper->GetLastRenderUsedOFB());
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->SetInputBufferTypeToRGB();
    grab->Update();
    const unsigned char* p = static_cast<unsigned char*>(grab->GetOutput()->GetScalarPointer());
    const double margin = 2.0 * this->OFB->GetCellSize();
    worst = 0.0;
    int compared = 0;
    for (int j = 0; j < Size; ++j)
    {
      for (int i = 0; i < Size; ++i)
      {
        const double x = -1.0 + (i + 0.5) * 2.0 / Size;
        const double y = -1.0 + (j + 0.5) * 2.0 / Size;
        double dx;
        double dy;
        const int bx = BlockOf(x, dx);
        const int by = BlockOf(y, dy);
        if (dx < margin || dy < margin)
        {
          continue;
        }
        double base[3];
        if (scalars)
        {
          this->LUT->GetColor(ScalarOf(by), base);
        }
        else
        {
          base[0] = (40 + 25 * by) / 255.0;
          base[1] = 200 / 255.0;
          base[2] = (230 - 20 * by) / 255.0;
        }
        double out[3];
        expected(base, LICOf(bx), out);
        const unsigned char* q = p + 3 * (j * Size + i);
        for (int c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::abs(q[c] - 255.0 * out[c]));
        }
        ++compared;
      }
    }
    return compared;
  }
};
}

TEST(OFBMapperLICDisplay, BlendModeFollowsVTKsFormula)
{
  for (bool scalars : { true, false })
  {
    FlatScene scene;
    if (scalars)
    {
      scene.Mapper->GetColoring()->SetColorSourceToScalars();
    }
    EXPECT_EQ(scene.Mapper->GetColoring()->GetLICColorMode(), vtkOFBColoring::COLOR_MODE_BLEND);
    EXPECT_DOUBLE_EQ(scene.Mapper->GetColoring()->GetLICIntensity(), 1.0);
    for (double intensity : { 0.8, 0.3, 1.0 })
    {
      scene.Mapper->GetColoring()->SetLICIntensity(intensity);
      double worst = 0.0;
      const int compared = scene.Compare(
        [intensity](const double base[3], double lic, double out[3])
        {
          for (int c = 0; c < 3; ++c)
          {
            out[c] = lic * intensity + base[c] * (1.0 - intensity);
          }
        },
        scalars,
        worst);
      EXPECT_GT(compared, Size * Size / 3);
      EXPECT_LE(worst, 3.0) << (scalars ? "scalars" : "paint") << ", LICIntensity " << intensity;
    }
  }
}

TEST(OFBMapperLICDisplay, MapModeFollowsVTKsFormula)
{
  for (bool scalars : { true, false })
  {
    FlatScene scene;
    if (scalars)
    {
      scene.Mapper->GetColoring()->SetColorSourceToScalars();
    }
    scene.Mapper->GetColoring()->SetLICColorModeToMap();
    for (double bias : { 0.0, 0.25, -0.3 })
    {
      scene.Mapper->GetColoring()->SetMapModeBias(bias);
      double worst = 0.0;
      const int compared = scene.Compare(
        [bias](const double base[3], double lic, double out[3])
        {
          for (int c = 0; c < 3; ++c)
          {
            out[c] = base[c] * std::min(1.0, std::max(0.0, lic + bias));
          }
        },
        scalars,
        worst);
      EXPECT_GT(compared, Size * Size / 3);
      EXPECT_LE(worst, 3.0) << (scalars ? "scalars" : "paint") << ", MapModeBias " << bias;
    }
  }
}

TEST(OFBMapperLICDisplay, WithoutModulationTheColourIsUnchanged)
{
  FlatScene scene;
  scene.Mapper->GetColoring()->SetColorSourceToScalars();
  scene.Mapper->GetColoring()->IntensityModulationOff();
  double worst = 0.0;
  scene.Compare([](const double base[3], double, double out[3]) { std::copy(base, base + 3, out); },
    true,
    worst);
  EXPECT_LE(worst, 3.0);
}

TEST(OFBMapperLICDisplay, ReconvolutionUploadsOnlyTheLICArray)
{
  FlatScene scene;
  scene.Mapper->GetColoring()->SetColorSourceToScalars();
  scene.Window->Render();
  const vtkIdType n = scene.OFB->GetNumberOfSamples();
  EXPECT_EQ(scene.Mapper->GetLastUploadedSampleCount(), n);

  // A new AnimationPhase: the same array, new values, Modified().
  auto animate = [&](vtkFloatArray* lic, double phase)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      scene.OFB->GetSamplePosition(i, x);
      lic->SetValue(i, static_cast<float>(0.5 + 0.5 * std::sin(20.0 * x[0] + phase)));
    }
    lic->Modified();
    scene.OFB->Modified();
  };
  animate(scene.LIC, 1.0);
  vtkIdType before = scene.Mapper->GetUploadedBytes();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetUploadedBytes() - before, (n + 3) / 4 * 4)
    << "only the LIC, a byte a sample in whole words";
  EXPECT_EQ(scene.Mapper->GetLastUploadedSampleCount(), n);

  // A re-convolution into a new array of the same name.
  vtkNew<vtkFloatArray> next;
  next->SetName("LIC");
  next->SetNumberOfTuples(n);
  animate(next, 2.0);
  scene.OFB->GetSampleData()->AddArray(next);
  before = scene.Mapper->GetUploadedBytes();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetUploadedBytes() - before, (n + 3) / 4 * 4);

  // Nothing changed: nothing sent.
  before = scene.Mapper->GetUploadedBytes();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetUploadedBytes() - before, 0);

  // A paint stroke over 100 samples sends their colour attribute and LIC bytes only.
  scene.OFB->MarkSamplesModified(1000, 1100);
  scene.OFB->Modified();
  before = scene.Mapper->GetUploadedBytes();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetUploadedBytes() - before, 100 * (8 + 1));
}

// vtkOFBMapToColors sharing the mapper's colouring (SetColoring) writes the colours the
// mapper shows: the OFB drawn with those as paint looks the same, pixel for pixel, with a
// LIC and scalars that vary from sample to sample; also with the colour contrast
// enhancement, which changes the picture.
TEST(OFBMapperLICDisplay, MapToColorsWritesWhatTheMapperShows)
{
  vtkSmartPointer<vtkImageData> plainScalars;
  for (int config : { 0, 1, 2 })
  {
    const bool scalars = config != 1;
    const bool enhance = config == 2;
    FlatScene scene;
    const vtkIdType n = scene.OFB->GetNumberOfSamples();
    vtkFloatArray* height =
      vtkFloatArray::SafeDownCast(scene.OFB->GetSampleData()->GetArray("Height"));
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      scene.OFB->GetSamplePosition(i, x);
      scene.LIC->SetValue(i, static_cast<float>(0.5 + 0.6 * std::sin(37.0 * x[0] + 23.0 * x[1])));
      height->SetValue(i, static_cast<float>(x[1] + 0.3 * std::sin(11.0 * x[0])));
    }
    if (scalars)
    {
      scene.Mapper->GetColoring()->SetColorSourceToScalars();
      scene.Mapper->GetColoring()->SetLICColorModeToMap();
      scene.Mapper->GetColoring()->SetMapModeBias(0.1);
      scene.Mapper->GetColoring()->SetIntensityWeight(0.7);
      scene.Mapper->GetColoring()->SetEnhanceColorContrast(enhance);
      scene.Mapper->GetColoring()->SetLowColorContrastEnhancementFactor(0.1);
      scene.Mapper->GetColoring()->SetHighColorContrastEnhancementFactor(0.2);
    }
    else
    {
      scene.Mapper->GetColoring()->SetLICIntensity(0.4);
    }
    auto grab = [&scene]()
    {
      scene.Window->Render();
      EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
      vtkNew<vtkWindowToImageFilter> grabber;
      grabber->SetInput(scene.Window);
      grabber->ReadFrontBufferOff();
      grabber->SetInputBufferTypeToRGB();
      grabber->Update();
      vtkSmartPointer<vtkImageData> image = grabber->GetOutput();
      return image;
    };
    vtkSmartPointer<vtkImageData> shown = grab();

    vtkNew<vtkOFBMapToColors> colors;
    colors->SetColoring(scene.Mapper->GetColoring());
    EXPECT_EQ(colors->GetColoring()->GetIntensityModulation(), true);
    colors->SetInputData(scene.OFB);
    colors->SetOutputArrayName("Colors");
    colors->Update();
    ASSERT_EQ(colors->GetOutput()->GetNumberOfSamples(), n);
    scene.Mapper->SetOFB(colors->GetOutput());
    EXPECT_EQ(colors->GetColoring()->GetEnhanceColorContrast(), enhance);
    // The exported colours shown as paint: the mapper gets a colouring of its own (the
    // default: paint, no intensity, no contrast), the filter keeps the shared one.
    vtkNew<vtkOFBColoring> paint;
    scene.Mapper->SetColoring(paint);
    EXPECT_EQ(scene.Mapper->GetColoring()->GetColorSource(), vtkOFBColoring::COLOR_SOURCE_PAINT);
    EXPECT_FALSE(scene.Mapper->GetColoring()->GetIntensityModulation());
    EXPECT_FALSE(scene.Mapper->GetColoring()->GetEnhanceColorContrast());
    vtkSmartPointer<vtkImageData> exported = grab();

    const auto* a = static_cast<unsigned char*>(shown->GetScalarPointer());
    const auto* b = static_cast<unsigned char*>(exported->GetScalarPointer());
    int worst = 0;
    double sum = 0.0;
    int lit = 0;
    for (int k = 0; k < 3 * Size * Size; ++k)
    {
      worst = std::max(worst, std::abs(a[k] - b[k]));
      sum += std::abs(a[k] - b[k]);
      lit += a[k] > 20 ? 1 : 0;
    }
    EXPECT_GT(lit, Size * Size) << "the square is drawn";
    EXPECT_LE(worst, 3) << "configuration " << config;
    EXPECT_LT(sum / (3 * Size * Size), 0.5) << "configuration " << config;
    if (config == 0)
    {
      plainScalars = shown;
    }
    else if (enhance)
    {
      // The stretch changed the picture.
      const auto* p = static_cast<unsigned char*>(plainScalars->GetScalarPointer());
      double changed = 0.0;
      for (int k = 0; k < 3 * Size * Size; ++k)
      {
        changed += std::abs(a[k] - p[k]);
      }
      EXPECT_GT(changed / (3 * Size * Size), 5.0);
    }
  }
}

// One vtkOFBColoring shared by the mapper and vtkOFBMapToColors: a setting changed once,
// through the filter, changes the next render and the filter's next output, and the two
// still agree pixel for pixel.
TEST(OFBMapperLICDisplay, SharedColoringChangeReachesTheRenderAndTheExport)
{
  FlatScene scene;
  scene.Mapper->GetColoring()->SetColorSourceToScalars();
  vtkNew<vtkOFBMapToColors> colors;
  colors->SetColoring(scene.Mapper->GetColoring());
  colors->SetInputData(scene.OFB);
  colors->SetOutputArrayName("Colors");
  auto grab = [&scene]()
  {
    scene.Window->Render();
    EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
    vtkNew<vtkWindowToImageFilter> grabber;
    grabber->SetInput(scene.Window);
    grabber->ReadFrontBufferOff();
    grabber->SetInputBufferTypeToRGB();
    grabber->Update();
    vtkSmartPointer<vtkImageData> image = grabber->GetOutput();
    return image;
  };
  auto difference = [](vtkImageData* a, vtkImageData* b)
  {
    const auto* pa = static_cast<unsigned char*>(a->GetScalarPointer());
    const auto* pb = static_cast<unsigned char*>(b->GetScalarPointer());
    double sum = 0.0;
    for (int k = 0; k < 3 * Size * Size; ++k)
    {
      sum += std::abs(pa[k] - pb[k]);
    }
    return sum / (3 * Size * Size);
  };
  auto exported = [&colors]()
  {
    colors->Update();
    vtkNew<vtkUnsignedCharArray> copy;
    copy->DeepCopy(colors->GetOutput()->GetSampleData()->GetArray("Colors"));
    return vtkSmartPointer<vtkUnsignedCharArray>(copy.Get());
  };
  vtkSmartPointer<vtkImageData> before = grab();
  vtkSmartPointer<vtkUnsignedCharArray> exportedBefore = exported();
  ASSERT_EQ(exportedBefore->GetNumberOfTuples(), scene.OFB->GetNumberOfSamples());

  const vtkMTimeType mapperTime = scene.Mapper->GetMTime();
  colors->GetColoring()->SetLICIntensity(0.2);
  EXPECT_GT(scene.Mapper->GetMTime(), mapperTime);
  vtkSmartPointer<vtkImageData> after = grab();
  EXPECT_GT(difference(before, after), 5.0) << "the render uses the new LICIntensity";
  vtkSmartPointer<vtkUnsignedCharArray> exportedAfter = exported();
  int changed = 0;
  for (vtkIdType i = 0; i < 4 * exportedAfter->GetNumberOfTuples(); ++i)
  {
    changed += exportedAfter->GetValue(i) != exportedBefore->GetValue(i) ? 1 : 0;
  }
  EXPECT_GT(changed, 0) << "the filter re-executed with the new LICIntensity";

  // The export of the changed colouring shown as paint: the same picture as the render.
  vtkNew<vtkOFBColoring> paint;
  scene.Mapper->SetColoring(paint);
  scene.Mapper->SetOFB(colors->GetOutput());
  EXPECT_LT(difference(after, grab()), 0.5);
}

TEST(OFBMapperLICDisplay, SettingsAreClampedAndNamedAsVTKs)
{
  vtkNew<vtkOFBPolyDataMapper> mapper;
  EXPECT_EQ(mapper->GetColoring()->GetLICColorMode(), vtkOFBColoring::COLOR_MODE_BLEND);
  EXPECT_DOUBLE_EQ(mapper->GetColoring()->GetLICIntensity(), 1.0);
  EXPECT_DOUBLE_EQ(mapper->GetColoring()->GetMapModeBias(), 0.0);
  mapper->GetColoring()->SetLICColorMode(7);
  EXPECT_EQ(mapper->GetColoring()->GetLICColorMode(), vtkOFBColoring::COLOR_MODE_MAP);
  mapper->GetColoring()->SetLICIntensity(2.0);
  EXPECT_DOUBLE_EQ(mapper->GetColoring()->GetLICIntensity(), 1.0);
  mapper->GetColoring()->SetMapModeBias(-5.0);
  EXPECT_DOUBLE_EQ(mapper->GetColoring()->GetMapModeBias(), -1.0);
  EXPECT_STREQ(vtkOFBColoring::GetLICColorModeAsString(1), "COLOR_MODE_MAP");
}
