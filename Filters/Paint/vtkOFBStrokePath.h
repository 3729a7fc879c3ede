// Private header of vtkOFBPainter and vtkOFBPaintFilter: the path of a stroke over the
// surface that an OFB samples, written once for vtkOFBPainter::StrokeTo and the strokes of
// vtkOFBPaintFilter.
#ifndef vtkOFBStrokePath_h
#define vtkOFBStrokePath_h

#include "vtkType.h"

#include <glm/glm.hpp>

#include <vector>

class vtkFloatArray;
class vtkOFB;

/**
 * Strokes that follow the surface. `Snap` moves a stroke point given in world
 * coordinates onto the surface: to the closest sample of the OFB, however far. `Trace`
 * finds a path over the surface between two samples, as a polyline through samples: from
 * the first, each step goes to the sample within two cells of the current one that is
 * closest to the target, among those whose normal is not turned away from the current
 * sample's by more than 120 degrees (so a step never jumps to the opposite wall of a thin
 * pipe or the back of a thin plate, and still turns a sharp crease). On a pipe this walks
 * around the wall, where the straight chord between the points would cross the inside.
 * Where no nearby sample gets closer to the target (the target lies past a fold the greedy
 * walk cannot go around) the path ends with the straight chord to the target.
 *
 * Steps are two cells long, so the path has one vertex every two cells at most and each
 * segment's chord stays within (2s)^2 / (8 R) of a surface of curvature radius R.
 */
class vtkOFBStrokePath
{
public:
  /// Read `ofb`, which must outlive this object and not change while it is used.
  explicit vtkOFBStrokePath(vtkOFB* ofb);

  /// True when the OFB has samples to snap to.
  bool IsValid() const { return this->Valid; }

  /**
   * The sample closest to `x` (a finite point), its position in `onSurface`; -1 (and
   * `onSurface` = x) when the OFB has no sample.
   */
  vtkIdType Snap(const double x[3], double onSurface[3]) const;

  /**
   * Append to `path` the polyline over the surface from sample `from` to sample `to`,
   * their positions included (one point when they are the same sample). Returns false
   * when the walk stopped and the path ends with a straight chord.
   */
  bool Trace(vtkIdType from, vtkIdType to, std::vector<glm::dvec3>& path) const;

  /// The length of a polyline.
  static double Length(const std::vector<glm::dvec3>& path, size_t first, size_t last);

private:
  glm::dvec3 Position(vtkIdType id) const;
  /// False when the normals of samples `a` and `b` are more than 120 degrees apart.
  bool Facing(vtkIdType a, vtkIdType b) const;

  vtkOFB* OFB;
  vtkFloatArray* Normals = nullptr;
  double Step = 0.0;
  double Diagonal = 0.0;
  bool Valid = false;
};

#endif
