// vtkOFBPainter's and vtkOFBPaintFilter's symmetric painting (MirrorX/Y/Z, MirrorOrigin):
// each dab also painted at its reflections, against the same dabs placed by hand.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPaintFilter.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace vtkofbtest;

namespace
{
/// A sphere of radius 1 about `centre` (symmetric about the planes through it).
vtkSmartPointer<vtkOFB> SphereOFB(const double centre[3])
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 96);
  vtkPoints* points = sphere->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + centre[0], p[1] + centre[1], p[2] + centre[2]);
  }
  return Build(sphere, 64);
}

std::vector<unsigned char> ColorsOf(vtkOFB* ofb)
{
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  if (!colors)
  {
    return {};
  }
  const unsigned char* p = colors->GetPointer(0);
  return std::vector<unsigned char>(p, p + 4 * colors->GetNumberOfTuples());
}

/// A painter on `ofb` with a red brush of radius 0.3.
vtkSmartPointer<vtkOFBPainter> RedPainter(vtkOFB* ofb)
{
  auto painter = vtkSmartPointer<vtkOFBPainter>::New();
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.3);
  painter->GetBrush()->SetColor(1.0, 0.0, 0.0);
  painter->GetBrush()->SetStrength(0.7);
  return painter;
}

/// The reflection of p in the planes through o across the axes of the bits of m.
void Reflect(const double p[3], const double o[3], int m, double out[3])
{
  for (int a = 0; a < 3; ++a)
  {
    out[a] = (m & (1 << a)) ? 2.0 * o[a] - p[a] : p[a];
  }
}

/// The number of samples whose colour differs between a and b.
vtkIdType Differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  vtkIdType n = 0;
  for (std::size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4)
  {
    n += std::memcmp(&a[i], &b[i], 4) != 0 ? 1 : 0;
  }
  return n;
}
}

//------------------------------------------------------------------------------
TEST(PainterMirror, ADabIsPaintedWithItsReflections)
{
  const double o[3] = { 0.25, -0.5, 2.0 };
  // A point on the sphere away from every mirror plane through its centre.
  const double p[3] = { o[0] + 0.6, o[1] + 0.48, o[2] + 0.64 };
  for (int axes : { 1, 2, 4, 3, 7 })
  {
    vtkSmartPointer<vtkOFB> mirrored = SphereOFB(o);
    vtkSmartPointer<vtkOFB> byHand = SphereOFB(o);
    vtkSmartPointer<vtkOFBPainter> painter = RedPainter(mirrored);
    painter->SetMirrorX((axes & 1) != 0);
    painter->SetMirrorY((axes & 2) != 0);
    painter->SetMirrorZ((axes & 4) != 0);
    painter->SetMirrorOrigin(o[0], o[1], o[2]);
    const vtkIdType changed = painter->Dab(p);

    // The same dabs placed one by one, in the painter's order, without mirroring.
    vtkSmartPointer<vtkOFBPainter> reference = RedPainter(byHand);
    vtkNew<vtkPoints> centres;
    for (int m = 0; m < 8; ++m)
    {
      if ((m & axes) == m)
      {
        double q[3];
        Reflect(p, o, m, q);
        centres->InsertNextPoint(q);
      }
    }
    const vtkIdType expected = reference->Dabs(centres);
    EXPECT_GT(expected, 0);
    EXPECT_EQ(changed, expected) << "axes " << axes;
    EXPECT_EQ(Differing(ColorsOf(mirrored), ColorsOf(byHand)), 0) << "axes " << axes;
    // One image for each combination of the axes set.
    EXPECT_EQ(centres->GetNumberOfPoints(),
      vtkIdType(1) << ((axes & 1) + ((axes >> 1) & 1) + ((axes >> 2) & 1)));
  }
}

//------------------------------------------------------------------------------
TEST(PainterMirror, ReflectionsAreListedInPaintingOrderWithoutRepeats)
{
  vtkNew<vtkOFBPainter> painter;
  double q[21];
  int axes[7];
  const double p[3] = { 1.0, 2.0, 3.0 };
  EXPECT_EQ(painter->GetMirrorReflections(p, q, axes), 0) << "no mirror";
  painter->MirrorXOn();
  painter->MirrorZOn();
  painter->SetMirrorOrigin(0.5, 0.0, 1.0);
  ASSERT_EQ(painter->GetMirrorReflections(p, q, axes), 3);
  const double expected[9] = { 0.0, 2.0, 3.0, 1.0, 2.0, -1.0, 0.0, 2.0, -1.0 };
  const int expectedAxes[3] = { 1, 4, 5 };
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(axes[k], expectedAxes[k]);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(q[3 * k + a], expected[3 * k + a]);
    }
  }
  // On the plane x = 0.5: the x reflection is the point itself, xz repeats z.
  const double onPlane[3] = { 0.5, 2.0, 3.0 };
  ASSERT_EQ(painter->GetMirrorReflections(onPlane, q, axes), 1);
  EXPECT_EQ(axes[0], 4);
  EXPECT_EQ(q[2], -1.0);
}

