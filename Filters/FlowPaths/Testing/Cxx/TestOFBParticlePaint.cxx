// Surface particles of vtkOFBParticleAdvector: footprints, chains, colours, smear,
// the OFB inputs, and bad input.
#include "vtkOFBParticleTestUtilities.h"
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <limits>

using namespace vtkofbtest;

namespace
{
const double ZAxis[3] = { 0.0, 0.0, 1.0 };
const double Origin[3] = { 0.0, 0.0, 0.0 };

vtkSmartPointer<vtkPolyData> RotatingSphere(int resolution = 64)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, resolution);
  SetRotationField(sphere, ZAxis, Origin);
  return sphere;
}

vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}
}

// The footprints colour exactly the samples within their radius of the positions
// the particles went through, as painting those positions by hand does.
TEST(ParticlePaint, FootprintsMatchHandPainting)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkSmartPointer<vtkOFB> original = Build(sphere, 128);
  vtkNew<vtkOFB> painted;
  painted->DeepCopy(original);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetOFB(painted);
  advector->SetNumberOfParticles(6);
  advector->SetColor(0.0, 0.5, 1.0);
  advector->SetFootprintRadius(2.5);
  std::vector<std::array<double, 3>> path;
  for (int s = 0; s < 15; ++s)
  {
    advector->Step();
    vtkPoints* points = advector->GetParticles()->GetPoints();
    ASSERT_EQ(points->GetNumberOfPoints(), 6);
    for (vtkIdType i = 0; i < 6; ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      path.push_back({ x[0], x[1], x[2] });
    }
  }
  // By hand: the same brush at the recorded positions.
  vtkNew<vtkOFB> byHand;
  byHand->DeepCopy(original);
  vtkNew<vtkOFBPainter> painter;
  vtkNew<vtkOFBBrush> brush;
  brush->SetColor(0.0, 0.5, 1.0);
  brush->SetFalloffToConstant(); // the advector's default
  brush->SetBlendModeToMix();
  brush->SetRadius(2.5 * original->GetCellSize());
  painter->SetBrush(brush);
  painter->SetOFB(byHand);
  for (const auto& x : path)
  {
    painter->Dab(x.data());
  }
  vtkUnsignedCharArray* a = Colors(painted);
  vtkUnsignedCharArray* b = Colors(byHand);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  const double r2 = std::pow(2.5 * original->GetCellSize(), 2);
  vtkIdType inside = 0;
  for (vtkIdType id = 0; id < painted->GetNumberOfSamples(); ++id)
  {
    double p[3];
    painted->GetSamplePosition(id, p);
    bool within = false;
    for (const auto& x : path)
    {
      within = within || vtkMath::Distance2BetweenPoints(p, x.data()) <= r2;
    }
    inside += within ? 1 : 0;
    for (int c = 0; c < 4; ++c)
    {
      ASSERT_EQ(a->GetTypedComponent(id, c), b->GetTypedComponent(id, c)) << "sample " << id;
    }
    const unsigned char expected[4] = { 0, 128, 255, 255 };
    if (within)
    {
      EXPECT_EQ(a->GetTypedComponent(id, 1), expected[1]) << "sample " << id;
      EXPECT_EQ(a->GetTypedComponent(id, 2), expected[2]) << "sample " << id;
    }
    else
    {
      EXPECT_EQ(a->GetTypedComponent(id, 2), 255); // white, untouched
      EXPECT_EQ(a->GetTypedComponent(id, 0), 255) << "sample " << id;
    }
  }
  EXPECT_GT(inside, 100);
}

