// vtkOFBBrush and vtkOFBPainter: falloffs, blend modes against a brute-force
// reference over all samples, strokes, threads, undo/redo, smear, normals, bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTimeStamp.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <vector>

using namespace vtkofbtest;

namespace
{
// The falloffs' closed forms, written out again here (x = distance / radius).
double ClosedForm(int falloff, double x)
{
  if (x > 1.0)
  {
    return 0.0;
  }
  switch (falloff)
  {
    case vtkOFBBrush::FALLOFF_CONSTANT:
      return 1.0;
    case vtkOFBBrush::FALLOFF_LINEAR:
      return 1.0 - x;
    case vtkOFBBrush::FALLOFF_SMOOTH:
      return 1.0 - 3.0 * x * x + 2.0 * x * x * x;
    case vtkOFBBrush::FALLOFF_SPHERE:
      return std::sqrt(1.0 - x * x);
    case vtkOFBBrush::FALLOFF_ROOT:
      return std::sqrt(1.0 - x);
    case vtkOFBBrush::FALLOFF_SHARP:
      return (1.0 - x) * (1.0 - x);
    case vtkOFBBrush::FALLOFF_GAUSSIAN:
      return std::exp(-x * x / (2.0 / 9.0));
    default:
      return 0.0;
  }
}

// The blend modes of vtkOFBBrush's description, in double, on bytes.
void ReferenceBlend(const unsigned char dst[4],
  const double src[4],
  double g,
  int mode,
  const unsigned char initial[4],
  double out[4])
{
  double d[4], i0[4];
  for (int k = 0; k < 4; ++k)
  {
    d[k] = dst[k] / 255.0;
    i0[k] = initial[k] / 255.0;
    out[k] = d[k];
  }
  const double a = g * src[3];
  auto lerp = [](double x, double y, double t) { return x + t * (y - x); };
  switch (mode)
  {
    case vtkOFBBrush::BLEND_MIX:
    {
      const double ao = a + d[3] * (1.0 - a);
      for (int k = 0; k < 3 && ao > 0.0; ++k)
      {
        out[k] = (src[k] * a + d[k] * d[3] * (1.0 - a)) / ao;
      }
      out[3] = ao;
      return;
    }
    case vtkOFBBrush::BLEND_ERASE:
      for (int k = 0; k < 4; ++k)
      {
        out[k] = lerp(d[k], i0[k], g);
      }
      return;
    case vtkOFBBrush::BLEND_ERASE_ALPHA:
      out[3] = d[3] * (1.0 - g);
      return;
    default:
      break;
  }
  for (int k = 0; k < 3; ++k)
  {
    double f = 0.0;
    switch (mode)
    {
      case vtkOFBBrush::BLEND_ADD:
        f = std::min(1.0, d[k] + src[k]);
        break;
      case vtkOFBBrush::BLEND_SUBTRACT:
        f = std::max(0.0, d[k] - src[k]);
        break;
      case vtkOFBBrush::BLEND_MULTIPLY:
        f = d[k] * src[k];
        break;
      case vtkOFBBrush::BLEND_LIGHTEN:
        f = std::max(d[k], src[k]);
        break;
      default:
        f = std::min(d[k], src[k]);
        break;
    }
    out[k] = lerp(d[k], f, a);
  }
  out[3] = d[3] + (1.0 - d[3]) * a;
}

vtkSmartPointer<vtkOFB> SphereOFB(int resolution = 96)
{
  static std::map<int, vtkSmartPointer<vtkOFB>> cache;
  if (!cache[resolution])
  {
    cache[resolution] = Build(MakeSphere(1.0, 96), resolution);
  }
  auto copy = vtkSmartPointer<vtkOFB>::New();
  copy->DeepCopy(cache[resolution]);
  return copy;
}

vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}

