#include "vtkOFBCPUSampler.h"

#include "vtkAlgorithm.h"
#include "vtkOFB.h"
#include "vtkOFBSampleArrays.h"
#include "vtkOFBSampleSources.h"
#include "vtkOFBSamplerBands.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTypeUInt32Array.h"

#include <cstdint>
#include <sstream>
#include <vector>

using vtkofb::Band;
using vtkofb::BandBuilder;
using vtkofb::BandScratch;
using vtkofb::Output;
using vtkofb::SpanRecord;

vtkStandardNewMacro(vtkOFBCPUSampler);

//------------------------------------------------------------------------------
vtkOFBCPUSampler::vtkOFBCPUSampler() = default;

//------------------------------------------------------------------------------
vtkOFBCPUSampler::~vtkOFBCPUSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBCPUSampler::ReleaseBuffers()
{
  this->Buffers.reset();
}

//------------------------------------------------------------------------------
double vtkOFBCPUSampler::EstimateWorkBytes(vtkIdType, vtkIdType triangles, double) const
{
  // Per triangle: its setup, band range, setup order key and position, and (at
  // least) one entry in the band lists. The spans are checked once counted.
  const double perTriangle =
    sizeof(vtkOFBTriangleRaster) + sizeof(vtkofb::BandRange) + 3 * sizeof(vtkTypeUInt32);
  return perTriangle * static_cast<double>(triangles);
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend::Result vtkOFBCPUSampler::Sample(Job& job)
{
  if (!vtkOFBCPUSampler::CheckIdRange(job) || !this->SetUpFrame(job))
  {
    return RESULT_FAILED;
  }
  vtkOFBRasterFrame frame;
  for (int a = 0; a < 3; ++a)
  {
    frame.Origin[a] = job.Origin[a];
    frame.Dims[a] = job.Dimensions[a];
    frame.CellBase[a] = job.Output->GetGridCellBase(a);
  }
  frame.InvCell = 1.0 / job.CellSize;
  if (!this->Buffers)
  {
    this->Buffers.reset(new vtkOFBSamplerBuffers);
  }
  BandBuilder builder(*job.Surface, frame, *this->Buffers);
  if (!this->SetUpTriangles(builder, job))
  {
    return RESULT_FAILED;
  }
  vtkOFBCPUSampler::SpanBands(builder);
  if (job.Algorithm)
  {
    job.Algorithm->UpdateProgress(0.3);
    if (job.Algorithm->GetAbortExecute())
    {
      return RESULT_FAILED;
    }
  }
  vtkIdType samples = 0;
  if (!this->AllocateSamples(builder, job, samples))
  {
    return RESULT_FAILED;
  }
  this->FillBands(builder, job, samples);
  if (job.Algorithm)
  {
    job.Algorithm->UpdateProgress(0.85);
  }
  return RESULT_BUILT;
}

//------------------------------------------------------------------------------
bool vtkOFBCPUSampler::CheckIdRange(Job& job)
{
  // Point and triangle ids are kept in 32 bits (vtkOFBTriangleRaster).
  const auto points = static_cast<uint64_t>(job.Surface->GetNumberOfPoints());
  const auto triangles = static_cast<uint64_t>(job.Surface->GetNumberOfTriangles());
  if (points >= UINT32_MAX || triangles >= UINT32_MAX)
  {
    std::ostringstream os;
    os << "The CPU backend samples surfaces of fewer than 2^32 points and triangles; "
       << "this one has " << points << " points and " << triangles << " triangles.";
    job.Error = os.str();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBCPUSampler::SetUpFrame(Job& job) const
{
  // The samples are counted exactly after pass 1 and checked before they are
  // allocated: this first estimate leaves them out.
  const double bytes = this->EstimateBytes(*job.Surface, job.Dimensions, 0.0);
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(bytes, job.MemoryLimit, job.Error))
  {
    return false;
  }
  const bool zeroOffsets = false; // pass 2 writes every offset
  return job.Output->SetFrame(job.Origin, job.CellSize, job.Dimensions, zeroOffsets);
}

//------------------------------------------------------------------------------
bool vtkOFBCPUSampler::SetUpTriangles(BandBuilder& builder, Job& job) const
{
  const vtkIdType triangles = job.Surface->GetNumberOfTriangles();
  builder.CutBands();
  if (!builder.SetupTriangles())
  {
    job.Error = "Cannot allocate the setup of " + std::to_string(triangles) + " triangles.";
    return false;
  }
  if (!builder.ListBandTriangles())
  {
    job.Error = "Cannot allocate the band lists of " + std::to_string(triangles) + " triangles.";
    return false;
  }
  // The spans (one record per row of a triangle) are counted now: check them too
  // before allocating them.
  const double spanBytes = static_cast<double>(builder.SpanRows) * sizeof(SpanRecord);
  const double bytes = this->EstimateBytes(*job.Surface, job.Dimensions, 0.0) + spanBytes;
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(bytes, job.MemoryLimit, job.Error))
  {
    return false;
  }
  if (!builder.AllocateSpans())
  {
    job.Error = "Cannot allocate the spans of " + std::to_string(builder.SpanRows) + " rows.";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBCPUSampler::SpanBands(BandBuilder& builder)
{
  std::vector<Band>& bands = builder.Bands;
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(bands.size()),
    1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        builder.SpanBand(bands[b]);
      }
    });
}

