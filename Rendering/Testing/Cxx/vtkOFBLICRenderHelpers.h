// Helpers of the LIC rendering tests: the LIC of a mesh with a field, and a window
// showing it through vtkOFBPolyDataMapper with the LIC as intensity.
#ifndef vtkOFBLICRenderHelpers_h
#define vtkOFBLICRenderHelpers_h

#include "vtkOFBLICTestHelpers.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

namespace vtkofbtest
{
/// Rotation about `axis` through `center`: v = axis x (x - center) (axis normalized).
inline VectorField RotationAbout(const double axis[3], const double center[3])
{
  double a[3] = { axis[0], axis[1], axis[2] };
  vtkMath::Normalize(a);
  const double c[3] = { center[0], center[1], center[2] };
  return [a, c](const double x[3], double v[3])
  {
    const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
    vtkMath::Cross(a, r, v);
  };
}

/// The centre of a mesh's bounding box.
inline void Center(vtkPolyData* mesh, double c[3])
{
  double b[6];
  mesh->GetBounds(b);
  for (int k = 0; k < 3; ++k)
  {
    c[k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
  }
}

/// A window of `size` pixels showing `mesh` coloured from `ofb`, the "LIC" array as
/// intensity (InverseDistance lookup).
struct LICScene
{
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  LICScene(vtkPolyData* mesh, vtkOFB* ofb, int size)
  {
    this->Mapper->SetInputData(mesh);
    this->Mapper->SetOFB(ofb);
    this->Mapper->SetLookupModeToInverseDistance();
    this->Mapper->GetColoring()->SetIntensityArrayName("LIC");
    this->Mapper->GetColoring()->IntensityModulationOn();
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetMultiSamples(0);
  }
};
}

#endif