// Random colours (alpha too) so that every blend mode has something to do.
void RandomColors(vtkOFB* ofb, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  vtkUnsignedCharArray* c = Colors(ofb);
  for (vtkIdType i = 0; i < 4 * c->GetNumberOfTuples(); ++i)
  {
    c->SetValue(i, static_cast<unsigned char>(random->GetNextRangeValue(0, 255.99)));
  }
}

std::vector<unsigned char> Copy(vtkUnsignedCharArray* c)
{
  return std::vector<unsigned char>(
    c->GetPointer(0), c->GetPointer(0) + 4 * c->GetNumberOfTuples());
}

// Check one dab against the brute-force reference over every sample: inside the
// radius within one step of 255 of the reference, outside it bit for bit unchanged.
void ExpectDabMatchesReference(vtkOFB* ofb,
  vtkOFBBrush* brush,
  const std::vector<unsigned char>& before,
  const std::vector<unsigned char>& initial,
  const double c[3],
  vtkIdType changed)
{
  vtkUnsignedCharArray* colors = Colors(ofb);
  const double* bc = brush->GetColor();
  const double src[4] = { bc[0], bc[1], bc[2], bc[3] };
  const double r = brush->GetRadius();
  vtkIdType differing = 0, inside = 0, worst = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const double d = std::sqrt(vtkMath::Distance2BetweenPoints(x, c));
    const unsigned char* now = colors->GetPointer(4 * i);
    const unsigned char* was = before.data() + 4 * i;
    differing += std::memcmp(now, was, 4) != 0;
    if (d > r * (1.0 + 1e-9))
    {
      ASSERT_EQ(std::memcmp(now, was, 4), 0) << "sample " << i << " outside the radius changed";
      continue;
    }
    ++inside;
    const double g = brush->GetStrength() * ClosedForm(brush->GetFalloff(), d / r);
    double ref[4];
    ReferenceBlend(was, src, g, brush->GetBlendMode(), initial.data() + 4 * i, ref);
    for (int k = 0; k < 4; ++k)
    {
      const double expected = std::min(1.0, std::max(0.0, ref[k])) * 255.0;
      const double diff = std::abs(now[k] - expected);
      ASSERT_LE(diff, 0.5 + 1e-3) << vtkOFBBrush::GetBlendModeAsString(brush->GetBlendMode())
                                  << " sample " << i << " component " << k;
      worst = std::max<vtkIdType>(worst, static_cast<vtkIdType>(diff > 0.5));
    }
  }
  EXPECT_GT(inside, 50);
  EXPECT_EQ(changed, differing);
}
}

//------------------------------------------------------------------------------
TEST(Brush, FalloffsMatchClosedForms)
{
  vtkNew<vtkOFBBrush> brush;
  for (int f = vtkOFBBrush::FALLOFF_CONSTANT; f <= vtkOFBBrush::FALLOFF_GAUSSIAN; ++f)
  {
    brush->SetFalloff(f);
    for (int i = 0; i <= 1000; ++i)
    {
      const double x = i / 1000.0;
      EXPECT_NEAR(brush->EvaluateFalloff(x), ClosedForm(f, x), 1e-6)
        << vtkOFBBrush::GetFalloffAsString(f) << " at " << x;
    }
    EXPECT_EQ(brush->EvaluateFalloff(1.0001), 0.0);
    EXPECT_EQ(brush->EvaluateFalloff(std::nan("")), 0.0);
  }
  // Custom: a piecewise linear curve through (0, 1), (0.5, 0.2), (1, 0).
  vtkNew<vtkPiecewiseFunction> curve;
  curve->AddPoint(0.0, 1.0);
  curve->AddPoint(0.5, 0.2);
  curve->AddPoint(1.0, 0.0);
  brush->SetCustomFalloff(curve);
  brush->SetFalloffToCustom();
  for (int i = 0; i <= 1000; ++i)
  {
    const double x = i / 1000.0;
    const double expected = x <= 0.5 ? 1.0 - 1.6 * x : 0.2 - 0.4 * (x - 0.5);
    EXPECT_NEAR(brush->EvaluateFalloff(x), expected, 1e-6) << "custom at " << x;
  }
  EXPECT_STREQ(vtkOFBBrush::GetFalloffAsString(vtkOFBBrush::FALLOFF_ROOT), "Root");
}

