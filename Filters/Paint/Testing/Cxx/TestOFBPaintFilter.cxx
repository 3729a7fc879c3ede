// vtkOFBPaintFilter: strokes with per-point arrays painted into a copy, progress, bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPaintFilter.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace vtkofbtest;

namespace
{
vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}

// One polyline over the top of the unit sphere, from (-0.6, 0, z) to (0.6, 0, z).
vtkSmartPointer<vtkPolyData> Stroke(int points)
{
  auto strokes = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(points);
  for (int i = 0; i < points; ++i)
  {
    const double x = -0.6 + 1.2 * i / (points - 1);
    pts->InsertNextPoint(x, 0.0, std::sqrt(1.0 - x * x));
    lines->InsertCellPoint(i);
  }
  strokes->SetPoints(pts);
  strokes->SetLines(lines);
  return strokes;
}

double DistanceToStroke(vtkPolyData* strokes, const double x[3])
{
  // Distance to the polyline's segments.
  double best = VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i + 1 < strokes->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3], ab[3], ax[3];
    strokes->GetPoint(i, a);
    strokes->GetPoint(i + 1, b);
    vtkMath::Subtract(b, a, ab);
    vtkMath::Subtract(x, a, ax);
    const double t = std::min(1.0, std::max(0.0, vtkMath::Dot(ax, ab) / vtkMath::Dot(ab, ab)));
    double p[3] = { a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2] };
    best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(p, x)));
  }
  return best;
}
}

//------------------------------------------------------------------------------
TEST(PaintFilter, PaintsACopyAlongTheStrokes)
{
  vtkSmartPointer<vtkOFB> input = Build(MakeSphere(1.0, 64), 96);
  const std::vector<unsigned char> before(
    Colors(input)->GetPointer(0), Colors(input)->GetPointer(0) + 4 * input->GetNumberOfSamples());
  vtkSmartPointer<vtkPolyData> strokes = Stroke(7);
  // Per-point colour (red to blue) and radius (0.05 to 0.15).
  vtkNew<vtkDoubleArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(4);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  for (int i = 0; i < 7; ++i)
  {
    const double t = i / 6.0;
    color->InsertNextTuple4(1.0 - t, 0.0, t, 1.0);
    radius->InsertNextValue(0.05 + 0.1 * t);
  }
  strokes->GetPointData()->AddArray(color);
  strokes->GetPointData()->AddArray(radius);

  vtkNew<vtkOFBPaintFilter> filter;
  filter->SetInputData(input);
  filter->SetStrokesData(strokes);
  filter->GetBrush()->SetFalloffToConstant();
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetClientData(&progress);
  cb->SetCallback([](vtkObject*, unsigned long, void* cd, void* data)
    { static_cast<std::vector<double>*>(cd)->push_back(*static_cast<double*>(data)); });
  filter->AddObserver(vtkCommand::ProgressEvent, cb);
  filter->Update();
  vtkOFB* output = filter->GetOutput();
  ASSERT_EQ(output->GetNumberOfSamples(), input->GetNumberOfSamples());
  EXPECT_GT(filter->GetNumberOfChangedSamples(), 100);
  EXPECT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), 1.0);
  // The input is untouched, its other arrays shared.
  EXPECT_TRUE(std::equal(before.begin(), before.end(), Colors(input)->GetPointer(0)));
  EXPECT_NE(Colors(output), Colors(input));
  EXPECT_EQ(output->GetDepths(), input->GetDepths());
  EXPECT_EQ(
    output->GetSampleData()->GetArray("Normals"), input->GetSampleData()->GetArray("Normals"));
  // Painted near the stroke only; red at its start, blue at its end.
  vtkIdType changed = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfSamples(); ++i)
  {
    double x[3];
    output->GetSamplePosition(i, x);
    const unsigned char* c = Colors(output)->GetPointer(4 * i);
    const bool differs = std::memcmp(c, before.data() + 4 * i, 4) != 0;
    changed += differs;
    if (differs)
    {
      // The dabs follow the surface between the points: within a cell of the chords.
      ASSERT_LE(DistanceToStroke(strokes, x), 0.15 + input->GetCellSize());
      EXPECT_EQ(c[1], 0);
    }
  }
  EXPECT_EQ(changed, filter->GetNumberOfChangedSamples());
  const double start[3] = { -0.6, 0.0, 0.8 }, end[3] = { 0.6, 0.0, 0.8 };
  const unsigned char* cs = Colors(output)->GetPointer(4 * output->FindClosestSample(start));
  const unsigned char* ce = Colors(output)->GetPointer(4 * output->FindClosestSample(end));
  EXPECT_GT(cs[0], 240);
  EXPECT_LT(cs[2], 15);
  EXPECT_GT(ce[2], 240);
  EXPECT_LT(ce[0], 15);

  // Without strokes: an unpainted copy.
  filter->SetStrokesData(nullptr);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfChangedSamples(), 0);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), Colors(filter->GetOutput())->GetPointer(0)));
}

