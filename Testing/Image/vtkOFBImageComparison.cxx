#include "vtkOFBImageComparison.h"

#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkTesting.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkOFBImageComparison);
vtkCxxSetObjectMacro(vtkOFBImageComparison, Image, vtkImageData);
vtkCxxSetObjectMacro(vtkOFBImageComparison, Baseline, vtkImageData);
vtkCxxSetObjectMacro(vtkOFBImageComparison, Mask, vtkImageData);

namespace
{
/// An image as float planes (levels 0-255): R, G, B and the luminance.
struct Planes
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Channel[3];
  std::vector<float> Grey;
};

/// The size of a 2-D image, or an error text.
bool SizeOf(vtkImageData* image, const char* what, int& width, int& height, std::string& why)
{
  if (!image)
  {
    why = std::string("no ") + what;
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0 || !image->GetPointData()->GetScalars())
  {
    why = std::string("the ") + what + " is empty";
    return false;
  }
  if (dims[2] != 1)
  {
    why = std::string("the ") + what + " is not 2-D (" + std::to_string(dims[2]) + " slices)";
    return false;
  }
  width = dims[0];
  height = dims[1];
  return true;
}

/// Reads a 1-, 3- or 4-component unsigned char image into planes.
bool ToPlanes(vtkImageData* image, const char* what, Planes& planes, std::string& why)
{
  if (!SizeOf(image, what, planes.Width, planes.Height, why))
  {
    return false;
  }
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  if (!scalars || (nc != 1 && nc != 3 && nc != 4))
  {
    why = std::string("the ") + what +
      " is not an unsigned char image of 1, 3 or 4 components (grey, RGB, RGBA)";
    return false;
  }
  const size_t n = static_cast<size_t>(planes.Width) * planes.Height;
  const unsigned char* p = scalars->GetPointer(0);
  for (auto& channel : planes.Channel)
  {
    channel.resize(n);
  }
  planes.Grey.resize(n);
  for (size_t i = 0; i < n; ++i)
  {
    const unsigned char* q = p + nc * i;
    for (int c = 0; c < 3; ++c)
    {
      planes.Channel[c][i] = q[nc == 1 ? 0 : c];
    }
    planes.Grey[i] = 0.2126f * planes.Channel[0][i] + 0.7152f * planes.Channel[1][i] +
      0.0722f * planes.Channel[2][i];
  }
  return true;
}

/// Box blur of radius r, separable, the border pixels repeated outside the image.
std::vector<float> BoxBlur(const std::vector<float>& in, int width, int height, int r)
{
  std::vector<float> tmp(in.size());
  std::vector<float> out(in.size());
  const float scale = 1.0f / (2 * r + 1);
  for (int y = 0; y < height; ++y)
  {
    const float* row = in.data() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x)
    {
      float sum = 0.0f;
      for (int k = -r; k <= r; ++k)
      {
        sum += row[std::min(width - 1, std::max(0, x + k))];
      }
      tmp[static_cast<size_t>(y) * width + x] = sum * scale;
    }
  }
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      float sum = 0.0f;
      for (int k = -r; k <= r; ++k)
      {
        sum += tmp[static_cast<size_t>(std::min(height - 1, std::max(0, y + k))) * width + x];
      }
      out[static_cast<size_t>(y) * width + x] = sum * scale;
    }
  }
  return out;
}

/// Erosion of a 0/1 mask by a square of radius r; outside the image counts as 0.
std::vector<unsigned char> Erode(const std::vector<unsigned char>& in, int width, int height, int r)
{
  std::vector<unsigned char> tmp(in.size());
  std::vector<unsigned char> out(in.size());
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      unsigned char keep = 1;
      for (int k = -r; k <= r && keep; ++k)
      {
        const int xx = x + k;
        keep = (xx >= 0 && xx < width) ? in[static_cast<size_t>(y) * width + xx] : 0;
      }
      tmp[static_cast<size_t>(y) * width + x] = keep;
    }
  }
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      unsigned char keep = 1;
      for (int k = -r; k <= r && keep; ++k)
      {
        const int yy = y + k;
        keep = (yy >= 0 && yy < height) ? tmp[static_cast<size_t>(yy) * width + x] : 0;
      }
      out[static_cast<size_t>(y) * width + x] = keep;
    }
  }
  return out;
}

