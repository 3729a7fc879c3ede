// ofbLICBenchmark: throughput of vtkOFBLIC (M samples/s) on the OFBs of the horse and
// the Stanford bunny, against the machine's memory bandwidth measured in the same run, and
// the frame time of vtkOFBPolyDataMapper showing the LIC against a plain
// vtkPolyDataMapper on the same mesh in the same window.
// Not a test: run it by hand, under xvfb-run on a headless machine:
//   xvfb-run -a -s "-screen 0 1280x1024x24" ofbLICBenchmark [options]
// Options: --meshes LIST (comma-separated files or bunny,horse; default bunny,horse),
// --resolutions LIST (default 1024,2048), --threads LIST (default 1,2), --steps N (each
// way, default 10: 2 x 10 steps a sample), --rounds N (default 3), --frames N (timed
// frames per mapper and round, default 20; 0: no rendering), --width W --height H
// (default 1024x768), --frames-only (skip the LIC throughput rows: only the sampler and
// the frame rows, e.g. for a GPU whose frames are the question), --offscreen (render off
// screen: the frame is not copied to the X server),
// --parts LIST (which LIC columns to time, of first,anim,first+enh,
// anim+enh; default all: `--parts first --rounds 1 --frames 0` under perf profiles the first
// computation alone), --checksum (a line per OFB with a 32-bit FNV-1a hash of the LIC
// array of each part: the same numbers before and after a change of the code mean a
// bit-for-bit identical result), --per-sample (CacheStreamlines off: every sample traces
// its own streamline, every update), --reuse D (StreamlineReuseDistance D cells),
// --quality (a line per OFB: the correlation of the LIC, EnhancedLIC on, with the one
// traced from every sample, and the downstream-neighbour difference across grid switches
// and tile planes as ratios to that elsewhere, with the per-sample traced LIC's),
// --cpu-time (the LIC columns time the processor time of the process, user and system of
// all its threads, instead of the wall clock: on a machine shared with other work the wall
// clock also counts the waits for a core; the GB/s columns then use that time).
// Rows, per mesh, resolution and number of threads (medians over the rounds):
// - first: a new vtkOFBLIC on the sampler's OFB, everything included (packed samples,
//   tangential field and mask, noise, tracing, convolution, output), EnhancedLIC off
//   (Eq. 4 once); first+enh: the same with EnhancedLIC on (two passes, high-pass);
// - anim: a re-convolution with a new AnimationPhase (the kept streamlines gathered
//   again); anim+enh: the same with EnhancedLIC on;
// - GB/s: the bytes the LIC must move (a model: the arrays it streams through once,
//   printed per sample) per second, and its share of the STREAM-triad bandwidth
//   measured with the same number of threads in the same run.
// Frames (2 threads, each mesh and resolution): the median frame time of the plain
// mapper (one colour), of vtkOFBPolyDataMapper showing the LIC (Nearest, InverseDistance
// and NearestMipmapped lookups), of the same mapper without the LIC (Nearest, the
// sampler's colours: what the LIC itself adds to a frame) and of an animation frame (new
// AnimationPhase, LIC update, upload of the LIC array and render; with NearestMipmapped
// also the filtering of the pyramid's arrays and their upload), as ratios to the plain
// mapper's frame. The
// mappers take turns within every round, so that a change of load hits all of them.
// On a shared machine the numbers are noisy: compare the ratios, repeat, and note the
// load (printed from /proc/loadavg at the start and the end).
#include "vtkOFBLICTestHelpers.h"
#include "vtkOFBReadMesh.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(const Clock::time_point& start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
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

std::string Load()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::vector<std::string> Split(const std::string& list)
{
  std::vector<std::string> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    if (!item.empty())
    {
      out.push_back(item);
    }
  }
  return out;
}

struct Options
{
  std::vector<std::string> Meshes = { "bunny", "horse" };
  std::vector<int> Resolutions = { 1024, 2048 };
  std::vector<int> Threads = { 1, 2 };
  int Steps = 10;
  int Rounds = 3;
  int Frames = 20;
  int Width = 1024;
  int Height = 768;
  bool FramesOnly = false;
  bool OffScreen = false;
  bool Parts[4] = { true, true, true, true }; // first, anim, first+enh, anim+enh
  bool Checksum = false;
  bool PerSample = false;
  double Reuse = -1.0; // StreamlineReuseDistance; negative: the filter's default
  bool Quality = false;
  bool CPUTime = false;
};