//------------------------------------------------------------------------------
TEST(Brush, ColorAndRadiusSettings)
{
  vtkNew<vtkOFBBrush> brush;
  brush->SetColor(0.1, 0.2, 0.3, 0.4);
  brush->SetColor(0.5, 0.6, 0.7);
  EXPECT_DOUBLE_EQ(brush->GetColor()[0], 0.5);
  EXPECT_DOUBLE_EQ(brush->GetOpacity(), 0.4);
  brush->SetOpacity(0.9);
  EXPECT_DOUBLE_EQ(brush->GetColor()[3], 0.9);
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(64);
  brush->SetRadiusInCells(5.0, ofb);
  EXPECT_DOUBLE_EQ(brush->GetRadius(), 5.0 * ofb->GetCellSize());
  vtkNew<MessageObserver> messages;
  messages->Watch(brush);
  vtkNew<vtkOFB> empty;
  brush->SetRadiusInCells(3.0, empty);
  EXPECT_NE(messages->Errors.find("empty"), std::string::npos);
  EXPECT_DOUBLE_EQ(brush->GetRadius(), 5.0 * ofb->GetCellSize());
}

//------------------------------------------------------------------------------
TEST(Painter, EveryBlendModeAndFalloffMatchesBruteForce)
{
  for (int mode = vtkOFBBrush::BLEND_MIX; mode <= vtkOFBBrush::BLEND_ERASE_ALPHA; ++mode)
  {
    for (int falloff = vtkOFBBrush::FALLOFF_CONSTANT; falloff <= vtkOFBBrush::FALLOFF_GAUSSIAN;
         ++falloff)
    {
      if (mode != vtkOFBBrush::BLEND_MIX && falloff != vtkOFBBrush::FALLOFF_SMOOTH &&
        falloff != vtkOFBBrush::FALLOFF_ROOT)
      {
        continue; // every falloff with Mix, two with the other modes
      }
      vtkSmartPointer<vtkOFB> ofb = SphereOFB();
      RandomColors(ofb, 7 + mode);
      const std::vector<unsigned char> initial = Copy(Colors(ofb));
      vtkNew<vtkOFBPainter> painter;
      painter->SetOFB(ofb);
      vtkOFBBrush* brush = painter->GetBrush();
      brush->SetRadius(0.3);
      brush->SetColor(0.9, 0.3, 0.6, 0.8);
      brush->SetStrength(0.75);
      brush->SetFalloff(falloff);
      if (mode == vtkOFBBrush::BLEND_ERASE)
      {
        // Paint first, so that there is something to erase back to the initial colours.
        double c0[3];
        OnSphere(0.4, 1.2, c0);
        brush->SetBlendModeToMix();
        ASSERT_GT(painter->Dab(c0), 0);
      }
      brush->SetBlendMode(mode);
      const std::vector<unsigned char> before = Copy(Colors(ofb));
      double c[3];
      OnSphere(0.5, 1.1, c);
      const vtkIdType changed = painter->Dab(c);
      EXPECT_GT(changed, 0) << vtkOFBBrush::GetBlendModeAsString(mode);
      ExpectDabMatchesReference(ofb, brush, before, initial, c, changed);
      if (HasFatalFailure())
      {
        return;
      }
    }
  }
}

