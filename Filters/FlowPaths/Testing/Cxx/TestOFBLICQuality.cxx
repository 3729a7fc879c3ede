// GoogleTest units of vtkOFBLIC's quality: the default LIC (streamlines kept for
// re-convolution) against the LIC of streamlines traced from every sample, on the pipe
// with a bump, a sphere and a bundled mesh: how closely it follows it, and no dashes
// along the streaks or seams where the grids change or at the planes of the tiles.
#include "vtkOFBLICTestHelpers.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <string>

using namespace vtkofbtest;

namespace
{
struct LICRun
{
  vtkSmartPointer<vtkOFB> Output;
  const float* Values = nullptr;
  const unsigned char* Mask = nullptr;
};

LICRun RunLIC(vtkOFB* ofb, bool cacheStreamlines, double reuseDistance = 0.05)
{
  vtkNew<vtkOFBLIC> lic;
  lic->SetCacheStreamlines(cacheStreamlines);
  lic->SetStreamlineReuseDistance(reuseDistance);
  lic->SetInputData(ofb);
  lic->Update();
  LICRun run;
  run.Output = vtkSmartPointer<vtkOFB>::New();
  run.Output->ShallowCopy(lic->GetOutput());
  vtkFloatArray* values = vtkFloatArray::SafeDownCast(run.Output->GetSampleData()->GetArray("LIC"));
  vtkUnsignedCharArray* mask =
    vtkUnsignedCharArray::SafeDownCast(run.Output->GetSampleData()->GetArray("LICMask"));
  run.Values = values ? values->GetPointer(0) : nullptr;
  run.Mask = mask ? mask->GetPointer(0) : nullptr;
  return run;
}

/**
 * The default LIC of `ofb` (its active sample vectors) correlates at least 0.95 with the
 * LIC traced from every sample, and its downstream-neighbour difference across grid
 * changes and across tile planes is within 1.1x of that elsewhere, or no worse than the
 * per-sample LIC's.
 */
void ExpectExactLooking(vtkOFB* ofb, const std::string& name)
{
  ASSERT_GT(ofb->GetNumberOfSamples(), 0) << name;
  const LICRun fast = RunLIC(ofb, true);
  const LICRun traced = RunLIC(ofb, false);
  ASSERT_NE(fast.Values, nullptr);
  ASSERT_NE(traced.Values, nullptr);
  ASSERT_NE(fast.Mask, nullptr);
  const Correlation c = CorrelationUnmasked(fast.Output, fast.Values, traced.Values, fast.Mask);
  const DownstreamDifference f = DownstreamDifferences(fast.Output, fast.Values, fast.Mask);
  const DownstreamDifference t = DownstreamDifferences(traced.Output, traced.Values, fast.Mask);
  const double gridRatio = f.GridSwitch / f.SameGrid;
  const double tileRatio = f.TilePlane / f.InTile;
  const double tracedGridRatio = t.GridSwitch / t.SameGrid;
  const double tracedTileRatio = t.TilePlane / t.InTile;
  std::cout << name << ": " << ofb->GetNumberOfSamples() << " samples, correlation with the "
            << "per-sample traced LIC " << c.Value << "\n  downstream difference, default: "
            << "grid switch / same grid " << f.GridSwitch << " / " << f.SameGrid << " = "
            << gridRatio << ", tile plane / in tile " << f.TilePlane << " / " << f.InTile << " = "
            << tileRatio << "\n  per-sample traced: grid switch / same grid " << tracedGridRatio
            << ", tile plane / in tile " << tracedTileRatio << " (pairs " << f.Pairs[0] << ", "
            << f.Pairs[1] << ", " << f.Pairs[2] << ", " << f.Pairs[3] << ")\n";
  for (vtkIdType pairs : f.Pairs)
  {
    EXPECT_GT(pairs, 1000) << name;
  }
  EXPECT_GE(c.Value, 0.95) << name;
  EXPECT_LE(gridRatio, std::max(1.1, tracedGridRatio)) << name;
  EXPECT_LE(tileRatio, std::max(1.1, tracedTileRatio)) << name;
}
}

//------------------------------------------------------------------------------
TEST(LICQuality, PipeWithBumpAt768Cells)
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakePipeWithBump(), 768);
  ExpectExactLooking(ofb, "pipe with bump, 768 cells");
}

//------------------------------------------------------------------------------
TEST(LICQuality, SphereWithRotation)
{
  const double axis[3] = { 0.2, 0.4, 1.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSphere(1.0, 128), 384, RotationField(axis));
  ExpectExactLooking(ofb, "sphere, rotation, 384 cells");
}

//------------------------------------------------------------------------------
TEST(LICQuality, BunnyWithRotation)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  const double axis[3] = { 0.3, 1.0, 0.2 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(bunny, 384, RotationField(axis));
  ExpectExactLooking(ofb, "bunny, rotation, 384 cells");
}

//------------------------------------------------------------------------------
TEST(LICQuality, ReuseDistanceTradesExactnessForSpeed)
{
  // 0: every sample's own streamline, kept (the per-sample traced LIC up to the order of
  // the sums); 1: every sample a seed streamline meets reads it, the measures show the
  // dashes and seams (a smaller correlation, a larger difference across tile planes).
  const double axis[3] = { 0.3, 1.0, 0.2 };
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(bunny, 256, RotationField(axis));
  const LICRun traced = RunLIC(ofb, false);
  const LICRun own = RunLIC(ofb, true, 0.0);
  const LICRun any = RunLIC(ofb, true, 1.0);
  const Correlation cOwn = CorrelationUnmasked(ofb, own.Values, traced.Values, traced.Mask);
  const Correlation cAny = CorrelationUnmasked(ofb, any.Values, traced.Values, traced.Mask);
  const DownstreamDifference d = DownstreamDifferences(any.Output, any.Values, any.Mask);
  std::cout << "reuse distance 0: correlation " << cOwn.Value << "; 1: correlation " << cAny.Value
            << ", tile plane / in tile " << d.TilePlane / d.InTile << "\n";
  EXPECT_GT(cOwn.Value, 0.999);
  EXPECT_LT(cAny.Value, 0.8);
  EXPECT_GT(d.TilePlane / d.InTile, 1.1);
}
