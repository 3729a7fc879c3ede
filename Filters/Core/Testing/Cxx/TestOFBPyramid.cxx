// GoogleTest units of vtkOFBPyramid: levels, filtering of the sample arrays, updates,
// Resample, bad input and PrintSelf.
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBPyramid.h"
#include "vtkOFBTestUtilities.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}

void Fill(vtkOFB* ofb, unsigned char r, unsigned char g, unsigned char b)
{
  const unsigned char c[4] = { r, g, b, 255 };
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    Colors(ofb)->SetTypedTuple(i, c);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
}

/// A sphere's OFB at 128 cells in one colour, and a pyramid of it (not updated yet).
struct SpherePyramid
{
  vtkSmartPointer<vtkPolyData> Sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> OFB = vtkofbtest::Build(Sphere, 128);
  vtkNew<vtkOFBPyramid> Pyramid;

  SpherePyramid()
  {
    Fill(this->OFB, 10, 200, 30);
    this->Pyramid->SetInputOFB(this->OFB);
    this->Pyramid->SetSurface(this->Sphere);
  }

  /// A float sample array "LIC" of `value` everywhere, added to the OFB.
  vtkSmartPointer<vtkFloatArray> AddLIC(float value)
  {
    vtkNew<vtkFloatArray> lic;
    lic->SetName("LIC");
    lic->SetNumberOfTuples(this->OFB->GetNumberOfSamples());
    lic->Fill(value);
    this->OFB->GetSampleData()->AddArray(lic);
    return lic.Get();
  }
};

/// The bytes of every named sample array of level k, by name.
std::map<std::string, std::vector<unsigned char>> Snapshot(vtkOFB* level)
{
  std::map<std::string, std::vector<unsigned char>> arrays;
  vtkPointData* pd = level->GetSampleData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    const auto* bytes = static_cast<const unsigned char*>(array->GetVoidPointer(0));
    arrays[array->GetName()].assign(bytes, bytes + array->GetDataSize() * array->GetDataTypeSize());
  }
  return arrays;
}

/// Whether sample i lies in one of the [first, last) ranges.
bool InRanges(vtkIdTypeArray* ranges, vtkIdType i)
{
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    if (i >= ranges->GetTypedComponent(r, 0) && i < ranges->GetTypedComponent(r, 1))
    {
      return true;
    }
  }
  return false;
}
}

TEST(OFBPyramid, LevelsHalveTheResolution)
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 128);
  vtkNew<vtkOFBPyramid> pyramid;
  pyramid->SetInputOFB(ofb);
  pyramid->SetSurface(sphere);
  pyramid->SetMinimumResolution(8);
  ASSERT_TRUE(pyramid->UpdateLevels());
  ASSERT_GE(pyramid->GetNumberOfLevels(), 4);
  EXPECT_EQ(pyramid->GetLevel(0), ofb.Get());
  EXPECT_EQ(pyramid->GetLevel(pyramid->GetNumberOfLevels()), nullptr);
  for (int k = 1; k < pyramid->GetNumberOfLevels(); ++k)
  {
    vtkOFB* finer = pyramid->GetLevel(k - 1);
    vtkOFB* level = pyramid->GetLevel(k);
    ASSERT_NE(level, nullptr);
    EXPECT_GT(level->GetNumberOfSamples(), 0);
    EXPECT_LT(level->GetNumberOfSamples(), finer->GetNumberOfSamples());
    EXPECT_NEAR(level->GetCellSize() / finer->GetCellSize(), 2.0, 0.2) << "level " << k;
    const vtkIdType* dims = level->GetDimensions();
    EXPECT_GE(std::max({ dims[0], dims[1], dims[2] }), 8);
  }
  pyramid->SetMaximumNumberOfLevels(2);
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_EQ(pyramid->GetNumberOfLevels(), 2);
}

