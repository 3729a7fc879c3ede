// Queries, copies and the point-cloud converter of vtkOFB.
#include "vtkOFBTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBToPolyData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

using namespace vtkofbtest;

namespace
{
vtkSmartPointer<vtkOFB> BunnyOFB(int resolution)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  return bunny ? Build(bunny, resolution) : nullptr;
}
}

//------------------------------------------------------------------------------
TEST(Queries, EmptyOFBAnswersNothing)
{
  vtkNew<vtkOFB> ofb;
  const double x[3] = { 0, 0, 0 }, n[3] = { 0, 0, 1 };
  double y[3];
  EXPECT_EQ(ofb->GetNumberOfSamples(), 0);
  EXPECT_EQ(ofb->FindSample(x, n), -1);
  EXPECT_EQ(ofb->FindClosestSample(x), -1);
  EXPECT_EQ(ofb->FindClosestSample(x, 1e9), -1);
  EXPECT_FALSE(ofb->GetSamplePosition(0, y));
  EXPECT_EQ(ofb->GetSampleAxis(0), -1);
  EXPECT_EQ(ofb->GetDepthComplexity(), 0);
  vtkNew<vtkIdList> ids;
  ids->InsertNextId(7);
  ofb->FindSamplesInSphere(x, 1e9, ids);
  EXPECT_EQ(ids->GetNumberOfIds(), 0);
  int calls = 0;
  for (vtkIdType n : { vtkIdType(-1), vtkIdType(3) })
  {
    ofb->ForEachSampleInSpheres(
      n,
      [&](vtkIdType, double c[3], double& r)
      {
        c[0] = c[1] = c[2] = 0.0;
        r = 1e9;
        ++calls;
      },
      [&](vtkIdType, vtkIdType, double) { ++calls; },
      [&](vtkIdType, vtkIdType) { ++calls; });
  }
  EXPECT_EQ(calls, 0) << "an empty OFB or a negative count asks and offers nothing";
  std::ostringstream os;
  ofb->Print(os);
  EXPECT_NE(os.str().find("NumberOfSamples: 0"), std::string::npos);
}

//------------------------------------------------------------------------------
TEST(Queries, SphereQueryMatchesBruteForce)
{
  vtkSmartPointer<vtkOFB> ofb = BunnyOFB(256);
  ASSERT_NE(ofb, nullptr);
  const vtkIdType n = ofb->GetNumberOfSamples();
  std::vector<double> positions(3 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ASSERT_TRUE(ofb->GetSamplePosition(i, &positions[3 * i]));
  }
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkIdList> ids;
  for (int q = 0; q < 20; ++q)
  {
    // Centre on a random sample, radius 0.5 to 8 cells.
    random->Next();
    const vtkIdType c = static_cast<vtkIdType>(random->GetValue() * (n - 1));
    random->Next();
    const double radius = (0.5 + 7.5 * random->GetValue()) * ofb->GetCellSize();
    const double* center = &positions[3 * c];
    std::set<vtkIdType> expected;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (vtkMath::Distance2BetweenPoints(center, &positions[3 * i]) <= radius * radius)
      {
        expected.insert(i);
      }
    }
    ofb->FindSamplesInSphere(center, radius, ids);
    std::set<vtkIdType> found(ids->begin(), ids->end());
    EXPECT_EQ(found.size(), static_cast<size_t>(ids->GetNumberOfIds())) << "no id twice";
    EXPECT_EQ(found, expected) << "query " << q;
    EXPECT_TRUE(found.count(c));
    // The closest sample to a sample is itself.
    EXPECT_EQ(ofb->FindClosestSample(center), c);
  }
}

