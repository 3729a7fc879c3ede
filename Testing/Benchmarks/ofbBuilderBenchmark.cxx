// OpenGL against CPU construction of vtkOFBBuilder, measured in the same run.
//
//   ofbBuilderBenchmark [--repetitions N] [--resolutions 512,1024,2048] [--egl [N]] [--phases]
//                       [mesh ...]
//
// Prints, per mesh and resolution, the median build time of each backend, the
// samples per second and the ratio OpenGL / CPU. Run it under xvfb-run on a
// machine without a GPU (Mesa llvmpipe), or on a GPU machine with a display. With
// --egl it takes its OpenGL context from EGL device N (default 0) and needs no X
// display: for a Linux machine with a GPU driver and no X server. --phases adds, after
// the timed builds, one OpenGL build that times its phases (each ended by a glFinish).
#include "ofbBenchmarkOptions.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBuilder.h"
#include "vtkOFBReadMesh.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"

#ifdef VTKOFB_BENCHMARK_HAVE_EGL
#include "ofbEGLWindow.h"
#endif

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
/// Median build time (ms) of `reps` builds after one warm-up; -1 if the backend did not run.
double Time(vtkOFBBuilder* builder, int backend, int reps, vtkIdType& samples)
{
  builder->SetBackend(backend);
  std::vector<double> times;
  for (int r = 0; r <= reps; ++r)
  {
    builder->Modified();
    builder->Update();
    if (builder->GetLastBackend() != backend)
    {
      return -1.0;
    }
    if (r > 0)
    {
      times.push_back(builder->GetLastBuildTime());
    }
  }
  samples = builder->GetOutput()->GetNumberOfSamples();
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}
}

int main(int argc, char* argv[])
{
  int reps = 5;
  std::vector<int> resolutions = { 512, 1024, 2048 };
  std::vector<std::string> meshes;
  int eglDevice = -1;
  bool phases = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--phases")
    {
      phases = true;
      continue;
    }
    if (arg == "--egl")
    {
      eglDevice = 0;
      if (i + 1 < argc && std::isdigit(static_cast<unsigned char>(argv[i + 1][0])))
      {
        eglDevice = std::atoi(argv[++i]);
      }
      continue;
    }
    if (arg == "--repetitions" && i + 1 < argc)
    {
      reps = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--resolutions" && i + 1 < argc)
    {
      resolutions = ofbbench::ParseIntList(argv[++i]);
    }
    else
    {
      meshes.push_back(arg);
    }
  }
  if (meshes.empty())
  {
    meshes = { VTKOFB_DATA_DIR "/stanford-bunny.obj", VTKOFB_DATA_DIR "/horse.ply" };
  }

  vtkSmartPointer<vtkRenderWindow> window;
  if (eglDevice >= 0)
  {
#ifdef VTKOFB_BENCHMARK_HAVE_EGL
    std::string why;
    window = ofbbench::NewEGLRenderWindow(eglDevice, why);
    if (!window)
    {
      std::printf("--egl: %s\n", why.c_str());
      return 1;
    }
#else
    std::printf("--egl: this build has no EGL (libegl-dev was not found)\n");
    return 1;
#endif
  }
  else
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetSize(8, 8);
  }
  if (!vtkOFBBuilder::IsSupported(window))
  {
    std::printf("This OpenGL context cannot run the OpenGL backend (needs 4.3).\n");
    return 1;
  }
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  gl->MakeCurrent();
  std::printf("OpenGL renderer: %s (%s)\n",
    reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
    reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  std::printf("CPU: vtkSMPTools %s backend, %d threads\n",
    vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("Median of %d builds after a warm-up.\n\n", reps);
  std::printf("%-20s %6s %11s %10s %10s %10s %10s %9s\n",
    "mesh",
    "res",
    "samples",
    "CPU ms",
    "CPU MS/s",
    "GL ms",
    "GL MS/s",
    "GL/CPU");
  for (const std::string& path : meshes)
  {
    vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::ReadMeshFile(path);
    if (!mesh || mesh->GetNumberOfPolys() == 0)
    {
      std::printf("cannot read %s\n", path.c_str());
      return 1;
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    for (int resolution : resolutions)
    {
      vtkNew<vtkOFBBuilder> builder;
      builder->SetInputData(mesh);
      builder->SetResolution(resolution);
      // The geometry and the default arrays only, as the peer stores: not the cell arrays
      // that a mesh reader adds (the OBJ reader's GroupIds).
      builder->PassCellArraysOff();
      builder->SetRenderWindow(window);
      vtkIdType cpuSamples = 0, glSamples = 0;
      const double cpu = Time(builder, vtkOFBBuilder::BACKEND_CPU, reps, cpuSamples);
      const double ogl = Time(builder, vtkOFBBuilder::BACKEND_OPENGL, reps, glSamples);
      if (ogl < 0.0)
      {
        std::printf(
          "%-20s %6d: the OpenGL backend fell back to the CPU\n", name.c_str(), resolution);
        continue;
      }
      std::printf("%-20s %6d %11lld %10.1f %10.1f %10.1f %10.1f %9.2f%s\n",
        name.c_str(),
        resolution,
        static_cast<long long>(cpuSamples),
        cpu,
        cpuSamples / cpu / 1000.0,
        ogl,
        glSamples / ogl / 1000.0,
        ogl / cpu,
        cpuSamples == glSamples ? "" : "  (counts differ)");
      if (phases)
      {
        builder->MeasureOpenGLPhasesOn();
        builder->Modified();
        builder->Update();
        std::printf("    OpenGL phases (ms): %s\n", builder->GetLastOpenGLPhaseTimes());
        builder->MeasureOpenGLPhasesOff();
      }
    }
  }
  return 0;
}
