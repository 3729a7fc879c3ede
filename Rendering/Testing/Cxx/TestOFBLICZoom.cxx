// GoogleTest units of the surface LIC's display at any zoom (vtkOFBPolyDataMapper's
// LOOKUP_SMOOTH over a vtkOFBLICPyramid), measured in screen space (vtkOFBZoomMetrics.h)
// on a LIC of a uniform field on a flat square, so that the field's direction on the
// screen is known:
// - at 0.25, 1 and 4 pixels a cell, the rendered LIC stays correlated at least 3 times
//   longer along the field than across it (streaks, not moire), and seen from far it
//   keeps at least half the contrast it has at one cell a pixel (not grey);
// - at 4 pixels a cell, the mean gradient across cell borders is at most 1.2 times that
//   inside cells (no cell blocks);
// - on the square seen at a grazing angle, where the footprint crosses whole mipmap
//   levels, the mean gradient along the field across the level-change line is at most 1.2
//   times that of the rows around it.
// The other lookup modes are measured too and printed, for comparison. They open render
// windows (run under xvfb-run).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkOFBZoomMetrics.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 128;       // window pixels
constexpr int Resolution = 514; // 512 cells on the unit square
constexpr int MaxLag = 24;      // pixels of the correlation lengths
constexpr int Margin = 2;       // pixels left out at the window's sides

// The unit square at z = 0 with a uniform field at `angle` degrees from x (0: x, 90: y),
// its OFB and LIC, and a mapper that shows the LIC alone (LICIntensity 1, lighting off).
struct ZoomScene
{
  vtkSmartPointer<vtkPolyData> Surface;
  vtkNew<vtkOFBSampler> Sampler;
  vtkNew<vtkOFBLIC> LIC;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkOFB* OFB = nullptr;

  explicit ZoomScene(double angle)
  {
    const double radians = vtkMath::RadiansFromDegrees(angle);
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(0.0, 0.0, 0.0);
    plane->SetPoint1(1.0, 0.0, 0.0);
    plane->SetPoint2(0.0, 1.0, 0.0);
    plane->SetResolution(8, 8);
    plane->Update();
    this->Surface = plane->GetOutput();
    vtkNew<vtkDoubleArray> field;
    field->SetName("Field");
    field->SetNumberOfComponents(3);
    field->SetNumberOfTuples(this->Surface->GetNumberOfPoints());
    for (vtkIdType i = 0; i < this->Surface->GetNumberOfPoints(); ++i)
    {
      field->SetTuple3(i, std::cos(radians), std::sin(radians), 0.0);
    }
    this->Surface->GetPointData()->SetVectors(field);
    this->Sampler->SetInputData(this->Surface);
    this->Sampler->SetResolution(Resolution);
    this->LIC->SetInputConnection(this->Sampler->GetOutputPort());
    this->LIC->Update();
    this->OFB = this->LIC->GetOutput();

    this->Mapper->SetInputData(this->Surface);
    this->Mapper->SetOFBConnection(this->LIC->GetOutputPort());
    vtkOFBColoring* coloring = this->Mapper->GetColoring();
    coloring->SetIntensityArrayName("LIC");
    coloring->IntensityModulationOn();
    coloring->SetLICColorModeToBlend();
    coloring->SetLICIntensity(1.0);
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->LightingOff();
    this->Actor->GetProperty()->SetAmbient(1.0);
    this->Actor->GetProperty()->SetDiffuse(0.0);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window->SetSize(Size, Size);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
  }

  double CellSize() const { return this->OFB->GetCellSize(); }

  /// Parallel view from +z centred on (cx, cy) at `zoom` pixels a cell.
  void ViewFlat(double cx, double cy, double zoom)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(cx, cy, 2.0);
    camera->SetFocalPoint(cx, cy, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(0.5 * Size * this->CellSize() / zoom);
    this->Renderer->ResetCameraClippingRange();
  }

  /// Perspective view along +y at a grazing angle: the footprint grows up the window.
  void ViewGrazing()
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOff();
    camera->SetPosition(0.5, -0.05, 0.06);
    camera->SetFocalPoint(0.5, 0.45, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange();
  }

