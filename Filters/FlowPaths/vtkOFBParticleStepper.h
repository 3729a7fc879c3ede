/**
 * @class   vtkOFBParticleStepper
 * @brief   One integration step of a surface particle (private)
 *
 * Euler, midpoint (RK2), classical Runge-Kutta (RK4) and Cash-Karp RK45 with
 * step-size control, on the surface of a vtkOFBTriangleWalker. Every stage is a
 * walk from the start point along a combination of the slopes found so far; the
 * slope at the stage's end is carried back into the start triangle's plane by the
 * inverse of the walk's turns (the unfolding of the triangles crossed), so all
 * slopes are combined in one plane and the final displacement is walked from the
 * start like the stages.
 *
 * The slope is the field times `Scale` (1 / the largest speed, so that the
 * fastest point moves `Length` per step) or, with `Normalize`, the unit field
 * (every particle moves `Length` of arc per step). `Sign` is -1 for backward
 * tracing. Where the field is shorter than `StopSpeed` (world units) the particle
 * stops.
 */

#ifndef vtkOFBParticleStepper_h
#define vtkOFBParticleStepper_h

#include "vtkOFBTriangleWalker.h"

class vtkOFBParticleStepper
{
public:
  enum Method
  {
    EULER = 0,
    RK2 = 1,
    RK4 = 2,
    RK45 = 3
  };

  /// How a step ended.
  enum Result
  {
    MOVED = 0,
    STOPPED_AT_BOUNDARY = 1,
    STOPPED_AT_ZERO = 2
  };

  const vtkOFBTriangleWalker* Walker = nullptr;
  int Integrator = RK4;
  bool Normalize = true;
  double Sign = 1.0;
  double Scale = 1.0;
  double StopSpeed = 0.0;
  /// Length of a step (world units).
  double Length = 1.0;
  /// RK45: largest error of a sub-step (world units).
  double Tolerance = 1e-3;

  /// The most particles `Advance` takes in one call.
  static constexpr int MaximumBatch = 16;

  /**
   * Advance `p` by one step. `subStep` is the RK45 sub-step length carried from
   * the particle's previous step (0 at first; updated).
   */
  Result Advance(vtkOFBSurfacePoint& p, double& subStep) const;

  /**
   * Advance `n` (at most MaximumBatch) particles by one step each, with the same
   * result for each as `Advance` alone (bit for bit). The stages go across the
   * particles (the first stage of all, then the second...) in structure-of-arrays
   * form: every stage starts from the particle's own triangle, so its record is
   * read once per step, and the stage points that stay in that triangle (most of
   * them) are computed for all the batch at once in SIMD loops without branches;
   * only the stages that cross an edge walk, one particle at a time.
   */
  void Advance(int n,
    vtkOFBSurfacePoint* const* points,
    double* const* subSteps,
    Result* results) const;

  /// The slope at `p` in its triangle's 2-D frame; false where the field is zero.
  bool Slope(const vtkOFBSurfacePoint& p, glm::dvec2& slope) const;

private:
  struct Batch;
  /// Batch: the records of the start triangles and the first slopes.
  void BatchStart(Batch& b, int n, vtkOFBSurfacePoint* const* points) const;
  /// Batch: the slopes at `c` times the current slopes from the start (one stage).
  void BatchStage(Batch& b, int n, vtkOFBSurfacePoint* const* points, double c) const;
  /// Batch: the walk of `c` times the sums of the slopes.
  void BatchFinal(Batch& b,
    int n,
    vtkOFBSurfacePoint* const* points,
    double c,
    Result* results) const;
  /// The slope at the end of a walk from `p` along `d` that leaves p's triangle.
  glm::dvec2 CrossingSlope(const vtkOFBSurfacePoint& p, const glm::dvec2& d) const;
  /// The slope at the end of a walk from `p` along `d`, in p's plane.
  glm::dvec2 StageSlope(const vtkOFBSurfacePoint& p, const glm::dvec2& d) const;
  Result Final(vtkOFBSurfacePoint& p, const glm::dvec2& d) const;
  Result AdvanceRK45(vtkOFBSurfacePoint& p, double& subStep) const;
  /// One Cash-Karp step of length h from p: displacement and error length.
  glm::dvec2 CashKarp(const vtkOFBSurfacePoint& p,
    const glm::dvec2& k1,
    double h,
    double& error) const;
};

// Inline: called for every stage of every particle.
inline bool vtkOFBParticleStepper::Slope(const vtkOFBSurfacePoint& p, glm::dvec2& slope) const
{
  const glm::dvec2 v = this->Walker->Field2(p);
  const double speed = glm::length(v);
  if (!(speed > this->StopSpeed))
  {
    slope = glm::dvec2(0.0);
    return false;
  }
  slope = this->Sign * (this->Normalize ? v / speed : v * this->Scale);
  return true;
}

inline glm::dvec2 vtkOFBParticleStepper::StageSlope(const vtkOFBSurfacePoint& p,
  const glm::dvec2& d) const
{
  vtkOFBSurfacePoint q = p;
  glm::dvec2 slope;
  if (this->Walker->WalkInside(q, d))
  {
    // No edge crossed: the slope is in p's frame already.
    this->Slope(q, slope);
    return slope;
  }
  return this->CrossingSlope(p, d);
}

inline glm::dvec2 vtkOFBParticleStepper::CrossingSlope(const vtkOFBSurfacePoint& p,
  const glm::dvec2& d) const
{
  vtkOFBSurfacePoint q = p;
  glm::dmat2 frame(1.0);
  this->Walker->Walk(q, d, &frame);
  glm::dvec2 slope;
  this->Slope(q, slope);
  // Back into p's frame: the turns are orthogonal, their inverse is the transpose.
  return glm::transpose(frame) * slope;
}

#endif
