// ofbPaintBenchmark: painting speed of vtkOFBPainter against the two things a user
// would otherwise reach for, in the same run and on the same dabs:
//  - an OpenVDB grid pair holding the same payload (packed RGBA in an Int32Grid and
//    normals in a Vec3SGrid) at the OFB's cell size, painted leaf by leaf: the active
//    voxels of the 8^3 leaves that the dab's bounding box meets;
//  - the samples as a point cloud with a vtkStaticPointLocator (build time reported),
//    painted through FindPointsWithinRadius.
// Every peer blends the same Mix colour with the same smooth falloff. The painter also
// records undo and marks the changed ranges; the peers do neither. With 2 threads the
// peers paint their dabs with vtkSMPTools::For without any ordering (overlapping dabs
// race), the painter in its deterministic waves.
// It also times 10,000 simultaneous dabs of radius 2.5 cells (the paper's particle
// footprint) and one stroke of 100 dabs of radius 25 cells with vtkOFBPolyDataMapper's
// incremental upload (a render window: run under xvfb-run on a headless machine).
// Not a test: run it by hand, e.g.
//   xvfb-run -a -s "-screen 0 1280x1024x24" ofbPaintBenchmark [options]
// Options: --mesh FILE (default the Stanford bunny), --resolutions 1024,2048,
// --dabs5 N (default 20000), --dabs25 N (default 2000), --repetitions N (default 3,
// the median is printed), --no-openvdb, --no-render, --lookup MODE (the stroke's display:
// nearest, the default, idw, mipmapped or nearestmipmapped).
#include "ofbBenchmarkOptions.h"
#include "vtkOFBMemoryFloor.h"
#include "vtkOFBReadMesh.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
#include <openvdb/openvdb.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// CPU time of the process (all threads), seconds: less disturbed by other load on a
/// shared machine than the wall clock.
double CPUNow()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double Median(std::vector<double> t)
{
  std::sort(t.begin(), t.end());
  const size_t m = t.size() / 2;
  return t.empty() ? 0.0 : (t.size() % 2 ? t[m] : 0.5 * (t[m - 1] + t[m]));
}

struct Options
{
  std::string Mesh = std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj";
  std::vector<int> Resolutions = { 1024, 2048 };
  int Dabs5 = 20000;
  int Dabs25 = 2000;
  int Repetitions = 3;
  bool OpenVDB = true;
  bool Render = true;
  bool FootprintsOnly = false;                       // only the 10,000 footprints (for profiling)
  int Lookup = vtkOFBPolyDataMapper::LOOKUP_NEAREST; // the stroke's display
};

