// Distributed particles under MPI against one process, in one run: every process holds
// its piece of a sphere (vtkExtractPolyDataPiece, with the ghost levels the advector asks
// for) and of its OFB (vtkOFBPSampler), and vtkOFBPParticleAdvector advances the
// particles on their owners, handing them over at piece borders. The first process also
// advances them on the whole sphere with no controller, gathers every process's
// particles, trails and owned samples, and compares.
//
//   mpirun -np N TestOFBPParticles [--empty-last] [--bad-input] [--border]
//
// --empty-last: the last process has an empty piece (the others share the sphere).
// --border: the seeds are where one step (of 4 cells) ends on the points shared by two
// pieces (found by a step backwards from those points), and the advector asks for 1
// ghost level only: the particles reach the piece borders at the end of their first
// step, and a step goes beyond one ring of ghost triangles near the poles, so the
// advector must ask for more itself (on more than one process).
// --bad-input: a Lifetime (reseeds), then no seeds: every process reports the error and
// outputs no particles, and none waits for another.
//
// Exit status 0 when every check holds, on every process.
#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMPIController.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBPParticleAdvector.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBPTestSupport.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <vector>

namespace
{
constexpr int Steps = 60;
/// --border: the step (cells), beyond one ring of ghost triangles near the poles.
constexpr double BorderStep = 4.0;

/// Particles (id, x, y, z, trail length) and owned samples (cell, depth, r, g, b, a).
struct Result
{
  std::vector<double> Particles;
  std::vector<double> Samples;
};

Result Collect(vtkOFBPParticleAdvector* advector)
{
  Result result;
  vtkPolyData* particles = vtkPolyData::SafeDownCast(advector->GetOutputDataObject(1));
  vtkPolyData* trails = vtkPolyData::SafeDownCast(advector->GetOutputDataObject(2));
  std::map<vtkIdType, vtkIdType> trailLength;
  vtkDataArray* trailIds = trails->GetCellData()->GetArray("Id");
  for (vtkIdType c = 0; trailIds && c < trails->GetNumberOfCells(); ++c)
  {
    trailLength[static_cast<vtkIdType>(trailIds->GetTuple1(c))] =
      trails->GetCell(c)->GetNumberOfPoints();
  }
  vtkDataArray* ids = particles->GetPointData()->GetArray("Id");
  for (vtkIdType i = 0; ids && i < particles->GetNumberOfPoints(); ++i)
  {
    double x[3];
    particles->GetPoint(i, x);
    const auto id = static_cast<vtkIdType>(ids->GetTuple1(i));
    const double row[5] = { static_cast<double>(id),
      x[0],
      x[1],
      x[2],
      static_cast<double>(trailLength.count(id) ? trailLength[id] : 0) };
    result.Particles.insert(result.Particles.end(), row, row + 5);
  }
  result.Samples =
    vtkofbtest::OwnedColorRows(vtkOFB::SafeDownCast(advector->GetOutputDataObject(0)));
  return result;
}

/// A pipeline: the surface piece, its OFB piece and the advector.
struct Pipeline
{
  vtkNew<vtkExtractPolyDataPiece> Surface;
  vtkNew<vtkExtractPolyDataPiece> Sampled;
  vtkNew<vtkOFBPSampler> Sampler;
  vtkNew<vtkOFBPParticleAdvector> Advector;

  Pipeline(vtkMultiProcessController* controller, vtkPolyData* mesh, vtkPolyData* seeds)
  {
    this->Surface->SetInputData(mesh);
    this->Sampled->SetInputData(mesh);
    vtkofbtest::SetUpAdvection(controller, this->Sampled, this->Sampler, this->Advector, seeds);
    this->Advector->SetInputConnection(this->Surface->GetOutputPort());
    this->Advector->SetTrailLength(8);
  }
};
}