//------------------------------------------------------------------------------
TEST(Queries, ManySpheresMatchOneByOne)
{
  // ForEachSampleInSpheres gives each sphere's samples with their squared distances
  // in the order of ForEachSampleInSphere, spheres in order: small spheres (the
  // pipelined path), spheres of more rows than a plan holds, a NaN radius, spheres
  // off the grid, and runs of 0, 1 and 2 spheres.
  vtkSmartPointer<vtkOFB> ofb = BunnyOFB(256);
  ASSERT_NE(ofb, nullptr);
  const double s = ofb->GetCellSize();
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  std::vector<double> centers;
  std::vector<double> radii;
  for (int q = 0; q < 300; ++q)
  {
    double x[3];
    random->Next();
    ofb->GetSamplePosition(
      static_cast<vtkIdType>(random->GetValue() * (ofb->GetNumberOfSamples() - 1)), x);
    random->Next();
    double r = (0.3 + 4.0 * random->GetValue()) * s;
    if (q % 50 == 7)
    {
      r = 30.0 * s; // more rows than a plan holds: queried alone
    }
    else if (q % 50 == 13)
    {
      r = std::nan("");
    }
    else if (q % 50 == 29)
    {
      x[0] += 1e3 * s; // off the grid
    }
    centers.insert(centers.end(), x, x + 3);
    radii.push_back(r);
  }
  struct Hit
  {
    vtkIdType Sphere, Id;
    double D2;
    bool operator==(const Hit& o) const
    {
      return this->Sphere == o.Sphere && this->Id == o.Id && this->D2 == o.D2;
    }
  };
  for (vtkIdType count : { vtkIdType(0), vtkIdType(1), vtkIdType(2), vtkIdType(300) })
  {
    std::vector<Hit> expected, found;
    for (vtkIdType k = 0; k < count; ++k)
    {
      ofb->ForEachSampleInSphere(&centers[3 * k],
        radii[k],
        [&](vtkIdType i, double d2) {
          expected.push_back({ k, i, d2 });
        });
    }
    vtkIdType prefetched = 0;
    ofb->ForEachSampleInSpheres(
      count,
      [&](vtkIdType k, double c[3], double& r)
      {
        std::copy_n(&centers[3 * k], 3, c);
        r = radii[k];
      },
      [&](vtkIdType k, vtkIdType i, double d2) {
        found.push_back({ k, i, d2 });
      },
      [&](vtkIdType first, vtkIdType last)
      {
        EXPECT_LE(0, first);
        EXPECT_LT(first, last);
        EXPECT_LE(last, ofb->GetNumberOfSamples());
        ++prefetched;
      });
    EXPECT_TRUE(found == expected)
      << count << " spheres: " << found.size() << " hits, " << expected.size() << " one by one";
    EXPECT_EQ(prefetched > 0, count > 0);
  }
}

//------------------------------------------------------------------------------
TEST(Queries, FindSampleUsesTheGridOfTheNormal)
{
  vtkSmartPointer<vtkOFB> ofb = BunnyOFB(256);
  ASSERT_NE(ofb, nullptr);
  vtkDataArray* normals = ofb->GetSampleData()->GetNormals();
  int wrong = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); i += 97)
  {
    double x[3], nrm[3];
    ofb->GetSamplePosition(i, x);
    // The grid's own axis as the normal: the sample itself must come back.
    nrm[0] = nrm[1] = nrm[2] = 0.0;
    nrm[ofb->GetSampleAxis(i)] = 1.0;
    wrong += ofb->FindSample(x, nrm) != i;
    // Moved by a third of a cell along the axis: still found, it is within s.
    x[ofb->GetSampleAxis(i)] += ofb->GetCellSize() / 3.0;
    const vtkIdType j = ofb->FindSample(x, nrm);
    wrong += j < 0 || ofb->GetSampleAxis(j) != ofb->GetSampleAxis(i);
    (void)normals;
  }
  EXPECT_EQ(wrong, 0);
  // Far from the surface: nothing within one cell.
  double bounds[6];
  ofb->GetBounds(bounds);
  const double outside[3] = { bounds[1] + 10.0, bounds[3] + 10.0, bounds[5] + 10.0 };
  const double up[3] = { 0, 0, 1 };
  EXPECT_EQ(ofb->FindSample(outside, up), -1);
  EXPECT_EQ(ofb->FindClosestSample(outside), -1);
  const double nan[3] = { std::nan(""), 0, 0 };
  EXPECT_EQ(ofb->FindClosestSample(nan), -1);
  EXPECT_EQ(ofb->FindSample(nan, up), -1);
}

