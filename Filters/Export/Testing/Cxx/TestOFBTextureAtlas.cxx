// vtkOFBTextureAtlas: texture coordinates for a surface without any. Charts: texel centres
// on the samples of the chart's grid, the bake exact there, no texel covered twice, cut
// where the surface folds over itself. Triangles: tiles apart, each triangle's corners on
// its tile's corner texels (the longest edge on the diagonal, the orientation kept, enough
// texels a cell). Both: the paint baked through them, the density lowered to fit, bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

using namespace vtkofbtest;

namespace
{
vtkSmartPointer<vtkPolyData> Atlas(vtkOFBTextureAtlas* atlas, vtkPolyData* mesh, vtkOFB* ofb)
{
  atlas->SetInputData(mesh);
  atlas->SetOFBData(ofb);
  atlas->Update();
  vtkSmartPointer<vtkPolyData> out = atlas->GetOutput();
  return out;
}

/// Calls f(texel, point, triangle) for each texel whose centre lies strictly inside an
/// output triangle in UV space, with the surface point there and the triangle's index;
/// returns the texels covered twice.
template<typename Functor>
vtkIdType ForEachCoveredTexel(vtkPolyData* out, const int size[2], Functor&& f)
{
  const int w = size[0];
  const int h = size[1];
  std::vector<unsigned char> covered(static_cast<size_t>(w) * h, 0);
  vtkIdType twice = 0;
  vtkDataArray* tc = out->GetPointData()->GetTCoords();
  auto iter = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  vtkIdType t = 0;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++t)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    iter->GetCurrentCell(npts, ids);
    double q[3][2];
    double x[3][3];
    for (int k = 0; k < 3; ++k)
    {
      q[k][0] = tc->GetComponent(ids[k], 0) * w - 0.5;
      q[k][1] = tc->GetComponent(ids[k], 1) * h - 0.5;
      out->GetPoint(ids[k], x[k]);
    }
    const double e1[2] = { q[1][0] - q[0][0], q[1][1] - q[0][1] };
    const double e2[2] = { q[2][0] - q[0][0], q[2][1] - q[0][1] };
    const double area = e1[0] * e2[1] - e1[1] * e2[0];
    if (!(std::fabs(area) > 1e-12))
    {
      continue;
    }
    const int i0 =
      std::max(0, static_cast<int>(std::ceil(std::min({ q[0][0], q[1][0], q[2][0] }))));
    const int i1 = std::min(w - 1, static_cast<int>(std::max({ q[0][0], q[1][0], q[2][0] })));
    const int j0 =
      std::max(0, static_cast<int>(std::ceil(std::min({ q[0][1], q[1][1], q[2][1] }))));
    const int j1 = std::min(h - 1, static_cast<int>(std::max({ q[0][1], q[1][1], q[2][1] })));
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double d[2] = { i - q[0][0], j - q[0][1] };
        const double w1 = (d[0] * e2[1] - d[1] * e2[0]) / area;
        const double w2 = (e1[0] * d[1] - e1[1] * d[0]) / area;
        const double w0 = 1.0 - w1 - w2;
        if (w0 <= 1e-9 || w1 <= 1e-9 || w2 <= 1e-9)
        {
          continue;
        }
        const vtkIdType texel = static_cast<vtkIdType>(j) * w + i;
        twice += covered[texel];
        covered[texel] = 1;
        double p[3];
        for (int c = 0; c < 3; ++c)
        {
          p[c] = w0 * x[0][c] + w1 * x[1][c] + w2 * x[2][c];
        }
        f(texel, p, t);
      }
    }
  }
  return twice;
}

/// The chart of each output triangle: charts share no points (they are repeated where
/// charts meet) and each is connected, so a chart is a component of shared points.
std::vector<vtkIdType> ChartOfTriangles(vtkPolyData* out)
{
  std::vector<vtkIdType> parent(out->GetNumberOfPoints());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](vtkIdType a)
  {
    while (parent[a] != a)
    {
      a = parent[a] = parent[parent[a]];
    }
    return a;
  };
  std::vector<vtkIdType> first;
  auto iter = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* ids;
    iter->GetCurrentCell(npts, ids);
    parent[find(ids[1])] = find(ids[0]);
    parent[find(ids[2])] = find(ids[0]);
    first.push_back(ids[0]);
  }
  for (vtkIdType& p : first)
  {
    p = find(p);
  }
  return first;
}

