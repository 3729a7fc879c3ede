// vtkOFBPainter's marks of changed samples (what vtkOFBPolyDataMapper uploads) when one
// call changes more separate runs of samples than the 128 ranges it may mark: every
// changed sample is covered, and the ranges are the runs joined across their gaps, the
// smallest first (a threshold doubled from 64 samples), as written out here again.
#include "vtkOFBTestUtilities.h"

#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTimeStamp.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

using namespace vtkofbtest;

namespace
{
using Ranges = std::vector<std::pair<vtkIdType, vtkIdType>>;

// The runs of samples whose colour differs, joined as the painter documents it.
Ranges ExpectedMarks(const unsigned char* before,
  const unsigned char* after,
  vtkIdType n,
  size_t& numberOfRuns)
{
  Ranges runs;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (std::memcmp(before + 4 * i, after + 4 * i, 4) == 0)
    {
      continue;
    }
    if (!runs.empty() && runs.back().second == i)
    {
      runs.back().second = i + 1;
    }
    else
    {
      runs.emplace_back(i, i + 1);
    }
  }
  numberOfRuns = runs.size();
  for (vtkIdType gap = 64; runs.size() > 128; gap *= 2)
  {
    Ranges joined;
    for (const auto& r : runs)
    {
      if (!joined.empty() && r.first - joined.back().second <= gap)
      {
        joined.back().second = r.second;
      }
      else
      {
        joined.push_back(r);
      }
    }
    runs.swap(joined);
  }
  return runs;
}

Ranges Marks(vtkOFB* ofb, vtkMTimeType since)
{
  vtkNew<vtkIdTypeArray> marks;
  ofb->GetSampleRangesModifiedSince(since, marks);
  Ranges ranges;
  for (vtkIdType r = 0; r < marks->GetNumberOfTuples(); ++r)
  {
    ranges.emplace_back(marks->GetValue(2 * r), marks->GetValue(2 * r + 1));
  }
  return ranges;
}
}

//------------------------------------------------------------------------------
TEST(PaintMarks, ManyRunsAreJoinedSmallestGapsFirst)
{
  // Small dabs all over the sphere: hundreds of separate runs of samples.
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  vtkNew<vtkPoints> centres;
  for (int k = 0; k < 400; ++k)
  {
    const double z = random->GetNextRangeValue(-1.0, 1.0);
    const double phi = random->GetNextRangeValue(0.0, 2.0 * vtkMath::Pi());
    const double s = std::sqrt(1.0 - z * z);
    centres->InsertNextPoint(s * std::cos(phi), s * std::sin(phi), z);
  }
  for (int threads : { 1, 2 })
  {
    SCOPED_TRACE(threads);
    vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 96), 128);
    vtkNew<vtkOFBPainter> painter;
    painter->SetOFB(ofb);
    painter->GetBrush()->SetRadius(1.5 * ofb->GetCellSize());
    painter->Dab(0, 0, 1); // creates "Colors"
    painter->GetBrush()->SetColor(0.9, 0.3, 0.1);
    auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
    ASSERT_NE(colors, nullptr);
    const std::vector<unsigned char> before(
      colors->GetPointer(0), colors->GetPointer(0) + 4 * colors->GetNumberOfTuples());
    vtkTimeStamp t;
    t.Modified();
    vtkIdType changed = 0;
    vtkSMPTools::LocalScope(
      vtkSMPTools::Config{ threads }, [&]() { changed = painter->Dabs(centres); });
    size_t runs = 0;
    const Ranges expected =
      ExpectedMarks(before.data(), colors->GetPointer(0), ofb->GetNumberOfSamples(), runs);
    const Ranges marks = Marks(ofb, t.GetMTime());
    ASSERT_GT(changed, 1000);
    ASSERT_GT(runs, 1000u) << "the dabs should leave many separate runs";
    ASSERT_LE(expected.size(), 128u);
    EXPECT_EQ(marks, expected);
    vtkIdType differing = 0;
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      differing += std::memcmp(before.data() + 4 * i, colors->GetPointer(4 * i), 4) != 0;
    }
    EXPECT_EQ(differing, changed);
  }
}

