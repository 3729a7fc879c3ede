// Units of vtkOFBTriangleRaster, the CPU backend's triangle set-up (a private
// header): its exact row walker against the edge functions cell by cell, and
// the top-left rule on triangles that share edges.
#include "vtkOFBTriangleRaster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace
{
/// A frame of n^3 unit cells at the origin.
vtkOFBRasterFrame UnitFrame(vtkIdType n)
{
  vtkOFBRasterFrame f;
  for (int a = 0; a < 3; ++a)
  {
    f.Origin[a] = 0.0;
    f.Dims[a] = n;
    f.CellBase[a] = 0;
  }
  f.InvCell = 1.0;
  return f;
}

/// Set up the triangle of points p (9 coordinates) in its dominant grid.
vtkOFBTriangleRaster SetUpTriangle(const double* p, const vtkOFBRasterFrame& f)
{
  const vtkIdType ids[3] = { 0, 1, 2 };
  vtkOFBTriangleRaster t;
  bool front;
  t.Setup(p, ids, vtkOFBTriangleRaster::DominantAxis(p, p + 3, p + 6, front), f);
  return t;
}

/// Whether all three edge functions of t are >= 0 at cell (iu, iv), in exact integers.
bool Inside(const vtkOFBTriangleRaster& t, int64_t iu, int64_t iv)
{
  for (int i = 0; i < 3; ++i)
  {
    if (t.Edge[i] + t.StepV(i) * (iv - t.V0) + t.StepU(i) * (iu - t.U0) < 0)
    {
      return false;
    }
  }
  return true;
}

/**
 * Every row of t: the walker's span is exactly the set of cells where the edge
 * functions are >= 0. Returns the number of covered cells.
 */
int64_t CheckRows(const vtkOFBTriangleRaster& t)
{
  int64_t covered = 0;
  vtkOFBTriangleRaster::RowWalker walker(t, t.V0);
  for (int64_t iv = t.V0; iv <= t.V1; ++iv, walker.Next())
  {
    int64_t first, last;
    walker.Span(first, last);
    for (int64_t iu = t.U0; iu <= t.U1; ++iu)
    {
      const bool inSpan = iu >= first && iu <= last;
      EXPECT_EQ(inSpan, Inside(t, iu, iv)) << "cell " << iu << ", row " << iv;
      if (inSpan != Inside(t, iu, iv))
      {
        return -1;
      }
    }
    covered += last >= first ? last - first + 1 : 0;
  }
  return covered;
}
}

TEST(TriangleRaster, WalkerSpansAreTheEdgeFunctionsCoverage)
{
  const vtkOFBRasterFrame f = UnitFrame(64);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.0, 64.0);
  std::uniform_int_distribution<int> lattice(0, 63);
  int tested = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    double p[9];
    for (double& x : p)
    {
      // A third of the triangles have vertices on cell centres and lattice
      // points (edges through centres, horizontal and vertical edges).
      x = trial % 3 == 0 ? lattice(rng) + 0.5 * (trial % 2) : coord(rng);
    }
    const vtkOFBTriangleRaster t = SetUpTriangle(p, f);
    if (t.Axis < 0)
    {
      continue;
    }
    ASSERT_GE(CheckRows(t), 0) << "trial " << trial;
    ++tested;
  }
  EXPECT_GT(tested, 2000);
}

TEST(TriangleRaster, WalkerIsExactOnLargeGrids)
{
  // Long thin triangles over a grid of 65536 cells a side: edge functions near
  // 2^49, where a floating-point root would need care.
  const vtkOFBRasterFrame f = UnitFrame(65536);
  const double p[9] = { 3.25, 0.0, 0.5, 65530.75, 0.0, 3.0, 65531.0, 0.0, 9.125 };
  const vtkOFBTriangleRaster t = SetUpTriangle(p, f);
  ASSERT_EQ(t.Axis, 1);
  vtkOFBTriangleRaster::RowWalker walker(t, t.V0);
  int64_t covered = 0;
  for (int64_t iv = t.V0; iv <= t.V1; ++iv, walker.Next())
  {
    int64_t first, last;
    walker.Span(first, last);
    // Check the ends and their neighbours only (rows are 65K cells long).
    if (last >= first)
    {
      EXPECT_TRUE(Inside(t, first, iv));
      EXPECT_TRUE(Inside(t, last, iv));
      covered += last - first + 1;
    }
    if (first - 1 >= t.U0)
    {
      EXPECT_FALSE(Inside(t, first - 1, iv)) << "row " << iv;
    }
    if (last + 1 <= t.U1)
    {
      EXPECT_FALSE(Inside(t, last + 1, iv)) << "row " << iv;
    }
  }
  // Area 0.5 * |u x v| cells, within a perimeter's worth of cells.
  const double area = 0.5 * ((p[3] - p[0]) * (p[8] - p[2]) - (p[5] - p[2]) * (p[6] - p[0]));
  EXPECT_NEAR(static_cast<double>(covered), std::abs(area), 2.0 * 65536.0);
}

