// GoogleTest units of vtkOFBPolyDataMapper: colour read-back, incremental uploads, colour
// sources, several viewports, GL state, bad input and PrintSelf. They open render windows
// (run under xvfb-run).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBColoring.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPainter.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkOFBTestUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtk_glew.h"

#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <vector>

namespace
{
using Pixel = std::array<int, 3>;

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkSmartPointer<vtkOFB> OFB;
  vtkSmartPointer<vtkPolyData> Surface;

  Scene(int ofbResolution = 128, int size = 100)
  {
    this->Surface = vtkofbtest::MakeSphere(1.0, 24);
    this->OFB = vtkofbtest::Build(this->Surface, ofbResolution);
    this->Mapper->SetInputData(this->Surface);
    this->Mapper->SetOFB(this->OFB);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }

  void Fill(unsigned char r, unsigned char g, unsigned char b)
  {
    vtkofbtest::Paint(this->OFB,
      [&](const double*, unsigned char rgba[4])
      {
        rgba[0] = r;
        rgba[1] = g;
        rgba[2] = b;
        rgba[3] = 255;
      });
  }
};

Pixel ReadPixel(vtkRenderWindow* window, int x, int y)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  const unsigned char* p =
    static_cast<unsigned char*>(grab->GetOutput()->GetScalarPointer(x, y, 0));
  return { p[0], p[1], p[2] };
}

Pixel Centre(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  return ReadPixel(window, size[0] / 2, size[1] / 2);
}

bool IsRed(const Pixel& p)
{
  return p[0] > 150 && p[1] < 40 && p[2] < 40;
}
}

TEST(OFBPolyDataMapper, AllRedOFBGivesARedCentrePixel)
{
  Scene scene;
  scene.Fill(255, 0, 0);
  scene.Window->Render();
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  const Pixel p = Centre(scene.Window);
  EXPECT_TRUE(IsRed(p)) << p[0] << " " << p[1] << " " << p[2];
}

TEST(OFBPolyDataMapper, EveryLookupModeReadsTheOFB)
{
  for (int mode = vtkOFBPolyDataMapper::LOOKUP_NEAREST;
       mode < vtkOFBPolyDataMapper::NUMBER_OF_LOOKUP_MODES;
       ++mode)
  {
    Scene scene;
    scene.Fill(0, 0, 255);
    scene.Mapper->SetLookupMode(mode);
    scene.Window->Render();
    EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
    const Pixel p = Centre(scene.Window);
    EXPECT_TRUE(p[2] > 150 && p[0] < 40 && p[1] < 40)
      << vtkOFBPolyDataMapper::GetLookupModeAsString(mode) << ": " << p[0] << " " << p[1] << " "
      << p[2];
  }
}

// The sphere's pixels (those not of the black background) of the window's image: their
// number and the mean and variance of their red channel.
struct SpherePixels
{
  int Count = 0;
  double Mean = 0.0;
  double Variance = 0.0;
  std::vector<unsigned char> Image;
};

SpherePixels GrabSphere(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  const int* dims = image->GetDimensions();
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  SpherePixels out;
  out.Image.assign(p, p + 3 * dims[0] * dims[1]);
  double sum = 0.0;
  double sum2 = 0.0;
  for (int k = 0; k < dims[0] * dims[1]; ++k)
  {
    if (p[3 * k] + p[3 * k + 1] + p[3 * k + 2] > 0)
    {
      ++out.Count;
      sum += p[3 * k];
      sum2 += p[3 * k] * p[3 * k];
    }
  }
  if (out.Count > 0)
  {
    out.Mean = sum / out.Count;
    out.Variance = sum2 / out.Count - out.Mean * out.Mean;
  }
  return out;
}