const char* const PartNames[4] = { "first", "anim", "first+enh", "anim+enh" };

// Returns -1 when the options are fine, else the exit code (usage printed).
int ParseOptions(int argc, char* argv[], Options& o)
{
  auto ints = [](const std::string& list)
  {
    std::vector<int> v;
    for (const std::string& s : Split(list))
    {
      v.push_back(std::max(1, std::atoi(s.c_str())));
    }
    return v;
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--meshes" && hasValue)
      o.Meshes = Split(argv[++i]);
    else if (arg == "--resolutions" && hasValue)
      o.Resolutions = ints(argv[++i]);
    else if (arg == "--threads" && hasValue)
      o.Threads = ints(argv[++i]);
    else if (arg == "--steps" && hasValue)
      o.Steps = std::max(0, std::atoi(argv[++i]));
    else if (arg == "--rounds" && hasValue)
      o.Rounds = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--frames" && hasValue)
      o.Frames = std::max(0, std::atoi(argv[++i]));
    else if (arg == "--width" && hasValue)
      o.Width = std::max(16, std::atoi(argv[++i]));
    else if (arg == "--height" && hasValue)
      o.Height = std::max(16, std::atoi(argv[++i]));
    else if (arg == "--frames-only")
      o.FramesOnly = true;
    else if (arg == "--offscreen")
      o.OffScreen = true;
    else if (arg == "--parts" && hasValue)
    {
      const std::vector<std::string> parts = Split(argv[++i]);
      for (int p = 0; p < 4; ++p)
      {
        o.Parts[p] = std::find(parts.begin(), parts.end(), PartNames[p]) != parts.end();
      }
    }
    else if (arg == "--checksum")
      o.Checksum = true;
    else if (arg == "--per-sample")
      o.PerSample = true;
    else if (arg == "--reuse" && hasValue)
      o.Reuse = std::max(0.0, std::atof(argv[++i]));
    else if (arg == "--quality")
      o.Quality = true;
    else if (arg == "--cpu-time")
      o.CPUTime = true;
    else
    {
      std::cout << "usage: ofbLICBenchmark [--meshes bunny,horse|FILES] [--resolutions LIST] "
                   "[--threads LIST] [--steps N] [--rounds N] [--frames N] [--width W] "
                   "[--height H] [--frames-only] [--offscreen] "
                   "[--parts first,anim,first+enh,anim+enh] [--checksum] [--per-sample] [--reuse "
                   "D] [--quality] [--cpu-time]\n";
      return arg == "--help" ? 0 : 1;
    }
  }
  return -1;
}

std::string MeshPath(const std::string& name)
{
  if (name == "bunny")
  {
    return std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj";
  }
  if (name == "horse")
  {
    return std::string(VTKOFB_DATA_DIR) + "/horse.ply";
  }
  return name;
}

/// The mesh with point normals and a rotation about a tilted axis through its centre as
/// the point vectors.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> out = vtkofbtest::ReadMeshFileWithNormals(path);
  if (!out)
  {
    return nullptr;
  }
  double b[6];
  out->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double a[3] = { 0.36, 0.89, 0.27 };
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    const double* x = out->GetPoint(p);
    const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
    flow->InsertNextTuple3(
      a[1] * r[2] - a[2] * r[1], a[2] * r[0] - a[0] * r[2], a[0] * r[1] - a[1] * r[0]);
  }
  out->GetPointData()->SetVectors(flow);
  return out;
}

