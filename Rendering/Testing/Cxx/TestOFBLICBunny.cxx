// Image test: the Stanford bunny with the LIC of the tangential part of a rotation about
// a tilted axis through its centre (vtkOFBLIC defaults: enhanced LIC, Gaussian noise),
// shown as grey intensity by vtkOFBPolyDataMapper.
#include "vtkOFBLICRenderHelpers.h"
#include "vtkOFBMapperTestHelpers.h"

int TestOFBLICBunny(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> bunny = vtkofbtest::ReadMesh("stanford-bunny.obj");
  if (!bunny)
  {
    std::cerr << "Cannot read the bunny." << std::endl;
    return 1;
  }
  double center[3];
  vtkofbtest::Center(bunny, center);
  const double axis[3] = { 0.4, 1.0, 0.3 };
  vtkSmartPointer<vtkOFB> ofb =
    vtkofbtest::BuildWithField(bunny, 384, vtkofbtest::RotationAbout(axis, center));
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_LIC);
  lic->Update();

  vtkofbtest::LICScene scene(bunny, lic->GetOutput(), 400);
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Dolly(1.4);
  scene.Renderer->ResetCameraClippingRange();
  return vtkofbtest::RenderAndCompare(argc, argv, scene.Window, scene.Mapper, true);
}
