// Image test: a far view of a sphere painted with a checker of 2-cell squares, without
// mipmaps (left, InverseDistance: aliasing) and with them (right, Mipmapped: the pattern
// averages out to the mean colour).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestOFBMapperMipmap(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 512);
  const unsigned char black[4] = { 20, 20, 20, 255 };
  const unsigned char yellow[4] = { 250, 220, 40, 255 };
  vtkofbtest::PaintChecker(ofb, 2.0 * ofb->GetCellSize(), black, yellow);

  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(400, 200);
  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkOFBPolyDataMapper> mapper;
    mapper->SetInputData(sphere);
    mapper->SetOFB(ofb);
    mapper->SetLookupMode(
      v == 0 ? vtkOFBPolyDataMapper::InverseDistance : vtkOFBPolyDataMapper::Mipmapped);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * v, 0.0, 0.5 * (v + 1), 1.0);
    renderer->AddActor(actor);
    renderer->SetBackground(0.3, 0.3, 0.4);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Zoom(0.5);
    renWin->AddRenderer(renderer);
  }
  renWin->Render();

  int retVal = vtkRegressionTestImage(renWin);
  if (retVal == vtkRegressionTester::DO_INTERACTOR)
  {
    vtkNew<vtkRenderWindowInteractor> iren;
    iren->SetRenderWindow(renWin);
    iren->Start();
  }
  return !retVal;
}