// The port-1 OFB is copied (the input is left as it was); SetOFB paints in place.
TEST(ParticlePaint, InputOFBCopiedHeldOFBInPlace)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkSmartPointer<vtkOFB> input = Build(sphere, 64);
  vtkNew<vtkOFB> before;
  before->DeepCopy(input);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetOFBData(input);
  advector->SetNumberOfParticles(20);
  advector->SetStepsPerUpdate(5);
  advector->Step();
  auto changed = [](vtkOFB* x, vtkOFB* y)
  {
    vtkIdType n = 0;
    for (vtkIdType id = 0; id < x->GetNumberOfSamples(); ++id)
    {
      n += Colors(x)->GetTypedComponent(id, 1) != Colors(y)->GetTypedComponent(id, 1) ? 1 : 0;
    }
    return n;
  };
  EXPECT_EQ(changed(input, before), 0);
  ASSERT_EQ(advector->GetOutput()->GetNumberOfSamples(), input->GetNumberOfSamples());
  EXPECT_GT(changed(advector->GetOutput(), before), 20);
  // Held: painted in place, and the output shares it.
  advector->SetOFB(input);
  advector->Step();
  EXPECT_GT(changed(input, before), 20);
}

// Chain member k paints with radius and strength scaled by 1 - k / ChainLength and
// is released k * ChainSpacing steps after the head.
TEST(ParticlePaint, ChainsFadeAsSpecified)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkSmartPointer<vtkOFB> ofb = Build(sphere, 64);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetOFB(ofb);
  advector->SetSeeds(MakeSeeds({ { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 } }));
  advector->SetChainLength(4);
  advector->SetChainSpacing(2);
  advector->SetFootprintRadius(3.0);
  advector->GetBrush()->SetStrength(0.8);
  advector->Update();
  EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 2); // the heads
  advector->SetStepsPerUpdate(3);
  advector->Step(); // step 3: heads and k = 1
  EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 4);
  advector->Step(); // step 6: all released
  EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 8);
  advector->SetStepsPerUpdate(1);
  advector->Step();
  vtkPolyData* footprints = advector->GetFootprints();
  ASSERT_EQ(footprints->GetNumberOfPoints(), 8);
  vtkDataArray* radius = footprints->GetPointData()->GetArray("Radius");
  vtkDataArray* strength = footprints->GetPointData()->GetArray("Strength");
  ASSERT_NE(radius, nullptr);
  ASSERT_NE(strength, nullptr);
  auto* chain =
    vtkIntArray::SafeDownCast(advector->GetParticles()->GetPointData()->GetArray("ChainIndex"));
  ASSERT_NE(chain, nullptr);
  const double cell = ofb->GetCellSize();
  for (vtkIdType i = 0; i < 8; ++i)
  {
    const int k = chain->GetValue(i);
    EXPECT_EQ(k, static_cast<int>(i % 4));
    EXPECT_NEAR(radius->GetTuple1(i), 3.0 * cell * (1.0 - k / 4.0), 1e-12);
    EXPECT_NEAR(strength->GetTuple1(i), 0.8 * (1.0 - k / 4.0), 1e-12);
  }
  // The later members follow behind the head on the same streamline.
  double head[3], tail[3];
  advector->GetParticles()->GetPoint(0, head);
  advector->GetParticles()->GetPoint(3, tail);
  EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(head, tail)), 6.0 * cell, 0.1 * cell);
}

// The periodic colour goes red, blue, green over ColorPeriod steps.
TEST(ParticlePaint, PeriodicColorOnSchedule)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetNumberOfParticles(3);
  advector->SetColorModeToPeriodic();
  advector->SetColorPeriod(30);
  const struct
  {
    int Steps;
    unsigned char Rgb[3];
  } schedule[] = { { 5, { 128, 0, 128 } },
    { 10, { 0, 0, 255 } },
    { 20, { 0, 255, 0 } },
    { 25, { 128, 128, 0 } },
    { 30, { 255, 0, 0 } },
    { 40, { 0, 0, 255 } } };
  int done = 0;
  for (const auto& entry : schedule)
  {
    advector->SetStepsPerUpdate(entry.Steps - done);
    advector->Step();
    done = entry.Steps;
    auto* color = vtkUnsignedCharArray::SafeDownCast(
      advector->GetParticles()->GetPointData()->GetArray("Color"));
    ASSERT_NE(color, nullptr);
    for (vtkIdType i = 0; i < 3; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(color->GetTypedComponent(i, c), entry.Rgb[c], 1) << "step " << entry.Steps;
      }
    }
  }
}

