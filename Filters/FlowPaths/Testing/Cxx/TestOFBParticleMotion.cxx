// Surface particles of vtkOFBParticleAdvector: accuracy, staying on the surface,
// boundaries, determinism and time requests (no painting).
#include "vtkOFBParticleTestUtilities.h"
#include "vtkOFBTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkPlaneSource.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

using namespace vtkofbtest;

namespace
{
const double ZAxis[3] = { 0.0, 0.0, 1.0 };
const double Origin[3] = { 0.0, 0.0, 0.0 };

// Seeds on the unit sphere at latitudes from -60 to 60 degrees.
vtkSmartPointer<vtkPolyData> SphereSeeds(int n)
{
  std::vector<std::array<double, 3>> xs;
  for (int i = 0; i < n; ++i)
  {
    const double lat = vtkMath::RadiansFromDegrees(-60.0 + 120.0 * (i + 0.5) / n);
    const double lon = 2.0 * vtkMath::Pi() * i / n;
    xs.push_back({ std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat) });
  }
  return MakeSeeds(xs);
}

// Largest distance (in cells) of the particles to the circles of their first
// positions, after `steps` steps of a time-accurate rotation.
double RotationError(int integrator, int steps, int resolution, double* phaseError = nullptr)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, resolution);
  SetRotationField(sphere, ZAxis, Origin);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetSeeds(SphereSeeds(40));
  advector->SetIntegrator(integrator);
  advector->NormalizeVectorsOff(); // a common time step: one revolution in `steps` steps
  advector->Update();
  const double cell = advector->GetCellSize();
  const double maxSpeed = sphere->GetPointData()->GetVectors()->GetMaxNorm();
  advector->SetStepSize(2.0 * vtkMath::Pi() * maxSpeed / (steps * cell));
  advector->Update();
  vtkNew<vtkPoints> start;
  start->SetDataTypeToDouble();
  start->DeepCopy(advector->GetParticles()->GetPoints());
  advector->SetStepsPerUpdate(steps);
  advector->Step();
  vtkPoints* end = advector->GetParticles()->GetPoints();
  EXPECT_EQ(end->GetNumberOfPoints(), start->GetNumberOfPoints());
  double worst = 0.0;
  double worstPhase = 0.0;
  for (vtkIdType i = 0; i < end->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    start->GetPoint(i, a);
    end->GetPoint(i, b);
    const double rho0 = std::hypot(a[0], a[1]);
    const double rho = std::hypot(b[0], b[1]);
    worst = std::max(worst, std::hypot(rho - rho0, b[2] - a[2]));
    worstPhase = std::max(worstPhase, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
  }
  if (phaseError)
  {
    *phaseError = worstPhase / cell;
  }
  return worst / cell;
}
}

TEST(Particles, SphereRotationRK4WithinQuarterCell)
{
  double phase = 0.0;
  const double error = RotationError(vtkOFBParticleAdvector::RK4, 2000, 256, &phase);
  std::cout << "RK4 one revolution: circle error " << error << " cells, back at start within "
            << phase << " cells\n";
  EXPECT_LT(error, 0.25);
  EXPECT_LT(phase, 1.0);
}

TEST(Particles, SphereRotationIntegratorsOrdered)
{
  const double euler = RotationError(vtkOFBParticleAdvector::EULER, 300, 128);
  const double rk2 = RotationError(vtkOFBParticleAdvector::RK2, 300, 128);
  const double rk4 = RotationError(vtkOFBParticleAdvector::RK4, 300, 128);
  const double rk45 = RotationError(vtkOFBParticleAdvector::RK45, 300, 128);
  std::cout << "one revolution in 300 steps, circle error (cells): Euler " << euler << ", RK2 "
            << rk2 << ", RK4 " << rk4 << ", RK45 " << rk45 << "\n";
  EXPECT_GT(euler, 10.0 * rk2); // Euler spirals outwards
  EXPECT_LT(rk4, 0.25);
  EXPECT_LT(rk45, 0.25);
}

// Every particle stays on the bundled meshes (and none is lost) after 1000 steps.
class ParticlesOnMesh : public ::testing::TestWithParam<const char*>
{
};