  vtkofbzoom::GreyImage Render()
  {
    this->Window->Render();
    EXPECT_TRUE(this->Mapper->GetLastRenderUsedOFB());
    return vtkofbzoom::Grab(this->Window);
  }

  /// The OFB grid position (level-0 cells, x and y) under pixel centre (i, j) of the
  /// grazing view, false where the pixel does not see the square.
  bool GridUnder(int i, int j, double g[2])
  {
    double ends[2][4];
    for (int e = 0; e < 2; ++e)
    {
      this->Renderer->SetDisplayPoint(i + 0.5, j + 0.5, e);
      this->Renderer->DisplayToWorld();
      this->Renderer->GetWorldPoint(ends[e]);
      for (int c = 0; c < 3; ++c)
      {
        ends[e][c] /= ends[e][3];
      }
    }
    const double dz = ends[1][2] - ends[0][2];
    if (std::abs(dz) < 1.0e-12)
    {
      return false;
    }
    const double t = -ends[0][2] / dz;
    const double x = ends[0][0] + t * (ends[1][0] - ends[0][0]);
    const double y = ends[0][1] + t * (ends[1][1] - ends[0][1]);
    if (t < 0.0 || x < 0.0 || x > 1.0 || y < 0.0 || y > 1.0)
    {
      return false;
    }
    const double* origin = this->OFB->GetOrigin();
    g[0] = (x - origin[0]) / this->CellSize();
    g[1] = (y - origin[1]) / this->CellSize();
    return true;
  }
};

// The display variants measured: a lookup mode, with or without a LIC per level.
struct Variant
{
  const char* Name;
  int Mode;
  bool LevelLIC;
};
const Variant Variants[] = {
  { "Nearest", vtkOFBPolyDataMapper::LOOKUP_NEAREST, false },
  { "NearestMipmapped", vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED, false },
  { "Smooth", vtkOFBPolyDataMapper::LOOKUP_SMOOTH, false },
  { "Smooth+LICPyramid", vtkOFBPolyDataMapper::LOOKUP_SMOOTH, true },
};

void Use(ZoomScene& scene, const Variant& variant)
{
  scene.Mapper->SetLookupMode(variant.Mode);
  if (variant.LevelLIC)
  {
    vtkNew<vtkOFBLICPyramid> pyramid;
    pyramid->SetLIC(scene.LIC);
    scene.Mapper->SetPyramid(pyramid);
  }
  else
  {
    scene.Mapper->SetPyramid(nullptr);
  }
}
}

TEST(OFBLICZoom, StreaksAndNoBlocksAtEveryZoom)
{
  ZoomScene scene(0.0); // the field along x: along the window's rows
  const double zooms[3] = { 0.25, 1.0, 4.0 };
  for (const Variant& variant : Variants)
  {
    Use(scene, variant);
    double contrast[3];
    for (int z = 0; z < 3; ++z)
    {
      // Far: the whole square; nearer: a part away from its sides.
      const double c = z == 0 ? 0.5 : 0.4;
      scene.ViewFlat(c, c + 0.01, zooms[z]);
      const vtkofbzoom::GreyImage image = scene.Render();
      const double along = vtkofbzoom::CorrelationLength(image, 1, 0, MaxLag, Margin);
      const double across = vtkofbzoom::CorrelationLength(image, 0, 1, MaxLag, Margin);
      const double ratio = along / std::max(across, 0.5);
      contrast[z] = vtkofbzoom::Contrast(image, Margin);
      std::printf("%-18s %5.2f px/cell: correlation length along %6.2f px, across %5.2f px, "
                  "ratio %5.2f, contrast %.3f\n",
        variant.Name,
        zooms[z],
        along,
        across,
        ratio,
        contrast[z]);
      if (z == 2)
      {
        // Cell borders of the grid that holds the square (Z): x and y at whole cells.
        const double s = scene.CellSize();
        const double* origin = scene.OFB->GetOrigin();
        const double cx = c;
        const double cy = c + 0.01;
        auto cellOf = [&](int p, double centre, double o)
        { return std::floor((centre + (p + 0.5 - 0.5 * Size) * s / zooms[z] - o) / s); };
        double border = 0.0;
        double inside = 0.0;
        const double blocks = vtkofbzoom::GradientRatio(
          image,
          [&](int i, int j, int i2, int j2)
          {
            const bool crosses = cellOf(i, cx, origin[0]) != cellOf(i2, cx, origin[0]) ||
              cellOf(j, cy, origin[1]) != cellOf(j2, cy, origin[1]);
            return crosses ? 1 : 2;
          },
          border,
          inside);
        std::printf("%-18s %5.2f px/cell: gradient across cell borders %.4f, inside cells "
                    "%.4f, ratio %.3f\n",
          variant.Name,
          zooms[z],
          border,
          inside,
          blocks);
        if (variant.LevelLIC)
        {
          EXPECT_LE(blocks, 1.2) << variant.Name;
        }
      }
      if (variant.LevelLIC)
      {
        EXPECT_GE(ratio, 3.0) << variant.Name << " at " << zooms[z] << " pixels a cell";
      }
    }
    std::printf("%-18s far contrast / contrast at 1 px/cell: %.3f\n",
      variant.Name,
      contrast[0] / std::max(contrast[1], 1.0e-9));
    if (variant.LevelLIC)
    {
      EXPECT_GE(contrast[0], 0.5 * contrast[1]) << "the LIC seen from far fades to grey";
    }
  }
}

