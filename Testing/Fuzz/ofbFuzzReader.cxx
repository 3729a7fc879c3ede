// Fuzz target: vtkOFBReader on arbitrary bytes, twice: as they are (the checksums then
// stop most mutations), and with every CRC recomputed (ofbFuzzSeal.h), so that the
// checks of the content are reached. An OFB that the reader accepts must be usable: its
// samples have finite positions inside the frame, it converts to a vtkPolyData that
// vtkPLYWriter writes, and vtkOFBWriter writes it back (the writer refuses what the
// reader would refuse, so a refusal here means the two disagree).
#include "ofbFuzzSeal.h"

#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBReader.h"
#include "vtkOFBToPolyData.h"
#include "vtkOFBWriter.h"
#include "vtkPLYWriter.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
/// A file of this process for the reader to read (vtkOFBReader reads files only).
std::string ScratchFile(const char* suffix)
{
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/ofb-fuzz-" + std::to_string(getpid()) + suffix;
}

void Check(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "ofbFuzzReader: check failed: %s\n", what);
    std::abort();
  }
}

/// Use an OFB the reader accepted, as an application would.
void Exercise(vtkOFB* ofb)
{
  const vtkIdType n = ofb->GetNumberOfSamples();
  const double* o = ofb->GetOrigin();
  const vtkIdType* d = ofb->GetDimensions();
  const double h = ofb->GetCellSize();
  for (vtkIdType id = 0; id < n; id += 1 + n / 16)
  {
    double x[3];
    Check(ofb->GetSamplePosition(id, x), "a sample has a position");
    for (int a = 0; a < 3; ++a)
    {
      Check(std::isfinite(x[a]), "sample positions are finite");
      Check(x[a] >= o[a] && x[a] <= o[a] + h * d[a], "samples lie inside the frame");
    }
    ofb->FindClosestSample(x);
  }

  vtkNew<vtkOFBToPolyData> points;
  points->SetInputData(ofb);
  vtkNew<vtkPLYWriter> ply;
  ply->SetInputConnection(points->GetOutputPort());
  ply->SetFileTypeToBinary();
  ply->WriteToOutputStringOn();
  ply->Write();

  static const std::string copy = ScratchFile("-copy.ofb");
  vtkNew<vtkOFBWriter> writer;
  writer->SetInputData(ofb);
  writer->SetFileName(copy.c_str());
  Check(writer->Write() == 1, "vtkOFBWriter writes what vtkOFBReader read");
}

void ReadBytes(const std::vector<uint8_t>& bytes)
{
  static const std::string path = ScratchFile(".ofb");
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    std::perror(path.c_str());
    std::abort();
  }
  if (!bytes.empty())
  {
    std::fwrite(bytes.data(), 1, bytes.size(), file);
  }
  std::fclose(file);
  vtkNew<vtkOFBReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkOFB* ofb = reader->GetOutput();
  if (reader->GetErrorCode() == 0)
  {
    Exercise(ofb);
  }
  else
  {
    Check(ofb->GetNumberOfSamples() == 0 && ofb->GetNumberOfCells() == 0 &&
        ofb->GetSampleData()->GetNumberOfArrays() == 0,
      "a refused file gives an empty output");
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  // The reader's error messages are expected here: keep them off the fuzzer's output.
  vtkObject::GlobalWarningDisplayOff();
  std::vector<uint8_t> bytes(data, data + size);
  ReadBytes(bytes);
  ofbfuzz::Reseal(bytes);
  ReadBytes(bytes);
  return 0;
}