//------------------------------------------------------------------------------
TEST(PaintFilter, SameColoursAsThePainterAlongTheSamePath)
{
  vtkSmartPointer<vtkOFB> input = Build(MakeSphere(1.0, 64), 96);
  vtkSmartPointer<vtkPolyData> strokes = Stroke(2);
  vtkNew<vtkOFBPaintFilter> filter;
  filter->SetInputData(input);
  filter->SetStrokesData(strokes);
  filter->GetBrush()->SetColor(0.2, 0.4, 0.9);
  filter->GetBrush()->SetRadius(0.1);
  filter->GetBrush()->SetStrength(0.3);
  filter->Update();

  vtkNew<vtkOFB> byHand;
  byHand->DeepCopy(input);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(byHand);
  painter->SetBrush(filter->GetBrush());
  painter->StrokeTo(strokes->GetPoint(0));
  painter->StrokeTo(strokes->GetPoint(1));
  painter->EndStroke();
  ASSERT_GT(painter->GetStrokeDabs()->GetNumberOfPoints(), 40);
  EXPECT_TRUE(std::equal(Colors(byHand)->GetPointer(0),
    Colors(byHand)->GetPointer(0) + 4 * input->GetNumberOfSamples(),
    Colors(filter->GetOutput())->GetPointer(0)));
}

//------------------------------------------------------------------------------
// The filter paints with its brush and its painter's settings: changing either
// re-executes it.
TEST(PaintFilter, BrushAndPainterChangesReexecute)
{
  vtkNew<vtkOFBPaintFilter> filter;
  ASSERT_NE(filter->GetBrush(), nullptr);
  ASSERT_NE(filter->GetPainter(), nullptr);
  vtkMTimeType t = filter->GetMTime();
  filter->GetBrush()->SetRadius(0.5);
  EXPECT_GT(filter->GetMTime(), t);
  t = filter->GetMTime();
  filter->GetPainter()->SetSpacing(0.5);
  EXPECT_GT(filter->GetMTime(), t);
  t = filter->GetMTime();
  filter->GetPainter()->MirrorYOn();
  EXPECT_GT(filter->GetMTime(), t);
}

TEST(PaintFilter, BadInputGivesAnErrorAndAnEmptyOutput)
{
  vtkNew<vtkOFBPaintFilter> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  vtkNew<vtkOFB> empty;
  filter->SetInputData(empty);
  filter->Update();
  EXPECT_NE(messages->Errors.find("no samples"), std::string::npos);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);

  vtkSmartPointer<vtkOFB> input = Build(MakeSphere(1.0, 32), 48);
  vtkSmartPointer<vtkPolyData> strokes = Stroke(3);
  strokes->GetPoints()->SetPoint(1, std::nan(""), 0.0, 0.0);
  filter->SetInputData(input);
  filter->SetStrokesData(strokes);
  messages->Clear();
  filter->Update();
  EXPECT_NE(messages->Errors.find("not finite"), std::string::npos);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);

  strokes = Stroke(3);
  vtkNew<vtkFloatArray> radius;
  radius->SetName("Radius");
  radius->InsertNextValue(0.1f);
  radius->InsertNextValue(-0.1f);
  radius->InsertNextValue(0.1f);
  strokes->GetPointData()->AddArray(radius);
  filter->SetStrokesData(strokes);
  messages->Clear();
  filter->Update();
  EXPECT_NE(messages->Errors.find("radius"), std::string::npos);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);
}

//------------------------------------------------------------------------------
TEST(PaintFilter, MisshapenPointArraysAreBadInput)
{
  // A "Color" of 2 components, or a "Radius" shorter than the points (reading it would
  // run past its end): an error naming the array, an empty output, nothing painted; the
  // same through vtkOFBPainter::Dabs. A well-formed array of the same name paints.
  vtkSmartPointer<vtkOFB> input = Build(MakeSphere(1.0, 32), 48);
  const std::vector<unsigned char> before(
    Colors(input)->GetPointer(0), Colors(input)->GetPointer(0) + 4 * input->GetNumberOfSamples());
  auto withArray = [](const char* name, int components, vtkIdType tuples)
  {
    vtkSmartPointer<vtkPolyData> strokes = Stroke(3);
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(tuples);
    a->Fill(0.2);
    strokes->GetPointData()->AddArray(a);
    return strokes;
  };
  vtkNew<vtkOFBPaintFilter> filter;
  filter->SetInputData(input);
  filter->GetBrush()->SetColor(0.9, 0.1, 0.1);
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(input);
  painter->GetBrush()->SetRadius(0.2);
  vtkNew<MessageObserver> painterMessages;
  painterMessages->Watch(painter);
  for (const auto& bad : { withArray("Color", 2, 3), withArray("Radius", 1, 2) })
  {
    const std::string name = bad->GetPointData()->GetArrayName(0);
    messages->Clear();
    filter->SetStrokesData(bad);
    filter->Update();
    EXPECT_NE(messages->Errors.find("'" + name + "'"), std::string::npos) << messages->Errors;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);
    painterMessages->Clear();
    EXPECT_EQ(painter->Dabs(bad), 0);
    EXPECT_NE(painterMessages->Errors.find("'" + name + "'"), std::string::npos);
  }
  EXPECT_EQ(0, std::memcmp(before.data(), Colors(input)->GetPointer(0), before.size()));

  filter->SetStrokesData(withArray("Radius", 1, 3));
  messages->Clear();
  filter->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  EXPECT_GT(filter->GetNumberOfChangedSamples(), 0);
}

