#include "vtkOFBSampler.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBArrayLength.h"
#include "vtkOFBCPUSampler.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkOFBSampleSources.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBSampler);

namespace
{
/**
 * Re-emits the errors and warnings of an inner algorithm as those of `Target`, where the
 * target's observers see them: the text after VTK's "Class (address): " prefix.
 */
class MessageForwarder : public vtkCommand
{
public:
  static MessageForwarder* New() { return new MessageForwarder; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    std::string text = data ? static_cast<const char*>(data) : "";
    const size_t prefix = text.find("): ");
    text = prefix == std::string::npos ? text : text.substr(prefix + 3);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    if (event == vtkCommand::ErrorEvent)
    {
      vtkErrorWithObjectMacro(this->Target, << text);
    }
    else
    {
      vtkWarningWithObjectMacro(this->Target, << text);
    }
  }
  vtkObject* Target = nullptr;
};
}

//------------------------------------------------------------------------------
vtkOFBSampler::vtkOFBSampler()
  : Resolution(1024)
  , MemoryLimit(8192)
  , UseInputColors(true)
  , PassPointArrays(true)
  , PassCellArrays(true)
  , ArrayPrecedence(POINT_ARRAYS_FIRST)
  , ProjectVectors(true)
  , StructureReuse(STRUCTURE_REUSE_TIME_SERIES)
  , LastUpdateResampled(false)
  , NumberOfSkippedTriangles(0)
  , LastBuildTime(0.0)
{
  this->DefaultColor[0] = this->DefaultColor[1] = this->DefaultColor[2] = 255;
  this->DefaultColor[3] = 255;
  this->CPUBackend = vtk::TakeSmartPointer(vtkOFBCPUSampler::New());
  this->Sources = vtk::TakeSmartPointer(vtkOFBSampleSources::New());
}