// NearestMipmapped: a checker of 1-cell squares seen from afar (about 5 cells a pixel)
// aliases with Nearest and averages out with the pyramid; up close (under a cell a
// pixel) the two modes read the same samples.
TEST(OFBPolyDataMapper, NearestMipmappedAveragesFarDetailAndIsNearestUpClose)
{
  Scene scene(512, 100);
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.Actor->GetProperty()->LightingOff();
  const unsigned char dark[4] = { 40, 40, 40, 255 };
  const unsigned char light[4] = { 240, 240, 240, 255 };
  vtkofbtest::PaintChecker(scene.OFB, scene.OFB->GetCellSize(), dark, light);
  SpherePixels far[2];
  SpherePixels near[2];
  for (int m = 0; m < 2; ++m)
  {
    scene.Mapper->SetLookupMode(m == 0 ? vtkOFBPolyDataMapper::LOOKUP_NEAREST
                                       : vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED);
    scene.Renderer->ResetCamera();
    scene.Window->Render();
    ASSERT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
    far[m] = GrabSphere(scene.Window);
    scene.Renderer->GetActiveCamera()->Zoom(12.0);
    scene.Window->Render();
    near[m] = GrabSphere(scene.Window);
  }
  ASSERT_GT(far[0].Count, 2000);
  EXPECT_EQ(far[0].Count, far[1].Count);
  // Nearest shows the two colours (variance near 100^2), the pyramid their mean.
  EXPECT_GT(far[0].Variance, 2500.0);
  EXPECT_LT(far[1].Variance, 0.25 * far[0].Variance);
  EXPECT_NEAR(far[1].Mean, 140.0, 30.0);
  // Up close both read level 0: the same image (a few pixels at the rim, seen at a
  // grazing angle, may read level 1).
  ASSERT_EQ(near[0].Image.size(), near[1].Image.size());
  size_t differ = 0;
  for (size_t k = 0; k < near[0].Image.size(); k += 3)
  {
    differ += near[0].Image[k] != near[1].Image[k];
  }
  EXPECT_GT(near[0].Count, 9000);
  EXPECT_LT(differ, near[0].Image.size() / 3 / 100) << differ << " pixels differ";
  EXPECT_GT(near[1].Variance, 2500.0);

  // A pyramid of level 0 alone: Nearest's picture, also from afar.
  scene.Mapper->SetMaximumNumberOfMipmapLevels(1);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_TRUE(GrabSphere(scene.Window).Image == far[0].Image);
}

// Every fragment finds a sample: also along the borders between the regions of the three
// grids, where the cell under a point in the grid of its triangle and in the other grids
// can hold no sample within one cell and the Nearest lookup falls back to the neighbouring
// cells. A fragment without a sample would keep the property colour (green).
TEST(OFBPolyDataMapper, NoFragmentKeepsThePropertyColour)
{
  for (int mode = vtkOFBPolyDataMapper::LOOKUP_NEAREST;
       mode < vtkOFBPolyDataMapper::NUMBER_OF_LOOKUP_MODES;
       ++mode)
  {
    Scene scene(128, 300);
    scene.Fill(255, 0, 0);
    scene.Actor->GetProperty()->SetColor(0.0, 1.0, 0.0);
    scene.Mapper->SetLookupMode(mode);
    scene.Renderer->GetActiveCamera()->Elevation(35);
    scene.Renderer->GetActiveCamera()->Azimuth(40);
    scene.Window->Render();
    ASSERT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(scene.Window);
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    const int* dims = image->GetDimensions();
    const int nc = image->GetNumberOfScalarComponents();
    const unsigned char* p = static_cast<unsigned char*>(image->GetScalarPointer());
    int red = 0;
    int green = 0;
    for (int i = 0; i < dims[0] * dims[1]; ++i, p += nc)
    {
      red += p[0] > p[1] + 10 ? 1 : 0;
      green += p[1] > p[0] + 10 ? 1 : 0;
    }
    EXPECT_GT(red, dims[0] * dims[1] / 8) << vtkOFBPolyDataMapper::GetLookupModeAsString(mode);
    EXPECT_EQ(green, 0) << vtkOFBPolyDataMapper::GetLookupModeAsString(mode);
  }
}