bool ParseOptions(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--mesh" && hasValue)
    {
      o.Mesh = argv[++i];
    }
    else if (arg == "--resolutions" && hasValue)
    {
      o.Resolutions = ofbbench::ParseIntList(argv[++i]);
    }
    else if (arg == "--dabs5" && hasValue)
    {
      o.Dabs5 = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--dabs25" && hasValue)
    {
      o.Dabs25 = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--repetitions" && hasValue)
    {
      o.Repetitions = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--no-openvdb")
    {
      o.OpenVDB = false;
    }
    else if (arg == "--no-render")
    {
      o.Render = false;
    }
    else if (arg == "--footprints-only")
    {
      o.FootprintsOnly = true;
    }
    else if (arg == "--lookup" && hasValue)
    {
      const std::string mode = argv[++i];
      const char* names[] = { "nearest", "idw", "mipmapped", "nearestmipmapped" };
      const int modes[] = { vtkOFBPolyDataMapper::LOOKUP_NEAREST,
        vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
        vtkOFBPolyDataMapper::LOOKUP_MIPMAPPED,
        vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED };
      o.Lookup = -1;
      for (int m = 0; m < 4; ++m)
      {
        o.Lookup = mode == names[m] ? modes[m] : o.Lookup;
      }
      if (o.Lookup < 0)
      {
        std::cerr << "--lookup: nearest, idw, mipmapped or nearestmipmapped\n";
        return false;
      }
    }
    else
    {
      std::cerr << "usage: ofbPaintBenchmark [--mesh FILE] [--resolutions 1024,2048] "
                   "[--dabs5 20000] [--dabs25 2000] [--repetitions 3] [--no-openvdb] "
                   "[--no-render] [--footprints-only] [--lookup nearest|idw|mipmapped|"
                   "nearestmipmapped (the stroke's display)]\n";
      return false;
    }
  }
  return true;
}

// The peers' blend: Mix of an opaque colour with the smooth falloff (the painter's
// default falloff), as the painter computes it on an opaque sample.
constexpr float BrushColor[3] = { 0.9f, 0.2f, 0.1f };

inline float Smooth(float x)
{
  const float t = 1.0f - x;
  return t * t * (3.0f - 2.0f * t);
}

inline void MixBytes(unsigned char* c, float g)
{
  for (int k = 0; k < 3; ++k)
  {
    const float d = c[k] * (1.0f / 255.0f);
    c[k] = static_cast<unsigned char>((d + g * (BrushColor[k] - d)) * 255.0f + 0.5f);
  }
}

/// Random dab centres on the surface: positions of random samples.
vtkSmartPointer<vtkPoints> RandomCentres(vtkOFB* ofb, int n, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<vtkIdType> pick(0, ofb->GetNumberOfSamples() - 1);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (int i = 0; i < n; ++i)
  {
    double x[3];
    ofb->GetSamplePosition(pick(random), x);
    points->SetPoint(i, x);
  }
  return points;
}

/// Time `paint` (after `reset`) `repetitions` times; the median in seconds (wall
/// clock), and in `cpu` the median CPU time of the process.
double TimeMedian(int repetitions,
  const std::function<void()>& reset,
  const std::function<void()>& paint,
  double* cpu = nullptr)
{
  std::vector<double> t, c;
  for (int r = 0; r < repetitions; ++r)
  {
    reset();
    const double start = Now();
    const double cpuStart = CPUNow();
    paint();
    c.push_back(CPUNow() - cpuStart);
    t.push_back(Now() - start);
  }
  if (cpu)
  {
    *cpu = Median(c);
  }
  return Median(t);
}

/// The point-cloud peer: sample positions, a locator and a copy of the colours.
struct LocatorPeer
{
  vtkNew<vtkPolyData> Cloud;
  vtkNew<vtkStaticPointLocator> Locator;
  std::vector<unsigned char> Colors;
  double BuildSeconds = 0.0;

  void Build(vtkOFB* ofb)
  {
    const vtkIdType n = ofb->GetNumberOfSamples();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      points->SetPoint(i, x);
    }
    this->Cloud->SetPoints(points);
    this->Colors.assign(4 * n, 255);
    const double start = Now();
    this->Locator->SetDataSet(this->Cloud);
    this->Locator->BuildLocator();
    this->BuildSeconds = Now() - start;
  }

  void Paint(vtkPoints* centres, double radius)
  {
    vtkSMPThreadLocalObject<vtkIdList> lists;
    const float* pts = static_cast<const float*>(this->Cloud->GetPoints()->GetVoidPointer(0));
    vtkSMPTools::For(0,
      centres->GetNumberOfPoints(),
      [&](vtkIdType first, vtkIdType last)
      {
        vtkIdList* ids = lists.Local();
        for (vtkIdType d = first; d < last; ++d)
        {
          double c[3];
          centres->GetPoint(d, c);
          this->Locator->FindPointsWithinRadius(radius, c, ids);
          for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
          {
            const vtkIdType i = ids->GetId(k);
            const double dx = pts[3 * i] - c[0], dy = pts[3 * i + 1] - c[1],
                         dz = pts[3 * i + 2] - c[2];
            const float x = static_cast<float>(std::sqrt(dx * dx + dy * dy + dz * dz) / radius);
            MixBytes(this->Colors.data() + 4 * i, Smooth(std::min(1.0f, x)));
          }
        }
      });
  }
};

#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
/// The OpenVDB peer: packed RGBA and normals, voxel centres on the OFB's cell centres.
struct VDBPeer
{
  openvdb::Int32Grid::Ptr Colors;
  openvdb::Vec3SGrid::Ptr Normals;
  openvdb::math::Transform::Ptr Transform;
  double CellSize = 1.0;
  double BuildSeconds = 0.0;

  void Build(vtkOFB* ofb)
  {
    const double start = Now();
    const double s = ofb->GetCellSize();
    const double* o = ofb->GetOrigin();
    this->CellSize = s;
    this->Transform = openvdb::math::Transform::createLinearTransform(s);
    this->Transform->postTranslate(openvdb::Vec3d(o[0] + 0.5 * s, o[1] + 0.5 * s, o[2] + 0.5 * s));
    this->Colors = openvdb::Int32Grid::create(0);
    this->Normals = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    this->Colors->setTransform(this->Transform);
    this->Normals->setTransform(this->Transform);
    auto colors = this->Colors->getAccessor();
    auto normals = this->Normals->getAccessor();
    auto* n = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("Normals"));
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      const openvdb::Coord ijk = this->Transform->worldToIndexCellCentered(openvdb::Vec3d(x));
      colors.setValue(ijk, -1); // opaque white
      normals.setValue(ijk, n ? openvdb::Vec3s(n->GetPointer(3 * i)) : openvdb::Vec3s(0.0f));
    }
    this->BuildSeconds = Now() - start;
  }

  void Reset()
  {
    for (auto leaf = this->Colors->tree().beginLeaf(); leaf; ++leaf)
    {
      for (auto v = leaf->beginValueOn(); v; ++v)
      {
        v.setValue(-1);
      }
    }
  }

  void PaintDab(openvdb::Int32Grid::Accessor& acc, const double c[3], double radius)
  {
    const openvdb::Vec3d ci = this->Transform->worldToIndex(openvdb::Vec3d(c));
    const double ri = radius / this->CellSize;
    const openvdb::Coord lo(static_cast<int>(std::floor(ci.x() - ri)) & ~7,
      static_cast<int>(std::floor(ci.y() - ri)) & ~7,
      static_cast<int>(std::floor(ci.z() - ri)) & ~7);
    const openvdb::Coord hi(static_cast<int>(std::ceil(ci.x() + ri)),
      static_cast<int>(std::ceil(ci.y() + ri)),
      static_cast<int>(std::ceil(ci.z() + ri)));
    for (int x = lo.x(); x <= hi.x(); x += 8)
    {
      for (int y = lo.y(); y <= hi.y(); y += 8)
      {
        for (int z = lo.z(); z <= hi.z(); z += 8)
        {
          auto* leaf = acc.probeLeaf(openvdb::Coord(x, y, z));
          if (!leaf)
          {
            continue;
          }
          for (auto v = leaf->beginValueOn(); v; ++v)
          {
            const openvdb::Coord ijk = v.getCoord();
            const double dx = ijk.x() - ci.x(), dy = ijk.y() - ci.y(), dz = ijk.z() - ci.z();
            const double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 > ri * ri)
            {
              continue;
            }
            int32_t packed = v.getValue();
            MixBytes(reinterpret_cast<unsigned char*>(&packed),
              Smooth(static_cast<float>(std::sqrt(d2) / ri)));
            v.setValue(packed);
          }
        }
      }
    }
  }

  void Paint(vtkPoints* centres, double radius)
  {
    vtkSMPTools::For(0,
      centres->GetNumberOfPoints(),
      [&](vtkIdType first, vtkIdType last)
      {
        auto acc = this->Colors->getAccessor();
        for (vtkIdType d = first; d < last; ++d)
        {
          double c[3];
          centres->GetPoint(d, c);
          this->PaintDab(acc, c, radius);
        }
      });
  }
};
#endif

