// vtkOFBSampler's attribute-only re-sampling (StructureReuse): the hook between the
// sampler and vtkOFBSampleSources.
#include "vtkOFBSampler.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkOFB.h"
#include "vtkOFBSampleSources.h"
#include "vtkOFBSurface.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

//------------------------------------------------------------------------------
bool vtkOFBSampler::ResampleAttributes(vtkInformation* inInfo,
  vtkPolyData* input,
  vtkOFBSamplerBackend::Job& job)
{
  const bool reuse = this->StructureReuse == STRUCTURE_REUSE_ALWAYS ||
    (this->StructureReuse == STRUCTURE_REUSE_TIME_SERIES && inInfo &&
      inInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  if (!reuse)
  {
    this->Sources->Reset();
    return false;
  }
  auto key =
    vtkOFBSampleSources::MakeKey(input, this->Resolution, this->LastBuildBackend.GetPointer());
  if (input->GetNumberOfPoints() > 0 && this->Sources->Matches(input, key))
  {
    // The geometry was checked and prepared by the last build: its triangles (and
    // their input cells) with this input's arrays.
    vtkOFBSurface surface;
    vtkDataArray* normals = input->GetPointData()->GetNormals();
    if (normals &&
      (normals->GetNumberOfComponents() != 3 ||
        normals->GetNumberOfTuples() != input->GetNumberOfPoints()))
    {
      normals = nullptr; // as PrepareNormals: computed, not an input array
    }
    if (!this->PrepareAttributes(input, normals, surface))
    {
      job.Output->Initialize();
      this->Sources->Reset();
      return true;
    }
    const bool cellsKnown = surface.ArraysPerCell.empty() || this->Sources->HasTriangleCells();
    if (cellsKnown && this->Sources->Resample(surface, job.Output))
    {
      this->ProjectCellVectors(surface, job.Output);
      this->LastUpdateResampled = true;
      vtkDebugMacro("Same geometry as the last build: re-sampled the attributes alone.");
      return true;
    }
  }
  // A full build, which records its sources; the kept structure is let go first.
  this->Sources->Reset();
  job.Sources = this->Sources;
  return false;
}
