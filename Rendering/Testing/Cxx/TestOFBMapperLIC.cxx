// Image test: a LIC-like pattern (a synthetic "LIC" sample array of wavy streaks around
// the axis of a sphere) blended with a scalar colouring (the height through a lookup
// table) in vtkSurfaceLICInterface's default mode, COLOR_MODE_BLEND with LICIntensity 0.8.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

int TestOFBMapperLIC(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 24);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 256);
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  height->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> lic;
  lic->SetName("LIC");
  lic->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const double longitude = std::atan2(x[1], x[0]);
    const double latitude = std::asin(std::max(-1.0, std::min(1.0, x[2])));
    // Streaks along the longitude, their phase varying with it: a flow around the axis.
    const double streaks = std::sin(70.0 * latitude + 2.5 * std::sin(5.0 * longitude));
    const double grain = std::sin(23.0 * longitude + 11.0 * latitude);
    lic->SetValue(i, static_cast<float>(0.5 + 0.4 * streaks + 0.1 * grain));
    height->SetValue(i, static_cast<float>(x[2]));
  }
  ofb->GetSampleData()->AddArray(height);
  ofb->GetSampleData()->AddArray(lic);
  ofb->Modified();

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.6667, 0.0);
  lut->Build();
  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(sphere);
  mapper->SetOFB(ofb);
  mapper->GetColoring()->SetLookupTable(lut);
  mapper->GetColoring()->SetScalarRange(-1.0, 1.0);
  mapper->GetColoring()->SetColorSourceToScalars();
  mapper->GetColoring()->SetScalarArrayName("Height");
  mapper->GetColoring()->SetIntensityArrayName("LIC");
  mapper->GetColoring()->IntensityModulationOn();
  mapper->GetColoring()->SetLICIntensity(0.8); // VTK's default
  mapper->SetLookupModeToInverseDistance();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.15);
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(300, 300);
  renWin->SetMultiSamples(0);
  renWin->AddRenderer(renderer);
  renderer->GetActiveCamera()->Elevation(-60);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.3);
  return vtkofbtest::RenderAndCompare(argc, argv, renWin, mapper, true);
}
