// Private header of vtkOFBPainter and vtkOFBPaintFilter: the arc-length walk that places
// the dabs of a stroke, written once for vtkOFBPainter::StrokeTo and the strokes of
// vtkOFBPaintFilter.
#ifndef vtkOFBStrokeSampler_h
#define vtkOFBStrokeSampler_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

/**
 * The path length between two dabs of a stroke: `spacing` radii, but at least an eighth
 * of an OFB cell (dabs closer than that paint the same samples, and a radius of 0, from a
 * pressure of 0, or of 1e-12 would place billions of them).
 */
inline double vtkOFBDabStep(double spacing, double radius, double cellSize)
{
  return std::max({ spacing * radius, 0.125 * cellSize, 1e-300 });
}

/// The most dabs one call may place along strokes (about 2 GB of them): more is an error.
constexpr double vtkOFBMaximumStrokeDabs = 16777216.0;

/**
 * Places the dabs of one stroke: the first at its first point (the caller's), then one
 * every vtkOFBDabStep(spacing, radius of the last dab) of path length, carried from
 * segment to segment. The caller gives the segments in order and places the dabs.
 */
class vtkOFBStrokeSampler
{
public:
  /// Start a stroke whose first dab, of radius `radius` (pressure included), is placed.
  void Start(double radius)
  {
    this->SinceLastDab = 0.0;
    this->LastRadius = radius;
  }

  /**
   * Walk the next segment of the stroke, `length` long: `place(t)` places a dab at the
   * fraction t in (0, 1] of the segment and returns its radius (pressure included),
   * which sets the distance to the next dab.
   */
  template<class Place>
  void Walk(double length, double spacing, double cellSize, Place&& place)
  {
    double s = vtkOFBDabStep(spacing, this->LastRadius, cellSize) - this->SinceLastDab;
    double lastS = -this->SinceLastDab;
    while (s <= length && length > 0.0)
    {
      this->LastRadius = place(s / length);
      lastS = s;
      s += vtkOFBDabStep(spacing, this->LastRadius, cellSize);
    }
    this->SinceLastDab = length - lastS;
  }

  /**
   * Walk the segments of a polyline in order (a stroke's path over the surface, see
   * vtkOFBStrokePath): `place(i, t)` places a dab at the fraction t in (0, 1] of the
   * segment from path[i] to path[i + 1] and returns its radius.
   */
  template<class Place>
  void WalkPath(const std::vector<glm::dvec3>& path, double spacing, double cellSize, Place&& place)
  {
    for (std::size_t i = 1; i < path.size(); ++i)
    {
      this->Walk(glm::length(path[i] - path[i - 1]),
        spacing,
        cellSize,
        [&](double t) { return place(i - 1, t); });
    }
  }

  /// The most dabs a segment of `length` places when no radius along it is below `radius`.
  static double MostDabs(double length, double spacing, double radius, double cellSize)
  {
    return length / vtkOFBDabStep(spacing, radius, cellSize);
  }

private:
  double SinceLastDab = 0.0; // path length walked since the last dab
  double LastRadius = 0.0;   // radius of the last dab
};

#endif
