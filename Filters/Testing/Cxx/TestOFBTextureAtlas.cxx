// vtkOFBTextureAtlas: tiles apart and inside the atlas, corners mapped to their tile's
// corner texels, texels coloured by a sample near their point, gathers (whole and by
// ranges), the density halved to fit, bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkPointData.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

using namespace vtkofbtest;

namespace
{
/// Normalized atlas coordinates of world point `x` on triangle `t`, in texels.
void MapToTexels(const vtkOFBTextureAtlas* atlas,
  vtkOFB* ofb,
  vtkIdType t,
  const double x[3],
  double uv[2])
{
  const float* m = atlas->GetTriangleMaps() + 8 * t;
  double g[3];
  for (int i = 0; i < 3; ++i)
  {
    g[i] = (x[i] - ofb->GetOrigin()[i]) / ofb->GetCellSize();
  }
  uv[0] = (m[0] * g[0] + m[1] * g[1] + m[2] * g[2] + m[3]) * atlas->GetWidth();
  uv[1] = (m[4] * g[0] + m[5] * g[1] + m[6] * g[2] + m[7]) * atlas->GetHeight();
}

vtkSmartPointer<vtkPolyData> Bunny()
{
  return ReadMesh("stanford-bunny.obj");
}

/// Paint a few dabs of random colours at random samples.
void Paint(vtkOFB* ofb, double radius)
{
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(radius);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  for (int k = 0; k < 20; ++k)
  {
    painter->GetBrush()->SetColor(random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0));
    const vtkIdType id =
      static_cast<vtkIdType>(random->GetNextRangeValue(0, ofb->GetNumberOfSamples() - 1));
    double x[3];
    ofb->GetSamplePosition(id, x);
    painter->Dab(x);
  }
}
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, TrianglesMapToTheCornersOfTilesApart)
{
  vtkSmartPointer<vtkPolyData> bunny = Bunny();
  ASSERT_NE(bunny, nullptr);
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  vtkNew<vtkOFBTextureAtlas> atlas;
  ASSERT_TRUE(atlas->Build(bunny, ofb));
  const int w = atlas->GetWidth();
  const int h = atlas->GetHeight();
  ASSERT_GT(w, 0);
  ASSERT_EQ(atlas->GetNumberOfTriangles(), bunny->GetNumberOfPolys());
  EXPECT_EQ(atlas->GetNumberOfTileLevels(), 2); // the default smallest tile, 4 texels
  std::vector<vtkIdType> owner(static_cast<size_t>(w) * h, -1);
  vtkIdType overlaps = 0;
  vtkIdType badCorners = 0;
  vtkIdType farSamples = 0;
  const vtkTypeInt32* samples = atlas->GetTexelSamples();
  auto iter = vtk::TakeSmartPointer(bunny->GetPolys()->NewIterator());
  vtkIdType t = 0;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++t)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    iter->GetCurrentCell(npts, ids);
    double uv[3][2];
    double x[3][3];
    for (int k = 0; k < 3; ++k)
    {
      bunny->GetPoint(ids[k], x[k]);
      MapToTexels(atlas, ofb, t, x[k], uv[k]);
    }
    // The tile: the corner texel centres are (x0 + 0.5, y0 + 0.5), (x0 + T - 0.5, y0 + 0.5)
    // and (x0 + 0.5, y0 + T - 0.5).
    const double u0 = std::min({ uv[0][0], uv[1][0], uv[2][0] });
    const double v0 = std::min({ uv[0][1], uv[1][1], uv[2][1] });
    const double side = std::max({ uv[0][0], uv[1][0], uv[2][0] }) - u0 + 1.0;
    const int x0 = static_cast<int>(std::lround(u0 - 0.5));
    const int y0 = static_cast<int>(std::lround(v0 - 0.5));
    const int ts = static_cast<int>(std::lround(side));
    int corners = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double du = uv[k][0] - (x0 + 0.5);
      const double dv = uv[k][1] - (y0 + 0.5);
      const bool origin = std::fabs(du) < 1e-2 && std::fabs(dv) < 1e-2;
      const bool right = std::fabs(du - (ts - 1)) < 1e-2 && std::fabs(dv) < 1e-2;
      const bool up = std::fabs(du) < 1e-2 && std::fabs(dv - (ts - 1)) < 1e-2;
      corners += origin || right || up;
      if (origin)
      {
        // The texel at a corner holds a sample within sqrt(3) cells of it (or none).
        const vtkTypeInt32 id = samples[static_cast<size_t>(y0) * w + x0];
        double p[3];
        if (id >= 0 && ofb->GetSamplePosition(id, p) &&
          std::sqrt(vtkMath::Distance2BetweenPoints(p, x[k])) >
            std::sqrt(3.0) * ofb->GetCellSize() + 1e-9)
        {
          ++farSamples;
        }
      }
    }
    badCorners += corners != 3 || (ts & (ts - 1)) != 0 || ts < 4;
    ASSERT_GE(x0, 0);
    ASSERT_GE(y0, 0);
    ASSERT_LE(x0 + ts, w);
    ASSERT_LE(y0 + ts, h);
    for (int j = y0; j < y0 + ts; ++j)
    {
      for (int i = x0; i < x0 + ts; ++i)
      {
        vtkIdType& o = owner[static_cast<size_t>(j) * w + i];
        overlaps += o >= 0;
        o = t;
      }
    }
  }
  EXPECT_EQ(badCorners, 0);
  EXPECT_EQ(overlaps, 0);
  EXPECT_EQ(farSamples, 0);
  // Nearly every texel of a closed surface has a sample.
  vtkIdType owned = 0;
  for (vtkIdType o : owner)
  {
    owned += o >= 0;
  }
  EXPECT_GT(atlas->GetNumberOfCoveredTexels(), owned * 99 / 100);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, GathersCopyTheTexelSamplesPremultiplied)
{
  vtkSmartPointer<vtkPolyData> bunny = Bunny();
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 128);
  Paint(ofb, 4.0 * ofb->GetCellSize());
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  ASSERT_NE(colors, nullptr);
  for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); i += 7)
  {
    colors->SetTypedComponent(i, 3, static_cast<unsigned char>(i % 256));
  }
  vtkNew<vtkOFBTextureAtlas> atlas;
  ASSERT_TRUE(atlas->Build(bunny, ofb));
  const size_t n = static_cast<size_t>(atlas->GetWidth()) * atlas->GetHeight();
  std::vector<unsigned char> rgba(4 * n, 7);
  ASSERT_TRUE(atlas->GatherColors(colors, rgba.data()));
  std::vector<unsigned char> coverage(n, 7);
  atlas->GatherCoverage(coverage.data());
  const vtkTypeInt32* samples = atlas->GetTexelSamples();
  vtkIdType wrong = 0;
  vtkIdType translucent = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const vtkTypeInt32 id = samples[i];
    unsigned char expect[4] = { 0, 0, 0, 0 };
    if (id >= 0)
    {
      const unsigned char* c = colors->GetPointer(4 * id);
      for (int k = 0; k < 3; ++k)
      {
        expect[k] = static_cast<unsigned char>((c[k] * c[3] + 127) / 255);
      }
      expect[3] = c[3];
      translucent += c[3] < 255;
    }
    wrong += std::memcmp(expect, &rgba[4 * i], 4) != 0;
    wrong += coverage[i] != (id >= 0 ? 255 : 0);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(translucent, 0);

  // Gather by ranges: only texels of samples in the ranges change, in the rows reported.
  vtkNew<vtkIdTypeArray> ranges;
  ranges->SetNumberOfComponents(2);
  const vtkIdType ns = ofb->GetNumberOfSamples();
  ranges->InsertNextTypedTuple(std::array<vtkIdType, 2>{ ns / 4, ns / 4 + 99 }.data());
  ranges->InsertNextTypedTuple(std::array<vtkIdType, 2>{ ns / 2, ns / 2 + 9 }.data());
  std::vector<unsigned char> partial(4 * n, 7);
  int rows[2];
  ASSERT_TRUE(atlas->GatherColors(colors, partial.data(), ranges, rows));
  vtkIdType written = 0;
  vtkIdType misplaced = 0;
  const int w = atlas->GetWidth();
  for (size_t i = 0; i < n; ++i)
  {
    const vtkTypeInt32 id = samples[i];
    const bool in =
      id >= 0 && ((id >= ns / 4 && id <= ns / 4 + 99) || (id >= ns / 2 && id <= ns / 2 + 9));
    const int row = static_cast<int>(i / w);
    if (in)
    {
      ++written;
      misplaced +=
        std::memcmp(&partial[4 * i], &rgba[4 * i], 4) != 0 || row < rows[0] || row > rows[1];
    }
    else
    {
      misplaced += partial[4 * i] != 7 || partial[4 * i + 3] != 7;
    }
  }
  EXPECT_GT(written, 0);
  EXPECT_EQ(misplaced, 0);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, HalvesTheDensityToFitAndFailsBeyond)
{
  vtkSmartPointer<vtkPolyData> bunny = Bunny();
  vtkSmartPointer<vtkOFB> ofb = Build(bunny, 256);
  vtkNew<vtkOFBTextureAtlas> atlas;
  atlas->SetTexelsPerCell(2.0);
  ASSERT_TRUE(atlas->Build(bunny, ofb));
  const int full = atlas->GetWidth();
  atlas->SetMaximumTextureSize(full / 2);
  ASSERT_TRUE(atlas->Build(bunny, ofb));
  EXPECT_LE(atlas->GetWidth(), full / 2);
  EXPECT_LT(atlas->GetEffectiveTexelsPerCell(), 2.0);
  vtkNew<MessageObserver> messages;
  messages->Watch(atlas);
  atlas->SetMaximumTextureSize(64); // 69,451 tiles of 4 x 4 texels need 1024 x 1024
  EXPECT_FALSE(atlas->Build(bunny, ofb));
  EXPECT_EQ(atlas->GetWidth(), 0);
  EXPECT_NE(messages->Errors.find("do not fit"), std::string::npos);
}

