// GoogleTest units of vtkOFBImageComparison on a surface LIC (a sphere with a rotation
// field through vtkOFBSampler, vtkOFBLIC and vtkOFBPolyDataMapper, 400 x 400 pixels):
// a rerun with the same settings passes; NumberOfSteps 20 -> 10, another
// NoiseGeneratorSeed and the OFB's Resolution 512 -> 502 (2 %) fail; a driver's noise
// (a level everywhere, antialiased silhouettes) and a one-pixel shift pass; a colour
// change fails; bad input fails with an error and no crash. The measures of each case
// are printed (docs/testing.md quotes them). They open render windows.
#include "vtkOFBImageComparison.h"
#include "vtkOFBLICRenderHelpers.h"
#include "vtkOFBRegressionTestImage.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <memory>
#include <tuple>

using namespace vtkofbtest;

namespace
{
constexpr int Size = 400;

/// The settings that the cases change.
struct Settings
{
  int Resolution = 512;
  int Steps = 20;
  int Seed = 1;
  bool operator<(const Settings& o) const
  {
    return std::tie(this->Resolution, this->Steps, this->Seed) <
      std::tie(o.Resolution, o.Steps, o.Seed);
  }
};

/// The LIC of a sphere under a rotation about a tilted axis, shown by the mapper: every
/// object from scratch, so that two scenes of the same settings are a true rerun.
struct Scene
{
  vtkSmartPointer<vtkPolyData> Sphere;
  vtkNew<vtkOFBLIC> LIC;
  std::unique_ptr<LICScene> View;

  explicit Scene(const Settings& s)
  {
    this->Sphere = MakeSphere(1.0, 128);
    const double axis[3] = { 0.4, 1.0, 0.3 };
    const double center[3] = { 0.0, 0.0, 0.0 };
    vtkSmartPointer<vtkOFB> ofb =
      BuildWithField(this->Sphere, s.Resolution, RotationAbout(axis, center));
    this->LIC->SetInputData(ofb);
    this->LIC->SetNumberOfSteps(s.Steps);
    this->LIC->SetNoiseGeneratorSeed(s.Seed);
    this->LIC->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_LIC);
    this->LIC->Update();
    this->View = std::make_unique<LICScene>(this->Sphere, this->LIC->GetOutput(), Size);
    this->View->Renderer->ResetCamera();
    this->View->Renderer->GetActiveCamera()->Dolly(1.3);
    this->View->Renderer->ResetCameraClippingRange();
  }

  vtkSmartPointer<vtkImageData> Grab()
  {
    this->View->Window->Render();
    EXPECT_TRUE(this->View->Mapper->GetLastRenderUsedOFB());
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->View->Window);
    grab->ReadFrontBufferOff();
    grab->SetInputBufferTypeToRGB();
    grab->Update();
    vtkSmartPointer<vtkImageData> image = grab->GetOutput();
    return image;
  }
};

/// The rendered image of each settings, rendered once (a second "rerun" key renders the
/// baseline settings again from scratch).
vtkImageData* Rendered(const Settings& s, bool rerun = false)
{
  static std::map<std::pair<Settings, bool>, vtkSmartPointer<vtkImageData>> images;
  auto& image = images[{ s, rerun }];
  if (!image)
  {
    Scene scene(s);
    image = scene.Grab();
  }
  return image;
}

/// Compares `image` with the baseline settings' image and prints the measures, with
/// VTK's own error over the whole image for reference.
bool CompareWithBaseline(vtkImageData* image, const char* what, vtkOFBImageComparison* c)
{
  c->SetImage(image);
  c->SetBaseline(Rendered(Settings()));
  c->SetBackgroundColor(0.1, 0.1, 0.15);
  const bool passed = c->Compare();
  vtkNew<vtkImageDifference> vtkDiff;
  vtkDiff->SetInputData(image);
  vtkDiff->SetImageData(Rendered(Settings()));
  vtkDiff->Update();
  std::cout << what << ": correlation " << c->GetCorrelation() << ", low-pass difference "
            << c->GetLowPassDifference() << ", mean absolute difference "
            << c->GetMeanAbsoluteDifference() << ", error outside " << c->GetImageDifferenceError()
            << ", mask " << c->GetNumberOfMaskPixels()
            << " pixels; vtkImageDifference over the whole image " << vtkDiff->GetThresholdedError()
            << std::endl;
  return passed;
}

