#include "vtkOFBParticleStepper.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
vtkOFBParticleStepper::Result vtkOFBParticleStepper::Final(vtkOFBSurfacePoint& p,
  const glm::dvec2& d) const
{
  if (this->Walker->WalkInside(p, d))
  {
    return MOVED;
  }
  const auto walk = this->Walker->Walk(p, d, nullptr);
  return walk == vtkOFBTriangleWalker::WALK_BOUNDARY ? STOPPED_AT_BOUNDARY : MOVED;
}

//------------------------------------------------------------------------------
vtkOFBParticleStepper::Result vtkOFBParticleStepper::Advance(vtkOFBSurfacePoint& p,
  double& subStep) const
{
  glm::dvec2 k1;
  if (!this->Slope(p, k1))
  {
    return STOPPED_AT_ZERO;
  }
  const double h = this->Length;
  switch (this->Integrator)
  {
    case EULER:
      return this->Final(p, h * k1);
    case RK2:
    {
      const glm::dvec2 k2 = this->StageSlope(p, 0.5 * h * k1);
      return this->Final(p, h * k2);
    }
    case RK45:
      return this->AdvanceRK45(p, subStep);
    case RK4:
    default:
    {
      const glm::dvec2 k2 = this->StageSlope(p, 0.5 * h * k1);
      const glm::dvec2 k3 = this->StageSlope(p, 0.5 * h * k2);
      const glm::dvec2 k4 = this->StageSlope(p, h * k3);
      return this->Final(p, (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
    }
  }
}

//------------------------------------------------------------------------------
// A batch in structure-of-arrays form, one lane per particle: the start triangle's
// record in double, the start barycentrics, the current slope and the sum of the
// slopes. The arithmetic of each lane is that of Advance, in the same order, so
// the results are the same bit for bit (the loops over the lanes vectorize; a lane
// past `n` holds zeros and is never written back).
struct vtkOFBParticleStepper::Batch
{
  static constexpr int Size = MaximumBatch;
  double G[4][Size]; // gradients of barycentrics 0 and 1: g0.x, g0.y, g1.x, g1.y
  double V[6][Size]; // the corner vectors: v0.x, v0.y, v1.x, v1.y, v2.x, v2.y
  double B[3][Size]; // the start barycentrics
  double K[2][Size]; // the current slope
  double S[2][Size]; // the sum of the weighted slopes
  double D[2][Size]; // the displacement of the current stage
  int Count;         // the lanes computed: n rounded up to the SIMD pairs
  // 1 or 0, in double: the loops then hold one type only and vectorize.
  double Moving[Size];
  double Leaves[Size]; // the stage's walk leaves the start triangle
};

namespace
{
constexpr int Lanes = vtkOFBParticleStepper::MaximumBatch;

// The rates of the barycentrics along (dx, dy) (vtkOFBWalkerTriangle::Rates), the
// barycentrics moved by them `q` (vtkOFBTriangleWalker::WalkInside), whether the
// walk leaves the triangle, and the field at q (vtkOFBTriangleWalker::Field2).
// Straight-line code: the loops over the lanes that call it vectorize.
inline bool MoveLane(const double (&g)[4][Lanes],
  const double (&b)[3][Lanes],
  const double (&v)[6][Lanes],
  int j,
  double dx,
  double dy,
  double (&q)[3],
  double& vx,
  double& vy)
{
  const double r0 = g[0][j] * dx + g[1][j] * dy;
  const double r1 = g[2][j] * dx + g[3][j] * dy;
  const double r2 = -(r0 + r1);
  const bool leaves = ((r0 < 0.0) & (b[0][j] < -r0)) | ((r1 < 0.0) & (b[1][j] < -r1)) |
    ((r2 < 0.0) & (b[2][j] < -r2));
  const double m0 = b[0][j] + r0;
  const double m1 = b[1][j] + r1;
  const double m2 = b[2][j] + r2;
  q[0] = m0 < 0.0 ? 0.0 : m0;
  q[1] = m1 < 0.0 ? 0.0 : m1;
  q[2] = m2 < 0.0 ? 0.0 : m2;
  vx = q[0] * v[0][j] + q[1] * v[2][j] + q[2] * v[4][j];
  vy = q[0] * v[1][j] + q[1] * v[3][j] + q[2] * v[5][j];
  return leaves;
}

// The slope of the field (vx, vy) as vtkOFBParticleStepper::Slope, 0 where the
// speed is not above `stop`; both forms are computed, so the loops vectorize.
inline bool LaneSlope(double vx,
  double vy,
  double stop,
  double sign,
  double scale,
  bool normalize,
  double& kx,
  double& ky)
{
  const double speed = std::sqrt(vx * vx + vy * vy);
  const bool fast = speed > stop;
  const double divisor = fast ? speed : 1.0;
  const double ux = vx / divisor;
  const double uy = vy / divisor;
  const double sx = vx * scale;
  const double sy = vy * scale;
  const double nx = sign * (normalize ? ux : sx);
  const double ny = sign * (normalize ? uy : sy);
  kx = fast ? nx : 0.0;
  ky = fast ? ny : 0.0;
  return fast;
}
}

//------------------------------------------------------------------------------
void vtkOFBParticleStepper::BatchStart(Batch& b, int n, vtkOFBSurfacePoint* const* points) const
{
  // Small batches (the ends of the threads' ranges) compute only their own lanes.
  b.Count = std::min(Lanes, (n + 1) & ~1);
  for (int j = 0; j < b.Count; ++j)
  {
    if (j < n)
    {
      const vtkOFBWalkerTriangle& r = this->Walker->GetRecord(points[j]->Triangle);
      b.G[0][j] = r.Gradient[0][0];
      b.G[1][j] = r.Gradient[0][1];
      b.G[2][j] = r.Gradient[1][0];
      b.G[3][j] = r.Gradient[1][1];
      for (int i = 0; i < 3; ++i)
      {
        b.V[2 * i][j] = r.Vector[i][0];
        b.V[2 * i + 1][j] = r.Vector[i][1];
        b.B[i][j] = points[j]->Bary[i];
      }
    }
    else
    {
      for (int i = 0; i < 4; ++i)
      {
        b.G[i][j] = 0.0;
      }
      for (int i = 0; i < 6; ++i)
      {
        b.V[i][j] = 0.0;
      }
      for (int i = 0; i < 3; ++i)
      {
        b.B[i][j] = 0.0;
      }
    }
  }
  // The first slope, at the start (Slope).
  const double stop = this->StopSpeed;
  const double sign = this->Sign;
  const double scale = this->Scale;
  const bool normalize = this->Normalize;
  for (int j = 0; j < b.Count; ++j)
  {
    const double vx = b.B[0][j] * b.V[0][j] + b.B[1][j] * b.V[2][j] + b.B[2][j] * b.V[4][j];
    const double vy = b.B[0][j] * b.V[1][j] + b.B[1][j] * b.V[3][j] + b.B[2][j] * b.V[5][j];
    double kx, ky;
    b.Moving[j] = LaneSlope(vx, vy, stop, sign, scale, normalize, kx, ky) ? 1.0 : 0.0;
    b.K[0][j] = kx;
    b.K[1][j] = ky;
    b.S[0][j] = kx;
    b.S[1][j] = ky;
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleStepper::BatchStage(Batch& b,
  int n,
  vtkOFBSurfacePoint* const* points,
  double c) const
{
  const double stop = this->StopSpeed;
  const double sign = this->Sign;
  const double scale = this->Scale;
  const bool normalize = this->Normalize;
  // Every lane as if its walk stayed in the start triangle (StageSlope's first case):
  // the field there, then its slope. A lane that does not move has a zero slope: it
  // stays where it is, so its slope stays zero and it never leaves.
  double v[2][Lanes];
  for (int j = 0; j < b.Count; ++j)
  {
    const double dx = c * b.K[0][j];
    const double dy = c * b.K[1][j];
    double q[3];
    b.Leaves[j] = MoveLane(b.G, b.B, b.V, j, dx, dy, q, v[0][j], v[1][j]) ? 1.0 : 0.0;
    b.D[0][j] = dx;
    b.D[1][j] = dy;
  }
  for (int j = 0; j < b.Count; ++j)
  {
    LaneSlope(v[0][j], v[1][j], stop, sign, scale, normalize, b.K[0][j], b.K[1][j]);
  }
  // The walks that leave, interleaved, then the slopes at their ends carried back
  // (CrossingSlope).
  vtkOFBWalkLanes walks;
  int lane[Lanes];
  // Collected without branches (which lanes leave is unpredictable): every lane is
  // written to the next free place, which only a leaving lane keeps.
  for (int j = 0; j < n; ++j)
  {
    lane[walks.Count] = j;
    walks.Set(walks.Count, *points[j], b.D[0][j], b.D[1][j]);
    walks.Count += b.Leaves[j] != 0.0;
  }
  if (walks.Count == 0)
  {
    return;
  }
  this->Walker->Walk(walks, true);
  for (int w = 0; w < walks.Count; ++w)
  {
    vtkOFBSurfacePoint q;
    walks.Get(w, q);
    // The step usually ends near the stage points: the caller reads the corners of
    // where it ends.
    this->Walker->PrefetchCorners(q.Triangle);
    glm::dvec2 slope;
    this->Slope(q, slope);
    const glm::dmat2 frame(
      walks.Frame[0][w], walks.Frame[1][w], walks.Frame[2][w], walks.Frame[3][w]);
    const glm::dvec2 k = glm::transpose(frame) * slope;
    b.K[0][lane[w]] = k[0];
    b.K[1][lane[w]] = k[1];
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleStepper::BatchFinal(Batch& b,
  int n,
  vtkOFBSurfacePoint* const* points,
  double c,
  Result* results) const
{
  double moved[3][Lanes];
  for (int j = 0; j < b.Count; ++j)
  {
    const double dx = c * b.S[0][j];
    const double dy = c * b.S[1][j];
    double q[3], vx, vy;
    b.Leaves[j] = MoveLane(b.G, b.B, b.V, j, dx, dy, q, vx, vy) ? 1.0 : 0.0;
    moved[0][j] = q[0];
    moved[1][j] = q[1];
    moved[2][j] = q[2];
    b.D[0][j] = dx;
    b.D[1][j] = dy;
  }
  vtkOFBWalkLanes walks;
  int lane[Lanes];
  // Without branches as in BatchStage: a lane that does not move has a zero sum, so
  // its moved barycentrics are its own; a lane that leaves is set from where it
  // started and its walk's end overwrites the moved barycentrics.
  for (int j = 0; j < n; ++j)
  {
    vtkOFBSurfacePoint& p = *points[j];
    lane[walks.Count] = j;
    walks.Set(walks.Count, p, b.D[0][j], b.D[1][j]);
    walks.Count += b.Leaves[j] != 0.0;
    p.Bary = glm::dvec3(moved[0][j], moved[1][j], moved[2][j]);
    results[j] = b.Moving[j] != 0.0 ? MOVED : STOPPED_AT_ZERO;
    // The caller reads the corners of where it ended next.
    this->Walker->PrefetchCorners(p.Triangle);
  }
  // The walks that leave the start triangle, interleaved (Final).
  this->Walker->Walk(walks, false);
  for (int w = 0; w < walks.Count; ++w)
  {
    const int j = lane[w];
    walks.Get(w, *points[j]);
    results[j] =
      walks.Result[w] == vtkOFBTriangleWalker::WALK_BOUNDARY ? STOPPED_AT_BOUNDARY : MOVED;
    this->Walker->PrefetchCorners(points[j]->Triangle);
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleStepper::Advance(int n,
  vtkOFBSurfacePoint* const* points,
  double* const* subSteps,
  Result* results) const
{
  if (this->Integrator == RK45 || n > MaximumBatch)
  {
    for (int j = 0; j < n; ++j)
    {
      results[j] = this->Advance(*points[j], *subSteps[j]);
    }
    return;
  }
  // The stages of Advance (Euler, RK2, RK4), each for all particles in turn.
  const double h = this->Length;
  Batch b;
  this->BatchStart(b, n, points);
  if (this->Integrator == RK2)
  {
    this->BatchStage(b, n, points, 0.5 * h);
    for (int j = 0; j < b.Count; ++j)
    {
      b.S[0][j] = b.K[0][j];
      b.S[1][j] = b.K[1][j];
    }
  }
  else if (this->Integrator == RK4)
  {
    static const double along[3] = { 0.5, 0.5, 1.0 };
    static const double weight[3] = { 2.0, 2.0, 1.0 };
    for (int stage = 0; stage < 3; ++stage)
    {
      this->BatchStage(b, n, points, along[stage] * h);
      for (int j = 0; j < b.Count; ++j)
      {
        b.S[0][j] += weight[stage] * b.K[0][j];
        b.S[1][j] += weight[stage] * b.K[1][j];
      }
    }
  }
  this->BatchFinal(b, n, points, this->Integrator == RK4 ? h / 6.0 : h, results);
}

//------------------------------------------------------------------------------
glm::dvec2 vtkOFBParticleStepper::CashKarp(const vtkOFBSurfacePoint& p,
  const glm::dvec2& k1,
  double h,
  double& error) const
{
  // Cash-Karp coefficients (as vtkRungeKutta45).
  const glm::dvec2 k2 = this->StageSlope(p, h * (1.0 / 5.0) * k1);
  const glm::dvec2 k3 = this->StageSlope(p, h * ((3.0 / 40.0) * k1 + (9.0 / 40.0) * k2));
  const glm::dvec2 k4 =
    this->StageSlope(p, h * ((3.0 / 10.0) * k1 - (9.0 / 10.0) * k2 + (6.0 / 5.0) * k3));
  const glm::dvec2 k5 = this->StageSlope(
    p, h * ((-11.0 / 54.0) * k1 + (5.0 / 2.0) * k2 - (70.0 / 27.0) * k3 + (35.0 / 27.0) * k4));
  const glm::dvec2 k6 = this->StageSlope(p,
    h *
      ((1631.0 / 55296.0) * k1 + (175.0 / 512.0) * k2 + (575.0 / 13824.0) * k3 +
        (44275.0 / 110592.0) * k4 + (253.0 / 4096.0) * k5));
  const glm::dvec2 fifth =
    (37.0 / 378.0) * k1 + (250.0 / 621.0) * k3 + (125.0 / 594.0) * k4 + (512.0 / 1771.0) * k6;
  const glm::dvec2 fourth = (2825.0 / 27648.0) * k1 + (18575.0 / 48384.0) * k3 +
    (13525.0 / 55296.0) * k4 + (277.0 / 14336.0) * k5 + 0.25 * k6;
  error = h * glm::length(fifth - fourth);
  return h * fifth;
}

//------------------------------------------------------------------------------
vtkOFBParticleStepper::Result vtkOFBParticleStepper::AdvanceRK45(vtkOFBSurfacePoint& p,
  double& subStep) const
{
  // Sub-steps with error control whose lengths add up to exactly one step.
  const double minimum = this->Length / 64.0;
  double h = subStep > 0.0 ? std::min(std::max(subStep, minimum), this->Length) : this->Length;
  double left = this->Length;
  for (int iteration = 0; left > 0.0 && iteration < 1000; ++iteration)
  {
    const bool last = h >= left;
    const double length = last ? left : h;
    glm::dvec2 k1;
    if (!this->Slope(p, k1))
    {
      return STOPPED_AT_ZERO;
    }
    double error = 0.0;
    const glm::dvec2 d = this->CashKarp(p, k1, length, error);
    if (error > this->Tolerance && length > minimum)
    {
      const double shrink = 0.9 * std::pow(this->Tolerance / error, 0.25);
      h = std::max(minimum, length * std::max(0.1, shrink));
      continue;
    }
    if (this->Final(p, d) == STOPPED_AT_BOUNDARY)
    {
      return STOPPED_AT_BOUNDARY;
    }
    left = last ? 0.0 : left - length;
    const double grow = error > 0.0 ? 0.9 * std::pow(this->Tolerance / error, 0.2) : 5.0;
    if (!last || length == h)
    {
      h = std::min(this->Length, length * std::min(5.0, std::max(1.0, grow)));
    }
    subStep = h;
  }
  return MOVED;
}