//------------------------------------------------------------------------------
TEST(Painter, CustomFalloffMatchesBruteForce)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB();
  RandomColors(ofb, 3);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  vtkOFBBrush* brush = painter->GetBrush();
  vtkNew<vtkPiecewiseFunction> curve;
  curve->AddPoint(0.0, 0.3);
  curve->AddPoint(0.4, 1.0);
  curve->AddPoint(1.0, 0.0);
  brush->SetCustomFalloff(curve);
  brush->SetFalloffToCustom();
  brush->SetRadius(0.25);
  brush->SetColor(0.0, 0.0, 1.0, 1.0);
  const std::vector<unsigned char> before = Copy(Colors(ofb));
  double c[3];
  OnSphere(2.0, 0.7, c);
  const vtkIdType changed = painter->Dab(c);
  // The reference evaluates the curve itself (ClosedForm knows no Custom).
  vtkUnsignedCharArray* colors = Colors(ofb);
  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const double d = std::sqrt(vtkMath::Distance2BetweenPoints(x, c)) / 0.25;
    const unsigned char* now = colors->GetPointer(4 * i);
    differing += std::memcmp(now, before.data() + 4 * i, 4) != 0;
    if (d > 1.0)
    {
      ASSERT_EQ(std::memcmp(now, before.data() + 4 * i, 4), 0);
      continue;
    }
    const double src[4] = { 0, 0, 1, 1 };
    double ref[4];
    ReferenceBlend(before.data() + 4 * i,
      src,
      brush->EvaluateFalloff(d),
      vtkOFBBrush::BLEND_MIX,
      before.data() + 4 * i,
      ref);
    for (int k = 0; k < 4; ++k)
    {
      ASSERT_LE(std::abs(now[k] - ref[k] * 255.0), 0.5 + 1e-3);
    }
  }
  EXPECT_EQ(changed, differing);
}

//------------------------------------------------------------------------------
TEST(Painter, MarksExactlyTheChangedSamplesAndModifiesOnce)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB();
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.08);
  painter->GetBrush()->SetColor(1, 0, 0);
  painter->Dab(0, 0, 1); // creates "Colors" (white)
  const std::vector<unsigned char> before = Copy(Colors(ofb));
  vtkTimeStamp t;
  t.Modified();
  const vtkMTimeType mtime = ofb->GetMTime();
  unsigned long modifiedEvents = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&modifiedEvents);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* cd, void*) { ++*static_cast<unsigned long*>(cd); });
  ofb->AddObserver(vtkCommand::ModifiedEvent, count);
  vtkNew<vtkPoints> centres;
  double p[3];
  OnSphere(0.2, 1.0, p);
  centres->InsertNextPoint(p);
  OnSphere(0.25, 1.0, p);
  centres->InsertNextPoint(p);
  const vtkIdType changed = painter->Dabs(centres);
  EXPECT_GT(changed, 0);
  EXPECT_EQ(modifiedEvents, 1u);
  EXPECT_GT(ofb->GetMTime(), mtime);
  vtkNew<vtkIdTypeArray> ranges;
  ofb->GetSampleRangesModifiedSince(t.GetMTime(), ranges);
  ASSERT_LT(ranges->GetNumberOfTuples(), 128); // not merged by the OFB
  std::vector<bool> marked(ofb->GetNumberOfSamples(), false);
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    for (vtkIdType i = ranges->GetValue(2 * r); i < ranges->GetValue(2 * r + 1); ++i)
    {
      marked[i] = true;
    }
  }
  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const bool differs = std::memcmp(Colors(ofb)->GetPointer(4 * i), before.data() + 4 * i, 4) != 0;
    differing += differs;
    EXPECT_EQ(marked[i], differs) << "sample " << i;
  }
  EXPECT_EQ(differing, changed);
}

