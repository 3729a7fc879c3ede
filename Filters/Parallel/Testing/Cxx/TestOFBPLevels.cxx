// The LICs of vtkOFBLICPyramid's coarser levels under MPI against one process: every
// process samples its piece of a sphere (vtkExtractPolyDataPiece with one ghost level,
// shallower than the coarse levels' streamlines), builds the levels from its ghosted piece
// and computes their LICs together (vtkOFBPLIC levels, DeferLevelLICs); the first process
// builds the pyramid of the whole sphere with no controller, gathers the owned samples of
// every level and compares their LIC.
//
//   mpirun -np N TestOFBPLevels [--empty-last] [--bad-input] [--resolution R]
//
// Runs the levels' LICs with the samples exchanged (LevelGhostSamples EXCHANGE, the
// default), all-gathered (GATHER), and, as the control, with the input's ghost samples
// (INPUT), which must differ near the piece borders on more than one piece. Prints per
// level the samples, what each process sent and received, and the times.
// --empty-last: the last process has an empty piece (the others share the sphere).
// --bad-input: no process has samples (a resolution out of range): the levels' LICs run
// on empty OFBs on every process, with an exchange, and none waits for another.
// --resolution R: level 0's resolution (default 96), for measurements.
// Exit status 0 when every check holds, on every process.
#include "vtkExtractPolyDataPiece.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBPLIC.h"
#include "vtkOFBPLICPyramid.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBPTestSupport.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{
int Resolution = 96; // --resolution N
constexpr int GhostLevels = 1;
constexpr int Steps = 10;
constexpr int NumberOfLevels = 4; // level 0 and three coarser ones (48, 24 and 12 cells)
constexpr int Fields = 9;         // cell, depth, LIC, field (3), normal (3)
constexpr int Traffic = 5;        // per level and process: see Gathered

/// The LIC settings of every run: `cached` the fast LIC.
void Configure(vtkOFBLIC* lic, bool cached)
{
  lic->SetNumberOfSteps(Steps);
  lic->SetCacheStreamlines(cached);
}

/// A pyramid of LICs: this process's piece, or the whole sphere with no controller.
struct Pyramid
{
  vtkNew<vtkExtractPolyDataPiece> Extract;
  vtkNew<vtkOFBPSampler> Sampler;
  vtkNew<vtkOFBPLIC> LIC;
  vtkNew<vtkOFBPLICPyramid> Levels;
  double Time = 0.0;

  Pyramid(vtkMultiProcessController* controller, int mode, bool cached, int resolution)
  {
    this->Sampler->SetController(controller);
    this->Sampler->SetResolution(resolution);
    this->LIC->SetController(controller);
    this->LIC->SetNumberOfGhostLevels(GhostLevels);
    this->LIC->SetLevelGhostSamples(mode);
    this->LIC->SetInputConnection(this->Sampler->GetOutputPort());
    Configure(this->LIC, cached);
    this->Levels->SetController(controller);
    this->Levels->SetLIC(this->LIC);
    this->Levels->SetMaximumNumberOfLevels(NumberOfLevels);
    this->Levels->SetFilterCacheSize(0);
    this->Levels->SetDeferLevelLICs(controller != nullptr);
  }

  /// Update on every process together: level 0, the levels, then their LICs.
  void Update(vtkMultiProcessController* controller, int piece, int pieces)
  {
    this->LIC->UpdatePiece(piece, pieces, 0);
    vtkOFB* ofb = this->LIC->GetOutput();
    auto* surface = vtkPolyData::SafeDownCast(this->Sampler->GetInputDataObject(0, 0));
    int local[2] = { 0, 0 };
    if (ofb->GetNumberOfSamples() > 0 && surface)
    {
      this->Levels->SetInputOFB(ofb);
      this->Levels->SetSurface(surface);
      this->Levels->SetLevelSurface(surface);
      if (this->Levels->UpdateLevels())
      {
        local[0] = this->Levels->GetLevelLICsPending() ? 1 : 0;
        local[1] = this->Levels->GetNumberOfLevels();
      }
    }
    if (!controller)
    {
      return;
    }
    int global[2] = { 0, 0 };
    controller->AllReduce(local, global, 2, vtkCommunicator::MAX_OP);
    const double start = vtkTimerLog::GetUniversalTime();
    if (global[0])
    {
      this->Levels->ComputeLevelLICs(global[1]);
    }
    this->Time = vtkTimerLog::GetUniversalTime() - start;
  }