TEST(OFBLICZoom, NoLineWhereTheMipmapLevelChanges)
{
  ZoomScene scene(90.0); // the field along y: up the window in the grazing view
  scene.ViewGrazing();
  scene.Window->Render();
  // The footprint of every pixel (log2 of level-0 cells a pixel, as the shader computes it
  // from the derivatives of the grid position), -inf where the square is not seen.
  std::vector<double> lod(static_cast<size_t>(Size) * Size, -HUGE_VAL);
  std::vector<double> gx(lod.size());
  std::vector<double> gy(lod.size());
  std::vector<char> seen(lod.size(), 0);
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      double g[2];
      const size_t k = static_cast<size_t>(j) * Size + i;
      seen[k] = scene.GridUnder(i, j, g);
      gx[k] = g[0];
      gy[k] = g[1];
    }
  }
  double lowest = HUGE_VAL;
  double highest = -HUGE_VAL;
  for (int j = 0; j + 1 < Size; ++j)
  {
    for (int i = 0; i + 1 < Size; ++i)
    {
      const size_t k = static_cast<size_t>(j) * Size + i;
      if (seen[k] && seen[k + 1] && seen[k + Size])
      {
        const double dx = std::hypot(gx[k + 1] - gx[k], gy[k + 1] - gy[k]);
        const double dy = std::hypot(gx[k + Size] - gx[k], gy[k + Size] - gy[k]);
        lod[k] = std::log2(std::max(std::max(dx, dy), 1.0e-6));
        lowest = std::min(lowest, lod[k]);
        highest = std::max(highest, lod[k]);
      }
    }
  }
  std::printf("grazing view: footprint from %.2f to %.2f (log2 cells a pixel)\n", lowest, highest);
  ASSERT_LT(std::floor(lowest + 0.5), std::floor(highest - 0.5)) << "no whole level crossed";

  for (const Variant& variant : Variants)
  {
    if (variant.Mode == vtkOFBPolyDataMapper::LOOKUP_NEAREST)
    {
      continue; // no levels
    }
    Use(scene, variant);
    const vtkofbzoom::GreyImage image = scene.Render();
    // Where the level read changes: at whole levels for the blended lookups (the pair of
    // levels), half-way for the nearest level.
    const double offset =
      variant.Mode == vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED ? 0.5 : 0.0;
    auto levelOf = [&](int i, int j)
    {
      const double l = lod[static_cast<size_t>(j) * Size + i];
      return std::isfinite(l) ? std::floor(std::max(l, 0.0) + offset) : -1.0;
    };
    // Rows from each vertical pair to the nearest level change in its column.
    std::vector<int> distance(lod.size(), 1 << 20);
    for (int i = 0; i < Size; ++i)
    {
      for (int j = 0; j + 1 < Size; ++j)
      {
        const double a = levelOf(i, j);
        const double b = levelOf(i, j + 1);
        if (a >= 0.0 && b >= 0.0 && a != b)
        {
          for (int d = -12; d <= 12; ++d)
          {
            if (j + d >= 0 && j + d < Size)
            {
              int& slot = distance[static_cast<size_t>(j + d) * Size + i];
              slot = std::min(slot, std::abs(d));
            }
          }
        }
      }
    }
    double line = 0.0;
    double around = 0.0;
    const double ratio = vtkofbzoom::GradientRatio(
      image,
      [&](int i, int j, int i2, int j2)
      {
        if (i2 != i || levelOf(i, j) < 0.0 || levelOf(i2, j2) < 0.0 || i < Margin ||
          i >= Size - Margin)
        {
          return 0; // vertical pairs (along the field) on the square only
        }
        const int d = distance[static_cast<size_t>(j) * Size + i];
        return d <= 1 ? 1 : (d >= 3 && d <= 10 ? 2 : 0);
      },
      line,
      around);
    std::printf("%-18s level change: gradient along the field across it %.4f, around it %.4f, "
                "ratio %.3f\n",
      variant.Name,
      line,
      around,
      ratio);
    if (variant.LevelLIC)
    {
      EXPECT_GT(around, 0.0);
      EXPECT_LE(ratio, 1.2) << variant.Name;
    }
  }
}