//------------------------------------------------------------------------------
TEST(Painter, StrokesAreSpacedAsSet)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(64);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.2);
  painter->FollowSurfaceOff(); // a straight path through space, above the sphere
  for (double spacing : { 0.25, 0.1, 1.0 })
  {
    painter->SetSpacing(spacing);
    painter->BeginStroke();
    // A straight path from (-1, 0, 1) to (1, 0, 1) given in uneven pieces.
    const double xs[] = { -1.0, -0.93, -0.5, -0.49, 0.2, 1.01 };
    for (double x : xs)
    {
      painter->StrokeTo(x, 0.0, 1.0);
    }
    painter->EndStroke();
    vtkPoints* dabs = painter->GetStrokeDabs();
    const double step = spacing * 0.2;
    ASSERT_EQ(dabs->GetNumberOfPoints(), static_cast<vtkIdType>(std::floor(2.01 / step)) + 1);
    for (vtkIdType i = 0; i < dabs->GetNumberOfPoints(); ++i)
    {
      double p[3];
      dabs->GetPoint(i, p);
      EXPECT_NEAR(p[0], -1.0 + i * step, 1e-9);
      EXPECT_EQ(p[1], 0.0);
      EXPECT_EQ(p[2], 1.0);
    }
  }
}

//------------------------------------------------------------------------------
TEST(Painter, OneAndTwoThreadsGiveTheColoursOfDabsOneByOne)
{
  // 3000 overlapping dabs of random sizes and colours, every blend mode but Erase.
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  vtkNew<vtkPolyData> dabs;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkUnsignedCharArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(4);
  for (int i = 0; i < 3000; ++i)
  {
    double p[3];
    OnSphere(random->GetNextRangeValue(0, 2 * vtkMath::Pi()),
      std::acos(random->GetNextRangeValue(-1, 1)),
      p);
    points->InsertNextPoint(p);
    radius->InsertNextValue(static_cast<float>(random->GetNextRangeValue(0.02, 0.15)));
    unsigned char c[4];
    RandomColor(random, 200, c);
    color->InsertNextTypedTuple(c);
  }
  dabs->SetPoints(points);
  dabs->GetPointData()->AddArray(radius);
  dabs->GetPointData()->AddArray(color);

  for (int mode : { vtkOFBBrush::BLEND_MIX, vtkOFBBrush::BLEND_ADD, vtkOFBBrush::BLEND_MULTIPLY })
  {
    std::vector<std::vector<unsigned char>> results;
    for (int threads : { 1, 2, 0 })
    {
      vtkSmartPointer<vtkOFB> ofb = SphereOFB();
      vtkNew<vtkOFBPainter> painter;
      painter->SetOFB(ofb);
      painter->GetBrush()->SetBlendMode(mode);
      painter->GetBrush()->SetStrength(0.6);
      if (threads > 0)
      {
        vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads }, [&]() { painter->Dabs(dabs); });
      }
      else
      {
        // One after the other, through Dab with the per-dab settings on the brush.
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        {
          const unsigned char* c = color->GetPointer(4 * i);
          painter->GetBrush()->SetColor(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, c[3] / 255.0);
          painter->GetBrush()->SetRadius(radius->GetValue(i));
          painter->Dab(points->GetPoint(i));
        }
      }
      results.push_back(Copy(Colors(ofb)));
    }
    EXPECT_TRUE(results[0] == results[1]) << "1 and 2 threads differ";
    EXPECT_TRUE(results[0] == results[2]) << "parallel dabs differ from dabs one by one";
  }
}