/// A copy of an RGB image with f(x, y, rgb) applied to each pixel.
template<typename F>
vtkSmartPointer<vtkImageData> Edited(vtkImageData* in, F f)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(in);
  int dims[3];
  out->GetDimensions(dims);
  auto* p = static_cast<unsigned char*>(out->GetScalarPointer());
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      f(x, y, p + 3 * (y * dims[0] + x));
    }
  }
  return out;
}

/// The test's own output directory (under the working directory of the test).
std::string OutputDirectory()
{
  const std::string dir =
    vtksys::SystemTools::GetCurrentWorkingDirectory() + "/ImageComparisonOutput";
  vtksys::SystemTools::MakeDirectory(dir);
  return dir;
}

void WritePNG(vtkImageData* image, const std::string& name)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(name.c_str());
  writer->Write();
}
}

//------------------------------------------------------------------------------
TEST(ImageComparison, SameSettingsRerunPasses)
{
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_TRUE(CompareWithBaseline(Rendered(Settings(), true), "rerun", c)) << c->GetErrorText();
  EXPECT_GT(c->GetNumberOfMaskPixels(), Size * Size / 3) << "the sphere fills the mask";
  EXPECT_GE(c->GetCorrelation(), c->GetCorrelationThreshold());
  EXPECT_STREQ(c->GetErrorText(), "");
}

TEST(ImageComparison, HalfTheStepsFails)
{
  Settings s;
  s.Steps = 10;
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_FALSE(CompareWithBaseline(Rendered(s), "steps 20 -> 10", c));
  EXPECT_LT(c->GetCorrelation(), c->GetCorrelationThreshold());
  EXPECT_NE(std::string(c->GetErrorText()).find("texture"), std::string::npos);
}

TEST(ImageComparison, AnotherNoiseSeedFails)
{
  Settings s;
  s.Seed = 2;
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_FALSE(CompareWithBaseline(Rendered(s), "seed 1 -> 2", c));
  EXPECT_LT(c->GetCorrelation(), c->GetCorrelationThreshold());
}

TEST(ImageComparison, TwoPercentResolutionFails)
{
  Settings s;
  s.Resolution = 502;
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_FALSE(CompareWithBaseline(Rendered(s), "resolution 512 -> 502", c));
  EXPECT_LT(c->GetCorrelation(), c->GetCorrelationThreshold());
}

// What another driver may change: a level here and there everywhere, and the
// silhouettes (blended half with the background).
TEST(ImageComparison, DriverNoiseAndSilhouettesPass)
{
  vtkImageData* base = Rendered(Settings());
  const unsigned char bg[3] = { 26, 26, 38 };
  auto isBackground = [&bg](const unsigned char* p)
  {
    return std::abs(p[0] - bg[0]) <= 2 && std::abs(p[1] - bg[1]) <= 2 &&
      std::abs(p[2] - bg[2]) <= 2;
  };
  const auto* src = static_cast<unsigned char*>(base->GetScalarPointer());
  vtkSmartPointer<vtkImageData> noisy = Edited(base,
    [&](int x, int y, unsigned char* p)
    {
      bool silhouette = false;
      for (int k = 0; k < 4 && x > 0 && y > 0 && x < Size - 1 && y < Size - 1; ++k)
      {
        const int nx = x + (k == 0) - (k == 1);
        const int ny = y + (k == 2) - (k == 3);
        silhouette |= !isBackground(p) && isBackground(src + 3 * (ny * Size + nx));
      }
      for (int c = 0; c < 3; ++c)
      {
        int v = p[c] + ((x * 7 + y * 13 + c) % 3) - 1; // -1, 0 or +1
        if (silhouette)
        {
          v = (v + bg[c]) / 2;
        }
        p[c] = static_cast<unsigned char>(std::min(255, std::max(0, v)));
      }
    });
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_TRUE(CompareWithBaseline(noisy, "a level of noise, blended silhouettes", c))
    << c->GetErrorText();
}

