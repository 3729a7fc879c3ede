// What the distributed tests share: their sphere with a swirl field and seeds on it, the
// gather of every process's rows on the first process and their sorting, the owned
// samples' colours, and the end of a run whose every process checks something.
#ifndef vtkOFBPTestSupport_h
#define vtkOFBPTestSupport_h

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkMPIController.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBPParticleAdvector.h"
#include "vtkOFBPSampler.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace vtkofbtest
{
/// A sphere of radius 0.5 (48 x 24) with a swirl "Field" (the active vectors) that
/// carries particles and streamlines around and across it; its point normals when
/// `normals`.
inline vtkSmartPointer<vtkPolyData> MakeSwirlSphere(bool normals)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  sphere->SetRadius(0.5);
  sphere->SetGenerateNormals(normals);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(sphere->GetOutput());
  vtkNew<vtkFloatArray> field;
  field->SetName("Field");
  field->SetNumberOfComponents(3);
  field->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const double v[3] = {
      -p[1] + 0.8 * p[2] * p[0], p[0] + 0.8 * p[2] * p[1], -0.8 * (p[0] * p[0] + p[1] * p[1])
    };
    field->SetTuple(i, v);
  }
  mesh->GetPointData()->SetVectors(field);
  return mesh;
}

/// `n` seeds spread over the sphere of radius 0.5 around `centre` (a Fibonacci spiral),
/// the same on every process.
inline vtkSmartPointer<vtkPolyData> MakeSeeds(int n, const double centre[3] = nullptr)
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double* c = centre ? centre : origin;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    const double a = i * vtkMath::Pi() * (3.0 - std::sqrt(5.0));
    points->InsertNextPoint(
      c[0] + 0.5 * r * std::cos(a), c[1] + 0.5 * r * std::sin(a), c[2] + 0.5 * z);
  }
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  seeds->SetPoints(points);
  return seeds;
}

/// The particle tests' set-up: `sampler` (resolution 96) on `sampled` feeds `advector`
/// (RK4 steps of 1.5 cells, footprints of 2 cells) with the OFB its particles paint.
inline void SetUpAdvection(vtkMultiProcessController* controller,
  vtkAlgorithm* sampled,
  vtkOFBPSampler* sampler,
  vtkOFBPParticleAdvector* advector,
  vtkPolyData* seeds)
{
  sampler->SetController(controller);
  sampler->SetResolution(96);
  sampler->SetInputConnection(sampled->GetOutputPort());
  advector->SetController(controller);
  advector->SetOFBConnection(sampler->GetOutputPort());
  advector->SetSeeds(seeds);
  advector->SetIntegrator(vtkOFBParticleAdvector::RK4);
  advector->SetStepSize(1.5);
  advector->SetFootprintRadius(2.0);
}

/// The MPI controller of a test's main, initialized and made the global one.
inline vtkSmartPointer<vtkMPIController> StartMPI(int* argc, char*** argv)
{
  auto controller = vtkSmartPointer<vtkMPIController>::New();
  controller->Initialize(argc, argv);
  vtkMultiProcessController::SetGlobalController(controller);
  return controller;
}

/// Calls visit(cell, sample, depth) for every sample of `ofb` that is not a ghost, cell by
/// cell and in each cell in depth order.
template<typename Visit>
void ForEachOwnedSample(vtkOFB* ofb, Visit&& visit)
{
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    ofb->GetSampleData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  const vtkTypeUInt32* offsets = ofb->GetCellOffsets()->GetPointer(0);
  const float* depths = ofb->GetDepths()->GetPointer(0);
  for (vtkIdType c = 0; c < ofb->GetNumberOfCells(); ++c)
  {
    for (vtkIdType i = offsets[c]; i < offsets[c + 1]; ++i)
    {
      if (!ghosts || !ghosts->GetValue(i))
      {
        visit(c, i, depths[i]);
      }
    }
  }
}

/// The owned samples of `ofb` as rows (cell, depth, r, g, b, a of its colours); none
/// without colours.
inline std::vector<double> OwnedColorRows(vtkOFB* ofb)
{
  std::vector<double> rows;
  vtkDataArray* colors = ofb ? ofb->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()) : nullptr;
  if (!colors || ofb->GetNumberOfSamples() == 0)
  {
    return rows;
  }
  ForEachOwnedSample(ofb,
    [&](vtkIdType c, vtkIdType i, float depth)
    {
      double rgba[4];
      colors->GetTuple(i, rgba);
      rows.insert(rows.end(),
        { static_cast<double>(c), static_cast<double>(depth), rgba[0], rgba[1], rgba[2], rgba[3] });
    });
  return rows;
}

/// Rows of `width` values, sorted.
inline std::vector<std::vector<double>> SortedRows(const std::vector<double>& values, size_t width)
{
  std::vector<std::vector<double>> rows;
  for (size_t i = 0; i + width <= values.size(); i += width)
  {
    rows.emplace_back(values.begin() + i, values.begin() + i + width);
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

/// Whether the command line has `flag`.
inline bool HasFlag(int argc, char* argv[], const char* flag)
{
  return std::any_of(
    argv + 1, argv + argc, [flag](const char* a) { return !std::strcmp(a, flag); });
}

/// The number of pieces: one a process, but the last process's is empty with `emptyLast`.
inline int NumberOfPieces(vtkMultiProcessController* controller, bool emptyLast)
{
  const int size = controller->GetNumberOfProcesses();
  return emptyLast && size > 1 ? size - 1 : size;
}

/// Every process's `local` values, in the order of the processes, on the first process
/// (empty on the others).
inline std::vector<double> GatherOnFirst(vtkMultiProcessController* controller,
  const std::vector<double>& local)
{
  const int size = controller->GetNumberOfProcesses();
  std::vector<vtkIdType> counts(size), offsets(size);
  const vtkIdType count = static_cast<vtkIdType>(local.size());
  controller->Gather(&count, counts.data(), 1, 0);
  vtkIdType total = 0;
  for (int r = 0; r < size; ++r)
  {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<double> all(std::max<vtkIdType>(total, 1));
  const double none = 0.0;
  controller->GatherV(
    local.empty() ? &none : local.data(), all.data(), count, counts.data(), offsets.data(), 0);
  all.resize(controller->GetLocalProcessId() == 0 ? total : 0);
  return all;
}

/// The end of a run in which every process checked something: PASS on the first
/// process when `ok` holds on all, MPI finalized; the exit status (the same everywhere).
inline int FinishAll(vtkMultiProcessController* controller, bool ok)
{
  int mine = ok ? 1 : 0;
  int all = 0;
  controller->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
  if (controller->GetLocalProcessId() == 0)
  {
    std::printf("%s\n", all ? "PASS" : "FAIL");
  }
  controller->Finalize();
  return all ? 0 : 1;
}

/// The end of a run that the first process checked (`ok` there), MPI finalized; the
/// exit status (the same everywhere).
inline int FinishFirst(vtkMultiProcessController* controller, int ok)
{
  controller->Broadcast(&ok, 1, 0);
  controller->Finalize();
  return ok ? 0 : 1;
}
}

#endif