TEST(OFBLICZoom, AutomaticLookupIsSmoothForALICAndNearestForPaint)
{
  ZoomScene scene(0.0);
  scene.ViewFlat(0.4, 0.41, 4.0);
  EXPECT_EQ(scene.Mapper->GetLookupMode(), vtkOFBPolyDataMapper::LOOKUP_AUTOMATIC);
  const vtkofbzoom::GreyImage automatic = scene.Render();
  EXPECT_EQ(scene.Mapper->GetResolvedLookupMode(), vtkOFBPolyDataMapper::LOOKUP_SMOOTH);
  // The OFB comes straight from a vtkOFBLIC: a LIC per level (AutomaticLevelLIC).
  EXPECT_TRUE(scene.Mapper->GetPyramid()->IsA("vtkOFBLICPyramid"));
  scene.Mapper->SetLookupModeToSmooth();
  const vtkofbzoom::GreyImage smooth = scene.Render();
  EXPECT_FALSE(scene.Mapper->GetPyramid()->IsA("vtkOFBLICPyramid"));
  EXPECT_EQ(automatic.Values, smooth.Values); // close up, both read level 0 alone
  scene.Mapper->SetLookupModeToAutomatic();
  scene.Mapper->GetColoring()->IntensityModulationOff();
  scene.Render();
  EXPECT_EQ(scene.Mapper->GetResolvedLookupMode(), vtkOFBPolyDataMapper::LOOKUP_NEAREST);
}

TEST(OFBLICZoom, NoBeadsAlongDiagonalStreaks)
{
  // Streaks at an angle to the grid, close up: the bilinear interpolation of the Smooth
  // lookup modulates them along their length (beads of one cell along x and y on a
  // diagonal, stair steps near an axis). The roughness along the streaks (the second
  // difference at lags of 1 pixel to a cell, vtkofbzoom::Roughness) over that across them
  // (the streaks' own detail), at 45, 30 and 15 degrees, 4 and 6 pixels a cell: the
  // flow-aligned filter (the default) keeps it at most 0.05; without the filter it is
  // larger (the measure sees the defect). The filter must not blur across the streaks: at
  // 45 and 0 degrees the roughness across them stays within 10 % of the unfiltered one.
  // (The streaks of a uniform field are straight along it, so an average along the field
  // changes only what varies along them: at 15 and 30 degrees it also removes the stair
  // steps, which the roughness across counts too.) At 0 degrees nothing is to be removed.
  for (const double angle : { 45.0, 30.0, 15.0, 0.0 })
  {
    ZoomScene scene(angle);
    EXPECT_TRUE(scene.Mapper->GetFlowAlignedFiltering());
    const double radians = vtkMath::RadiansFromDegrees(angle);
    const double c = std::cos(radians);
    const double s = std::sin(radians);
    for (const double zoom : { 4.0, 6.0 })
    {
      scene.ViewFlat(0.4, 0.41, zoom);
      const int lags = static_cast<int>(zoom);
      double beads[2];
      double across[2];
      for (const bool filter : { false, true })
      {
        scene.Mapper->SetFlowAlignedFiltering(filter);
        const vtkofbzoom::GreyImage image = scene.Render();
        EXPECT_EQ(std::string(scene.Mapper->GetResolvedFlowArrayName()), filter ? "Field" : "");
        const double along = vtkofbzoom::Roughness(image, c, s, lags, Margin);
        across[filter] = vtkofbzoom::Roughness(image, -s, c, lags, Margin);
        beads[filter] = along / std::max(across[filter], 1.0e-12);
        std::printf("%2.0f degrees, %.0f px/cell, %-11s: roughness along / across the streaks "
                    "%.4f (across %.4f)\n",
          angle,
          zoom,
          filter ? "flow filter" : "no filter",
          beads[filter],
          across[filter]);
      }
      EXPECT_LE(beads[1], beads[0] + 1.0e-3) << angle << " degrees, " << zoom << " px a cell";
      if (angle == 45.0 || angle == 0.0)
      {
        EXPECT_GE(across[1], 0.9 * across[0])
          << "the flow filter blurs across the streaks at " << angle << " degrees";
      }
      if (angle > 0.0)
      {
        EXPECT_GT(beads[0], 0.05) << "the measure does not see the beads without the filter";
        EXPECT_LE(beads[1], 0.05) << "beads along streaks at " << angle << " degrees, " << zoom
                                  << " px a cell";
      }
    }
  }
}

