// ofbBenchmark: build time, throughput and memory of vtkOFBSampler (CPU backend) on
// real meshes, against OpenVDB storing the same samples, and the build's output
// bandwidth against the machine's measured memory bandwidth.
//
//   ofbBenchmark [--resolutions 512,1024,2048] [--meshes bunny,horse] [--repetitions 5]
//                [--threads N] [--no-openvdb]
//
// Meshes are names (bunny, horse, fandisk, rocker-arm, teapot), files of Testing/Data
// or paths to .obj/.ply files. Every measurement is taken after one untimed warm-up
// build and reported as the best and the median of the repetitions; rebuilds write
// over the memory of the previous output and the sampler's kept buffers. The
// warm-up, the first build of a new sampler into new memory (fresh to the process
// where the earlier builds used less), is reported too.
// OpenVDB runs in a process of its own (this program with --openvdb-peer MESH
// RESOLUTION, which builds the OFB untimed and times OpenVDB storing its
// samples): its millions of small allocations, once freed, would otherwise stay
// in this process's heap in 4 KiB pages, where the next OFB's arrays would land.

#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBReadMesh.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersion.h"

#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
#include <openvdb/openvdb.h>
#endif

#if defined(__unix__)
#include <unistd.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
double Now()
{
  return vtkTimerLog::GetUniversalTime();
}

/// Best and median of a set of timings (seconds).
struct Timing
{
  double Best = 0.0;
  double Median = 0.0;
};

Timing Summarize(std::vector<double> t)
{
  Timing r;
  if (t.empty())
  {
    return r;
  }
  std::sort(t.begin(), t.end());
  r.Best = t.front();
  const size_t m = t.size() / 2;
  r.Median = t.size() % 2 ? t[m] : 0.5 * (t[m - 1] + t[m]);
  return r;
}

struct Options
{
  std::vector<int> Resolutions = { 512, 1024, 2048 };
  std::vector<std::string> Meshes = { "bunny", "horse" };
  int Repetitions = 5;
  int Threads = 0;
  bool OpenVDB = true;
  std::string PeerMesh; // --openvdb-peer: time OpenVDB for this mesh and resolution
  int PeerResolution = 0;
};

void Usage(const char* argv0)
{
  std::printf("usage: %s [--resolutions 512,1024,2048] [--meshes bunny,horse] "
              "[--repetitions 5] [--threads N] [--no-openvdb]\n"
              "  meshes: bunny, horse, fandisk, rocker-arm, teapot, a file of Testing/Data "
              "or a path to an .obj/.ply file\n",
    argv0);
}

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
  {
    if (!part.empty())
    {
      parts.push_back(part);
    }
  }
  return parts;
}

bool ParseOptions(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--help" || arg == "-h")
    {
      return false;
    }
    else if (arg == "--no-openvdb")
    {
      options.OpenVDB = false;
    }
    else if (arg == "--resolutions" && hasValue)
    {
      options.Resolutions.clear();
      for (const std::string& r : Split(argv[++i]))
      {
        options.Resolutions.push_back(std::atoi(r.c_str()));
      }
    }
    else if (arg == "--meshes" && hasValue)
    {
      options.Meshes = Split(argv[++i]);
    }
    else if (arg == "--repetitions" && hasValue)
    {
      options.Repetitions = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--threads" && hasValue)
    {
      options.Threads = std::max(0, std::atoi(argv[++i]));
    }
    else if (arg == "--openvdb-peer" && i + 2 < argc)
    {
      options.PeerMesh = argv[++i];
      options.PeerResolution = std::atoi(argv[++i]);
    }
    else
    {
      std::fprintf(stderr, "unknown or incomplete option '%s'\n", arg.c_str());
      return false;
    }
  }
  return !options.Resolutions.empty() && !options.Meshes.empty();
}

/// Path of a mesh given by short name, data file name or path.
std::string MeshPath(const std::string& name)
{
  const char* known[][2] = { { "bunny", "stanford-bunny.obj" },
    { "horse", "horse.ply" },
    { "fandisk", "fandisk.obj" },
    { "rocker-arm", "rocker-arm.obj" },
    { "teapot", "teapot.obj" } };
  for (const auto& k : known)
  {
    if (name == k[0])
    {
      return std::string(VTKOFB_DATA_DIR) + "/" + k[1];
    }
  }
  if (std::ifstream(name).good())
  {
    return name;
  }
  return std::string(VTKOFB_DATA_DIR) + "/" + name;
}

