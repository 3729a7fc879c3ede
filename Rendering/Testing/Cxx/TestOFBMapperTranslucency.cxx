// GoogleTest units of vtkOFBPolyDataMapper's translucency: the OFB's alpha decides whether
// the surface is translucent, and an unpainted, fully transparent OFB renders nothing of
// the surface under depth peeling. They open render windows (run under xvfb-run).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
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
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

namespace
{
struct AlphaScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkSmartPointer<vtkOFB> OFB;
  vtkSmartPointer<vtkPolyData> Surface;

  AlphaScene()
  {
    this->Surface = vtkofbtest::MakeSphere(1.0, 24);
    this->OFB = vtkofbtest::Build(this->Surface, 128);
    this->Mapper->SetInputData(this->Surface);
    this->Mapper->SetOFB(this->OFB);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.2, 0.4, 0.6);
    this->Renderer->SetUseDepthPeeling(1);
    this->Renderer->SetMaximumNumberOfPeels(8);
    this->Renderer->SetOcclusionRatio(0.0);
    this->Window->SetSize(120, 120);
    this->Window->SetAlphaBitPlanes(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }

  void Fill(unsigned char r, unsigned char g, unsigned char b, unsigned char a)
  {
    vtkofbtest::Paint(this->OFB,
      [&](const double*, unsigned char rgba[4])
      {
        rgba[0] = r;
        rgba[1] = g;
        rgba[2] = b;
        rgba[3] = a;
      });
  }

  // Pixels that differ from the background (the corner pixel, outside the sphere).
  int CountNonBackgroundPixels()
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->SetInputBufferTypeToRGB();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    const int* dims = image->GetDimensions();
    const unsigned char* p = static_cast<unsigned char*>(image->GetScalarPointer());
    const unsigned char bg[3] = { p[0], p[1], p[2] };
    int count = 0;
    for (int i = 0; i < dims[0] * dims[1]; ++i)
    {
      count += (p[3 * i] != bg[0] || p[3 * i + 1] != bg[1] || p[3 * i + 2] != bg[2]) ? 1 : 0;
    }
    return count;
  }
};
}

TEST(OFBMapperTranslucency, UnpaintedTransparentOFBRendersNothing)
{
  AlphaScene scene;
  scene.Fill(255, 0, 0, 0);
  EXPECT_TRUE(scene.Mapper->HasTranslucentPolygonalGeometry());
  scene.Window->Render();
  ASSERT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_TRUE(scene.Renderer->GetLastRenderingUsedDepthPeeling());
  EXPECT_EQ(scene.CountNonBackgroundPixels(), 0);

  // The same surface, opaque: it covers much of the window (so the count above could fail).
  scene.Fill(255, 0, 0, 255);
  EXPECT_FALSE(scene.Mapper->HasTranslucentPolygonalGeometry());
  scene.Window->Render();
  EXPECT_GT(scene.CountNonBackgroundPixels(), 120 * 120 / 8);
}

TEST(OFBMapperTranslucency, PaintRevealsTheSurfaceWhereItLands)
{
  AlphaScene scene;
  scene.Fill(255, 255, 255, 0);
  const double centre[3] = { 0.0, 0.0, 1.0 }; // the point facing the camera
  const unsigned char red[4] = { 255, 0, 0, 255 };
  ASSERT_GT(vtkofbtest::PaintSphere(scene.OFB, centre, 0.3, red), 0);
  scene.Window->Render();
  const int painted = scene.CountNonBackgroundPixels();
  EXPECT_GT(painted, 0);
  // The patch is a disc of radius about 0.3 of a sphere that fills most of the window.
  EXPECT_LT(painted, 120 * 120 / 8);
}

TEST(OFBMapperTranslucency, TranslucencyFollowsTheAlphaOfThePaint)
{
  AlphaScene scene;
  scene.Fill(0, 0, 255, 255);
  EXPECT_FALSE(scene.Mapper->HasTranslucentPolygonalGeometry());
  scene.Window->Render();

  // One sample painted half transparent (the incremental path: a modified range).
  vtkUnsignedCharArray* colors = vtkofbtest::GetColors(scene.OFB);
  const vtkIdType i = scene.OFB->GetNumberOfSamples() / 3;
  const unsigned char half[4] = { 0, 0, 255, 128 };
  colors->SetTypedTuple(i, half);
  scene.OFB->MarkSamplesModified(i, i + 1);
  scene.OFB->Modified();
  EXPECT_TRUE(scene.Mapper->HasTranslucentPolygonalGeometry());
  scene.Window->Render();

  // Back to opaque.
  const unsigned char opaque[4] = { 0, 0, 255, 255 };
  colors->SetTypedTuple(i, opaque);
  scene.OFB->MarkSamplesModified(i, i + 1);
  scene.OFB->Modified();
  EXPECT_FALSE(scene.Mapper->HasTranslucentPolygonalGeometry());

  // A lookup table with translucent entries makes the Scalars source translucent.
  const vtkIdType n = scene.OFB->GetNumberOfSamples();
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  height->SetNumberOfTuples(n);
  height->FillValue(0.5f);
  scene.OFB->GetSampleData()->AddArray(height);
  scene.Mapper->GetColoring()->SetColorSourceToScalars();
  scene.Mapper->GetColoring()->SetScalarArrayName("Height");
  vtkNew<vtkLookupTable> lut;
  lut->Build();
  scene.Mapper->GetColoring()->SetLookupTable(lut);
  EXPECT_FALSE(scene.Mapper->HasTranslucentPolygonalGeometry());
  lut->SetAlphaRange(0.2, 0.2);
  lut->ForceBuild();
  EXPECT_TRUE(scene.Mapper->HasTranslucentPolygonalGeometry());
}
