// GoogleTest units of vtkOFBLICPyramid: the coarser levels hold a LIC computed on their own
// samples (streaks as wide as their cells, full contrast) instead of level 0's filtered
// down (grey), with the LIC's settings; a new phase computes them again; values painted in
// place leave them as they are; without a LIC it is a plain vtkOFBPyramid; deferred
// (DeferLevelLICs) they are the direct ones; the levels' frames follow level 0's.
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBLICTestHelpers.h"
#include "vtkOFBPyramid.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace
{
// The standard deviation of a one-component sample array.
double Spread(vtkDataArray* array)
{
  double sum = 0.0;
  double sum2 = 0.0;
  const vtkIdType n = array->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = array->GetComponent(i, 0);
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
}

struct Square
{
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkOFB> OFB;
  vtkNew<vtkOFBLIC> LIC;

  Square()
  {
    const double x[3] = { 1.0, 0.0, 0.0 };
    this->Surface = vtkofbtest::WithField(vtkofbtest::MakeSquare(), vtkofbtest::UniformField(x));
    this->OFB = vtkofbtest::Build(this->Surface, 258);
    this->LIC->SetInputData(this->OFB);
    this->LIC->Update();
  }
};
}

TEST(OFBLICPyramid, LevelsHoldTheirOwnLIC)
{
  Square square;
  vtkOFB* level0 = square.LIC->GetOutput();
  vtkNew<vtkOFBPyramid> filtered;
  filtered->SetInputOFB(level0);
  filtered->SetSurface(square.Surface);
  filtered->SetMaximumNumberOfLevels(4);
  ASSERT_TRUE(filtered->UpdateLevels());

  vtkNew<vtkOFBLICPyramid> pyramid;
  pyramid->SetInputOFB(level0);
  pyramid->SetSurface(square.Surface);
  pyramid->SetMaximumNumberOfLevels(4);
  pyramid->SetLIC(square.LIC);
  ASSERT_TRUE(pyramid->UpdateLevels());
  ASSERT_EQ(pyramid->GetNumberOfLevels(), 4);
  EXPECT_EQ(pyramid->GetNumberOfLevelLICComputations(), 1);
  EXPECT_TRUE(pyramid->IsComputedArray("LIC"));
  EXPECT_TRUE(pyramid->IsComputedArray("LICMask"));
  EXPECT_FALSE(pyramid->IsComputedArray("Colors"));
  EXPECT_FALSE(filtered->IsComputedArray("LIC"));

  const double spread0 = Spread(level0->GetSampleData()->GetArray("LIC"));
  for (int k = 1; k < 4; ++k)
  {
    vtkDataArray* own = pyramid->GetLevel(k)->GetSampleData()->GetArray("LIC");
    vtkDataArray* mean = filtered->GetLevel(k)->GetSampleData()->GetArray("LIC");
    ASSERT_NE(own, nullptr);
    ASSERT_NE(mean, nullptr);
    ASSERT_EQ(own->GetNumberOfTuples(), pyramid->GetLevel(k)->GetNumberOfSamples());
    ASSERT_NE(pyramid->GetLevel(k)->GetSampleData()->GetArray("LICMask"), nullptr);
    // A LIC of the level keeps the contrast of level 0's; the filtered one fades.
    const double ownSpread = Spread(own);
    const double meanSpread = Spread(mean);
    std::printf("level %d: LIC spread %.4f computed, %.4f filtered (level 0: %.4f)\n",
      k,
      ownSpread,
      meanSpread,
      spread0);
    EXPECT_GT(ownSpread, 0.6 * spread0) << "level " << k;
    EXPECT_LT(meanSpread, ownSpread) << "level " << k;
  }

  std::ostringstream os;
  pyramid->Print(os);
  EXPECT_NE(os.str().find("NumberOfLevelLICComputations"), std::string::npos);
}

