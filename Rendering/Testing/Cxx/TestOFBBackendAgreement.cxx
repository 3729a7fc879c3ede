// The OpenGL and CPU backends of vtkOFBBuilder agree: sample counts within 0.1 %,
// matched samples' depths within 1e-4 of a cell, attributes within 1e-3. Runs on
// whatever OpenGL the test machine has (llvmpipe in CI).
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkOFBBuilder.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>

using namespace vtkofbtest;

namespace
{
vtkSmartPointer<vtkOFB> BuildWith(vtkPolyData* mesh,
  int resolution,
  int backend,
  vtkRenderWindow* window,
  int* used = nullptr)
{
  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputData(mesh);
  builder->SetResolution(resolution);
  builder->SetBackend(backend);
  builder->SetRenderWindow(window);
  builder->Update();
  if (used)
  {
    *used = builder->GetLastBackend();
  }
  std::cout << vtkOFBBuilder::GetBackendAsString(builder->GetLastBackend())
            << " build: " << builder->GetOutput()->GetNumberOfSamples() << " samples, "
            << builder->GetLastBuildTime() << " ms\n";
  vtkSmartPointer<vtkOFB> ofb = builder->GetOutput();
  return ofb;
}

void ExpectAgreement(const char* name, vtkPolyData* mesh, int resolution, vtkRenderWindow* window)
{
  int used = vtkOFBBuilder::BACKEND_AUTO;
  vtkSmartPointer<vtkOFB> gl =
    BuildWith(mesh, resolution, vtkOFBBuilder::BACKEND_OPENGL, window, &used);
  ASSERT_EQ(used, vtkOFBBuilder::BACKEND_OPENGL) << name << ": the OpenGL backend did not run";
  vtkSmartPointer<vtkOFB> cpu = BuildWith(mesh, resolution, vtkOFBBuilder::BACKEND_CPU, nullptr);
  ASSERT_EQ(gl->GetNumberOfCells(), cpu->GetNumberOfCells());
  ASSERT_DOUBLE_EQ(gl->GetCellSize(), cpu->GetCellSize());
  const double n = static_cast<double>(cpu->GetNumberOfSamples());
  ASSERT_GT(n, 0);
  EXPECT_NEAR(static_cast<double>(gl->GetNumberOfSamples()), n, 1e-3 * n) << name;

  // Match the samples of cells holding as many samples in both, in depth order.
  const vtkTypeUInt32* oc = cpu->GetCellOffsets()->GetPointer(0);
  const vtkTypeUInt32* og = gl->GetCellOffsets()->GetPointer(0);
  const float* dc = cpu->GetDepths()->GetPointer(0);
  const float* dg = gl->GetDepths()->GetPointer(0);
  vtkDataArray* nc = cpu->GetSampleData()->GetNormals();
  vtkDataArray* ng = gl->GetSampleData()->GetNormals();
  const double s = cpu->GetCellSize();
  vtkIdType matched = 0;
  double depthError = 0.0, normalError = 0.0;
  for (vtkIdType c = 0; c < cpu->GetNumberOfCells(); ++c)
  {
    if (oc[c + 1] - oc[c] != og[c + 1] - og[c])
    {
      continue;
    }
    for (vtkTypeUInt32 k = 0; k < oc[c + 1] - oc[c]; ++k)
    {
      const vtkIdType i = oc[c] + k, j = og[c] + k;
      depthError = std::max(depthError, std::fabs(dc[i] - dg[j]) / s);
      if (std::getenv("OFB_DEBUG") && std::fabs(dc[i] - dg[j]) / s > 1e-5)
      {
        std::cout << "cell " << c << " k " << k << " of " << oc[c + 1] - oc[c] << ": " << dc[i] / s
                  << " vs " << dg[j] / s << "\n";
      }
      for (int a = 0; a < 3; ++a)
      {
        normalError =
          std::max(normalError, std::fabs(nc->GetComponent(i, a) - ng->GetComponent(j, a)));
      }
      ++matched;
    }
  }
  std::cout << name << " at " << resolution << ": CPU " << cpu->GetNumberOfSamples() << ", OpenGL "
            << gl->GetNumberOfSamples() << " samples; " << matched << " matched; depth "
            << depthError << " cells, normals " << normalError << "\n";
  EXPECT_GE(matched, 0.998 * n) << name;
  EXPECT_LE(depthError, 1e-4) << name;
  EXPECT_LE(normalError, 1e-3) << name;
  EXPECT_EQ(gl->GetSampleData()->GetNumberOfArrays(), cpu->GetSampleData()->GetNumberOfArrays());
}
}

TEST(BackendAgreement, SphereBunnyAndRockerArm)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  if (!vtkOFBBuilder::IsSupported(window))
  {
    GTEST_SKIP() << "this machine's OpenGL cannot run the OpenGL backend (needs 4.3)";
  }
  ExpectAgreement("sphere", MakeSphere(1.0, 128), 256, window);
  ExpectAgreement("bunny", ReadMesh("stanford-bunny.obj"), 256, window);
  ExpectAgreement("rocker-arm", ReadMesh("rocker-arm.obj"), 256, window);
}

TEST(BackendAgreement, AutoPicksTheCPUOnSoftwareRenderersAndWithoutAWindow)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  int used = vtkOFBBuilder::BACKEND_OPENGL;
  BuildWith(sphere, 64, vtkOFBBuilder::BACKEND_AUTO, nullptr, &used);
  EXPECT_EQ(used, vtkOFBBuilder::BACKEND_CPU);
}

TEST(BackendAgreement, CellArraysOfAnImageBoxOnBothBackends)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  if (!vtkOFBBuilder::IsSupported(window))
  {
    GTEST_SKIP() << "this machine's OpenGL cannot run the OpenGL backend (needs 4.3)";
  }
  // A box of 3 x 2 x 2 unit voxels whose cell array "CellId" is each voxel's id:
  // sampled through its outer surface, each sample has the id of a voxel touching it.
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 3, 3);
  vtkNew<vtkIntArray> ids;
  ids->SetName("CellId");
  for (vtkIdType c = 0; c < image->GetNumberOfCells(); ++c)
  {
    ids->InsertNextValue(static_cast<int>(c));
  }
  image->GetCellData()->AddArray(ids);
  for (const int backend : { vtkOFBBuilder::BACKEND_OPENGL, vtkOFBBuilder::BACKEND_CPU })
  {
    vtkNew<vtkOFBBuilder> builder;
    builder->SetInputData(image);
    builder->SetResolution(64);
    builder->SetBackend(backend);
    builder->SetRenderWindow(window);
    builder->Update();
    ASSERT_EQ(builder->GetLastBackend(), backend);
    vtkOFB* ofb = builder->GetOutput();
    ASSERT_GT(ofb->GetNumberOfSamples(), 1000);
    vtkDataArray* cellIds = ofb->GetSampleData()->GetArray("CellId");
    ASSERT_NE(cellIds, nullptr);
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3], bounds[6];
      ofb->GetSamplePosition(i, x);
      image->GetCellBounds(static_cast<vtkIdType>(cellIds->GetTuple1(i)), bounds);
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_GE(x[k], bounds[2 * k] - 0.05) << "backend " << backend << ", sample " << i;
        ASSERT_LE(x[k], bounds[2 * k + 1] + 0.05) << "backend " << backend << ", sample " << i;
      }
    }
  }
}
