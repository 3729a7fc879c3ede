// ofbLICBenchmark: throughput of vtkOFBLIC (samples per second) on a mesh's OFB, with the
// OFB's own construction (vtkOFBSampler) measured in the same run as the peer.
// Not a test: run it by hand:
//   ofbLICBenchmark [--mesh FILE] [--resolution N] [--threads N] [--steps N] [--rounds N]
// Defaults: the Stanford bunny, 1024 cells, 2 threads, 10 steps each way (2 x 10 steps
// per sample), 3 rounds. Each round times: the sampler; the first LIC (field, noise and
// one convolution, EnhancedLIC off); the same with EnhancedLIC on (two convolutions); a
// re-convolution for animation (a new AnimationPhase). Medians over the rounds are
// printed as M samples/s and as ratios to the sampler's time. On a shared machine the
// numbers are noisy: compare the ratios, and repeat.
#include "vtkOFBReadMesh.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{
double Seconds(const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CPU time of the process (all threads), in seconds: less disturbed by other load.
double CPUSeconds()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// A rotation about a tilted axis through the centre of the mesh, as point vectors.
void AddField(vtkPolyData* mesh)
{
  double b[6];
  mesh->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double a[3] = { 0.36, 0.89, 0.27 };
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    const double* x = mesh->GetPoint(p);
    const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
    flow->InsertNextTuple3(
      a[1] * r[2] - a[2] * r[1], a[2] * r[0] - a[0] * r[2], a[0] * r[1] - a[1] * r[0]);
  }
  mesh->GetPointData()->SetVectors(flow);
}
}

int main(int argc, char* argv[])
{
  std::string mesh = std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj";
  int resolution = 1024, threads = 2, steps = 10, rounds = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--mesh" && hasValue)
      mesh = argv[++i];
    else if (arg == "--resolution" && hasValue)
      resolution = std::atoi(argv[++i]);
    else if (arg == "--threads" && hasValue)
      threads = std::atoi(argv[++i]);
    else if (arg == "--steps" && hasValue)
      steps = std::atoi(argv[++i]);
    else if (arg == "--rounds" && hasValue)
      rounds = std::max(1, std::atoi(argv[++i]));
    else
    {
      std::cerr << "usage: " << argv[0]
                << " [--mesh FILE] [--resolution N] [--threads N] [--steps N] [--rounds N]\n";
      return arg == "--help" ? 0 : 1;
    }
  }
  vtkSmartPointer<vtkPolyData> surface = vtkofbtest::ReadMeshFile(mesh);
  if (!surface)
  {
    std::cerr << "Cannot read " << mesh << "\n";
    return 1;
  }
  AddField(surface);
  vtkSMPTools::Initialize(threads);

  std::vector<double> build, first, enhanced, animate;
  std::vector<double> buildCPU, firstCPU, enhancedCPU, animateCPU;
  double c0 = 0.0;
  vtkIdType n = 0;
  for (int r = 0; r < rounds; ++r)
  {
    vtkNew<vtkOFBSampler> sampler;
    sampler->SetInputData(surface);
    sampler->SetResolution(resolution);
    auto t0 = std::chrono::steady_clock::now();
    c0 = CPUSeconds();
    sampler->Update();
    build.push_back(Seconds(t0));
    buildCPU.push_back(CPUSeconds() - c0);
    n = sampler->GetOutput()->GetNumberOfSamples();

    vtkNew<vtkOFBLIC> lic;
    lic->SetInputData(sampler->GetOutput());
    lic->SetNumberOfSteps(steps);
    lic->EnhancedLICOff();
    lic->AnimateOn();
    t0 = std::chrono::steady_clock::now();
    c0 = CPUSeconds();
    lic->Update();
    first.push_back(Seconds(t0));
    firstCPU.push_back(CPUSeconds() - c0);
    lic->SetAnimationPhase(0.1);
    t0 = std::chrono::steady_clock::now();
    c0 = CPUSeconds();
    lic->Update();
    animate.push_back(Seconds(t0));
    animateCPU.push_back(CPUSeconds() - c0);
    lic->EnhancedLICOn();
    t0 = std::chrono::steady_clock::now();
    c0 = CPUSeconds();
    lic->Update();
    enhanced.push_back(Seconds(t0));
    enhancedCPU.push_back(CPUSeconds() - c0);
  }
  const double b = Median(build);
  std::cout << mesh << " at " << resolution << ": " << n << " samples, " << threads
            << " threads, 2 x " << steps << " steps, median of " << rounds << " rounds\n";
  const double bc = Median(buildCPU);
  auto report = [&](const char* what, const std::vector<double>& t, const std::vector<double>& c)
  {
    const double m = Median(t);
    const double mc = Median(c);
    std::cout << "  " << what << ": " << 1000.0 * m << " ms, " << n / m / 1e6 << " M samples/s, "
              << m / b << " x the OFB build; CPU " << 1000.0 * mc << " ms, " << mc / bc
              << " x the OFB build's CPU\n";
  };
  std::cout << "  OFB build (peer): " << 1000.0 * b << " ms, " << n / b / 1e6
            << " M samples/s; CPU " << 1000.0 * bc << " ms\n";
  report("first LIC", first, firstCPU);
  report("animation re-convolution", animate, animateCPU);
  report("enhanced LIC (two passes)", enhanced, enhancedCPU);
  return 0;
}
