// vtkOFBProbeFilter: OFB sample arrays onto the points of a surface, against brute-force
// lookups over all samples; thin sheets; bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBProbeFilter.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace vtkofbtest;

namespace
{
/// A sphere OFB with a few random dabs of paint and a float array "Height" (the z of
/// each sample).
vtkSmartPointer<vtkOFB> PaintedSphere()
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 64), 96);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.3);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  for (int k = 0; k < 12; ++k)
  {
    const double c[4] = { random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      random->GetNextRangeValue(0.0, 1.0),
      1.0 };
    painter->GetBrush()->SetColor(c);
    double p[3];
    OnSphere(random->GetNextRangeValue(0.0, vtkMath::Pi()),
      random->GetNextRangeValue(0.0, 2.0 * vtkMath::Pi()),
      p);
    painter->Dab(p);
  }
  AddCoordinateArray(ofb, "Height", 2);
  return ofb;
}

/// A coarser sphere of another triangulation, with point normals.
vtkSmartPointer<vtkPolyData> ProbeSphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(37);
  sphere->SetPhiResolution(23);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> out = sphere->GetOutput();
  return out;
}

/// Whether sample j faces the way of normal n (the probe's facing test).
bool Faces(vtkOFB* ofb, vtkIdType j, const double n[3])
{
  double sn[3];
  ofb->GetSampleData()->GetArray("Normals")->GetTuple(j, sn);
  return vtkMath::Dot(sn, n) >= 0.0;
}

vtkSmartPointer<vtkPolyData> Probe(vtkPolyData* surface, vtkOFB* ofb, int mode, MessageObserver* o)
{
  vtkNew<vtkOFBProbeFilter> probe;
  if (o)
  {
    o->Watch(probe);
  }
  probe->SetInputData(surface);
  probe->SetOFBData(ofb);
  probe->SetLookupMode(mode);
  probe->Update();
  vtkSmartPointer<vtkPolyData> out = probe->GetOutput();
  return out;
}
}

//------------------------------------------------------------------------------
TEST(ProbeFilter, NearestIsTheClosestFacingSample)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedSphere();
  vtkSmartPointer<vtkPolyData> surface = ProbeSphere();
  vtkSmartPointer<vtkPolyData> out =
    Probe(surface, ofb, vtkOFBProbeFilter::LOOKUP_NEAREST, nullptr);
  ASSERT_EQ(out->GetNumberOfPoints(), surface->GetNumberOfPoints());
  auto* colors = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("Colors"));
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(out->GetPointData()->GetScalars(), colors); // the OFB's active scalars
  auto* inColors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  vtkDataArray* mask = out->GetPointData()->GetArray("vtkValidPointMask");
  ASSERT_NE(mask, nullptr);
  const double r = std::sqrt(3.0) * ofb->GetCellSize();
  int painted = 0;
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    double x[3], n[3];
    surface->GetPoint(p, x);
    surface->GetPointData()->GetNormals()->GetTuple(p, n);
    vtkIdType best = -1;
    double bestD2 = 4.0 * r * r;
    for (vtkIdType j = 0; j < ofb->GetNumberOfSamples(); ++j)
    {
      double y[3];
      ofb->GetSamplePosition(j, y);
      const double d2 = vtkMath::Distance2BetweenPoints(x, y);
      if (d2 < bestD2 && Faces(ofb, j, n))
      {
        best = j;
        bestD2 = d2;
      }
    }
    ASSERT_GE(best, 0);
    ASSERT_EQ(mask->GetComponent(p, 0), 1.0);
    for (int c = 0; c < 4; ++c)
    {
      ASSERT_EQ(colors->GetValue(4 * p + c), inColors->GetValue(4 * best + c)) << "point " << p;
    }
    painted += colors->GetValue(4 * p) != 255 || colors->GetValue(4 * p + 1) != 255;
  }
  EXPECT_GT(painted, 20); // the dabs reached some points
}

