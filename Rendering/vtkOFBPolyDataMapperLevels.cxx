// vtkOFBPolyDataMapper's LIC display: the vtkOFBLICPyramid of the Automatic lookup, the mean
// intensity that the blend of levels computed on their own samples keeps, and the field of
// the flow-aligned filter.
#include "vtkOFBPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBLookupModes.h"
#include "vtkOFBPolyDataMapperInternals.h"
#include "vtkOFBShaderStorage.h"
#include "vtkOpenGLRenderWindow.h" // for vtkOFBShaderStorage's weak pointers
#include "vtkPointData.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::UpdateAutomaticPyramid()
{
  if (this->UserPyramid)
  {
    return;
  }
  vtkOFBLIC* producer = nullptr;
  if (this->AutomaticLevelLIC && this->LookupMode == LOOKUP_AUTOMATIC &&
    this->ResolvedLookupMode == LOOKUP_SMOOTH && this->GetNumberOfInputConnections(1) > 0)
  {
    producer = vtkOFBLIC::SafeDownCast(this->GetInputAlgorithm(1, 0));
  }
  if (producer)
  {
    vtkOFBLICPyramid* pyramid = vtkOFBLICPyramid::SafeDownCast(this->AutoPyramid);
    if (!pyramid)
    {
      this->AutoPyramid = vtkSmartPointer<vtkOFBLICPyramid>::New();
      pyramid = vtkOFBLICPyramid::SafeDownCast(this->AutoPyramid);
    }
    if (pyramid->GetLIC() != producer)
    {
      pyramid->SetLIC(producer);
    }
    this->Storage->SetPyramid(pyramid);
  }
  else if (this->AutoPyramid && this->Storage->GetPyramid() == this->AutoPyramid)
  {
    this->Storage->SetPyramid(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::UpdateLevelIntensity(vtkOFB* ofb)
{
  this->LevelIntensity = false;
  const char* name = this->Coloring->GetIntensityArrayName();
  if (!this->UseIntensity || !name || !vtkOFBFindLookupMode(this->ResolvedLookupMode)->Pyramid ||
    this->Storage->GetNumberOfLevels() < 2 || !this->Storage->GetPyramid()->IsComputedArray(name))
  {
    return;
  }
  vtkDataArray* array = ofb->GetSampleData()->GetArray(name);
  if (!array)
  {
    return;
  }
  this->LevelIntensity = true;
  // A distributed surface's mean, over every process's owned samples, where the pyramid
  // has it (vtkOFBPLICPyramid); else this OFB's.
  double shared = 0.0;
  if (this->Storage->GetPyramid()->GetSharedMean(name, shared))
  {
    this->IntensityMean = shared;
    this->MeanArray = nullptr;
    return;
  }
  if (array == this->MeanArray && array->GetMTime() <= this->MeanTime)
  {
    return;
  }
  // As the shader reads it: clamped to [0, 1], NaN as 0.
  const vtkIdType n = std::min(array->GetNumberOfTuples(), ofb->GetNumberOfSamples());
  double sum = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = array->GetComponent(i, 0);
    sum += v > 0.0 ? std::min(v, 1.0) : 0.0;
  }
  this->IntensityMean = n > 0 ? sum / n : 0.5;
  this->MeanArray = array;
  this->MeanTime = array->GetMTime();
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SelectFlow(vtkOFB* ofb, vtkSelection& selection)
{
  selection.FlowName.clear();
  this->UseFlow = false;
  this->ResolvedFlowArrayName.clear();
  if (!this->FlowAlignedFiltering || !this->UseIntensity ||
    this->ResolvedLookupMode != LOOKUP_SMOOTH || !(this->MaximumFlowFilterOffset > 0.0))
  {
    return;
  }
  vtkPointData* sd = ofb->GetSampleData();
  vtkDataArray* field = nullptr;
  if (!this->FlowArrayName.empty())
  {
    field = sd->GetArray(this->FlowArrayName.c_str());
  }
  else
  {
    // The field of the LIC the OFB comes from (its input array to process), else the
    // active vectors (vtkOFBLIC's default field).
    vtkOFBLIC* lic = this->GetNumberOfInputConnections(1) > 0
      ? vtkOFBLIC::SafeDownCast(this->GetInputAlgorithm(1, 0))
      : nullptr;
    if (!lic)
    {
      auto* pyramid = vtkOFBLICPyramid::SafeDownCast(this->Storage->GetPyramid());
      lic = pyramid ? pyramid->GetLIC() : nullptr;
    }
    vtkInformation* info = lic ? lic->GetInputArrayInformation(0) : nullptr;
    if (info && info->Has(vtkDataObject::FIELD_NAME()))
    {
      field = sd->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
    }
    else if (info && info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
    {
      field = sd->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
    }
    else
    {
      field = sd->GetVectors();
    }
  }
  if (!field || !field->GetName() || field->GetNumberOfComponents() != 3)
  {
    return;
  }
  selection.FlowName = field->GetName();
  if (!vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::BUFFER_FLOW, selection))
  {
    selection.FlowName.clear();
    return;
  }
  this->UseFlow = true;
  this->ResolvedFlowArrayName = selection.FlowName;
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::FlowFilterInView(vtkRenderer* ren, vtkActor* act)
{
  vtkOFB* ofb = this->Storage->GetUploadedOFB();
  vtkCamera* camera = ren ? ren->GetActiveCamera() : nullptr;
  const int* size = ren ? ren->GetSize() : nullptr;
  if (!ofb || !camera || !act || !size || size[1] <= 0)
  {
    return true;
  }
  // A level-0 cell in world units (the actor's largest scale).
  double scale = 1.0;
  if (!act->GetIsIdentity())
  {
    vtkMatrix4x4* m = act->GetMatrix();
    scale = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      scale = std::max(scale,
        std::sqrt(m->GetElement(0, c) * m->GetElement(0, c) +
          m->GetElement(1, c) * m->GetElement(1, c) + m->GetElement(2, c) * m->GetElement(2, c)));
    }
  }
  const double cell = ofb->GetCellSize() * scale;
  // The smallest world size of a pixel on the surface: at the bounds' nearest point.
  double perPixel = 0.0;
  if (camera->GetParallelProjection())
  {
    perPixel = 2.0 * camera->GetParallelScale() / size[1];
  }
  else
  {
    const double* b = act->GetBounds();
    const double* eye = camera->GetPosition();
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      const double out = std::max({ b[2 * i] - eye[i], eye[i] - b[2 * i + 1], 0.0 });
      d2 += out * out;
    }
    const double distance = std::max(std::sqrt(d2), camera->GetClippingRange()[0]);
    perPixel = 2.0 * distance *
      std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle())) / size[1];
  }
  // The shader filters where log2(cells a pixel) < 0.5 (and level 0 is read).
  return !(cell > 0.0) || !(perPixel > 0.0) || std::log2(perPixel / cell) < 0.5;
}
