// ofbMapperBenchmark: frame time of vtkOFBPolyDataMapper (Nearest, InverseDistance,
// Mipmapped) against VTK's own poly data mapper with vertex colours, on the same mesh
// (the Stanford bunny by default) in the same window, printed as ratios.
// Not a test: run it by hand, under xvfb-run on a headless machine:
//   xvfb-run -a -s "-screen 0 1280x1024x24" ofbMapperBenchmark [options]
// Options: --mesh FILE (.obj/.ply), --resolution N (OFB cells, default 1024),
// --frames N (timed frames per mapper and round, default 30), --rounds N (default 3),
// --warmup N (untimed frames before each timing, default 3), --modes LIST (comma-separated
// subset of nearest,idw,mipmapped; default all), --width W --height H (1280x1024),
// --images PREFIX (write PREFIX<k>-<mapper>.ppm of the first view of every mapper).
// Fairness: one window, renderer, actor, property and headlight for every mapper; each
// timing starts from the same camera and turns it once around the surface; the mappers
// take turns within every round (so that a change of machine load hits all of them), and
// the medians over the rounds are compared. The frame time includes the clear and the
// copy of the frame to the X server, which are the same for every mapper. Besides the
// wall-clock times (the goal's measure) it prints the CPU time of the process (llvmpipe's
// rendering threads included), which other load on a shared machine disturbs less.
#include "vtkOFBReadMesh.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{
// The same colour for a vertex and for a sample: bands of the position.
void ColorAt(const double x[3], const double bounds[6], unsigned char rgba[4])
{
  double t[3];
  for (int i = 0; i < 3; ++i)
  {
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    t[i] = extent > 0.0 ? (x[i] - bounds[2 * i]) / extent : 0.0;
  }
  rgba[0] = static_cast<unsigned char>(127.5 + 127.5 * std::sin(12.0 * t[0]));
  rgba[1] = static_cast<unsigned char>(127.5 + 127.5 * std::sin(12.0 * t[1] + 1.0));
  rgba[2] = static_cast<unsigned char>(127.5 + 127.5 * std::sin(12.0 * t[2] + 2.0));
  rgba[3] = 255;
}

