// Strokes that follow the surface: sparse stroke points on a pipe paint a continuous line
// around the wall (vtkOFBPainter::StrokeTo and vtkOFBPaintFilter polylines), points off
// the surface are moved onto it, and a stroke turns a cube's edge.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPaintFilter.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vtkofbtest;

namespace
{
vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}

/// An open pipe of radius 1 about the y axis, y in [-2, 2] (no caps).
vtkSmartPointer<vtkOFB> MakePipeOFB()
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(1.0);
  cylinder->SetHeight(4.0);
  cylinder->SetResolution(256);
  cylinder->CappingOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cylinder->GetOutputPort());
  triangles->Update();
  return Build(triangles->GetOutput(), 96);
}

/// The point of the pipe's wall at `degrees` about the axis (from +x towards -z), height
/// y, at `radius` from the axis.
void OnPipe(double degrees, double y, double radius, double p[3])
{
  const double a = vtkMath::RadiansFromDegrees(degrees);
  p[0] = radius * std::cos(a);
  p[1] = y;
  p[2] = -radius * std::sin(a);
}

/// The angle of x about the pipe's axis in degrees, in [0, 360).
double AngleOf(const double x[3])
{
  const double a = vtkMath::DegreesFromRadians(std::atan2(-x[2], x[0]));
  return a < 0.0 ? a + 360.0 : a;
}

/// Counts of the samples near the ring y = 0 between two angles: those within half the
/// brush radius of it (all must be painted), and those painted farther from it than the
/// radius and a cell (none may be).
struct RingCheck
{
  vtkIdType Near = 0;
  vtkIdType NearUnpainted = 0;
  vtkIdType PaintedFar = 0;
};

RingCheck CheckRing(vtkOFB* ofb,
  const std::vector<unsigned char>& before,
  double fromDegrees,
  double toDegrees,
  double radius)
{
  RingCheck check;
  const unsigned char* now = Colors(ofb)->GetPointer(0);
  const double s = ofb->GetCellSize();
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const bool painted = std::equal(now + 4 * i, now + 4 * i + 4, before.data() + 4 * i) == false;
    const double angle = AngleOf(x);
    // Arc length along the wall outside [from, to], in radians of a unit pipe (the angle
    // taken once round either way too).
    double outsideDegrees = 360.0;
    for (double a : { angle - 360.0, angle, angle + 360.0 })
    {
      outsideDegrees = std::min(outsideDegrees, std::max({ fromDegrees - a, a - toDegrees, 0.0 }));
    }
    const double outside = vtkMath::RadiansFromDegrees(outsideDegrees);
    const double distance = std::sqrt(x[1] * x[1] + outside * outside);
    if (std::abs(x[1]) < 0.5 * radius && outside == 0.0)
    {
      ++check.Near;
      check.NearUnpainted += painted ? 0 : 1;
    }
    if (painted && distance > radius + s)
    {
      ++check.PaintedFar;
    }
  }
  return check;
}

/// The largest distance from a dab centre to the pipe's wall.
double LargestDistanceToPipe(vtkPoints* dabs)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < dabs->GetNumberOfPoints(); ++i)
  {
    double p[3];
    dabs->GetPoint(i, p);
    largest = std::max(largest, std::abs(std::hypot(p[0], p[2]) - 1.0));
  }
  return largest;
}

/// The largest distance from a dab centre to the surface of the cube [-1, 1]^3.
double LargestDistanceToCube(vtkPoints* dabs)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < dabs->GetNumberOfPoints(); ++i)
  {
    double p[3];
    dabs->GetPoint(i, p);
    const double inside = 1.0 - std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
    largest = std::max(largest, std::abs(inside));
  }
  return largest;
}

std::vector<unsigned char> Copy(vtkOFB* ofb)
{
  const unsigned char* c = Colors(ofb)->GetPointer(0);
  return std::vector<unsigned char>(c, c + 4 * ofb->GetNumberOfSamples());
}