/// STREAM triad a = b + s c over arrays far larger than the caches, with the current
/// number of threads: the best of 5 runs in bytes per second (3 x 8 bytes an element).
double TriadBandwidth()
{
  const vtkIdType n = 1 << 24; // 16 Mi doubles: 128 MiB an array
  std::vector<double> a(n), b(n, 1.0), c(n, 2.0);
  vtkSMPTools::For(0,
    n,
    1 << 16,
    [&](vtkIdType begin, vtkIdType end) { std::fill(a.data() + begin, a.data() + end, 0.0); });
  double best = 0.0;
  for (int r = 0; r < 5; ++r)
  {
    const double s = 1.0 + r;
    const Clock::time_point t0 = Clock::now();
    vtkSMPTools::For(0,
      n,
      1 << 16,
      [&](vtkIdType begin, vtkIdType end)
      {
        double* pa = a.data();
        const double* pb = b.data();
        const double* pc = c.data();
        for (vtkIdType i = begin; i < end; ++i)
        {
          pa[i] = pb[i] + s * pc[i];
        }
      });
    best = std::max(best, 3.0 * sizeof(double) * n / Seconds(t0));
  }
  return best + 0.0 * a[n / 2];
}

/// Times of one round of the LIC parts (first, anim, first+enh, anim+enh), in seconds (0:
/// not timed), and the FNV-1a hash of each part's LIC array.
struct LICTimes
{
  double Seconds[4] = { 0.0, 0.0, 0.0, 0.0 };
  std::uint32_t Hash[4] = { 0, 0, 0, 0 };
};

std::uint32_t HashLIC(vtkOFBLIC* lic)
{
  vtkFloatArray* a =
    vtkFloatArray::SafeDownCast(lic->GetOutput()->GetSampleData()->GetArray("LIC"));
  std::uint32_t h = 2166136261u;
  if (!a)
  {
    return h;
  }
  const unsigned char* bytes = reinterpret_cast<const unsigned char*>(a->GetPointer(0));
  for (vtkIdType i = 0, n = a->GetNumberOfValues() * 4; i < n; ++i)
  {
    h = (h ^ bytes[i]) * 16777619u;
  }
  return h;
}

/// User and system processor seconds of the process so far (all threads).
double ProcessSeconds()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

LICTimes TimeLIC(vtkOFB* ofb,
  int steps,
  const bool parts[4],
  bool perSample,
  double reuse,
  bool cpuTime)
{
  LICTimes t;
  auto update = [cpuTime](vtkOFBLIC* lic)
  {
    const double c0 = ProcessSeconds();
    const Clock::time_point t0 = Clock::now();
    lic->Update();
    return cpuTime ? ProcessSeconds() - c0 : Seconds(t0);
  };
  for (int enhanced = 0; enhanced < 2; ++enhanced)
  {
    const int first = 2 * enhanced;
    if (!parts[first] && !parts[first + 1])
    {
      continue;
    }
    vtkNew<vtkOFBLIC> lic;
    lic->SetInputData(ofb);
    lic->SetNumberOfSteps(steps);
    lic->SetEnhancedLIC(enhanced != 0);
    lic->AnimateOn();
    lic->SetCacheStreamlines(!perSample);
    if (reuse >= 0.0)
    {
      lic->SetStreamlineReuseDistance(reuse);
    }
    t.Seconds[first] = update(lic);
    t.Hash[first] = HashLIC(lic);
    if (parts[first + 1])
    {
      lic->SetAnimationPhase(0.1);
      t.Seconds[first + 1] = update(lic);
      t.Hash[first + 1] = HashLIC(lic);
    }
  }
  return t;
}

/**
 * Bytes a sample that the LIC moves at least (the model of the bandwidth share), Animate
 * on: the re-convolution reads the kept sums of the sample's window (16 bytes), the mask
 * and the noise and writes the result (9 bytes), and the output reads the result and the
 * mask and writes LIC and LICMask (10 bytes); the second pass of EnhancedLIC reads the
 * ids of its window of 2 (steps / 2) + 1 kept steps (4 bytes each), reads and writes the
 * values (9 bytes), and the high-pass reads and writes them (16 bytes); the first
 * computation also reads the input's depth, cell index, normal and field (32 bytes),
 * writes the packed sample and the noise (44 bytes), and writes the streamlines (about
 * steps + 1 ids of 4 bytes) and the kept sums.
 */
double BytesPerSample(int steps, bool first, bool enhanced)
{
  double bytes = 16.0 + 9.0 + 10.0;
  if (enhanced)
  {
    bytes += 4.0 * (2 * (steps / 2) + 1) + 9.0 + 16.0;
  }
  if (first)
  {
    bytes += 76.0 + 4.0 * (steps + 1) + 16.0;
  }
  return bytes;
}