//------------------------------------------------------------------------------
TEST(Painter, UndoRedoExactAndMemoryProportional)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB();
  RandomColors(ofb, 5);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetColor(0.2, 0.9, 0.1);
  painter->GetBrush()->SetRadius(0.1);
  const std::vector<unsigned char> original = Copy(Colors(ofb));
  EXPECT_FALSE(painter->CanUndo());

  // One stroke: its memory is one record (id + RGBA) per changed sample.
  painter->BeginStroke();
  vtkIdType touched = 0;
  for (int i = 0; i <= 20; ++i)
  {
    double p[3];
    OnSphere(0.1 * i, 1.0, p);
    touched += painter->StrokeTo(p);
  }
  painter->EndStroke();
  const std::vector<unsigned char> stroke1 = Copy(Colors(ofb));
  vtkIdType distinct = 0;
  for (size_t i = 0; i < original.size(); i += 4)
  {
    distinct += std::memcmp(original.data() + i, stroke1.data() + i, 4) != 0;
  }
  EXPECT_GE(touched, distinct);
  EXPECT_EQ(painter->GetUndoMemory(), distinct * 8);

  // A second, larger dab: memory grows by its own changed samples only.
  painter->GetBrush()->SetRadius(0.3);
  const vtkIdType second = painter->Dab(0.0, 0.0, -1.0);
  EXPECT_EQ(painter->GetUndoMemory(), (distinct + second) * 8);
  const std::vector<unsigned char> stroke2 = Copy(Colors(ofb));
  EXPECT_EQ(painter->GetNumberOfUndoSteps(), 2);

  EXPECT_EQ(painter->Undo(), second);
  EXPECT_TRUE(Copy(Colors(ofb)) == stroke1);
  EXPECT_EQ(painter->Undo(), distinct);
  EXPECT_TRUE(Copy(Colors(ofb)) == original);
  EXPECT_FALSE(painter->CanUndo());
  EXPECT_EQ(painter->Undo(), 0);
  EXPECT_EQ(painter->Redo(), distinct);
  EXPECT_TRUE(Copy(Colors(ofb)) == stroke1);
  EXPECT_EQ(painter->Redo(), second);
  EXPECT_TRUE(Copy(Colors(ofb)) == stroke2);
  EXPECT_FALSE(painter->CanRedo());

  // A new step drops the redo steps; the limit drops the oldest steps.
  painter->Undo();
  painter->Dab(1.0, 0.0, 0.0);
  EXPECT_FALSE(painter->CanRedo());
  painter->SetUndoLimit(0);
  painter->Dab(-1.0, 0.0, 0.0);
  EXPECT_FALSE(painter->CanUndo());
  EXPECT_EQ(painter->GetUndoMemory(), 0);

  // Without an undo budget nothing is kept, in a stroke either; a budget given back
  // records the next step in full (no sample left marked as recorded).
  painter->BeginStroke();
  painter->StrokeTo(-1.0, 0.0, 0.0);
  painter->StrokeTo(-1.0, 0.5, 0.0);
  painter->EndStroke();
  EXPECT_FALSE(painter->CanUndo());
  EXPECT_EQ(painter->GetUndoMemory(), 0);
  painter->SetUndoLimit(VTK_ID_MAX);
  const std::vector<unsigned char> beforeLast = Copy(Colors(ofb));
  painter->GetBrush()->SetColor(0.1, 0.9, 0.3);
  const vtkIdType last = painter->Dab(-1.0, 0.25, 0.0);
  EXPECT_GT(last, 0);
  EXPECT_EQ(painter->Undo(), last);
  EXPECT_TRUE(Copy(Colors(ofb)) == beforeLast);
}

//------------------------------------------------------------------------------
TEST(Painter, SmearCarriesColourInTheStrokeDirectionOnly)
{
  // A flat square, red for x < 0 and white for x > 0.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->Update();
  vtkSmartPointer<vtkOFB> base = Build(plane->GetOutput(), 128);
  ASSERT_GT(base->GetNumberOfSamples(), 0);
  auto reddestBeyond = [](vtkOFB* ofb)
  {
    // The largest x of a white-side sample that got red in it.
    double far = -1.0;
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      const unsigned char* c = Colors(ofb)->GetPointer(4 * i);
      if (x[0] > 0.0 && c[1] < 250)
      {
        far = std::max(far, x[0]);
      }
    }
    return far;
  };
  const double r = 0.1;
  double extent[2];
  for (int direction = 0; direction < 2; ++direction)
  {
    vtkNew<vtkOFB> ofb;
    ofb->DeepCopy(base);
    vtkNew<vtkOFBPainter> painter;
    painter->SetOFB(ofb);
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      unsigned char* c = Colors(ofb)->GetPointer(4 * i);
      const unsigned char red[4] = { 255, 0, 0, 255 }, white[4] = { 255, 255, 255, 255 };
      std::memcpy(c, x[0] < 0.0 ? red : white, 4);
    }
    painter->GetBrush()->SetTargetToSmear();
    painter->GetBrush()->SetRadius(r);
    painter->GetBrush()->SetFalloffToSmooth();
    painter->BeginStroke();
    const double from = direction == 0 ? -0.4 : 0.4;
    for (int i = 0; i <= 8; ++i)
    {
      painter->StrokeTo(from - from * 2.0 * i / 8.0, 0.0, 0.0);
    }
    painter->EndStroke();
    extent[direction] = reddestBeyond(ofb);
  }
  // Forward (red to white): red carried along the stroke far into the white side.
  EXPECT_GT(extent[0], 0.3);
  // Backward (white to red): no red further than one radius into the white side.
  EXPECT_LT(extent[1], r + 1e-6);
}