// Colour from a seed array and by a scalar.
TEST(ParticlePaint, ColorFromSeedsAndByScalar)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkSmartPointer<vtkPolyData> seeds = MakeSeeds({ { 1.0, 0.0, 0.0 }, { 0.0, 0.0, 1.0 } });
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("SeedRGB");
  rgb->SetNumberOfComponents(3);
  rgb->InsertNextTuple3(10, 20, 30);
  rgb->InsertNextTuple3(200, 100, 50);
  seeds->GetPointData()->AddArray(rgb);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetSeeds(seeds);
  advector->SetColorModeToFromSeeds();
  advector->SetSeedColorArrayName("SeedRGB");
  advector->Step();
  auto* color =
    vtkUnsignedCharArray::SafeDownCast(advector->GetParticles()->GetPointData()->GetArray("Color"));
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->GetTypedComponent(0, 0), 10);
  EXPECT_EQ(color->GetTypedComponent(1, 1), 100);
  // By height z through the default blue-to-red table: the pole is red.
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    height->InsertNextValue(sphere->GetPoint(i)[2]);
  }
  sphere->GetPointData()->AddArray(height);
  advector->SetColorModeToByScalar();
  advector->SetScalarArrayName("Height");
  advector->Step();
  color =
    vtkUnsignedCharArray::SafeDownCast(advector->GetParticles()->GetPointData()->GetArray("Color"));
  EXPECT_GT(color->GetTypedComponent(1, 0), 200); // at the pole: red
  EXPECT_LT(color->GetTypedComponent(1, 2), 50);
  // Far above the table's range: its last colour (red), not its first (the conversion of
  // the position in the table to an integer overflowed).
  vtkNew<vtkLookupTable> table;
  table->SetHueRange(0.667, 0.0);
  table->SetRange(0.0, 1.0);
  table->Build();
  advector->SetLookupTable(table);
  height->Fill(1e300);
  height->Modified();
  advector->Step();
  color =
    vtkUnsignedCharArray::SafeDownCast(advector->GetParticles()->GetPointData()->GetArray("Color"));
  EXPECT_GT(color->GetTypedComponent(0, 0), 200);
  EXPECT_LT(color->GetTypedComponent(0, 2), 50);
}

// Smear: the footprints carry the previous positions.
TEST(ParticlePaint, SmearCarriesPreviousPositions)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetNumberOfParticles(4);
  advector->GetBrush()->SetTargetToSmear();
  advector->GetBrush()->SetSmearAmount(0.7);
  advector->Step();
  vtkNew<vtkPoints> previous;
  previous->SetDataTypeToDouble();
  previous->DeepCopy(advector->GetParticles()->GetPoints());
  advector->Step();
  vtkDataArray* source = advector->GetFootprints()->GetPointData()->GetArray("PreviousPosition");
  ASSERT_NE(source, nullptr);
  for (vtkIdType i = 0; i < 4; ++i)
  {
    double a[3];
    previous->GetPoint(i, a);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, source->GetTuple3(i)), 0.0);
  }
}

namespace
{
// Updates `advector` and expects the error `what` and empty outputs.
void ExpectEmptyWithError(MessageObserver* messages,
  vtkOFBParticleAdvector* advector,
  const char* what)
{
  messages->Clear();
  messages->Watch(advector);
  advector->Update();
  EXPECT_NE(messages->Errors.find(what), std::string::npos) << messages->Errors;
  EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 0);
  EXPECT_EQ(advector->GetTrails()->GetNumberOfPoints(), 0);
  EXPECT_EQ(advector->GetOutput()->GetNumberOfSamples(), 0);
}
}

