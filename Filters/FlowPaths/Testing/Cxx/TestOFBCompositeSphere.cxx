// A sphere cut into four patches (a vtkMultiBlockDataSet, by the signs of x and y of the
// cell centres) with a rotation about z across the cuts: its OFB is the uncut sphere's,
// and LIC, particles and a paint stroke cross the cuts with no seam.
#include "vtkOFBLICTestHelpers.h"
#include "vtkOFBParticleTestUtilities.h"
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkOFBBrush.h"
#include "vtkOFBLIC.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkOFBPainter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vtkofbtest;

namespace
{
const double ZAxis[3] = { 0.0, 0.0, 1.0 };
constexpr int Resolution = 128;

/// The patch of a point: 0..3 from the signs of x and y.
int Patch(const double x[3])
{
  return Quadrant(x);
}

/// The sphere with the rotation about z as its point vectors "Flow".
vtkSmartPointer<vtkPolyData> FlowSphere()
{
  return WithField(MakeSphere(1.0, 64), RotationField(ZAxis));
}

/// `sphere` cut into four polydata blocks by the signs of x and y of its cell centres.
vtkSmartPointer<vtkMultiBlockDataSet> CutSphere(vtkPolyData* sphere)
{
  return CutIntoQuadrants(sphere);
}

vtkSmartPointer<vtkOFB> Sample(vtkDataObject* input)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(input);
  sampler->SetResolution(Resolution);
  sampler->Update();
  vtkSmartPointer<vtkOFB> ofb = sampler->GetOutput();
  return ofb;
}

/// The LIC of `ofb` (its "Flow").
vtkSmartPointer<vtkOFB> LIC(vtkOFB* ofb)
{
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->Update();
  vtkSmartPointer<vtkOFB> out = vtkSmartPointer<vtkOFB>::New();
  out->ShallowCopy(lic->GetOutput());
  return out;
}

/// Distance of x to the nearest cut (the planes x = 0 and y = 0), in cells.
double CellsToCut(vtkOFB* ofb, const double x[3])
{
  return std::min(std::fabs(x[0]), std::fabs(x[1])) / ofb->GetCellSize();
}

/// The downstream-difference measure over the samples of a band along the cuts.
struct Downstream
{
  double Crossing = 0.0; ///< mean over the pairs on both sides of a cut
  double Inside = 0.0;   ///< mean over the pairs inside one patch
  vtkIdType CrossingPairs = 0;
  vtkIdType InsidePairs = 0;
};

/**
 * |L(x) - L(y)|, y the sample closest to 2 cells downstream of x, over the samples x
 * within 60 degrees of the equator and 3 cells of a cut: the mean over the pairs that
 * cross a cut, and over those inside one patch (the same band, so the same geometry).
 */
Downstream CutDownstreamDifference(vtkOFB* ofb)
{
  Downstream m;
  auto* lic = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("LIC"));
  EXPECT_NE(lic, nullptr);
  for (vtkIdType i = 0; lic && i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3], along[3];
    ofb->GetSamplePosition(i, x);
    if (std::fabs(x[2]) > std::sin(vtkMath::RadiansFromDegrees(60.0)) || CellsToCut(ofb, x) > 3.0)
    {
      continue;
    }
    vtkMath::Cross(ZAxis, x, along);
    vtkMath::Normalize(along);
    double y[3];
    for (int k = 0; k < 3; ++k)
    {
      y[k] = x[k] + 2.0 * ofb->GetCellSize() * along[k];
    }
    const vtkIdType j = ofb->FindClosestSample(y);
    if (j < 0)
    {
      continue;
    }
    ofb->GetSamplePosition(j, y);
    const double d = std::fabs(lic->GetValue(i) - lic->GetValue(j));
    if (Patch(x) != Patch(y))
    {
      m.Crossing += d;
      ++m.CrossingPairs;
    }
    else
    {
      m.Inside += d;
      ++m.InsidePairs;
    }
  }
  m.Crossing /= std::max<vtkIdType>(1, m.CrossingPairs);
  m.Inside /= std::max<vtkIdType>(1, m.InsidePairs);
  return m;
}

/// Seeds on the sphere at latitudes from -60 to 60 degrees, next to the cuts.
vtkSmartPointer<vtkPolyData> Seeds()
{
  std::vector<std::array<double, 3>> xs;
  for (int i = 0; i < 40; ++i)
  {
    const double lat = vtkMath::RadiansFromDegrees(-60.0 + 120.0 * (i + 0.5) / 40);
    const double lon = vtkMath::RadiansFromDegrees(90.0 * (i % 4) - 3.0 - 0.1 * i);
    xs.push_back({ std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat) });
  }
  return MakeSeeds(xs);
}