TEST(OFBPolyDataMapper, PaintingUploadsOnlyTheModifiedSamples)
{
  Scene scene(256);
  scene.Fill(255, 0, 0);
  scene.Window->Render();
  const vtkIdType n = scene.OFB->GetNumberOfSamples();
  EXPECT_EQ(scene.Mapper->GetLastUploadedSampleCount(), n);
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetLastUploadedSampleCount(), 0);

  // One stroke: 100 samples, contiguous.
  vtkUnsignedCharArray* colors = vtkofbtest::GetColors(scene.OFB);
  const unsigned char green[4] = { 0, 255, 0, 255 };
  for (vtkIdType i = 1000; i < 1100; ++i)
  {
    colors->SetTypedTuple(i, green);
  }
  scene.OFB->MarkSamplesModified(1000, 1100);
  scene.OFB->Modified();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetLastUploadedSampleCount(), 100);
  EXPECT_LT(100 * 100, n) << "the OFB should be much larger than the stroke";

  // Another stroke: 100 scattered samples, one dab each.
  for (vtkIdType k = 0; k < 100; ++k)
  {
    const vtkIdType i = (k * 7919) % n;
    colors->SetTypedTuple(i, green);
    scene.OFB->MarkSamplesModified(i, i + 1);
  }
  scene.OFB->Modified();
  scene.Window->Render();
  EXPECT_GE(scene.Mapper->GetLastUploadedSampleCount(), 95); // a few may coincide
  EXPECT_LE(scene.Mapper->GetLastUploadedSampleCount(), 100);
}

// With a mipmapped display, a dab uploads the painted samples and, on each coarser level,
// only those that read them (vtkOFBPyramid filters those alone), and the paint reaches
// the screen through the coarse level that a small window reads.
TEST(OFBPolyDataMapper, PaintingWithMipmapsUploadsOnlyThePaintedNeighbourhood)
{
  Scene scene(256);
  scene.Mapper->SetLookupModeToNearestMipmapped();
  scene.Fill(255, 0, 0);
  scene.Window->Render();
  const vtkIdType all = scene.Mapper->GetLastUploadedSampleCount();
  ASSERT_GT(all, scene.OFB->GetNumberOfSamples()) << "the coarser levels are uploaded too";
  ASSERT_TRUE(IsRed(Centre(scene.Window)));

  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(scene.OFB);
  painter->GetBrush()->SetColor(0.0, 1.0, 0.0);
  painter->GetBrush()->SetRadius(0.3);
  const vtkIdType painted = painter->Dab(0.0, 0.0, 1.0); // the point facing the camera
  ASSERT_GT(painted, 0);
  scene.Window->Render();
  const vtkIdType uploaded = scene.Mapper->GetLastUploadedSampleCount();
  EXPECT_GT(uploaded, painted) << "the coarser levels' samples near the paint";
  EXPECT_LT(4 * uploaded, all) << "more than the painted neighbourhood was uploaded";
  const Pixel p = Centre(scene.Window);
  EXPECT_TRUE(p[1] > 150 && p[0] < 40) << p[0] << " " << p[1] << " " << p[2];
}

TEST(OFBPolyDataMapper, IncrementalUploadReachesTheScreen)
{
  Scene scene;
  scene.Fill(255, 0, 0);
  scene.Window->Render();
  ASSERT_TRUE(IsRed(Centre(scene.Window)));
  // Repaint the samples near the point facing the camera, (0, 0, 1), in green.
  vtkUnsignedCharArray* colors = vtkofbtest::GetColors(scene.OFB);
  const unsigned char green[4] = { 0, 255, 0, 255 };
  vtkIdType marked = 0;
  for (vtkIdType i = 0; i < scene.OFB->GetNumberOfSamples(); ++i)
  {
    double x[3];
    scene.OFB->GetSamplePosition(i, x);
    if (x[0] * x[0] + x[1] * x[1] < 0.04 && x[2] > 0.0)
    {
      colors->SetTypedTuple(i, green);
      scene.OFB->MarkSamplesModified(i, i + 1);
      ++marked;
    }
  }
  scene.OFB->Modified();
  scene.Window->Render();
  // Hundreds of one-sample marks: vtkOFB may merge them conservatively, up to everything.
  EXPECT_GE(scene.Mapper->GetLastUploadedSampleCount(), marked);
  EXPECT_LE(scene.Mapper->GetLastUploadedSampleCount(), scene.OFB->GetNumberOfSamples());
  const Pixel p = Centre(scene.Window);
  EXPECT_TRUE(p[1] > 150 && p[0] < 40) << p[0] << " " << p[1] << " " << p[2];
}

