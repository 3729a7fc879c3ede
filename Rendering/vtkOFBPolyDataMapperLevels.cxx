// vtkOFBPolyDataMapper's pyramid levels: the vtkOFBLICPyramid of the Automatic lookup, and
// the mean intensity that the blend of levels computed on their own samples keeps.
#include "vtkOFBPolyDataMapper.h"

#include "vtkDataArray.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBLookupModes.h"
#include "vtkOFBPolyDataMapperInternals.h"
#include "vtkOFBShaderStorage.h"
#include "vtkOpenGLRenderWindow.h" // for vtkOFBShaderStorage's weak pointers
#include "vtkPointData.h"

#include <algorithm>

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
