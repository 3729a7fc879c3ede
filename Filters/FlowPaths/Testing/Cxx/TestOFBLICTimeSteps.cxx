// vtkOFBLIC over the time steps of a surface: a new step through vtkOFBSampler's
// attribute-only re-sampling keeps the OFB's structure, the LIC keeps its noise and
// says it packed the field and traced the streamlines again (LastRecomputed); its
// values are those of a LIC computed from nothing on the same OFB.
#include "vtkOFBLIC.h"
#include "vtkOFBTestUtilities.h"
#include "vtkOFBTurningRotationSource.h"

#include "vtkFloatArray.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

using namespace vtkofbtest;

TEST(OFBLICTimeSteps, ANewStepKeepsTheStructureAndTheNoise)
{
  vtkNew<TurningRotationSource> source;
  source->Mesh = MakeSphere(1.0, 48);
  source->Alpha = 3.0;
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetResolution(128);
  sampler->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkOFBLIC> lic;
  lic->SetNumberOfSteps(10);
  lic->SetInputConnection(sampler->GetOutputPort());

  lic->UpdateTimeStep(0.0);
  const int all = vtkOFBLIC::RECOMPUTED_STRUCTURE | vtkOFBLIC::RECOMPUTED_SAMPLES |
    vtkOFBLIC::RECOMPUTED_NOISE | vtkOFBLIC::RECOMPUTED_STREAMLINES;
  EXPECT_EQ(lic->GetLastRecomputed(), all);
  vtkNew<vtkFloatArray> first;
  first->DeepCopy(
    vtkOFB::SafeDownCast(lic->GetOutputDataObject(0))->GetSampleData()->GetArray("LIC"));

  lic->UpdateTimeStep(1.0);
  EXPECT_TRUE(sampler->GetLastUpdateResampled());
  EXPECT_EQ(
    lic->GetLastRecomputed(), vtkOFBLIC::RECOMPUTED_SAMPLES | vtkOFBLIC::RECOMPUTED_STREAMLINES);
  vtkDataArray* second =
    vtkOFB::SafeDownCast(lic->GetOutputDataObject(0))->GetSampleData()->GetArray("LIC");
  ASSERT_NE(second, nullptr);
  ASSERT_EQ(second->GetNumberOfTuples(), first->GetNumberOfTuples());

  // The field turned: other streamlines, other values.
  vtkIdType changed = 0;
  for (vtkIdType i = 0; i < second->GetNumberOfTuples(); ++i)
  {
    changed += std::abs(second->GetComponent(i, 0) - first->GetComponent(i, 0)) > 1e-3 ? 1 : 0;
  }
  EXPECT_GT(changed, second->GetNumberOfTuples() / 10);

  // The same values as a LIC of the same OFB from nothing.
  vtkNew<vtkOFB> copy;
  copy->DeepCopy(sampler->GetOutput());
  vtkNew<vtkOFBLIC> fresh;
  fresh->SetNumberOfSteps(10);
  fresh->SetInputData(copy);
  fresh->Update();
  EXPECT_EQ(fresh->GetLastRecomputed(), all);
  vtkDataArray* expected =
    vtkOFB::SafeDownCast(fresh->GetOutputDataObject(0))->GetSampleData()->GetArray("LIC");
  ASSERT_NE(expected, nullptr);
  vtkIdType different = 0;
  for (vtkIdType i = 0; i < expected->GetNumberOfTuples(); ++i)
  {
    different += expected->GetComponent(i, 0) != second->GetComponent(i, 0) ? 1 : 0;
  }
  EXPECT_EQ(different, 0);
}