//------------------------------------------------------------------------------
TEST(ProbeFilter, SmoothIsTheWeightedMean)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedSphere();
  vtkSmartPointer<vtkPolyData> surface = ProbeSphere();
  vtkSmartPointer<vtkPolyData> out = Probe(surface, ofb, vtkOFBProbeFilter::LOOKUP_SMOOTH, nullptr);
  vtkDataArray* height = out->GetPointData()->GetArray("Height");
  ASSERT_NE(height, nullptr);
  ASSERT_EQ(height->GetDataType(), VTK_FLOAT);
  const double r = std::sqrt(3.0) * ofb->GetCellSize();
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    double x[3], n[3];
    surface->GetPoint(p, x);
    surface->GetPointData()->GetNormals()->GetTuple(p, n);
    double sum = 0.0, weights = 0.0;
    for (vtkIdType j = 0; j < ofb->GetNumberOfSamples(); ++j)
    {
      double y[3];
      ofb->GetSamplePosition(j, y);
      const double d2 = vtkMath::Distance2BetweenPoints(x, y);
      if (d2 < r * r && Faces(ofb, j, n))
      {
        const double q = 1.0 - d2 / (r * r);
        sum += q * q * y[2];
        weights += q * q;
      }
    }
    ASSERT_GT(weights, 0.0);
    EXPECT_NEAR(height->GetComponent(p, 0), sum / weights, 1e-5) << "point " << p;
    // And the height is the point's own, to about a cell.
    EXPECT_NEAR(height->GetComponent(p, 0), x[2], 2.0 * ofb->GetCellSize());
  }
}

//------------------------------------------------------------------------------
TEST(ProbeFilter, ThinSheetsKeepTheirSides)
{
  // Two parallel sheets a cell apart facing away from each other; the top one red.
  vtkNew<vtkPlaneSource> top;
  top->SetResolution(20, 20);
  top->SetOrigin(-1, -1, 0.01);
  top->SetPoint1(1, -1, 0.01);
  top->SetPoint2(-1, 1, 0.01);
  vtkNew<vtkPlaneSource> bottom;
  bottom->SetResolution(20, 20);
  bottom->SetOrigin(-1, -1, -0.01);
  bottom->SetPoint1(-1, 1, -0.01);
  bottom->SetPoint2(1, -1, -0.01); // normal -z
  top->Update();
  bottom->Update();
  vtkNew<vtkAppendPolyData> both;
  both->AddInputData(top->GetOutput());
  both->AddInputData(bottom->GetOutput());
  both->Update();
  vtkSmartPointer<vtkOFB> ofb = Build(both->GetOutput(), 128); // cell 0.0157, sheets 1.3 apart
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  ASSERT_NE(colors, nullptr);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    if (x[2] > 0.0)
    {
      colors->SetTypedTuple(i, std::array<unsigned char, 4>{ 255, 0, 0, 255 }.data());
    }
  }
  for (int aware = 0; aware < 2; ++aware)
  {
    int wrong = 0;
    for (vtkPlaneSource* sheet : { top.Get(), bottom.Get() })
    {
      vtkNew<vtkOFBProbeFilter> probe;
      probe->SetInputData(sheet->GetOutput());
      probe->SetOFBData(ofb);
      probe->SetNormalAware(aware == 1);
      probe->SetLookupModeToSmooth(); // every sample within 2 cells, both sheets'
      probe->SetRadius(2.0);
      probe->Update();
      vtkDataArray* c = probe->GetOutput()->GetPointData()->GetArray("Colors");
      const bool isTop = sheet == top.Get();
      for (vtkIdType p = 0; p < c->GetNumberOfTuples(); ++p)
      {
        // Red on the top sheet, white on the bottom one; a mix is wrong on both.
        wrong += c->GetComponent(p, 1) != (isTop ? 0.0 : 255.0);
      }
    }
    if (aware)
    {
      EXPECT_EQ(wrong, 0);
    }
    else
    {
      EXPECT_GT(wrong, 0); // without the facing test the other sheet's colour leaks
    }
  }
}

