// vtkOFBPainter's strokes: BeginStroke, StrokeTo (the dabs along a path over the surface,
// vtkOFBStrokePath, spaced by vtkOFBStrokeSampler) and EndStroke.
#include "vtkOFBPainter.h"

#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPaintKernel.h"
#include "vtkOFBPainterInternals.h"
#include "vtkOFBStrokePath.h"
#include "vtkOFBStrokeSampler.h"
#include "vtkPoints.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
bool Finite3(const double p[3])
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
}

//------------------------------------------------------------------------------
void vtkOFBPainter::BeginStroke()
{
  CallScope scope(this, "BeginStroke");
  if (scope)
  {
    this->StartStroke();
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainter::StartStroke()
{
  if (this->InStroke)
  {
    this->FinishStroke();
  }
  this->InStroke = true;
  this->Internals->HasLastPoint = false;
  this->Internals->HasLastDab = false;
  this->Internals->Sampler.Start(0.0);
  this->Internals->StrokeDabs->Initialize();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::StrokeTo(const double p[3], double pressure)
{
  CallScope scope(this, "StrokeTo");
  if (!scope)
  {
    return 0;
  }
  if (!Finite3(p))
  {
    vtkErrorMacro("A stroke point is not finite (NaN or infinite): ignored.");
    return 0;
  }
  if (!this->CheckBrush("StrokeTo"))
  {
    return 0;
  }
  if (!this->InStroke)
  {
    this->StartStroke();
  }
  vtkInternals& internals = *this->Internals;
  pressure = std::min(1.0, std::max(0.0, std::isfinite(pressure) ? pressure : 1.0));
  std::vector<vtkOFBDab> dabs;
  auto place = [&](const double c[3], double pr)
  {
    vtkOFBDab d;
    this->MakeDab(c, pr, d);
    d.HasPrevious = internals.HasLastDab;
    std::copy(internals.LastDab, internals.LastDab + 3, d.Previous);
    dabs.push_back(d);
    std::copy(c, c + 3, internals.LastDab);
    internals.HasLastDab = true;
    internals.StrokeDabs->InsertNextPoint(c);
  };
  vtkOFBBrush* brush = internals.Brush;
  auto radiusAt = [brush](double pr)
  { return brush->GetRadius() * (brush->GetPressureAffectsRadius() ? pr : 1.0); };
  // With FollowSurface the point moves to the closest sample and the dabs follow a path
  // over the surface from the last point; otherwise they follow the straight chord.
  const vtkOFBStrokePath surface(this->FollowSurface ? internals.OFB.GetPointer() : nullptr);
  double q[3] = { p[0], p[1], p[2] };
  const vtkIdType sample = surface.IsValid() ? surface.Snap(p, q) : -1;
  if (!internals.HasLastPoint)
  {
    place(q, pressure);
    internals.Sampler.Start(radiusAt(pressure));
  }
  else
  {
    // The last point is re-found rather than kept as a sample id: the OFB may have been
    // rebuilt between two calls (it was moved onto a sample: the same one when it was not).
    std::vector<glm::dvec3> path;
    double lastOnSurface[3];
    const vtkIdType last = sample >= 0 ? surface.Snap(internals.LastPoint, lastOnSurface) : -1;
    if (last >= 0)
    {
      surface.Trace(last, sample, path);
    }
    else
    {
      path = { glm::dvec3(internals.LastPoint[0], internals.LastPoint[1], internals.LastPoint[2]),
        glm::dvec3(q[0], q[1], q[2]) };
    }
    const double length = vtkOFBStrokePath::Length(path, 0, path.size() - 1);
    const double cellSize = internals.OFB ? internals.OFB->GetCellSize() : 0.0;
    const double smallest = radiusAt(std::min(pressure, internals.LastPressure));
    if (vtkOFBStrokeSampler::MostDabs(length, this->Spacing, smallest, cellSize) >
      vtkOFBMaximumStrokeDabs)
    {
      vtkErrorMacro("StrokeTo: this segment ("
        << length << " long) would place more than " << vtkOFBMaximumStrokeDabs << " dabs (radius "
        << brush->GetRadius() << ", Spacing " << this->Spacing << "): nothing painted.");
      std::copy(q, q + 3, internals.LastPoint);
      internals.LastPressure = pressure;
      internals.Sampler.Start(radiusAt(pressure));
      return 0;
    }
    // The pressure goes from the last point's to this one's along the path's length.
    const double startPressure = internals.LastPressure;
    std::vector<double> walked(path.size(), 0.0);
    for (size_t i = 1; i < path.size(); ++i)
    {
      walked[i] = walked[i - 1] + glm::length(path[i] - path[i - 1]);
    }
    internals.Sampler.WalkPath(path,
      this->Spacing,
      cellSize,
      [&](size_t i, double t)
      {
        const glm::dvec3 c = path[i] + t * (path[i + 1] - path[i]);
        const double f = length > 0.0
          ? std::min(1.0, (walked[i] + t * (walked[i + 1] - walked[i])) / length)
          : 1.0;
        const double pr = startPressure + f * (pressure - startPressure);
        const double cc[3] = { c.x, c.y, c.z };
        place(cc, pr);
        return radiusAt(pr);
      });
  }
  std::copy(q, q + 3, internals.LastPoint);
  internals.LastPressure = pressure;
  internals.HasLastPoint = true;
  return dabs.empty() ? 0 : this->Paint(dabs);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::StrokeTo(double x, double y, double z, double pressure)
{
  const double p[3] = { x, y, z };
  return this->StrokeTo(p, pressure);
}

//------------------------------------------------------------------------------
void vtkOFBPainter::EndStroke()
{
  CallScope scope(this, "EndStroke");
  if (scope)
  {
    this->FinishStroke();
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainter::FinishStroke()
{
  if (!this->InStroke)
  {
    return;
  }
  this->InStroke = false;
  this->CloseStep();
}
