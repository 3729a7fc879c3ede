// What the distributed tests (TestOFBPDistributed, TestOFBPParticles) share: their
// sphere with a swirl field, the gather of every process's rows on the first process,
// and the end of a run whose every process checks something.
#ifndef vtkOFBPTestSupport_h
#define vtkOFBPTestSupport_h

#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
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