TEST(OFBPolyDataMapper, OFBFromAPipelineConnection)
{
  Scene scene;
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(scene.Surface);
  sampler->SetResolution(64);
  sampler->SetDefaultColor(255, 0, 0, 255);
  sampler->UseInputColorsOff();
  scene.Mapper->SetOFBConnection(sampler->GetOutputPort());
  scene.Window->Render();
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_EQ(scene.Mapper->GetOFB(), sampler->GetOutput());
  EXPECT_TRUE(IsRed(Centre(scene.Window)));
}

TEST(OFBPolyDataMapper, ScalarsThroughTheLookupTableWithIntensity)
{
  // Every lookup mode: each compiles its own shader variant.
  for (int mode = vtkOFBPolyDataMapper::LOOKUP_NEAREST;
       mode < vtkOFBPolyDataMapper::NUMBER_OF_LOOKUP_MODES;
       ++mode)
  {
    SCOPED_TRACE(vtkOFBPolyDataMapper::GetLookupModeAsString(mode));
    Scene scene;
    scene.Mapper->SetLookupMode(mode);
    const vtkIdType n = scene.OFB->GetNumberOfSamples();
    vtkNew<vtkFloatArray> height;
    height->SetName("Height");
    height->SetNumberOfTuples(n);
    vtkNew<vtkFloatArray> intensity;
    intensity->SetName("LIC");
    intensity->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      scene.OFB->GetSamplePosition(i, x);
      height->SetValue(i, static_cast<float>(x[2]));
      intensity->SetValue(i, 0.5f);
    }
    scene.OFB->GetSampleData()->AddArray(height);
    scene.OFB->GetSampleData()->AddArray(intensity);
    scene.OFB->Modified();

    vtkNew<vtkLookupTable> lut; // red at the low end, blue at the high end
    lut->SetHueRange(0.0, 0.6667);
    lut->Build();
    scene.Mapper->GetColoring()->SetLookupTable(lut);
    scene.Mapper->GetColoring()->SetScalarRange(-1.0, 1.0);
    scene.Mapper->GetColoring()->SetColorSourceToScalars();
    scene.Mapper->GetColoring()->SetScalarArrayName("Height");
    scene.Window->Render();
    EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
    Pixel p = Centre(scene.Window); // z = 1: the high end
    EXPECT_TRUE(p[2] > 150 && p[0] < 40 && p[1] < 40) << p[0] << " " << p[1] << " " << p[2];

    scene.Mapper->GetColoring()->SetScalarRange(1.0, 3.0); // z = 1 is now the low end
    scene.Window->Render();
    p = Centre(scene.Window);
    EXPECT_TRUE(IsRed(p)) << p[0] << " " << p[1] << " " << p[2];

    scene.Mapper->GetColoring()->SetIntensityArrayName("LIC");
    scene.Mapper->GetColoring()->SetLICColorModeToMap(); // the colour times the intensity
    scene.Mapper->GetColoring()->IntensityModulationOn();
    scene.Window->Render();
    const Pixel half = Centre(scene.Window);
    EXPECT_NEAR(half[0], p[0] / 2, 12);

    scene.Mapper->GetColoring()->SetIntensityWeight(0.0);
    scene.Window->Render();
    EXPECT_NEAR(Centre(scene.Window)[0], p[0], 6);
  }
}