//------------------------------------------------------------------------------
TEST(PaintFilter, TinyRadiiAndEndlessStrokesStayBounded)
{
  // Dabs are at least an eighth of a cell apart: a radius of 1e-12, or of 0 from a
  // pressure of 0, placed billions along a stroke (the call never came back). A stroke
  // that would still place more than 2^24 dabs is an error.
  vtkSmartPointer<vtkOFB> input = Build(MakeSphere(1.0, 32), 48);
  const double eighth = 0.125 * input->GetCellSize();
  vtkSmartPointer<vtkPolyData> strokes = Stroke(2); // (-0.6, 0, 0.8) to (0.6, 0, 0.8)
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  radius->InsertNextValue(1e-12);
  radius->InsertNextValue(1e-12);
  strokes->GetPointData()->AddArray(radius);
  vtkNew<vtkOFBPaintFilter> filter;
  // Strokes through space (FollowSurface off: the far point is not moved onto the sphere).
  filter->GetPainter()->FollowSurfaceOff();
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  filter->SetInputData(input);
  filter->SetStrokesData(strokes);
  filter->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), input->GetNumberOfSamples());

  vtkNew<vtkOFB> ofb;
  ofb->DeepCopy(input);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.1);
  painter->GetBrush()->PressureAffectsRadiusOn();
  painter->FollowSurfaceOff();
  painter->BeginStroke();
  painter->StrokeTo(-0.6, 0.0, 0.8, 0.0);
  painter->StrokeTo(0.6, 0.0, 0.8, 0.0);
  const double dabs = static_cast<double>(painter->GetStrokeDabs()->GetNumberOfPoints());
  EXPECT_NEAR(dabs, 1.2 / eighth + 1.0, 1.5);
  painter->EndStroke();

  vtkNew<vtkPoints> far;
  far->InsertNextPoint(0.0, 0.0, 1.0);
  far->InsertNextPoint(1e9, 0.0, 1.0);
  strokes->SetPoints(far);
  strokes->GetPointData()->RemoveArray("Radius");
  messages->Clear();
  filter->Modified();
  filter->Update();
  EXPECT_NE(messages->Errors.find("dabs"), std::string::npos) << messages->Errors;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);
  vtkNew<MessageObserver> painterMessages;
  painterMessages->Watch(painter);
  painter->BeginStroke();
  EXPECT_EQ(painter->StrokeTo(0.0, 0.0, 1.0), 0);
  EXPECT_EQ(painter->StrokeTo(1e9, 0.0, 1.0), 0);
  painter->EndStroke();
  EXPECT_NE(painterMessages->Errors.find("dabs"), std::string::npos) << painterMessages->Errors;
}

//------------------------------------------------------------------------------
TEST(PaintFilter, NaNBrushSettingsAreErrors)
{
  // NaN passes the brush's clamps: a NaN strength blended into undefined colour bytes.
  vtkSmartPointer<vtkOFB> input = Build(MakeSphere(1.0, 32), 48);
  const double nan = std::nan("");
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkOFB> ofb;
    ofb->DeepCopy(input);
    const std::vector<unsigned char> before(
      Colors(ofb)->GetPointer(0), Colors(ofb)->GetPointer(0) + 4 * ofb->GetNumberOfSamples());
    vtkNew<vtkOFBPainter> painter;
    painter->SetOFB(ofb);
    vtkOFBBrush* brush = painter->GetBrush();
    brush->SetRadius(0.3);
    brush->SetStrength(k == 0 ? nan : 1.0);
    brush->SetSmearAmount(k == 1 ? nan : 1.0);
    brush->SetBumpDepth(k == 2 ? nan : 0.5);
    brush->SetMaxNormalAngle(k == 3 ? nan : 90.0);
    vtkNew<MessageObserver> messages;
    messages->Watch(painter);
    EXPECT_EQ(painter->Dab(0.0, 0.0, 1.0), 0) << k;
    EXPECT_NE(messages->Errors.find("not finite"), std::string::npos) << k << messages->Errors;
    EXPECT_EQ(0, std::memcmp(before.data(), Colors(ofb)->GetPointer(0), before.size())) << k;
  }
}