//------------------------------------------------------------------------------
// Memory bandwidth: STREAM-like copy (c = a) and triad (a = b + s c) on arrays of
// doubles, split in contiguous chunks over the threads, each thread touching its
// own chunk first. Bytes counted as in STREAM: read + written, no write-allocate.
struct Bandwidth
{
  double Copy = 0.0;  // bytes/s
  double Triad = 0.0; // bytes/s
  double ArrayBytes = 0.0;
};

template<typename F>
double RunOnThreads(int nThreads, size_t n, F&& f)
{
  const double start = Now();
  std::vector<std::thread> threads;
  for (int t = 0; t < nThreads; ++t)
  {
    const size_t begin = n * t / nThreads;
    const size_t end = n * (t + 1) / nThreads;
    threads.emplace_back([&f, begin, end]() { f(begin, end); });
  }
  for (auto& thread : threads)
  {
    thread.join();
  }
  return Now() - start;
}

Bandwidth MeasureBandwidth(int nThreads, size_t n, int repetitions)
{
  std::unique_ptr<double[]> a(new double[n]);
  std::unique_ptr<double[]> b(new double[n]);
  std::unique_ptr<double[]> c(new double[n]);
  double* A = a.get();
  double* B = b.get();
  double* C = c.get();
  RunOnThreads(nThreads,
    n,
    [=](size_t begin, size_t end)
    {
      for (size_t i = begin; i < end; ++i)
      {
        A[i] = 1.0;
        B[i] = 2.0;
        C[i] = 0.0;
      }
    });
  std::vector<double> copy, triad;
  for (int r = 0; r < repetitions; ++r)
  {
    copy.push_back(RunOnThreads(nThreads,
      n,
      [=](size_t begin, size_t end) { std::memcpy(C + begin, A + begin, (end - begin) * 8); }));
    triad.push_back(RunOnThreads(nThreads,
      n,
      [=](size_t begin, size_t end)
      {
        for (size_t i = begin; i < end; ++i)
        {
          A[i] = B[i] + 3.0 * C[i];
        }
      }));
  }
  volatile double sink = A[n / 2] + C[n / 3];
  (void)sink;
  Bandwidth result;
  result.ArrayBytes = 8.0 * n;
  result.Copy = 2.0 * 8.0 * n / Summarize(copy).Best;
  result.Triad = 3.0 * 8.0 * n / Summarize(triad).Best;
  return result;
}

//------------------------------------------------------------------------------
/// The OFB samples as a sparse-volume peer receives them: world position, normal
/// and RGBA colour packed in 32 bits.
struct SamplePayload
{
  std::vector<double> Positions; // xyz per sample
  std::vector<float> Normals;    // xyz per sample
  std::vector<int32_t> Colors;   // RGBA, R in the low byte
};

SamplePayload ExtractSamples(vtkOFB* ofb)
{
  SamplePayload p;
  const vtkIdType n = ofb->GetNumberOfSamples();
  p.Positions.resize(3 * n);
  p.Normals.resize(3 * n);
  p.Colors.resize(n);
  vtkDataArray* normals = ofb->GetSampleData()->GetNormals();
  auto colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetScalars());
  vtkSMPTools::For(0,
    n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        ofb->GetSamplePosition(i, &p.Positions[3 * i]);
        for (int k = 0; k < 3; ++k)
        {
          p.Normals[3 * i + k] = static_cast<float>(normals->GetComponent(i, k));
        }
        uint32_t rgba = 0;
        for (int k = 0; colors && k < 4; ++k)
        {
          rgba |= static_cast<uint32_t>(colors->GetValue(4 * i + k)) << (8 * k);
        }
        p.Colors[i] = static_cast<int32_t>(rgba);
      }
    });
  return p;
}

#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
/**
 * OpenVDB peer: a Vec3SGrid of normals and an Int32Grid of packed RGBA colours
 * with voxel size = OFB cell size, voxel centres on the OFB cell centres. Each
 * sample is written with setValue through the grids' accessors at the voxel that
 * holds its position. With several threads, thread t fills its own pair of grids
 * with the samples whose leaf node (8^3 voxels) lies in a slab x / 8 = t modulo
 * the number of threads, so that the threads' leaves are disjoint and the merge
 * (MERGE_ACTIVE_STATES) only moves nodes.
 */