//------------------------------------------------------------------------------
vtkOFBSampler::~vtkOFBSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBSampler::ReleaseBuffers()
{
  this->CPUBackend->ReleaseBuffers();
  this->Sources->Reset();
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend* vtkOFBSampler::SelectBackend()
{
  return this->CPUBackend;
}

//------------------------------------------------------------------------------
int vtkOFBSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  // Composite datasets are merged here (vtkOFBMergeBlocks), not block by block by the
  // pipeline: one OFB on one frame over all blocks.
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBSampler::GetSurface(vtkDataObject* input)
{
  // A polydata is sampled as it is (no copy); any other dataset through its
  // outer surface, with its point and cell arrays; a composite dataset as the
  // surface of all its blocks, with their block index (vtkOFBMergeBlocks).
  if (auto* polyData = vtkPolyData::SafeDownCast(input))
  {
    return polyData;
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  if (vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkNew<vtkOFBMergeBlocks> merge;
    merge->SetInputData(input);
    vtkNew<MessageForwarder> forward;
    forward->Target = this;
    merge->AddObserver(vtkCommand::ErrorEvent, forward);
    merge->AddObserver(vtkCommand::WarningEvent, forward);
    merge->Update();
    surface->ShallowCopy(merge->GetOutput());
    return surface;
  }
  if (!vtkDataSet::SafeDownCast(input))
  {
    return surface;
  }
  auto extract = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
  extract->SetInputData(input);
  extract->Update();
  surface->ShallowCopy(extract->GetOutput());
  return surface;
}

//------------------------------------------------------------------------------
int vtkOFBSampler::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkSmartPointer<vtkPolyData> input = this->GetSurface(vtkDataObject::GetData(inputVector[0]));
  vtkOFB* output = vtkOFB::GetData(outputVector);
  // The pipeline has recycled the previous output (vtkOFB::PrepareForNewData):
  // SetFrame, AllocateSamples and the sample arrays reuse its memory, and
  // vtkOFBAlgorithm frees what is left after this.
  this->NumberOfSkippedTriangles = 0;
  this->LastBuildTime = 0.0;
  this->LastUpdateResampled = false;

  const double start = vtkTimerLog::GetUniversalTime();
  vtkOFBSamplerBackend* backend = this->SelectBackend();
  this->LastBuildBackend = backend;
  this->UpdateProgress(0.0);
  vtkOFBSurface surface;
  vtkOFBSamplerBackend::Job job;
  job.Surface = &surface;
  job.Output = output;
  job.MemoryLimit = 1024.0 * 1024.0 * static_cast<double>(this->MemoryLimit);
  job.Algorithm = this;
  if (this->ResampleAttributes(inputVector[0]->GetInformationObject(0), input, job))
  {
    this->LastBuildTime = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
    this->UpdateProgress(1.0);
    return 1;
  }
  if (!this->CheckInputCells(input) || !this->CheckInputMemory(input, backend, job) ||
    !this->PrepareSurface(input, surface) || !this->ComputeFrame(surface, job))
  {
    output->Initialize();
    this->Sources->Reset();
    return 1;
  }
  this->UpdateProgress(0.05);
  auto key = vtkOFBSampleSources::MakeKey(input, this->Resolution, backend);
  if (this->RunBackend(backend, job) != vtkOFBSamplerBackend::RESULT_BUILT)
  {
    this->Sources->Reset();
    return 1;
  }
  if (job.Sources)
  {
    key.Backend = this->LastBuildBackend.GetPointer();
    this->Sources->Keep(output, input, key, surface);
  }
  this->ProjectCellVectors(surface, output);
  this->LastBuildTime = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend::Result vtkOFBSampler::RunBackend(vtkOFBSamplerBackend* backend,
  vtkOFBSamplerBackend::Job& job)
{
  vtkOFBSamplerBackend::Result result = backend->Sample(job);
  if (result == vtkOFBSamplerBackend::RESULT_UNAVAILABLE && backend != this->CPUBackend)
  {
    vtkWarningMacro("The " << backend->GetBackendName() << " build failed (" << job.Error
                           << "); building on the CPU instead.");
    job.Output->Initialize();
    job.Error.clear();
    this->LastBuildBackend = this->CPUBackend;
    result = this->CPUBackend->Sample(job);
  }
  if (result != vtkOFBSamplerBackend::RESULT_BUILT)
  {
    if (!job.Error.empty())
    {
      vtkErrorMacro(<< job.Error);
    }
    job.Output->Initialize();
  }
  return result;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::ComputeFrame(const vtkOFBSurface& surface, vtkOFBSamplerBackend::Job& job)
{
  if (this->Resolution < 3 || this->Resolution > 65536)
  {
    vtkErrorMacro("Resolution must be in [3, 65536], it is " << this->Resolution << ".");
    return false;
  }
  double b[6];
  this->GetFrameBounds(surface.Bounds, b);
  const double longest = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  if (!std::isfinite(longest))
  {
    // Finite coordinates whose extent is not (e.g. -1e308 and 1e308).
    vtkErrorMacro("The input bounds overflow a double (extent of the coordinates too large): "
                  "nothing to sample.");
    return false;
  }
  if (!(longest > 0.0))
  {
    vtkErrorMacro("The input bounds are degenerate: nothing to sample.");
    return false;
  }
  const double cellSize = longest / (this->Resolution - 2);
  job.CellSize = cellSize;
  for (int a = 0; a < 3; ++a)
  {
    const double cells = std::ceil((b[2 * a + 1] - b[2 * a]) / cellSize - 1e-9);
    job.Dimensions[a] = std::max<vtkIdType>(1, static_cast<vtkIdType>(cells)) + 2;
    job.Origin[a] = 0.5 * (b[2 * a] + b[2 * a + 1]) - 0.5 * job.Dimensions[a] * cellSize;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBSampler::GetFrameBounds(const double surfaceBounds[6], double bounds[6])
{
  std::copy(surfaceBounds, surfaceBounds + 6, bounds);
}

//------------------------------------------------------------------------------
double vtkOFBSampler::EstimateMemory(vtkDataObject* dataSet)
{
  vtkSmartPointer<vtkPolyData> input = this->GetSurface(dataSet);
  vtkOFBSurface surface;
  vtkOFBSamplerBackend::Job job;
  if (!this->CheckInputCells(input) || !this->PrepareSurface(input, surface) ||
    !this->ComputeFrame(surface, job))
  {
    return -1.0;
  }
  const double samples = vtkOFBSamplerBackend::EstimateSamples(surface, job.CellSize);
  return this->CPUBackend->EstimateBytes(surface, job.Dimensions, samples);
}

//------------------------------------------------------------------------------
void vtkOFBSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "DefaultColor: (" << static_cast<int>(this->DefaultColor[0]) << ", "
     << static_cast<int>(this->DefaultColor[1]) << ", " << static_cast<int>(this->DefaultColor[2])
     << ", " << static_cast<int>(this->DefaultColor[3]) << ")\n";
  os << indent << "UseInputColors: " << (this->UseInputColors ? "On" : "Off") << "\n";
  os << indent << "PassPointArrays: " << (this->PassPointArrays ? "On" : "Off") << "\n";
  os << indent << "PassCellArrays: " << (this->PassCellArrays ? "On" : "Off") << "\n";
  os << indent << "ArrayPrecedence: "
     << (this->ArrayPrecedence == CELL_ARRAYS_FIRST ? "CELL_ARRAYS_FIRST" : "POINT_ARRAYS_FIRST")
     << "\n";
  os << indent << "ProjectVectors: " << (this->ProjectVectors ? "On" : "Off") << "\n";
  os << indent << "StructureReuse: " << this->StructureReuse << "\n";
  os << indent << "LastUpdateResampled: " << (this->LastUpdateResampled ? "yes" : "no") << "\n";
  os << indent << "NumberOfSkippedTriangles: " << this->NumberOfSkippedTriangles << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << " ms\n";
}