TEST(OFBPolyDataMapper, PaintedNormalsShadeTheSurface)
{
  // Every lookup mode: each compiles its own shader variant.
  for (int mode = vtkOFBPolyDataMapper::LOOKUP_NEAREST;
       mode < vtkOFBPolyDataMapper::NUMBER_OF_LOOKUP_MODES;
       ++mode)
  {
    SCOPED_TRACE(vtkOFBPolyDataMapper::GetLookupModeAsString(mode));
    Scene scene;
    scene.Mapper->SetLookupMode(mode);
    scene.Fill(255, 0, 0);
    scene.Mapper->UsePaintedNormalsOn();
    scene.Window->Render();
    EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
    EXPECT_TRUE(IsRed(Centre(scene.Window)));
    // Normals painted to face away sideways darken the centre.
    vtkDataArray* normals = scene.OFB->GetSampleData()->GetArray("Normals");
    ASSERT_NE(normals, nullptr);
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      normals->SetTuple3(i, 1.0, 0.0, 0.05);
    }
    scene.OFB->MarkAllSamplesModified();
    scene.OFB->Modified();
    scene.Window->Render();
    EXPECT_LT(Centre(scene.Window)[0], 60);
  }
}

TEST(OFBPolyDataMapper, SeveralViewportsAndRestoredBindings)
{
  Scene scene(128, 200);
  scene.Fill(255, 0, 0);
  scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkRenderer> second;
  second->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(scene.Mapper); // the same mapper in a second renderer
  second->AddActor(actor);
  scene.Window->AddRenderer(second);
  second->ResetCamera();
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  EXPECT_TRUE(IsRed(ReadPixel(scene.Window, 50, 100)));
  EXPECT_TRUE(IsRed(ReadPixel(scene.Window, 150, 100)));

  // No shader storage buffer is left bound.
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(scene.Window);
  ASSERT_NE(gl, nullptr);
  gl->MakeCurrent();
  GLint bound = -1;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &bound);
  EXPECT_EQ(bound, 0);
  for (GLuint i = 0; i < 16; ++i)
  {
    GLint b = -1;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, i, &b);
    EXPECT_EQ(b, 0) << "binding point " << i;
  }
  EXPECT_GT(scene.Mapper->GetGPUMemorySize(), 0);
  scene.Mapper->ReleaseGraphicsResources(scene.Window);
  EXPECT_EQ(scene.Mapper->GetGPUMemorySize(), 0);
  // It renders again after a release.
  scene.Window->Render();
  EXPECT_TRUE(IsRed(ReadPixel(scene.Window, 50, 100)));
}

TEST(OFBPolyDataMapper, NoOFBWarnsAndRendersThePropertyColour)
{
  Scene scene;
  scene.Mapper->SetOFB(nullptr);
  scene.Actor->GetProperty()->SetColor(0.0, 1.0, 0.0);
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(scene.Mapper);
  scene.Window->Render();
  scene.Window->Render();
  EXPECT_FALSE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_NE(messages->Warnings.find("No OFB"), std::string::npos) << messages->Warnings;
  EXPECT_EQ(messages->Warnings.find("No OFB"), messages->Warnings.rfind("No OFB"))
    << "warned more than once";
  const Pixel p = Centre(scene.Window);
  EXPECT_TRUE(p[1] > 150 && p[0] < 40) << p[0] << " " << p[1] << " " << p[2];
}