TEST(OFBLICPyramid, NewPhaseComputesTheLevelsAgainAndPaintLeavesThem)
{
  Square square;
  square.LIC->AnimateOn();
  square.LIC->SetAnimationPhase(0.0);
  square.LIC->Update();
  vtkNew<vtkOFBLICPyramid> pyramid;
  pyramid->SetInputOFB(square.LIC->GetOutput());
  pyramid->SetSurface(square.Surface);
  pyramid->SetMaximumNumberOfLevels(3);
  pyramid->SetFilterCacheSize(0);
  pyramid->SetLIC(square.LIC);
  ASSERT_TRUE(pyramid->UpdateLevels());
  vtkSmartPointer<vtkDataArray> before = pyramid->GetLevel(1)->GetSampleData()->GetArray("LIC");
  const double first = before->GetComponent(0, 0);

  square.LIC->SetAnimationPhase(0.5);
  square.LIC->Update();
  pyramid->SetInputOFB(square.LIC->GetOutput());
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_EQ(pyramid->GetNumberOfLevelLICComputations(), 2);
  vtkDataArray* after = pyramid->GetLevel(1)->GetSampleData()->GetArray("LIC");
  int changed = 0;
  for (vtkIdType i = 0; i < after->GetNumberOfTuples(); ++i)
  {
    changed += after->GetComponent(i, 0) != before->GetComponent(i, 0);
  }
  EXPECT_GT(changed, after->GetNumberOfTuples() / 2) << "first value " << first;

  // Paint changed in place at a few samples of level 0: the colours are filtered again
  // there, the levels' LIC stays.
  vtkOFB* level0 = square.LIC->GetOutput();
  auto* colors = vtkUnsignedCharArray::SafeDownCast(
    level0->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()));
  ASSERT_NE(colors, nullptr);
  std::vector<float> lic1(static_cast<size_t>(after->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < after->GetNumberOfTuples(); ++i)
  {
    lic1[i] = static_cast<float>(after->GetComponent(i, 0));
  }
  for (vtkIdType i = 100; i < 200; ++i)
  {
    colors->SetTypedComponent(i, 0, 0);
  }
  auto redSum = [](vtkOFB* ofb)
  {
    vtkDataArray* c = ofb->GetSampleData()->GetArray(vtkOFB::ColorsArrayName());
    double sum = 0.0;
    for (vtkIdType i = 0; i < c->GetNumberOfTuples(); ++i)
    {
      sum += c->GetComponent(i, 0);
    }
    return sum;
  };
  const double redBefore = redSum(pyramid->GetLevel(1));
  level0->MarkSamplesModified(100, 200);
  level0->Modified();
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_LT(redSum(pyramid->GetLevel(1)), redBefore) << "the paint was not filtered down";
  EXPECT_EQ(pyramid->GetNumberOfLevelLICComputations(), 2);
  vtkDataArray* kept = pyramid->GetLevel(1)->GetSampleData()->GetArray("LIC");
  for (vtkIdType i = 0; i < kept->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(static_cast<float>(kept->GetComponent(i, 0)), lic1[i]) << "sample " << i;
  }
}

TEST(OFBLICPyramid, WithoutALICItFilters)
{
  Square square;
  vtkNew<vtkOFBPyramid> plain;
  vtkNew<vtkOFBLICPyramid> pyramid;
  for (vtkOFBPyramid* p : { plain.GetPointer(), static_cast<vtkOFBPyramid*>(pyramid) })
  {
    p->SetInputOFB(square.LIC->GetOutput());
    p->SetSurface(square.Surface);
    p->SetMaximumNumberOfLevels(2);
    ASSERT_TRUE(p->UpdateLevels());
  }
  EXPECT_EQ(pyramid->GetNumberOfLevelLICComputations(), 0);
  vtkDataArray* a = plain->GetLevel(1)->GetSampleData()->GetArray("LIC");
  vtkDataArray* b = pyramid->GetLevel(1)->GetSampleData()->GetArray("LIC");
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(a->GetComponent(i, 0), b->GetComponent(i, 0));
  }
}

