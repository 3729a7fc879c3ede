// Attribute-only re-sampling of vtkOFBSampler (StructureReuse) against a full build of
// the same input, measured in the same run.
//
//   ofbResampleBenchmark [--repetitions N] [--resolutions 512,1024] [mesh ...]
//
// Each mesh gets a point vector field "Velocity" and a point scalar "Pressure" that
// change at every repetition (a time series on a fixed geometry). Prints, per mesh and
// resolution, the median time of a full build (StructureReuse off) and of a
// re-sampling (StructureReuse always, the arrays changed in place), and the ratio
// full build / re-sampling. The floor beside it: the same bytes moved by memcpy on one
// thread in the same run. A re-sampling of this field reads 24 bytes a sample (the
// sample's triangle and two barycentrics, 12 bytes; its normal, 12, to project the
// vectors) and writes 24 (colour 4, vector 12, pressure 8); the floor copies 24 bytes a
// sample from one buffer to another.
#include "ofbBenchmarkOptions.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBReadMesh.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <time.h>
#include <vector>

namespace
{
/// Fill the mesh's "Velocity" and "Pressure" for time t (marked modified).
void SetField(vtkPolyData* mesh, double t)
{
  auto* velocity = vtkFloatArray::SafeDownCast(mesh->GetPointData()->GetArray("Velocity"));
  auto* pressure = vtkDoubleArray::SafeDownCast(mesh->GetPointData()->GetArray("Pressure"));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    velocity->SetTuple3(i, std::sin(7 * x[1] + t), std::cos(5 * x[2] - t), x[0] * t);
    pressure->SetValue(i, std::cos(9 * x[0] + t));
  }
  velocity->Modified();
  pressure->Modified();
}

/// Processor time of the calling thread (ms).
double ThreadMilliseconds()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1000.0 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

/// Processor time of the whole process, all threads (ms).
double ProcessMilliseconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1000.0 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

/**
 * Median update time (ms) of `reps` updates after one warm-up, the field changed
 * before each, and the median processor time of the calling thread (ms) in `cpu`:
 * with vtkSMPTools' Sequential backend (VTK_SMP_BACKEND_IN_USE=Sequential) that is
 * all the work of an update, which a loaded machine does not inflate as it does
 * the wall-clock time. `process` gets the median processor time of all threads
 * over an update: with several threads, that time over the wall-clock time is the
 * number of threads that worked on average, and beside the Sequential thread time it
 * shows what the threads add.
 */
