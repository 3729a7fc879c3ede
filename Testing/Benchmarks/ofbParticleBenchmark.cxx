// ofbParticleBenchmark: vtkOFBParticleAdvector against vtkStreamTracer with
// SurfaceStreamlines on, measured in the same run, printed as ratios.
//  1. Accuracy: a finely triangulated unit sphere with v = w x p, the same seeds and
//     the same step length for both (RK4); the distance of each end point to the
//     circle of its seed after one revolution, in OFB cells (1/1024 of the box).
//  2. Speed: RK4 particle steps per second on the horse (rotation field), the same
//     seeds, step length and number of steps for both, with 1 and 2 threads.
//  3. Painting: one step of 10,000 particles each painting a footprint of radius 2.5
//     cells into the horse's OFB at 2048, in ms, with 1 and 2 threads.
//     The step is split into advection, painting and output building as the
//     advector times them; the scaling from 1 to 2 threads of both parts.
// Rounds are interleaved with the peer and reported as medians with the load
// average (the machine may be shared); part 2 also gives the ratio of steps per
// second of processor time of the process (with 1 thread, the time spent waiting
// for a core on a loaded machine left out).
// Not a test: run it by hand,
// `ofbParticleBenchmark [--steps N] [--seeds N] [--part 1|2|3] [--rounds N] [--no-peer]
// [--threads 1|2]` (--no-peer: ours alone, for profiling; --threads: parts 2 and 3 with
// that number of threads only).
#include "vtkOFBMemoryFloor.h"
#include "vtkOFBReadMesh.h"
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRungeKutta4.h"
#include "vtkSMPTools.h"
#include "vtkStreamTracer.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
void SetRotationField(vtkPolyData* mesh, const double w[3], const double c[3])
{
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  field->SetNumberOfComponents(3);
  field->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3], r[3], v[3];
    mesh->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      r[k] = x[k] - c[k];
    }
    vtkMath::Cross(w, r, v);
    field->SetTuple(i, v);
  }
  mesh->GetPointData()->SetVectors(field);
}

double CircleError(const double a[3], const double b[3])
{
  return std::hypot(std::hypot(b[0], b[1]) - std::hypot(a[0], a[1]), b[2] - a[2]);
}