/**
 * The quality of the LIC (EnhancedLIC on, as by default) against the LIC traced from
 * every sample (CacheStreamlines off): their correlation, and the mean LIC difference
 * between a sample and the sample one cell downstream across grid switches and across
 * the 64-cell tile planes, as ratios to that elsewhere (vtkOFBLICTestHelpers.h).
 */
void PrintQuality(const Options& o, vtkOFB* ofb)
{
  vtkNew<vtkOFBLIC> fast;
  vtkNew<vtkOFBLIC> traced;
  for (vtkOFBLIC* lic : { fast.Get(), traced.Get() })
  {
    lic->SetInputData(ofb);
    lic->SetNumberOfSteps(o.Steps);
  }
  if (o.Reuse >= 0.0)
  {
    fast->SetStreamlineReuseDistance(o.Reuse);
  }
  fast->SetCacheStreamlines(!o.PerSample);
  traced->CacheStreamlinesOff();
  fast->Update();
  traced->Update();
  auto values = [](vtkOFBLIC* lic)
  { return vtkFloatArray::SafeDownCast(lic->GetOutput()->GetSampleData()->GetArray("LIC")); };
  vtkUnsignedCharArray* mask =
    vtkUnsignedCharArray::SafeDownCast(traced->GetOutput()->GetSampleData()->GetArray("LICMask"));
  if (!values(fast) || !values(traced) || !mask)
  {
    return;
  }
  const float* a = values(fast)->GetPointer(0);
  const float* b = values(traced)->GetPointer(0);
  const unsigned char* m = mask->GetPointer(0);
  const vtkofbtest::Correlation c = vtkofbtest::CorrelationUnmasked(ofb, a, b, m);
  const vtkofbtest::DownstreamDifference da = vtkofbtest::DownstreamDifferences(ofb, a, m);
  const vtkofbtest::DownstreamDifference db = vtkofbtest::DownstreamDifferences(ofb, b, m);
  std::cout << "  quality: correlation with the per-sample traced LIC " << std::setprecision(3)
            << c.Value << "; downstream difference grid switch / same grid "
            << da.GridSwitch / da.SameGrid << " (per-sample " << db.GridSwitch / db.SameGrid
            << "), tile plane / in tile " << da.TilePlane / da.InTile << " (per-sample "
            << db.TilePlane / db.InTile << ")" << std::endl;
}

/// The LIC rows of one OFB for every number of threads.
void RunLIC(const Options& o,
  const std::string& name,
  int resolution,
  vtkOFB* ofb,
  double buildSeconds)
{
  const vtkIdType n = ofb->GetNumberOfSamples();
  for (int threads : o.Threads)
  {
    vtkSMPTools::Initialize(threads);
    const double triad = TriadBandwidth();
    std::vector<double> times[4];
    LICTimes last;
    for (int r = 0; r < o.Rounds; ++r)
    {
      last = TimeLIC(ofb, o.Steps, o.Parts, o.PerSample, o.Reuse, o.CPUTime);
      for (int p = 0; p < 4; ++p)
      {
        times[p].push_back(last.Seconds[p]);
      }
    }
    auto cell = [&](int part)
    {
      const bool isFirst = part % 2 == 0;
      const bool enhanced = part >= 2;
      const double m = Median(times[part]);
      if (!o.Parts[part])
      {
        return std::string(37, ' ');
      }
      const double bytes = BytesPerSample(o.Steps, isFirst, enhanced) * n / m;
      std::ostringstream s;
      s << std::fixed << std::setprecision(1) << std::setw(7) << 1e3 * m << " ms " << std::setw(6)
        << n / m / 1e6 << " M/s " << std::setprecision(2) << std::setw(5) << bytes / 1e9 << " GB/s "
        << std::setprecision(0) << std::setw(3) << 100.0 * bytes / triad << "%";
      return s.str();
    };
    std::cout << std::left << std::setw(7) << name << std::right << std::setw(5) << resolution
              << std::setw(9) << n << std::setw(3) << threads << std::fixed << std::setprecision(1)
              << std::setw(7) << triad / 1e9 << std::setw(7) << 1e3 * buildSeconds << " | "
              << cell(0) << " | " << cell(1) << " | " << cell(2) << " | " << cell(3) << std::endl;
    if (o.Checksum)
    {
      std::cout << "  LIC hashes:";
      for (int p = 0; p < 4; ++p)
      {
        if (o.Parts[p])
        {
          std::cout << " " << PartNames[p] << " " << std::hex << std::setw(8) << std::setfill('0')
                    << last.Hash[p] << std::dec << std::setfill(' ');
        }
      }
      std::cout << std::endl;
    }
  }
}

