// Image test: a close-up of the bunny's head with enhanced LIC and contrast enhancement
// (low/high factors 0.05), Hann kernel, noise grain 2 cells: the streaks must be crisp
// at a scale where the OFB's cells span several pixels.
#include "vtkOFBLICRenderHelpers.h"
#include "vtkOFBMapperTestHelpers.h"

int TestOFBLICEnhancedCloseUp(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> bunny = vtkofbtest::ReadMesh("stanford-bunny.obj");
  if (!bunny)
  {
    std::cerr << "Cannot read the bunny." << std::endl;
    return 1;
  }
  double center[3];
  vtkofbtest::Center(bunny, center);
  const double axis[3] = { 0.0, 1.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb =
    vtkofbtest::BuildWithField(bunny, 384, vtkofbtest::RotationAbout(axis, center));
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->EnhancedLICOn();
  lic->SetKernelTypeToHann();
  lic->SetNoiseGrainSize(2.0);
  lic->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_LIC);
  lic->SetLowLICContrastEnhancementFactor(0.05);
  lic->SetHighLICContrastEnhancementFactor(0.05);
  lic->Update();

  vtkofbtest::LICScene scene(bunny, lic->GetOutput(), 400);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(-0.06, 0.15, 0.02); // the head
  camera->SetPosition(-0.06, 0.17, 0.22);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(20.0);
  scene.Renderer->ResetCameraClippingRange();
  return vtkofbtest::RenderAndCompare(argc, argv, scene.Window, scene.Mapper, true);
}