// 1. One revolution on the sphere.
void Accuracy(int steps, int numSeeds)
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 256);
  const double z[3] = { 0, 0, 1 }, o[3] = { 0, 0, 0 };
  SetRotationField(sphere, z, o);
  vtkNew<vtkPoints> seedPoints;
  seedPoints->SetDataTypeToDouble();
  for (int i = 0; i < numSeeds; ++i)
  {
    const double lat = vtkMath::RadiansFromDegrees(-60.0 + 120.0 * (i + 0.5) / numSeeds);
    const double lon = 2.0 * vtkMath::Pi() * i / numSeeds;
    seedPoints->InsertNextPoint(
      std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  }
  vtkNew<vtkPolyData> seeds;
  seeds->SetPoints(seedPoints);

  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(sphere);
  advector->SetSeeds(seeds);
  advector->SetIntegratorToRK4();
  advector->NormalizeVectorsOff(); // every particle revolves in `steps` steps
  advector->Update();
  const double cell = advector->GetCellSize();
  const double maxSpeed = sphere->GetPointData()->GetVectors()->GetMaxNorm();
  advector->SetStepSize(2.0 * vtkMath::Pi() * maxSpeed / (steps * cell));
  advector->Update();
  vtkNew<vtkPoints> start;
  start->SetDataTypeToDouble();
  start->DeepCopy(advector->GetParticles()->GetPoints());
  advector->SetStepsPerUpdate(steps);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  advector->Step();
  timer->StopTimer();
  const double oursTime = timer->GetElapsedTime();
  double oursMax = 0.0, oursMean = 0.0;
  for (vtkIdType i = 0; i < start->GetNumberOfPoints(); ++i)
  {
    const double e = CircleError(start->GetPoint(i), advector->GetParticles()->GetPoint(i));
    oursMax = std::max(oursMax, e);
    oursMean += e / start->GetNumberOfPoints();
  }

  // vtkStreamTracer: one run per seed (its propagation length is one revolution).
  double peerMax = 0.0, peerMean = 0.0, peerTime = 0.0;
  vtkIdType peerSteps = 0;
  for (vtkIdType i = 0; i < start->GetNumberOfPoints(); ++i)
  {
    double a[3];
    start->GetPoint(i, a);
    const double rho = std::hypot(a[0], a[1]);
    vtkNew<vtkPolyData> one;
    vtkNew<vtkPoints> p;
    p->InsertNextPoint(a);
    one->SetPoints(p);
    vtkNew<vtkStreamTracer> tracer;
    tracer->SetInputData(sphere);
    tracer->SetSourceData(one);
    tracer->SurfaceStreamlinesOn();
    tracer->SetIntegratorTypeToRungeKutta4();
    tracer->SetIntegrationDirectionToForward();
    tracer->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
    tracer->SetInitialIntegrationStep(2.0 * vtkMath::Pi() * rho / steps);
    tracer->SetMaximumPropagation(2.0 * vtkMath::Pi() * rho);
    tracer->SetMaximumNumberOfSteps(10 * steps);
    tracer->SetTerminalSpeed(1e-12);
    timer->StartTimer();
    tracer->Update();
    timer->StopTimer();
    peerTime += timer->GetElapsedTime();
    vtkPolyData* lines = tracer->GetOutput();
    const vtkIdType n = lines->GetNumberOfPoints();
    peerSteps += std::max<vtkIdType>(0, n - 1);
    const double e = n > 0 ? CircleError(a, lines->GetPoint(n - 1)) : 1e9;
    peerMax = std::max(peerMax, e);
    peerMean += e / start->GetNumberOfPoints();
  }
  const double oursSteps = static_cast<double>(steps) * start->GetNumberOfPoints();
  std::cout << std::setprecision(4) << "1. Unit sphere (" << sphere->GetNumberOfPolys()
            << " triangles), w x p, " << start->GetNumberOfPoints()
            << " seeds, RK4, one revolution in " << steps << " steps:\n"
            << "   vtkOFBParticleAdvector: circle error max " << oursMax / cell << " mean "
            << oursMean / cell << " cells; " << oursSteps / oursTime / 1e6
            << " M particle-steps/s\n"
            << "   vtkStreamTracer (SurfaceStreamlines): circle error max " << peerMax / cell
            << " mean " << peerMean / cell << " cells; " << peerSteps / peerTime / 1e6
            << " M particle-steps/s\n"
            << "   speed ratio " << (oursSteps / oursTime) / (peerSteps / peerTime) << "x\n";
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

// The load average of the machine (other work running beside the benchmark).
std::string Load()
{
  std::ifstream file("/proc/loadavg");
  std::string one, five;
  file >> one >> five;
  return one.empty() ? std::string("unknown") : one + " (1 min), " + five + " (5 min)";
}

struct SpeedResult
{
  double Ours = 0.0; // median M steps/s
  double Peer = 0.0;
};

// 2. RK4 steps on the horse, both tracers from the same seeds.
SpeedResult Speed(vtkPolyData* horse,
  int numSeeds,
  int steps,
  int threads,
  int rounds,
  bool peerToo)
{
  vtkSMPTools::Initialize(threads);
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(horse);
  advector->SetNumberOfParticles(numSeeds);
  advector->SetIntegratorToRK4();
  advector->Update(); // seeds at step 0
  vtkNew<vtkPolyData> seeds;
  seeds->DeepCopy(advector->GetParticles());
  advector->SetStepsPerUpdate(steps);

  vtkNew<vtkStreamTracer> tracer;
  tracer->SetInputData(horse);
  tracer->SetSourceData(seeds);
  tracer->SurfaceStreamlinesOn();
  tracer->SetIntegratorTypeToRungeKutta4();
  tracer->SetIntegrationDirectionToForward();
  tracer->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
  tracer->SetInitialIntegrationStep(advector->GetStepSize() * advector->GetCellSize());
  tracer->SetMaximumNumberOfSteps(steps);
  tracer->SetMaximumPropagation(1e30);
  tracer->SetTerminalSpeed(1e-12);
  // Rounds of each, taken in turns (the machine may be shared): medians. The
  // process's processor time is taken too: with one thread, the ratio of steps per
  // processor second does not count the time the process waited for a core.
  vtkNew<vtkTimerLog> timer;
  std::vector<double> ours, peer, ratio, cpuRatio;
  double peerSteps = 0.0;
  for (int round = 0; round < rounds; ++round)
  {
    std::clock_t cpu = std::clock();
    timer->StartTimer();
    advector->Step();
    timer->StopTimer();
    const double oursCPU = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    ours.push_back(static_cast<double>(numSeeds) * steps / timer->GetElapsedTime() / 1e6);
    if (!peerToo)
    {
      continue;
    }
    tracer->Modified();
    cpu = std::clock();
    timer->StartTimer();
    tracer->Update();
    timer->StopTimer();
    const double peerCPU = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    vtkPolyData* lines = tracer->GetOutput();
    peerSteps = static_cast<double>(lines->GetNumberOfPoints() - lines->GetNumberOfLines());
    peer.push_back(peerSteps / timer->GetElapsedTime() / 1e6);
    ratio.push_back(ours.back() / peer.back());
    if (oursCPU > 0.0 && peerCPU > 0.0)
    {
      cpuRatio.push_back((static_cast<double>(numSeeds) * steps / oursCPU) / (peerSteps / peerCPU));
    }
  }
  SpeedResult result;
  result.Ours = Median(ours);
  result.Peer = Median(peer);
  std::cout << "   " << threads << " thread(s): vtkOFBParticleAdvector " << result.Ours
            << " M steps/s, vtkStreamTracer " << result.Peer << " M steps/s ("
            << static_cast<vtkIdType>(peerSteps) << " steps), ratio " << Median(ratio)
            << "x (median of " << rounds << " rounds; range "
            << (ratio.empty() ? 0.0 : *std::min_element(ratio.begin(), ratio.end())) << "-"
            << (ratio.empty() ? 0.0 : *std::max_element(ratio.begin(), ratio.end())) << ")\n";
  if (!cpuRatio.empty())
  {
    std::cout << "     per processor second (process time): ratio " << Median(cpuRatio)
              << "x (range " << *std::min_element(cpuRatio.begin(), cpuRatio.end()) << "-"
              << *std::max_element(cpuRatio.begin(), cpuRatio.end()) << ")\n";
  }
  return result;
}

struct PaintResult
{
  double Step = 0.0; // median ms
  double Advection = 0.0;
  double Painting = 0.0;
  double Outputs = 0.0;
};

// 3. One painting step of many particles, split as the advector times it.
PaintResult Paint(vtkPolyData* horse, int threads, int rounds)
{
  vtkSMPTools::Initialize(threads);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(horse);
  sampler->SetResolution(2048);
  sampler->Update();
  vtkNew<vtkOFB> ofb;
  ofb->ShallowCopy(sampler->GetOutput());
  vtkNew<vtkOFBParticleAdvector> advector;
  advector->SetInputData(horse);
  advector->SetOFB(ofb);
  advector->SetNumberOfParticles(10000);
  advector->SetFootprintRadius(2.5);
  advector->Step(); // warm-up: seeds, first footprints
  vtkNew<vtkTimerLog> timer;
  std::vector<double> step, advection, painting, outputs, rest;
  for (int round = 0; round < rounds; ++round)
  {
    timer->StartTimer();
    advector->Step();
    timer->StopTimer();
    step.push_back(1e3 * timer->GetElapsedTime());
    advection.push_back(advector->GetLastAdvectionTime());
    painting.push_back(advector->GetLastPaintingTime());
    outputs.push_back(advector->GetLastOutputTime());
    rest.push_back(step.back() - advection.back() - painting.back() - outputs.back());
  }
  // The floor: touching as many random cache lines as the footprints do.
  const vtkofb_bench::FootprintLines lines = vtkofb_bench::CountFootprintLines(
    ofb, advector->GetParticles()->GetPoints(), 2.5 * ofb->GetCellSize());
  const double floor = 1e3 *
    vtkofb_bench::RandomLineFloor(
      static_cast<size_t>(lines.Lines * advector->GetParticles()->GetNumberOfPoints()),
      size_t(1024) * ofb->GetActualMemorySize(),
      rounds);
  PaintResult result;
  result.Step = Median(step);
  result.Advection = Median(advection);
  result.Painting = Median(painting);
  result.Outputs = Median(outputs);
  std::cout << "   " << threads << " thread(s): one step of 10,000 particles with footprints "
            << result.Step << " ms: advection " << result.Advection << ", painting "
            << result.Painting << ", outputs " << result.Outputs << ", the rest (pipeline) "
            << Median(rest) << " ms (medians of " << rounds << " steps), "
            << ofb->GetNumberOfSamples() << " samples\n"
            << "     footprints: " << lines.Rows << " rows with samples, " << lines.Hits
            << " samples painted and at least " << lines.Lines
            << " cache lines touched per particle; touching as many random cache lines alone "
            << floor << " ms (painting " << result.Painting / floor << "x that floor)\n";
  return result;
}
}

