// vtkOFBSamplePicker: the sample under the mouse on a rendered bunny.
#include "vtkOFBTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkOFBSamplePicker.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace vtkofbtest;

TEST(SamplePicker, PicksTheSampleUnderTheCursor)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 512);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(bunny);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkOFBSamplePicker> picker;
  picker->SetOFB(ofb);
  int hits = 0;
  for (int i = 0; i < 5; ++i)
  {
    const vtkIdType id = picker->Pick(150 + 10 * (i - 2), 150, renderer);
    if (id < 0)
    {
      continue;
    }
    ++hits;
    double x[3], p[3];
    picker->GetPickPosition(p);
    ASSERT_TRUE(ofb->GetSamplePosition(id, x));
    EXPECT_LE(std::sqrt(vtkMath::Distance2BetweenPoints(x, p)),
      std::sqrt(3.0) * ofb->GetCellSize());
    EXPECT_EQ(picker->GetSampleId(), id);
  }
  EXPECT_GE(hits, 3) << "the bunny covers the centre of the view";
  // Off the surface: nothing.
  EXPECT_EQ(picker->Pick(2, 2, renderer), -1);
}

TEST(SamplePicker, ErrorsWithoutRendererOrOFB)
{
  vtkNew<vtkOFBSamplePicker> picker;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(picker);
  vtkNew<vtkRenderer> renderer;
  EXPECT_EQ(picker->Pick(0, 0, nullptr), -1);
  EXPECT_NE(observer->Errors.find("no renderer"), std::string::npos);
  EXPECT_EQ(picker->Pick(0, 0, renderer), -1);
  EXPECT_NE(observer->Errors.find("no OFB"), std::string::npos);
  std::ostringstream os;
  picker->Print(os);
  EXPECT_NE(os.str().find("Tolerance: 0.001"), std::string::npos);
  observer->Delete();
}