// Milliseconds per frame of `frames` renders while the camera turns once around the
// surface (after 3 untimed ones), waiting for completion; `before` runs before each
// frame (the animation's LIC update), its time included.
template<typename Before>
double TimeFrames(vtkRenderWindow* window,
  vtkRenderer* renderer,
  vtkCamera* start,
  int frames,
  Before&& before)
{
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->DeepCopy(start);
  // Warm-up frames with other indices than the timed ones: an animation's timed phases
  // are new (the pyramid's filter cache would otherwise serve the mipmapped ones).
  for (int i = 0; i < 3; ++i)
  {
    before(frames + i);
    window->Render();
  }
  if (gl)
  {
    gl->WaitForCompletion();
  }
  const Clock::time_point t0 = Clock::now();
  for (int i = 0; i < frames; ++i)
  {
    before(i);
    camera->Azimuth(360.0 / frames);
    window->Render();
    if (gl)
    {
      gl->WaitForCompletion();
    }
  }
  const double ms = 1e3 * Seconds(t0) / frames;
  camera->DeepCopy(start);
  return ms;
}

/// The frame rows of one mesh and OFB (2 threads for the LIC).
void RunFrames(const Options& o,
  const std::string& name,
  int resolution,
  vtkPolyData* mesh,
  vtkOFB* ofb)
{
  vtkSMPTools::Initialize(2);
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->SetNumberOfSteps(o.Steps);
  lic->EnhancedLICOff();
  lic->AnimateOn();
  lic->Update();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(o.OffScreen);
  window->SetSize(o.Width, o.Height);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  vtkNew<vtkActor> actor;
  actor->GetProperty()->SetColor(0.9, 0.85, 0.75);
  renderer->AddActor(actor);
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputData(mesh);
  plain->ScalarVisibilityOff();
  std::vector<vtkSmartPointer<vtkMapper>> mappers = { plain.Get() };
  // The OFB mapper showing the LIC (Nearest, InverseDistance, NearestMipmapped), then
  // without it (Nearest, the sampler's colours only): the cost of the LIC in the display
  // itself.
  for (int mode : { vtkOFBPolyDataMapper::LOOKUP_NEAREST,
         vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
         vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED,
         vtkOFBPolyDataMapper::LOOKUP_NEAREST })
  {
    vtkNew<vtkOFBPolyDataMapper> m;
    m->SetInputData(mesh);
    m->SetOFBConnection(lic->GetOutputPort());
    m->SetLookupMode(mode);
    if (mappers.size() < 4)
    {
      m->GetColoring()->SetIntensityArrayName("LIC");
      m->GetColoring()->IntensityModulationOn();
    }
    mappers.emplace_back(m.Get());
  }
  actor->SetMapper(plain);
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkCamera> start;
  start->DeepCopy(renderer->GetActiveCamera());
  // Rows: plain, LIC Nearest, LIC InverseDistance, LIC NearestMipmapped, Nearest without
  // the LIC, animation (LIC Nearest, then LIC NearestMipmapped, with a new phase a frame).
  std::vector<std::vector<double>> ms(7);
  auto nothing = [](int) {};
  for (int r = 0; r < o.Rounds; ++r)
  {
    for (size_t m = 0; m < mappers.size(); ++m)
    {
      actor->SetMapper(mappers[m]);
      ms[m].push_back(TimeFrames(window, renderer, start, o.Frames, nothing));
    }
    for (int a = 0; a < 2; ++a)
    {
      // NearestMipmapped's animation frames filter the pyramid again (about 0.3 s on the
      // bunny at 1024): a quarter of the frames.
      actor->SetMapper(mappers[a == 0 ? 1 : 3]);
      ms[5 + a].push_back(TimeFrames(window,
        renderer,
        start,
        a == 0 ? o.Frames : std::max(2, o.Frames / 4),
        [&](int i) { lic->SetAnimationPhase(0.05 * (i + 1) + 0.01 * r + 0.5 * a); }));
    }
  }
  const double peer = Median(ms[0]);
  std::cout << std::left << std::setw(7) << name << std::right << std::setw(5) << resolution
            << std::fixed << std::setprecision(1) << std::setw(10) << peer;
  for (int m = 1; m < 7; ++m)
  {
    const double t = Median(ms[m]);
    std::cout << std::setw(10) << t << " (" << std::setprecision(2) << t / peer << "x)"
              << std::setprecision(1);
  }
  std::cout << std::endl;
  auto* ofbMapper = vtkOFBPolyDataMapper::SafeDownCast(mappers[1]);
  if (!ofbMapper->GetLastRenderUsedOFB())
  {
    std::cout << "  (vtkOFBPolyDataMapper did not draw from the OFB on this context)\n";
  }
}
}