/// The smallest Chebyshev distance, in texels, between covered texel centres of two
/// different charts (texel centres strictly inside the triangles, as ForEachCoveredTexel).
int ClosestTexelsOfTwoCharts(vtkPolyData* out, const int size[2])
{
  const std::vector<vtkIdType> chart = ChartOfTriangles(out);
  std::vector<vtkIdType> owner(static_cast<size_t>(size[0]) * size[1], -1);
  ForEachCoveredTexel(
    out, size, [&](vtkIdType texel, const double*, vtkIdType t) { owner[texel] = chart[t]; });
  int closest = std::numeric_limits<int>::max();
  const int reach = 8;
  for (int j = 0; j < size[1]; ++j)
  {
    for (int i = 0; i < size[0]; ++i)
    {
      const vtkIdType a = owner[static_cast<size_t>(j) * size[0] + i];
      if (a < 0)
      {
        continue;
      }
      for (int dj = -reach; dj <= reach; ++dj)
      {
        for (int di = -reach; di <= reach; ++di)
        {
          const int x = i + di;
          const int y = j + dj;
          if (x < 0 || y < 0 || x >= size[0] || y >= size[1])
          {
            continue;
          }
          const vtkIdType b = owner[static_cast<size_t>(y) * size[0] + x];
          if (b >= 0 && b != a)
          {
            closest = std::min(closest, std::max(std::abs(di), std::abs(dj)));
          }
        }
      }
    }
  }
  return closest;
}

/// A helicoid ramp of `turns` turns between radii 1 and 2, rising `pitch` a radian: its
/// normal is mostly +z, and its turns lie over each other along z.
vtkSmartPointer<vtkPolyData> MakeHelicoid(double turns, double pitch)
{
  const int nr = 8;
  const int nt = static_cast<int>(96 * turns);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j <= nt; ++j)
  {
    const double theta = 2.0 * vtkMath::Pi() * turns * j / nt;
    for (int i = 0; i <= nr; ++i)
    {
      const double r = 1.0 + static_cast<double>(i) / nr;
      points->InsertNextPoint(r * std::cos(theta), r * std::sin(theta), pitch * theta);
    }
  }
  for (int j = 0; j < nt; ++j)
  {
    for (int i = 0; i < nr; ++i)
    {
      const vtkIdType a = j * (nr + 1) + i;
      const vtkIdType b = a + nr + 1;
      const vtkIdType t0[3] = { a, a + 1, b + 1 };
      const vtkIdType t1[3] = { a, b + 1, b };
      triangles->InsertNextCell(3, t0);
      triangles->InsertNextCell(3, t1);
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh;
}

/// Random dabs of 6 cells over the OFB, random colours.
void PaintDabs(vtkOFB* ofb, int count)
{
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(6.0 * ofb->GetCellSize());
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  for (int k = 0; k < count; ++k)
  {
    painter->GetBrush()->SetColor(random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0));
    double x[3];
    ofb->GetSamplePosition(
      static_cast<vtkIdType>(random->GetNextRangeValue(0, ofb->GetNumberOfSamples() - 1)), x);
    painter->Dab(x);
  }
}