//------------------------------------------------------------------------------
TEST(ProbeFilter, SelectsAndPassesArrays)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedSphere();
  vtkSmartPointer<vtkPolyData> surface = ProbeSphere();
  vtkNew<vtkFloatArray> mine;
  mine->SetName("Mine");
  mine->SetNumberOfValues(surface->GetNumberOfPoints());
  mine->Fill(3.0);
  surface->GetPointData()->AddArray(mine);
  vtkNew<vtkOFBProbeFilter> probe;
  probe->SetInputData(surface);
  probe->SetOFBData(ofb);
  probe->AddArrayName("Height");
  probe->Update();
  vtkPointData* pd = probe->GetOutput()->GetPointData();
  EXPECT_NE(pd->GetArray("Height"), nullptr);
  EXPECT_EQ(pd->GetArray("Colors"), nullptr);
  EXPECT_NE(pd->GetArray("Mine"), nullptr);
  EXPECT_EQ(probe->GetOutput()->GetNumberOfPolys(), surface->GetNumberOfPolys());
  probe->PassPointArraysOff();
  probe->SetValidPointMaskArrayName("");
  probe->Update();
  pd = probe->GetOutput()->GetPointData();
  EXPECT_EQ(pd->GetArray("Mine"), nullptr);
  EXPECT_EQ(pd->GetArray("vtkValidPointMask"), nullptr);
  EXPECT_NE(pd->GetArray("Height"), nullptr);
}

//------------------------------------------------------------------------------
TEST(ProbeFilter, BadInput)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedSphere();
  vtkSmartPointer<vtkPolyData> surface = ProbeSphere();
  vtkNew<MessageObserver> o;
  // No OFB, an empty OFB.
  {
    vtkNew<vtkOFBProbeFilter> probe;
    o->Watch(probe);
    probe->SetInputData(surface);
    probe->SetOFBData(vtkNew<vtkOFB>());
    probe->Update();
    EXPECT_NE(o->Errors.find("empty"), std::string::npos) << o->Errors;
    EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), 0);
  }
  // Radius 0, NaN, infinite; an array the OFB lacks.
  for (double radius : { 0.0, -1.0, std::nan(""), HUGE_VAL })
  {
    o->Clear();
    vtkNew<vtkOFBProbeFilter> probe;
    o->Watch(probe);
    probe->SetInputData(surface);
    probe->SetOFBData(ofb);
    probe->SetRadius(radius);
    probe->Update();
    EXPECT_NE(o->Errors.find("Radius"), std::string::npos) << radius;
    EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    o->Clear();
    vtkNew<vtkOFBProbeFilter> probe;
    o->Watch(probe);
    probe->SetInputData(surface);
    probe->SetOFBData(ofb);
    probe->AddArrayName("NoSuchArray");
    probe->Update();
    EXPECT_NE(o->Errors.find("NoSuchArray"), std::string::npos);
    EXPECT_EQ(probe->GetOutput()->GetNumberOfPoints(), 0);
  }
  // Points far from the surface and NaN points find nothing: zeros and a 0 in the mask.
  vtkNew<vtkPolyData> odd;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 1.0); // on the sphere
  points->InsertNextPoint(5.0, 5.0, 5.0);
  points->InsertNextPoint(std::nan(""), 0.0, 0.0);
  points->InsertNextPoint(0.0, 0.0, 0.0); // the centre, far from every sample
  odd->SetPoints(points);
  o->Clear();
  vtkNew<vtkOFBProbeFilter> probe;
  o->Watch(probe);
  probe->SetInputData(odd);
  probe->SetOFBData(ofb);
  probe->SetLookupModeToSmooth();
  probe->Update();
  EXPECT_TRUE(o->Errors.empty()) << o->Errors;
  vtkDataArray* mask = probe->GetOutput()->GetPointData()->GetArray("vtkValidPointMask");
  vtkDataArray* height = probe->GetOutput()->GetPointData()->GetArray("Height");
  ASSERT_NE(mask, nullptr);
  EXPECT_EQ(mask->GetComponent(0, 0), 1.0);
  EXPECT_NEAR(height->GetComponent(0, 0), 1.0, 0.05);
  for (vtkIdType p = 1; p < 4; ++p)
  {
    EXPECT_EQ(mask->GetComponent(p, 0), 0.0) << p;
    EXPECT_EQ(height->GetComponent(p, 0), 0.0) << p;
  }
  EXPECT_EQ(probe->GetNumberOfInvalidPoints(), 3);
}