//------------------------------------------------------------------------------
TEST(PaintMarks, SmallCallsOnALargeOFBMarkExactly)
{
  // Over half a million samples: the changed-sample bitmap has three chunks, of which a
  // small call reads only those it changed.
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 96), 512);
  ASSERT_GT(ofb->GetNumberOfSamples(), 2 * 262144);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(3.0 * ofb->GetCellSize());
  painter->Dab(0, 0, 1); // creates "Colors"
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  ASSERT_NE(colors, nullptr);
  const double centres[][3] = {
    { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 }, { 0.6, 0.8, 0 }, { -0.6, 0, 0.8 }
  };
  int call = 0;
  for (const auto& c : centres)
  {
    for (bool undo : { false, true })
    {
      SCOPED_TRACE(call);
      ++call;
      painter->GetBrush()->SetColor(0.1 * call, 0.5, 0.9);
      const std::vector<unsigned char> before(
        colors->GetPointer(0), colors->GetPointer(0) + 4 * colors->GetNumberOfTuples());
      vtkTimeStamp t;
      t.Modified();
      const vtkIdType changed = undo ? painter->Undo() : painter->Dab(c);
      ASSERT_GT(changed, 0);
      size_t runs = 0;
      const Ranges expected =
        ExpectedMarks(before.data(), colors->GetPointer(0), ofb->GetNumberOfSamples(), runs);
      ASSERT_GT(runs, 0u);
      EXPECT_EQ(Marks(ofb, t.GetMTime()), expected);
    }
  }
}

//------------------------------------------------------------------------------
TEST(PaintMarks, SetSampleColorsIsUndoablePaint)
{
  // Colours computed elsewhere (every 37th of the first 3,700 samples, a colour from its
  // id: 100 runs, fewer than the 128 ranges a call marks exactly) written
  // through the painter: exactly those samples change and are marked, undo restores the
  // colours bit for bit and redo writes them again; bad ids write nothing.
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(vtkofbtest::MakeSphere(1.0, 32), 64);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  ASSERT_NE(colors, nullptr);
  const std::vector<unsigned char> before(
    colors->GetPointer(0), colors->GetPointer(0) + 4 * ofb->GetNumberOfSamples());
  vtkNew<vtkIdTypeArray> ids;
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetNumberOfComponents(4);
  ASSERT_GT(ofb->GetNumberOfSamples(), 3700);
  for (vtkIdType i = 0; i < 3700; i += 37)
  {
    ids->InsertNextValue(i);
    const unsigned char c[4] = { static_cast<unsigned char>(i % 251), 0, 200, 255 };
    rgba->InsertNextTypedTuple(c);
  }
  vtkTimeStamp t;
  t.Modified();
  const vtkIdType changed = painter->SetSampleColors(ids, rgba);
  EXPECT_EQ(changed, ids->GetNumberOfTuples());
  vtkNew<vtkIdTypeArray> ranges;
  ofb->GetSampleRangesModifiedSince(t.GetMTime(), ranges);
  vtkIdType marked = 0;
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    marked += ranges->GetValue(2 * r + 1) - ranges->GetValue(2 * r);
  }
  EXPECT_EQ(marked, changed); // no sample between them
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const unsigned char* c = colors->GetPointer(4 * i);
    if (i % 37 == 0 && i < 3700)
    {
      ASSERT_EQ(c[0], i % 251);
      ASSERT_EQ(c[2], 200);
    }
    else
    {
      ASSERT_EQ(std::memcmp(c, before.data() + 4 * i, 4), 0) << i;
    }
  }
  const std::vector<unsigned char> after(
    colors->GetPointer(0), colors->GetPointer(0) + 4 * ofb->GetNumberOfSamples());
  ASSERT_TRUE(painter->Undo());
  EXPECT_EQ(std::memcmp(colors->GetPointer(0), before.data(), before.size()), 0);
  ASSERT_TRUE(painter->Redo());
  EXPECT_EQ(std::memcmp(colors->GetPointer(0), after.data(), after.size()), 0);
  // The same colours again change nothing.
  EXPECT_EQ(painter->SetSampleColors(ids, rgba), 0);

  vtkNew<vtkofbtest::MessageObserver> o;
  o->Watch(painter);
  ids->SetValue(3, ofb->GetNumberOfSamples());
  rgba->SetTypedComponent(0, 1, 77);
  EXPECT_EQ(painter->SetSampleColors(ids, rgba), 0);
  EXPECT_NE(o->Errors.find("outside"), std::string::npos) << o->Errors;
  EXPECT_EQ(colors->GetTypedComponent(0, 1), 0); // nothing written
  o->Clear();
  rgba->SetNumberOfTuples(2);
  EXPECT_EQ(painter->SetSampleColors(ids, rgba), 0);
  EXPECT_NE(o->Errors.find("one RGBA tuple an id"), std::string::npos) << o->Errors;
  EXPECT_EQ(painter->SetSampleColors(nullptr, rgba), 0);
}
