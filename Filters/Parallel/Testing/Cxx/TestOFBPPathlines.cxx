// Distributed pathlines under MPI against one process, in one run: a time series (a
// sphere carrying a rotation whose axis turns with time, reporting TIME_STEPS as a
// reader does) read piece by piece (vtkExtractPolyDataPiece with the ghost levels the
// advector asks for), and vtkOFBPParticleAdvector advancing particles through it, step
// by step and then with one request that skips to the last step (the advector then
// reads every step between, on every process together). The first process also runs
// the same requests on the whole sphere with no controller, gathers every process's
// particles and painted owned samples, and compares them after each request.
//
//   mpirun -np N TestOFBPPathlines [--empty-last]
//
// --empty-last: the last process reads an empty piece of the same time series (its
// reader still reports the time steps); the others share the sphere.
//
// Exit status 0 when every check holds.
#include "vtkCommunicator.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkInformation.h"
#include "vtkMPIController.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBPParticleAdvector.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBPTestSupport.h"
#include "vtkOFBTurningRotationSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace
{
/// Where the sphere's centre is: off the rotation's axis, so that the field's largest
/// speed differs from piece to piece (as the step duration must not).
constexpr double Centre[3] = { 0.35, 0.1, 0.0 };

/// The sphere of radius 0.5 around Centre.
vtkSmartPointer<vtkPolyData> MakeMesh()
{
  vtkSmartPointer<vtkPolyData> mesh = vtkofbtest::MakeSwirlSphere(false);
  vtkNew<vtkPoints> moved;
  moved->DeepCopy(mesh->GetPoints());
  for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
  {
    double x[3];
    moved->GetPoint(i, x);
    moved->SetPoint(i, x[0] + Centre[0], x[1] + Centre[1], x[2] + Centre[2]);
  }
  mesh->SetPoints(moved);
  return mesh;
}

/// The time series, its piece, the piece's OFB and the advector.
struct Pipeline
{
  vtkNew<vtkofbtest::TurningRotationSource> Series;
  vtkNew<vtkExtractPolyDataPiece> Surface;
  vtkNew<vtkExtractPolyDataPiece> Sampled;
  vtkNew<vtkOFBPSampler> Sampler;
  vtkNew<vtkOFBPParticleAdvector> Advector;

  Pipeline(vtkMultiProcessController* controller, vtkPolyData* mesh, vtkPolyData* seeds)
  {
    this->Series->Mesh = mesh;
    this->Series->Omega = 2.0;
    this->Surface->SetInputConnection(this->Series->GetOutputPort());
    this->Sampled->SetInputData(mesh);
    vtkofbtest::SetUpAdvection(controller, this->Sampled, this->Sampler, this->Advector, seeds);
    this->Advector->SetInputConnection(this->Surface->GetOutputPort());
  }
};

/// Particles (id, x, y, z), as rows.
std::vector<double> Particles(vtkOFBPParticleAdvector* advector)
{
  std::vector<double> rows;
  vtkPolyData* particles = advector->GetParticles();
  vtkDataArray* ids = particles->GetPointData()->GetArray("Id");
  for (vtkIdType i = 0; ids && i < particles->GetNumberOfPoints(); ++i)
  {
    double x[3];
    particles->GetPoint(i, x);
    rows.insert(rows.end(), { ids->GetTuple1(i), x[0], x[1], x[2] });
  }
  return rows;
}

/// Compares the gathered rows with one process's on the first process; prints a line.
bool Same(const char* what,
  double time,
  const std::vector<double>& gathered,
  const std::vector<double>& reference,
  size_t width,
  double tolerance)
{
  const auto got = vtkofbtest::SortedRows(gathered, width);
  const auto want = vtkofbtest::SortedRows(reference, width);
  double worst = 0.0;
  size_t keysDiffer = 0;
  for (size_t i = 0; i < std::min(got.size(), want.size()); ++i)
  {
    keysDiffer += got[i][0] != want[i][0];
    for (size_t k = 1; k < width; ++k)
    {
      worst = std::max(worst, std::abs(got[i][k] - want[i][k]));
    }
  }
  // Samples: how many are painted (the default paint is white).
  size_t painted = 0;
  for (const auto& row : want)
  {
    painted += width == 6 && row[3] < 255.0 ? 1 : 0;
  }
  const bool ok = !want.empty() && got.size() == want.size() && keysDiffer == 0 &&
    worst <= tolerance && (width != 6 || time == 0.0 || painted > 0);
  std::printf("t = %.2f, %s: %zu rows (%zu on one process), %zu keys differ, max |diff| %.3g",
    time,
    what,
    got.size(),
    want.size(),
    keysDiffer,
    worst);
  if (width == 6)
  {
    std::printf(", %zu painted", painted);
  }
  std::printf("%s\n", ok ? "" : " FAIL");
  return ok;
}
}