TEST(OFBPyramid, ConstantColourIsKeptAndFinePatternsAverageOut)
{
  SpherePyramid scene;
  vtkOFB* ofb = scene.OFB;
  vtkOFBPyramid* pyramid = scene.Pyramid;
  ASSERT_TRUE(pyramid->UpdateLevels());
  for (int k = 1; k < pyramid->GetNumberOfLevels(); ++k)
  {
    vtkUnsignedCharArray* colors = Colors(pyramid->GetLevel(k));
    ASSERT_NE(colors, nullptr);
    for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); i += 7)
    {
      EXPECT_EQ(colors->GetTypedComponent(i, 1), 200) << "level " << k << " sample " << i;
    }
  }

  // A checker of one-cell squares, black and white: two levels down it is grey.
  const double s = ofb->GetCellSize();
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const long k =
      static_cast<long>(std::floor(x[0] / s) + std::floor(x[1] / s) + std::floor(x[2] / s));
    const unsigned char v = (k % 2 == 0) ? 0 : 255;
    const unsigned char c[4] = { v, v, v, 255 };
    Colors(ofb)->SetTypedTuple(i, c);
  }
  ofb->Modified();
  const vtkMTimeType before = pyramid->GetArraysTime();
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_GT(pyramid->GetArraysTime(), before);
  vtkOFB* coarse = pyramid->GetLevel(2);
  double sum = 0.0;
  double sum2 = 0.0;
  const vtkIdType n = coarse->GetNumberOfSamples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = Colors(coarse)->GetTypedComponent(i, 0);
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  const double stddev = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  EXPECT_NEAR(mean, 127.5, 30.0);
  EXPECT_LT(stddev, 40.0) << "the checker should average out, not alias";

  // Nothing changed: no recomputation.
  const vtkMTimeType after = pyramid->GetArraysTime();
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_EQ(pyramid->GetArraysTime(), after);
}

// A re-convolved LIC (a modified array) filters that array alone: the coarser levels'
// other arrays stay the same objects, and the LIC's coarse values are those of a full
// recomputation.
TEST(OFBPyramid, OnlyModifiedArraysAreFilteredAgain)
{
  SpherePyramid scene;
  vtkOFB* ofb = scene.OFB;
  vtkOFBPyramid* pyramid = scene.Pyramid;
  vtkSmartPointer<vtkFloatArray> lic = scene.AddLIC(0.25f);
  ASSERT_TRUE(pyramid->UpdateLevels());
  const int levels = pyramid->GetNumberOfLevels();
  ASSERT_GE(levels, 3);
  std::vector<vtkDataArray*> colors;
  for (int k = 1; k < levels; ++k)
  {
    colors.push_back(pyramid->GetLevel(k)->GetSampleData()->GetArray("Colors"));
    EXPECT_NEAR(
      pyramid->GetLevel(k)->GetSampleData()->GetArray("LIC")->GetComponent(0, 0), 0.25, 1e-6);
  }
  // A new LIC: the height of each sample.
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    lic->SetValue(i, static_cast<float>(0.5 + 0.5 * x[2]));
  }
  lic->Modified();
  ofb->Modified();
  const vtkMTimeType before = pyramid->GetArraysTime();
  const vtkMTimeType allBefore = pyramid->GetAllArraysTime();
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_GT(pyramid->GetArraysTime(), before);
  EXPECT_EQ(pyramid->GetAllArraysTime(), allBefore) << "not all arrays were filtered again";
  std::vector<std::vector<double>> partial;
  for (int k = 1; k < levels; ++k)
  {
    vtkPointData* pd = pyramid->GetLevel(k)->GetSampleData();
    EXPECT_EQ(pd->GetArray("Colors"), colors[k - 1]) << "level " << k << " filtered again";
    vtkDataArray* coarse = pd->GetArray("LIC");
    partial.emplace_back();
    for (vtkIdType i = 0; i < coarse->GetNumberOfTuples(); ++i)
    {
      partial.back().push_back(coarse->GetComponent(i, 0));
    }
  }
  pyramid->UpdateArrays();
  EXPECT_GT(pyramid->GetAllArraysTime(), allBefore);
  for (int k = 1; k < levels; ++k)
  {
    vtkPointData* pd = pyramid->GetLevel(k)->GetSampleData();
    EXPECT_NE(pd->GetArray("Colors"), colors[k - 1]);
    vtkDataArray* coarse = pd->GetArray("LIC");
    ASSERT_EQ(static_cast<size_t>(coarse->GetNumberOfTuples()), partial[k - 1].size());
    double spread = 0.0;
    for (vtkIdType i = 0; i < coarse->GetNumberOfTuples(); ++i)
    {
      ASSERT_EQ(coarse->GetComponent(i, 0), partial[k - 1][i]) << "level " << k;
      spread = std::max(spread, std::fabs(partial[k - 1][i] - 0.25));
    }
    EXPECT_GT(spread, 0.2) << "level " << k << " kept the old LIC";
  }
}