/// The painted OFB baked through an atlas of `layout`: at each triangle's centroid, the
/// texel has the colour of the closest sample.
void ExpectTheBakeShowsThePaint(vtkPolyData* bunny, vtkOFB* ofb, int layout)
{
  vtkNew<vtkOFBTextureAtlas> atlas;
  atlas->SetLayout(layout);
  vtkSmartPointer<vtkPolyData> out = Atlas(atlas, bunny, ofb);
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetInputData(out);
  baker->SetOFBData(ofb);
  baker->SetTextureSize(atlas->GetAtlasSize());
  baker->Update();
  vtkImageData* image = baker->GetOutput();
  auto* texels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  ASSERT_NE(texels, nullptr);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  // At each triangle's centroid, the texel equals the colour of the closest sample.
  vtkDataArray* tc = out->GetPointData()->GetTCoords();
  const int w = atlas->GetAtlasSize()[0];
  const int h = atlas->GetAtlasSize()[1];
  vtkIdType same = 0;
  vtkIdType painted = 0;
  const unsigned char* white = colors->GetPointer(0); // the sampler's default, unpainted
  auto iter = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* ids;
    iter->GetCurrentCell(npts, ids);
    double c[3] = { 0, 0, 0 };
    double uv[2] = { 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      double p[3];
      out->GetPoint(ids[k], p);
      for (int i = 0; i < 3; ++i)
      {
        c[i] += p[i] / 3.0;
      }
      uv[0] += tc->GetComponent(ids[k], 0) * w / 3.0;
      uv[1] += tc->GetComponent(ids[k], 1) * h / 3.0;
    }
    const vtkIdType id = ofb->FindClosestSample(c);
    const int i = std::min(static_cast<int>(uv[0]), w - 1);
    const int j = std::min(static_cast<int>(uv[1]), h - 1);
    const unsigned char* texel = texels->GetPointer(4 * (static_cast<vtkIdType>(j) * w + i));
    const unsigned char* sample = colors->GetPointer(4 * id);
    int diff = 0;
    for (int k = 0; k < 3; ++k)
    {
      diff = std::max(diff, std::abs(texel[k] - sample[k]));
    }
    same += diff <= 2;
    painted += id >= 0 && std::memcmp(sample, white, 3) != 0;
  }
  const vtkIdType n = out->GetNumberOfPolys();
  EXPECT_GT(painted, n / 20); // the dabs reached a fair share of the triangles
  EXPECT_GE(same, n * 97 / 100);
}