// A lookup mode that is no LookupModes value is refused with an error (it once fell
// through to Mipmapped in the shader); the mode stays and the scene still renders.
TEST(OFBPolyDataMapper, UnknownLookupModeIsAnError)
{
  Scene scene;
  scene.Fill(0, 0, 255);
  scene.Mapper->SetLookupModeToInverseDistance();
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(scene.Mapper);
  for (int bad : { -1, static_cast<int>(vtkOFBPolyDataMapper::NUMBER_OF_LOOKUP_MODES), 99 })
  {
    messages->Clear();
    scene.Mapper->SetLookupMode(bad);
    EXPECT_NE(messages->Errors.find("not a LookupModes value"), std::string::npos) << bad;
    EXPECT_EQ(scene.Mapper->GetLookupMode(), vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE);
  }
  EXPECT_STREQ(vtkOFBPolyDataMapper::GetLookupModeAsString(99), "Unknown");
  messages->Clear();
  scene.Window->Render();
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  const Pixel p = Centre(scene.Window);
  EXPECT_TRUE(p[2] > 150 && p[0] < 40 && p[1] < 40) << p[0] << " " << p[1] << " " << p[2];
}

TEST(OFBPolyDataMapper, EmptyOFBWarns)
{
  Scene scene;
  vtkNew<vtkOFB> empty;
  scene.Mapper->SetOFB(empty);
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(scene.Mapper);
  scene.Window->Render();
  EXPECT_FALSE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_NE(messages->Warnings.find("empty"), std::string::npos) << messages->Warnings;
  // An OFB without colours falls back too.
  scene.Mapper->SetOFB(scene.OFB);
  scene.OFB->GetSampleData()->RemoveArray("Colors");
  scene.OFB->Modified();
  scene.Window->Render();
  EXPECT_FALSE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_NE(messages->Warnings.find("Colors"), std::string::npos) << messages->Warnings;
}

TEST(OFBPolyDataMapper, MeshAndOFBMismatchWarnsAndKeepsThePropertyColour)
{
  Scene scene;
  scene.Fill(255, 0, 0);
  vtkNew<vtkTransform> shift;
  shift->Translate(5.0, 0.0, 0.0);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputData(scene.Surface);
  move->SetTransform(shift);
  move->Update();
  scene.Mapper->SetInputData(move->GetOutput());
  scene.Actor->GetProperty()->SetColor(0.0, 1.0, 0.0);
  scene.Renderer->ResetCamera();
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(scene.Mapper);
  scene.Window->Render();
  EXPECT_NE(messages->Warnings.find("beyond"), std::string::npos) << messages->Warnings;
  const Pixel p = Centre(scene.Window);
  EXPECT_TRUE(p[1] > 150 && p[0] < 40) << p[0] << " " << p[1] << " " << p[2];
}

TEST(OFBPolyDataMapper, MovesToANewWindowAfterTheOldOneIsGone)
{
  // A mapper rendered in a window that is then destroyed (with the mapper still in its
  // renderer), then in a new one, several times: its buffers died with the old context
  // and are made again in the new one (the old names, reused there, would name other
  // objects or none: the upload failed or overwrote one of VTK's buffers).
  vtkSmartPointer<vtkPolyData> surface = vtkofbtest::MakeSphere(1.0, 24);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(surface, 128);
  vtkofbtest::Paint(ofb,
    [](const double*, unsigned char rgba[4])
    {
      rgba[0] = 255;
      rgba[1] = rgba[2] = 0;
      rgba[3] = 255;
    });
  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->SetOFB(ofb);
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(mapper);
  for (int mode : { vtkOFBPolyDataMapper::LOOKUP_NEAREST,
         vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED,
         vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE })
  {
    mapper->SetLookupMode(mode);
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkRenderWindow> window;
      vtkNew<vtkRenderer> renderer;
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      renderer->AddActor(actor);
      window->SetSize(60, 60);
      window->AddRenderer(renderer);
      renderer->ResetCamera();
      window->Render();
      EXPECT_TRUE(mapper->GetLastRenderUsedOFB())
        << vtkOFBPolyDataMapper::GetLookupModeAsString(mode) << ", window " << k << ": "
        << messages->Warnings;
      const Pixel p = Centre(window);
      EXPECT_TRUE(IsRed(p)) << vtkOFBPolyDataMapper::GetLookupModeAsString(mode) << ", window " << k
                            << ": " << p[0] << " " << p[1] << " " << p[2];
    }
  }
}

