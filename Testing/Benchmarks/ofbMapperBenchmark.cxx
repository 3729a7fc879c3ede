// ofbMapperBenchmark: frame time of vtkOFBPolyDataMapper (Nearest, InverseDistance,
// Mipmapped, NearestMipmapped, Smooth) against VTK's own poly data mapper with vertex colours, on
// the same mesh (the Stanford bunny by default) in the same window, printed as ratios. Not a test:
// run it by hand, under xvfb-run on a headless machine:
//   xvfb-run -a -s "-screen 0 1280x1024x24" ofbMapperBenchmark [options]
// Options: --mesh FILE (.obj/.ply), --resolution N (OFB cells, default 1024),
// --frames N (timed frames per mapper and round, default 30), --rounds N (default 3),
// --warmup N (untimed frames before each timing, default 3), --modes LIST (comma-separated
// subset of nearest,idw,mipmapped,nearestmipmapped,smooth; default all), --width W --height H
// (1280x1024), --images PREFIX (write PREFIX<k>-<mapper>.ppm of the first view of every
// mapper), --offscreen (render off screen: the frame is not copied to the X server),
// --painted-normals (each mode also with UsePaintedNormals, the sample normals shading),
// --egl [N] (an OpenGL context of EGL device N, default 0, instead of an X window: for a
// Linux machine with a GPU driver and no X display; the frames render off screen),
// --lic (the OFB mappers show a LIC, vtkOFBLIC's defaults, of a rotation about a tilted
// axis, instead of the paint; Smooth is timed with and without FlowAlignedFiltering),
// --zoom F (the camera zoomed by F: 4 shows about 4 pixels a cell of the default bunny).
// Fairness: one window, renderer, actor, property and headlight for every mapper; each
// timing starts from the same camera and turns it once around the surface; the mappers
// take turns within every round (so that a change of machine load hits all of them), and
// the medians over the rounds are compared. The frame time includes the clear and the
// copy of the frame to the X server (none with --offscreen), the same for every mapper.
// Besides the wall-clock times (the goal's measure) it prints the CPU time of the process
// (llvmpipe's rendering threads included), which other load on a shared machine disturbs
// less.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBReadMesh.h"
#include "vtkOFBSampler.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#ifdef VTKOFB_BENCHMARK_HAVE_EGL
#include "ofbEGLWindow.h"
#endif
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cctype>
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
  return vtkofbtest::ReadMeshFileWithNormals(path);
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
FrameTime TimeFrames(vtkRenderWindow* window,
  vtkRenderer* renderer,
  vtkCamera* start,
  int frames,
  int warmup)
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

struct Options
{
  std::string Mesh = std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj";
  int Resolution = 1024;
  int Frames = 30;
  int Rounds = 3;
  int Warmup = 3;
  int Width = 1280;
  int Height = 1024;
  std::string Images;
  bool OffScreen = false;
  int EGLDevice = -1;          // --egl: the EGL device whose context renders
  bool PaintedNormals = false; // each mode also with UsePaintedNormals
  bool LIC = false;            // show a LIC; Smooth also without the flow-aligned filter
  double Zoom = 1.0;           // camera zoom factor
  std::vector<int> Modes = { vtkOFBPolyDataMapper::LOOKUP_NEAREST,
    vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
    vtkOFBPolyDataMapper::LOOKUP_MIPMAPPED,
    vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED,
    vtkOFBPolyDataMapper::LOOKUP_SMOOTH };
};

// Lookup modes from a comma-separated list; false on an unknown name.
bool ParseModes(const std::string& list, std::vector<int>& modes)
{
  modes.clear();
  size_t begin = 0;
  while (begin <= list.size())
  {
    const size_t comma = std::min(list.find(',', begin), list.size());
    const std::string name = list.substr(begin, comma - begin);
    if (name == "nearest")
    {
      modes.push_back(vtkOFBPolyDataMapper::LOOKUP_NEAREST);
    }
    else if (name == "idw")
    {
      modes.push_back(vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE);
    }
    else if (name == "mipmapped")
    {
      modes.push_back(vtkOFBPolyDataMapper::LOOKUP_MIPMAPPED);
    }
    else if (name == "nearestmipmapped")
    {
      modes.push_back(vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED);
    }
    else if (name == "smooth")
    {
      modes.push_back(vtkOFBPolyDataMapper::LOOKUP_SMOOTH);
    }
    else if (!name.empty())
    {
      std::cerr << "Unknown mode " << name << "\n";
      return false;
    }
    begin = comma + 1;
  }
  return true;
}

