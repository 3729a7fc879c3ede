// Image test: two decals on spot (vtkOFBDecalPatch + vtkOFBTextureProjector), a 4 x 4
// colour checker with a transparent border, one over the flank and one wrapped over the
// head; drawn by vtkOFBPolyDataMapper. The checker's squares follow the surface.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

int TestOFBMapperDecal(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> spot = vtkofbtest::ReadMesh("spot.obj");
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(spot, 512);

  // 6 x 6 texels: a 4 x 4 checker of red, green, blue and yellow inside a transparent
  // border (the decal's rim shows nothing).
  vtkNew<vtkImageData> checker;
  checker->SetDimensions(6, 6, 1);
  checker->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* texels = vtkUnsignedCharArray::SafeDownCast(checker->GetPointData()->GetScalars());
  const unsigned char palette[4][4] = {
    { 220, 40, 30, 255 }, { 40, 170, 60, 255 }, { 40, 70, 210, 255 }, { 240, 200, 40, 255 }
  };
  const unsigned char clear[4] = { 0, 0, 0, 0 };
  for (int j = 0; j < 6; ++j)
  {
    for (int i = 0; i < 6; ++i)
    {
      const bool border = i == 0 || j == 0 || i == 5 || j == 5;
      texels->SetTypedTuple(j * 6 + i, border ? clear : palette[(i + j) % 4]);
    }
  }

  vtkSmartPointer<vtkAlgorithmOutput> stage;
  const double centres[2][3] = { { 0.45, 0.1, 0.1 }, { 0.0, 0.55, 0.75 } };
  const double sizes[2] = { 0.7, 0.5 };
  vtkNew<vtkOFBTextureProjector> projectors[2];
  vtkNew<vtkOFBDecalPatch> decals[2];
  for (int k = 0; k < 2; ++k)
  {
    decals[k]->SetInputData(spot);
    decals[k]->SetCenter(centres[k][0], centres[k][1], centres[k][2]);
    decals[k]->SetDirection(0.0, 0.0, 1.0);
    decals[k]->SetWidth(sizes[k]);
    decals[k]->SetHeight(sizes[k]);
    if (k == 0)
    {
      projectors[k]->SetInputData(ofb);
    }
    else
    {
      projectors[k]->SetInputConnection(projectors[k - 1]->GetOutputPort());
    }
    projectors[k]->SetMeshConnection(decals[k]->GetOutputPort());
    projectors[k]->SetTextureData(checker);
    projectors[k]->InterpolateTextureOff();
    projectors[k]->RepeatTextureOff();
    projectors[k]->SetMaximumDistance(1.0);
  }
  projectors[1]->Update();
  for (auto& projector : projectors)
  {
    if (projector->GetNumberOfProjectedSamples() == 0)
    {
      std::cerr << "A decal stamped no sample." << std::endl;
      return 1;
    }
  }

  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(spot);
  mapper->SetOFBConnection(projectors[1]->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(300, 300);
  renWin->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1.0, 0.4, 0.6);
  camera->SetFocalPoint(0.0, 0.1, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  return vtkofbtest::RenderAndCompare(argc, argv, renWin, mapper);
}
