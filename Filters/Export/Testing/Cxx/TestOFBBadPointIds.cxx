// Meshes whose cells name points that do not exist (an id past the end, a negative id),
// and meshes with attribute arrays shorter than their points or cells, given to the
// export filters: an error naming the input and the bad id or array, an empty output,
// never a read out of bounds (vtkOFBInputChecks.h).
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkOFBProbeFilter.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <string>

using namespace vtkofbtest;

namespace
{
/// Expect an error naming the bad point id.
void ExpectBadIdError(const std::string& errors, vtkIdType badId)
{
  EXPECT_NE(errors.find("point id " + std::to_string(badId)), std::string::npos) << errors;
}
}

//------------------------------------------------------------------------------
TEST(BadPointIds, TextureAtlasRefusesThemInBothLayouts)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedTrianglePlane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  for (int layout : { vtkOFBTextureAtlas::CHARTS, vtkOFBTextureAtlas::TRIANGLES })
  {
    for (vtkIdType badId : BadPlanePointIds)
    {
      vtkNew<vtkOFBTextureAtlas> atlas;
      vtkNew<MessageObserver> o;
      o->Watch(atlas);
      atlas->SetLayout(layout);
      atlas->SetInputData(WithBadPointId(plane, badId));
      atlas->SetOFBData(ofb);
      atlas->Update();
      ExpectBadIdError(o->Errors, badId);
      EXPECT_EQ(atlas->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_EQ(atlas->GetOutput()->GetNumberOfCells(), 0);
    }
  }
}

//------------------------------------------------------------------------------
TEST(BadPointIds, TextureAtlasRefusesShortAttributeArrays)
{
  // The atlas copies the point and cell arrays to its output: a short one would be read
  // past its end.
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedTrianglePlane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  for (bool onCells : { false, true })
  {
    auto mesh = vtkSmartPointer<vtkPolyData>::New();
    mesh->ShallowCopy(plane);
    vtkNew<vtkFloatArray> shortArray;
    shortArray->SetName("Short");
    shortArray->SetNumberOfTuples(3);
    shortArray->Fill(1.0);
    if (onCells)
    {
      mesh->GetCellData()->AddArray(shortArray);
    }
    else
    {
      mesh->GetPointData()->AddArray(shortArray);
    }
    vtkNew<vtkOFBTextureAtlas> atlas;
    vtkNew<MessageObserver> o;
    o->Watch(atlas);
    atlas->SetInputData(mesh);
    atlas->SetOFBData(ofb);
    atlas->Update();
    EXPECT_NE(o->Errors.find("'Short' has 3 tuples"), std::string::npos) << o->Errors;
    EXPECT_EQ(atlas->GetOutput()->GetNumberOfPoints(), 0);
  }
}

//------------------------------------------------------------------------------
TEST(BadPointIds, TextureBakerRefusesThem)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedTrianglePlane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  for (vtkIdType badId : BadPlanePointIds)
  {
    vtkNew<vtkOFBTextureBaker> baker;
    vtkNew<MessageObserver> o;
    o->Watch(baker);
    baker->SetTextureSize(16, 16);
    baker->SetInputData(WithBadPointId(plane, badId));
    baker->SetOFBData(ofb);
    baker->Update();
    ExpectBadIdError(o->Errors, badId);
    EXPECT_EQ(baker->GetOutput()->GetNumberOfPoints(), 0);
  }
}

//------------------------------------------------------------------------------
TEST(BadPointIds, ProbeFilterRefusesThem)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedTrianglePlane();
  vtkSmartPointer<vtkOFB> ofb = Build(plane, 32);
  for (vtkIdType badId : BadPlanePointIds)
  {
    vtkNew<vtkOFBProbeFilter> probe;
    vtkNew<MessageObserver> o;
    o->Watch(probe);
    probe->SetInputData(WithBadPointId(plane, badId));
    probe->SetOFBData(ofb);
    probe->Update();
    ExpectBadIdError(o->Errors, badId);
    EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(probe->GetOutput()->GetNumberOfCells(), 0);
  }
  // The good mesh still probes without a message.
  vtkNew<vtkOFBProbeFilter> probe;
  vtkNew<MessageObserver> o;
  o->Watch(probe);
  probe->SetInputData(plane);
  probe->SetOFBData(ofb);
  probe->Update();
  EXPECT_TRUE(o->Errors.empty()) << o->Errors;
  EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), plane->GetNumberOfPoints());
}