//------------------------------------------------------------------------------
TEST(Queries, ShallowAndDeepCopies)
{
  vtkSmartPointer<vtkOFB> ofb = BunnyOFB(128);
  ASSERT_NE(ofb, nullptr);
  vtkNew<vtkOFB> shallow;
  shallow->ShallowCopy(ofb);
  vtkNew<vtkOFB> deep;
  deep->DeepCopy(ofb);
  EXPECT_EQ(shallow->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  EXPECT_EQ(deep->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  EXPECT_EQ(shallow->GetDepths(), ofb->GetDepths());
  EXPECT_NE(deep->GetDepths(), ofb->GetDepths());
  EXPECT_EQ(deep->GetDepthComplexity(), ofb->GetDepthComplexity());
  // Painting the deep copy leaves the original alone; the shallow copy shares it.
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetScalars());
  auto* deepColors = vtkUnsignedCharArray::SafeDownCast(deep->GetSampleData()->GetScalars());
  auto* shallowColors = vtkUnsignedCharArray::SafeDownCast(shallow->GetSampleData()->GetScalars());
  ASSERT_NE(colors, nullptr);
  deepColors->SetValue(0, 17);
  EXPECT_EQ(colors->GetValue(0), 255);
  shallowColors->SetValue(0, 42);
  EXPECT_EQ(colors->GetValue(0), 42);
  // Memory: at least depth, cell index, colours and normals per sample.
  EXPECT_GT(ofb->GetBytesPerSample(), 24.0);
  EXPECT_GT(ofb->GetActualMemorySize(), 0u);
  // A copy from something that is not an OFB is refused.
  vtkNew<vtkPolyData> poly;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(deep);
  deep->ShallowCopy(poly);
  EXPECT_NE(observer->Errors.find("not a vtkOFB"), std::string::npos);
  EXPECT_EQ(deep->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  observer->Delete();
}

//------------------------------------------------------------------------------
TEST(Queries, PointCloudCarriesEveryArray)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(bunny);
  sampler->SetResolution(128);
  vtkNew<vtkOFBToPolyData> cloud;
  cloud->SetInputConnection(sampler->GetOutputPort());
  cloud->GenerateCellIdsOn();
  cloud->Update();
  vtkOFB* ofb = sampler->GetOutput();
  vtkPolyData* out = cloud->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), ofb->GetNumberOfSamples());
  EXPECT_EQ(out->GetNumberOfVerts(), ofb->GetNumberOfSamples());
  for (int i = 0; i < ofb->GetSampleData()->GetNumberOfArrays(); ++i)
  {
    EXPECT_NE(out->GetPointData()->GetArray(ofb->GetSampleData()->GetArrayName(i)), nullptr);
  }
  vtkDataArray* axis = out->GetPointData()->GetArray("GridAxis");
  ASSERT_NE(axis, nullptr);
  ASSERT_NE(out->GetPointData()->GetArray("CellIndex"), nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); i += 13)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    double* y = out->GetPoint(i);
    EXPECT_DOUBLE_EQ(x[0], y[0]);
    EXPECT_DOUBLE_EQ(x[2], y[2]);
    EXPECT_EQ(static_cast<int>(axis->GetTuple1(i)), ofb->GetSampleAxis(i));
  }
}