/// The particles' positions after `steps` steps on `surface`.
vtkSmartPointer<vtkPoints> Advect(vtkPolyData* surface, int steps, double& cellSize)
{
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(surface);
  advector->SetSeeds(Seeds());
  advector->SetStepsPerUpdate(steps);
  advector->Update();
  advector->Step();
  cellSize = advector->GetCellSize();
  auto end = vtkSmartPointer<vtkPoints>::New();
  end->SetDataTypeToDouble();
  end->DeepCopy(advector->GetParticles()->GetPoints());
  return end;
}

/// Paint a stroke along the equator from longitude -12 to 12 degrees (across the cut y = 0).
void PaintStroke(vtkOFB* ofb)
{
  vtkNew<vtkOFBBrush> brush;
  brush->SetRadiusInCells(3.0, ofb);
  brush->SetColor(1.0, 0.0, 0.0);
  brush->SetFalloffToConstant();
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->SetBrush(brush);
  painter->BeginStroke();
  for (int k = -12; k <= 12; ++k)
  {
    const double a = vtkMath::RadiansFromDegrees(static_cast<double>(k));
    painter->StrokeTo(std::cos(a), std::sin(a), 0.0);
  }
  painter->EndStroke();
}

bool IsPainted(vtkUnsignedCharArray* colors, vtkIdType i)
{
  return colors->GetValue(4 * i + 1) < 128; // white, red where painted
}
}

TEST(CompositeSphere, TheFourPatchesGiveTheUncutSpheresSamples)
{
  vtkSmartPointer<vtkPolyData> sphere = FlowSphere();
  vtkSmartPointer<vtkOFB> whole = Sample(sphere);
  vtkSmartPointer<vtkOFB> cut = Sample(CutSphere(sphere));
  ASSERT_GT(whole->GetNumberOfSamples(), 10000);
  ASSERT_EQ(cut->GetNumberOfSamples(), whole->GetNumberOfSamples());
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(cut->GetOrigin()[a], whole->GetOrigin()[a]);
  }
  EXPECT_EQ(cut->GetCellSize(), whole->GetCellSize());
  vtkDataArray* flowA = whole->GetSampleData()->GetVectors();
  vtkDataArray* flowB = cut->GetSampleData()->GetVectors();
  vtkDataArray* normalsA = whole->GetSampleData()->GetNormals();
  vtkDataArray* normalsB = cut->GetSampleData()->GetNormals();
  auto* block = vtkIntArray::SafeDownCast(cut->GetSampleData()->GetArray("BlockIndex"));
  ASSERT_TRUE(flowA && flowB && normalsA && normalsB && block);
  double worstPosition = 0.0, worstFlow = 0.0, worstNormal = 0.0;
  vtkIdType wrongBlock = 0;
  for (vtkIdType i = 0; i < whole->GetNumberOfSamples(); ++i)
  {
    double a[3], b[3];
    whole->GetSamplePosition(i, a);
    cut->GetSamplePosition(i, b);
    worstPosition = std::max(worstPosition, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
    // Away from the cuts, the block index is the patch's flat index (patch + 1).
    if (CellsToCut(cut, b) > 0.5 && block->GetValue(i) != Patch(b) + 1)
    {
      ++wrongBlock;
    }
    flowA->GetTuple(i, a);
    flowB->GetTuple(i, b);
    worstFlow = std::max(worstFlow, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
    normalsA->GetTuple(i, a);
    normalsB->GetTuple(i, b);
    worstNormal = std::max(worstNormal, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
  }
  EXPECT_LE(worstPosition, 1e-6 * whole->GetCellSize());
  EXPECT_LE(worstFlow, 1e-6);
  EXPECT_LE(worstNormal, 1e-6);
  EXPECT_EQ(wrongBlock, 0);
}

TEST(CompositeSphere, LICCrossesTheCutsWithNoSeam)
{
  vtkSmartPointer<vtkPolyData> sphere = FlowSphere();
  vtkSmartPointer<vtkOFB> whole = LIC(Sample(sphere));
  vtkSmartPointer<vtkOFB> cut = LIC(Sample(CutSphere(sphere)));
  // Pairs across a cut differ downstream as the pairs inside a patch in the same band
  // (a seam would show as a larger difference across),
  // and exactly as the same pairs of the uncut sphere.
  const Downstream m = CutDownstreamDifference(cut);
  const Downstream uncut = CutDownstreamDifference(whole);
  std::cout << "downstream difference: across a cut " << m.Crossing << " (" << m.CrossingPairs
            << " pairs), inside a patch " << m.Inside << " (" << m.InsidePairs
            << "), the same pairs on the uncut sphere " << uncut.Crossing << "\n";
  ASSERT_GT(m.CrossingPairs, 500);
  ASSERT_GT(m.InsidePairs, 1000);
  EXPECT_GT(m.Inside, 0.0);
  EXPECT_LT(m.Crossing, 1.3 * m.Inside);
  EXPECT_GT(m.Crossing, 0.7 * m.Inside);
  EXPECT_EQ(m.CrossingPairs, uncut.CrossingPairs);
  EXPECT_NEAR(m.Crossing, uncut.Crossing, 1e-6);
  // And the LIC is the uncut sphere's.
  auto* a = vtkFloatArray::SafeDownCast(whole->GetSampleData()->GetArray("LIC"));
  auto* b = vtkFloatArray::SafeDownCast(cut->GetSampleData()->GetArray("LIC"));
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    worst = std::max(worst, static_cast<double>(std::fabs(a->GetValue(i) - b->GetValue(i))));
  }
  EXPECT_LE(worst, 1e-5);
}

TEST(CompositeSphere, ParticlesCrossTheCutsAsOnTheUncutSphere)
{
  vtkSmartPointer<vtkPolyData> sphere = FlowSphere();
  vtkNew<vtkOFBMergeBlocks> merge;
  merge->SetInputData(CutSphere(sphere));
  merge->Update();
  EXPECT_EQ(merge->GetOutput()->GetNumberOfPoints(), sphere->GetNumberOfPoints());
  double cellWhole = 0.0, cellCut = 0.0;
  vtkSmartPointer<vtkPoints> a = Advect(sphere, 150, cellWhole);
  vtkSmartPointer<vtkPoints> b = Advect(merge->GetOutput(), 150, cellCut);
  EXPECT_EQ(cellWhole, cellCut);
  ASSERT_EQ(a->GetNumberOfPoints(), 40);
  ASSERT_EQ(b->GetNumberOfPoints(), 40);
  double worst = 0.0;
  int crossed = 0;
  vtkSmartPointer<vtkPolyData> seeds = Seeds();
  for (vtkIdType i = 0; i < 40; ++i)
  {
    double p[3], q[3], s[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    seeds->GetPoint(i, s);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)) / cellWhole);
    crossed += Patch(p) != Patch(s);
  }
  std::cout << "largest end point difference " << worst << " cells; " << crossed
            << " particles of 40 crossed a cut\n";
  EXPECT_LE(worst, 1e-3);
  EXPECT_GE(crossed, 30);
}