TEST_P(ParticlesOnMesh, StayOnSurfaceFor1000Steps)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(GetParam());
  ASSERT_NE(mesh, nullptr);
  double c[3];
  mesh->GetCenter(c);
  const double w[3] = { 0.3, 1.0, 0.2 };
  SetRotationField(mesh, w, c);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(mesh);
  advector->SetNumberOfParticles(300);
  advector->SetRandomSeed(7);
  advector->SetStepsPerUpdate(1000);
  advector->Step();
  vtkPolyData* particles = advector->GetParticles();
  ASSERT_EQ(particles->GetNumberOfPoints(), 300);
  EXPECT_EQ(advector->GetCurrentStep(), 1000);
  const double distance = MaximumDistanceToSurface(mesh, particles->GetPoints());
  std::cout << GetParam() << ": largest distance to the surface after 1000 steps "
            << distance / advector->GetCellSize() << " cells\n";
  EXPECT_LT(distance, 1e-4 * advector->GetCellSize());
  // Every id once.
  auto* ids = vtkIdTypeArray::SafeDownCast(particles->GetPointData()->GetArray("Id"));
  ASSERT_NE(ids, nullptr);
  std::set<vtkIdType> unique;
  for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
  {
    unique.insert(ids->GetValue(i));
  }
  EXPECT_EQ(unique.size(), 300u);
  EXPECT_EQ(*unique.rbegin(), 299);
  // The trails too lie on the surface, and particles moved.
  EXPECT_LT(MaximumDistanceToSurface(mesh, advector->GetTrails()->GetPoints()),
    1e-4 * advector->GetCellSize());
  EXPECT_GT(advector->GetTrails()->GetNumberOfCells(), 250);
}

INSTANTIATE_TEST_SUITE_P(BundledMeshes,
  ParticlesOnMesh,
  ::testing::Values("stanford-bunny.obj",
    "horse.ply",
    "fandisk.obj",
    "rocker-arm.obj",
    "teapot.obj"));

// A field along the meridians of a torus: particles go once round the tube,
// over the inner and the outer side, and come back where they started.
TEST(Particles, TorusMeridiansCrossTheWholeSurface)
{
  const double R = 1.0, r = 0.4;
  vtkSmartPointer<vtkPolyData> torus = MakeTorus(R, r, 64);
  SetField(torus,
    [&](const double* x, double* v)
    {
      const double rho = std::hypot(x[0], x[1]);
      const double e[3] = { x[0] / rho, x[1] / rho, 0.0 };            // radial
      const double n[3] = { x[0] - R * e[0], x[1] - R * e[1], x[2] }; // out of the tube
      const double phi[3] = { -e[1], e[0], 0.0 };                     // along the ring
      vtkMath::Cross(phi, n, v);
    });
  std::vector<std::array<double, 3>> xs;
  for (int i = 0; i < 12; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / 12;
    xs.push_back({ (R + r) * std::cos(a), (R + r) * std::sin(a), 0.0 });
  }
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(torus);
  advector->SetSeeds(MakeSeeds(xs));
  advector->Update();
  const double cell = advector->GetCellSize();
  const int steps = 200;
  advector->SetStepSize(2.0 * vtkMath::Pi() * r / (steps * cell)); // one turn round the tube
  advector->Update();
  std::vector<double> turned(xs.size(), 0.0);
  std::vector<double> previous(xs.size(), 0.0);
  double worstSurface = 0.0;
  double worstRing = 0.0;
  for (int s = 0; s <= steps; ++s)
  {
    if (s > 0)
    {
      advector->Step();
    }
    vtkPoints* points = advector->GetParticles()->GetPoints();
    ASSERT_EQ(points->GetNumberOfPoints(), static_cast<vtkIdType>(xs.size()));
    worstSurface = std::max(worstSurface, MaximumDistanceToSurface(torus, points));
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      const double rho = std::hypot(x[0], x[1]);
      const double angle = std::atan2(x[2], rho - R); // round the tube
      if (s > 0)
      {
        double d = angle - previous[i];
        d -= 2.0 * vtkMath::Pi() * std::round(d / (2.0 * vtkMath::Pi()));
        turned[i] += d;
      }
      previous[i] = angle;
      // It stays on its meridian: the angle about z does not change.
      const double a = std::atan2(x[1], x[0]) - std::atan2(xs[i][1], xs[i][0]);
      worstRing = std::max(worstRing, std::abs(std::remainder(a, 2.0 * vtkMath::Pi())) * rho);
    }
  }
  EXPECT_LT(worstSurface, 1e-4 * cell);
  EXPECT_LT(worstRing, 0.25 * cell);
  for (double t : turned)
  {
    EXPECT_NEAR(std::abs(t), 2.0 * vtkMath::Pi(), 0.01);
  }
}