/// The points of `mesh` shared by two or more of its `pieces` (vtkExtractPolyDataPiece).
vtkSmartPointer<vtkPolyData> BorderPoints(vtkPolyData* mesh, int pieces)
{
  std::map<std::array<double, 3>, unsigned> owners;
  for (int piece = 0; piece < pieces; ++piece)
  {
    vtkNew<vtkExtractPolyDataPiece> extract;
    extract->SetInputData(mesh);
    extract->UpdatePiece(piece, pieces, 0);
    vtkPolyData* part = extract->GetOutput();
    for (vtkIdType c = 0; c < part->GetNumberOfCells(); ++c)
    {
      vtkCell* cell = part->GetCell(c);
      for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k)
      {
        std::array<double, 3> x;
        part->GetPoint(cell->GetPointId(k), x.data());
        owners[x] |= 1u << piece;
      }
    }
  }
  vtkNew<vtkPoints> points;
  for (const auto& entry : owners)
  {
    if (entry.second & (entry.second - 1)) // two bits or more
    {
      points->InsertNextPoint(entry.first.data());
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  return result;
}

/// --bad-input: settings that distributed particles refuse, and an empty piece.
bool RunBadInput(vtkMultiProcessController* controller, vtkPolyData* mesh, vtkPolyData* seeds)
{
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  bool ok = true;
  for (int bad = 0; bad < 2; ++bad)
  {
    Pipeline pipeline(controller, mesh, seeds);
    const char* what = "a Lifetime";
    if (bad == 0)
    {
      pipeline.Advector->SetLifetime(5);
    }
    else
    {
      what = "no seeds";
      pipeline.Advector->SetSeeds(nullptr);
    }
    pipeline.Advector->UpdateTimeStep(5, rank, size, 0);
    const vtkIdType particles =
      vtkPolyData::SafeDownCast(pipeline.Advector->GetOutputDataObject(1))->GetNumberOfPoints();
    // One process has no reason to refuse: it advances its particles as ever.
    const bool expected = size == 1 || particles == 0;
    std::printf("rank %d, %s: %lld particles%s\n",
      rank,
      what,
      static_cast<long long>(particles),
      expected ? "" : " FAIL");
    ok = ok && expected;
  }
  return ok;
}

/// Advances `seeds` on the pieces of `mesh` (the last process's piece empty when
/// `pieces` < processes) and, on the first process, on the whole mesh with no
/// controller; compares them there, with steps of `step` cells and `ghostLevels` asked
/// for; `needsMoreGhostLevels`: the advector must have asked for more itself. 1 when
/// every check holds (on the first process; the others return 1).
int Compare(vtkMultiProcessController* controller,
  vtkPolyData* mesh,
  vtkPolyData* seeds,
  int pieces,
  double step,
  int ghostLevels,
  bool needsMoreGhostLevels)
{
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  Pipeline distributed(controller, mesh, seeds);
  distributed.Advector->SetStepSize(step);
  distributed.Advector->SetNumberOfGhostLevels(ghostLevels);
  vtkNew<vtkPolyData> none;
  if (rank >= pieces)
  {
    distributed.Advector->SetInputData(none);
    distributed.Sampler->SetInputData(none);
  }
  distributed.Advector->UpdateTimeStep(Steps, std::min(rank, pieces - 1), pieces, 0);
  const Result mine = Collect(distributed.Advector);
  const std::vector<double> particles = vtkofbtest::GatherOnFirst(controller, mine.Particles);
  const std::vector<double> samples = vtkofbtest::GatherOnFirst(controller, mine.Samples);

  int ok = 1;
  if (rank == 0)
  {
    Pipeline whole(nullptr, mesh, seeds);
    whole.Advector->SetStepSize(step);
    whole.Advector->UpdateTimeStep(Steps, 0, 1, 0);
    const Result reference = Collect(whole.Advector);
    const auto got = vtkofbtest::SortedRows(particles, 5);
    const auto want = vtkofbtest::SortedRows(reference.Particles, 5);
    size_t duplicates = 0;
    for (size_t i = 1; i < got.size(); ++i)
    {
      duplicates += got[i][0] == got[i - 1][0];
    }
    double maxPosition = 0.0;
    size_t idsDiffer = 0, trailsDiffer = 0;
    for (size_t i = 0; i < std::min(got.size(), want.size()); ++i)
    {
      idsDiffer += got[i][0] != want[i][0];
      trailsDiffer += got[i][4] != want[i][4];
      for (int k = 1; k < 4; ++k)
      {
        maxPosition = std::max(maxPosition, std::abs(got[i][k] - want[i][k]));
      }
    }
    const auto gotSamples = vtkofbtest::SortedRows(samples, 6);
    const auto wantSamples = vtkofbtest::SortedRows(reference.Samples, 6);
    size_t colorsDiffer = 0, painted = 0;
    for (size_t i = 0; i < std::min(gotSamples.size(), wantSamples.size()); ++i)
    {
      bool differ = gotSamples[i][0] != wantSamples[i][0];
      for (int k = 2; k < 6; ++k)
      {
        differ = differ || std::abs(gotSamples[i][k] - wantSamples[i][k]) > 1.0;
      }
      colorsDiffer += differ;
      painted += wantSamples[i][3] < 255.0; // the default paint is white
    }
    const double cell = whole.Sampler->GetOutput()->GetCellSize();
    const vtkIdType handOffs = distributed.Advector->GetNumberOfHandOffs();
    const int required = distributed.Advector->GetRequiredGhostLevels();
    std::printf(
      "%d processes, %d steps: %lld hand-offs, %zu particles (%zu on one process), %zu duplicated, "
      "%zu ids differ, end points max |diff| %.2g cells, %zu trail lengths differ; "
      "%zu owned samples (%zu), %zu painted, %zu colours differ by more than 1; ghost levels "
      "asked %d, found needed %d\n",
      size,
      Steps,
      static_cast<long long>(handOffs),
      got.size(),
      want.size(),
      duplicates,
      idsDiffer,
      maxPosition / cell,
      trailsDiffer,
      gotSamples.size(),
      wantSamples.size(),
      painted,
      colorsDiffer,
      ghostLevels,
      required);
    ok = got.size() == want.size() && !want.empty() && duplicates == 0 && idsDiffer == 0 &&
      maxPosition <= 1e-6 * cell && trailsDiffer == 0 && gotSamples.size() == wantSamples.size() &&
      painted > 0 && colorsDiffer == 0 && (size == 1 || handOffs > 0) &&
      (size == 1 || !needsMoreGhostLevels || required > ghostLevels);
    std::printf("%s\n", ok ? "PASS" : "FAIL");
  }
  return ok;
}

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkMPIController> controller = vtkofbtest::StartMPI(&argc, &argv);
  const int rank = controller->GetLocalProcessId();
  vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::MakeSwirlSphere(true);
  vtkSmartPointer<vtkPolyData> seeds = vtkofbtest::MakeSeeds(40);
  const bool border = vtkofbtest::HasFlag(argc, argv, "--border");
  const int pieces =
    vtkofbtest::NumberOfPieces(controller, vtkofbtest::HasFlag(argc, argv, "--empty-last"));
  if (vtkofbtest::HasFlag(argc, argv, "--bad-input"))
  {
    return vtkofbtest::FinishAll(controller, RunBadInput(controller, mesh, seeds));
  }

  int ok = 1;
  if (border)
  {
    // One step backwards from the points that pieces share: the seeds whose first step
    // ends there (to the integrator's error).
    vtkSmartPointer<vtkPolyData> shared = BorderPoints(mesh, pieces);
    Pipeline back(nullptr, mesh, shared);
    back.Advector->SetStepSize(BorderStep);
    back.Advector->SetDirectionToBackward();
    back.Advector->UpdateTimeStep(1, 0, 1, 0);
    vtkPolyData* ends = back.Advector->GetParticles();
    vtkDataArray* ids = ends->GetPointData()->GetArray("Id");
    vtkNew<vtkPoints> starts;
    starts->SetNumberOfPoints(ends->GetNumberOfPoints());
    for (vtkIdType i = 0; ids && i < ends->GetNumberOfPoints(); ++i)
    {
      starts->SetPoint(static_cast<vtkIdType>(ids->GetTuple1(i)), ends->GetPoint(i));
    }
    vtkNew<vtkPolyData> borderSeeds;
    borderSeeds->SetPoints(starts);
    if (rank == 0)
    {
      std::printf("%lld points shared by pieces, %lld seeds a step before them\n",
        static_cast<long long>(shared->GetNumberOfPoints()),
        static_cast<long long>(starts->GetNumberOfPoints()));
    }
    ok = Compare(controller, mesh, borderSeeds, pieces, BorderStep, 1, true);
  }
  else
  {
    ok = Compare(controller, mesh, seeds, pieces, 1.5, 2, false);
  }
  return vtkofbtest::FinishFirst(controller, ok);
}
