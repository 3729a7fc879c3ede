/**
 * @class   vtkOFBImageComparison
 * @brief   Compares a rendered image with its baseline by a measure that sees texture
 *
 * VTK's image difference (vtkImageDifference, as vtkRegressionTestImage uses it) forgives
 * differences of up to about 105 levels a channel after a 3 x 3 averaging, and allows a
 * shift of one pixel: that is right for shaded geometry, but a surface LIC is a texture of
 * fine grey streaks, and a LIC with half the steps, another noise, or the OFB at another
 * resolution passes it. vtkOFBImageComparison compares such an image in two parts:
 *
 * - Inside the surface's mask, the texture: the Pearson correlation of the high-passed
 *   luminance of the image and of the baseline (luminance minus its box blur of radius
 *   HighPassRadius), which must be at least CorrelationThreshold; and the colour: the
 *   mean absolute difference of the low-passed (box-blurred) RGB images, in levels of
 *   0-255, which must be at most LowPassThreshold.
 * - Everywhere else (the background, the silhouettes), VTK's own measure: the
 *   vtkImageDifference thresholded error of the image whose mask pixels are replaced by
 *   the baseline's, which must be at most ImageDifferenceThreshold (VTK's default 0.15).
 *
 * The mask is the given Mask image (non-zero pixels), or else the pixels that differ from
 * BackgroundColor (by more than BackgroundTolerance levels in a channel) in both images.
 * It is eroded by HighPassRadius + 1 pixels, so that silhouettes, where antialiasing and
 * sub-pixel coverage differ between drivers, never enter the high pass. With AllowShift
 * the correlation is the best over the nine shifts of the image by up to one pixel, as
 * vtkImageDifference allows.
 *
 * Compare() computes the measures and returns whether the image passed. Bad input (no
 * image or baseline, an empty image, sizes that differ, a mask of another size, a type
 * other than unsigned char, too small a mask) fails the comparison with an error
 * (vtkErrorMacro and GetErrorText()), never a crash.
 *
 * RegressionTest() renders a window, reads its baseline (a PNG, and the alternatives
 * name_1.png, name_2.png, ... as vtkTesting accepts them) and, when the image fails,
 * writes the rendered image (name.png) and a difference image (name.diff.png) to a
 * directory, so that the image can be inspected and copied over the baseline. Test() does
 * the same with the arguments of a VTK test (-V baseline, -T temporary directory, -I
 * interactive, -D/-B data roots), as vtkRegressionTestImage does; see
 * vtkOFBRegressionTestImage.h.
 *
 * The thresholds are calibrated on surface LIC rendered by Mesa's llvmpipe: a rerun with
 * the same settings correlates at 1, while NumberOfSteps 20 -> 10, another
 * NoiseGeneratorSeed and the OFB's Resolution 512 -> 502 correlate far below the
 * threshold (docs/testing.md gives the numbers).
 */

#ifndef vtkOFBImageComparison_h
#define vtkOFBImageComparison_h

#include "vtkOFBTestingImageModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for the error text

class vtkImageData;
class vtkRenderWindow;