//------------------------------------------------------------------------------
TEST(Painter, NormalTargetPaintsBumpsAndUndoes)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB();
  auto* normals = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("Normals"));
  ASSERT_NE(normals, nullptr);
  const std::vector<float> before(
    normals->GetPointer(0), normals->GetPointer(0) + 3 * normals->GetNumberOfTuples());
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  vtkOFBBrush* brush = painter->GetBrush();
  brush->SetTargetToNormal();
  brush->SetRadius(0.3);
  brush->SetBumpDepth(1.0);
  const double c[3] = { 0.0, 0.0, 1.0 };
  const vtkIdType changed = painter->Dab(c);
  EXPECT_GT(changed, 100);
  vtkIdType tiltedOutwards = 0, inside = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const float* n = normals->GetPointer(3 * i);
    const float* o = before.data() + 3 * i;
    if (vtkMath::Distance2BetweenPoints(x, c) > 0.09)
    {
      ASSERT_TRUE(n[0] == o[0] && n[1] == o[1] && n[2] == o[2]);
      continue;
    }
    ++inside;
    EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-5);
    // A bump: the normal leans away from the centre.
    const double lean =
      (n[0] - o[0]) * (x[0] - c[0]) + (n[1] - o[1]) * (x[1] - c[1]) + (n[2] - o[2]) * (x[2] - c[2]);
    tiltedOutwards += lean > 0.0;
  }
  EXPECT_GT(tiltedOutwards, inside * 9 / 10);
  EXPECT_GT(painter->Undo(), 0);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), normals->GetPointer(0)));
  // Erase brings painted normals back to the initial ones.
  painter->Redo();
  brush->SetBlendModeToErase();
  brush->SetFalloffToConstant();
  painter->Dab(c);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), normals->GetPointer(0)));
}

//------------------------------------------------------------------------------
TEST(Painter, AlphaRevealsATransparentOFB)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB();
  ofb->GetSampleData()->RemoveArray("Colors");
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->SetDefaultColor(1, 1, 1, 0); // transparent
  painter->GetBrush()->SetColor(0, 0, 1, 1);
  painter->GetBrush()->SetFalloffToConstant();
  painter->GetBrush()->SetRadius(0.2);
  const double c[3] = { 1, 0, 0 };
  EXPECT_GT(painter->Dab(c), 0);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const unsigned char* col = Colors(ofb)->GetPointer(4 * i);
    const bool in = vtkMath::Distance2BetweenPoints(x, c) <= 0.04;
    ASSERT_EQ(col[3], in ? 255 : 0);
    if (in)
    {
      ASSERT_EQ(col[2], 255);
      ASSERT_EQ(col[0], 0);
    }
  }
}