/// Pearson correlation of a (shifted by dx, dy) against b over the mask pixels; sets the
/// RMS of each (about its mean).
double ShiftedCorrelation(const std::vector<float>& a,
  const std::vector<float>& b,
  const std::vector<unsigned char>& mask,
  int width,
  int height,
  int dx,
  int dy,
  double& rmsA,
  double& rmsB)
{
  double sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
  double n = 0.0;
  for (int y = std::max(0, -dy); y < std::min(height, height - dy); ++y)
  {
    for (int x = std::max(0, -dx); x < std::min(width, width - dx); ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (!mask[i])
      {
        continue;
      }
      const double va = a[static_cast<size_t>(y + dy) * width + (x + dx)];
      const double vb = b[i];
      sa += va;
      sb += vb;
      saa += va * va;
      sbb += vb * vb;
      sab += va * vb;
      n += 1.0;
    }
  }
  if (n < 2.0)
  {
    rmsA = rmsB = 0.0;
    return 0.0;
  }
  const double varA = std::max(0.0, saa / n - (sa / n) * (sa / n));
  const double varB = std::max(0.0, sbb / n - (sb / n) * (sb / n));
  rmsA = std::sqrt(varA);
  rmsB = std::sqrt(varB);
  if (varA <= 0.0 || varB <= 0.0)
  {
    return 0.0;
  }
  return (sab / n - (sa / n) * (sb / n)) / (rmsA * rmsB);
}

/// An RGB unsigned char image of the planes.
vtkSmartPointer<vtkImageData> ToImage(const Planes& planes)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(planes.Width, planes.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  const size_t n = planes.Grey.size();
  for (size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      p[3 * i + c] = static_cast<unsigned char>(planes.Channel[c][i]);
    }
  }
  return image;
}

/// The surface's mask (1 inside): the non-zero pixels of `given`, or else the pixels that
/// differ from `background` (RGB in [0, 1]) by more than `tolerance` levels in both images.
bool SurfaceMask(vtkImageData* given,
  const Planes& image,
  const Planes& baseline,
  const double background[3],
  int tolerance,
  std::vector<unsigned char>& mask,
  std::string& why)
{
  const int w = image.Width;
  const int h = image.Height;
  const size_t n = static_cast<size_t>(w) * h;
  mask.assign(n, 0);
  if (given)
  {
    int mw = 0;
    int mh = 0;
    if (!SizeOf(given, "mask", mw, mh, why))
    {
      return false;
    }
    vtkDataArray* values = given->GetPointData()->GetScalars();
    if (mw != w || mh != h || values->GetNumberOfComponents() != 1)
    {
      std::ostringstream text;
      text << "the mask is " << mw << " x " << mh << " pixels of "
           << values->GetNumberOfComponents() << " components, not " << w << " x " << h
           << " of one component";
      why = text.str();
      return false;
    }
    for (size_t i = 0; i < n; ++i)
    {
      mask[i] = values->GetComponent(static_cast<vtkIdType>(i), 0) != 0.0;
    }
    return true;
  }
  const double limit = tolerance + 0.5;
  auto isBackground = [&](const Planes& p, size_t i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::fabs(p.Channel[c][i] - 255.0 * background[c]) > limit)
      {
        return false;
      }
    }
    return true;
  };
  for (size_t i = 0; i < n; ++i)
  {
    mask[i] = !isBackground(image, i) && !isBackground(baseline, i);
  }
  return true;
}

/// The correlation of the high-passed luminance (minus its box blur of radius r) over the
/// mask, the best over the shifts of the image by up to `shift` pixels; 1 when neither
/// image has texture there (a high pass under half a level RMS).
double TextureCorrelation(const Planes& image,
  const Planes& baseline,
  const std::vector<unsigned char>& mask,
  int r,
  int shift)
{
  const int w = image.Width;
  const int h = image.Height;
  std::vector<float> highImage = BoxBlur(image.Grey, w, h, r);
  std::vector<float> highBaseline = BoxBlur(baseline.Grey, w, h, r);
  for (size_t i = 0; i < highImage.size(); ++i)
  {
    highImage[i] = image.Grey[i] - highImage[i];
    highBaseline[i] = baseline.Grey[i] - highBaseline[i];
  }
  double best = -2.0;
  double rmsImage = 0.0;
  double rmsBaseline = 0.0;
  for (int dy = -shift; dy <= shift; ++dy)
  {
    for (int dx = -shift; dx <= shift; ++dx)
    {
      best = std::max(best,
        ShiftedCorrelation(highImage, highBaseline, mask, w, h, dx, dy, rmsImage, rmsBaseline));
    }
  }
  return (rmsImage < 0.5 && rmsBaseline < 0.5) ? 1.0 : best;
}

