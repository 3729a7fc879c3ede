// vtkOFBBuilder: backends, fallback, settings.
#include "vtkOFBTestUtilities.h"

#include "vtkOFBBuilder.h"
#include "vtkRenderWindow.h"

#include <gtest/gtest.h>

#include <sstream>

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
  EXPECT_EQ(builder->GetLastBackend(), vtkOFBBuilder::CPU);
  EXPECT_GT(reference->GetNumberOfSamples(), 0);
  EXPECT_EQ(builder->GetOutput()->GetNumberOfSamples(), reference->GetNumberOfSamples());
  EXPECT_EQ(builder->GetOutput()->GetDepthComplexity(), reference->GetDepthComplexity());
  EXPECT_GT(builder->GetLastBuildTime(), 0.0);
}

TEST(Builder, OpenGLRequestFallsBackWithAWarning)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  vtkNew<vtkOFBBuilder> builder;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(builder);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  builder->SetRenderWindow(window);
  EXPECT_EQ(builder->GetRenderWindow(), window.GetPointer());
  builder->SetInputData(sphere);
  builder->SetResolution(64);
  builder->SetBackendToOpenGL();
  builder->Update();
  EXPECT_NE(observer->Warnings.find("CPU"), std::string::npos);
  EXPECT_EQ(builder->GetLastBackend(), vtkOFBBuilder::CPU);
  EXPECT_GT(builder->GetOutput()->GetNumberOfSamples(), 0);
  observer->Delete();
}

TEST(Builder, BackendIsClampedAndNamed)
{
  vtkNew<vtkOFBBuilder> builder;
  EXPECT_EQ(builder->GetBackend(), vtkOFBBuilder::Auto);
  builder->SetBackend(17);
  EXPECT_EQ(builder->GetBackend(), vtkOFBBuilder::OpenGL);
  builder->SetBackend(-3);
  EXPECT_EQ(builder->GetBackend(), vtkOFBBuilder::Auto);
  EXPECT_STREQ(vtkOFBBuilder::GetBackendAsString(vtkOFBBuilder::CPU), "CPU");
  EXPECT_EQ(builder->GetResolution(), 1024);
}

TEST(Builder, PrintSelfShowsEverySetting)
{
  vtkNew<vtkOFBBuilder> builder;
  std::ostringstream os;
  builder->Print(os);
  for (const char* setting : { "Resolution: 1024", "MemoryLimit: 8192", "DefaultColor:",
         "UseInputColors: On", "PassPointArrays: On", "ProjectVectors: On", "Backend: Auto",
         "LastBackend:", "RenderWindow:", "NumberOfSkippedTriangles:", "LastBuildTime:" })
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
