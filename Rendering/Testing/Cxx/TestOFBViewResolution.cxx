// GoogleTest units of vtkOFBViewResolution: the OFB resolution that gives a chosen number
// of cells a pixel on the visible surface, for a parallel and a perspective camera, its
// clamping and noise grain, and bad input.
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFBTestUtilities.h"
#include "vtkOFBViewResolution.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace
{
// A unit square at z = 0 and a 200 x 100 window's renderer looking at it from +z.
struct ViewScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkPolyData> Square;

  ViewScene()
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(0.0, 0.0, 0.0);
    plane->SetPoint1(1.0, 0.0, 0.0);
    plane->SetPoint2(0.0, 1.0, 0.0);
    plane->SetResolution(16, 16);
    plane->Update();
    this->Square = plane->GetOutput();
    this->Window->SetSize(200, 100);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.5, 0.5, 0.0);
    camera->SetPosition(0.5, 0.5, 4.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    this->Renderer->ResetCameraClippingRange();
  }
};
}

TEST(OFBViewResolution, ParallelViewGivesTheCellsPerPixel)
{
  ViewScene scene;
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.5); // the square's height fills the 100 pixels
  vtkNew<vtkOFBViewResolution> view;
  ASSERT_TRUE(view->Compute(scene.Renderer, scene.Square));
  EXPECT_NEAR(view->GetPixelSize(), 0.01, 1.0e-12);
  EXPECT_EQ(view->GetResolution(), 102); // 100 cells + the sampler's 2 padding cells
  EXPECT_NEAR(view->GetNoiseGrainSize(), 2.0, 1.0e-9);
  EXPECT_GT(view->GetNumberOfVisiblePoints(), 0);

  view->SetCellsPerPixel(2.0);
  view->SetNoiseGrainPixels(3.0);
  ASSERT_TRUE(view->Compute(scene.Renderer, scene.Square));
  EXPECT_EQ(view->GetResolution(), 202);
  EXPECT_NEAR(view->GetNoiseGrainSize(), 6.0, 1.0e-9); // 3 pixels of 2 cells

  // Zoomed in 100 times, the resolution is clamped, and the grain is a cell (3 pixels are
  // less than a cell there).
  camera->SetParallelScale(0.005);
  view->SetMaximumResolution(1000);
  ASSERT_TRUE(view->Compute(scene.Renderer, scene.Square));
  EXPECT_EQ(view->GetResolution(), 1000);
  EXPECT_EQ(view->GetNoiseGrainSize(), 1.0);

  // Zoomed out to a pixel a unit: the resolution is clamped to the minimum, and the grain
  // stays 3 pixels wide, 3 units: 42 cells of 1/14.
  camera->SetParallelScale(50.0);
  ASSERT_TRUE(view->Compute(scene.Renderer, scene.Square));
  EXPECT_EQ(view->GetResolution(), 16);
  EXPECT_NEAR(view->GetNoiseGrainSize(), 42.0, 1.0e-9);
}

TEST(OFBViewResolution, PerspectiveResolutionFollowsTheDistance)
{
  ViewScene scene;
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->ParallelProjectionOff();
  camera->SetViewAngle(30.0);
  vtkNew<vtkOFBViewResolution> view;
  view->SetMaximumResolution(65536);
  ASSERT_TRUE(view->Compute(scene.Renderer, scene.Square));
  // At distance 4 a pixel is 2 * 4 * tan(15 deg) / 100 long.
  EXPECT_NEAR(view->GetPixelSize(), 8.0 * std::tan(vtkMath::Pi() / 12.0) / 100.0, 1.0e-9);
  const int far = view->GetResolution();
  camera->SetPosition(0.5, 0.5, 1.0);
  scene.Renderer->ResetCameraClippingRange();
  ASSERT_TRUE(view->Compute(scene.Renderer, scene.Square));
  const int near = view->GetResolution();
  EXPECT_NEAR(near - 2, 4.0 * (far - 2), 4.0) << far << " cells at distance 4, " << near << " at 1";

  // The bounds' lattice gives the same for a flat box.
  double bounds[6];
  scene.Square->GetBounds(bounds);
  ASSERT_TRUE(view->Compute(scene.Renderer, bounds));
  EXPECT_EQ(view->GetResolution(), near);

  std::ostringstream os;
  view->Print(os);
  EXPECT_NE(os.str().find("CellsPerPixel"), std::string::npos);
  EXPECT_NE(os.str().find("NoiseGrainPixels"), std::string::npos);
}

TEST(OFBViewResolution, BadInputIsAnError)
{
  ViewScene scene;
  vtkNew<vtkOFBViewResolution> view;
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(view);
  EXPECT_FALSE(view->Compute(nullptr, scene.Square));
  EXPECT_FALSE(view->Compute(scene.Renderer, static_cast<vtkDataSet*>(nullptr)));
  vtkNew<vtkPolyData> empty;
  EXPECT_FALSE(view->Compute(scene.Renderer, empty));
  const double inverted[6] = { 1.0, 0.0, 0.0, 1.0, 0.0, 1.0 };
  EXPECT_FALSE(view->Compute(scene.Renderer, inverted));
  // Behind the camera: nothing in view.
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.5, 0.5, -4.0);
  camera->SetFocalPoint(0.5, 0.5, -8.0);
  EXPECT_FALSE(view->Compute(scene.Renderer, scene.Square));
  EXPECT_EQ(view->GetResolution(), 0);
  EXPECT_NE(messages->Errors.find("no point of the surface is in the view"), std::string::npos)
    << messages->Errors;
}