// Returns -1 when the options are fine, else the exit code (usage printed).
int ParseOptions(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    int* integer = nullptr;
    int minimum = VTK_INT_MIN;
    if (arg == "--mesh" && hasValue)
    {
      o.Mesh = argv[++i];
      continue;
    }
    if (arg == "--images" && hasValue)
    {
      o.Images = argv[++i];
      continue;
    }
    if (arg == "--offscreen")
    {
      o.OffScreen = true;
      continue;
    }
    if (arg == "--egl")
    {
      o.EGLDevice = 0;
      if (i + 1 < argc && std::isdigit(static_cast<unsigned char>(argv[i + 1][0])))
      {
        o.EGLDevice = std::atoi(argv[++i]);
      }
      continue;
    }
    if (arg == "--painted-normals")
    {
      o.PaintedNormals = true;
      continue;
    }
    if (arg == "--lic")
    {
      o.LIC = true;
      continue;
    }
    if (arg == "--zoom" && hasValue)
    {
      o.Zoom = std::max(0.01, std::atof(argv[++i]));
      continue;
    }
    if (arg == "--modes" && hasValue)
    {
      if (!ParseModes(argv[++i], o.Modes))
      {
        return 1;
      }
      continue;
    }
    if (hasValue)
    {
      if (arg == "--resolution")
      {
        integer = &o.Resolution;
      }
      else if (arg == "--frames")
      {
        integer = &o.Frames;
        minimum = 1;
      }
      else if (arg == "--rounds")
      {
        integer = &o.Rounds;
        minimum = 1;
      }
      else if (arg == "--warmup")
      {
        integer = &o.Warmup;
        minimum = 0;
      }
      else if (arg == "--width")
      {
        integer = &o.Width;
      }
      else if (arg == "--height")
      {
        integer = &o.Height;
      }
    }
    if (integer)
    {
      *integer = std::max(minimum, std::atoi(argv[++i]));
      continue;
    }
    std::cout
      << "usage: ofbMapperBenchmark [--mesh FILE] [--resolution N] [--frames N] "
         "[--rounds N] [--warmup N] [--modes nearest,idw,mipmapped,nearestmipmapped,smooth] "
         "[--painted-normals] [--lic] [--zoom F] [--width W] "
         "[--height H] [--images PREFIX] [--offscreen] [--egl [N]]\n";
    return arg == "--help" ? 0 : 1;
  }
  return -1;
}

// The surface with vertex colours for the peer.
vtkSmartPointer<vtkPolyData> ColorVertices(vtkPolyData* surface)
{
  double bounds[6];
  surface->GetBounds(bounds);
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
  return colored;
}

// The surface with a rotation about a tilted axis through its centre as its point vectors
// (the field of --lic).
void AddRotation(vtkPolyData* surface)
{
  double b[6];
  surface->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double a[3] = { 0.36, 0.89, 0.27 };
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    const double* x = surface->GetPoint(p);
    const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
    flow->InsertNextTuple3(
      a[1] * r[2] - a[2] * r[1], a[2] * r[0] - a[0] * r[2], a[0] * r[1] - a[1] * r[0]);
  }
  surface->GetPointData()->SetVectors(flow);
}

// The LIC of `ofb` (vtkOFBLIC's defaults, the field its active vectors).
vtkSmartPointer<vtkOFB> ComputeLIC(vtkOFB* ofb)
{
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->Update();
  return lic->GetOutput();
}

// The OFB of the surface, with the same colours per sample (null on failure).
vtkSmartPointer<vtkOFB> BuildColoredOFB(vtkPolyData* surface, int resolution)
{
  double bounds[6];
  surface->GetBounds(bounds);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetResolution(resolution);
  sampler->Update();
  vtkSmartPointer<vtkOFB> ofb = sampler->GetOutput();
  if (ofb->GetNumberOfSamples() == 0)
  {
    return nullptr;
  }
  auto* sampleColors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
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
  return ofb;
}

// The mappers (the peer first, then one OFB mapper per mode) in one window, renderer and
// actor, all kept alive so that every round only switches the actor's mapper.
struct Bench
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkCamera> Start;
  std::vector<vtkSmartPointer<vtkMapper>> Mappers;
  std::vector<std::string> Names;
  std::vector<int> Modes; // of the OFB mappers, from Mappers[1] on
  std::vector<std::vector<double>> Wall;
  std::vector<std::vector<double>> CPU;
  std::vector<std::vector<double>> RoundRatios;
};

