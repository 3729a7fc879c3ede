// Regression image: 10,000 particles on the horse, moving along the tangential part
// of a rotation, leave colour (the periodic red-blue-green of the paper's Fig. 6) for
// 200 steps; the surface drawn by vtkOFBPolyDataMapper.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBReadMesh.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestOFBParticlesHorse(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> read =
    vtkofbtest::ReadMeshFile(std::string(VTKOFB_DATA_DIR) + "/horse.ply");
  if (!read)
  {
    return 1;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(read);
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* mesh = normals->GetOutput();
  double c[3];
  mesh->GetCenter(c);
  const double w[3] = { 0.2, 1.0, 0.1 };
  vtkNew<vtkDoubleArray> field;
  field->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3], r[3], v[3];
    mesh->GetPoint(i, x);
    vtkMath::Subtract(x, c, r);
    vtkMath::Cross(w, r, v);
    field->InsertNextTuple(v);
  }
  mesh->GetPointData()->SetVectors(field);

  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetResolution(512);
  sampler->Update();
  vtkNew<vtkOFB> ofb;
  ofb->ShallowCopy(sampler->GetOutput());

  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(mesh);
  advector->SetOFB(ofb);
  advector->SetNumberOfParticles(10000);
  advector->SetRandomSeed(3);
  advector->SetColorModeToPeriodic();
  advector->SetColorPeriod(90);
  advector->SetFootprintRadius(1.0);
  advector->SetStepsPerUpdate(200);
  advector->Step();
  if (advector->GetParticles()->GetNumberOfPoints() != 10000)
  {
    return 1;
  }

  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->SetOFB(ofb);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.2, 0.22, 0.26);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0], c[1] - 1.0, c[2]);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Azimuth(-30.0);
  camera->Zoom(1.4);
  window->Render();
  int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
