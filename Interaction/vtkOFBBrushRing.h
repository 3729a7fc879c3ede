// Private header of vtkOFBPainterRepresentation: one ring of the brush cursor.
#ifndef vtkOFBBrushRing_h
#define vtkOFBBrushRing_h

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkOFB.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>

/**
 * Append to `points` and `lines` a closed ring of `resolution` points of radius r around
 * `centre` in the plane of the unit `normal`, and a tick of r / 2 from the centre along
 * the normal. With `conform` (an OFB, else null) each ring point moves to the OFB's
 * sample closest to it within r / 2 (the ring then lies on the surface, where the volume
 * brush's sphere cuts it). Ring points are lifted by `lift` along the normal, toward the
 * viewer, so that the surface hides less of them.
 */
inline void vtkOFBAddBrushRing(vtkOFB* conform,
  const double centre[3],
  const double normal[3],
  double r,
  int resolution,
  double lift,
  vtkPoints* points,
  vtkCellArray* lines)
{
  double u[3], v[3], n[3] = { normal[0], normal[1], normal[2] };
  vtkMath::Perpendiculars(n, u, v, 0.0);
  const vtkIdType first = points->GetNumberOfPoints();
  lines->InsertNextCell(resolution + 1);
  for (int k = 0; k < resolution; ++k)
  {
    const double a = 2.0 * vtkMath::Pi() * k / resolution;
    double p[3], q[3];
    for (int i = 0; i < 3; ++i)
    {
      p[i] = centre[i] + r * (std::cos(a) * u[i] + std::sin(a) * v[i]);
    }
    const vtkIdType id = conform ? conform->FindClosestSample(p, 0.5 * r) : -1;
    if (id >= 0 && conform->GetSamplePosition(id, q))
    {
      std::copy_n(q, 3, p);
    }
    for (int i = 0; i < 3; ++i)
    {
      p[i] += lift * normal[i];
    }
    lines->InsertCellPoint(points->InsertNextPoint(p));
  }
  lines->InsertCellPoint(first);
  double tip[3];
  for (int i = 0; i < 3; ++i)
  {
    tip[i] = centre[i] + 0.5 * r * normal[i];
  }
  const vtkIdType tick[2] = { points->InsertNextPoint(centre), points->InsertNextPoint(tip) };
  lines->InsertNextCell(2, tick);
}

#endif
