// A process killed while it writes its piece of a distributed OFB leaves no partial file.
//
//   mpirun -np N TestOFBPExportFault DIR
//     Every process samples its piece of a sphere (vtkOFBPSampler) and writes it to
//     DIR/piece-<rank>.ofb at resolution 48; then, after a barrier, every process but the
//     last writes it again at resolution 96, and the last one kills itself (SIGKILL)
//     halfway through its write of the second version. mpirun then ends the others.
//   TestOFBPExportFault --check DIR N
//     Every DIR/piece-<r>.ofb is a complete file (vtkOFBReader reads it, checksums
//     included): the last process's is its first version, the others' the second. Any
//     other file in DIR must be a writer's temporary of the killed process, and the
//     next write of that piece removes it. Exit status 0 when all of this holds.
#include "vtkCommand.h"
#include "vtkDirectory.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBReader.h"
#include "vtkOFBWriter.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

namespace
{
/// Kills this process when the writer it observes is halfway through.
class KillHalfway : public vtkCommand
{
public:
  static KillHalfway* New() { return new KillHalfway; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (*static_cast<double*>(data) >= 0.5)
    {
      std::raise(SIGKILL);
    }
  }
};

std::string PieceName(const std::string& dir, int rank)
{
  return dir + "/piece-" + std::to_string(rank) + ".ofb";
}

/// The largest dimension of the frame of the OFB in `file` (its resolution), or -1.
int ReadResolution(const std::string& file)
{
  vtkNew<vtkOFBReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkOFB* ofb = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !ofb || !(ofb->GetCellSize() > 0.0))
  {
    return -1;
  }
  const vtkIdType* d = ofb->GetDimensions();
  return static_cast<int>(std::max({ d[0], d[1], d[2] }));
}

int Check(const std::string& dir, int size)
{
  int failures = 0;
  for (int r = 0; r < size; ++r)
  {
    const int expected = size > 1 && r == size - 1 ? 48 : 96;
    const int found = ReadResolution(PieceName(dir, r));
    std::printf("piece %d: resolution %d (expected %d)\n", r, found, expected);
    failures += found != expected;
  }
  vtkNew<vtkDirectory> listing;
  listing->Open(dir.c_str());
  int temporaries = 0;
  for (vtkIdType i = 0; i < listing->GetNumberOfFiles(); ++i)
  {
    const std::string name = listing->GetFile(i);
    if (name == "." || name == "..")
    {
      continue;
    }
    bool piece = false;
    for (int r = 0; r < size; ++r)
    {
      piece = piece || name == "piece-" + std::to_string(r) + ".ofb";
    }
    if (piece)
    {
      continue;
    }
    const bool temporary = name.find(".ofb.tmp-") != std::string::npos;
    std::printf("%s file left: %s\n", temporary ? "temporary" : "FAIL other", name.c_str());
    temporaries += temporary;
    failures += !temporary;
  }
  if (temporaries > 0)
  {
    // The next write of the killed process's piece removes the dead writer's temporaries.
    vtkNew<vtkOFBReader> reader;
    reader->SetFileName(PieceName(dir, size - 1).c_str());
    reader->Update();
    vtkNew<vtkOFBWriter> writer;
    writer->SetInputData(reader->GetOutput());
    writer->SetFileName(PieceName(dir, size - 1).c_str());
    writer->Write();
    listing->Open(dir.c_str());
    const int left = static_cast<int>(listing->GetNumberOfFiles()) - 2 - size;
    std::printf("after a rewrite: %d temporaries left\n", left);
    failures += left != 0;
  }
  std::printf("%s\n", failures ? "FAIL" : "PASS");
  return failures ? 1 : 0;
}
}

int main(int argc, char* argv[])
{
  if (argc >= 4 && !std::strcmp(argv[1], "--check"))
  {
    return Check(argv[2], std::atoi(argv[3]));
  }
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: TestOFBPExportFault DIR | --check DIR N\n");
    return 2;
  }
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  const std::string dir = argv[1];

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkExtractPolyDataPiece> piece;
  piece->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkOFBPSampler> sampler;
  sampler->SetInputConnection(piece->GetOutputPort());
  // The writer writes a copy of this process's piece (connected to the sampler, its
  // update would ask for the whole surface).
  vtkNew<vtkOFB> ofb;
  vtkNew<vtkOFBWriter> writer;
  writer->SetInputData(ofb);
  writer->SetFileName(PieceName(dir, rank).c_str());

  sampler->SetResolution(48);
  sampler->UpdatePiece(rank, size, 0);
  ofb->ShallowCopy(sampler->GetOutput());
  writer->Write();
  controller->Barrier();

  sampler->SetResolution(96);
  sampler->UpdatePiece(rank, size, 0);
  ofb->ShallowCopy(sampler->GetOutput());
  const bool killed = size > 1 && rank == size - 1;
  if (killed)
  {
    controller->Barrier(); // the others have written their second version
    vtkNew<KillHalfway> kill;
    writer->AddObserver(vtkCommand::ProgressEvent, kill);
  }
  writer->Write();
  if (!killed)
  {
    controller->Barrier();
  }
  controller->Finalize();
  return 0;
}