//------------------------------------------------------------------------------
TEST(Queries, ModifiedRangesTrackOnlyWhatChanged)
{
  vtkSmartPointer<vtkOFB> ofb = BunnyOFB(128);
  ASSERT_NE(ofb, nullptr);
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkIdTypeArray> ranges;
  // A consumer that never uploaded gets everything.
  ofb->GetSampleRangesModifiedSince(0, ranges);
  ASSERT_EQ(ranges->GetNumberOfTuples(), 1);
  EXPECT_EQ(ranges->GetValue(0), 0);
  EXPECT_EQ(ranges->GetValue(1), n);
  // After an upload at time t, only the marked ranges, merged and clipped.
  vtkTimeStamp upload;
  upload.Modified();
  const vtkMTimeType t = upload.GetMTime();
  ofb->GetSampleRangesModifiedSince(t, ranges);
  EXPECT_EQ(ranges->GetNumberOfTuples(), 0);
  ofb->MarkSamplesModified(100, 150);
  ofb->MarkSamplesModified(140, 200);
  ofb->MarkSamplesModified(1000, 1100);
  ofb->MarkSamplesModified(n - 10, n + 50);
  ofb->MarkSamplesModified(-5, -1); // nothing
  ofb->GetSampleRangesModifiedSince(t, ranges);
  ASSERT_EQ(ranges->GetNumberOfTuples(), 3);
  EXPECT_EQ(ranges->GetValue(0), 100);
  EXPECT_EQ(ranges->GetValue(1), 200);
  EXPECT_EQ(ranges->GetValue(2), 1000);
  EXPECT_EQ(ranges->GetValue(3), 1100);
  EXPECT_EQ(ranges->GetValue(4), n - 10);
  EXPECT_EQ(ranges->GetValue(5), n);
  // Many small marks stay bounded and still cover every marked sample.
  vtkTimeStamp second;
  second.Modified();
  for (vtkIdType i = 0; i < 1000; ++i)
  {
    ofb->MarkSamplesModified(7 * i, 7 * i + 1);
  }
  ofb->GetSampleRangesModifiedSince(second.GetMTime(), ranges);
  vtkIdType covered = 0;
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    for (vtkIdType i = 0; i < 1000; ++i)
    {
      covered += 7 * i >= ranges->GetValue(2 * r) && 7 * i < ranges->GetValue(2 * r + 1);
    }
  }
  EXPECT_EQ(covered, 1000);
  EXPECT_LE(ranges->GetNumberOfTuples(), 257);
  // Scattered strokes (10 clusters of 100 dabs) stay far smaller than the whole.
  vtkNew<vtkOFB> painted;
  painted->DeepCopy(ofb);
  vtkTimeStamp strokes;
  strokes.Modified();
  for (vtkIdType c = 0; c < 10; ++c)
  {
    for (vtkIdType i = 0; i < 100; ++i)
    {
      const vtkIdType first = c * (n / 10) + 3 * i;
      painted->MarkSamplesModified(first, first + 2);
    }
  }
  painted->GetSampleRangesModifiedSince(strokes.GetMTime(), ranges);
  vtkIdType length = 0;
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    length += ranges->GetValue(2 * r + 1) - ranges->GetValue(2 * r);
  }
  EXPECT_GE(length, 2000);
  EXPECT_LT(length, n / 10) << "merging must not grow to the whole OFB";
  // A rebuild (reallocation) invalidates everything again.
  vtkNew<vtkOFB> copy;
  copy->DeepCopy(ofb);
  vtkTimeStamp third;
  third.Modified();
  copy->GetSampleRangesModifiedSince(third.GetMTime(), ranges);
  EXPECT_EQ(ranges->GetNumberOfTuples(), 0);
  copy->Initialize();
  copy->GetSampleRangesModifiedSince(third.GetMTime(), ranges);
  EXPECT_EQ(ranges->GetNumberOfTuples(), 0) << "an empty OFB has nothing to upload";
}

//------------------------------------------------------------------------------
TEST(Queries, PointCloudOfAnEmptyOFBIsEmpty)
{
  vtkNew<vtkOFB> empty;
  vtkNew<vtkOFBToPolyData> cloud;
  cloud->SetInputData(empty);
  cloud->Update();
  EXPECT_EQ(cloud->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(cloud->GetOutput()->GetNumberOfVerts(), 0);
  // A polydata is not an OFB: the pipeline refuses it, no crash, empty output.
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkOFBToPolyData> wrong;
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(wrong);
  wrong->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  wrong->SetInputData(poly);
  wrong->Update();
  EXPECT_FALSE(observer->Errors.empty());
  EXPECT_EQ(wrong->GetOutput()->GetNumberOfPoints(), 0);
  observer->Delete();
}

//------------------------------------------------------------------------------
TEST(Queries, AxisAndSampleIndicesOutOfRangeAnswerNothing)
{
  // The per-grid accessors with an axis outside 0..3 (GetGridCellBase read past its
  // array), and positions of samples that do not exist.
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 16), 32);
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 0);
  EXPECT_EQ(ofb->GetGridCellBase(3), ofb->GetNumberOfCells());
  for (int axis : { -1, 4, 9, 1000 })
  {
    EXPECT_EQ(ofb->GetGridCellBase(axis), 0) << axis;
    EXPECT_EQ(ofb->GetGridFirstSample(axis), 0) << axis;
    EXPECT_EQ(ofb->GetNumberOfSamples(axis), 0) << axis;
  }
  double x[3] = { 7.0, 7.0, 7.0 };
  for (vtkIdType i : { vtkIdType(-1), n, n + 5 })
  {
    EXPECT_FALSE(ofb->GetSamplePosition(i, x)) << i;
  }
}

