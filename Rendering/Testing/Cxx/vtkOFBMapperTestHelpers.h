// Helpers of the vtkOFBPolyDataMapper tests: painting patterns into OFB colours.
#ifndef vtkOFBMapperTestHelpers_h
#define vtkOFBMapperTestHelpers_h

#include "vtkOFB.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <functional>

namespace vtkofbtest
{
/// The RGBA "Colors" sample array of an OFB (null if missing).
inline vtkUnsignedCharArray* GetColors(vtkOFB* ofb)
{
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  return (colors && colors->GetNumberOfComponents() == 4) ? colors : nullptr;
}

/// Set every sample's colour from its position; marks all samples modified.
inline void Paint(
  vtkOFB* ofb, const std::function<void(const double x[3], unsigned char rgba[4])>& f)
{
  vtkUnsignedCharArray* colors = GetColors(ofb);
  if (!colors)
  {
    return;
  }
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    unsigned char rgba[4] = { 255, 255, 255, 255 };
    f(x, rgba);
    colors->SetTypedTuple(i, rgba);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
}

/// A 3-D checker of cubes of edge `size` (world units), colours a and b.
inline void PaintChecker(
  vtkOFB* ofb, double size, const unsigned char a[4], const unsigned char b[4])
{
  Paint(ofb, [&](const double x[3], unsigned char rgba[4]) {
    const long k = static_cast<long>(std::floor(x[0] / size) + std::floor(x[1] / size) +
      std::floor(x[2] / size));
    const unsigned char* c = (k % 2 == 0) ? a : b;
    for (int i = 0; i < 4; ++i)
    {
      rgba[i] = c[i];
    }
  });
}
}

#endif