// Antialiasing: the same settings rendered with 8 samples a pixel (the silhouettes
// blended by multisampling) pass against the baseline rendered with one.
TEST(ImageComparison, MultisampledRenderingPasses)
{
  Scene scene{ Settings() };
  scene.View->Window->SetMultiSamples(8);
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_TRUE(CompareWithBaseline(scene.Grab(), "8 samples a pixel", c)) << c->GetErrorText();
}

TEST(ImageComparison, OnePixelShiftPassesUnlessShiftIsOff)
{
  vtkImageData* base = Rendered(Settings());
  const auto* src = static_cast<unsigned char*>(base->GetScalarPointer());
  vtkSmartPointer<vtkImageData> shifted = Edited(base,
    [&](int x, int y, unsigned char* p)
    {
      const int sx = std::max(0, x - 1);
      std::copy(src + 3 * (y * Size + sx), src + 3 * (y * Size + sx) + 3, p);
    });
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_TRUE(CompareWithBaseline(shifted, "shifted one pixel", c)) << c->GetErrorText();
  c->AllowShiftOff();
  EXPECT_FALSE(CompareWithBaseline(shifted, "shifted one pixel, AllowShift off", c));
}

TEST(ImageComparison, ColourChangeFailsByTheLowPass)
{
  vtkImageData* base = Rendered(Settings());
  vtkSmartPointer<vtkImageData> warmer = Edited(base,
    [](int, int, unsigned char* p)
    {
      if (p[0] != 26 || p[2] != 38)
      {
        p[0] = static_cast<unsigned char>(std::min(255, p[0] + 25));
      }
    });
  vtkNew<vtkOFBImageComparison> c;
  EXPECT_FALSE(CompareWithBaseline(warmer, "red + 25 levels", c));
  EXPECT_GE(c->GetCorrelation(), c->GetCorrelationThreshold()) << "the texture is the same";
  EXPECT_GT(c->GetLowPassDifference(), c->GetLowPassThreshold());
}

TEST(ImageComparison, BadInputFailsWithAnError)
{
  vtkImageData* base = Rendered(Settings());
  vtkNew<vtkOFBImageComparison> c;
  vtkNew<MessageObserver> messages;
  messages->Watch(c);
  auto expectError = [&](const char* what, const char* words)
  {
    messages->Clear();
    EXPECT_FALSE(c->Compare()) << what;
    EXPECT_FALSE(c->GetPassed()) << what;
    EXPECT_NE(std::string(c->GetErrorText()).find(words), std::string::npos)
      << what << ": " << c->GetErrorText();
    EXPECT_NE(messages->Errors.find(words), std::string::npos) << what;
    EXPECT_EQ(c->GetDifferenceImage(), nullptr) << what;
  };

  expectError("nothing set", "no image");
  c->SetImage(base);
  expectError("no baseline", "no baseline");
  vtkNew<vtkImageData> empty;
  c->SetBaseline(empty);
  expectError("an empty baseline", "baseline is empty");

  vtkNew<vtkImageData> small;
  small->SetDimensions(300, 200, 1);
  small->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  c->SetBaseline(small);
  expectError("sizes differ", "the image is 400 x 400 pixels, the baseline 300 x 200");

  vtkNew<vtkImageData> floats;
  floats->SetDimensions(Size, Size, 1);
  floats->AllocateScalars(VTK_FLOAT, 3);
  c->SetBaseline(floats);
  expectError("float pixels", "not an unsigned char image");

  c->SetBaseline(base);
  vtkNew<vtkImageData> mask;
  mask->SetDimensions(Size, Size / 2, 1);
  mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  c->SetMask(mask);
  expectError("a mask of another size", "the mask is 400 x 200");
  c->SetMask(nullptr);

  c->SetBackgroundColor(1.0, 1.0, 1.0); // no pixel is white: all surface, eroded away
  c->SetMinimumMaskPixels(Size * Size);
  expectError("too small a mask", "fewer than MinimumMaskPixels");

  // The same comparison passes once the input is good.
  c->SetMinimumMaskPixels(400);
  c->SetBackgroundColor(0.1, 0.1, 0.15);
  messages->Clear();
  EXPECT_TRUE(c->Compare()) << c->GetErrorText();
  EXPECT_EQ(messages->Errors, "");
  EXPECT_NE(c->GetDifferenceImage(), nullptr);
}