// An array whose values come back (an animation looping over the same phases) takes its
// levels from the filter cache: the values of a filtering, to the bit; painting in place,
// a full filtering and FilterCacheSize 0 keep nothing.
TEST(OFBPyramid, RepeatedValuesTakeTheirLevelsFromTheCache)
{
  SpherePyramid scene;
  vtkOFB* ofb = scene.OFB;
  vtkOFBPyramid* pyramid = scene.Pyramid;
  vtkSmartPointer<vtkFloatArray> lic = scene.AddLIC(0.0f);
  auto phase = [&](int p)
  {
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      lic->SetValue(i, static_cast<float>(0.5 + 0.5 * std::sin(9.0 * x[2] + p)));
    }
    lic->Modified();
    ofb->Modified();
    EXPECT_TRUE(pyramid->UpdateLevels());
  };
  auto levels = [&]()
  {
    std::vector<std::vector<unsigned char>> all;
    for (int k = 1; k < pyramid->GetNumberOfLevels(); ++k)
    {
      all.push_back(Snapshot(pyramid->GetLevel(k))["LIC"]);
    }
    return all;
  };
  phase(0); // the first filtering, of every array: kept too
  ASSERT_GE(pyramid->GetNumberOfLevels(), 3);
  const auto zero = levels();
  phase(1);
  const auto one = levels();
  phase(2);
  const auto two = levels();
  EXPECT_EQ(pyramid->GetNumberOfFilterCacheHits(), 0);
  EXPECT_NE(one, two);
  phase(1);
  EXPECT_EQ(pyramid->GetNumberOfFilterCacheHits(), 1);
  EXPECT_EQ(levels(), one);
  phase(2);
  EXPECT_EQ(pyramid->GetNumberOfFilterCacheHits(), 2);
  EXPECT_EQ(levels(), two);
  phase(0);
  EXPECT_EQ(pyramid->GetNumberOfFilterCacheHits(), 3);
  EXPECT_EQ(levels(), zero);
  // Painting the whole OFB filters every array again, which drops what was kept: the
  // next phase is filtered again.
  Fill(ofb, 200, 10, 10);
  ASSERT_TRUE(pyramid->UpdateLevels());
  phase(1);
  EXPECT_EQ(pyramid->GetNumberOfFilterCacheHits(), 3);
  EXPECT_EQ(levels(), one);
  // Without a cache nothing is kept.
  pyramid->SetFilterCacheSize(0);
  phase(2);
  phase(1);
  EXPECT_EQ(pyramid->GetNumberOfFilterCacheHits(), 3);
  EXPECT_EQ(levels(), one);
}

