/**
 * vtkOFBRegressionTestImage(window): the image test of a VTK test program
 * (`int TestX(int argc, char* argv[])`) by vtkOFBImageComparison, as VTK's
 * vtkRegressionTestImage(window) by vtkTesting: the baseline of -V, the rendered and
 * difference images to the directory of -T when it fails. Returns
 * vtkOFBImageComparison::PASSED (1), FAILED (0), NOT_RUN (2, no -V) or DO_INTERACTOR
 * (3, -I).
 *
 * vtkOFBRegressionTestImageWith(window, comparison): the same with the settings of a
 * vtkOFBImageComparison (thresholds, mask).
 */
#ifndef vtkOFBRegressionTestImage_h
#define vtkOFBRegressionTestImage_h
#ifndef __VTK_WRAP__

#include "vtkOFBImageComparison.h"

#define vtkOFBRegressionTestImage(window) vtkOFBImageComparison::Test(argc, argv, window)

#define vtkOFBRegressionTestImageWith(window, comparison)                                          \
  vtkOFBImageComparison::Test(argc, argv, window, comparison)

#endif
#endif