//------------------------------------------------------------------------------
TEST(TextureAtlas, BadInputFailsWithAMessage)
{
  vtkNew<vtkOFBTextureAtlas> atlas;
  vtkNew<MessageObserver> messages;
  messages->Watch(atlas);
  vtkSmartPointer<vtkPolyData> quads = MakeTexturedPlane(4);
  vtkSmartPointer<vtkOFB> ofb = Build(quads, 32);
  EXPECT_FALSE(atlas->Build(quads, ofb));
  EXPECT_NE(messages->Errors.find("not triangles"), std::string::npos);
  EXPECT_FALSE(atlas->Build(nullptr, ofb));
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(quads);
  triangles->Update();
  vtkNew<vtkOFB> empty;
  messages->Clear();
  EXPECT_FALSE(atlas->Build(triangles->GetOutput(), empty));
  EXPECT_NE(messages->Errors.find("empty"), std::string::npos);
  EXPECT_TRUE(atlas->Build(triangles->GetOutput(), ofb));
  vtkNew<vtkFloatArray> shortArray;
  shortArray->SetNumberOfValues(3);
  std::vector<unsigned short> out(static_cast<size_t>(atlas->GetWidth()) * atlas->GetHeight());
  EXPECT_FALSE(atlas->GatherIntensity(shortArray, out.data()));
  EXPECT_FALSE(atlas->GatherColors(nullptr, nullptr));
}