// Painting in place (the samples marked modified, the OFB Modified()) filters again only
// the samples of each level that read painted ones, marks them modified on their level,
// and gives the values of a full recomputation (every array, to the bit).
TEST(OFBPyramid, PaintingFiltersOnlyTheSamplesThatReadThePaint)
{
  SpherePyramid scene;
  vtkOFB* ofb = scene.OFB;
  vtkOFBPyramid* pyramid = scene.Pyramid;
  ASSERT_TRUE(pyramid->UpdateLevels());
  const int levels = pyramid->GetNumberOfLevels();
  ASSERT_GE(levels, 4);
  std::vector<std::vector<unsigned char>> before;
  for (int k = 1; k < levels; ++k)
  {
    before.push_back(Snapshot(pyramid->GetLevel(k))["Colors"]);
  }
  const vtkMTimeType arraysBefore = pyramid->GetArraysTime();
  const vtkMTimeType allBefore = pyramid->GetAllArraysTime();

  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetColor(1.0, 0.0, 0.0);
  painter->GetBrush()->SetRadius(0.2);
  ASSERT_GT(painter->Dab(0.0, 0.0, 1.0), 0);
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_GT(pyramid->GetArraysTime(), arraysBefore);
  EXPECT_EQ(pyramid->GetAllArraysTime(), allBefore) << "everything was filtered again";

  std::vector<std::map<std::string, std::vector<unsigned char>>> partial;
  for (int k = 1; k < levels; ++k)
  {
    vtkOFB* level = pyramid->GetLevel(k);
    partial.push_back(Snapshot(level));
    vtkNew<vtkIdTypeArray> ranges;
    level->GetSampleRangesModifiedSince(arraysBefore, ranges);
    vtkIdType marked = 0;
    for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
    {
      marked += ranges->GetTypedComponent(r, 1) - ranges->GetTypedComponent(r, 0);
    }
    EXPECT_GT(marked, 0) << "level " << k;
    if (k <= 2)
    {
      EXPECT_LT(4 * marked, level->GetNumberOfSamples()) << "level " << k;
    }
    // The paint reached the level; nothing unmarked changed.
    const std::vector<unsigned char>& colors = partial.back()["Colors"];
    int reddened = 0;
    for (vtkIdType i = 0; i < level->GetNumberOfSamples(); ++i)
    {
      if (!InRanges(ranges, i))
      {
        ASSERT_EQ(std::memcmp(&colors[4 * i], &before[k - 1][4 * i], 4), 0)
          << "level " << k << " sample " << i << " changed outside the marks";
      }
      reddened += colors[4 * i] > before[k - 1][4 * i] + 20 ? 1 : 0;
    }
    EXPECT_GT(reddened, 0) << "level " << k;
  }
  pyramid->UpdateArrays();
  EXPECT_GT(pyramid->GetAllArraysTime(), allBefore);
  for (int k = 1; k < levels; ++k)
  {
    const auto full = Snapshot(pyramid->GetLevel(k));
    ASSERT_EQ(full.size(), partial[k - 1].size());
    for (const auto& array : full)
    {
      EXPECT_TRUE(array.second == partial[k - 1][array.first])
        << "level " << k << " array " << array.first << " differs from a full filtering";
    }
  }

  // Most of level 0 marked (more than a quarter): everything is filtered again.
  Fill(ofb, 0, 0, 255);
  const vtkMTimeType allAfter = pyramid->GetAllArraysTime();
  ASSERT_TRUE(pyramid->UpdateLevels());
  EXPECT_GT(pyramid->GetAllArraysTime(), allAfter);
  EXPECT_EQ(Snapshot(pyramid->GetLevel(1))["Colors"][2], 255);
}

// A coarse sample with no facing source within the filter radius r reads the closest one
// within 2 r: painting a sample that far from it filters it again too. Level 0's normals
// are flipped within 1.9 r of the level-1 sample T nearest the pole, so that T falls
// back, then the samples 1.9-2 r from T are painted (farther than the neighbourhood of
// the painted samples that is filtered again for the samples that did not fall back).
TEST(OFBPyramid, PaintingNearSamplesThatFellBackFiltersThemToo)
{
  SpherePyramid scene;
  vtkOFB* ofb = scene.OFB;
  vtkOFBPyramid* pyramid = scene.Pyramid;
  ASSERT_TRUE(pyramid->UpdateLevels());
  vtkOFB* level = pyramid->GetLevel(1);
  const double r = std::max(
    pyramid->GetFilterRadius() * level->GetCellSize(), std::sqrt(3.0) * ofb->GetCellSize());
  const double pole[3] = { 0.0, 0.0, 1.0 };
  vtkIdType t = -1;
  double nearest = 1e30;
  double c[3];
  for (vtkIdType i = 0; i < level->GetNumberOfSamples(); ++i)
  {
    double x[3];
    level->GetSamplePosition(i, x);
    if (vtkMath::Distance2BetweenPoints(x, pole) < nearest)
    {
      nearest = vtkMath::Distance2BetweenPoints(x, pole);
      t = i;
      std::copy(x, x + 3, c);
    }
  }
  auto distance = [&](vtkIdType i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    return std::sqrt(vtkMath::Distance2BetweenPoints(x, c));
  };
  vtkDataArray* normals = ofb->GetSampleData()->GetArray("Normals");
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    if (distance(i) < 1.9 * r)
    {
      double n[3];
      normals->GetTuple(i, n);
      normals->SetTuple3(i, -n[0], -n[1], -n[2]);
    }
  }
  ofb->Modified();
  pyramid->UpdateArrays();
  const vtkMTimeType allBefore = pyramid->GetAllArraysTime();
  const unsigned char before = Colors(level)->GetTypedComponent(t, 1);
  const unsigned char purple[4] = { 200, 0, 200, 255 };
  int painted = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const double d = distance(i);
    if (d >= 1.9 * r && d < 2.0 * r)
    {
      Colors(ofb)->SetTypedTuple(i, purple);
      ofb->MarkSamplesModified(i, i + 1);
      ++painted;
    }
  }
  ASSERT_GT(painted, 0);
  ofb->Modified();
  ASSERT_TRUE(pyramid->UpdateLevels());
  ASSERT_EQ(pyramid->GetAllArraysTime(), allBefore) << "everything was filtered again";
  EXPECT_NE(Colors(level)->GetTypedComponent(t, 1), before) << "the sample that fell back";
  const auto partial = Snapshot(level);
  pyramid->UpdateArrays();
  EXPECT_TRUE(Snapshot(pyramid->GetLevel(1))["Colors"] == partial.at("Colors"))
    << "a sample that fell back was not filtered again";
}

