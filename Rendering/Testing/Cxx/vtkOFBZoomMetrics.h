// Screen-space measures of a rendered LIC for the zoom tests (TestOFBLICZoom): how much
// longer it is correlated along the field than across it, how much larger its gradient is
// across OFB cell borders than inside cells, and across the line where the mipmap level
// changes than around it. Images are grey levels in [0, 1], row-major from the bottom row.
#ifndef vtkOFBZoomMetrics_h
#define vtkOFBZoomMetrics_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace vtkofbzoom
{
struct GreyImage
{
  int Width = 0;
  int Height = 0;
  std::vector<double> Values;
  double At(int i, int j) const { return this->Values[static_cast<size_t>(j) * this->Width + i]; }
};

/// The back buffer of `window` as grey levels (the red channel; the LIC tests render grey).
inline GreyImage Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  GreyImage out;
  out.Width = dims[0];
  out.Height = dims[1];
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  out.Values.resize(static_cast<size_t>(dims[0]) * dims[1]);
  for (size_t k = 0; k < out.Values.size(); ++k)
  {
    out.Values[k] = p[3 * k] / 255.0;
  }
  return out;
}

/// Mean and variance of the grey levels over the pixels at least `margin` from the image's
/// sides (0 and 0 where there are none).
struct Moments
{
  double Mean = 0.0;
  double Variance = 0.0;
};

inline Moments MeanAndVariance(const GreyImage& image, int margin)
{
  double sum = 0.0;
  double sum2 = 0.0;
  long n = 0;
  for (int j = margin; j < image.Height - margin; ++j)
  {
    for (int i = margin; i < image.Width - margin; ++i)
    {
      sum += image.At(i, j);
      sum2 += image.At(i, j) * image.At(i, j);
      ++n;
    }
  }
  Moments m;
  if (n > 0)
  {
    m.Mean = sum / n;
    m.Variance = sum2 / n - m.Mean * m.Mean;
  }
  return m;
}

/// Standard deviation of the image over the pixels at least `margin` from its sides.
inline double Contrast(const GreyImage& image, int margin)
{
  return std::sqrt(std::max(0.0, MeanAndVariance(image, margin).Variance));
}

/// The integral scale in pixel steps along the direction (di, dj) (a unit step: an axis
/// or a diagonal): 1 + the sum over lags d = 1..maxLag of the normalised autocorrelation at lag d,
/// over the pixels at least `margin` from the sides. Long for streaks along the
/// direction, about the grain's width across them, about 1 for uncorrelated noise.
inline double CorrelationLength(const GreyImage& image, int di, int dj, int maxLag, int margin)
{
  const Moments moments = MeanAndVariance(image, margin);
  const double mean = moments.Mean;
  const double variance = moments.Variance;
  if (!(variance > 1.0e-12))
  {
    return 0.0;
  }
  double length = 1.0;
  for (int d = 1; d <= maxLag; ++d)
  {
    double c = 0.0;
    int m = 0;
    for (int j = margin + std::max(0, -d * dj); j < image.Height - margin - std::max(0, d * dj);
         ++j)
    {
      for (int i = margin + std::max(0, -d * di); i < image.Width - margin - std::max(0, d * di);
           ++i)
      {
        c += (image.At(i, j) - mean) * (image.At(i + d * di, j + d * dj) - mean);
        ++m;
      }
    }
    length += m ? c / (m * variance) : 0.0;
  }
  return length;
}

