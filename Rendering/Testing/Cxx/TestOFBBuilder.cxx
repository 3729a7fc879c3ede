// vtkOFBBuilder: backends, fallback, settings.
#include "vtkOFBTestUtilities.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkOFBBuilder.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

using namespace vtkofbtest;

TEST(Builder, CPUBackendMatchesTheSampler)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 64);
  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputData(sphere);
  builder->SetResolution(128);
  builder->SetBackendToCPU();
  builder->Update();
  vtkSmartPointer<vtkOFB> reference = Build(sphere, 128);
  EXPECT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_CPU);
  EXPECT_GT(reference->GetNumberOfSamples(), 0);
  EXPECT_EQ(builder->GetOutput()->GetNumberOfSamples(), reference->GetNumberOfSamples());
  EXPECT_EQ(builder->GetOutput()->GetDepthComplexity(), reference->GetDepthComplexity());
  EXPECT_GT(builder->GetLastBuildTime(), 0.0);
}

TEST(Builder, OpenGLRequestFallsBackWithAWarning)
{
  // No render window and no display to make one: the CPU builds, with a warning.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  unsetenv("DISPLAY");
  vtkNew<vtkOFBBuilder> builder;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(builder);
  builder->SetInputData(sphere);
  builder->SetResolution(64);
  builder->SetBackendToOpenGL();
  builder->Update();
  if (display)
  {
    setenv("DISPLAY", saved.c_str(), 1);
  }
  EXPECT_NE(observer->Warnings.find("building on the CPU"), std::string::npos);
  EXPECT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_CPU);
  EXPECT_GT(builder->GetOutput()->GetNumberOfSamples(), 0);
  observer->Delete();
}

TEST(Builder, OpenGLBuildLeavesTheWindowsRenderingUnchanged)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(sphere);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetViewport(0.1, 0.2, 0.9, 0.8);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(120, 100);
  window->AddRenderer(renderer);
  window->Render();
  if (!vtkOFBBuilder::IsSupported(window))
  {
    GTEST_SKIP() << "this machine's OpenGL cannot run the OpenGL backend";
  }
  auto grab = [&]()
  {
    window->Render();
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(window);
    capture->ReadFrontBufferOff();
    capture->Update();
    vtkSmartPointer<vtkImageData> image = capture->GetOutput();
    return image;
  };
  vtkSmartPointer<vtkImageData> before = grab();
  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputData(sphere);
  builder->SetResolution(128);
  builder->SetRenderWindow(window);
  builder->SetBackendToOpenGL();
  builder->Update();
  EXPECT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_OPENGL);
  EXPECT_GT(builder->GetOutput()->GetNumberOfSamples(), 0);
  vtkSmartPointer<vtkImageData> after = grab();
  vtkDataArray* a = before->GetPointData()->GetScalars();
  vtkDataArray* b = after->GetPointData()->GetScalars();
  ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues());
  vtkIdType different = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    different += a->GetVariantValue(i) != b->GetVariantValue(i);
  }
  EXPECT_EQ(different, 0) << "the build changed GL state that the renderer relies on";
}

TEST(Builder, BackendIsClampedAndNamed)
{
  vtkNew<vtkOFBBuilder> builder;
  EXPECT_EQ(builder->GetBackend(), vtkOFBBuilder::BACKEND_AUTO);
  builder->SetBackend(17);
  EXPECT_EQ(builder->GetBackend(), vtkOFBBuilder::BACKEND_OPENGL);
  builder->SetBackend(-3);
  EXPECT_EQ(builder->GetBackend(), vtkOFBBuilder::BACKEND_AUTO);
  EXPECT_STREQ(vtkOFBBuilder::GetBackendAsString(vtkOFBBuilder::BACKEND_CPU), "CPU");
  EXPECT_EQ(builder->GetResolution(), 1024);
}

TEST(Builder, PrintSelfShowsEverySetting)
{
  vtkNew<vtkOFBBuilder> builder;
  std::ostringstream os;
  builder->Print(os);
  for (const char* setting : { "Resolution: 1024",
         "MemoryLimit: 8192",
         "DefaultColor:",
         "UseInputColors: On",
         "PassPointArrays: On",
         "ProjectVectors: On",
         "Backend: Auto",
         "LastBackend:",
         "RenderWindow:",
         "NumberOfSkippedTriangles:",
         "LastBuildTime:" })
  {
    EXPECT_NE(os.str().find(setting), std::string::npos) << setting;
  }
}

TEST(Builder, ErrorsGiveAnEmptyOutputAfterAGoodBuild)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  vtkNew<vtkOFBBuilder> builder;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(builder);
  builder->SetInputData(sphere);
  builder->SetResolution(64);
  builder->Update();
  ASSERT_GT(builder->GetOutput()->GetNumberOfSamples(), 0);
  // A bad setting on the next update must not leave the previous OFB behind.
  builder->SetResolution(-1);
  builder->Update();
  EXPECT_NE(observer->Errors.find("Resolution"), std::string::npos);
  EXPECT_EQ(builder->GetOutput()->GetNumberOfSamples(), 0);
  observer->Delete();
}

TEST(Builder, OpenGLPhaseTimesOnlyWhenAskedFor)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  if (!vtkOFBBuilder::IsSupported(window))
  {
    GTEST_SKIP() << "this machine's OpenGL cannot run the OpenGL backend (needs 4.3)";
  }
  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputData(MakeSphere(1.0, 32));
  builder->SetResolution(64);
  builder->SetBackendToOpenGL();
  builder->SetRenderWindow(window);
  builder->Update();
  ASSERT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_OPENGL);
  EXPECT_STREQ(builder->GetLastOpenGLPhaseTimes(), "");
  const vtkIdType samples = builder->GetOutput()->GetNumberOfSamples();

  builder->MeasureOpenGLPhasesOn();
  builder->Update(); // a new setting: the builder runs again
  const std::string phases = builder->GetLastOpenGLPhaseTimes();
  for (const char* phase : { "compile ",
         "upload ",
         "count ",
         "scan ",
         "fill ",
         "sort ",
         "read back ",
         "cell index ",
         "interpolate " })
  {
    EXPECT_NE(phases.find(phase), std::string::npos) << phase << " missing in: " << phases;
  }
  // The timing does not change the result.
  EXPECT_EQ(builder->GetOutput()->GetNumberOfSamples(), samples);
}

TEST(Builder, OpenGLProgramsFollowTheWindow)
{
  // The builder keeps its compiled programs between builds in one context; a new
  // window (a new context) gets its own, and the old window may go first.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputData(sphere);
  builder->SetResolution(64);
  builder->SetBackendToOpenGL();
  vtkIdType samples[3] = { 0, 0, 0 };
  for (int round = 0; round < 3; ++round)
  {
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(64, 64);
    if (!vtkOFBBuilder::IsSupported(window))
    {
      GTEST_SKIP() << "this machine's OpenGL cannot run the OpenGL backend (needs 4.3)";
    }
    builder->SetRenderWindow(window);
    builder->Update();
    builder->Modified();
    builder->Update(); // the same context again: the kept programs
    ASSERT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_OPENGL) << round;
    samples[round] = builder->GetOutput()->GetNumberOfSamples();
    builder->SetRenderWindow(nullptr);
  }
  EXPECT_GT(samples[0], 0);
  EXPECT_EQ(samples[1], samples[0]);
  EXPECT_EQ(samples[2], samples[0]);
}
