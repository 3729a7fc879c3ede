#include "vtkOFBTexturedGLTF.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkGLTFExporter.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

//------------------------------------------------------------------------------
std::string vtkOFBTexturedGLTF::WriteToString(vtkPolyData* surface,
  vtkImageData* texture,
  vtkCommand* errors)
{
  vtkNew<vtkTexture> image;
  image->SetInputData(texture);
  image->InterpolateOn();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(image);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  vtkNew<vtkGLTFExporter> exporter;
  if (errors)
  {
    exporter->AddObserver(vtkCommand::ErrorEvent, errors);
  }
  exporter->SetRenderWindow(window);
  exporter->InlineDataOn();
  exporter->SaveNormalOn();
  return exporter->WriteToString();
}