TEST(CompositeSphere, PaintStrokeCrossesTheCut)
{
  vtkSmartPointer<vtkPolyData> sphere = FlowSphere();
  vtkSmartPointer<vtkOFB> whole = Sample(sphere);
  vtkSmartPointer<vtkOFB> cut = Sample(CutSphere(sphere));
  ASSERT_EQ(cut->GetNumberOfSamples(), whole->GetNumberOfSamples());
  PaintStroke(whole);
  PaintStroke(cut);
  auto* a = vtkUnsignedCharArray::SafeDownCast(whole->GetSampleData()->GetArray("Colors"));
  auto* b = vtkUnsignedCharArray::SafeDownCast(cut->GetSampleData()->GetArray("Colors"));
  ASSERT_TRUE(a && b);
  vtkIdType differ = 0, below = 0, above = 0, gaps = 0;
  for (vtkIdType i = 0; i < cut->GetNumberOfSamples(); ++i)
  {
    differ += IsPainted(a, i) != IsPainted(b, i);
    double x[3];
    cut->GetSamplePosition(i, x);
    if (IsPainted(b, i))
    {
      below += x[1] < 0.0;
      above += x[1] >= 0.0;
    }
    // On the stroke's path across the cut (within a cell of the equator and of y = 0)
    // every sample is painted.
    if (x[0] > 0.0 && std::fabs(x[2]) < cut->GetCellSize() &&
      std::fabs(x[1]) < cut->GetCellSize() && !IsPainted(b, i))
    {
      ++gaps;
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(below, 50);
  EXPECT_GT(above, 50);
  EXPECT_EQ(gaps, 0);

  // A block painted alone: the samples of block 3 (x < 0, y >= 0) through their indices.
  auto* block = vtkIntArray::SafeDownCast(cut->GetSampleData()->GetArray("BlockIndex"));
  ASSERT_NE(block, nullptr);
  vtkNew<vtkIdTypeArray> ids;
  vtkNew<vtkUnsignedCharArray> blue;
  blue->SetNumberOfComponents(4);
  for (vtkIdType i = 0; i < cut->GetNumberOfSamples(); ++i)
  {
    if (block->GetValue(i) == 3)
    {
      ids->InsertNextValue(i);
      const unsigned char c[4] = { 0, 0, 255, 255 };
      blue->InsertNextTypedTuple(c);
    }
  }
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(cut);
  EXPECT_EQ(painter->SetSampleColors(ids, blue), ids->GetNumberOfValues());
  vtkIdType wrong = 0;
  for (vtkIdType i = 0; i < cut->GetNumberOfSamples(); ++i)
  {
    const bool isBlue = b->GetValue(4 * i + 2) == 255 && b->GetValue(4 * i) == 0;
    wrong += isBlue != (block->GetValue(i) == 3);
  }
  EXPECT_EQ(wrong, 0);
}
