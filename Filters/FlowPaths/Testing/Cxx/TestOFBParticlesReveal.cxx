// Regression image after the paper's Fig. 2: a surface revealed by particles. The
// bunny starts transparent (every sample's alpha 0); particles moving up the
// surface gradient of the height (reseeded every 40 steps) leave colour by height
// through a lookup table. Three views: after 15, 50 and 150 steps. The mapper
// draws the surface opaque, so the not yet revealed samples show their dark base
// colour.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
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
#include "vtkUnsignedCharArray.h"

int TestOFBParticlesReveal(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> read =
    vtkofbtest::ReadMeshFile(std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj");
  if (!read)
  {
    return 1;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(read);
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* mesh = normals->GetOutput();
  vtkNew<vtkDoubleArray> up; // the surface gradient of the height y, once projected
  up->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    up->InsertNextTuple3(0.0, 1.0, 0.0);
    height->InsertNextValue(mesh->GetPoint(i)[1]);
  }
  mesh->GetPointData()->SetVectors(up);
  mesh->GetPointData()->AddArray(height);

  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetResolution(384);
  sampler->Update();
  vtkNew<vtkOFB> ofb;
  ofb->DeepCopy(sampler->GetOutput());
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  const unsigned char hidden[4] = { 40, 40, 48, 0 };
  for (vtkIdType i = 0; colors && i < colors->GetNumberOfTuples(); ++i)
  {
    colors->SetTypedTuple(i, hidden);
  }

  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(mesh);
  advector->SetOFB(ofb);
  advector->SetNumberOfParticles(1500);
  advector->SetLifetime(40);
  advector->SetColorModeToByScalar();
  advector->SetScalarArrayName("Height");
  advector->SetFootprintRadius(2.0);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 220);
  const int steps[3] = { 15, 50, 150 };
  int done = 0;
  for (int k = 0; k < 3; ++k)
  {
    advector->SetStepsPerUpdate(steps[k] - done);
    advector->Step();
    done = steps[k];
    vtkNew<vtkOFB> snapshot;
    snapshot->DeepCopy(ofb);
    vtkNew<vtkOFBPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    mapper->SetOFB(snapshot);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(k / 3.0, 0.0, (k + 1) / 3.0, 1.0);
    renderer->AddActor(actor);
    renderer->SetBackground(0.85, 0.87, 0.9);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Zoom(1.5);
    window->AddRenderer(renderer);
  }
  window->Render();
  int retVal = vtkRegressionTestImage(window);
  return !retVal;
}
