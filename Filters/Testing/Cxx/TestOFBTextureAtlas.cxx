// vtkOFBTextureAtlas: texture coordinates for a surface without any. Tiles apart, each
// triangle's corners on its tile's corner texels (the longest edge on the diagonal, the
// orientation kept, enough texels a cell), the paint baked through them, the density
// halved to fit, bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkPointData.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace vtkofbtest;

namespace
{
vtkSmartPointer<vtkPolyData> Atlas(vtkOFBTextureAtlas* atlas, vtkPolyData* mesh, vtkOFB* ofb)
{
  atlas->SetInputData(mesh);
  atlas->SetSourceData(ofb);
  atlas->Update();
  vtkSmartPointer<vtkPolyData> out = atlas->GetOutput();
  return out;
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
  vtkSmartPointer<vtkPolyData> out = Atlas(atlas, bunny, ofb);
  const vtkIdType n = bunny->GetNumberOfPolys();
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
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(6.0 * ofb->GetCellSize());
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  for (int k = 0; k < 30; ++k)
  {
    painter->GetBrush()->SetColor(random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0));
    double x[3];
    ofb->GetSamplePosition(
      static_cast<vtkIdType>(random->GetNextRangeValue(0, ofb->GetNumberOfSamples() - 1)), x);
    painter->Dab(x);
  }
  vtkNew<vtkOFBTextureAtlas> atlas;
  vtkSmartPointer<vtkPolyData> out = Atlas(atlas, bunny, ofb);
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetInputData(out);
  baker->SetSourceData(ofb);
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

//------------------------------------------------------------------------------
TEST(TextureAtlas, HalvesTheDensityToFitAndFailsBeyond)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  vtkNew<vtkOFBTextureAtlas> atlas;
  atlas->SetTexelsPerCell(2.0);
  Atlas(atlas, bunny, ofb);
  const int full = atlas->GetAtlasSize()[0];
  ASSERT_GT(full, 0);
  vtkNew<MessageObserver> messages;
  messages->Watch(atlas);
  atlas->SetMaximumTextureSize(full * 2 / 3);
  Atlas(atlas, bunny, ofb);
  EXPECT_GT(atlas->GetAtlasSize()[0], 0);
  EXPECT_LE(atlas->GetAtlasSize()[0], full * 2 / 3);
  EXPECT_LE(atlas->GetAtlasSize()[1], full * 2 / 3);
  EXPECT_LT(atlas->GetEffectiveTexelsPerCell(), 2.0);
  EXPECT_NE(messages->Warnings.find("to fit"), std::string::npos);
  atlas->SetMaximumTextureSize(64); // 69,451 tiles of 4 x 4 texels need about 1054 x 1054
  vtkSmartPointer<vtkPolyData> none = Atlas(atlas, bunny, ofb);
  EXPECT_EQ(none->GetNumberOfPoints(), 0);
  EXPECT_EQ(atlas->GetAtlasSize()[0], 0);
  EXPECT_NE(messages->Errors.find("do not fit"), std::string::npos);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, BadInputGivesAnErrorAndAnEmptyOutput)
{
  vtkNew<vtkOFBTextureAtlas> atlas;
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
  // A point that is not finite and a zero-area triangle: the smallest tiles, no crash.
  vtkNew<vtkPolyData> odd;
  odd->DeepCopy(triangles->GetOutput());
  odd->GetPoints()->SetPoint(0, std::nan(""), 0.0, 0.0);
  odd->GetPoints()->SetPoint(1, 0.0, 0.0, 0.0);
  odd->GetPoints()->SetPoint(2, 0.0, 0.0, 0.0);
  vtkSmartPointer<vtkPolyData> out = Atlas(atlas, odd, ofb);
  EXPECT_EQ(out->GetNumberOfPolys(), 32);
  EXPECT_GT(atlas->GetAtlasSize()[0], 0);
}
