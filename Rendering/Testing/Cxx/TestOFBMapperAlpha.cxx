// Image test (paper Fig. 2): a sphere whose OFB colours start fully transparent is
// revealed where paint lands: a translucent red patch in front, an opaque yellow patch on
// the far side seen through the unpainted surface, and an opaque blue cylinder piercing
// the sphere, sorted with the surface by depth peeling.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCylinderSource.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestOFBMapperAlpha(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 24);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 128);
  vtkofbtest::Paint(ofb,
    [](const double*, unsigned char rgba[4])
    {
      rgba[0] = rgba[1] = rgba[2] = 255;
      rgba[3] = 0;
    });
  const double front[3] = { 0.35, 0.3, 0.9 };
  const unsigned char red[4] = { 230, 30, 20, 170 };
  const double back[3] = { -0.3, -0.25, -0.9 };
  const unsigned char yellow[4] = { 250, 210, 40, 255 };
  if (vtkofbtest::PaintSphere(ofb, front, 0.55, red) == 0 ||
    vtkofbtest::PaintSphere(ofb, back, 0.6, yellow) == 0)
  {
    std::cerr << "No sample painted." << std::endl;
    return 1;
  }

  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(sphere);
  mapper->SetOFB(ofb);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  if (!mapper->HasTranslucentPolygonalGeometry())
  {
    std::cerr << "The mapper does not report its translucent colours." << std::endl;
    return 1;
  }

  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(0.2);
  cylinder->SetHeight(3.2);
  cylinder->SetResolution(32);
  vtkNew<vtkPolyDataMapper> cylinderMapper;
  cylinderMapper->SetInputConnection(cylinder->GetOutputPort());
  vtkNew<vtkActor> cylinderActor;
  cylinderActor->SetMapper(cylinderMapper);
  cylinderActor->GetProperty()->SetColor(0.2, 0.35, 0.9);
  cylinderActor->RotateZ(60.0);
  cylinderActor->RotateX(30.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(cylinderActor);
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.15);
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(8);
  renderer->SetOcclusionRatio(0.0);
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(300, 300);
  renWin->SetAlphaBitPlanes(1);
  renWin->SetMultiSamples(0);
  renWin->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.3);
  renWin->Render();
  if (!mapper->GetLastRenderUsedOFB() || !renderer->GetLastRenderingUsedDepthPeeling())
  {
    std::cerr << "The mapper did not colour from the OFB, or depth peeling was not used."
              << std::endl;
    return 1;
  }

  return vtkofbtest::CompareWithBaseline(argc, argv, renWin);
}
