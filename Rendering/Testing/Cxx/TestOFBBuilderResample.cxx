// vtkOFBBuilder's OpenGL backend records the sources of its samples too: a new field
// on the same geometry is re-sampled on the structure of the OpenGL build, with the
// values of a full OpenGL build.
#include "vtkOFBTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkOFBBuilder.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vtkofbtest;

namespace
{
/// The sphere with new point arrays (and new points of the same coordinates) for time t.
vtkSmartPointer<vtkPolyData> AtTime(vtkPolyData* sphere, double t)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(sphere);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->DeepCopy(sphere->GetPoints());
  out->SetPoints(points);
  out->GetPointData()->Initialize();
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("Pressure");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    velocity->InsertNextTuple3(-x[1] * std::cos(t), x[0], std::sin(3 * x[2] + t));
    pressure->InsertNextValue(std::cos(5 * x[0] - t));
  }
  out->GetPointData()->SetVectors(velocity);
  out->GetPointData()->AddArray(pressure);
  return out;
}
}

TEST(BuilderResample, OpenGLBuildIsResampled)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  window->Render();
  if (!vtkOFBBuilder::IsSupported(window))
  {
    GTEST_SKIP() << "this machine's OpenGL cannot run the OpenGL backend";
  }
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 48);
  vtkNew<vtkOFBBuilder> builder;
  builder->SetRenderWindow(window);
  builder->SetBackendToOpenGL();
  builder->SetStructureReuseToAlways();
  builder->SetResolution(128);
  builder->SetInputData(AtTime(sphere, 0.0));
  builder->Update();
  ASSERT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_OPENGL);
  EXPECT_FALSE(builder->GetLastUpdateResampled());
  const vtkMTimeType structure = builder->GetOutput()->GetStructureMTime();

  vtkSmartPointer<vtkPolyData> next = AtTime(sphere, 0.7);
  builder->SetInputData(next);
  builder->Update();
  EXPECT_TRUE(builder->GetLastUpdateResampled());
  EXPECT_EQ(builder->GetLastBackend(), vtkOFBBuilder::BACKEND_OPENGL);
  EXPECT_EQ(builder->GetOutput()->GetStructureMTime(), structure);

  vtkNew<vtkOFBBuilder> full;
  full->SetRenderWindow(window);
  full->SetBackendToOpenGL();
  full->SetStructureReuseToOff();
  full->SetResolution(128);
  full->SetInputData(next);
  full->Update();
  ASSERT_EQ(full->GetLastBackend(), vtkOFBBuilder::BACKEND_OPENGL);
  vtkOFB* a = builder->GetOutput();
  vtkOFB* b = full->GetOutput();
  ASSERT_EQ(a->GetNumberOfSamples(), b->GetNumberOfSamples());
  for (const char* name : { "Velocity", "Pressure", "Colors", "Normals" })
  {
    vtkDataArray* got = a->GetSampleData()->GetArray(name);
    vtkDataArray* expected = b->GetSampleData()->GetArray(name);
    ASSERT_NE(got, nullptr) << name;
    ASSERT_NE(expected, nullptr) << name;
    ASSERT_EQ(got->GetNumberOfValues(), expected->GetNumberOfValues()) << name;
    vtkIdType different = 0;
    for (vtkIdType v = 0; v < got->GetNumberOfValues(); ++v)
    {
      const double e = expected->GetVariantValue(v).ToDouble();
      different += std::abs(got->GetVariantValue(v).ToDouble() - e) > 1e-6 * (1.0 + std::abs(e));
    }
    EXPECT_EQ(different, 0) << name;
  }
}
