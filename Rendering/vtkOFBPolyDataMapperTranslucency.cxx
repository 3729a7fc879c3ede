// vtkOFBPolyDataMapper's translucency: whether the OFB's colours (or the colouring's lookup
// table) make the surface translucent, with the scan of the colours' alpha cached.
#include "vtkOFBPolyDataMapper.h"

#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBShaderStorage.h"
#include "vtkOpenGLRenderWindow.h" // for vtkOFBShaderStorage's weak pointers
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::HasTranslucentPolygonalGeometry()
{
  this->UpdateOFBProducer();
  vtkOFB* ofb = this->GetOFB();
  if (!ofb || ofb->GetNumberOfSamples() == 0)
  {
    return this->Superclass::HasTranslucentPolygonalGeometry();
  }
  vtkOFBShaderStorage::Selection selection;
  selection.ScalarName = this->Coloring->GetScalarArrayName();
  selection.ScalarComponent = this->Coloring->GetScalarComponent();
  if (this->Coloring->GetColorSource() == vtkOFBColoring::COLOR_SOURCE_SCALARS &&
    vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::ATTRIBUTE_SCALARS, selection))
  {
    vtkScalarsToColors* lut = this->Coloring->GetLookupTable();
    lut->Build();
    return lut->IsOpaque() == 0;
  }
  return this->HasTranslucentColors(ofb);
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::HasTranslucentColors(vtkOFB* ofb)
{
  vtkOFBShaderStorage::Selection selection;
  auto* colors = vtkUnsignedCharArray::SafeDownCast(
    vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::ATTRIBUTE_COLORS, selection));
  if (!colors || colors->GetNumberOfComponents() != 4)
  {
    return false;
  }
  const vtkIdType n = std::min(colors->GetNumberOfTuples(), ofb->GetNumberOfSamples());
  const unsigned char* rgba = colors->GetPointer(0);
  // First sample of [first, last) with alpha below 255, or -1.
  auto findTranslucent = [rgba](vtkIdType first, vtkIdType last) -> vtkIdType
  {
    for (vtkIdType i = first; i < last; ++i)
    {
      if (rgba[4 * i + 3] != 255)
      {
        return i;
      }
    }
    return -1;
  };
  const bool changed = ofb != this->AlphaOFB || colors != this->AlphaColors ||
    ofb->GetStructureMTime() > this->AlphaTime.GetMTime() ||
    colors->GetMTime() > this->AlphaTime.GetMTime();
  vtkNew<vtkIdTypeArray> ranges;
  if (!changed)
  {
    ofb->GetSampleRangesModifiedSince(this->AlphaTime.GetMTime(), ranges);
    if (ranges->GetNumberOfTuples() == 0)
    {
      return this->AlphaTranslucent;
    }
  }
  vtkIdType found = -1;
  if (!changed && !this->AlphaTranslucent)
  {
    // Opaque so far: only the modified samples can have made it translucent.
    for (vtkIdType r = 0; r < ranges->GetNumberOfTuples() && found < 0; ++r)
    {
      found = findTranslucent(std::max<vtkIdType>(0, ranges->GetTypedComponent(r, 0)),
        std::min(n, ranges->GetTypedComponent(r, 1)));
    }
  }
  else
  {
    // A full scan, from where the last translucent sample was (likely still translucent).
    const vtkIdType hint = std::min(std::max<vtkIdType>(this->AlphaHint, 0), n);
    found = findTranslucent(hint, n);
    if (found < 0)
    {
      found = findTranslucent(0, hint);
    }
  }
  this->AlphaOFB = ofb;
  this->AlphaColors = colors;
  this->AlphaTime.Modified();
  this->AlphaTranslucent = found >= 0;
  this->AlphaHint = found >= 0 ? found : 0;
  return this->AlphaTranslucent;
}