// An open surface: particles stop on its boundary edge, no particle is lost, and
// with a lifetime they are reseeded.
TEST(Particles, OpenSurfaceBoundaryStops)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(40, 40);
  plane->Update();
  vtkSmartPointer<vtkPolyData> mesh = plane->GetOutput();
  SetField(mesh,
    [](const double*, double* v)
    {
      v[0] = 1.0;
      v[1] = 0.3;
      v[2] = 0.0;
    });
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(mesh);
  advector->SetNumberOfParticles(50);
  advector->SetStepSize(20.0);
  advector->SetStepsPerUpdate(200); // 4000 cells: far beyond the plane
  advector->Step();
  vtkPolyData* particles = advector->GetParticles();
  ASSERT_EQ(particles->GetNumberOfPoints(), 50);
  for (vtkIdType i = 0; i < 50; ++i)
  {
    double x[3];
    particles->GetPoint(i, x);
    // On the right or top edge of the square [-0.5, 0.5]^2.
    EXPECT_TRUE(std::abs(x[0] - 0.5) < 1e-9 || std::abs(x[1] - 0.5) < 1e-9) << x[0] << " " << x[1];
    EXPECT_NEAR(x[2], 0.0, 1e-12);
  }
  // Stopped particles stay.
  vtkNew<vtkPoints> before;
  before->SetDataTypeToDouble();
  before->DeepCopy(particles->GetPoints());
  advector->Step();
  for (vtkIdType i = 0; i < 50; ++i)
  {
    double a[3], b[3];
    before->GetPoint(i, a);
    advector->GetParticles()->GetPoint(i, b);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, b), 0.0);
  }
  // With a lifetime, stopped particles are reseeded inside the square.
  advector->SetLifetime(1000);
  advector->SetStepsPerUpdate(200);
  advector->Step(); // restart (a motion setting changed), 200 steps: all stopped
  advector->SetStepsPerUpdate(1);
  advector->Step(); // reseeded, one step
  int inside = 0;
  for (vtkIdType i = 0; i < advector->GetParticles()->GetNumberOfPoints(); ++i)
  {
    double x[3];
    advector->GetParticles()->GetPoint(i, x);
    inside += (x[0] < 0.5 - 1e-6 && x[1] < 0.5 - 1e-6) ? 1 : 0;
  }
  EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 50);
  EXPECT_GT(inside, 40);
}

// A mesh that repeats its points per face (an OBJ with texture coordinates, read by
// vtkOBJReader) is one surface to the particles: they cross its edges as on shared points.
TEST(Particles, CrossEdgesOfPointsRepeatedPerFace)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(20, 20);
  plane->Update();
  // Every triangle with points of its own.
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  vtkPolyData* shared = triangles->GetOutput();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (vtkIdType c = 0; c < shared->GetNumberOfCells(); ++c)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = points->InsertNextPoint(shared->GetPoint(shared->GetCell(c)->GetPointId(k)));
    }
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  SetField(mesh,
    [](const double*, double* v)
    {
      v[0] = 1.0;
      v[1] = 0.0;
      v[2] = 0.0;
    });
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(mesh);
  advector->SetSeeds(MakeSeeds({ { -0.45, 0.013, 0.0 } }));
  advector->SetStepSize(20.0);
  advector->SetStepsPerUpdate(200); // far beyond the plane: stops on its right edge
  advector->Step();
  double x[3];
  advector->GetParticles()->GetPoint(0, x);
  EXPECT_NEAR(x[0], 0.5, 1e-9); // across all 20 columns of triangles, not at the first edge
  EXPECT_NEAR(x[1], 0.013, 1e-9);
}

