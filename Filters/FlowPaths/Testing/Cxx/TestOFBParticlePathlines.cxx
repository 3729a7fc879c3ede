// Pathlines through an unsteady field: a sphere carrying a rotation whose axis turns
// with time, given as a time-aware source (TIME_STEPS, UPDATE_TIME_STEP). The
// particles go on from step to step (no restart) and end where the exact pathline
// (the ODE integrated by fine RK4) ends, within the bound stated below.
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBTestUtilities.h"
#include "vtkOFBTurningRotationSource.h"

#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vtkofbtest;

namespace
{
/**
 * The bound on the distance between a particle and the exact pathline after
 * two time units (20 steps of 0.1; the fastest point moves 2 radians), in cells
 * (1/1024 of the sphere's diameter): the linear interpolation in time of the
 * field between steps 0.1 apart (the axis's chord against its arc: a relative
 * error of Alpha^2 dt^2 / 8 = 1.3e-3 of the speed, 2.5e-3 of the radius over the
 * run, 1.3 cells), the flat triangles of the sphere (64 x 128) and the
 * integration, with a margin.
 */
constexpr double BoundInCells = 3.0;

vtkSmartPointer<vtkPolyData> Seeds()
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 12; ++i)
  {
    double p[3];
    OnSphere(0.5 * i, 0.4 + 0.2 * i, p);
    points->InsertNextPoint(p);
  }
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  seeds->SetPoints(points);
  return seeds;
}

struct Pipeline
{
  vtkNew<TurningRotationSource> Source;
  vtkNew<vtkOFBParticleAdvector> Advector;
  Pipeline()
  {
    this->Source->Mesh = MakeSphere(1.0, 64);
    this->Advector->SetInputConnection(this->Source->GetOutputPort());
    this->Advector->SetSourceData(Seeds());
    this->Advector->SetIntegratorToRK4();
    this->Advector->SetStepSize(0.5);
    this->Advector->PaintOff();
  }
  double Cell() const { return this->Advector->GetCellSize(); }
};
}

TEST(OFBParticlePathlines, FollowTheExactPathlines)
{
  Pipeline p;
  p.Advector->UpdateTimeStep(0.0);
  vtkNew<vtkPoints> start;
  start->DeepCopy(p.Advector->GetParticles()->GetPoints());
  ASSERT_EQ(start->GetNumberOfPoints(), 12);
  vtkIdType steps = p.Advector->GetCurrentStep();
  for (int k = 1; k <= 20; ++k)
  {
    p.Advector->UpdateTimeStep(0.1 * k);
    // Going on from the particles: the step count grows, never back to zero.
    EXPECT_GT(p.Advector->GetCurrentStep(), steps) << "time " << 0.1 * k;
    steps = p.Advector->GetCurrentStep();
    EXPECT_DOUBLE_EQ(
      p.Advector->GetParticles()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 0.1 * k);
  }
  vtkPoints* end = p.Advector->GetParticles()->GetPoints();
  ASSERT_EQ(end->GetNumberOfPoints(), 12);
  double worst = 0.0, frozenBest = 1e300;
  for (vtkIdType i = 0; i < 12; ++i)
  {
    double exact[3], frozen[3], x[3];
    start->GetPoint(i, exact);
    start->GetPoint(i, frozen);
    p.Source->Advance(exact, 0.0, 2.0);
    // The field of t = 0 held (a steady field): what a tracer without time would do.
    vtkNew<TurningRotationSource> steady;
    steady->Alpha = 0.0;
    steady->Advance(frozen, 0.0, 2.0);
    end->GetPoint(i, x);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(x, exact)));
    frozenBest = std::min(frozenBest, std::sqrt(vtkMath::Distance2BetweenPoints(frozen, exact)));
  }
  const double cell = p.Cell();
  std::cout << "largest distance to the exact pathline: " << worst / cell << " cells\n";
  EXPECT_LT(worst, BoundInCells * cell);
  // The bound tells the unsteady field from a steady one.
  EXPECT_GT(frozenBest, 10.0 * BoundInCells * cell);
}

TEST(OFBParticlePathlines, TimeBackwardsRestartsAndOutsideTheRangeIsClamped)
{
  Pipeline p;
  p.Advector->UpdateTimeStep(0.0);
  vtkNew<vtkPoints> start;
  start->DeepCopy(p.Advector->GetParticles()->GetPoints());
  p.Advector->UpdateTimeStep(0.5);
  p.Advector->UpdateTimeStep(0.2); // backwards: a restart at 0.2, from the seeds
  vtkPoints* points = p.Advector->GetParticles()->GetPoints();
  ASSERT_EQ(points->GetNumberOfPoints(), 12);
  for (vtkIdType i = 0; i < 12; ++i)
  {
    double a[3], b[3];
    start->GetPoint(i, a);
    points->GetPoint(i, b);
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(a, b)), 1e-6); // float output points
  }
  // Beyond the last step (2.0): the field of the last step held (clamped, as VTK's
  // readers do); the particles move on to the time asked for.
  const vtkIdType before = p.Advector->GetCurrentStep();
  p.Advector->UpdateTimeStep(3.0);
  EXPECT_GT(p.Advector->GetCurrentStep(), before);
  EXPECT_DOUBLE_EQ(
    p.Advector->GetParticles()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 3.0);
  points = p.Advector->GetParticles()->GetPoints();
  ASSERT_EQ(points->GetNumberOfPoints(), 12);
  for (vtkIdType i = 0; i < 12; ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    EXPECT_NEAR(vtkMath::Norm(x), 1.0, 1e-3);
  }
  // A non-finite time: an error and empty outputs.
  vtkNew<MessageObserver> messages;
  messages->Watch(p.Advector);
  p.Advector->UpdateTimeStep(std::nan(""));
  EXPECT_NE(messages->Errors.find("not finite"), std::string::npos);
  EXPECT_EQ(p.Advector->GetParticles()->GetNumberOfPoints(), 0);
}

TEST(OFBParticlePathlines, ARequestThatSkipsStepsGoesThroughEach)
{
  // From t = 0 straight to t = 2: the advector reads every step between (one
  // execution a step) and ends where the step-by-step run ends.
  Pipeline jump;
  jump.Advector->UpdateTimeStep(0.0);
  vtkNew<vtkPoints> start;
  start->DeepCopy(jump.Advector->GetParticles()->GetPoints());
  const size_t before = jump.Source->RequestedTimes.size();
  jump.Advector->UpdateTimeStep(2.0);
  EXPECT_EQ(jump.Source->RequestedTimes.size() - before, 20u);
  EXPECT_DOUBLE_EQ(
    jump.Advector->GetParticles()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 2.0);

  Pipeline stepwise;
  for (int k = 0; k <= 20; ++k)
  {
    stepwise.Advector->UpdateTimeStep(0.1 * k);
  }
  vtkPoints* a = jump.Advector->GetParticles()->GetPoints();
  vtkPoints* b = stepwise.Advector->GetParticles()->GetPoints();
  ASSERT_EQ(a->GetNumberOfPoints(), 12);
  ASSERT_EQ(b->GetNumberOfPoints(), 12);
  double worst = 0.0;
  for (vtkIdType i = 0; i < 12; ++i)
  {
    double x[3], y[3], exact[3];
    a->GetPoint(i, x);
    b->GetPoint(i, y);
    start->GetPoint(i, exact);
    jump.Source->Advance(exact, 0.0, 2.0);
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(x, y)), 1e-6);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(x, exact)));
  }
  EXPECT_LT(worst, BoundInCells * jump.Cell());
}