/// Median time (ms) of copying `bytes` bytes between two buffers on one thread.
double CopyFloor(size_t bytes, int reps)
{
  std::vector<char> from(bytes, 1), to(bytes, 0);
  std::vector<double> times;
  for (int r = 0; r <= reps; ++r)
  {
    from[static_cast<size_t>(r) % bytes] = static_cast<char>(r);
    const double start = ThreadMilliseconds();
    std::memcpy(to.data(), from.data(), bytes);
    const double used = ThreadMilliseconds() - start;
    if (to[static_cast<size_t>(r) % bytes] != static_cast<char>(r))
    {
      return -1.0;
    }
    if (r > 0)
    {
      times.push_back(used);
    }
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

double Time(vtkOFBSampler* sampler,
  vtkPolyData* mesh,
  int reps,
  bool expectResampled,
  double& cpu,
  double& process)
{
  std::vector<double> times, cpus, processes;
  for (int r = 0; r <= reps; ++r)
  {
    SetField(mesh, 0.1 * r);
    const double start = ThreadMilliseconds();
    const double processStart = ProcessMilliseconds();
    sampler->Update();
    const double used = ThreadMilliseconds() - start;
    const double processUsed = ProcessMilliseconds() - processStart;
    if (r > 0)
    {
      if (sampler->GetLastUpdateResampled() != expectResampled)
      {
        std::fprintf(stderr, "unexpected %s\n", expectResampled ? "full build" : "re-sampling");
        return -1.0;
      }
      times.push_back(sampler->GetLastBuildTime());
      cpus.push_back(used);
      processes.push_back(processUsed);
    }
  }
  std::sort(cpus.begin(), cpus.end());
  cpu = cpus[cpus.size() / 2];
  std::sort(processes.begin(), processes.end());
  process = processes[processes.size() / 2];
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}
}

int main(int argc, char* argv[])
{
  int reps = 5;
  std::vector<int> resolutions = { 512, 1024 };
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--repetitions" && i + 1 < argc)
    {
      reps = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--resolutions" && i + 1 < argc)
    {
      resolutions = ofbbench::ParseIntList(argv[++i]);
    }
    else if (arg == "--help")
    {
      std::printf("ofbResampleBenchmark [--repetitions N] [--resolutions 512,1024] [mesh ...]\n");
      return 0;
    }
    else
    {
      meshes.push_back(arg);
    }
  }
  if (meshes.empty())
  {
    for (const char* name : { "stanford-bunny.obj",
           "horse.ply",
           "spot.obj",
           "teapot.obj",
           "fandisk.obj",
           "rocker-arm.obj" })
    {
      meshes.push_back(std::string(VTKOFB_DATA_DIR) + "/" + name);
    }
  }
  std::printf(
    "threads: %d (%s)\n", vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend());
  std::printf("| mesh | cells | samples | full build ms | re-sampling ms | full / re-sampling | "
              "full build thread CPU ms | re-sampling thread CPU ms | full / re-sampling (CPU) "
              "| full build process CPU ms | re-sampling process CPU ms "
              "| copy floor ms | re-sampling GB/s | re-sampling / floor |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& path : meshes)
  {
    vtkSmartPointer<vtkPolyData> read = vtkofbtest::ReadMeshFile(path);
    if (!read)
    {
      std::fprintf(stderr, "cannot read %s\n", path.c_str());
      return 1;
    }
    vtkNew<vtkPolyData> mesh;
    mesh->CopyStructure(read);
    vtkNew<vtkFloatArray> velocity;
    velocity->SetName("Velocity");
    velocity->SetNumberOfComponents(3);
    velocity->SetNumberOfTuples(mesh->GetNumberOfPoints());
    vtkNew<vtkDoubleArray> pressure;
    pressure->SetName("Pressure");
    pressure->SetNumberOfTuples(mesh->GetNumberOfPoints());
    mesh->GetPointData()->SetVectors(velocity);
    mesh->GetPointData()->AddArray(pressure);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    for (const int resolution : resolutions)
    {
      vtkNew<vtkOFBSampler> full;
      full->SetStructureReuseToOff();
      full->SetResolution(resolution);
      full->SetInputData(mesh);
      double fullCpu = 0.0, resampleCpu = 0.0, fullProcess = 0.0, resampleProcess = 0.0;
      const double fullMs = Time(full, mesh, reps, false, fullCpu, fullProcess);
      const vtkIdType samples = full->GetOutput()->GetNumberOfSamples();
      full->ReleaseBuffers();
      full->SetInputData(nullptr);
      vtkNew<vtkOFBSampler> reuse;
      reuse->SetStructureReuseToAlways();
      reuse->SetResolution(resolution);
      reuse->SetInputData(mesh);
      const double resampleMs = Time(reuse, mesh, reps, true, resampleCpu, resampleProcess);
      if (fullMs < 0.0 || resampleMs < 0.0)
      {
        return 1;
      }
      const double floorMs = CopyFloor(24 * static_cast<size_t>(samples), reps);
      const double gbs = 48.0 * static_cast<double>(samples) / (1.0e6 * resampleCpu);
      std::printf(
        "| %s | %d | %lld | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | "
        "%.2f |\n",
        name.c_str(),
        resolution,
        static_cast<long long>(samples),
        fullMs,
        resampleMs,
        fullMs / resampleMs,
        fullCpu,
        resampleCpu,
        fullCpu / resampleCpu,
        fullProcess,
        resampleProcess,
        floorMs,
        gbs,
        resampleCpu / floorMs);
      std::fflush(stdout);
    }
  }
  return 0;
}