struct VDBResult
{
  double Seconds = 0.0;
  double Bytes = 0.0;
  uint64_t Voxels = 0;
};

struct VDBGrids
{
  openvdb::Vec3SGrid::Ptr Normals;
  openvdb::Int32Grid::Ptr Colors;
};

VDBGrids FillVDB(const SamplePayload& p, openvdb::math::Transform::Ptr xform, int part, int nParts)
{
  VDBGrids g;
  g.Normals = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  g.Colors = openvdb::Int32Grid::create(0);
  g.Normals->setTransform(xform);
  g.Colors->setTransform(xform);
  auto normals = g.Normals->getAccessor();
  auto colors = g.Colors->getAccessor();
  const size_t n = p.Colors.size();
  for (size_t i = 0; i < n; ++i)
  {
    const openvdb::Vec3d x(p.Positions[3 * i], p.Positions[3 * i + 1], p.Positions[3 * i + 2]);
    const openvdb::Coord ijk = xform->worldToIndexCellCentered(x);
    if (nParts > 1 && static_cast<uint32_t>(ijk.x() >> 3) % nParts != static_cast<uint32_t>(part))
    {
      continue;
    }
    normals.setValue(ijk, openvdb::Vec3s(&p.Normals[3 * i]));
    colors.setValue(ijk, p.Colors[i]);
  }
  return g;
}

VDBResult BuildVDB(const SamplePayload& p, vtkOFB* ofb, int nThreads)
{
  const double s = ofb->GetCellSize();
  const double* o = ofb->GetOrigin();
  const double start = Now();
  openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(s);
  xform->postTranslate(openvdb::Vec3d(o[0] + 0.5 * s, o[1] + 0.5 * s, o[2] + 0.5 * s));
  std::vector<VDBGrids> parts(nThreads);
  if (nThreads == 1)
  {
    parts[0] = FillVDB(p, xform, 0, 1);
  }
  else
  {
    std::vector<std::thread> threads;
    for (int t = 0; t < nThreads; ++t)
    {
      threads.emplace_back([&, t]() { parts[t] = FillVDB(p, xform, t, nThreads); });
    }
    for (auto& thread : threads)
    {
      thread.join();
    }
    for (int t = 1; t < nThreads; ++t)
    {
      parts[0].Normals->merge(*parts[t].Normals);
      parts[0].Colors->merge(*parts[t].Colors);
    }
  }
  VDBResult r;
  r.Seconds = Now() - start;
  r.Bytes = static_cast<double>(parts[0].Normals->memUsage() + parts[0].Colors->memUsage());
  r.Voxels = parts[0].Normals->activeVoxelCount();
  return r;
}
#endif

#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
/**
 * The OpenVDB peer, in its own process: build the OFB of `mesh` at `resolution`
 * (untimed), time OpenVDB storing its samples, print one line "peer" and the
 * results.
 */
int RunPeer(const std::string& mesh, int resolution, int repetitions, int nThreads)
{
  vtkSmartPointer<vtkPolyData> polyData = vtkofbtest::ReadMeshFile(MeshPath(mesh));
  if (!polyData)
  {
    return 1;
  }
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(polyData);
  sampler->SetResolution(resolution);
  // The geometry and the default arrays only, as the peer stores: not the cell arrays
  // that a mesh reader adds (the OBJ reader's GroupIds).
  sampler->PassCellArraysOff();
  sampler->Update();
  vtkOFB* ofb = sampler->GetOutput();
  const SamplePayload payload = ExtractSamples(ofb);
  std::vector<double> t1, tn;
  VDBResult result;
  for (int r = -1; r < repetitions; ++r)
  {
    result = BuildVDB(payload, ofb, 1);
    const VDBResult parallel = BuildVDB(payload, ofb, nThreads);
    if (r >= 0)
    {
      t1.push_back(result.Seconds);
      tn.push_back(parallel.Seconds);
    }
  }
  const Timing one = Summarize(t1), many = Summarize(tn);
  std::printf("peer %.9g %.9g %.9g %.9g %.17g %llu\n",
    one.Best,
    one.Median,
    many.Best,
    many.Median,
    result.Bytes,
    static_cast<unsigned long long>(result.Voxels));
  return 0;
}
#endif