/// The OFB under test, its painter and a copy of its initial colours.
struct OFBUnderTest
{
  vtkSmartPointer<vtkOFB> OFB;
  vtkNew<vtkOFBPainter> Painter;
  std::vector<unsigned char> Initial;

  void Reset()
  {
    this->Painter->ClearHistory();
    auto* c = vtkUnsignedCharArray::SafeDownCast(this->OFB->GetSampleData()->GetArray("Colors"));
    std::memcpy(c->GetPointer(0), this->Initial.data(), this->Initial.size());
  }
};

/// Dabs per second of the painter and the peers, one radius, 1 and 2 threads.
void CompareThroughput(OFBUnderTest& ofb,
  LocatorPeer& locator,
  void* vdb,
  double radiusCells,
  int count,
  const Options& o)
{
  const double radius = radiusCells * ofb.OFB->GetCellSize();
  vtkSmartPointer<vtkPoints> centres = RandomCentres(ofb.OFB, count, 1234u + count);
  ofb.Painter->GetBrush()->SetRadius(radius);
  for (int threads : { 1, 2 })
  {
    const vtkSMPTools::Config config{ threads };
    double tOFB = 0.0, tLocator = 0.0, tVDB = 0.0, cOFB = 0.0, cLocator = 0.0, cVDB = 0.0;
    vtkSMPTools::LocalScope(config,
      [&]()
      {
        tOFB = TimeMedian(
          o.Repetitions, [&]() { ofb.Reset(); }, [&]() { ofb.Painter->Dabs(centres); }, &cOFB);
        tLocator = TimeMedian(
          o.Repetitions,
          [&]() { std::fill(locator.Colors.begin(), locator.Colors.end(), 255); },
          [&]() { locator.Paint(centres, radius); },
          &cLocator);
#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
        if (vdb)
        {
          auto* peer = static_cast<VDBPeer*>(vdb);
          tVDB = TimeMedian(
            o.Repetitions,
            [&]() { peer->Reset(); },
            [&]() { peer->Paint(centres, radius); },
            &cVDB);
        }
#endif
      });
    std::printf("  radius %4.1f cells, %6d dabs, %d thread%s: OFB %8.0f dabs/s | locator %8.0f "
                "dabs/s (OFB %5.2fx, CPU time %5.2fx)",
      radiusCells,
      count,
      threads,
      threads > 1 ? "s" : " ",
      count / tOFB,
      count / tLocator,
      tLocator / tOFB,
      cLocator / cOFB);
    if (tVDB > 0.0)
    {
      std::printf(" | OpenVDB %8.0f dabs/s (OFB %5.2fx, CPU time %5.2fx)",
        count / tVDB,
        tVDB / tOFB,
        cVDB / cOFB);
    }
    std::printf("\n");
  }
}