/// The mesh with point normals (both mappers shade with the same normals).
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::ReadMeshFile(path);
  if (!mesh)
  {
    return nullptr;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

struct FrameTime
{
  double Wall; // ms per frame
  double CPU;  // ms of CPU time of this process (all threads) per frame
};

double CPUMilliseconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return 1e3 * (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
    1e-3 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Milliseconds per frame of `frames` renders while the camera turns once around the
// surface, after `warmup` untimed renders. Every call starts from the same camera, so
// every mapper draws the same views; Render() returns after glFinish
// (WaitForCompletion) so that each frame's work is counted in full.
FrameTime TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, vtkCamera* start,
  int frames, int warmup)
{
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->DeepCopy(start);
  for (int i = 0; i < warmup; ++i)
  {
    window->Render();
  }
  if (gl)
  {
    gl->WaitForCompletion();
  }
  const auto begin = std::chrono::steady_clock::now();
  const double cpuBegin = CPUMilliseconds();
  for (int i = 0; i < frames; ++i)
  {
    camera->Azimuth(360.0 / frames);
    window->Render();
    if (gl)
    {
      gl->WaitForCompletion();
    }
  }
  const auto stop = std::chrono::steady_clock::now();
  const double cpuStop = CPUMilliseconds();
  camera->DeepCopy(start);
  return { std::chrono::duration<double, std::milli>(stop - begin).count() / frames,
    (cpuStop - cpuBegin) / frames };
}

// Binary PPM of an RGB image (VTK's rows run bottom to top).
void WritePPM(const std::string& path, vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << dims[0] << " " << dims[1] << "\n255\n";
  for (int y = dims[1] - 1; y >= 0; --y)
  {
    out.write(static_cast<const char*>(image->GetScalarPointer(0, y, 0)), 3 * dims[0]);
  }
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}

int main(int argc, char* argv[])
{
  std::string mesh = std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj";
  int resolution = 1024;
  int frames = 30;
  int rounds = 3;
  int warmup = 3;
  int width = 1280;
  int height = 1024;
  std::string images;
  std::vector<int> modes = { vtkOFBPolyDataMapper::Nearest,
    vtkOFBPolyDataMapper::InverseDistance, vtkOFBPolyDataMapper::Mipmapped };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--mesh" && hasValue)
    {
      mesh = argv[++i];
    }
    else if (arg == "--resolution" && hasValue)
    {
      resolution = std::atoi(argv[++i]);
    }
    else if (arg == "--frames" && hasValue)
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--rounds" && hasValue)
    {
      rounds = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--warmup" && hasValue)
    {
      warmup = std::max(0, std::atoi(argv[++i]));
    }
    else if (arg == "--width" && hasValue)
    {
      width = std::atoi(argv[++i]);
    }
    else if (arg == "--height" && hasValue)
    {
      height = std::atoi(argv[++i]);
    }
    else if (arg == "--images" && hasValue)
    {
      images = argv[++i];
    }
    else if (arg == "--modes" && hasValue)
    {
      modes.clear();
      std::string list = argv[++i];
      size_t begin = 0;
      while (begin <= list.size())
      {
        const size_t comma = std::min(list.find(',', begin), list.size());
        const std::string name = list.substr(begin, comma - begin);
        if (name == "nearest")
        {
          modes.push_back(vtkOFBPolyDataMapper::Nearest);
        }
        else if (name == "idw")
        {
          modes.push_back(vtkOFBPolyDataMapper::InverseDistance);
        }
        else if (name == "mipmapped")
        {
          modes.push_back(vtkOFBPolyDataMapper::Mipmapped);
        }
        else if (!name.empty())
        {
          std::cerr << "Unknown mode " << name << "\n";
          return 1;
        }
        begin = comma + 1;
      }
    }
    else
    {
      std::cout << "usage: ofbMapperBenchmark [--mesh FILE] [--resolution N] [--frames N] "
                   "[--rounds N] [--warmup N] [--modes nearest,idw,mipmapped] [--width W] "
                   "[--height H] [--images PREFIX]\n";
      return arg == "--help" ? 0 : 1;
    }
  }

  vtkSmartPointer<vtkPolyData> surface = ReadMesh(mesh);
  if (!surface)
  {
    std::cerr << "Cannot read a surface from " << mesh << "\n";
    return 1;
  }
  double bounds[6];
  surface->GetBounds(bounds);

  // Vertex colours for the peer.
  vtkSmartPointer<vtkPolyData> colored = vtkSmartPointer<vtkPolyData>::New();
  colored->ShallowCopy(surface);
  vtkNew<vtkUnsignedCharArray> vertexColors;
  vertexColors->SetName("Colors");
  vertexColors->SetNumberOfComponents(4);
  vertexColors->SetNumberOfTuples(surface->GetNumberOfPoints());
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    unsigned char rgba[4];
    ColorAt(surface->GetPoint(i), bounds, rgba);
    vertexColors->SetTypedTuple(i, rgba);
  }
  colored->GetPointData()->SetScalars(vertexColors);

  // The OFB, with the same colours per sample.
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetResolution(resolution);
  sampler->Update();
  vtkOFB* ofb = sampler->GetOutput();
  if (ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "The OFB build failed.\n";
    return 1;
  }
  auto* sampleColors =
    vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    unsigned char rgba[4];
    ColorAt(x, bounds, rgba);
    sampleColors->SetTypedTuple(i, rgba);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.2, 0.25);
  window->AddRenderer(renderer);
  vtkNew<vtkActor> actor;
  renderer->AddActor(actor);

  // The mappers: the peer first, then one OFB mapper per mode, all kept alive so that
  // every round only switches the actor's mapper.
  vtkNew<vtkPolyDataMapper> peer;
  peer->SetInputData(colored);
  std::vector<vtkSmartPointer<vtkMapper>> mappers(1, peer.Get());
  std::vector<std::string> names(1, "vtkPolyDataMapper, vertex colours");
  for (int mode : modes)
  {
    vtkNew<vtkOFBPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->SetOFB(ofb);
    mapper->SetLookupMode(mode);
    mappers.emplace_back(mapper.Get());
    names.push_back(
      std::string("vtkOFBPolyDataMapper, ") + vtkOFBPolyDataMapper::GetLookupModeAsString(mode));
  }

  actor->SetMapper(peer);
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkCamera> start;
  start->DeepCopy(renderer->GetActiveCamera());
  for (size_t m = 1; m < mappers.size(); ++m)
  {
    actor->SetMapper(mappers[m]);
    window->Render();
    if (!vtkOFBPolyDataMapper::SafeDownCast(mappers[m])->GetLastRenderUsedOFB())
    {
      std::cerr << "vtkOFBPolyDataMapper could not use the OFB on this context.\n";
      return 1;
    }
  }
  const std::string capabilities =
    window->ReportCapabilities() ? window->ReportCapabilities() : "";

  std::cout << "ofbMapperBenchmark: " << mesh << "\n"
            << "  triangles " << surface->GetNumberOfPolys() << ", OFB resolution "
            << resolution << ", samples " << ofb->GetNumberOfSamples() << ", depth complexity "
            << ofb->GetDepthComplexity() << ", window " << width << "x" << height << ", "
            << frames << " frames per mapper and round, " << rounds << " rounds\n";
  const std::string::size_type at = capabilities.find("OpenGL renderer string:");
  if (at != std::string::npos)
  {
    std::cout << "  " << capabilities.substr(at, capabilities.find('\n', at) - at) << "\n";
  }
  std::cout << std::fixed << std::setprecision(2);

  std::vector<std::vector<double>> wall(mappers.size());
  std::vector<std::vector<double>> cpu(mappers.size());
  std::vector<std::vector<double>> roundRatios(mappers.size());
  std::cout << "  per round, wall ms/frame (CPU ms/frame of this process):\n";
  for (int r = 0; r < rounds; ++r)
  {
    std::cout << "  round " << r + 1 << ":";
    for (size_t m = 0; m < mappers.size(); ++m)
    {
      actor->SetMapper(mappers[m]);
      const FrameTime t = TimeFrames(window, renderer, start, frames, warmup);
      wall[m].push_back(t.Wall);
      cpu[m].push_back(t.CPU);
      roundRatios[m].push_back(t.Wall / wall[0].back());
      std::cout << " " << t.Wall << " (" << t.CPU << ")";
    }
    std::cout << std::endl;
  }

  // The goal compares wall-clock frame times; CPU time is less sensitive to other load.
  const double peerMs = Median(wall[0]);
  const double peerCPU = Median(cpu[0]);
  std::cout << "  medians over the rounds: wall ms/frame, ratio to the peer; CPU ms/frame, "
               "ratio; median of the per-round wall ratios\n";
  std::cout << "  " << std::left << std::setw(40) << names[0] << std::right << std::setw(8)
            << peerMs << "          " << std::setw(8) << peerCPU << "\n";
  double nearestRatio = -1.0;
  for (size_t m = 1; m < mappers.size(); ++m)
  {
    const double ms = Median(wall[m]);
    const double ratio = ms / peerMs;
    if (modes[m - 1] == vtkOFBPolyDataMapper::Nearest)
    {
      nearestRatio = ratio;
    }
    std::cout << "  " << std::left << std::setw(40) << names[m] << std::right << std::setw(8)
              << ms << " " << std::setw(6) << ratio << "x " << std::setw(8) << Median(cpu[m])
              << " " << std::setw(6) << Median(cpu[m]) / peerCPU << "x " << std::setw(6)
              << Median(roundRatios[m]) << "x\n";
  }
  if (!images.empty())
  {
    const char* files[4] = { "peer", "nearest", "idw", "mipmapped" };
    for (size_t m = 0; m < mappers.size(); ++m)
    {
      actor->SetMapper(mappers[m]);
      renderer->GetActiveCamera()->DeepCopy(start);
      window->Render();
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(window);
      grab->ReadFrontBufferOff();
      grab->ShouldRerenderOff();
      grab->SetInputBufferTypeToRGB();
      grab->Update();
      WritePPM(images + std::to_string(m) + "-" + files[m == 0 ? 0 : 1 + modes[m - 1]] + ".ppm",
        grab->GetOutput());
    }
  }
  for (size_t m = 1; m < mappers.size(); ++m)
  {
    mappers[m]->ReleaseGraphicsResources(window);
  }
  if (nearestRatio >= 0.0)
  {
    std::cout << "  goal: Nearest at most 2x the vertex-colour mapper: "
              << (nearestRatio <= 2.0 ? "met" : "NOT met") << " (" << nearestRatio << "x)\n";
  }
  return 0;
}