int main(int argc, char* argv[])
{
  vtkSmartPointer<vtkMPIController> controller = vtkofbtest::StartMPI(&argc, &argv);
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  const int pieces =
    vtkofbtest::NumberOfPieces(controller, vtkofbtest::HasFlag(argc, argv, "--empty-last"));
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh();
  vtkSmartPointer<vtkPolyData> seeds = vtkofbtest::MakeSeeds(40, Centre);

  vtkNew<vtkPolyData> none;
  Pipeline distributed(controller, rank < pieces ? mesh.Get() : none.Get(), seeds);
  distributed.Advector->SetNumberOfGhostLevels(2);
  std::unique_ptr<Pipeline> whole;
  if (rank == 0)
  {
    whole.reset(new Pipeline(nullptr, mesh, seeds));
  }
  // Step by step to t = 0.5, one request to t = 2.0 (15 steps skipped), back to 0.3 (a
  // restart there, from the seeds) and on to 0.6.
  const std::vector<double> times = { 0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 2.0, 0.3, 0.6 };
  int ok = 1;
  double cell = 0.0;
  vtkIdType handOffs = 0;
  for (double t : times)
  {
    distributed.Advector->UpdateTimeStep(t, std::min(rank, pieces - 1), pieces, 0);
    handOffs += distributed.Advector->GetNumberOfHandOffs();
    // Every process's outputs at the time asked for, the empty piece's too.
    vtkInformation* info = distributed.Advector->GetParticles()->GetInformation();
    int timed =
      info->Has(vtkDataObject::DATA_TIME_STEP()) && info->Get(vtkDataObject::DATA_TIME_STEP()) == t
      ? 1
      : 0;
    int allTimed = 0;
    controller->AllReduce(&timed, &allTimed, 1, vtkCommunicator::MIN_OP);
    const std::vector<double> particles =
      vtkofbtest::GatherOnFirst(controller, Particles(distributed.Advector));
    const std::vector<double> samples = vtkofbtest::GatherOnFirst(
      controller, vtkofbtest::OwnedColorRows(distributed.Advector->GetOutput()));
    if (rank == 0)
    {
      whole->Advector->UpdateTimeStep(t, 0, 1, 0);
      cell = whole->Sampler->GetOutput()->GetCellSize();
      ok = Same("particles", t, particles, Particles(whole->Advector), 4, 1e-6 * cell) && ok;
      ok = Same("owned samples",
             t,
             samples,
             vtkofbtest::OwnedColorRows(whole->Advector->GetOutput()),
             6,
             1.0) &&
        ok;
      if (!allTimed)
      {
        std::printf("t = %.2f: a process's particles are not at that time FAIL\n", t);
        ok = 0;
      }
    }
  }
  if (rank == 0)
  {
    // On more than one process the particles crossed piece borders (the rotation moves
    // every seed off the poles by 2 radians and more).
    std::printf(
      "%d processes: %lld hand-offs over the run\n", size, static_cast<long long>(handOffs));
    ok = ok && (size == 1 || handOffs > 0) && cell > 0.0;
    std::printf("%s\n", ok ? "PASS" : "FAIL");
  }
  return vtkofbtest::FinishFirst(controller, ok);
}