TEST(ImageComparison, GivenMaskIsUsed)
{
  // A mask that covers the left half only: a change in the right half's texture is
  // judged by VTK's difference, which lets it pass; the same change on the left fails.
  Settings s;
  s.Seed = 2;
  vtkImageData* base = Rendered(Settings());
  vtkImageData* other = Rendered(s);
  const auto* o = static_cast<unsigned char*>(other->GetScalarPointer());
  vtkSmartPointer<vtkImageData> rightChanged = Edited(base,
    [&](int x, int y, unsigned char* p)
    {
      if (x >= Size / 2)
        std::copy(o + 3 * (y * Size + x), o + 3 * (y * Size + x) + 3, p);
    });
  vtkNew<vtkImageData> mask;
  mask->SetDimensions(Size, Size, 1);
  mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* m = static_cast<unsigned char*>(mask->GetScalarPointer());
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      m[y * Size + x] = x < Size / 2 - 10 && std::abs(x - Size / 2) + std::abs(y - Size / 2) < 150;
    }
  }
  vtkNew<vtkOFBImageComparison> c;
  c->SetMask(mask);
  EXPECT_TRUE(CompareWithBaseline(rightChanged, "right half changed, left half masked", c))
    << c->GetErrorText();
  c->SetMask(nullptr);
  EXPECT_FALSE(CompareWithBaseline(rightChanged, "right half changed, no mask", c));
}