/// One row of the results.
struct Row
{
  std::string Mesh;
  int Resolution = 0;
  vtkIdType Samples = 0;
  Timing OFB;
  double First = 0.0; // seconds of the first build of a new sampler (fresh memory)
  double BytesPerSample = 0.0;
  double OFBBytes = 0.0;
  bool HasVDB = false;
  Timing VDB1, VDBN;
  double VDBBytes = 0.0;
  uint64_t VDBVoxels = 0;
};

#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
/// `text` quoted for the shell.
std::string Quoted(const std::string& text)
{
  std::string quoted = "'";
  for (const char c : text)
  {
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return quoted + "'";
}

/// Run the OpenVDB peer of `row` in a process of its own; false if it fails.
bool RunPeerProcess(const std::string& self, int repetitions, int nThreads, Row& row)
{
  const std::string command = Quoted(self) + " --openvdb-peer " + Quoted(row.Mesh) + " " +
    std::to_string(row.Resolution) + " --repetitions " + std::to_string(repetitions) +
    " --threads " + std::to_string(nThreads);
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    return false;
  }
  char line[512];
  bool found = false;
  while (std::fgets(line, sizeof(line), pipe))
  {
    unsigned long long voxels = 0;
    if (std::sscanf(line,
          "peer %lf %lf %lf %lf %lf %llu",
          &row.VDB1.Best,
          &row.VDB1.Median,
          &row.VDBN.Best,
          &row.VDBN.Median,
          &row.VDBBytes,
          &voxels) == 6)
    {
      row.VDBVoxels = voxels;
      found = true;
    }
  }
  return pclose(pipe) == 0 && found;
}
#endif

/// The OFB build of `mesh` (named `name`) at `resolution`: one untimed warm-up, then
/// options.Repetitions timed rebuilds; with `self`, its OpenVDB peer in a process of its
/// own. False after a message.
bool MeasureRow(const std::string& name,
  vtkPolyData* mesh,
  int resolution,
  const Options& options,
  const std::string& self,
  int nThreads,
  Row& row)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetResolution(resolution);
  // The geometry and the default arrays only, as the peer stores: not the cell arrays
  // that a mesh reader adds (the OBJ reader's GroupIds).
  sampler->PassCellArraysOff();
  std::vector<double> times;
  double first = 0.0;
  for (int r = -1; r < options.Repetitions; ++r)
  {
    sampler->Modified();
    const double start = Now();
    sampler->Update();
    const double seconds = Now() - start;
    if (r >= 0)
    {
      times.push_back(seconds);
    }
    else
    {
      first = seconds;
    }
  }
  vtkOFB* ofb = sampler->GetOutput();
  if (ofb->GetNumberOfSamples() == 0)
  {
    std::fprintf(stderr, "%s at %d: the build failed\n", name.c_str(), resolution);
    return false;
  }
  row.Mesh = name;
  row.Resolution = resolution;
  row.Samples = ofb->GetNumberOfSamples();
  row.OFB = Summarize(times);
  row.First = first;
  row.BytesPerSample = ofb->GetBytesPerSample();
  row.OFBBytes = 1024.0 * ofb->GetActualMemorySize();
#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
  if (!self.empty())
  {
    sampler->RemoveAllInputs(); // its memory back before the peer runs
    ofb->Initialize();
    row.HasVDB = RunPeerProcess(self, options.Repetitions, nThreads, row);
    if (!row.HasVDB)
    {
      std::fprintf(stderr, "%s at %d: the OpenVDB peer failed\n", name.c_str(), resolution);
      return false;
    }
  }
#else
  (void)self;
  (void)nThreads;
#endif
  return true;
}

