#include "vtkOFBParticleStepper.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
vtkOFBParticleStepper::Result vtkOFBParticleStepper::Final(vtkOFBSurfacePoint& p,
  const glm::dvec2& d) const
{
  if (this->Walker->WalkInside(p, d))
  {
    return Moved;
  }
  const auto walk = this->Walker->Walk(p, d, nullptr);
  return walk == vtkOFBTriangleWalker::Boundary ? StoppedAtBoundary : Moved;
}

//------------------------------------------------------------------------------
vtkOFBParticleStepper::Result vtkOFBParticleStepper::Advance(vtkOFBSurfacePoint& p,
  double& subStep) const
{
  glm::dvec2 k1;
  if (!this->Slope(p, k1))
  {
    return StoppedAtZero;
  }
  const double h = this->Length;
  switch (this->Integrator)
  {
    case Euler:
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
  glm::dvec2 k[MaximumBatch];
  glm::dvec2 sum[MaximumBatch];
  bool moving[MaximumBatch];
  for (int j = 0; j < n; ++j)
  {
    moving[j] = this->Slope(*points[j], k[j]);
    results[j] = moving[j] ? Moved : StoppedAtZero;
    sum[j] = k[j];
  }
  if (this->Integrator == RK2)
  {
    for (int j = 0; j < n; ++j)
    {
      sum[j] = moving[j] ? this->StageSlope(*points[j], 0.5 * h * k[j]) : sum[j];
    }
  }
  else if (this->Integrator == RK4)
  {
    static const double along[3] = { 0.5, 0.5, 1.0 };
    static const double weight[3] = { 2.0, 2.0, 1.0 };
    for (int stage = 0; stage < 3; ++stage)
    {
      for (int j = 0; j < n; ++j)
      {
        if (moving[j])
        {
          k[j] = this->StageSlope(*points[j], along[stage] * h * k[j]);
          sum[j] += weight[stage] * k[j];
        }
      }
    }
  }
  const double scale = this->Integrator == RK4 ? h / 6.0 : h;
  for (int j = 0; j < n; ++j)
  {
    if (moving[j])
    {
      results[j] = this->Final(*points[j], scale * sum[j]);
      // The caller reads the corners of where it ended next.
      this->Walker->PrefetchCorners(points[j]->Triangle);
    }
  }
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
      return StoppedAtZero;
    }
    double error = 0.0;
    const glm::dvec2 d = this->CashKarp(p, k1, length, error);
    if (error > this->Tolerance && length > minimum)
    {
      const double shrink = 0.9 * std::pow(this->Tolerance / error, 0.25);
      h = std::max(minimum, length * std::max(0.1, shrink));
      continue;
    }
    if (this->Final(p, d) == StoppedAtBoundary)
    {
      return StoppedAtBoundary;
    }
    left = last ? 0.0 : left - length;
    const double grow = error > 0.0 ? 0.9 * std::pow(this->Tolerance / error, 0.2) : 5.0;
    if (!last || length == h)
    {
      h = std::min(this->Length, length * std::min(5.0, std::max(1.0, grow)));
    }
    subStep = h;
  }
  return Moved;
}
