// Private header of vtkOFBPainter and vtkOFBPaintFilter: the path of a stroke over the
// surface that an OFB samples, written once for vtkOFBPainter::StrokeTo and the strokes of
// vtkOFBPaintFilter.
#ifndef vtkOFBStrokePath_h
#define vtkOFBStrokePath_h

#include "vtkType.h"

#include <glm/glm.hpp>

#include <utility>
#include <vector>

class vtkFloatArray;
class vtkOFB;
class vtkOFBStrokeExchange;
class vtkUnsignedCharArray;

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
 *
 * `PlaceDistributed` does the same on an OFB distributed over processes (each holds a
 * piece, its ghost samples flagged in the ghost array): every process walks every path,
 * and at each step each process offers the best of its own (non-ghost) samples and the
 * processes keep the best of all, so every process gets the points and paths of Snap and
 * Trace on one OFB of all the pieces' owned samples, value for value. Ties between
 * samples at the same distance go to the sample of smallest (cell, depth), the order of
 * sample ids in any OFB of the common frame, as on one process.
 */
class vtkOFBStrokePath
{
public:
  /**
   * Read `ofb`, which must outlive this object and not change while it is used. With
   * `ownedOnly`, samples flagged in its ghost array (vtkGhostType, non-zero: another
   * process owns them) are never snapped to or stepped on.
   */
  explicit vtkOFBStrokePath(vtkOFB* ofb, bool ownedOnly = false);

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

  /**
   * On a distributed OFB (this process's piece, possibly without samples): `at[i]`, point
   * i moved onto the closest owned sample of every process (the point itself when no
   * process has a sample), and `paths[k]`, the path over the owned samples from point
   * `segments[k].first` to point `segments[k].second`, as Trace gives it (a chord when an
   * end did not move onto a sample). Every process calls it with the same points and
   * segments; each call of `exchange` is collective, and every process makes the same
   * calls: one for the frame, one per level of Snap's growing spheres (one level for
   * points on the surface), four for the points, then four per step of the longest path.
   */
  void PlaceDistributed(const std::vector<glm::dvec3>& points,
    const std::vector<std::pair<vtkIdType, vtkIdType>>& segments,
    vtkOFBStrokeExchange* exchange,
    std::vector<glm::dvec3>& at,
    std::vector<std::vector<glm::dvec3>>& paths);

  /// The length of a polyline.
  static double Length(const std::vector<glm::dvec3>& path, size_t first, size_t last);

private:
  /// A sample offered by a query (see the .cxx).
  struct Candidate;
  /// A path being walked (see the .cxx).
  struct Walk;

  glm::dvec3 Position(vtkIdType id) const;
  /// False when `normal` and the normal of sample `b` are more than 120 degrees apart.
  bool Facing(const double normal[3], vtkIdType b) const;
  /// Sample `id` as a candidate at `distance`.
  Candidate MakeCandidate(vtkIdType id, double distance) const;
  /// The closest (owned) sample to `x` and its squared distance `d2`, or -1.
  vtkIdType ClosestSample(const double x[3], double& d2) const;
  /// The radius of Snap's search sphere number `level` (from 0) around `x`.
  double SearchRadius(const double x[3], int level) const;
  /// The closest (owned) sample within `radius` of `x` and its squared distance, or -1.
  vtkIdType ClosestWithin(const double x[3], double radius, double& d2) const;
  /// Start walking from `from` to `to`: the first point of `path`.
  Walk Begin(const Candidate& from, const Candidate& to, std::vector<glm::dvec3>& path) const;
  /// False when the walk is over (the target, or the chord to it, then ends `path`).
  bool Continue(Walk& walk, std::vector<glm::dvec3>& path) const;
  /// The best next sample among this OFB's owned samples.
  Candidate Next(const Walk& walk) const;
  /// Step to `next` (the walk is over when it is none).
  void Take(Walk& walk, const Candidate& next, std::vector<glm::dvec3>& path) const;
  /// Every point on the closest owned sample of every process (collective).
  std::vector<Candidate> SnapDistributed(const std::vector<glm::dvec3>& points,
    vtkOFBStrokeExchange* exchange) const;
  /// Keep the best candidate of every process, for each of `candidates`.
  static void Reduce(std::vector<Candidate>& candidates, vtkOFBStrokeExchange* exchange);
  /// Reduce through one all-gather of every process's candidates (few of them).
  static void ReduceGathered(std::vector<Candidate>& candidates, vtkOFBStrokeExchange* exchange);

  vtkOFB* OFB;
  vtkFloatArray* Normals = nullptr;
  vtkUnsignedCharArray* Ghosts = nullptr;
  double Step = 0.0;
  double Diagonal = 0.0;
  bool Valid = false;
};

#endif