TEST(OFBPolyDataMapper, MissingArraysFallBackWithWarnings)
{
  Scene scene;
  scene.Fill(255, 0, 0);
  scene.Mapper->GetColoring()->SetColorSourceToScalars();
  scene.Mapper->GetColoring()->SetScalarArrayName("NoSuchArray");
  scene.Mapper->GetColoring()->SetIntensityArrayName("NoLIC");
  scene.Mapper->GetColoring()->IntensityModulationOn();
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(scene.Mapper);
  scene.Window->Render();
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_NE(messages->Warnings.find("NoSuchArray"), std::string::npos) << messages->Warnings;
  EXPECT_NE(messages->Warnings.find("NoLIC"), std::string::npos) << messages->Warnings;
  EXPECT_TRUE(IsRed(Centre(scene.Window)));
}

TEST(OFBPolyDataMapper, ArraysShorterThanTheSamplesAreMissing)
{
  // An intensity array of 5 tuples (its upload would read past its end): a warning, the
  // paint shown unmodulated; a "Colors" of 5 tuples: a warning, the property colour.
  Scene scene;
  scene.Fill(255, 0, 0);
  vtkNew<vtkFloatArray> lic;
  lic->SetName("LIC");
  lic->SetNumberOfTuples(5);
  lic->FillValue(0.0f);
  scene.OFB->GetSampleData()->AddArray(lic);
  scene.Mapper->GetColoring()->SetIntensityArrayName("LIC");
  scene.Mapper->GetColoring()->IntensityModulationOn();
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(scene.Mapper);
  scene.Window->Render();
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_NE(messages->Warnings.find("\"LIC\""), std::string::npos) << messages->Warnings;
  EXPECT_TRUE(IsRed(Centre(scene.Window))); // a LIC of 0 would have made it dark

  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(5);
  colors->Fill(0);
  scene.OFB->GetSampleData()->RemoveArray("Colors");
  scene.OFB->GetSampleData()->AddArray(colors);
  scene.OFB->Modified();
  messages->Clear();
  scene.Window->Render();
  EXPECT_FALSE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_NE(messages->Warnings.find("\"Colors\""), std::string::npos) << messages->Warnings;
}

TEST(OFBPolyDataMapper, SettingsAreClampedAndPrinted)
{
  vtkNew<vtkOFBPolyDataMapper> mapper;
  EXPECT_EQ(mapper->GetLookupMode(), vtkOFBPolyDataMapper::LOOKUP_AUTOMATIC);
  EXPECT_EQ(mapper->GetColoring()->GetColorSource(), vtkOFBColoring::COLOR_SOURCE_PAINT);
  EXPECT_NEAR(mapper->GetInterpolationRadius(), 1.7320508, 1e-6);
  mapper->SetLookupMode(99); // not a lookup mode: an error, the mode stays
  EXPECT_EQ(mapper->GetLookupMode(), vtkOFBPolyDataMapper::LOOKUP_AUTOMATIC);
  mapper->GetColoring()->SetIntensityWeight(3.0);
  EXPECT_EQ(mapper->GetColoring()->GetIntensityWeight(), 1.0);
  EXPECT_EQ(mapper->GetOFB(), nullptr);
  std::ostringstream os;
  mapper->Print(os);
  for (const char* name : { "OFB:",
         "LookupMode: Nearest",
         "InterpolationRadius",
         "MipmapBias",
         "MaximumNumberOfMipmapLevels",
         "MinimumMipmapResolution",
         "ColorSource",
         "ScalarArrayName",
         "ScalarComponent",
         "IntensityArrayName",
         "IntensityModulation",
         "IntensityWeight",
         "LICColorMode: COLOR_MODE_BLEND",
         "LICIntensity: 1",
         "MapModeBias",
         "UsePaintedNormals",
         "LastUploadedSampleCount",
         "GPUMemorySize",
         "UploadedBytes" })
  {
    EXPECT_NE(os.str().find(name), std::string::npos) << name;
  }
}