//------------------------------------------------------------------------------
TEST(Queries, PointCloudLeavesOutSampleArraysOfAnotherLength)
{
  // A sample array of 3 tuples would be a point array shorter than the cloud's points.
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 16), 32);
  vtkNew<vtkFloatArray> shortArray;
  shortArray->SetName("Short");
  shortArray->SetNumberOfTuples(3);
  ofb->GetSampleData()->AddArray(shortArray);
  vtkNew<vtkOFBToPolyData> cloud;
  vtkNew<MessageObserver> observer;
  observer->Watch(cloud);
  cloud->SetInputData(ofb);
  cloud->Update();
  vtkPolyData* out = cloud->GetOutput();
  EXPECT_EQ(out->GetNumberOfPoints(), ofb->GetNumberOfSamples());
  EXPECT_EQ(out->GetPointData()->GetArray("Short"), nullptr);
  EXPECT_NE(observer->Warnings.find("'Short'"), std::string::npos) << observer->Warnings;
  EXPECT_NE(out->GetPointData()->GetArray("Colors"), nullptr); // the others are kept
  EXPECT_NE(ofb->GetSampleData()->GetArray("Short"), nullptr); // the input is untouched
}

//------------------------------------------------------------------------------
TEST(Queries, CellIndexIsRebuiltAlikeByManyThreads)
{
  // A frame of about 800 thousand cells: a dozen chunks of the SMP loop.
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 64), 512);
  ASSERT_GE(ofb->GetNumberOfCells(), 12 * 65536);
  vtkTypeUInt32Array* index = ofb->GetCellIndex();
  const vtkTypeUInt32* first = index->GetPointer(0);
  const std::vector<vtkTypeUInt32> expected(first, first + index->GetNumberOfValues());
  vtkTypeUInt32* offsets = ofb->GetCellOffsets()->GetPointer(0);
  vtkNew<MessageObserver> observer;
  observer->Watch(ofb);
  for (int threads : { 1, 2, 7, 16, 64 })
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config(threads),
      [&]()
      {
        // Valid offsets: the same index as the builder's, from every thread count.
        std::fill(index->GetPointer(0), index->GetPointer(0) + expected.size(), 0xFFFFFFFFu);
        EXPECT_TRUE(ofb->BuildCellIndex());
        EXPECT_TRUE(std::equal(expected.begin(), expected.end(), index->GetPointer(0)))
          << threads << " threads";
        // One decreasing offset in a late chunk, met by whichever thread takes it.
        const vtkIdType cell = ofb->GetNumberOfCells() - 3 * 65536 + threads;
        const vtkTypeUInt32 kept = offsets[cell];
        offsets[cell] = offsets[cell + 1] + 1;
        EXPECT_FALSE(ofb->BuildCellIndex()) << threads << " threads";
        offsets[cell] = kept;
        EXPECT_TRUE(ofb->BuildCellIndex()) << threads << " threads";
      });
  }
  EXPECT_NE(observer->Errors.find("decrease"), std::string::npos) << observer->Errors;
}

//------------------------------------------------------------------------------
TEST(Queries, HugeAndInfiniteRadiiReachEverySample)
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 16), 24);
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 100);
  const double inf = std::numeric_limits<double>::infinity();
  const double centers[][3] = { { 0.0, 0.0, 0.0 }, { 1e3, -2e3, 5.0 }, { -1e15, 0.0, 1e15 } };
  vtkNew<vtkIdList> ids;
  for (const double* c : centers)
  {
    // The sample closest to c, by brute force.
    double best = inf;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      best = std::min(best, vtkMath::Distance2BetweenPoints(x, c));
    }
    for (double radius : { 1e6, 1e17, 1e19, 1e300, std::numeric_limits<double>::max(), inf })
    {
      if (std::sqrt(best) > radius)
      {
        continue;
      }
      ofb->FindSamplesInSphere(c, radius, ids);
      EXPECT_EQ(ids->GetNumberOfIds(), n) << "radius " << radius;
      const vtkIdType closest = ofb->FindClosestSample(c, radius);
      ASSERT_GE(closest, 0) << "radius " << radius;
      double x[3];
      ofb->GetSamplePosition(closest, x);
      EXPECT_NEAR(vtkMath::Distance2BetweenPoints(x, c), best, 1e-9 * best) << "radius " << radius;
    }
  }
  // A NaN radius finds nothing.
  ofb->FindSamplesInSphere(centers[0], std::nan(""), ids);
  EXPECT_EQ(ids->GetNumberOfIds(), 0);
  EXPECT_EQ(ofb->FindClosestSample(centers[0], std::nan("")), -1);
}