// Set the scene up and render once with every mapper; false if the OFB mapper cannot
// use the OFB on this context.
bool SetUp(Bench& b, const Options& o, vtkPolyData* surface, vtkPolyData* colored, vtkOFB* ofb)
{
  b.Window->SetOffScreenRendering(o.OffScreen);
  b.Window->SetSize(o.Width, o.Height);
  b.Renderer->SetBackground(0.2, 0.2, 0.25);
  b.Window->AddRenderer(b.Renderer);
  b.Renderer->AddActor(b.Actor);
  vtkNew<vtkPolyDataMapper> peer;
  peer->SetInputData(colored);
  b.Mappers.assign(1, peer.Get());
  b.Names.assign(1, "vtkPolyDataMapper, vertex colours");
  b.Modes.clear();
  for (int mode : o.Modes)
  {
    for (int variant = 0; variant < 4; ++variant)
    {
      const bool normals = (variant & 1) != 0;
      const bool noFlow = (variant & 2) != 0; // Smooth of a LIC without the flow filter
      if ((normals && !o.PaintedNormals) ||
        (noFlow && !(o.LIC && mode == vtkOFBPolyDataMapper::LOOKUP_SMOOTH)))
      {
        continue;
      }
      vtkNew<vtkOFBPolyDataMapper> mapper;
      mapper->SetInputData(surface);
      mapper->SetOFB(ofb);
      mapper->SetLookupMode(mode);
      mapper->SetUsePaintedNormals(normals);
      mapper->SetFlowAlignedFiltering(!noFlow);
      if (o.LIC)
      {
        mapper->GetColoring()->SetIntensityArrayName("LIC");
        mapper->GetColoring()->IntensityModulationOn();
        mapper->GetColoring()->SetLICIntensity(1.0);
      }
      b.Mappers.emplace_back(mapper.Get());
      b.Modes.push_back(mode);
      b.Names.push_back(std::string("vtkOFBPolyDataMapper, ") +
        vtkOFBPolyDataMapper::GetLookupModeAsString(mode) + (o.LIC ? ", LIC" : "") +
        (noFlow ? ", no flow filter" : "") + (normals ? ", painted normals" : ""));
    }
  }
  b.Actor->SetMapper(peer);
  b.Renderer->ResetCamera();
  b.Renderer->GetActiveCamera()->Zoom(o.Zoom);
  b.Renderer->ResetCameraClippingRange();
  b.Window->Render();
  b.Start->DeepCopy(b.Renderer->GetActiveCamera());
  for (size_t m = 1; m < b.Mappers.size(); ++m)
  {
    b.Actor->SetMapper(b.Mappers[m]);
    b.Window->Render();
    if (!vtkOFBPolyDataMapper::SafeDownCast(b.Mappers[m])->GetLastRenderUsedOFB())
    {
      std::cerr << "vtkOFBPolyDataMapper could not use the OFB on this context.\n";
      return false;
    }
  }
  return true;
}

void PrintHeader(Bench& b, const Options& o, vtkPolyData* surface, vtkOFB* ofb)
{
  const std::string capabilities =
    b.Window->ReportCapabilities() ? b.Window->ReportCapabilities() : "";
  std::cout << "ofbMapperBenchmark: " << o.Mesh << "\n"
            << "  triangles " << surface->GetNumberOfPolys() << ", OFB resolution " << o.Resolution
            << ", samples " << ofb->GetNumberOfSamples() << ", depth complexity "
            << ofb->GetDepthComplexity() << ", window " << o.Width << "x" << o.Height
            << (o.OffScreen ? " off screen" : "") << (o.LIC ? ", LIC" : "") << ", zoom " << o.Zoom
            << ", " << o.Frames << " frames per mapper and round, " << o.Rounds << " rounds\n";
  const std::string::size_type at = capabilities.find("OpenGL renderer string:");
  if (at != std::string::npos)
  {
    std::cout << "  " << capabilities.substr(at, capabilities.find('\n', at) - at) << "\n";
  }
  std::cout << std::fixed << std::setprecision(2);
}

// The mappers take turns within every round.
void TimeRounds(Bench& b, const Options& o)
{
  const size_t n = b.Mappers.size();
  b.Wall.assign(n, {});
  b.CPU.assign(n, {});
  b.RoundRatios.assign(n, {});
  std::cout << "  per round, wall ms/frame (CPU ms/frame of this process):\n";
  for (int r = 0; r < o.Rounds; ++r)
  {
    std::cout << "  round " << r + 1 << ":";
    for (size_t m = 0; m < n; ++m)
    {
      b.Actor->SetMapper(b.Mappers[m]);
      const FrameTime t = TimeFrames(b.Window, b.Renderer, b.Start, o.Frames, o.Warmup);
      b.Wall[m].push_back(t.Wall);
      b.CPU[m].push_back(t.CPU);
      b.RoundRatios[m].push_back(t.Wall / b.Wall[0].back());
      std::cout << " " << t.Wall << " (" << t.CPU << ")";
    }
    std::cout << std::endl;
  }
}