/// Paint a stroke through `points` with a painter (radius 0.1, opaque red).
vtkSmartPointer<vtkOFBPainter> PaintStroke(vtkOFB* ofb,
  const std::vector<std::vector<double>>& points,
  bool followSurface)
{
  auto painter = vtkSmartPointer<vtkOFBPainter>::New();
  painter->SetOFB(ofb);
  painter->SetFollowSurface(followSurface);
  painter->GetBrush()->SetRadius(0.1);
  painter->GetBrush()->SetColor(1.0, 0.0, 0.0, 1.0);
  painter->GetBrush()->SetStrength(1.0);
  painter->BeginStroke();
  for (const auto& p : points)
  {
    painter->StrokeTo(p.data());
  }
  painter->EndStroke();
  return painter;
}

std::vector<std::vector<double>> RingPoints(const std::vector<double>& degrees, double radius)
{
  std::vector<std::vector<double>> points;
  for (double d : degrees)
  {
    std::vector<double> p(3);
    OnPipe(d, 0.0, radius, p.data());
    points.push_back(p);
  }
  return points;
}
}

//------------------------------------------------------------------------------
TEST(StrokeSurface, SparsePointsOnAPipePaintAContinuousLine)
{
  // Four points a quarter turn apart (1.41 apart, 14 brush radii): the chords between
  // them cross the inside of the pipe; the stroke must go around the wall.
  vtkSmartPointer<vtkOFB> pipe = MakePipeOFB();
  const std::vector<unsigned char> before = Copy(pipe);
  const auto points = RingPoints({ 0.0, 90.0, 180.0, 270.0 }, 1.0);

  vtkNew<vtkOFB> followed;
  followed->DeepCopy(pipe);
  vtkSmartPointer<vtkOFBPainter> painter = PaintStroke(followed, points, true);
  const RingCheck ring = CheckRing(followed, before, 0.0, 270.0, 0.1);
  EXPECT_GT(ring.Near, 150);
  EXPECT_EQ(ring.NearUnpainted, 0) << "of " << ring.Near << " samples along the wall";
  EXPECT_EQ(ring.PaintedFar, 0);
  EXPECT_LT(LargestDistanceToPipe(painter->GetStrokeDabs()), 0.25 * pipe->GetCellSize());

  // The same points joined by chords (FollowSurface off) leave most of the ring unpainted
  // and place dabs inside the pipe: what the check above catches.
  vtkNew<vtkOFB> chords;
  chords->DeepCopy(pipe);
  vtkSmartPointer<vtkOFBPainter> straight = PaintStroke(chords, points, false);
  const RingCheck gaps = CheckRing(chords, before, 0.0, 270.0, 0.1);
  EXPECT_GT(gaps.NearUnpainted, gaps.Near / 2);
  EXPECT_GT(LargestDistanceToPipe(straight->GetStrokeDabs()), 0.2);
}

//------------------------------------------------------------------------------
TEST(StrokeSurface, OppositePointsGoAroundTheWall)
{
  // Two points on opposite sides of the pipe: the chord runs through the axis, where no
  // dab paints anything; the path goes half-way around the wall (either way).
  vtkSmartPointer<vtkOFB> pipe = MakePipeOFB();
  const std::vector<unsigned char> before = Copy(pipe);
  vtkSmartPointer<vtkOFBPainter> painter = PaintStroke(pipe, RingPoints({ 0.0, 180.0 }, 1.0), true);
  vtkPoints* dabs = painter->GetStrokeDabs();
  EXPECT_LT(LargestDistanceToPipe(dabs), 0.25 * pipe->GetCellSize());
  // Dabs every Spacing * radius = 0.025 along a half circle of length pi.
  EXPECT_GT(dabs->GetNumberOfPoints(), 0.9 * vtkMath::Pi() / 0.025);
  EXPECT_LT(dabs->GetNumberOfPoints(), 1.3 * vtkMath::Pi() / 0.025);
  double mid[3];
  dabs->GetPoint(dabs->GetNumberOfPoints() / 2, mid);
  const double a = AngleOf(mid);
  const RingCheck ring = a < 180.0 ? CheckRing(pipe, before, 0.0, 180.0, 0.1)
                                   : CheckRing(pipe, before, 180.0, 360.0, 0.1);
  EXPECT_EQ(ring.NearUnpainted, 0) << "of " << ring.Near;
  EXPECT_EQ(ring.PaintedFar, 0);
}