TEST(OFBPyramid, ResampleTransfersFloatArrays)
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 32);
  vtkSmartPointer<vtkOFB> fine = vtkofbtest::Build(sphere, 128);
  vtkSmartPointer<vtkOFB> coarse = vtkofbtest::Build(sphere, 48);
  vtkofbtest::AddCoordinateArray(fine, "Height", 2);
  ASSERT_TRUE(vtkOFBPyramid::Resample(fine, coarse, coarse->GetCellSize()));
  vtkDataArray* out = coarse->GetSampleData()->GetArray("Height");
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(out->GetNumberOfTuples(), coarse->GetNumberOfSamples());
  for (vtkIdType i = 0; i < coarse->GetNumberOfSamples(); i += 5)
  {
    double x[3];
    coarse->GetSamplePosition(i, x);
    EXPECT_NEAR(out->GetComponent(i, 0), x[2], 1.5 * coarse->GetCellSize()) << i;
  }
  EXPECT_FALSE(vtkOFBPyramid::Resample(nullptr, coarse, 1.0));
  EXPECT_FALSE(vtkOFBPyramid::Resample(fine, nullptr, 1.0));
  EXPECT_FALSE(vtkOFBPyramid::Resample(fine, coarse, 0.0));
  vtkNew<vtkOFB> empty;
  EXPECT_FALSE(vtkOFBPyramid::Resample(empty, coarse, 1.0));
}

TEST(OFBPyramid, BadInputGivesAnErrorAndNoLevels)
{
  vtkNew<vtkOFBPyramid> pyramid;
  vtkNew<vtkofbtest::MessageObserver> messages;
  messages->Watch(pyramid);
  EXPECT_FALSE(pyramid->UpdateLevels());
  EXPECT_FALSE(messages->Errors.empty());
  EXPECT_EQ(pyramid->GetNumberOfLevels(), 0);
  EXPECT_EQ(pyramid->GetLevel(0), nullptr);
  pyramid->UpdateModifiedArrays(); // no input, no levels: nothing to filter
  pyramid->UpdateArrays();
  EXPECT_EQ(pyramid->GetNumberOfLevels(), 0);

  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 16);
  vtkSmartPointer<vtkOFB> ofb = vtkofbtest::Build(sphere, 64);
  pyramid->SetInputOFB(ofb);
  messages->Clear();
  EXPECT_FALSE(pyramid->UpdateLevels()); // no surface
  EXPECT_NE(messages->Errors.find("surface"), std::string::npos) << messages->Errors;
  EXPECT_EQ(pyramid->GetNumberOfLevels(), 1);

  vtkNew<vtkOFB> empty;
  pyramid->SetInputOFB(empty);
  pyramid->SetSurface(sphere);
  messages->Clear();
  EXPECT_FALSE(pyramid->UpdateLevels());
  EXPECT_FALSE(messages->Errors.empty());
}

TEST(OFBPyramid, PrintSelfShowsEverySetting)
{
  vtkNew<vtkOFBPyramid> pyramid;
  pyramid->SetMaximumNumberOfLevels(40);
  EXPECT_EQ(pyramid->GetMaximumNumberOfLevels(), 16);
  std::ostringstream os;
  pyramid->Print(os);
  for (const char* name : { "InputOFB",
         "Surface",
         "MaximumNumberOfLevels: 16",
         "MinimumResolution",
         "FilterRadius",
         "NumberOfLevels",
         "FilterCacheSize" })
  {
    EXPECT_NE(os.str().find(name), std::string::npos) << name;
  }
}