/// 10,000 simultaneous dabs of radius 2.5 cells (the paper's particle footprints).
void TimeParticles(OFBUnderTest& ofb, const Options& o)
{
  const int count = 10000;
  vtkSmartPointer<vtkPoints> centres = RandomCentres(ofb.OFB, count, 99u);
  ofb.Painter->GetBrush()->SetRadius(2.5 * ofb.OFB->GetCellSize());
  const vtkofb_bench::FootprintLines lines =
    vtkofb_bench::CountFootprintLines(ofb.OFB, centres, 2.5 * ofb.OFB->GetCellSize());
  std::printf("  per dab: %.1f rows with samples, %.1f samples painted, at least %.0f cache lines "
              "touched (%.0f MB in all)\n",
    lines.Rows,
    lines.Hits,
    lines.Lines,
    count * lines.Lines * 64.0 / 1e6);
  for (int threads : { 1, 2 })
  {
    double t = 0.0, cpu = 0.0;
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads },
      [&]()
      {
        t = TimeMedian(
          std::max(5, o.Repetitions),
          [&]() { ofb.Reset(); },
          [&]() { ofb.Painter->Dabs(centres); },
          &cpu);
      });
    double floor = 0.0;
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads },
      [&]()
      {
        floor = vtkofb_bench::RandomLineFloor(static_cast<size_t>(count * lines.Lines),
          size_t(1024) * ofb.OFB->GetActualMemorySize(),
          std::max(5, o.Repetitions));
      });
    std::printf("  10,000 dabs of radius 2.5 cells, %d thread%s: %.2f ms (CPU time %.2f ms); "
                "touching as many random cache lines alone: %.2f ms (painter %.2fx that floor)\n",
      threads,
      threads > 1 ? "s" : "",
      1e3 * t,
      1e3 * cpu,
      1e3 * floor,
      t / floor);
  }
}

/// One stroke of 100 dabs of radius 25 cells with the mapper's incremental upload.
void TimeStrokeWithUpload(OFBUnderTest& ofb, vtkPolyData* surface, int lookup)
{
  vtkOFB* o = ofb.OFB;
  const double s = o->GetCellSize();
  const double radius = 25.0 * s;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 800);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->SetOFB(o);
  mapper->SetLookupMode(lookup);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  renderer->ResetCamera();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  auto frame = [&]()
  {
    window->Render();
    if (gl)
    {
      gl->WaitForCompletion();
    }
  };
  frame();
  frame();
  if (!mapper->GetLastRenderUsedOFB())
  {
    std::printf("  stroke with upload: the mapper could not use the OFB here; skipped\n");
    return;
  }
  // Each frame after a dab (with its upload) is followed by a frame without change,
  // so both sets see the same load; the medians of the two are compared.
  std::vector<double> still, changed;
  // The path: a line across the surface's bounds, each point snapped to the surface,
  // a quarter radius apart (one dab per point at the default spacing).
  double b[6];
  o->GetBounds(b);
  const double from[3] = { b[0] + 0.3 * (b[1] - b[0]), 0.5 * (b[2] + b[3]), b[5] };
  ofb.Reset();
  ofb.Painter->GetBrush()->SetRadius(radius);
  ofb.Painter->BeginStroke();
  double paint = 0.0;
  vtkIdType uploaded = 0;
  for (int i = 0; i < 100; ++i)
  {
    const double x[3] = { from[0] + 0.25 * radius * i, from[1], from[2] - 0.5 * (b[5] - b[4]) };
    const vtkIdType id = o->FindClosestSample(x, 0.5 * (b[5] - b[4]));
    double p[3];
    if (id < 0 || !o->GetSamplePosition(id, p))
    {
      continue;
    }
    const double t0 = Now();
    ofb.Painter->StrokeTo(p);
    const double t1 = Now();
    frame();
    const double t2 = Now();
    paint += t1 - t0;
    changed.push_back(t2 - t1);
    uploaded += mapper->GetLastUploadedSampleCount();
    frame();
    still.push_back(Now() - t2);
  }
  ofb.Painter->EndStroke();
  const vtkIdType dabs = ofb.Painter->GetStrokeDabs()->GetNumberOfPoints();
  const int frames = static_cast<int>(changed.size());
  if (frames == 0 || dabs == 0)
  {
    std::printf("  stroke with upload: no point of the path on the surface; skipped\n");
    return;
  }
  // The upload's share of a frame (median difference, alternated frames), times the
  // frames, spread over the dabs they carried.
  const double upload = std::max(0.0, Median(changed) - Median(still)) * frames;
  std::printf(
    "  stroke of %lld dabs of radius 25 cells (display: %s): paint %.3f ms/dab, frame with upload "
    "%.2f ms, frame without change %.2f ms (medians of %d alternated frames) -> "
    "upload %.3f ms/dab; paint + upload %.3f ms/dab (%.0f samples uploaded per "
    "frame)\n",
    static_cast<long long>(dabs),
    vtkOFBPolyDataMapper::GetLookupModeAsString(lookup),
    1e3 * paint / dabs,
    1e3 * Median(changed),
    1e3 * Median(still),
    frames,
    1e3 * upload / dabs,
    1e3 * (paint + upload) / dabs,
    static_cast<double>(uploaded) / frames);
}
}

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  Options o;
  if (!ParseOptions(argc, argv, o))
  {
    return 1;
  }
  vtkSmartPointer<vtkPolyData> surface = vtkofbtest::ReadMeshFile(o.Mesh);
  if (!surface)
  {
    std::cerr << "Cannot read " << o.Mesh << "\n";
    return 1;
  }