//------------------------------------------------------------------------------
TEST(StrokeSurface, PointsOffTheSurfaceAreMovedOntoIt)
{
  // Points given outside (radius 1.3) and inside (radius 0.7) the pipe paint the wall.
  vtkSmartPointer<vtkOFB> pipe = MakePipeOFB();
  const std::vector<unsigned char> before = Copy(pipe);
  auto points = RingPoints({ 0.0, 180.0 }, 1.3);
  const auto inside = RingPoints({ 90.0 }, 0.7);
  points.insert(points.begin() + 1, inside[0]);
  vtkSmartPointer<vtkOFBPainter> painter = PaintStroke(pipe, points, true);
  vtkPoints* dabs = painter->GetStrokeDabs();
  EXPECT_LT(LargestDistanceToPipe(dabs), 0.25 * pipe->GetCellSize());
  double first[3];
  dabs->GetPoint(0, first);
  EXPECT_NEAR(std::hypot(first[0], first[2]), 1.0, pipe->GetCellSize());
  const RingCheck ring = CheckRing(pipe, before, 0.0, 180.0, 0.1);
  EXPECT_EQ(ring.NearUnpainted, 0) << "of " << ring.Near;
  EXPECT_EQ(ring.PaintedFar, 0);
}

//------------------------------------------------------------------------------
TEST(StrokeSurface, PaintFilterPolylinesFollowThePipe)
{
  // vtkOFBPaintFilter places the painter's dabs: the same colours as StrokeTo.
  vtkSmartPointer<vtkOFB> pipe = MakePipeOFB();
  const std::vector<unsigned char> before = Copy(pipe);
  const auto points = RingPoints({ 0.0, 90.0, 180.0, 270.0 }, 1.0);
  auto strokes = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<int>(points.size()));
  for (const auto& p : points)
  {
    lines->InsertCellPoint(pts->InsertNextPoint(p.data()));
  }
  strokes->SetPoints(pts);
  strokes->SetLines(lines);
  vtkNew<vtkOFBPaintFilter> filter;
  filter->SetInputData(pipe);
  filter->SetStrokesData(strokes);
  filter->GetBrush()->SetRadius(0.1);
  filter->GetBrush()->SetColor(1.0, 0.0, 0.0, 1.0);
  filter->GetBrush()->SetStrength(1.0);
  filter->Update();
  vtkOFB* painted = filter->GetOutput();
  ASSERT_EQ(painted->GetNumberOfSamples(), pipe->GetNumberOfSamples());
  const RingCheck ring = CheckRing(painted, before, 0.0, 270.0, 0.1);
  EXPECT_GT(ring.Near, 150);
  EXPECT_EQ(ring.NearUnpainted, 0) << "of " << ring.Near;
  EXPECT_EQ(ring.PaintedFar, 0);

  vtkNew<vtkOFB> byPainter;
  byPainter->DeepCopy(pipe);
  PaintStroke(byPainter, points, true);
  EXPECT_EQ(Copy(painted), Copy(byPainter));

  // With the painter's FollowSurface off, the filter's strokes are chords again.
  filter->GetPainter()->FollowSurfaceOff();
  filter->Update();
  const RingCheck gaps = CheckRing(filter->GetOutput(), before, 0.0, 270.0, 0.1);
  EXPECT_GT(gaps.NearUnpainted, gaps.Near / 2);
}

//------------------------------------------------------------------------------
TEST(StrokeSurface, StrokesTurnACubesEdge)
{
  // From the centre of the top face to the centre of a side face: over the edge (a path
  // of length 2), not along the chord (1.41) through the inside.
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2.0);
  cube->SetYLength(2.0);
  cube->SetZLength(2.0);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  triangles->Update();
  vtkSmartPointer<vtkOFB> ofb = Build(triangles->GetOutput(), 64);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.1);
  painter->StrokeTo(0.0, 0.0, 1.0);
  painter->StrokeTo(1.0, 0.0, 0.0);
  painter->EndStroke();
  vtkPoints* dabs = painter->GetStrokeDabs();
  // Within a cell of the faces: the path's two-cell steps cut the edge's corner a little.
  EXPECT_LT(LargestDistanceToCube(dabs), ofb->GetCellSize());
  EXPECT_GT(dabs->GetNumberOfPoints(), 0.9 * 2.0 / 0.025);
  double last[3];
  dabs->GetPoint(dabs->GetNumberOfPoints() - 1, last);
  const double target[3] = { 1.0, 0.0, 0.0 };
  EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(last, target)), 0.03 + ofb->GetCellSize());
}