//------------------------------------------------------------------------------
TEST(PainterMirror, ADabOnTheMirrorPlaneIsPaintedOnce)
{
  const double o[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> mirrored = SphereOFB(o);
  vtkSmartPointer<vtkOFB> single = SphereOFB(o);
  vtkSmartPointer<vtkOFBPainter> painter = RedPainter(mirrored);
  painter->MirrorXOn();
  const double p[3] = { 0.0, 0.6, 0.8 }; // x = 0: its reflection is itself
  painter->Dab(p);
  RedPainter(single)->Dab(p);
  EXPECT_EQ(Differing(ColorsOf(mirrored), ColorsOf(single)), 0)
    << "a strength below 1 shows a second application";
}

//------------------------------------------------------------------------------
TEST(PainterMirror, AMirroredStrokeUndoesAsOneStepAndSmearsOnBothSides)
{
  const double o[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(o);
  vtkSmartPointer<vtkOFBPainter> painter = RedPainter(ofb);
  const std::vector<unsigned char> initial = ColorsOf(ofb);
  painter->MirrorXOn();
  // A stroke on the x > 0 side, far enough from x = 0 that the two sides do not meet.
  painter->BeginStroke();
  painter->StrokeTo(0.8, 0.6, 0.0);
  painter->StrokeTo(0.8, 0.0, 0.6);
  painter->EndStroke();
  const std::vector<unsigned char> painted = ColorsOf(ofb);
  EXPECT_GT(Differing(initial, painted), 0);
  EXPECT_EQ(painter->GetNumberOfUndoSteps(), 1);
  painter->Undo();
  EXPECT_EQ(Differing(initial, ColorsOf(ofb)), 0) << "undo restores both sides";
  painter->Redo();
  EXPECT_EQ(Differing(painted, ColorsOf(ofb)), 0);

  // Smear: the stroke and its reflection carry colour as two separate strokes would.
  vtkSmartPointer<vtkOFB> smeared = SphereOFB(o);
  vtkSmartPointer<vtkOFB> twoStrokes = SphereOFB(o);
  for (vtkOFB* target : { smeared.GetPointer(), twoStrokes.GetPointer() })
  {
    vtkSmartPointer<vtkOFBPainter> base = RedPainter(target);
    base->MirrorXOn();
    base->Dab(0.8, 0.0, 0.6); // red on both sides, to be smeared
  }
  vtkSmartPointer<vtkOFBPainter> smear = RedPainter(smeared);
  smear->MirrorXOn();
  smear->GetBrush()->SetTargetToSmear();
  smear->GetBrush()->SetSmearAmount(0.8);
  vtkSmartPointer<vtkOFBPainter> plain = RedPainter(twoStrokes);
  plain->GetBrush()->SetTargetToSmear();
  plain->GetBrush()->SetSmearAmount(0.8);
  smear->BeginStroke();
  smear->StrokeTo(0.8, 0.0, 0.6);
  smear->StrokeTo(0.8, 0.6, 0.0);
  smear->EndStroke();
  for (double sign : { 1.0, -1.0 })
  {
    plain->BeginStroke();
    plain->StrokeTo(sign * 0.8, 0.0, 0.6);
    plain->StrokeTo(sign * 0.8, 0.6, 0.0);
    plain->EndStroke();
  }
  EXPECT_EQ(Differing(ColorsOf(smeared), ColorsOf(twoStrokes)), 0);
}

//------------------------------------------------------------------------------
TEST(PainterMirror, ThePaintFilterMirrorsItsStrokes)
{
  const double o[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(o);
  auto strokes = [](std::initializer_list<double> xs)
  {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (double x : xs)
    {
      lines->InsertNextCell(2);
      lines->InsertCellPoint(points->InsertNextPoint(x, 0.6, 0.0));
      lines->InsertCellPoint(points->InsertNextPoint(x, 0.0, 0.6));
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetLines(lines);
    return poly;
  };
  auto paint = [&](vtkPolyData* input, bool mirror)
  {
    vtkNew<vtkOFBPaintFilter> filter;
    filter->SetInputData(ofb);
    filter->SetStrokesData(input);
    filter->GetBrush()->SetRadius(0.3);
    filter->GetBrush()->SetColor(0.0, 0.0, 1.0);
    filter->GetPainter()->SetMirrorX(mirror);
    filter->Update();
    return ColorsOf(filter->GetOutput());
  };
  const std::vector<unsigned char> mirrored = paint(strokes({ 0.8 }), true);
  const std::vector<unsigned char> byHand = paint(strokes({ 0.8, -0.8 }), false);
  EXPECT_GT(Differing(ColorsOf(ofb), mirrored), 0);
  EXPECT_EQ(Differing(mirrored, byHand), 0);
  EXPECT_GT(Differing(paint(strokes({ 0.8 }), false), mirrored), 0);
}

//------------------------------------------------------------------------------
TEST(PainterMirror, ANonFiniteOriginIsAnError)
{
  const double o[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(o);
  vtkSmartPointer<vtkOFBPainter> painter = RedPainter(ofb);
  const std::vector<unsigned char> initial = ColorsOf(ofb);
  vtkNew<MessageObserver> messages;
  messages->Watch(painter);
  painter->MirrorYOn();
  painter->SetMirrorOrigin(0.0, std::nan(""), 0.0);
  EXPECT_EQ(painter->Dab(0.8, 0.6, 0.0), 0);
  EXPECT_NE(messages->Errors.find("MirrorOrigin is not finite"), std::string::npos);
  EXPECT_EQ(Differing(initial, ColorsOf(ofb)), 0);
  // Without a mirror the origin is not used.
  painter->MirrorYOff();
  EXPECT_GT(painter->Dab(0.8, 0.6, 0.0), 0);
}
