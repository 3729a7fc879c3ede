// GoogleTest units of vtkOFBLIC's contrast: with every setting at its default, the LIC
// of the pipe with a bump and of bundled meshes spans the range [0, 1] (1st to 99th
// percentile at least 0.7 apart, standard deviation at least 0.15), as VTK's enhanced LIC
// does; the contrast settings still act as documented.
#include "vtkOFBLICTestHelpers.h"

#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBReadMesh.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

using namespace vtkofbtest;

namespace
{
/// The LIC of `mesh` (its active point vectors) with every setting of the sampler and of
/// vtkOFBLIC at its default, but those `configure` sets.
vtkSmartPointer<vtkOFB> LICOf(vtkPolyData* mesh,
  const std::function<void(vtkOFBLIC*)>& configure = nullptr)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(mesh);
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputConnection(sampler->GetOutputPort());
  if (configure)
  {
    configure(lic);
  }
  lic->Update();
  vtkSmartPointer<vtkOFB> out = vtkSmartPointer<vtkOFB>::New();
  out->ShallowCopy(lic->GetOutput());
  return out;
}

/// A bundled mesh with the flow "Flow" = a rotation about a tilted axis through the
/// centre of its bounds.
vtkSmartPointer<vtkPolyData> MeshWithRotation(const std::string& file)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshFile(std::string(VTKOFB_DATA_DIR) + "/" + file);
  if (!mesh)
  {
    return nullptr;
  }
  double b[6];
  mesh->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  double axis[3] = { 0.4, 1.0, 0.3 };
  vtkMath::Normalize(axis);
  return WithField(mesh,
    [axis, c](const double x[3], double v[3])
    {
      const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
      vtkMath::Cross(axis, r, v);
    });
}

void Print(const std::string& what, const ContrastMeasure& c)
{
  std::cout << what << ": 1st-99th percentile " << c.Low << "-" << c.High << " (span " << c.Span()
            << "), std " << c.Std << " over " << c.Count << " samples\n";
}
}

//------------------------------------------------------------------------------
TEST(LICContrast, DefaultsGiveFullContrastOnThePipeAndBundledMeshes)
{
  struct Case
  {
    std::string Name;
    vtkSmartPointer<vtkPolyData> Mesh;
  };
  const Case cases[] = { { "pipe with a bump", MakePipeWithBump() },
    { "stanford-bunny.obj", MeshWithRotation("stanford-bunny.obj") },
    { "horse.ply", MeshWithRotation("horse.ply") },
    { "fandisk.obj", MeshWithRotation("fandisk.obj") } };
  for (const Case& c : cases)
  {
    ASSERT_NE(c.Mesh, nullptr) << c.Name;
    vtkSmartPointer<vtkOFB> out = LICOf(c.Mesh);
    ASSERT_GT(out->GetNumberOfSamples(), 100000) << c.Name;
    const ContrastMeasure contrast = LICContrast(out);
    Print(c.Name + ", defaults", contrast);
    EXPECT_GT(contrast.Count, out->GetNumberOfSamples() / 2) << c.Name;
    EXPECT_GE(contrast.Span(), 0.7) << c.Name;
    EXPECT_GE(contrast.Std, 0.15) << c.Name;
  }
}

//------------------------------------------------------------------------------
TEST(LICContrast, ContrastSettingsStillAct)
{
  vtkSmartPointer<vtkPolyData> pipe = MakePipeWithBump(128, 128);
  const ContrastMeasure defaults = LICContrast(LICOf(pipe));
  // Without the enhanced pass the LIC is the plain convolution of the noise: an average
  // of many noise values, so of a narrow range.
  const ContrastMeasure plain =
    LICContrast(LICOf(pipe, [](vtkOFBLIC* lic) { lic->EnhancedLICOff(); }));
  // EnhanceContrast with factors: the range the final stretch maps to [0, 1] shrinks, so
  // more values reach 0 and 1 and the spread grows.
  const ContrastMeasure stretched = LICContrast(LICOf(pipe,
    [](vtkOFBLIC* lic)
    {
      lic->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_LIC);
      lic->SetLowLICContrastEnhancementFactor(0.2);
      lic->SetHighLICContrastEnhancementFactor(0.2);
    }));
  Print("pipe, defaults", defaults);
  Print("pipe, EnhancedLIC off", plain);
  Print("pipe, EnhanceContrast LIC 0.2 0.2", stretched);
  EXPECT_LT(plain.Span(), 0.5);
  EXPECT_LT(plain.Std, defaults.Std);
  EXPECT_GT(stretched.Std, defaults.Std);
  EXPECT_GE(stretched.Span(), defaults.Span());
}