// Bad input: a clear error and empty outputs, never a crash.
TEST(ParticlePaint, BadInput)
{
  vtkNew<MessageObserver> messages;
  auto expectEmpty = [&](vtkOFBParticleAdvector* advector, const char* what)
  { ExpectEmptyWithError(messages, advector, what); };
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  {
    vtkNew<vtkOFBParticleAdvector> advector; // no vectors
    advector->SetInputData(sphere);
    expectEmpty(advector, "no vector field");
  }
  {
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(sphere);
    vtkNew<vtkDoubleArray> v2;
    v2->SetNumberOfComponents(2);
    v2->SetNumberOfTuples(copy->GetNumberOfPoints());
    v2->Fill(1.0);
    v2->SetName("Flat");
    copy->GetPointData()->AddArray(v2);
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(copy);
    advector->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Flat");
    expectEmpty(advector, "components, not 3");
    // Fewer tuples than points: an error, not a read past the array's end.
    v2->SetNumberOfComponents(3);
    v2->SetNumberOfTuples(copy->GetNumberOfPoints() / 2);
    v2->Fill(1.0);
    v2->Modified();
    expectEmpty(advector, "tuples for");
  }
  {
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(sphere);
    SetField(copy, [](const double*, double* v) { v[0] = v[1] = v[2] = 0.0; });
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(copy);
    expectEmpty(advector, "zero everywhere");
    SetField(copy,
      [](const double* x, double* v)
      {
        v[0] = x[0] > 0.9 ? std::numeric_limits<double>::quiet_NaN() : 1.0;
        v[1] = v[2] = 0.0;
      });
    expectEmpty(advector, "non-finite");
  }
  vtkSmartPointer<vtkPolyData> rotating = RotatingSphere(32);
  for (double step : { 0.0, -1.0, std::numeric_limits<double>::quiet_NaN() })
  {
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(rotating);
    advector->SetStepSize(step);
    expectEmpty(advector, "StepSize must be positive");
  }
  // A step of more than four times the surface (1024 cells without an OFB): an error at
  // once (1e300 cells walked the sphere for minutes a step); four times steps.
  for (double step : { 1e300, 5000.0, 4000.0 })
  {
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(rotating);
    advector->SetNumberOfParticles(50);
    advector->SetStepSize(step);
    if (step > 4096.0)
    {
      expectEmpty(advector, "more than four times the surface's extent");
      continue;
    }
    advector->Update();
    advector->Step();
    EXPECT_EQ(vtkPolyData::SafeDownCast(advector->GetOutputDataObject(1))->GetNumberOfPoints(), 50);
  }
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(empty);
    expectEmpty(advector, "no polygons");
  }
  // NaN seeds and seeds far from the surface are rejected with a warning; seeds
  // near it are moved onto it.
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(rotating);
    advector->SetSeeds(MakeSeeds({ { nan, 0.0, 0.0 }, { 5.0, 0.0, 0.0 }, { 1.001, 0.0, 0.0 } }));
    messages->Clear();
    messages->Watch(advector);
    advector->Update();
    EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
    EXPECT_NE(messages->Warnings.find("non-finite"), std::string::npos) << messages->Warnings;
    EXPECT_NE(messages->Warnings.find("farther than MaximumSeedDistance"), std::string::npos);
    ASSERT_EQ(advector->GetParticles()->GetNumberOfPoints(), 1);
    double x[3];
    advector->GetParticles()->GetPoint(0, x);
    EXPECT_LT(std::abs(vtkMath::Norm(x) - 1.0), 2e-3); // on the sphere's facets
  }
  // Seed colours and colouring scalars with fewer tuples than seeds or points: not used,
  // with a warning; the particles are there and take the constant colour.
  {
    vtkSmartPointer<vtkPolyData> seeds = MakeSeeds({ { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 } });
    vtkNew<vtkUnsignedCharArray> seedColors;
    seedColors->SetName("SeedColor");
    seedColors->SetNumberOfComponents(3);
    seedColors->SetNumberOfTuples(1);
    seedColors->Fill(200);
    seeds->GetPointData()->AddArray(seedColors);
    vtkNew<vtkPolyData> surface;
    surface->DeepCopy(rotating);
    vtkNew<vtkFloatArray> scalars;
    scalars->SetName("Height");
    scalars->SetNumberOfTuples(3);
    scalars->Fill(1.0);
    surface->GetPointData()->AddArray(scalars);
    for (int mode :
      { vtkOFBParticleAdvector::COLOR_FROM_SEEDS, vtkOFBParticleAdvector::COLOR_BY_SCALAR })
    {
      vtkNew<vtkOFBParticleAdvector> advector;
      advector->SetInputData(surface);
      advector->SetSeeds(seeds);
      advector->SetSeedColorArrayName("SeedColor");
      advector->SetScalarArrayName("Height");
      advector->SetColorMode(mode);
      messages->Clear();
      messages->Watch(advector);
      advector->Update();
      EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
      EXPECT_NE(messages->Warnings.find(
                  mode == vtkOFBParticleAdvector::COLOR_FROM_SEEDS ? "'SeedColor'" : "'Height'"),
        std::string::npos)
        << messages->Warnings;
      EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 2);
    }
  }
  // Cell vectors hold on their cells' triangles (no averaging, no warning): on a plane
  // of quads whose cells have different vectors, a particle inside a cell moves along
  // its own cell's vector.
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-1.0, -1.0, 0.0);
    plane->SetPoint1(1.0, -1.0, 0.0);
    plane->SetPoint2(-1.0, 1.0, 0.0);
    plane->SetResolution(4, 4);
    plane->Update();
    vtkNew<vtkPolyData> cells;
    cells->DeepCopy(plane->GetOutput());
    cells->GetPointData()->Initialize();
    vtkNew<vtkDoubleArray> v;
    v->SetNumberOfComponents(3);
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      v->InsertNextTuple3(1.0, 0.1 * static_cast<double>(c) - 0.8, 0.0);
    }
    cells->GetCellData()->SetVectors(v);
    // A seed in the middle of cell 5 (column 1, row 1: x in [-0.5, 0], y in [-0.5, 0]).
    vtkNew<vtkPolyData> seeds;
    vtkNew<vtkPoints> seedPoints;
    seedPoints->InsertNextPoint(-0.25, -0.25, 0.0);
    seeds->SetPoints(seedPoints);
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(cells);
    advector->SetSourceData(seeds);
    advector->PaintOff();
    messages->Clear();
    messages->Watch(advector);
    advector->Step();
    EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
    EXPECT_TRUE(messages->Warnings.empty()) << messages->Warnings;
    ASSERT_EQ(advector->GetParticles()->GetNumberOfPoints(), 1);
    double x[3];
    advector->GetParticles()->GetPoint(0, x);
    const double expected = 0.1 * 5 - 0.8; // cell 5's slope dy/dx
    ASSERT_GT(x[0] + 0.25, 0.0);
    EXPECT_NEAR((x[1] + 0.25) / (x[0] + 0.25), expected, 1e-5);
  }
}