TEST(ImageComparison, RegressionTestWritesTheImagesWhenItFails)
{
  const std::string dir = OutputDirectory();
  const std::string baseline = dir + "/TestSphereLIC.png";
  const std::string image = dir + "/out/TestSphereLIC.png";
  const std::string diff = dir + "/out/TestSphereLIC.diff.png";
  vtksys::SystemTools::MakeDirectory(dir + "/out");
  vtksys::SystemTools::RemoveFile(baseline);
  vtksys::SystemTools::RemoveFile(image);
  vtksys::SystemTools::RemoveFile(diff);

  Scene scene{ Settings() };
  vtkNew<vtkOFBImageComparison> c;
  vtkNew<MessageObserver> messages;
  messages->Watch(c);

  // No baseline: fails, and writes the rendered image to copy over the baseline.
  EXPECT_EQ(c->RegressionTest(scene.View->Window, baseline.c_str(), (dir + "/out").c_str()),
    vtkOFBImageComparison::FAILED);
  EXPECT_NE(std::string(c->GetErrorText()).find("No baseline"), std::string::npos);
  EXPECT_NE(
    std::string(c->GetErrorText()).find("cp '" + image + "' '" + baseline + "'"), std::string::npos)
    << c->GetErrorText();
  ASSERT_TRUE(vtksys::SystemTools::FileExists(image, true));

  // Copied over the baseline, it passes, and the output is removed.
  vtksys::SystemTools::CopyFileAlways(image, baseline);
  EXPECT_EQ(c->RegressionTest(scene.View->Window, baseline.c_str(), (dir + "/out").c_str()),
    vtkOFBImageComparison::PASSED)
    << c->GetErrorText();
  EXPECT_FALSE(vtksys::SystemTools::FileExists(image, true));
  EXPECT_EQ(c->GetBackgroundColor()[2], 0.15) << "the renderer's background";

  // Half the steps: fails, with the image and its difference written.
  scene.LIC->SetNumberOfSteps(10);
  scene.LIC->Update();
  EXPECT_EQ(c->RegressionTest(scene.View->Window, baseline.c_str(), (dir + "/out").c_str()),
    vtkOFBImageComparison::FAILED);
  EXPECT_TRUE(vtksys::SystemTools::FileExists(image, true));
  EXPECT_TRUE(vtksys::SystemTools::FileExists(diff, true));
  EXPECT_NE(std::string(c->GetErrorText()).find("texture"), std::string::npos);

  // Output into the baseline's own directory: the baseline is never overwritten.
  vtksys::SystemTools::CopyFileAlways(baseline, dir + "/out/Kept.png");
  EXPECT_EQ(c->RegressionTest(scene.View->Window, baseline.c_str(), dir.c_str()),
    vtkOFBImageComparison::FAILED);
  EXPECT_FALSE(vtksys::SystemTools::FilesDiffer(baseline, dir + "/out/Kept.png"));

  // An alternative baseline (name_1.png) that matches passes.
  vtksys::SystemTools::CopyFileAlways(image, dir + "/TestSphereLIC_1.png");
  EXPECT_EQ(c->RegressionTest(scene.View->Window, baseline.c_str(), (dir + "/out").c_str()),
    vtkOFBImageComparison::PASSED)
    << c->GetErrorText();
  vtksys::SystemTools::RemoveFile(dir + "/TestSphereLIC_1.png");

  // Bad input: no window, no baseline name, a file that is not a PNG.
  EXPECT_EQ(c->RegressionTest(nullptr, baseline.c_str(), nullptr), vtkOFBImageComparison::FAILED);
  EXPECT_EQ(c->RegressionTest(scene.View->Window, "", nullptr), vtkOFBImageComparison::FAILED);
  const std::string notPNG = dir + "/NotAPNG.png";
  {
    std::ofstream out(notPNG);
    out << "not a PNG\n";
  }
  EXPECT_EQ(
    c->RegressionTest(scene.View->Window, notPNG.c_str(), nullptr), vtkOFBImageComparison::FAILED);
  EXPECT_NE(std::string(c->GetErrorText()).find("cannot read"), std::string::npos)
    << c->GetErrorText();
  EXPECT_NE(messages->Errors, "");
}

TEST(ImageComparison, TestReadsTheArgumentsOfAVTKTest)
{
  const std::string dir = OutputDirectory();
  Scene scene{ Settings() };
  std::string name = "TestOFBImageComparison";
  std::string v = "-V";
  std::string t = "-T";
  std::string i = "-I";
  std::string baseline = dir + "/TestArguments.png";
  std::string out = dir + "/out";
  vtksys::SystemTools::MakeDirectory(out);
  vtksys::SystemTools::RemoveFile(baseline);
  {
    std::vector<char*> args = { &name[0] };
    int argc = static_cast<int>(args.size());
    char** argv = args.data();
    EXPECT_EQ(vtkOFBRegressionTestImage(scene.View->Window), vtkOFBImageComparison::NOT_RUN);
  }
  {
    std::vector<char*> args = { &name[0], &i[0] };
    int argc = static_cast<int>(args.size());
    char** argv = args.data();
    EXPECT_EQ(vtkOFBRegressionTestImage(scene.View->Window), vtkOFBImageComparison::DO_INTERACTOR);
  }
  std::vector<char*> args = { &name[0], &v[0], &baseline[0], &t[0], &out[0] };
  int argc = static_cast<int>(args.size());
  char** argv = args.data();
  vtkNew<vtkOFBImageComparison> quiet;
  vtkNew<MessageObserver> messages;
  messages->Watch(quiet);
  EXPECT_EQ(
    vtkOFBRegressionTestImageWith(scene.View->Window, quiet), vtkOFBImageComparison::FAILED);
  ASSERT_TRUE(vtksys::SystemTools::FileExists(out + "/TestArguments.png", true));
  vtksys::SystemTools::CopyFileAlways(out + "/TestArguments.png", baseline);
  EXPECT_EQ(vtkOFBRegressionTestImage(scene.View->Window), vtkOFBImageComparison::PASSED);
}