/// Table 1: the OFB build, its rates and its output bandwidth against `bw`'s triad.
void PrintBuildTable(const std::vector<Row>& rows, const Bandwidth& bw, int nThreads)
{
  std::printf(
    "\nOFB build (vtkOFBSampler::Update, CPU backend, %d threads); MB = 10^6 bytes\n", nThreads);
  std::printf("%-8s %5s %11s %9s %9s %10s %10s %9s %10s %7s %8s %9s %7s\n",
    "mesh",
    "res",
    "samples",
    "best ms",
    "med ms",
    "Msmp/s",
    "Msmp/s",
    "first ms",
    "Msmp/s",
    "B/smp",
    "MB",
    "out GB/s",
    "% bw");
  std::printf("%-8s %5s %11s %9s %9s %10s %10s %9s %10s %7s %8s %9s %7s\n",
    "",
    "",
    "",
    "",
    "",
    "(best)",
    "(median)",
    "",
    "(first)",
    "",
    "",
    "(best)",
    "triad");
  for (const Row& r : rows)
  {
    const double rate = r.OFBBytes / r.OFB.Best;
    std::printf(
      "%-8s %5d %11lld %9.1f %9.1f %10.1f %10.1f %9.1f %10.1f %7.2f %8.1f %9.2f %6.1f%%\n",
      r.Mesh.c_str(),
      r.Resolution,
      static_cast<long long>(r.Samples),
      1e3 * r.OFB.Best,
      1e3 * r.OFB.Median,
      r.Samples / r.OFB.Best / 1e6,
      r.Samples / r.OFB.Median / 1e6,
      1e3 * r.First,
      r.Samples / r.First / 1e6,
      r.BytesPerSample,
      r.OFBBytes / 1e6,
      rate / 1e9,
      100.0 * rate / bw.Triad);
  }
  std::printf("best, median: rebuilds (Modified + Update), which write over the previous "
              "output's and the sampler's memory;\nfirst: the first build of a new sampler, "
              "into new memory. out GB/s: the OFB's bytes (GetActualMemorySize) / best\n"
              "build time; %% bw: of the measured triad bandwidth %.2f GB/s\n",
    bw.Triad / 1e9);
}

/// Table 2: the OFB against OpenVDB storing the same samples.
void PrintOpenVDBTable(const std::vector<Row>& rows, int nThreads)
{
  std::printf("\nOpenVDB storing the same samples (normals + RGBA); time = best, ratio = "
              "OFB / OpenVDB\n");
  std::printf("%-8s %5s %11s %11s %9s %9s %9s %8s %8s %8s %8s\n",
    "mesh",
    "res",
    "samples",
    "vdb voxels",
    "OFB ms",
    "VDB1 ms",
    ("VDB" + std::to_string(nThreads) + " ms").c_str(),
    "OFB MB",
    "VDB MB",
    "t/VDB1",
    "mem");
  for (const Row& r : rows)
  {
    std::printf("%-8s %5d %11lld %11llu %9.1f %9.1f %9.1f %8.1f %8.1f %8.2f %8.2f\n",
      r.Mesh.c_str(),
      r.Resolution,
      static_cast<long long>(r.Samples),
      static_cast<unsigned long long>(r.VDBVoxels),
      1e3 * r.OFB.Best,
      1e3 * r.VDB1.Best,
      1e3 * r.VDBN.Best,
      r.OFBBytes / 1e6,
      r.VDBBytes / 1e6,
      r.OFB.Best / r.VDB1.Best,
      r.OFBBytes / r.VDBBytes);
  }
  std::printf("VDB1: one thread; VDB%d: %d threads filling their own grids (disjoint leaf "
              "slabs), then merged. "
              "OpenVDB times cover only\nthe insertion of the already computed samples; the "
              "OFB times cover the whole build from the mesh.\nvdb voxels < samples where "
              "two samples fall in one voxel.\n",
    nThreads,
    nThreads);
}

/// The goals at resolution 2048: the build rate, and the memory against OpenVDB's.
void PrintGoals(const std::vector<Row>& rows, int nThreads)
{
  std::printf("\nGoals (this machine, %d threads):\n", nThreads);
  for (const Row& r : rows)
  {
    if (r.Resolution != 2048)
    {
      continue;
    }
    const double rate = r.Samples / r.OFB.Best / 1e6;
    std::printf("  %-8s 2048: %.1f M samples/s (best; median %.1f) -> >= 150 M samples/s %s",
      r.Mesh.c_str(),
      rate,
      r.Samples / r.OFB.Median / 1e6,
      rate >= 150.0 ? "MET" : "NOT MET");
    if (r.HasVDB)
    {
      const double ratio = r.OFBBytes / r.VDBBytes;
      std::printf(
        "; memory OFB/OpenVDB %.2f -> <= 0.5 %s", ratio, ratio <= 0.5 ? "MET" : "NOT MET");
    }
    std::printf("\n");
  }
}

