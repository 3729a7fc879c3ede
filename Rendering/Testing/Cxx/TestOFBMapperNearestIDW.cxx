// Image test: Nearest (left) against InverseDistance (right) lookups, close up on a
// sphere whose coarse OFB (64 cells) holds a random colour per sample: Nearest shows
// the sample mosaic, IDW blends it smoothly.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestOFBMapperNearestIDW(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 64);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkofbtest::Paint(ofb, [&](const double*, unsigned char rgba[4]) {
    for (int i = 0; i < 3; ++i)
    {
      random->Next();
      rgba[i] = static_cast<unsigned char>(40 + 200 * random->GetValue());
    }
    rgba[3] = 255;
  });

  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(400, 200);
  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkOFBPolyDataMapper> mapper;
    mapper->SetInputData(sphere);
    mapper->SetOFB(ofb);
    mapper->SetLookupMode(
      v == 0 ? vtkOFBPolyDataMapper::Nearest : vtkOFBPolyDataMapper::InverseDistance);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * v, 0.0, 0.5 * (v + 1), 1.0);
    renderer->AddActor(actor);
    renderer->SetBackground(0.1, 0.1, 0.1);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Zoom(1.8);
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