// A sphere whose two halves have each their own copy of the points, one copy a unit in
// the last place from the other (as pieces of a surface made apart repeat their seam
// points a rounding error apart). Particles cross the seams and end where they end on
// the sphere in one piece.
TEST(Particles, CrossSeamsOfPiecesMadeApart)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(48);
  source->SetPhiResolution(24);
  source->SetRadius(0.5);
  source->Update();
  vtkPolyData* whole = source->GetOutput();
  const vtkIdType n = whole->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    whole->GetPoint(i, x);
    points->SetPoint(i, x);
    for (double& c : x)
    {
      c = std::nextafter(c, 1.0);
    }
    points->SetPoint(n + i, x);
  }
  vtkNew<vtkCellArray> polys;
  for (vtkIdType c = 0; c < whole->GetNumberOfCells(); ++c)
  {
    vtkCell* cell = whole->GetCell(c);
    double center = 0.0;
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = cell->GetPointId(k);
      center += whole->GetPoint(ids[k])[0];
    }
    for (int k = 0; center < 0.0 && k < 3; ++k)
    {
      ids[k] += n; // the half x < 0 on the second copy
    }
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> halves;
  halves->SetPoints(points);
  halves->SetPolys(polys);

  double ends[2][3];
  vtkPolyData* surfaces[2] = { whole, halves };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkPolyData> mesh;
    mesh->ShallowCopy(surfaces[k]);
    SetRotationField(mesh, ZAxis, Origin);
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(mesh);
    advector->SetSeeds(MakeSeeds({ { 0.3, 0.05, 0.39 } }));
    advector->SetStepSize(2.0);
    advector->SetStepsPerUpdate(500); // about half a turn: across the seam at x = 0
    advector->Step();
    ASSERT_EQ(advector->GetParticles()->GetNumberOfPoints(), 1);
    advector->GetParticles()->GetPoint(0, ends[k]);
  }
  EXPECT_LT(ends[0][0], -0.2); // on the other half
  EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(ends[0], ends[1])), 1e-9);
}

// A zero region of the field stops the particles that reach it.
TEST(Particles, ZeroFieldStops)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(40, 40);
  plane->Update();
  vtkSmartPointer<vtkPolyData> mesh = plane->GetOutput();
  SetField(mesh,
    [](const double* x, double* v)
    {
      v[0] = x[0] < 0.0 ? 1.0 : 0.0;
      v[1] = 0.0;
      v[2] = 0.0;
    });
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(mesh);
  advector->SetSeeds(MakeSeeds({ { -0.4, 0.1, 0.0 } }));
  advector->SetStepsPerUpdate(2000);
  advector->Step();
  double x[3];
  advector->GetParticles()->GetPoint(0, x);
  // The field is zero from the column of points at x = 0 on: it stops before it.
  EXPECT_GT(x[0], -0.05);
  EXPECT_LE(x[0], advector->GetCellSize()); // within its last step (one cell)
}

// Results do not depend on the number of threads.
TEST(Particles, OneAndTwoThreadsIdentical)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(mesh, nullptr);
  double c[3];
  mesh->GetCenter(c);
  const double w[3] = { 0.0, 1.0, 0.3 };
  SetRotationField(mesh, w, c);
  std::vector<double> results[2];
  for (int threads = 1; threads <= 2; ++threads)
  {
    vtkSMPTools::Initialize(threads);
    vtkNew<vtkOFBParticleAdvector> advector;
    advector->SetInputData(mesh);
    advector->SetNumberOfParticles(2000);
    advector->SetIntegrator(vtkOFBParticleAdvector::RK45);
    advector->SetLifetime(30); // reseeding draws random numbers
    advector->SetStepsPerUpdate(100);
    advector->Step();
    vtkPoints* points = advector->GetParticles()->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      results[threads - 1].insert(results[threads - 1].end(), x, x + 3);
    }
  }
  vtkSMPTools::Initialize(0);
  ASSERT_EQ(results[0].size(), 6000u);
  EXPECT_TRUE(results[0] == results[1]);
}