TEST(OFBLICPyramid, DeferredLevelLICsAreTheDirectOnes)
{
  Square square;
  vtkOFB* level0 = square.LIC->GetOutput();
  vtkNew<vtkOFBLICPyramid> direct;
  vtkNew<vtkOFBLICPyramid> deferred;
  deferred->DeferLevelLICsOn();
  for (vtkOFBLICPyramid* p : { direct.GetPointer(), deferred.GetPointer() })
  {
    p->SetInputOFB(level0);
    p->SetSurface(square.Surface);
    p->SetMaximumNumberOfLevels(3);
    p->SetLIC(square.LIC);
    ASSERT_TRUE(p->UpdateLevels());
  }
  EXPECT_EQ(direct->GetNumberOfLevelLICComputations(), 1);
  EXPECT_FALSE(direct->GetLevelLICsPending());
  // Deferred: the levels hold the filtered LIC until ComputeLevelLICs.
  EXPECT_EQ(deferred->GetNumberOfLevelLICComputations(), 0);
  EXPECT_TRUE(deferred->GetLevelLICsPending());
  const vtkMTimeType before = deferred->GetArraysTime();
  // More levels than it has (another process's count): the extra ones run on nothing.
  deferred->ComputeLevelLICs(5);
  EXPECT_FALSE(deferred->GetLevelLICsPending());
  EXPECT_EQ(deferred->GetNumberOfLevelLICComputations(), 1);
  EXPECT_GT(deferred->GetArraysTime(), before);
  EXPECT_GT(deferred->GetAllArraysTime(), before);
  ASSERT_EQ(deferred->GetNumberOfLevels(), 3);
  for (int k = 1; k < 3; ++k)
  {
    vtkDataArray* a = direct->GetLevel(k)->GetSampleData()->GetArray("LIC");
    vtkDataArray* b = deferred->GetLevel(k)->GetSampleData()->GetArray("LIC");
    ASSERT_NE(b, nullptr);
    ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      ASSERT_EQ(a->GetComponent(i, 0), b->GetComponent(i, 0)) << "level " << k << " sample " << i;
    }
  }
  // Nothing pending after an update without change.
  ASSERT_TRUE(deferred->UpdateLevels());
  EXPECT_FALSE(deferred->GetLevelLICsPending());
}

TEST(OFBLICPyramid, LevelFramesFollowLevelZerosFrame)
{
  // Level 0 sampled on the whole square; the levels sample its left half (a piece of a
  // distributed surface): their frames are those of the whole square's levels.
  Square square;
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(0.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(100, 200);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  const double x[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkPolyData> half =
    vtkofbtest::WithField(triangles->GetOutput(), vtkofbtest::UniformField(x));
  vtkNew<vtkOFBPyramid> whole;
  vtkNew<vtkOFBPyramid> piece;
  for (vtkOFBPyramid* p : { whole.GetPointer(), piece.GetPointer() })
  {
    p->SetInputOFB(square.OFB);
    p->SetSurface(p == whole.GetPointer() ? square.Surface.Get() : half.Get());
    p->SetMaximumNumberOfLevels(4);
    ASSERT_TRUE(p->UpdateLevels());
  }
  ASSERT_EQ(piece->GetNumberOfLevels(), whole->GetNumberOfLevels());
  for (int k = 1; k < whole->GetNumberOfLevels(); ++k)
  {
    vtkOFB* a = whole->GetLevel(k);
    vtkOFB* b = piece->GetLevel(k);
    EXPECT_NEAR(b->GetCellSize(), a->GetCellSize(), 1e-12 * a->GetCellSize()) << "level " << k;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(b->GetOrigin()[c], a->GetOrigin()[c], 1e-9 * a->GetCellSize()) << "level " << k;
      EXPECT_EQ(b->GetDimensions()[c], a->GetDimensions()[c]) << "level " << k;
    }
    // The piece's samples are the whole's on the left half.
    EXPECT_GT(b->GetNumberOfSamples(), a->GetNumberOfSamples() / 3) << "level " << k;
    EXPECT_LT(b->GetNumberOfSamples(), 2 * a->GetNumberOfSamples() / 3) << "level " << k;
  }
}