//------------------------------------------------------------------------------
TEST(Painter, BadInputIsRefusedOrDefined)
{
  vtkNew<vtkOFBPainter> painter;
  vtkNew<MessageObserver> messages;
  messages->Watch(painter);
  // No OFB.
  EXPECT_EQ(painter->Dab(0, 0, 0), 0);
  EXPECT_NE(messages->Errors.find("No OFB"), std::string::npos);
  // Empty OFB.
  vtkNew<vtkOFB> empty;
  painter->SetOFB(empty);
  messages->Clear();
  EXPECT_EQ(painter->Dab(0, 0, 0), 0);
  EXPECT_NE(messages->Errors.find("no samples"), std::string::npos);

  vtkSmartPointer<vtkOFB> ofb = SphereOFB(64);
  ofb->GetSampleData()->RemoveArray("Colors");
  painter->SetOFB(ofb);
  painter->GetBrush()->SetColor(0, 1, 0);
  // NaN centre, zero and negative radius: errors, nothing changes.
  messages->Clear();
  EXPECT_EQ(painter->Dab(std::nan(""), 0, 1), 0);
  EXPECT_NE(messages->Errors.find("not finite"), std::string::npos);
  for (double radius : { 0.0, -1.0, std::nan(""), HUGE_VAL })
  {
    painter->GetBrush()->SetRadius(radius);
    messages->Clear();
    EXPECT_EQ(painter->Dab(0, 0, 1), 0);
    EXPECT_NE(messages->Errors.find("radius"), std::string::npos);
  }
  EXPECT_EQ(ofb->GetSampleData()->GetArray("Colors"), nullptr);
  EXPECT_FALSE(painter->CanUndo());
  // No "Colors": created on demand, filled with DefaultColor.
  painter->GetBrush()->SetRadius(0.2);
  messages->Clear();
  EXPECT_GT(painter->Dab(0, 0, 1), 0);
  EXPECT_TRUE(messages->Errors.empty());
  ASSERT_NE(Colors(ofb), nullptr);
  EXPECT_EQ(Colors(ofb)->GetValue(0) + Colors(ofb)->GetValue(3), 510); // white far away
  EXPECT_EQ(painter->StrokeTo(std::nan(""), 0, 0), 0);

  // Another painter changes the OFB: this one's history is dropped with a warning.
  vtkNew<vtkOFBPainter> other;
  other->SetOFB(ofb);
  other->GetBrush()->SetColor(0, 0, 1);
  EXPECT_GT(other->Dab(0, 0, -1), 0);
  messages->Clear();
  EXPECT_EQ(painter->Undo(), 0);
  EXPECT_NE(messages->Warnings.find("undo history is dropped"), std::string::npos);
  EXPECT_FALSE(painter->CanUndo());
  EXPECT_GT(painter->Dab(1, 0, 0), 0); // still paints
  EXPECT_TRUE(painter->CanUndo());
  // A rebuilt OFB (new samples): defined as well.
  vtkSmartPointer<vtkOFB> rebuilt = SphereOFB(48);
  ofb->ShallowCopy(rebuilt);
  messages->Clear();
  EXPECT_GT(painter->Dab(0, 1, 0), 0);
  EXPECT_FALSE(messages->Warnings.empty());
}

//------------------------------------------------------------------------------
TEST(Painter, RadiusCoveringTheWholeOFBWorksWithProgress)
{
  vtkSmartPointer<vtkOFB> ofb = SphereOFB(640);
  ASSERT_GT(ofb->GetNumberOfSamples(), vtkIdType(1) << 20);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(10.0);
  painter->GetBrush()->SetColor(0, 0, 0);
  painter->GetBrush()->SetFalloffToConstant();
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetClientData(&progress);
  cb->SetCallback([](vtkObject*, unsigned long, void* cd, void* data)
    { static_cast<std::vector<double>*>(cd)->push_back(*static_cast<double*>(data)); });
  painter->AddObserver(vtkCommand::ProgressEvent, cb);
  EXPECT_EQ(painter->Dab(0, 0, 0), ofb->GetNumberOfSamples());
  ASSERT_GE(progress.size(), 2u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(progress.back(), 1.0);
}