TEST(TriangleRaster, SharedEdgesCoverEachCellCentreOnce)
{
  // A fan of triangles around a centre tiles a convex polygon; its centre and
  // vertices are cell centres, so that spokes (horizontal, vertical, diagonal)
  // run through cell centres: each centre inside is covered once, none twice.
  const vtkOFBRasterFrame f = UnitFrame(32);
  const int n = 12;
  const double c[2] = { 16.5, 16.5 };
  const double ring[n][2] = { { 28.5, 16.5 },
    { 26.5, 22.5 },
    { 22.5, 26.5 },
    { 16.5, 28.5 },
    { 10.5, 26.5 },
    { 6.5, 22.5 },
    { 4.5, 16.5 },
    { 6.5, 10.5 },
    { 10.5, 6.5 },
    { 16.5, 4.5 },
    { 22.5, 6.5 },
    { 26.5, 10.5 } };
  std::vector<int> hits(32 * 32, 0);
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    // The z grid: cell (iu, iv) has its centre at x = iu + 0.5, y = iv + 0.5.
    const double p[9] = {
      c[0], c[1], 1.0, ring[i][0], ring[i][1], 1.0, ring[j][0], ring[j][1], 1.0
    };
    const vtkOFBTriangleRaster t = SetUpTriangle(p, f);
    ASSERT_EQ(t.Axis, 2);
    ASSERT_GE(CheckRows(t), 0);
    vtkOFBTriangleRaster::RowWalker walker(t, t.V0);
    for (int64_t iv = t.V0; iv <= t.V1; ++iv, walker.Next())
    {
      int64_t first, last;
      walker.Span(first, last);
      for (int64_t iu = first; iu <= last; ++iu)
      {
        ++hits[iv * 32 + iu];
      }
    }
  }
  int inside = 0;
  for (int iv = 0; iv < 32; ++iv)
  {
    for (int iu = 0; iu < 32; ++iu)
    {
      // Strictly inside the polygon (counter-clockwise): left of every edge.
      const double x = iu + 0.5, y = iv + 0.5;
      bool strictly = true;
      for (int i = 0; i < n; ++i)
      {
        const double* a = ring[i];
        const double* b = ring[(i + 1) % n];
        strictly &= (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) > 1e-9;
      }
      const int h = hits[iv * 32 + iu];
      EXPECT_LE(h, 1) << "cell (" << iu << ", " << iv << ") covered twice";
      if (strictly)
      {
        EXPECT_EQ(h, 1) << "hole at cell (" << iu << ", " << iv << ")";
        ++inside;
      }
    }
  }
  EXPECT_GT(inside, 400);
}

TEST(TriangleRaster, RoundIsLlround)
{
  // Halves away from zero, as std::llround, which Setup used before (Mesa snaps
  // vertices the same way).
  for (const double x : { 2.5, -2.5, 0.5, -0.5, 2.4999999999, -2.4999999999, 0.0, 1e12 + 0.5 })
  {
    EXPECT_EQ(vtkOFBTriangleRaster::Round(x), std::llround(x)) << x;
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(-1e7, 1e7);
  for (int i = 0; i < 100000; ++i)
  {
    // Quarters and random values.
    const double x = i % 2 ? std::floor(value(rng)) * 0.25 : value(rng);
    ASSERT_EQ(vtkOFBTriangleRaster::Round(x), std::llround(x)) << x;
  }
}