// Bad settings: NaN where the setters' clamps let it through, particles beyond MemoryLimit.
TEST(ParticlePaint, NaNSettingsAndMemoryLimit)
{
  vtkNew<MessageObserver> messages;
  auto expectEmpty = [&](vtkOFBParticleAdvector* advector, const char* what)
  { ExpectEmptyWithError(messages, advector, what); };
  vtkSmartPointer<vtkPolyData> rotating = RotatingSphere(32);
  // A NaN footprint radius, strength or colour (NaN passes the setters' clamps).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(rotating);
    advector->SetFootprintRadius(k == 0 ? nan : 2.5);
    advector->GetBrush()->SetStrength(k == 1 ? nan : 1.0);
    advector->SetColor(k == 2 ? nan : 1.0, 0.0, 0.0);
    expectEmpty(advector, "must be finite");
  }
  // Particles, chains or trails beyond MemoryLimit: an error before anything is
  // allocated (not an exhausted memory), and the advector recovers when they fit.
  {
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(rotating);
    advector->SetNumberOfParticles(VTK_ID_MAX / 2);
    expectEmpty(advector, "MemoryLimit");
    advector->SetNumberOfParticles(10000);
    advector->SetTrailLength(1000000);
    expectEmpty(advector, "MemoryLimit");
    advector->SetTrailLength(16);
    advector->SetNumberOfParticles(20);
    advector->SetChainLength(1000000);
    expectEmpty(advector, "MemoryLimit");
    advector->SetChainLength(1);
    advector->SetNumberOfParticles(100000);
    advector->SetMemoryLimit(1);
    expectEmpty(advector, "MemoryLimit");
    advector->SetMemoryLimit(4096);
    advector->SetNumberOfParticles(100);
    messages->Clear();
    advector->Update();
    EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
    EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 100);
  }
}