  /// The owned samples of level k (cell, depth, LIC), in the order of their cells.
  std::vector<double> Owned(int k) const
  {
    std::vector<double> out;
    vtkOFB* level = k < this->Levels->GetNumberOfLevels() ? this->Levels->GetLevel(k) : nullptr;
    vtkDataArray* lic = level ? level->GetSampleData()->GetArray("LIC") : nullptr;
    vtkDataArray* field = level ? level->GetSampleData()->GetArray("Field") : nullptr;
    vtkDataArray* normals =
      level ? level->GetSampleData()->GetArray(vtkOFB::NormalsArrayName()) : nullptr;
    if (!lic || !field || !normals)
    {
      return out;
    }
    vtkofbtest::ForEachOwnedSample(level,
      [&](vtkIdType c, vtkIdType i, float depth)
      {
        const double* f = field->GetTuple3(i);
        const double row[6] = {
          static_cast<double>(c), depth, lic->GetTuple1(i), f[0], f[1], f[2]
        };
        out.insert(out.end(), row, row + 6);
        const double* nrm = normals->GetTuple3(i);
        out.insert(out.end(), nrm, nrm + 3);
      });
    return out;
  }
};

/// Rows sorted by cell, then depth.
std::vector<double> Sorted(const std::vector<double>& rows)
{
  const size_t n = rows.size() / Fields;
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i)
  {
    order[i] = i;
  }
  std::stable_sort(order.begin(),
    order.end(),
    [&](size_t a, size_t b)
    {
      return rows[a * Fields] != rows[b * Fields] ? rows[a * Fields] < rows[b * Fields]
                                                  : rows[a * Fields + 1] < rows[b * Fields + 1];
    });
  std::vector<double> out;
  for (size_t i : order)
  {
    out.insert(out.end(), rows.begin() + i * Fields, rows.begin() + (i + 1) * Fields);
  }
  return out;
}

/// What the pieces' owned samples of a level differ by from one process's.
struct Difference
{
  size_t Samples = 0;
  size_t Reference = 0;
  size_t Placement = 0; // samples whose cell or depth differs
  size_t Off = 0;       // |LIC difference| > 1e-3
  double Max = 0.0;
  double Mean = 0.0;
  double Field = 0.0;  // the largest difference of a component of the field
  double Normal = 0.0; // and of the normals
};

Difference Compare(const std::vector<double>& pieces, const std::vector<double>& whole)
{
  Difference d;
  const std::vector<double> p = Sorted(pieces);
  const std::vector<double> w = Sorted(whole);
  d.Samples = p.size() / Fields;
  d.Reference = w.size() / Fields;
  const size_t n = std::min(d.Samples, d.Reference);
  for (size_t i = 0; i < n; ++i)
  {
    const double* a = p.data() + i * Fields;
    const double* b = w.data() + i * Fields;
    d.Placement += a[0] != b[0] || std::abs(a[1] - b[1]) > 1e-6;
    const double diff = std::abs(a[2] - b[2]);
    d.Max = std::max(d.Max, diff);
    d.Mean += diff;
    d.Off += diff > 1e-3;
    for (int c = 0; c < 3; ++c)
    {
      d.Field = std::max(d.Field, std::abs(a[3 + c] - b[3 + c]));
      d.Normal = std::max(d.Normal, std::abs(a[6 + c] - b[6 + c]));
    }
  }
  d.Mean = n > 0 ? d.Mean / n : 0.0;
  return d;
}

const char* ModeName(int mode)
{
  return mode == vtkOFBPLIC::GHOST_SAMPLES_INPUT ? "input ghosts"
    : mode == vtkOFBPLIC::GHOST_SAMPLES_EXCHANGE ? "exchange"
                                                 : "all-gather";
}