TEST(OFBLICZoom, FlowFilterFieldChoice)
{
  // The field of the flow-aligned filter: the LIC's (here the active vectors "Field"),
  // else FlowArrayName; a missing or 1-component array, another lookup or no intensity
  // turn the filter off without an error, and the surface still renders from the OFB.
  ZoomScene scene(45.0);
  scene.ViewFlat(0.4, 0.41, 4.0);
  scene.Render();
  EXPECT_STREQ(scene.Mapper->GetResolvedFlowArrayName(), "Field");
  const vtkofbzoom::GreyImage filtered = scene.Render();
  scene.Mapper->SetFlowArrayName("LIC"); // one component
  scene.Render();
  EXPECT_STREQ(scene.Mapper->GetResolvedFlowArrayName(), "");
  scene.Mapper->SetFlowArrayName("NoSuchArray");
  const vtkofbzoom::GreyImage unfiltered = scene.Render();
  EXPECT_STREQ(scene.Mapper->GetResolvedFlowArrayName(), "");
  EXPECT_NE(filtered.Values, unfiltered.Values);
  scene.Mapper->SetFlowArrayName("Field");
  EXPECT_EQ(scene.Render().Values, filtered.Values);
  EXPECT_STREQ(scene.Mapper->GetResolvedFlowArrayName(), "Field");
  scene.Mapper->SetMaximumFlowFilterOffset(-1.0); // clamped to 0: off
  EXPECT_EQ(scene.Mapper->GetMaximumFlowFilterOffset(), 0.0);
  EXPECT_EQ(scene.Render().Values, unfiltered.Values);
  scene.Mapper->SetMaximumFlowFilterOffset(2.0);
  scene.Mapper->SetLookupModeToNearest();
  scene.Render();
  EXPECT_STREQ(scene.Mapper->GetResolvedFlowArrayName(), "");
  scene.Mapper->SetLookupModeToAutomatic();
  scene.Mapper->GetColoring()->IntensityModulationOff();
  scene.Render();
  EXPECT_STREQ(scene.Mapper->GetResolvedFlowArrayName(), "");
  // From far (no cell over 0.7 pixels), the shader without the filter: the same picture.
  scene.Mapper->GetColoring()->IntensityModulationOn();
  scene.ViewFlat(0.5, 0.51, 0.25);
  const vtkofbzoom::GreyImage far = scene.Render();
  scene.Mapper->FlowAlignedFilteringOff();
  EXPECT_EQ(scene.Render().Values, far.Values);
  scene.Mapper->FlowAlignedFilteringOn();
  std::ostringstream printed;
  scene.Mapper->Print(printed);
  for (const char* setting :
    { "FlowAlignedFiltering: On", "MaximumFlowFilterOffset: 2", "FlowArrayName: \"Field\"" })
  {
    EXPECT_NE(printed.str().find(setting), std::string::npos) << setting;
  }
}