// The advector's brush refuses a value that is no enumerator (the advector's Falloff and
// BlendMode once took any int), and a change of it re-executes the advector.
TEST(ParticlePaint, BrushRefusesUnknownEnumeratorsAndReexecutes)
{
  vtkNew<vtkOFBParticleAdvector> advector;
  vtkOFBBrush* brush = advector->GetBrush();
  ASSERT_NE(brush, nullptr);
  EXPECT_EQ(brush->GetFalloff(), vtkOFBBrush::FALLOFF_CONSTANT); // the advector's default
  vtkNew<MessageObserver> messages;
  messages->Watch(brush);
  brush->SetFalloff(99);
  EXPECT_NE(messages->Errors.find("not a FalloffType"), std::string::npos);
  EXPECT_EQ(brush->GetFalloff(), vtkOFBBrush::FALLOFF_CONSTANT);
  messages->Clear();
  brush->SetBlendMode(99);
  EXPECT_NE(messages->Errors.find("not a BlendModeType"), std::string::npos);
  EXPECT_EQ(brush->GetBlendMode(), vtkOFBBrush::BLEND_MIX);
  const vtkMTimeType t = advector->GetMTime();
  brush->SetFalloffToSmooth();
  EXPECT_GT(advector->GetMTime(), t);
}

// The painted OFB does not depend on the number of threads.
TEST(ParticlePaint, OneAndTwoThreadsPaintTheSame)
{
  vtkSmartPointer<vtkPolyData> sphere = RotatingSphere();
  vtkSmartPointer<vtkOFB> original = Build(sphere, 128);
  std::vector<unsigned char> results[2];
  for (int threads = 1; threads <= 2; ++threads)
  {
    vtkSMPTools::Initialize(threads);
    vtkNew<vtkOFB> ofb;
    ofb->DeepCopy(original);
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(sphere);
    advector->SetOFB(ofb);
    advector->SetNumberOfParticles(500);
    advector->SetColorModeToPeriodic();
    advector->SetColorPeriod(7);
    advector->GetBrush()->SetStrength(0.6);
    advector->GetBrush()->SetFalloff(vtkOFBBrush::FALLOFF_SMOOTH);
    advector->GetBrush()->SetTargetToSmear();
    advector->GetBrush()->SetSmearAmount(0.3);
    advector->SetLifetime(9);
    advector->SetStepsPerUpdate(25);
    advector->Step();
    vtkUnsignedCharArray* colors = Colors(ofb);
    results[threads - 1].assign(
      colors->GetPointer(0), colors->GetPointer(0) + 4 * colors->GetNumberOfTuples());
  }
  vtkSMPTools::Initialize(0);
  EXPECT_FALSE(results[0].empty());
  EXPECT_TRUE(results[0] == results[1]);
}

//------------------------------------------------------------------------------
TEST(ParticlePaint, MissingInputsOrBrushAreErrors)
{
  vtkNew<MessageObserver> messages;
  // No surface at all: the pipeline's error, no crash.
  {
    vtkNew<vtkOFBParticleAdvector> advector;
    messages->Clear();
    messages->Watch(advector);
    messages->Watch(advector->GetExecutive());
    advector->Update();
    EXPECT_FALSE(messages->Errors.empty());
  }
  // No brush.
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(RotatingSphere(32));
  advector->SetBrush(nullptr);
  ExpectEmptyWithError(messages, advector, "No brush");
  // No OFB of its own to paint (SetOFB(nullptr)) still works: it builds one.
  vtkNew<vtkOFBParticleAdvector> own;
  own->SetInputData(RotatingSphere(32));
  own->SetOFB(nullptr);
  messages->Clear();
  messages->Watch(own);
  own->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
}