/// The mean square of the second difference at lag `lag` along the pixel step (di, dj)
/// (an axis or a diagonal): I(p) - (I(p - lag d) + I(p + lag d)) / 2, over the pixels at
/// least `margin` from the sides, both ends included. A band-pass along the direction that
/// passes most a period of 2 lag steps: along a streak it sees beads of that period, which
/// a streak smooth along its length does not have.
inline double SecondDifferencePower(const GreyImage& image, int di, int dj, int lag, int margin)
{
  double sum = 0.0;
  long n = 0;
  const int reach = margin + lag * std::max(std::abs(di), std::abs(dj));
  for (int j = reach; j < image.Height - reach; ++j)
  {
    for (int i = reach; i < image.Width - reach; ++i)
    {
      const double d = image.At(i, j) -
        0.5 * (image.At(i - lag * di, j - lag * dj) + image.At(i + lag * di, j + lag * dj));
      sum += d * d;
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

/// The image at (x, y) in pixel units (pixel centres at whole numbers), bilinear.
inline double Bilinear(const GreyImage& image, double x, double y)
{
  const int i = static_cast<int>(std::floor(x));
  const int j = static_cast<int>(std::floor(y));
  const double fx = x - i;
  const double fy = y - j;
  const int i1 = std::min(i + 1, image.Width - 1);
  const int j1 = std::min(j + 1, image.Height - 1);
  return (1.0 - fy) * ((1.0 - fx) * image.At(i, j) + fx * image.At(i1, j)) +
    fy * ((1.0 - fx) * image.At(i, j1) + fx * image.At(i1, j1));
}

/// The roughness of the image along the unit direction (dx, dy): the sum over lags
/// h = 1..maxLag pixels of the mean square of I(p) - (I(p - h d) + I(p + h d)) / 2 (the
/// image read bilinearly between pixels), over the pixels p whose reads stay `margin`
/// from the sides. Along a streak it sees any modulation of a period up to 2 maxLag
/// pixels (beads), which a streak smooth along its length does not have; across it, the
/// streaks themselves.
inline double Roughness(const GreyImage& image, double dx, double dy, int maxLag, int margin)
{
  double total = 0.0;
  const int reach = margin + maxLag + 1;
  for (int h = 1; h <= maxLag; ++h)
  {
    double sum = 0.0;
    long n = 0;
    for (int j = reach; j < image.Height - reach; ++j)
    {
      for (int i = reach; i < image.Width - reach; ++i)
      {
        const double d = image.At(i, j) -
          0.5 * (Bilinear(image, i - h * dx, j - h * dy) + Bilinear(image, i + h * dx, j + h * dy));
        sum += d * d;
        ++n;
      }
    }
    total += n ? sum / n : 0.0;
  }
  return total;
}

/// The normalised autocorrelation at lag `lag` along the pixel step (di, dj), over the
/// pixels at least `margin` from the sides.
inline double Autocorrelation(const GreyImage& image, int di, int dj, int lag, int margin)
{
  const Moments moments = MeanAndVariance(image, margin);
  const double mean = moments.Mean;
  const double variance = moments.Variance;
  const int reach = margin + lag * std::max(std::abs(di), std::abs(dj));
  double c = 0.0;
  long m = 0;
  for (int j = reach; j < image.Height - reach; ++j)
  {
    for (int i = reach; i < image.Width - reach; ++i)
    {
      c += (image.At(i, j) - mean) * (image.At(i + lag * di, j + lag * dj) - mean);
      ++m;
    }
  }
  return m && variance > 1.0e-12 ? c / (m * variance) : 0.0;
}

/// Mean absolute difference of neighbouring pixels (horizontal and vertical pairs) whose
/// pair `selected(i, j, i2, j2)` returns 1 (group A) and 2 (group B); other values skip
/// the pair. Returns mean(A) / mean(B) and both means.
inline double GradientRatio(const GreyImage& image,
  const std::function<int(int, int, int, int)>& selected,
  double& meanA,
  double& meanB)
{
  double sums[2] = { 0.0, 0.0 };
  long counts[2] = { 0, 0 };
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const int pairs[2][2] = { { i + 1, j }, { i, j + 1 } };
      for (const auto& q : pairs)
      {
        if (q[0] >= image.Width || q[1] >= image.Height)
        {
          continue;
        }
        const int group = selected(i, j, q[0], q[1]);
        if (group == 1 || group == 2)
        {
          sums[group - 1] += std::abs(image.At(q[0], q[1]) - image.At(i, j));
          ++counts[group - 1];
        }
      }
    }
  }
  meanA = counts[0] ? sums[0] / counts[0] : 0.0;
  meanB = counts[1] ? sums[1] / counts[1] : 0.0;
  return meanB > 0.0 ? meanA / meanB : (meanA > 0.0 ? HUGE_VAL : 1.0);
}
}

#endif