/// What every process has after the levels' LICs, on the first process.
struct Gathered
{
  std::vector<double> Filters;   // per process: bytes sent to filter again, seconds, levels
  std::vector<double> Means;     // per process: whether it has the shared mean, the mean
  std::vector<double> LevelZero; // the owned samples of level 0
  std::vector<std::vector<double>> Levels; // the owned samples of each coarser level
  // Per level and process (Traffic values): sent, received, exchange s, LIC s, recomputed.
  std::vector<double> Traffic;
};

Gathered Gather(vtkMultiProcessController* controller, const Pyramid& distributed)
{
  Gathered g;
  vtkOFBPLICPyramid* levels = distributed.Levels;
  const double filter[3] = { static_cast<double>(levels->GetLastFilterSentBytes()),
    levels->GetLastRefilterTime(),
    static_cast<double>(levels->GetLastRefilteredLevels()) };
  g.Filters = vtkofbtest::GatherOnFirst(controller, { filter, filter + 3 });
  double mean = -1.0;
  const double row[2] = { levels->GetSharedMean("LIC", mean) ? 1.0 : 0.0, mean };
  g.Means = vtkofbtest::GatherOnFirst(controller, { row, row + 2 });
  g.LevelZero = vtkofbtest::GatherOnFirst(controller, distributed.Owned(0));
  g.Levels.resize(NumberOfLevels);
  for (int k = 1; k < NumberOfLevels; ++k)
  {
    g.Levels[k] = vtkofbtest::GatherOnFirst(controller, distributed.Owned(k));
    auto* lic = vtkOFBPLIC::SafeDownCast(levels->GetLevelLIC(k));
    const double t[Traffic] = { lic ? static_cast<double>(lic->GetLastSentBytes()) : 0.0,
      lic ? static_cast<double>(lic->GetLastReceivedBytes()) : 0.0,
      lic ? lic->GetLastExchangeTime() : 0.0,
      lic ? lic->GetLastExecutionTime() / 1000.0 : 0.0,
      lic ? static_cast<double>(lic->GetLastRecomputed()) : 0.0 };
    std::vector<double> all = vtkofbtest::GatherOnFirst(controller, { t, t + Traffic });
    g.Traffic.insert(g.Traffic.end(), all.begin(), all.end());
  }
  return g;
}

/// Every process with a piece has the shared mean of level 0's LIC: that of all owned
/// samples. (A process whose piece is empty has no level 0, nor a mean: it draws nothing.)
bool CheckMean(const Gathered& g, int pieces)
{
  double sum = 0.0;
  for (size_t i = 2; i < g.LevelZero.size(); i += Fields)
  {
    sum += std::min(1.0, std::max(0.0, g.LevelZero[i]));
  }
  const double expected = g.LevelZero.empty() ? 0.5 : sum / (g.LevelZero.size() / Fields);
  bool ok = true;
  for (int r = 0; r < pieces; ++r)
  {
    if (g.Means[2 * r] != 1.0 || std::abs(g.Means[2 * r + 1] - expected) > 1e-9)
    {
      std::printf("FAIL process %d's shared mean of level 0's LIC: %s %.9f, the owned samples' "
                  "%.9f\n",
        r,
        g.Means[2 * r] == 1.0 ? "" : "none,",
        g.Means[2 * r + 1],
        expected);
      ok = false;
    }
  }
  return ok;
}