/// The mean absolute differences (levels) over the `count` mask pixels of the low-passed
/// (box blur of radius r) and of the plain RGB images.
void ColourDifferences(const Planes& image,
  const Planes& baseline,
  const std::vector<unsigned char>& mask,
  int r,
  vtkIdType count,
  double& low,
  double& plain)
{
  double lowSum = 0.0;
  double plainSum = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const std::vector<float> lowImage = BoxBlur(image.Channel[c], image.Width, image.Height, r);
    const std::vector<float> lowBaseline =
      BoxBlur(baseline.Channel[c], image.Width, image.Height, r);
    for (size_t i = 0; i < mask.size(); ++i)
    {
      if (mask[i])
      {
        lowSum += std::fabs(lowImage[i] - lowBaseline[i]);
        plainSum += std::fabs(image.Channel[c][i] - baseline.Channel[c][i]);
      }
    }
  }
  low = lowSum / (3.0 * count);
  plain = plainSum / (3.0 * count);
}

/// vtkImageDifference's thresholded error outside the mask: of the image whose mask
/// pixels are replaced by the baseline's, so that they add no error.
double OutsideError(const Planes& image,
  const Planes& baseline,
  const std::vector<unsigned char>& mask)
{
  Planes outside = image;
  for (size_t i = 0; i < mask.size(); ++i)
  {
    if (mask[i])
    {
      for (int c = 0; c < 3; ++c)
      {
        outside.Channel[c][i] = baseline.Channel[c][i];
      }
    }
  }
  vtkNew<vtkImageDifference> difference;
  difference->SetInputData(ToImage(outside));
  difference->SetImageData(ToImage(baseline));
  difference->Update();
  return difference->GetThresholdedError();
}

/// |image - baseline| x 8 per channel, clamped, as an RGB image.
vtkSmartPointer<vtkImageData> DifferenceOf(const Planes& image, const Planes& baseline)
{
  Planes diff = image;
  for (int c = 0; c < 3; ++c)
  {
    for (size_t i = 0; i < diff.Grey.size(); ++i)
    {
      diff.Channel[c][i] =
        std::min(255.0f, 8.0f * std::fabs(image.Channel[c][i] - baseline.Channel[c][i]));
    }
  }
  return ToImage(diff);
}

/// name.png -> name_<count>.png, as vtkTesting names alternative baselines.
std::string AlternativeName(const std::string& name, int count)
{
  const std::string stem = name.size() > 4 ? name.substr(0, name.size() - 4) : name;
  return stem + "_" + std::to_string(count) + ".png";
}

vtkSmartPointer<vtkImageData> ReadPNG(const std::string& fileName)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(fileName.c_str()))
  {
    return nullptr;
  }
  reader->SetFileName(fileName.c_str());
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  return image;
}

bool WritePNG(vtkImageData* image, const std::string& fileName)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(fileName.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}
}

//------------------------------------------------------------------------------
vtkOFBImageComparison::vtkOFBImageComparison() = default;