//------------------------------------------------------------------------------
bool vtkOFBCPUSampler::AllocateSamples(BandBuilder& builder, Job& job, vtkIdType& samples) const
{
  uint64_t total = 0;
  for (Band& band : builder.Bands)
  {
    band.First = static_cast<vtkIdType>(total);
    total += static_cast<uint64_t>(band.Count);
  }
  if (total >= UINT32_MAX)
  {
    job.Error = "The OFB would hold " + std::to_string(total) +
      " samples, more than 2^32. Lower the resolution.";
    return false;
  }
  samples = static_cast<vtkIdType>(total);
  const double spanBytes = static_cast<double>(builder.SpanRows) * sizeof(SpanRecord);
  const double bytes =
    this->EstimateBytes(*job.Surface, job.Dimensions, static_cast<double>(samples)) + spanBytes;
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(bytes, job.MemoryLimit, job.Error))
  {
    return false;
  }
  return job.Output->AllocateSamples(samples);
}

//------------------------------------------------------------------------------
void vtkOFBCPUSampler::FillBands(BandBuilder& builder, Job& job, vtkIdType samples)
{
  const vtkOFBSurface& surface = *job.Surface;
  vtkOFB* output = job.Output;
  vtkOFBSampleArrays arrays(surface, samples, output);
  Output out;
  vtkTypeUInt32* offsets = output->GetCellOffsets()->GetPointer(0);
  out.Offsets = offsets;
  out.Depth = output->GetDepths()->GetPointer(0);
  out.CellIndex = output->GetCellIndex()->GetPointer(0);
  out.Colors = arrays.Colors->GetPointer(0);
  out.Normals = arrays.Normals->GetPointer(0);
  out.Vectors = arrays.Vectors ? arrays.Vectors->GetPointer(0) : nullptr;
  if (job.Sources && job.Sources->RecordSamples(samples))
  {
    out.SourceTri = job.Sources->GetTriangles();
    out.SourceW1 = job.Sources->GetW1();
    out.SourceW2 = job.Sources->GetW2();
  }
  std::vector<bool> interpolated;
  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    interpolated.push_back(vtkOFBAttributeInterpolator::IsInterpolable(surface.Arrays[k]));
    if (interpolated.back())
    {
      out.OthersIn.push_back(surface.Arrays[k]);
      out.Others.push_back(arrays.Others[k]);
      out.OthersCells.push_back(surface.GetArrayCells(k));
    }
  }
  std::vector<Band>& bands = builder.Bands;
  vtkSMPThreadLocal<BandScratch>& scratch = this->Buffers->Scratch;
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(bands.size()),
    1,
    [&](vtkIdType begin, vtkIdType end)
    {
      BandScratch& local = scratch.Local();
      for (vtkIdType b = begin; b < end; ++b)
      {
        builder.FillBand(bands[b], out, local);
      }
    });
  offsets[output->GetNumberOfCells()] = static_cast<vtkTypeUInt32>(samples);
  arrays.Attach(surface, output->GetSampleData(), interpolated);
}