/// The gathered levels against one process's (`whole`), printed; false where one differs.
bool CheckLevels(const Gathered& g, const Pyramid& whole, int size, int mode, bool cached)
{
  bool ok = true;
  size_t off = 0;
  for (int k = 1; k < NumberOfLevels; ++k)
  {
    const Difference d = Compare(g.Levels[k], whole.Owned(k));
    double t[Traffic] = { 0, 0, 0, 0, 0 }; // the most of any process
    for (int r = 0; r < size; ++r)
    {
      for (int c = 0; c < Traffic; ++c)
      {
        t[c] = std::max(t[c], g.Traffic[Traffic * (size * (k - 1) + r) + c]);
      }
    }
    std::printf("  level %d: %zu owned samples (one process %zu), placement differs at %zu, "
                "field %.2g, normals %.2g, LIC max |diff| %.3g, mean %.3g, %zu > 1e-3; most sent "
                "%.0f B, received %.0f B, exchange %.4f s, LIC %.4f s (slowest process)\n",
      k,
      d.Samples,
      d.Reference,
      d.Placement,
      d.Field,
      d.Normal,
      d.Max,
      d.Mean,
      d.Off,
      t[0],
      t[1],
      t[2],
      t[3]);
    ok = ok && d.Samples == d.Reference && d.Reference > 0 && d.Placement == 0;
    off += d.Off;
    // The plain LIC, and any LIC all-gathered: one process's values. The fast LIC
    // exchanged: which sample seeds a streamline depends on the samples of its tile (64
    // cells a side), which the exchange gives only around the owned samples: the values
    // agree statistically (a mean difference of at most 0.005; the input's ghosts give
    // 0.036 to 0.19 here).
    const bool plain = !cached || mode == vtkOFBPLIC::GHOST_SAMPLES_GATHER;
    if (mode != vtkOFBPLIC::GHOST_SAMPLES_INPUT &&
      (plain ? d.Off > 0 || d.Max > 1e-4 : d.Mean > 0.005))
    {
      ok = false;
    }
  }
  if (mode == vtkOFBPLIC::GHOST_SAMPLES_INPUT && g.Levels[1].size() > 0 && off == 0 && size > 1)
  {
    std::printf("FAIL with the input's ghost samples the levels' LICs equal one process's: "
                "the comparison does not see the piece borders\n");
    ok = false;
  }
  return ok;
}

/// One mode on every process; on the first process the comparison with one process. With
/// the plain LIC exchanged, a second computation with another noise seed: the levels'
/// LICs again, without filtering the levels again (only the LIC changed).
bool RunMode(vtkMultiProcessController* controller,
  vtkPolyData* mesh,
  int pieces,
  int mode,
  bool cached)
{
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  vtkNew<vtkPolyData> none;
  Pyramid distributed(controller, mode, cached, Resolution);
  Pyramid whole(nullptr, mode, cached, Resolution);
  whole.Sampler->SetInputData(mesh);
  if (rank < pieces)
  {
    distributed.Extract->SetInputData(mesh);
    distributed.Sampler->SetInputConnection(distributed.Extract->GetOutputPort());
  }
  else
  {
    distributed.Sampler->SetInputData(none);
  }
  const bool again = mode == vtkOFBPLIC::GHOST_SAMPLES_EXCHANGE && !cached;
  bool ok = true;
  for (int pass = 0; pass < (again ? 2 : 1); ++pass)
  {
    distributed.LIC->SetNoiseGeneratorSeed(pass == 0 ? 1 : 7);
    whole.LIC->SetNoiseGeneratorSeed(pass == 0 ? 1 : 7);
    distributed.Update(controller, std::min(rank, pieces - 1), pieces);
    const Gathered g = Gather(controller, distributed);
    if (rank != 0)
    {
      continue;
    }
    whole.Update(nullptr, 0, 1);
    double filterSent = 0.0, filterTime = 0.0;
    for (int r = 0; r < size; ++r)
    {
      filterSent = std::max(filterSent, g.Filters[3 * r]);
      filterTime = std::max(filterTime, g.Filters[3 * r + 1]);
      // Every level filtered again at the first computation, none at the second.
      const double expected = r >= pieces ? 0.0 : pass == 0 ? NumberOfLevels - 1.0 : 0.0;
      if (size > 1 && g.Filters[3 * r + 2] != expected)
      {
        std::printf("FAIL process %d filtered %.0f levels again (expected %.0f)\n",
          r,
          g.Filters[3 * r + 2],
          expected);
        ok = false;
      }
    }
    std::printf("%s, %s LIC%s, %d processes (%d pieces), resolution %d, levels' LICs %.3f s; "
                "filtering again: most sent %.0f B, %.4f s:\n",
      ModeName(mode),
      cached ? "fast" : "plain",
      pass == 0 ? "" : " (another noise seed)",
      size,
      pieces,
      Resolution,
      distributed.Time,
      filterSent,
      filterTime);
    ok = CheckMean(g, pieces) && ok;
    ok = CheckLevels(g, whole, size, mode, cached) && ok;
    // Only the LIC changed: the levels' LICs keep their exchanged samples (nothing sent)
    // and what they prepared from them (no structure or samples recomputed).
    for (size_t i = 0; pass == 1 && size > 1 && i < g.Traffic.size(); i += Traffic)
    {
      const int recomputed = static_cast<int>(g.Traffic[i + 4]);
      if (g.Traffic[i] != 0.0 ||
        (recomputed & (vtkOFBLIC::RECOMPUTED_STRUCTURE | vtkOFBLIC::RECOMPUTED_SAMPLES)))
      {
        std::printf("FAIL a level's LIC exchanged again (%.0f B) or prepared its samples "
                    "again (%d)\n",
          g.Traffic[i],
          recomputed);
        ok = false;
      }
    }
  }
  if (rank == 0)
  {
    std::printf("%s\n", ok ? "  ok" : "  FAIL");
  }
  return ok;
}