class VTKOFBTESTINGIMAGE_EXPORT vtkOFBImageComparison : public vtkObject
{
public:
  static vtkOFBImageComparison* New();
  vtkTypeMacro(vtkOFBImageComparison, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Results of Test() and RegressionTest(), as vtkTesting's.
   */
  enum ReturnValue
  {
    FAILED = 0,
    PASSED = 1,
    NOT_RUN = 2,
    DO_INTERACTOR = 3
  };

  ///@{
  /**
   * The image to check and its baseline: 2-D unsigned char images with 1 (grey), 3 (RGB)
   * or 4 (RGBA, the alpha is ignored) components, of the same size (default none).
   */
  void SetImage(vtkImageData* image);
  vtkGetObjectMacro(Image, vtkImageData);
  void SetBaseline(vtkImageData* baseline);
  vtkGetObjectMacro(Baseline, vtkImageData);
  ///@}

  ///@{
  /**
   * The surface's mask: a one-component image of the same size, non-zero where the
   * surface is (default none: the mask comes from BackgroundColor).
   */
  void SetMask(vtkImageData* mask);
  vtkGetObjectMacro(Mask, vtkImageData);
  ///@}

  ///@{
  /**
   * Without a Mask, the pixels of this colour (RGB in [0, 1], as vtkRenderer's
   * background; default black) in either image are background. RegressionTest() sets it
   * to the background of the window's first renderer.
   */
  vtkSetVector3Macro(BackgroundColor, double);
  vtkGetVector3Macro(BackgroundColor, double);
  ///@}

  ///@{
  /**
   * A pixel is background when each channel is within this many levels (0-255) of
   * BackgroundColor (default 2).
   */
  vtkSetClampMacro(BackgroundTolerance, int, 0, 255);
  vtkGetMacro(BackgroundTolerance, int);
  ///@}

  ///@{
  /**
   * Radius in pixels of the box blur that the high pass subtracts and that the low pass
   * is (default 3: a 7 x 7 box). The mask is eroded by HighPassRadius + 1 pixels.
   */
  vtkSetClampMacro(HighPassRadius, int, 1, 32);
  vtkGetMacro(HighPassRadius, int);
  ///@}

  ///@{
  /**
   * The least correlation of the high-passed luminance inside the mask for the image to
   * pass (default 0.97).
   */
  vtkSetClampMacro(CorrelationThreshold, double, -1.0, 1.0);
  vtkGetMacro(CorrelationThreshold, double);
  ///@}

  ///@{
  /**
   * The largest mean absolute difference of the low-passed RGB images inside the mask, in
   * levels of 0-255, for the image to pass (default 6).
   */
  vtkSetClampMacro(LowPassThreshold, double, 0.0, 255.0);
  vtkGetMacro(LowPassThreshold, double);
  ///@}

  ///@{
  /**
   * The largest vtkImageDifference thresholded error outside the mask for the image to
   * pass (default 0.15, the threshold of vtkRegressionTestImage).
   */
  vtkSetClampMacro(ImageDifferenceThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ImageDifferenceThreshold, double);
  ///@}

  ///@{
  /**
   * Whether the correlation is the best over the shifts of the image by up to one pixel
   * in x and y (default on, as vtkImageDifference's AllowShift).
   */
  vtkSetMacro(AllowShift, bool);
  vtkGetMacro(AllowShift, bool);
  vtkBooleanMacro(AllowShift, bool);
  ///@}

  ///@{
  /**
   * The fewest pixels the eroded mask must have; fewer fail the comparison, as the
   * correlation would say little (default 400).
   */
  vtkSetClampMacro(MinimumMaskPixels, int, 1, VTK_INT_MAX);
  vtkGetMacro(MinimumMaskPixels, int);
  ///@}

  /**
   * Compare the image with the baseline: compute the measures below and return whether
   * the image passed (false with an error text for bad input).
   */
  bool Compare();

  ///@{
  /**
   * Results of the last Compare(). Correlation: of the high-passed luminance inside the
   * eroded mask (1 when neither image has texture there: a high pass under half a level
   * RMS). LowPassDifference and MeanAbsoluteDifference: of the low-passed and of the
   * plain RGB images inside the eroded mask, in levels of 0-255. ImageDifferenceError:
   * vtkImageDifference's thresholded error outside it. NumberOfMaskPixels: the pixels of
   * the eroded mask. All are 0 before a comparison or after bad input.
   */
  vtkGetMacro(Correlation, double);
  vtkGetMacro(LowPassDifference, double);
  vtkGetMacro(MeanAbsoluteDifference, double);
  vtkGetMacro(ImageDifferenceError, double);
  vtkGetMacro(NumberOfMaskPixels, vtkIdType);
  vtkGetMacro(Passed, bool);
  ///@}

  /**
   * Why the last comparison failed: each measure over its threshold, or the bad input
   * ("" when it passed).
   */
  const char* GetErrorText() { return this->ErrorText.c_str(); }

  /**
   * A difference image of the last comparison (RGB, the size of the inputs): the absolute
   * difference of the two images times 8, clamped; null before a comparison or after bad
   * input.
   */
  vtkGetObjectMacro(DifferenceImage, vtkImageData);

  /**
   * Render `window` (back buffer, RGB) and compare it with the PNG `baselineFileName`
   * and its alternatives name_1.png, name_2.png, ...; the background of the window's
   * first renderer is the BackgroundColor. It passes when any baseline passes; the
   * measures are those of the best (highest correlation). When it fails and
   * `outputDirectory` is given, the rendered image and a difference image are written
   * there as <name>.png and <name>.diff.png (with no baseline, the rendered image only).
   * Returns PASSED or FAILED.
   */
  int RegressionTest(vtkRenderWindow* window,
    const char* baselineFileName,
    const char* outputDirectory);

#ifndef __VTK_WRAP__
  /**
   * RegressionTest() with the arguments of a VTK test, as vtkTesting::Test: the baseline
   * of -V (relative to -B or -D, VTK_BASELINE_ROOT or VTK_DATA_ROOT), the directory of -T
   * (or VTK_TEMP_DIR). Returns DO_INTERACTOR with -I, NOT_RUN without -V, else PASSED or
   * FAILED. `settings` (optional) gives the thresholds and mask settings.
   */
  static int Test(int argc,
    char* argv[],
    vtkRenderWindow* window,
    vtkOFBImageComparison* settings = nullptr);
#endif

protected:
  vtkOFBImageComparison();
  ~vtkOFBImageComparison() override;

  /// Clears the results and records `text` as the error (vtkErrorMacro); returns false.
  bool Fail(const std::string& text);

  vtkImageData* Image = nullptr;
  vtkImageData* Baseline = nullptr;
  vtkImageData* Mask = nullptr;
  vtkImageData* DifferenceImage = nullptr;
  double BackgroundColor[3] = { 0.0, 0.0, 0.0 };
  int BackgroundTolerance = 2;
  int HighPassRadius = 3;
  double CorrelationThreshold = 0.97;
  double LowPassThreshold = 6.0;
  double ImageDifferenceThreshold = 0.15;
  bool AllowShift = true;
  int MinimumMaskPixels = 400;

  double Correlation = 0.0;
  double LowPassDifference = 0.0;
  double MeanAbsoluteDifference = 0.0;
  double ImageDifferenceError = 0.0;
  vtkIdType NumberOfMaskPixels = 0;
  bool Passed = false;
  std::string ErrorText;

private:
  vtkOFBImageComparison(const vtkOFBImageComparison&) = delete;
  void operator=(const vtkOFBImageComparison&) = delete;
};

#endif