int main(int argc, char* argv[])
{
  Options o;
  const int parsed = ParseOptions(argc, argv, o);
  if (parsed >= 0)
  {
    return parsed;
  }
  std::cout << "ofbLICBenchmark: 2 x " << o.Steps << " steps a sample, medians of " << o.Rounds
            << " rounds, load " << Load() << "\n"
            << "first: new vtkOFBLIC, everything included; anim: re-convolution with a new "
               "AnimationPhase; +enh: EnhancedLIC on"
            << (o.CPUTime ? "; times are processor time (all threads)" : "") << ".\n"
            << "Each cell: time, M samples/s, GB/s the LIC moves (model: "
            << BytesPerSample(o.Steps, true, false) << ", " << BytesPerSample(o.Steps, false, false)
            << ", " << BytesPerSample(o.Steps, true, true) << ", "
            << BytesPerSample(o.Steps, false, true)
            << " bytes a sample), % of the STREAM triad (triad GB/s, same threads, same run).\n"
            << "mesh     res  samples th  triad  build |        first                      | "
               "        anim                      |        first+enh                  |  "
               "      anim+enh\n";
  struct Built
  {
    std::string Name;
    int Resolution;
    vtkSmartPointer<vtkPolyData> Mesh;
    vtkSmartPointer<vtkOFB> OFB;
  };
  std::vector<Built> built;
  for (const std::string& name : o.Meshes)
  {
    vtkSmartPointer<vtkPolyData> mesh = ReadMesh(MeshPath(name));
    if (!mesh)
    {
      std::cerr << "Cannot read " << MeshPath(name) << "\n";
      return 1;
    }
    for (int resolution : o.Resolutions)
    {
      vtkSMPTools::Initialize(2);
      vtkNew<vtkOFBSampler> sampler;
      sampler->SetInputData(mesh);
      sampler->SetResolution(resolution);
      const Clock::time_point t0 = Clock::now();
      sampler->Update();
      const double buildSeconds = Seconds(t0);
      vtkSmartPointer<vtkOFB> ofb = sampler->GetOutput();
      if (!o.FramesOnly)
      {
        RunLIC(o, name, resolution, ofb, buildSeconds);
        if (o.Quality)
        {
          PrintQuality(o, ofb);
        }
      }
      built.push_back({ name, resolution, mesh, ofb });
    }
  }
  if (o.Frames > 0)
  {
    std::cout << "\nFrames (ms, " << o.Width << "x" << o.Height
              << (o.OffScreen ? " off screen" : "") << ", " << o.Frames
              << " frames a mapper and round, LIC on 2 threads):\n"
              << "mesh     res     plain  LIC Nearest        LIC InverseDistance   "
                 "LIC NearestMipmapped  no LIC, Nearest    animation frame (new phase + "
                 "render): Nearest, NearestMipmapped\n";
    for (const Built& b : built)
    {
      RunFrames(o, b.Name, b.Resolution, b.Mesh, b.OFB);
    }
  }
  std::cout << "load at the end " << Load() << "\n";
  return 0;
}