void Normal(vtkPoints* points, const vtkIdType* ids, double n[3])
{
  double p[3][3];
  for (int k = 0; k < 3; ++k)
  {
    points->GetPoint(ids[k], p[k]);
  }
  double a[3];
  double b[3];
  vtkMath::Subtract(p[1], p[0], a);
  vtkMath::Subtract(p[2], p[0], b);
  vtkMath::Cross(a, b, n);
}
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, TrianglesGetTilesApartWithTheirCornersOnCornerTexels)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  vtkNew<vtkOFBTextureAtlas> atlas;
  atlas->SetLayoutToTriangles();
  vtkSmartPointer<vtkPolyData> out = Atlas(atlas, bunny, ofb);
  const vtkIdType n = bunny->GetNumberOfPolys();
  EXPECT_EQ(atlas->GetNumberOfCharts(), n);
  ASSERT_EQ(out->GetNumberOfPolys(), n);
  ASSERT_EQ(out->GetNumberOfPoints(), 3 * n);
  const int w = atlas->GetAtlasSize()[0];
  const int h = atlas->GetAtlasSize()[1];
  ASSERT_GT(w, 0);
  auto* size = vtkIntArray::SafeDownCast(out->GetFieldData()->GetArray("AtlasSize"));
  ASSERT_NE(size, nullptr);
  EXPECT_EQ(size->GetValue(0), w);
  EXPECT_EQ(size->GetValue(1), h);
  vtkDataArray* tc = out->GetPointData()->GetTCoords();
  ASSERT_NE(tc, nullptr);
  // The bunny has no normals: the atlas computes point normals, so that the repeated points
  // shade smoothly (copies of one point share its normal).
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  ASSERT_EQ(normals->GetNumberOfTuples(), 3 * n);
  std::vector<vtkIdType> owner(static_cast<size_t>(w) * h, -1);
  vtkIdType bad = 0;
  vtkIdType overlaps = 0;
  auto inIter = vtk::TakeSmartPointer(bunny->GetPolys()->NewIterator());
  auto outIter = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  const double s = ofb->GetCellSize();
  vtkIdType t = 0;
  for (inIter->GoToFirstCell(), outIter->GoToFirstCell(); !outIter->IsDoneWithTraversal();
       inIter->GoToNextCell(), outIter->GoToNextCell(), ++t)
  {
    vtkIdType npts;
    const vtkIdType* in;
    const vtkIdType* ids;
    inIter->GetCurrentCell(npts, in);
    outIter->GetCurrentCell(npts, ids);
    double uv[3][2];
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      uv[k][0] = tc->GetComponent(ids[k], 0) * w;
      uv[k][1] = tc->GetComponent(ids[k], 1) * h;
      out->GetPoint(ids[k], p[k]);
    }
    const int x0 = static_cast<int>(std::lround(uv[0][0] - 0.5));
    const int y0 = static_cast<int>(std::lround(uv[0][1] - 0.5));
    const double far = uv[1][0] - uv[0][0];
    const int side = static_cast<int>(std::lround(far + 1.0));
    // Corner 0 at the tile's corner texel, corners 1 and 2 along its two sides.
    bad += std::fabs(uv[0][0] - (x0 + 0.5)) > 1e-2 || std::fabs(uv[0][1] - (y0 + 0.5)) > 1e-2 ||
      std::fabs(uv[1][1] - uv[0][1]) > 1e-2 || std::fabs(uv[2][0] - uv[0][0]) > 1e-2 ||
      std::fabs(uv[2][1] - uv[0][1] - far) > 1e-2 || side % 4 != 0;
    // The longest edge (1-2) on the diagonal; at least a texel a cell along every edge.
    const double l01 = std::sqrt(vtkMath::Distance2BetweenPoints(p[0], p[1])) / s;
    const double l02 = std::sqrt(vtkMath::Distance2BetweenPoints(p[0], p[2])) / s;
    const double l12 = std::sqrt(vtkMath::Distance2BetweenPoints(p[1], p[2])) / s;
    bad += l12 + 1e-9 < std::max(l01, l02);
    bad += far + 1e-6 < std::max({ l01, l02, l12 / std::sqrt(2.0) });
    // The triangle's orientation kept.
    double n0[3];
    double n1[3];
    Normal(bunny->GetPoints(), in, n0);
    Normal(out->GetPoints(), ids, n1);
    bad += vtkMath::Dot(n0, n1) < 0.0;
    for (int k = 0; k < 3; ++k)
    {
      double pn[3];
      normals->GetTuple(ids[k], pn);
      bad += std::fabs(vtkMath::Norm(pn) - 1.0) > 1e-3;
    }
    ASSERT_GE(x0, 0);
    ASSERT_GE(y0, 0);
    ASSERT_LE(x0 + side, w);
    ASSERT_LE(y0 + side, h);
    for (int j = y0; j < y0 + side; ++j)
    {
      for (int i = x0; i < x0 + side; ++i)
      {
        vtkIdType& o = owner[static_cast<size_t>(j) * w + i];
        overlaps += o >= 0;
        o = t;
      }
    }
  }
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(overlaps, 0);
  // The rows of tiles fill most of the atlas.
  vtkIdType used = 0;
  for (vtkIdType o : owner)
  {
    used += o >= 0;
  }
  EXPECT_GT(used, static_cast<vtkIdType>(w) * h * 8 / 10);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, TheBakedTextureShowsThePaint)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 128);
  PaintDabs(ofb, 30);
  for (int layout : { vtkOFBTextureAtlas::CHARTS, vtkOFBTextureAtlas::TRIANGLES })
  {
    SCOPED_TRACE(layout == vtkOFBTextureAtlas::CHARTS ? "charts" : "triangles");
    ExpectTheBakeShowsThePaint(bunny, ofb, layout);
  }
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, ChartsPutTexelCentresOnTheSamplesOfTheirGrid)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  PaintDabs(ofb, 60);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  const vtkIdType n = bunny->GetNumberOfPolys();
  const double s = ofb->GetCellSize();
  vtkIdType texels[2];
  vtkIdType points[2];
  for (int layout : { vtkOFBTextureAtlas::CHARTS, vtkOFBTextureAtlas::TRIANGLES })
  {
    SCOPED_TRACE(layout == vtkOFBTextureAtlas::CHARTS ? "charts" : "triangles");
    vtkNew<vtkOFBTextureAtlas> atlas;
    atlas->SetLayout(layout);
    vtkSmartPointer<vtkPolyData> out = Atlas(atlas, bunny, ofb);
    ASSERT_EQ(out->GetNumberOfPolys(), n);
    const int* size = atlas->GetAtlasSize();
    texels[layout] = static_cast<vtkIdType>(size[0]) * size[1];
    points[layout] = out->GetNumberOfPoints();
    vtkNew<vtkOFBTextureBaker> baker;
    baker->SetInputData(out);
    baker->SetOFBData(ofb);
    baker->SetTextureSize(atlas->GetAtlasSize());
    baker->Update();
    auto* image =
      vtkUnsignedCharArray::SafeDownCast(baker->GetOutput()->GetPointData()->GetScalars());
    ASSERT_NE(image, nullptr);
    // Each covered texel's surface point: on a sample (within 1/100 cell), and that
    // sample's colour baked, byte for byte.
    vtkIdType covered = 0;
    vtkIdType onSample = 0;
    vtkIdType sameColour = 0;
    const vtkIdType twice = ForEachCoveredTexel(out,
      size,
      [&](vtkIdType texel, const double p[3], vtkIdType)
      {
        ++covered;
        const vtkIdType id = ofb->FindClosestSample(p);
        double y[3];
        ofb->GetSamplePosition(id, y);
        if (std::sqrt(vtkMath::Distance2BetweenPoints(p, y)) < 0.01 * s)
        {
          ++onSample;
          sameColour +=
            std::memcmp(image->GetPointer(4 * texel), colors->GetPointer(4 * id), 4) == 0;
        }
      });
    EXPECT_EQ(twice, 0);
    ASSERT_GT(covered, 0);
    if (layout == vtkOFBTextureAtlas::CHARTS)
    {
      EXPECT_GE(onSample, covered * 99 / 100);
      EXPECT_GE(sameColour, onSample * 999 / 1000);
      EXPECT_GT(atlas->GetNumberOfCharts(), 6);
      EXPECT_LT(atlas->GetNumberOfCharts(), n / 20);
      // The charts' outlines interlock: the covered texels fill over 40 % of the atlas (a
      // shelf of their rectangles filled 28 %), and still two charts' texels are more
      // than twice ChartPadding apart.
      EXPECT_GT(covered, static_cast<vtkIdType>(0.4 * size[0] * size[1]));
      EXPECT_GT(ClosestTexelsOfTwoCharts(out, size), 2 * atlas->GetChartPadding());
    }
    else
    {
      EXPECT_LT(onSample, covered / 5); // a tile's texels fall anywhere between samples
    }
  }
  // Fewer texels at the same density, points repeated only where charts meet.
  EXPECT_LT(texels[vtkOFBTextureAtlas::CHARTS], texels[vtkOFBTextureAtlas::TRIANGLES] * 6 / 10);
  EXPECT_LT(points[vtkOFBTextureAtlas::CHARTS], bunny->GetNumberOfPoints() * 13 / 10);
  EXPECT_EQ(points[vtkOFBTextureAtlas::TRIANGLES], 3 * n);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, ChartsGrowAcrossPointsRepeatedAtOnePlace)
{
  // The bunny with the points of every triangle its own (as an OBJ with per-corner
  // normals or texture coordinates, or an STL, reads): charts still grow over the edges,
  // about as many as on the shared points, and every texel is baked from a sample.
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  auto iter = vtk::TakeSmartPointer(bunny->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* ids;
    iter->GetCurrentCell(npts, ids);
    vtkIdType own[3];
    for (int k = 0; k < 3; ++k)
    {
      own[k] = points->InsertNextPoint(bunny->GetPoint(ids[k]));
    }
    triangles->InsertNextCell(3, own);
  }
  vtkNew<vtkPolyData> split;
  split->SetPoints(points);
  split->SetPolys(triangles);
  vtkNew<vtkOFBTextureAtlas> shared;
  Atlas(shared, bunny, ofb);
  vtkNew<vtkOFBTextureAtlas> separate;
  vtkSmartPointer<vtkPolyData> out = Atlas(separate, split, ofb);
  const vtkIdType n = bunny->GetNumberOfPolys();
  ASSERT_EQ(out->GetNumberOfPolys(), n);
  EXPECT_LT(separate->GetNumberOfCharts(), n / 20);
  EXPECT_LE(separate->GetNumberOfCharts(), shared->GetNumberOfCharts() * 11 / 10);
  EXPECT_GE(separate->GetNumberOfCharts(), shared->GetNumberOfCharts() * 9 / 10);
  // The points stay as they were given: one per corner.
  EXPECT_EQ(out->GetNumberOfPoints(), 3 * n);
  vtkIdType covered = 0;
  const vtkIdType twice = ForEachCoveredTexel(
    out, separate->GetAtlasSize(), [&covered](vtkIdType, const double*, vtkIdType) { ++covered; });
  EXPECT_EQ(twice, 0);
  EXPECT_GT(covered, ofb->GetNumberOfSamples() * 9 / 10);
  // A point not finite welds to nothing and breaks nothing.
  points->SetPoint(0, std::nan(""), 0.0, 0.0);
  split->Modified();
  vtkNew<vtkOFBTextureAtlas> withNaN;
  vtkSmartPointer<vtkPolyData> out2 = Atlas(withNaN, split, ofb);
  EXPECT_EQ(out2->GetNumberOfPolys(), n);
  EXPECT_GT(withNaN->GetAtlasSize()[0], 0);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, ChartsAreCutWhereTheSurfaceFoldsOverItself)
{
  for (double turns : { 0.9, 1.6 })
  {
    SCOPED_TRACE(turns);
    vtkSmartPointer<vtkPolyData> ramp = MakeHelicoid(turns, 0.1);
    vtkSmartPointer<vtkOFB> ofb = Build(ramp, 128);
    vtkNew<vtkOFBTextureAtlas> atlas;
    vtkSmartPointer<vtkPolyData> out = Atlas(atlas, ramp, ofb);
    ASSERT_EQ(out->GetNumberOfPolys(), ramp->GetNumberOfPolys());
    vtkIdType covered = 0;
    const vtkIdType twice = ForEachCoveredTexel(
      out, atlas->GetAtlasSize(), [&covered](vtkIdType, const double*, vtkIdType) { ++covered; });
    EXPECT_EQ(twice, 0);
    // One chart while the ramp does not come over itself, then at least two.
    if (turns < 1.0)
    {
      EXPECT_EQ(atlas->GetNumberOfCharts(), 1);
    }
    else
    {
      EXPECT_GE(atlas->GetNumberOfCharts(), 2);
      EXPECT_LE(atlas->GetNumberOfCharts(), 4);
    }
    // Every turn has its texels: the ramp's area seen along z, in cells.
    const double cells = turns * vtkMath::Pi() * 3.0 / std::pow(ofb->GetCellSize(), 2);
    EXPECT_GT(covered, 0.97 * cells);
    EXPECT_LT(covered, 1.03 * cells);
  }
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, LowersTheDensityToFitAndFailsBeyond)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  for (int layout : { vtkOFBTextureAtlas::CHARTS, vtkOFBTextureAtlas::TRIANGLES })
  {
    SCOPED_TRACE(layout == vtkOFBTextureAtlas::CHARTS ? "charts" : "triangles");
    vtkNew<vtkOFBTextureAtlas> atlas;
    atlas->SetLayout(layout);
    atlas->SetTexelsPerCell(2.0);
    Atlas(atlas, bunny, ofb);
    const int full = atlas->GetAtlasSize()[0];
    ASSERT_GT(full, 0);
    vtkNew<MessageObserver> messages;
    messages->Watch(atlas);
    atlas->SetMaximumTextureSize(full * 2 / 3);
    // Progress rises with every try at a density, up to 1.
    std::vector<double> progress;
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetClientData(&progress);
    onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
      { static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(call)); });
    const unsigned long tag = atlas->AddObserver(vtkCommand::ProgressEvent, onProgress);
    Atlas(atlas, bunny, ofb);
    atlas->RemoveObserver(tag);
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back(), 1.0);
    if (layout == vtkOFBTextureAtlas::CHARTS)
    {
      EXPECT_GT(progress.size(), 5u) << "a progress event a try";
    }
    EXPECT_GT(atlas->GetAtlasSize()[0], 0);
    EXPECT_LE(atlas->GetAtlasSize()[0], full * 2 / 3);
    EXPECT_LE(atlas->GetAtlasSize()[1], full * 2 / 3);
    EXPECT_LT(atlas->GetEffectiveTexelsPerCell(), 2.0);
    EXPECT_NE(messages->Warnings.find("to fit"), std::string::npos);
    if (layout == vtkOFBTextureAtlas::CHARTS)
    {
      // The density found takes most of the room (halving would not).
      EXPECT_GE(
        std::max(atlas->GetAtlasSize()[0], atlas->GetAtlasSize()[1]), full * 2 / 3 * 9 / 10);
    }
    else
    {
      EXPECT_EQ(atlas->GetEffectiveTexelsPerCell(), 1.0);
    }
    // 69,451 tiles of 4 x 4 texels need about 1054 x 1054; hundreds of charts of at least
    // 5 x 5 texels (the padding) about 120 x 120.
    atlas->SetMaximumTextureSize(64);
    vtkSmartPointer<vtkPolyData> none = Atlas(atlas, bunny, ofb);
    EXPECT_EQ(none->GetNumberOfPoints(), 0);
    EXPECT_EQ(atlas->GetAtlasSize()[0], 0);
    EXPECT_EQ(atlas->GetNumberOfCharts(), 0);
    EXPECT_NE(messages->Errors.find("do not fit"), std::string::npos);
  }
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, BadInputGivesAnErrorAndAnEmptyOutput)
{
  for (int layout : { vtkOFBTextureAtlas::CHARTS, vtkOFBTextureAtlas::TRIANGLES })
  {
    SCOPED_TRACE(layout == vtkOFBTextureAtlas::CHARTS ? "charts" : "triangles");
    vtkNew<vtkOFBTextureAtlas> atlas;
    atlas->SetLayout(layout);
    vtkNew<MessageObserver> messages;
    messages->Watch(atlas);
    vtkSmartPointer<vtkPolyData> quads = MakeTexturedPlane(4);
    vtkSmartPointer<vtkOFB> ofb = Build(quads, 32);
    EXPECT_EQ(Atlas(atlas, quads, ofb)->GetNumberOfPoints(), 0);
    EXPECT_NE(messages->Errors.find("not triangles"), std::string::npos);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(quads);
    triangles->Update();
    vtkNew<vtkOFB> empty;
    messages->Clear();
    EXPECT_EQ(Atlas(atlas, triangles->GetOutput(), empty)->GetNumberOfPoints(), 0);
    EXPECT_NE(messages->Errors.find("empty"), std::string::npos);
    vtkNew<vtkPolyData> nothing;
    messages->Clear();
    EXPECT_EQ(Atlas(atlas, nothing, ofb)->GetNumberOfPoints(), 0);
    EXPECT_NE(messages->Errors.find("no polygons"), std::string::npos);
    EXPECT_EQ(Atlas(atlas, triangles->GetOutput(), ofb)->GetNumberOfPolys(), 32);
    // A point that is not finite and a zero-area triangle: no crash, every triangle out,
    // texture coordinates finite.
    vtkNew<vtkPolyData> odd;
    odd->DeepCopy(triangles->GetOutput());
    odd->GetPoints()->SetPoint(0, std::nan(""), 0.0, 0.0);
    odd->GetPoints()->SetPoint(1, 0.0, 0.0, 0.0);
    odd->GetPoints()->SetPoint(2, 0.0, 0.0, 0.0);
    messages->Clear();
    vtkSmartPointer<vtkPolyData> out = Atlas(atlas, odd, ofb);
    EXPECT_EQ(out->GetNumberOfPolys(), 32);
    EXPECT_GT(atlas->GetAtlasSize()[0], 0);
    EXPECT_TRUE(messages->Errors.empty());
    vtkDataArray* tc = out->GetPointData()->GetTCoords();
    ASSERT_NE(tc, nullptr);
    for (vtkIdType p = 0; p < tc->GetNumberOfTuples(); ++p)
    {
      EXPECT_TRUE(std::isfinite(tc->GetComponent(p, 0)) && std::isfinite(tc->GetComponent(p, 1)));
    }
  }
}
