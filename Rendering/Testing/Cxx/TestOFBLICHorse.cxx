// Image test: the horse coloured by height through a lookup table, modulated by the LIC
// of a flow along its body (the tangential part of a uniform field), as VTK's surface
// LIC blends the LIC with a scalar colouring (weight 0.8, VTK's LICIntensity default).
#include "vtkLookupTable.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLICRenderHelpers.h"
#include "vtkOFBMapperTestHelpers.h"

int TestOFBLICHorse(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> horse = vtkofbtest::ReadMesh("horse.ply");
  if (!horse)
  {
    std::cerr << "Cannot read the horse." << std::endl;
    return 1;
  }
  // The scalar: height (z), interpolated into the samples by the sampler.
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  for (vtkIdType p = 0; p < horse->GetNumberOfPoints(); ++p)
  {
    height->InsertNextValue(static_cast<float>(horse->GetPoint(p)[2]));
  }
  horse->GetPointData()->AddArray(height);
  const double flow[3] = { 0.0, 1.0, 0.25 };
  vtkSmartPointer<vtkOFB> ofb =
    vtkofbtest::BuildWithField(horse, 384, vtkofbtest::UniformField(flow));
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->SetNumberOfSteps(15);
  lic->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_LIC);
  lic->Update();

  vtkofbtest::LICScene scene(horse, lic->GetOutput(), 400);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  scene.Mapper->GetColoring()->SetLookupTable(lut);
  scene.Mapper->GetColoring()->SetScalarRange(height->GetRange());
  scene.Mapper->GetColoring()->SetColorSourceToScalars();
  scene.Mapper->GetColoring()->SetScalarArrayName("Height");
  scene.Mapper->GetColoring()->SetLICColorModeToMap();
  scene.Mapper->GetColoring()->SetIntensityWeight(0.8);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(1.0, 0.0, 0.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->Azimuth(35.0);
  camera->Elevation(15.0);
  scene.Renderer->ResetCamera();
  scene.Renderer->GetActiveCamera()->Dolly(1.3);
  scene.Renderer->ResetCameraClippingRange();
  return vtkofbtest::RenderAndCompare(argc, argv, scene.Window, scene.Mapper, true);
}