// Time requests: forward by stepping, backward by restarting; the same positions
// as stepping by hand.
TEST(Particles, TimeRequests)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 64);
  SetRotationField(sphere, ZAxis, Origin);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetNumberOfParticles(20);
  advector->UpdateTimeStep(25.0);
  EXPECT_EQ(advector->GetCurrentStep(), 25);
  vtkNew<vtkPoints> at25;
  at25->SetDataTypeToDouble();
  at25->DeepCopy(advector->GetParticles()->GetPoints());
  advector->UpdateTimeStep(40.5);
  EXPECT_EQ(advector->GetCurrentStep(), 40);
  advector->UpdateTimeStep(25.0);
  EXPECT_EQ(advector->GetCurrentStep(), 25);
  vtkPoints* again = advector->GetParticles()->GetPoints();
  ASSERT_EQ(again->GetNumberOfPoints(), 20);
  for (vtkIdType i = 0; i < 20; ++i)
  {
    double a[3], b[3];
    at25->GetPoint(i, a);
    again->GetPoint(i, b);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, b), 0.0);
  }
  vtkNew<vtkOFBParticleAdvector> byHand;
  byHand->SetInputData(sphere);
  byHand->SetNumberOfParticles(20);
  byHand->SetStepsPerUpdate(25);
  byHand->Step();
  for (vtkIdType i = 0; i < 20; ++i)
  {
    double a[3], b[3];
    at25->GetPoint(i, a);
    byHand->GetParticles()->GetPoint(i, b);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, b), 0.0);
  }
}

// Backward tracing retraces a forward trace.
TEST(Particles, BackwardRetracesForward)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 128);
  SetRotationField(sphere, ZAxis, Origin);
  vtkNew<vtkOFBParticleAdvector> forward;
  forward->SetInputData(sphere);
  forward->SetNumberOfParticles(10);
  forward->SetStepsPerUpdate(100);
  forward->Step();
  vtkNew<vtkOFBParticleAdvector> backward;
  backward->SetInputData(sphere);
  backward->SetSeeds(forward->GetParticles());
  backward->SetDirectionToBackward();
  backward->SetStepsPerUpdate(100);
  backward->Step();
  vtkNew<vtkOFBParticleAdvector> start;
  start->SetInputData(sphere);
  start->SetNumberOfParticles(10);
  start->Update();
  for (vtkIdType i = 0; i < 10; ++i)
  {
    double a[3], b[3];
    start->GetParticles()->GetPoint(i, a);
    backward->GetParticles()->GetPoint(i, b);
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(a, b)), 0.05 * start->GetCellSize());
  }
}

// PrintSelf names every setting; many steps at once report progress.
TEST(Particles, PrintSelfAndProgress)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 32);
  SetRotationField(sphere, ZAxis, Origin);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetNumberOfParticles(10);
  advector->SetStepsPerUpdate(20);
  int events = 0;
  double last = 0.0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&events);
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* data, void*)
    {
      ++*static_cast<int*>(data);
      (void)caller;
    });
  advector->AddObserver(vtkCommand::ProgressEvent, progress);
  advector->Step();
  last = advector->GetProgress();
  EXPECT_GE(events, 20);
  EXPECT_DOUBLE_EQ(last, 1.0);
  std::ostringstream os;
  advector->Print(os);
  for (const char* name : { "Integrator: RK4",
         "StepSize: 1",
         "ErrorTolerance",
         "NormalizeVectors",
         "Direction: Forward",
         "StepsPerUpdate: 20",
         "Lifetime",
         "NumberOfParticles: 10",
         "RandomSeed",
         "MaximumSeedDistance",
         "ChainLength",
         "ChainSpacing",
         "ColorMode: Constant",
         "Color:",
         "FootprintRadius",
         "Brush",
         "Strength",
         "Falloff",
         "BlendMode",
         "SmearAmount",
         "Paint",
         "ColorPeriod",
         "SeedColorArrayName",
         "ScalarArrayName",
         "LookupTable",
         "TrailLength",
         "CurrentStep: 20" })
  {
    EXPECT_NE(os.str().find(name), std::string::npos) << name;
  }
}