/// --bad-input: no process has samples; the levels' LICs (an exchange each) run on empty
/// OFBs on every process and output empty OFBs, without a hang.
bool RunBadInput(vtkMultiProcessController* controller, vtkPolyData* mesh, int pieces)
{
  const int rank = controller->GetLocalProcessId();
  vtkNew<vtkPolyData> none;
  Pyramid distributed(controller, vtkOFBPLIC::GHOST_SAMPLES_EXCHANGE, false, 2);
  if (rank < pieces)
  {
    distributed.Extract->SetInputData(mesh);
    distributed.Sampler->SetInputConnection(distributed.Extract->GetOutputPort());
  }
  else
  {
    distributed.Sampler->SetInputData(none);
  }
  distributed.Update(controller, std::min(rank, pieces - 1), pieces);
  // Levels that no process has, computed anyway.
  distributed.Levels->ComputeLevelLICs(NumberOfLevels);
  bool ok = distributed.LIC->GetOutput()->GetNumberOfSamples() == 0;
  for (int k = 1; k < NumberOfLevels; ++k)
  {
    vtkOFBLIC* lic = distributed.Levels->GetLevelLIC(k);
    ok = ok && lic && vtkOFB::SafeDownCast(lic->GetOutputDataObject(0)) &&
      vtkOFB::SafeDownCast(lic->GetOutputDataObject(0))->GetNumberOfSamples() == 0;
  }
  std::printf("rank %d: no samples anywhere, %d levels' LICs on empty OFBs%s\n",
    rank,
    NumberOfLevels - 1,
    ok ? "" : " FAIL");
  return ok;
}
}

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkMPIController> controller = vtkofbtest::StartMPI(&argc, &argv);
  const int pieces =
    vtkofbtest::NumberOfPieces(controller, vtkofbtest::HasFlag(argc, argv, "--empty-last"));
  vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::MakeSwirlSphere(true);
  if (vtkofbtest::HasFlag(argc, argv, "--bad-input"))
  {
    return vtkofbtest::FinishAll(controller, RunBadInput(controller, mesh, pieces));
  }
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--resolution"))
    {
      Resolution = std::max(16, std::atoi(argv[i + 1]));
    }
  }
  bool ok = true;
  for (int mode : { vtkOFBPLIC::GHOST_SAMPLES_EXCHANGE,
         vtkOFBPLIC::GHOST_SAMPLES_GATHER,
         vtkOFBPLIC::GHOST_SAMPLES_INPUT })
  {
    ok = RunMode(controller, mesh, pieces, mode, false) && ok;
  }
  ok = RunMode(controller, mesh, pieces, vtkOFBPLIC::GHOST_SAMPLES_EXCHANGE, true) && ok;
  ok = RunMode(controller, mesh, pieces, vtkOFBPLIC::GHOST_SAMPLES_GATHER, true) && ok;
  return vtkofbtest::FinishAll(controller, ok);
}