//------------------------------------------------------------------------------
vtkOFBImageComparison::~vtkOFBImageComparison()
{
  this->SetImage(nullptr);
  this->SetBaseline(nullptr);
  this->SetMask(nullptr);
  if (this->DifferenceImage)
  {
    this->DifferenceImage->Delete();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBImageComparison::Fail(const std::string& text)
{
  this->Correlation = 0.0;
  this->LowPassDifference = 0.0;
  this->MeanAbsoluteDifference = 0.0;
  this->ImageDifferenceError = 0.0;
  this->NumberOfMaskPixels = 0;
  this->Passed = false;
  this->ErrorText = text;
  if (this->DifferenceImage)
  {
    this->DifferenceImage->Delete();
    this->DifferenceImage = nullptr;
  }
  vtkErrorMacro(<< text);
  return false;
}

//------------------------------------------------------------------------------
bool vtkOFBImageComparison::Compare()
{
  // Step 1: the inputs as planes, checked.
  Planes image;
  Planes baseline;
  std::string why;
  if (!ToPlanes(this->Image, "image", image, why) ||
    !ToPlanes(this->Baseline, "baseline", baseline, why))
  {
    return this->Fail(why);
  }
  const int w = image.Width;
  const int h = image.Height;
  if (baseline.Width != w || baseline.Height != h)
  {
    std::ostringstream text;
    text << "the image is " << w << " x " << h << " pixels, the baseline " << baseline.Width
         << " x " << baseline.Height;
    return this->Fail(text.str());
  }
  // Step 2: the mask (given, or the pixels off the background in both), eroded.
  std::vector<unsigned char> mask;
  if (!SurfaceMask(
        this->Mask, image, baseline, this->BackgroundColor, this->BackgroundTolerance, mask, why))
  {
    return this->Fail(why);
  }
  const int r = this->HighPassRadius;
  mask = Erode(mask, w, h, r + 1);
  const vtkIdType count = std::count(mask.begin(), mask.end(), 1);
  if (count < this->MinimumMaskPixels)
  {
    std::ostringstream text;
    text << "the mask has " << count << " pixels once eroded by " << r + 1
         << " pixels, fewer than MinimumMaskPixels (" << this->MinimumMaskPixels
         << "): no surface in the image or the baseline, or the wrong background colour";
    return this->Fail(text.str());
  }
  this->NumberOfMaskPixels = count;

  // Steps 3-5: the texture and the colour inside the mask, VTK's measure outside.
  this->Correlation = TextureCorrelation(image, baseline, mask, r, this->AllowShift ? 1 : 0);
  ColourDifferences(
    image, baseline, mask, r, count, this->LowPassDifference, this->MeanAbsoluteDifference);
  this->ImageDifferenceError = OutsideError(image, baseline, mask);

  // Step 6: the difference image, the verdict and its text.
  if (this->DifferenceImage)
  {
    this->DifferenceImage->Delete();
  }
  vtkSmartPointer<vtkImageData> differenceImage = DifferenceOf(image, baseline);
  differenceImage->Register(this);
  this->DifferenceImage = differenceImage;

  std::ostringstream text;
  if (this->Correlation < this->CorrelationThreshold)
  {
    text << "The high-passed images correlate at " << this->Correlation << " inside the mask ("
         << count << " pixels), below CorrelationThreshold " << this->CorrelationThreshold
         << ": the texture changed.";
  }
  if (this->LowPassDifference > this->LowPassThreshold)
  {
    text << (text.tellp() > 0 ? " " : "") << "The low-passed images differ by "
         << this->LowPassDifference << " levels inside the mask, more than LowPassThreshold "
         << this->LowPassThreshold << ": the colours changed.";
  }
  if (this->ImageDifferenceError > this->ImageDifferenceThreshold)
  {
    text << (text.tellp() > 0 ? " " : "") << "vtkImageDifference's error outside the mask is "
         << this->ImageDifferenceError << ", more than ImageDifferenceThreshold "
         << this->ImageDifferenceThreshold << ": the silhouette or the background changed.";
  }
  this->ErrorText = text.str();
  this->Passed = this->ErrorText.empty();
  this->Modified();
  return this->Passed;
}

//------------------------------------------------------------------------------
int vtkOFBImageComparison::RegressionTest(vtkRenderWindow* window,
  const char* baselineFileName,
  const char* outputDirectory)
{
  if (!window)
  {
    this->Fail("no render window");
    return FAILED;
  }
  if (!baselineFileName || !*baselineFileName)
  {
    this->Fail("no baseline file name");
    return FAILED;
  }

  // The rendered image: the back buffer of a fresh render, as vtkTesting reads it.
  const vtkTypeBool swap = window->GetSwapBuffers();
  window->SwapBuffersOff();
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  window->SetSwapBuffers(swap);
  vtkSmartPointer<vtkImageData> rendered = grab->GetOutput();
  this->SetImage(rendered);
  if (vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer())
  {
    this->SetBackgroundColor(renderer->GetBackground());
  }

  const std::string baselineName = baselineFileName;
  const std::string name = vtksys::SystemTools::GetFilenameWithoutLastExtension(baselineName);
  const std::string directory = outputDirectory ? outputDirectory : "";
  std::string imageOut = directory.empty() ? "" : directory + "/" + name + ".png";
  std::string diffOut = directory.empty() ? "" : directory + "/" + name + ".diff.png";
  if (!imageOut.empty() &&
    vtksys::SystemTools::CollapseFullPath(imageOut) ==
      vtksys::SystemTools::CollapseFullPath(baselineName))
  {
    // Never over the baseline itself: no output.
    imageOut.clear();
    diffOut.clear();
  }
  if (!vtksys::SystemTools::FileExists(baselineName, true))
  {
    std::string text = "No baseline " + baselineName + ".";
    if (!imageOut.empty() && WritePNG(rendered, imageOut))
    {
      text += " The rendered image is " + imageOut + "; cp '" + imageOut + "' '" + baselineName +
        "' makes it the baseline.";
    }
    this->Fail(text);
    return FAILED;
  }

  // Every baseline (name.png, name_1.png, ...): the first that passes, else the best.
  std::string bestName;
  std::string compared; // the baseline of the last Compare()
  double bestCorrelation = -VTK_DOUBLE_MAX;
  for (int k = 0;; ++k)
  {
    const std::string candidate = k == 0 ? baselineName : AlternativeName(baselineName, k);
    if (k > 0 && !vtksys::SystemTools::FileExists(candidate, true))
    {
      break;
    }
    vtkSmartPointer<vtkImageData> baseline = ReadPNG(candidate);
    if (!baseline)
    {
      this->Fail("cannot read the baseline " + candidate + " as a PNG");
      continue;
    }
    this->SetBaseline(baseline);
    compared = candidate;
    if (this->Compare())
    {
      bestName = candidate;
      break;
    }
    if (this->NumberOfMaskPixels > 0 && this->Correlation > bestCorrelation)
    {
      bestCorrelation = this->Correlation;
      bestName = candidate;
    }
  }
  if (!this->Passed && !bestName.empty() && bestName != compared)
  {
    vtkSmartPointer<vtkImageData> baseline = ReadPNG(bestName);
    this->SetBaseline(baseline);
    this->Compare();
  }

  std::cout << "Image comparison (" << name << ", baseline " << bestName
            << "): high-pass correlation " << this->Correlation << ", low-pass difference "
            << this->LowPassDifference << " levels, mean absolute difference "
            << this->MeanAbsoluteDifference << " levels, over " << this->NumberOfMaskPixels
            << " mask pixels; vtkImageDifference error outside " << this->ImageDifferenceError
            << std::endl;
  if (this->Passed)
  {
    // Leave no image of an earlier failure behind.
    if (!imageOut.empty())
    {
      vtksys::SystemTools::RemoveFile(imageOut);
      vtksys::SystemTools::RemoveFile(diffOut);
    }
    return PASSED;
  }

  std::string text = this->ErrorText;
  if (!imageOut.empty() && WritePNG(rendered, imageOut))
  {
    text += " The rendered image is " + imageOut;
    if (this->DifferenceImage && WritePNG(this->DifferenceImage, diffOut))
    {
      text += ", the difference " + diffOut;
    }
    text += "; cp '" + imageOut + "' '" + baselineName + "' makes it the baseline.";
  }
  this->ErrorText = text;
  std::cout << "Failed image comparison (" << name << "): " << text << std::endl;
  return FAILED;
}

//------------------------------------------------------------------------------
int vtkOFBImageComparison::Test(int argc,
  char* argv[],
  vtkRenderWindow* window,
  vtkOFBImageComparison* settings)
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  if (testing->IsInteractiveModeSpecified())
  {
    return DO_INTERACTOR;
  }
  if (!testing->IsValidImageSpecified())
  {
    return NOT_RUN;
  }
  vtkSmartPointer<vtkOFBImageComparison> comparison = settings;
  if (!comparison)
  {
    comparison = vtkSmartPointer<vtkOFBImageComparison>::New();
  }
  const std::string baseline = testing->GetValidImageFileName();
  const std::string directory = testing->GetTempDirectory();
  return comparison->RegressionTest(window, baseline.c_str(), directory.c_str());
}

//------------------------------------------------------------------------------
void vtkOFBImageComparison::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Image: " << this->Image << "\n";
  os << indent << "Baseline: " << this->Baseline << "\n";
  os << indent << "Mask: " << this->Mask << "\n";
  os << indent << "BackgroundColor: (" << this->BackgroundColor[0] << ", "
     << this->BackgroundColor[1] << ", " << this->BackgroundColor[2] << ")\n";
  os << indent << "BackgroundTolerance: " << this->BackgroundTolerance << "\n";
  os << indent << "HighPassRadius: " << this->HighPassRadius << "\n";
  os << indent << "CorrelationThreshold: " << this->CorrelationThreshold << "\n";
  os << indent << "LowPassThreshold: " << this->LowPassThreshold << "\n";
  os << indent << "ImageDifferenceThreshold: " << this->ImageDifferenceThreshold << "\n";
  os << indent << "AllowShift: " << (this->AllowShift ? "On" : "Off") << "\n";
  os << indent << "MinimumMaskPixels: " << this->MinimumMaskPixels << "\n";
  os << indent << "Correlation: " << this->Correlation << "\n";
  os << indent << "LowPassDifference: " << this->LowPassDifference << "\n";
  os << indent << "MeanAbsoluteDifference: " << this->MeanAbsoluteDifference << "\n";
  os << indent << "ImageDifferenceError: " << this->ImageDifferenceError << "\n";
  os << indent << "NumberOfMaskPixels: " << this->NumberOfMaskPixels << "\n";
  os << indent << "Passed: " << (this->Passed ? "true" : "false") << "\n";
  os << indent << "ErrorText: " << this->ErrorText << "\n";
}