int main(int argc, char* argv[])
{
  int steps = 2000;
  int seeds = 1000;
  int part = 0; // all
  int rounds = 7;
  bool peer = true;
  int threads = 0; // 1 and 2
  std::string mesh = std::string(VTKOFB_DATA_DIR) + "/horse.ply";
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--steps") && i + 1 < argc)
    {
      steps = std::max(10, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc)
    {
      seeds = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--part") && i + 1 < argc)
    {
      part = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc)
    {
      rounds = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--no-peer"))
    {
      peer = false;
    }
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
    {
      threads = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc)
    {
      mesh = argv[++i];
    }
    else
    {
      std::cout << "ofbParticleBenchmark [--steps N (per revolution, 2000)] [--seeds N (1000)] "
                   "[--mesh FILE (horse)] [--part 1|2|3 (all)] [--rounds N (7)] [--no-peer] "
                   "[--threads N (1 and 2)]\n";
      return argv[i] == std::string("--help") ? 0 : 1;
    }
  }
  if (part == 0 || part == 1)
  {
    Accuracy(steps, 40);
  }
  vtkSmartPointer<vtkPolyData> horse = vtkofbtest::ReadMeshFile(mesh);
  if (!horse)
  {
    std::cerr << "Cannot read " << mesh << "\n";
    return 1;
  }
  double c[3];
  horse->GetCenter(c);
  const double w[3] = { 0.3, 1.0, 0.2 };
  SetRotationField(horse, w, c);
  if (part == 0 || part == 2)
  {
    std::cout << "2. " << mesh << " (" << horse->GetNumberOfPolys() << " triangles), " << seeds
              << " seeds, RK4, 200 steps of 1 cell (1/1024 of the box); load " << Load() << ":\n";
    if (threads > 0)
    {
      Speed(horse, seeds, 200, threads, rounds, peer);
    }
    else
    {
      const SpeedResult one = Speed(horse, seeds, 200, 1, rounds, peer);
      const SpeedResult two = Speed(horse, seeds, 200, 2, rounds, peer);
      std::cout << "   scaling 1 -> 2 threads: vtkOFBParticleAdvector " << two.Ours / one.Ours
                << "x, vtkStreamTracer " << (one.Peer > 0.0 ? two.Peer / one.Peer : 0.0) << "x\n";
    }
  }
  if (part == 0 || part == 3)
  {
    std::cout << "3. Painting on " << mesh << " at 2048, footprint radius 2.5 cells; load "
              << Load() << ":\n";
    if (threads > 0)
    {
      Paint(horse, threads, rounds);
    }
    else
    {
      const PaintResult one = Paint(horse, 1, rounds);
      const PaintResult two = Paint(horse, 2, rounds);
      std::cout << "   scaling 1 -> 2 threads: step " << one.Step / two.Step << "x, advection "
                << one.Advection / two.Advection << "x, painting " << one.Painting / two.Painting
                << "x, outputs " << one.Outputs / two.Outputs << "x\n";
    }
  }
  vtkSMPTools::Initialize(0);
  return 0;
}