#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
  if (o.OpenVDB)
  {
    openvdb::initialize();
  }
#else
  o.OpenVDB = false;
#endif
  std::printf("ofbPaintBenchmark: %s, %lld triangles, SMP backend %s, median of %d runs\n",
    o.Mesh.c_str(),
    static_cast<long long>(surface->GetNumberOfPolys()),
    vtkSMPTools::GetBackend(),
    o.Repetitions);
  std::printf("The OFB painter also records undo and marks the changed ranges for the "
              "mapper; the peers do neither. Same dabs, same Mix blend and smooth falloff.\n");
  for (size_t r = 0; r < o.Resolutions.size(); ++r)
  {
    const int resolution = o.Resolutions[r];
    vtkNew<vtkOFBSampler> sampler;
    sampler->SetInputData(surface);
    sampler->SetResolution(resolution);
    sampler->Update();
    OFBUnderTest ofb;
    ofb.OFB = sampler->GetOutput();
    ofb.Painter->SetOFB(ofb.OFB);
    ofb.Painter->GetBrush()->SetColor(BrushColor[0], BrushColor[1], BrushColor[2]);
    ofb.Painter->Dab(ofb.OFB->GetOrigin()); // first use: the painter's flags
    auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb.OFB->GetSampleData()->GetArray("Colors"));
    ofb.Initial.assign(
      colors->GetPointer(0), colors->GetPointer(0) + 4 * colors->GetNumberOfTuples());
    if (o.FootprintsOnly)
    {
      TimeParticles(ofb, o);
      continue;
    }
    LocatorPeer locator;
    locator.Build(ofb.OFB);
    void* vdb = nullptr;
    std::printf("resolution %d: %lld samples; vtkStaticPointLocator build %.0f ms",
      resolution,
      static_cast<long long>(ofb.OFB->GetNumberOfSamples()),
      1e3 * locator.BuildSeconds);
#ifdef VTKOFB_BENCHMARK_HAVE_OPENVDB
    VDBPeer vdbPeer;
    if (o.OpenVDB)
    {
      vdbPeer.Build(ofb.OFB);
      vdb = &vdbPeer;
      std::printf("; OpenVDB grids %llu voxels, built in %.0f ms",
        static_cast<unsigned long long>(vdbPeer.Colors->activeVoxelCount()),
        1e3 * vdbPeer.BuildSeconds);
    }
#endif
    std::printf("\n");
    CompareThroughput(ofb, locator, vdb, 5.0, o.Dabs5, o);
    CompareThroughput(ofb, locator, vdb, 25.0, o.Dabs25, o);
    TimeParticles(ofb, o);
    if (o.Render && r + 1 == o.Resolutions.size())
    {
      TimeStrokeWithUpload(ofb, surface, o.Lookup);
    }
  }
  return 0;
}