/// The path of this program (for its OpenVDB peer): /proc/self/exe, else argv0.
std::string ThisProgram(const char* argv0)
{
  std::string self = argv0;
#if defined(__unix__)
  char exe[4096];
  const ssize_t length = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
  if (length > 0)
  {
    self.assign(exe, static_cast<size_t>(length));
  }
#endif
  return self;
}

/// The first lines: versions, threads, the OpenVDB peer; whether the peer runs.
bool PrintHeader(const Options& options, int nThreads)
{
  std::printf("ofbBenchmark: VTK %s, SMP backend %s, %d threads (hardware: %u), %d "
              "repetitions after one warm-up\n",
    vtkVersion::GetVTKVersion(),
    vtkSMPTools::GetBackend(),
    nThreads,
    std::thread::hardware_concurrency(),
    options.Repetitions);
#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
  if (options.OpenVDB)
  {
    openvdb::initialize();
    std::printf("OpenVDB %s peer: Vec3SGrid normals + Int32Grid packed RGBA, voxel = OFB cell, "
                "setValue through accessors\n",
      openvdb::getLibraryAbiVersionString());
  }
  return options.OpenVDB;
#else
  std::printf("OpenVDB was not found at configure time: the benchmark runs without the "
              "OpenVDB peer.\n");
  return false;
#endif
}
}

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  Options options;
  if (!ParseOptions(argc, argv, options))
  {
    Usage(argv[0]);
    return 1;
  }
  if (options.Threads > 0)
  {
    vtkSMPTools::Initialize(options.Threads);
  }
  const int nThreads = vtkSMPTools::GetEstimatedNumberOfThreads();
  if (!options.PeerMesh.empty())
  {
#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
    openvdb::initialize();
    return RunPeer(options.PeerMesh, options.PeerResolution, options.Repetitions, nThreads);
#else
    std::fprintf(stderr, "--openvdb-peer: OpenVDB was not found at configure time\n");
    return 1;
#endif
  }
  const bool useVDB = PrintHeader(options, nThreads);
  const std::string self = useVDB ? ThisProgram(argv[0]) : std::string();

  // Memory bandwidth of the machine, measured now (3 arrays of 128 MiB).
  const Bandwidth bw = MeasureBandwidth(nThreads, size_t(16) << 20, 5);
  std::printf("Memory bandwidth (STREAM-like, %d threads, 3 x %.0f MB arrays, best of 5): "
              "copy %.2f GB/s, triad %.2f GB/s\n\n",
    nThreads,
    bw.ArrayBytes / 1e6,
    bw.Copy / 1e9,
    bw.Triad / 1e9);
  std::fflush(stdout);

  std::vector<Row> rows;
  for (const std::string& name : options.Meshes)
  {
    const std::string path = MeshPath(name);
    vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::ReadMeshFile(path);
    if (!mesh)
    {
      std::fprintf(stderr, "cannot read a mesh with polygons from '%s'\n", path.c_str());
      return 1;
    }
    std::printf("%s: %lld points, %lld polygons (%s)\n",
      name.c_str(),
      static_cast<long long>(mesh->GetNumberOfPoints()),
      static_cast<long long>(mesh->GetNumberOfPolys()),
      path.c_str());
    std::fflush(stdout);
    for (const int resolution : options.Resolutions)
    {
      Row row;
      if (!MeasureRow(name, mesh, resolution, options, self, nThreads, row))
      {
        return 1;
      }
      std::printf("  resolution %5d: %lld samples, OFB best %.1f ms, median %.1f ms%s\n",
        resolution,
        static_cast<long long>(row.Samples),
        1e3 * row.OFB.Best,
        1e3 * row.OFB.Median,
        row.HasVDB ? ", OpenVDB done" : "");
      std::fflush(stdout);
      rows.push_back(row);
    }
  }
  PrintBuildTable(rows, bw, nThreads);
  if (useVDB)
  {
    PrintOpenVDBTable(rows, nThreads);
  }
  PrintGoals(rows, nThreads);
  return 0;
}
