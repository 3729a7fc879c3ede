// Image test: resolution independence. The teapot (6320 triangles) rendered by
// vtkOFBPolyDataMapper with stripes and dots a few OFB cells wide painted into its OFB;
// the triangle edges are drawn too, to show that the painted detail is much finer than
// the triangles (and exercises the geometry-shader path of the mapper).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>

int TestOFBMapperResolution(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> teapot = vtkofbtest::ReadMesh("teapot.obj");
  if (!teapot)
  {
    std::cerr << "Cannot read teapot.obj" << std::endl;
    return 1;
  }
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(teapot, 512);
  const double s = ofb->GetCellSize();
  double bounds[6];
  teapot->GetBounds(bounds);
  const double midY = 0.5 * (bounds[2] + bounds[3]);
  // Upper half: stripes 3 cells wide (period 6 cells); lower half: dots of radius 2 cells
  // on an 8-cell lattice.
  vtkofbtest::Paint(ofb,
    [&](const double x[3], unsigned char rgba[4])
    {
      rgba[0] = 245;
      rgba[1] = 225;
      rgba[2] = 160;
      rgba[3] = 255;
      if (x[1] > midY)
      {
        if (std::fmod(std::fabs(x[0] + x[2]) / s, 6.0) < 3.0)
        {
          rgba[0] = 30;
          rgba[1] = 60;
          rgba[2] = 170;
        }
      }
      else
      {
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i)
        {
          const double c = 8.0 * s * std::floor(x[i] / (8.0 * s)) + 4.0 * s;
          d2 += (x[i] - c) * (x[i] - c);
        }
        if (d2 < 4.0 * s * s * 2.0)
        {
          rgba[0] = 200;
          rgba[1] = 30;
          rgba[2] = 40;
        }
      }
    });

  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(teapot);
  mapper->SetOFB(ofb);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->EdgeVisibilityOn();
  actor->GetProperty()->SetEdgeColor(0.45, 0.45, 0.45);
  actor->GetProperty()->SetLineWidth(1.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.9, 0.9, 0.95);
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(400, 300);
  renWin->AddRenderer(renderer);
  renderer->GetActiveCamera()->Elevation(25);
  renderer->GetActiveCamera()->Azimuth(35);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(3.0);
  return vtkofbtest::RenderAndCompare(argc, argv, renWin, mapper);
}
