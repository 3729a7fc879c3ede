// GoogleTest units of the surface LIC as shown: the pipe with a bump, its LIC with every
// setting of the sampler, vtkOFBLIC, vtkOFBColoring and vtkOFBPolyDataMapper at its
// default (but IntensityModulation on, to show the LIC), rendered close up and whole. The
// grey of the pixels that show the surface spans at least 0.7 between its 1st and 99th
// percentiles and has a standard deviation of at least 0.15, as the LIC array does. They
// open render windows (run under xvfb-run).
#include "vtkOFBLICTestHelpers.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <string>

using namespace vtkofbtest;

namespace
{
constexpr int Size = 400;                            // window pixels
constexpr double Background[3] = { 0.1, 0.1, 0.15 }; // not a grey

/// The grey (mean of R, G, B, in [0, 1]) of the pixels of `window` that are not the
/// background.
std::vector<double> SurfaceGreys(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  std::vector<double> greys;
  const int components = rgb ? rgb->GetNumberOfComponents() : 0;
  for (vtkIdType p = 0; rgb && p < rgb->GetNumberOfTuples(); ++p)
  {
    bool background = true;
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double v = rgb->GetValue(components * p + c);
      background = background && std::fabs(v - std::round(255.0 * Background[c])) <= 2.5;
      sum += v;
    }
    if (!background)
    {
      greys.push_back(sum / (3.0 * 255.0));
    }
  }
  return greys;
}
}

//------------------------------------------------------------------------------
TEST(LICDisplayContrast, DefaultsShowFullContrastCloseUpAndWhole)
{
  vtkNew<vtkTransform> tilt; // the tilt of MakePipeWithBump, to aim at the bump
  tilt->RotateY(20.0);
  tilt->RotateX(30.0);
  vtkSmartPointer<vtkPolyData> pipe = MakePipeWithBump();
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(pipe);
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputConnection(sampler->GetOutputPort());
  lic->Update();
  const ContrastMeasure array = LICContrast(lic->GetOutput());
  std::cout << "LIC array: 1st-99th percentile " << array.Low << "-" << array.High << " (span "
            << array.Span() << "), std " << array.Std << "\n";

  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(pipe);
  mapper->SetOFBConnection(lic->GetOutputPort());
  mapper->GetColoring()->SetIntensityArrayName("LIC");
  mapper->GetColoring()->IntensityModulationOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(Size, Size);
  window->AddRenderer(renderer);

  double bump[3], outward[3], axis[3];
  tilt->TransformPoint(std::array<double, 3>{ 1.35, 0.0, 0.0 }.data(), bump);
  tilt->TransformVector(std::array<double, 3>{ 0.8, 0.0, 0.6 }.data(), outward);
  tilt->TransformVector(std::array<double, 3>{ 0.0, 0.0, 1.0 }.data(), axis);
  struct View
  {
    std::string Name;
    const double* Focus;
    double Distance;
  };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  // Close: the bump, 0.45 units (about 100 OFB cells) across; far: the whole pipe.
  const View views[] = {
    { "close up", bump, 0.45 / (2.0 * std::tan(vtkMath::RadiansFromDegrees(15.0))) },
    { "whole", origin, 9.0 }
  };
  for (const View& view : views)
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(view.Focus[0], view.Focus[1], view.Focus[2]);
    camera->SetPosition(view.Focus[0] + view.Distance * outward[0],
      view.Focus[1] + view.Distance * outward[1],
      view.Focus[2] + view.Distance * outward[2]);
    camera->SetViewUp(axis);
    renderer->ResetCameraClippingRange();
    window->Render();
    ASSERT_TRUE(mapper->GetLastRenderUsedOFB()) << view.Name;
    const std::vector<double> greys = SurfaceGreys(window);
    const ContrastMeasure shown = MeasureContrast(greys);
    std::cout << "grey shown " << view.Name << ": 1st-99th percentile " << shown.Low << "-"
              << shown.High << " (span " << shown.Span() << "), std " << shown.Std << " over "
              << shown.Count << " pixels\n";
    EXPECT_GT(shown.Count, Size * Size / 5) << view.Name;
    EXPECT_GE(shown.Span(), 0.7) << view.Name;
    EXPECT_GE(shown.Std, 0.15) << view.Name;
  }
}