// Medians and ratios to the peer; returns Nearest's wall ratio (-1 if not measured).
double PrintMedians(const Bench& b, const Options& o)
{
  // The goal compares wall-clock frame times; CPU time is less sensitive to other load.
  const double peerMs = Median(b.Wall[0]);
  const double peerCPU = Median(b.CPU[0]);
  std::cout << "  medians over the rounds: wall ms/frame, ratio to the peer; CPU ms/frame, "
               "ratio; median of the per-round wall ratios\n";
  std::cout << "  " << std::left << std::setw(40) << b.Names[0] << std::right << std::setw(8)
            << peerMs << "          " << std::setw(8) << peerCPU << "\n";
  double nearestRatio = -1.0;
  for (size_t m = 1; m < b.Mappers.size(); ++m)
  {
    const double ms = Median(b.Wall[m]);
    const double ratio = ms / peerMs;
    if (b.Modes[m - 1] == vtkOFBPolyDataMapper::LOOKUP_NEAREST && nearestRatio < 0.0)
    {
      nearestRatio = ratio;
    }
    std::cout << "  " << std::left << std::setw(40) << b.Names[m] << std::right << std::setw(8)
              << ms << " " << std::setw(6) << ratio << "x " << std::setw(8) << Median(b.CPU[m])
              << " " << std::setw(6) << Median(b.CPU[m]) / peerCPU << "x " << std::setw(6)
              << Median(b.RoundRatios[m]) << "x\n";
  }
  return nearestRatio;
}

// PREFIX<k>-<mapper>.ppm of the first view of every mapper.
void WriteImages(Bench& b, const Options& o)
{
  for (size_t m = 0; m < b.Mappers.size(); ++m)
  {
    // peer, or the lookup mode in lower case, with "-normals" for painted normals.
    std::string file = "peer";
    if (auto* mapper = vtkOFBPolyDataMapper::SafeDownCast(b.Mappers[m]))
    {
      file = vtkOFBPolyDataMapper::GetLookupModeAsString(mapper->GetLookupMode());
      std::transform(file.begin(),
        file.end(),
        file.begin(),
        [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      file += mapper->GetUsePaintedNormals() ? "-normals" : "";
      file += o.LIC && !mapper->GetFlowAlignedFiltering() ? "-noflow" : "";
    }
    b.Actor->SetMapper(b.Mappers[m]);
    b.Renderer->GetActiveCamera()->DeepCopy(b.Start);
    b.Window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(b.Window);
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->SetInputBufferTypeToRGB();
    grab->Update();
    WritePPM(o.Images + std::to_string(m) + "-" + file + ".ppm", grab->GetOutput());
  }
}
}

int main(int argc, char* argv[])
{
  Options options;
  const int exitCode = ParseOptions(argc, argv, options);
  if (exitCode >= 0)
  {
    return exitCode;
  }
  vtkSmartPointer<vtkPolyData> surface = ReadMesh(options.Mesh);
  if (!surface)
  {
    std::cerr << "Cannot read a surface from " << options.Mesh << "\n";
    return 1;
  }
  vtkSmartPointer<vtkPolyData> colored = ColorVertices(surface);
  if (options.LIC)
  {
    AddRotation(surface);
  }
  vtkSmartPointer<vtkOFB> ofb = BuildColoredOFB(surface, options.Resolution);
  if (!ofb)
  {
    std::cerr << "The OFB build failed.\n";
    return 1;
  }
  if (options.LIC)
  {
    ofb = ComputeLIC(ofb);
  }
  Bench bench;
  if (options.EGLDevice >= 0)
  {
#ifdef VTKOFB_BENCHMARK_HAVE_EGL
    std::string why;
    bench.Window = ofbbench::NewEGLRenderWindow(options.EGLDevice, why);
    if (!bench.Window)
    {
      std::cerr << "--egl: " << why << "\n";
      return 1;
    }
    options.OffScreen = true;
#else
    std::cerr << "--egl: this build has no EGL (libegl-dev was not found)\n";
    return 1;
#endif
  }
  else
  {
    bench.Window = vtkSmartPointer<vtkRenderWindow>::New();
  }
  if (!SetUp(bench, options, surface, colored, ofb))
  {
    return 1;
  }
  PrintHeader(bench, options, surface, ofb);
  TimeRounds(bench, options);
  const double nearestRatio = PrintMedians(bench, options);
  if (!options.Images.empty())
  {
    WriteImages(bench, options);
  }
  for (size_t m = 1; m < bench.Mappers.size(); ++m)
  {
    bench.Mappers[m]->ReleaseGraphicsResources(bench.Window);
  }
  if (nearestRatio >= 0.0)
  {
    std::cout << "  goal: Nearest at most 2x the vertex-colour mapper: "
              << (nearestRatio <= 2.0 ? "met" : "NOT met") << " (" << nearestRatio << "x)\n";
  }
  return 0;
}
