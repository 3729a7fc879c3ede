// Image test: a sphere whose OFB colours hold a 3-D checker (by sample position),
// rendered by vtkOFBPolyDataMapper in Nearest mode: the squares must be crisp even
// though the sphere has few, large triangles.
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

int TestOFBMapperChecker(int argc, char* argv[])
{
  // A coarse sphere (24 x 12 segments): the checker is finer than its triangles.
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 12);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 256);
  const unsigned char red[4] = { 220, 40, 30, 255 };
  const unsigned char white[4] = { 240, 240, 240, 255 };
  vtkofbtest::PaintChecker(ofb, 0.25, red, white);

  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(sphere);
  mapper->SetOFB(ofb);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(300, 300);
  renWin->AddRenderer(renderer);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->ResetCamera();
  return vtkofbtest::RenderAndCompare(argc, argv, renWin, mapper);
}
