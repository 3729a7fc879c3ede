// vtkOFBSamplePicker: the sample under the mouse on a rendered bunny.
#include "vtkOFBTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellPicker.h"
#include "vtkMath.h"
#include "vtkOFBSamplePicker.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTriangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace vtkofbtest;

namespace
{
/**
 * Pick a 7 x 7 grid of display positions over the rendered `bunny`: every pick that
 * hits the surface gives a sample of the grid of the picked triangle's face normal, in
 * the cell of that grid under the picked point, within a cell of it in depth.
 */
void ExpectPicksUnderTheCursor(vtkPolyData* bunny)
{
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
  // The same pick, to know the picked triangle.
  vtkNew<vtkCellPicker> cellPicker;
  cellPicker->SetTolerance(picker->GetTolerance());
  const double s = ofb->GetCellSize();
  const double slack = 1e-9 * s;
  int hits = 0;
  for (int j = -3; j <= 3; ++j)
  {
    for (int i = -3; i <= 3; ++i)
    {
      const double x = 150 + 11 * i, y = 150 + 11 * j;
      const vtkIdType id = picker->Pick(x, y, renderer);
      EXPECT_EQ(picker->GetSampleId(), id);
      if (!cellPicker->Pick(x, y, 0.0, renderer) || cellPicker->GetCellId() < 0)
      {
        EXPECT_EQ(id, -1) << "nothing under " << x << " " << y;
        continue;
      }
      ++hits;
      ASSERT_GE(id, 0) << "no sample under " << x << " " << y;
      // The sample belongs to the grid of the picked triangle's face normal...
      vtkCell* triangle = bunny->GetCell(cellPicker->GetCellId());
      double corners[3][3], n[3];
      for (int k = 0; k < 3; ++k)
      {
        triangle->GetPoints()->GetPoint(k, corners[k]);
      }
      vtkTriangle::ComputeNormal(corners[0], corners[1], corners[2], n);
      int a = 0;
      a = std::fabs(n[1]) > std::fabs(n[a]) ? 1 : a;
      a = std::fabs(n[2]) > std::fabs(n[a]) ? 2 : a;
      EXPECT_EQ(ofb->GetSampleAxis(id), a) << "pick at " << x << " " << y;
      // ... and to the cell of that grid under the picked point, within a cell in depth.
      double sample[3], p[3];
      picker->GetPickPosition(p);
      ASSERT_TRUE(ofb->GetSamplePosition(id, sample));
      EXPECT_LE(std::fabs(sample[(a + 1) % 3] - p[(a + 1) % 3]), 0.5 * s + slack);
      EXPECT_LE(std::fabs(sample[(a + 2) % 3] - p[(a + 2) % 3]), 0.5 * s + slack);
      EXPECT_LE(std::fabs(sample[a] - p[a]), s + slack);
    }
  }
  EXPECT_GE(hits, 30) << "the bunny covers the centre of the view";
  // Off the surface: nothing.
  EXPECT_EQ(picker->Pick(2, 2, renderer), -1);
}
}

TEST(SamplePicker, PicksTheSampleUnderTheCursor)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  ExpectPicksUnderTheCursor(bunny);
}

TEST(SamplePicker, PicksInTheGridOfTheFaceWithPointNormals)
{
  // The cell picker interpolates point normals; the OFB's grids follow face normals.
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(bunny);
  normals->SplittingOff();
  normals->Update();
  ASSERT_NE(normals->GetOutput()->GetPointData()->GetNormals(), nullptr);
  ExpectPicksUnderTheCursor(normals->GetOutput());
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
