// vtkOFBPainter's mirror painting: the reflections of a point, and of the dabs of a call.
#include "vtkOFBPainter.h"

#include "vtkOFBPaintKernel.h"

#include <algorithm>
#include <vector>

//------------------------------------------------------------------------------
int vtkOFBPainter::GetMirrorReflections(const double point[3],
  double reflections[21],
  int axes[7]) const
{
  const int mirrors = (this->MirrorX ? 1 : 0) | (this->MirrorY ? 2 : 0) | (this->MirrorZ ? 4 : 0);
  int count = 0;
  // Reflection m flips the axes of its bits: x, y, xy, z, xz, yz, xyz.
  for (int m = 1; m < 8; ++m)
  {
    if ((m & mirrors) != m)
    {
      continue;
    }
    double* q = reflections + 3 * count;
    for (int a = 0; a < 3; ++a)
    {
      q[a] = (m & (1 << a)) ? 2.0 * this->MirrorOrigin[a] - point[a] : point[a];
    }
    bool repeated = std::equal(q, q + 3, point);
    for (int k = 0; k < count && !repeated; ++k)
    {
      repeated = std::equal(q, q + 3, reflections + 3 * k);
    }
    if (!repeated)
    {
      axes[count++] = m;
    }
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkOFBPainter::AddMirrorImages(std::vector<vtkOFBDab>& dabs) const
{
  if (!this->MirrorX && !this->MirrorY && !this->MirrorZ)
  {
    return;
  }
  std::vector<vtkOFBDab> all;
  all.reserve(dabs.size() * 8);
  double centres[21];
  int axes[7];
  for (const vtkOFBDab& dab : dabs)
  {
    all.push_back(dab);
    const int count = this->GetMirrorReflections(dab.Center, centres, axes);
    for (int k = 0; k < count; ++k)
    {
      vtkOFBDab image = dab;
      for (int a = 0; a < 3; ++a)
      {
        image.Center[a] = centres[3 * k + a];
        if (axes[k] & (1 << a))
        {
          image.Previous[a] = 2.0 * this->MirrorOrigin[a] - dab.Previous[a];
          image.Normal[a] = -dab.Normal[a];
        }
      }
      all.push_back(image);
    }
  }
  dabs.swap(all);
}
