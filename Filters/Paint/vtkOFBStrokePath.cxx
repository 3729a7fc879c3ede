#include "vtkOFBStrokePath.h"

#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBStrokeExchange.h"
#include "vtkPointData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
/// Steps of a walk, in cells.
constexpr double StepCells = 2.0;
/// The cosine of the largest turn between the normals of two consecutive samples.
constexpr double LargestTurnCosine = -0.5;
constexpr double Infinity = std::numeric_limits<double>::infinity();
/// The values of a candidate that processes exchange: distance, cell, depth, position,
/// normal.
constexpr size_t CandidateValues = 9;
/// The most values one all-gather of candidates receives (beyond: four all-reduces).
constexpr size_t GatheredValuesLimit = 4096;
}

/**
 * A sample offered by a query, with what every process needs to compare it and to walk
 * on from it: the measure compared (`Distance`), its key (`Cell`, the global cell index,
 * then `Depth`: the order of sample ids in any OFB of the common frame), its position and
 * normal (zero without normals). None: an infinite distance.
 */
struct vtkOFBStrokePath::Candidate
{
  double Distance = Infinity;
  double Cell = Infinity;
  double Depth = Infinity;
  double Position[3] = { 0.0, 0.0, 0.0 };
  double Normal[3] = { 0.0, 0.0, 0.0 };

  bool Found() const { return this->Distance < Infinity; }
  bool SameSample(const Candidate& other) const
  {
    return this->Cell == other.Cell && this->Depth == other.Depth;
  }
};

/// A path being walked: where it is, the normal there, and the target.
struct vtkOFBStrokePath::Walk
{
  glm::dvec3 At;
  glm::dvec3 Target;
  double Normal[3] = { 0.0, 0.0, 0.0 };
  double Distance = 0.0; // from At to Target
  double Most = 0.0;     // the bound on the steps
  double Steps = 0.0;
  bool Done = false;
};

//------------------------------------------------------------------------------
vtkOFBStrokePath::vtkOFBStrokePath(vtkOFB* ofb, bool ownedOnly)
  : OFB(ofb)
{
  if (!ofb || ofb->GetNumberOfSamples() == 0 || !(ofb->GetCellSize() > 0.0))
  {
    return;
  }
  this->Valid = true;
  this->Step = StepCells * ofb->GetCellSize();
  double b[6];
  ofb->GetBounds(b);
  this->Diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  vtkFloatArray* normals =
    vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray(vtkOFB::NormalsArrayName()));
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() >= ofb->GetNumberOfSamples())
  {
    this->Normals = normals;
  }
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    ofb->GetSampleData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (ownedOnly && ghosts && ghosts->GetNumberOfComponents() == 1 &&
    ghosts->GetNumberOfTuples() >= ofb->GetNumberOfSamples())
  {
    this->Ghosts = ghosts;
  }
}

//------------------------------------------------------------------------------
glm::dvec3 vtkOFBStrokePath::Position(vtkIdType id) const
{
  double x[3] = { 0.0, 0.0, 0.0 };
  this->OFB->GetSamplePosition(id, x);
  return glm::dvec3(x[0], x[1], x[2]);
}

//------------------------------------------------------------------------------
bool vtkOFBStrokePath::Facing(const double na[3], vtkIdType b) const
{
  if (!this->Normals)
  {
    return true;
  }
  const float* nb = this->Normals->GetPointer(3 * b);
  const double dot = na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2];
  const double la = na[0] * na[0] + na[1] * na[1] + na[2] * na[2];
  const double lb = double(nb[0]) * nb[0] + double(nb[1]) * nb[1] + double(nb[2]) * nb[2];
  // Samples without a normal (zero length) face every way.
  return !(dot < LargestTurnCosine * std::sqrt(la * lb));
}

//------------------------------------------------------------------------------
vtkOFBStrokePath::Candidate vtkOFBStrokePath::MakeCandidate(vtkIdType id, double distance) const
{
  Candidate c;
  if (id < 0)
  {
    return c;
  }
  c.Distance = distance;
  c.Cell = static_cast<double>(this->OFB->GetCellIndex()->GetValue(id));
  c.Depth = static_cast<double>(this->OFB->GetDepths()->GetValue(id));
  this->OFB->GetSamplePosition(id, c.Position);
  if (this->Normals)
  {
    const float* n = this->Normals->GetPointer(3 * id);
    std::copy(n, n + 3, c.Normal);
  }
  return c;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBStrokePath::Snap(const double x[3], double onSurface[3]) const
{
  double d2 = Infinity;
  const vtkIdType id = this->ClosestSample(x, d2);
  std::copy(x, x + 3, onSurface);
  if (id >= 0)
  {
    this->OFB->GetSamplePosition(id, onSurface);
  }
  return id;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBStrokePath::ClosestSample(const double x[3], double& d2) const
{
  d2 = Infinity;
  if (!this->Valid || !std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
  {
    return -1;
  }
  // Search spheres of growing radius: the first one with a sample holds the closest.
  for (int level = 0;; ++level)
  {
    const double r = this->SearchRadius(x, level);
    const vtkIdType id = this->ClosestWithin(x, r, d2);
    if (id >= 0 || !(r < Infinity))
    {
      return id;
    }
  }
}

//------------------------------------------------------------------------------
double vtkOFBStrokePath::SearchRadius(const double x[3], int level) const
{
  // sqrt(3) cells (a point on the surface has a sample that close), 4 times larger at
  // each level, then infinite once the sphere would reach past the frame.
  double b[6];
  this->OFB->GetBounds(b);
  double outside = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = std::max({ b[2 * k] - x[k], x[k] - b[2 * k + 1], 0.0 });
    outside += d * d;
  }
  const double farthest = std::sqrt(outside) + this->Diagonal;
  const double r = std::ldexp(std::sqrt(3.0) * this->OFB->GetCellSize(), 2 * level);
  return r < farthest ? r : Infinity;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBStrokePath::ClosestWithin(const double x[3], double radius, double& d2) const
{
  // As vtkOFB::FindClosestSample, over the owned samples.
  vtkIdType id = -1;
  double best = std::numeric_limits<double>::max();
  this->OFB->ForEachSampleInSphere(x,
    radius,
    [&](vtkIdType sample, double s2)
    {
      if ((s2 < best || (s2 == best && sample < id)) &&
        !(this->Ghosts && this->Ghosts->GetValue(sample)))
      {
        best = s2;
        id = sample;
      }
    });
  d2 = id >= 0 ? best : Infinity;
  return id;
}

//------------------------------------------------------------------------------
vtkOFBStrokePath::Walk vtkOFBStrokePath::Begin(const Candidate& from,
  const Candidate& to,
  std::vector<glm::dvec3>& path) const
{
  Walk w;
  w.At = glm::dvec3(from.Position[0], from.Position[1], from.Position[2]);
  w.Target = glm::dvec3(to.Position[0], to.Position[1], to.Position[2]);
  std::copy(from.Normal, from.Normal + 3, w.Normal);
  path.push_back(w.At);
  w.Done = from.SameSample(to);
  // Each step gets closer to the target by at least a thousandth of a step, so a walk
  // ends; the bound on the steps is far above any path that does.
  w.Distance = glm::length(w.Target - w.At);
  w.Most = 64.0 + 16.0 * (w.Distance + this->Diagonal) / this->Step;
  return w;
}

//------------------------------------------------------------------------------
bool vtkOFBStrokePath::Continue(Walk& w, std::vector<glm::dvec3>& path) const
{
  if (w.Done)
  {
    return false;
  }
  if (!(w.Steps < w.Most) || w.Distance <= this->Step)
  {
    path.push_back(w.Target);
    w.Done = true;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkOFBStrokePath::Candidate vtkOFBStrokePath::Next(const Walk& w) const
{
  if (!this->Valid)
  {
    return Candidate();
  }
  vtkIdType best = -1;
  double bestDistance = w.Distance - 1e-3 * this->Step;
  const double c[3] = { w.At.x, w.At.y, w.At.z };
  this->OFB->ForEachSampleInSphere(c,
    this->Step,
    [&](vtkIdType id, double)
    {
      if (this->Ghosts && this->Ghosts->GetValue(id))
      {
        return;
      }
      const double d = glm::length(w.Target - this->Position(id));
      if (d < bestDistance && this->Facing(w.Normal, id))
      {
        bestDistance = d;
        best = id;
      }
    });
  return this->MakeCandidate(best, bestDistance);
}

//------------------------------------------------------------------------------
void vtkOFBStrokePath::Take(Walk& w, const Candidate& next, std::vector<glm::dvec3>& path) const
{
  if (!next.Found())
  {
    // No nearby sample gets closer: the chord to the target.
    path.push_back(w.Target);
    w.Done = true;
    return;
  }
  w.At = glm::dvec3(next.Position[0], next.Position[1], next.Position[2]);
  std::copy(next.Normal, next.Normal + 3, w.Normal);
  w.Distance = next.Distance;
  w.Steps += 1.0;
  path.push_back(w.At);
}

//------------------------------------------------------------------------------
bool vtkOFBStrokePath::Trace(vtkIdType from, vtkIdType to, std::vector<glm::dvec3>& path) const
{
  Walk w = this->Begin(this->MakeCandidate(from, 0.0), this->MakeCandidate(to, 0.0), path);
  if (w.Done)
  {
    return true;
  }
  while (this->Continue(w, path))
  {
    this->Take(w, this->Next(w), path);
  }
  return w.Distance <= this->Step;
}

//------------------------------------------------------------------------------
void vtkOFBStrokePath::Reduce(std::vector<Candidate>& c, vtkOFBStrokeExchange* exchange)
{
  // The smallest distance, then among those the smallest cell, then depth: one winner
  // (owned samples are on one process only), whose position and normal every process
  // then takes (a minimum of their negatives against the others' infinities: exact).
  // Few candidates (a walk across a large surface, a round after another) go in one
  // all-gather, whose latency is that of one all-reduce: the same winner.
  const size_t n = c.size();
  if (n * CandidateValues * static_cast<size_t>(exchange->GetNumberOfProcesses()) <=
    GatheredValuesLimit)
  {
    ReduceGathered(c, exchange);
    return;
  }
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i)
  {
    v[i] = c[i].Distance;
  }
  exchange->AllReduceMinimum(v);
  for (size_t i = 0; i < n; ++i)
  {
    if (!(c[i].Distance == v[i]))
    {
      c[i].Cell = c[i].Depth = Infinity;
    }
    c[i].Distance = v[i];
    v[i] = c[i].Cell;
  }
  exchange->AllReduceMinimum(v);
  for (size_t i = 0; i < n; ++i)
  {
    if (!(c[i].Cell == v[i]))
    {
      c[i].Depth = Infinity;
    }
    c[i].Cell = v[i];
    v[i] = c[i].Depth;
  }
  exchange->AllReduceMinimum(v);
  std::vector<double> payload(6 * n, Infinity);
  for (size_t i = 0; i < n; ++i)
  {
    if (c[i].Depth == v[i] && c[i].Found())
    {
      for (int k = 0; k < 3; ++k)
      {
        payload[6 * i + k] = -c[i].Position[k];
        payload[6 * i + 3 + k] = -c[i].Normal[k];
      }
    }
    c[i].Depth = v[i];
  }
  exchange->AllReduceMinimum(payload);
  for (size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[i].Position[k] = -payload[6 * i + k];
      c[i].Normal[k] = -payload[6 * i + 3 + k];
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBStrokePath::ReduceGathered(std::vector<Candidate>& c, vtkOFBStrokeExchange* exchange)
{
  const size_t n = c.size();
  std::vector<double> local(CandidateValues * n);
  for (size_t i = 0; i < n; ++i)
  {
    double* v = local.data() + CandidateValues * i;
    v[0] = c[i].Distance;
    v[1] = c[i].Cell;
    v[2] = c[i].Depth;
    std::copy(c[i].Position, c[i].Position + 3, v + 3);
    std::copy(c[i].Normal, c[i].Normal + 3, v + 6);
  }
  std::vector<double> all;
  exchange->AllGather(local, all);
  const size_t processes = n > 0 ? all.size() / (CandidateValues * n) : 0;
  for (size_t i = 0; i < n; ++i)
  {
    // The smallest (distance, cell, depth) of every process's offer, as Reduce keeps it.
    const double* best = nullptr;
    for (size_t p = 0; p < processes; ++p)
    {
      const double* v = all.data() + CandidateValues * (p * n + i);
      if (!best || std::lexicographical_compare(v, v + 3, best, best + 3))
      {
        best = v;
      }
    }
    Candidate& winner = c[i];
    winner.Distance = best ? best[0] : Infinity;
    const bool found = winner.Found();
    winner.Cell = found ? best[1] : Infinity;
    winner.Depth = found ? best[2] : Infinity;
    for (int k = 0; k < 3; ++k)
    {
      // None found: what Reduce's minimum of negatives gives.
      winner.Position[k] = found ? best[3 + k] : -Infinity;
      winner.Normal[k] = found ? best[6 + k] : -Infinity;
    }
  }
}

//------------------------------------------------------------------------------
std::vector<vtkOFBStrokePath::Candidate> vtkOFBStrokePath::SnapDistributed(
  const std::vector<glm::dvec3>& points,
  vtkOFBStrokeExchange* exchange) const
{
  // Every point onto the closest owned sample of every process: the spheres of Snap,
  // level by level on every process, until some process has a sample in a point's
  // sphere (then that sphere holds the closest of all, as on one process), or every
  // process has searched everywhere.
  std::vector<Candidate> onSurface(points.size());
  std::vector<size_t> open(points.size());
  for (size_t i = 0; i < points.size(); ++i)
  {
    open[i] = i;
  }
  std::vector<double> found;
  for (int level = 0; !open.empty(); ++level)
  {
    found.assign(open.size() + 1, Infinity);
    bool searchedEverywhere = true;
    for (size_t j = 0; this->Valid && j < open.size(); ++j)
    {
      const double x[3] = { points[open[j]].x, points[open[j]].y, points[open[j]].z };
      const double r = this->SearchRadius(x, level);
      searchedEverywhere = searchedEverywhere && !(r < Infinity);
      double d2 = Infinity;
      const vtkIdType id = this->ClosestWithin(x, r, d2);
      onSurface[open[j]] = this->MakeCandidate(id, d2);
      found[j] = d2;
    }
    found.back() = searchedEverywhere ? 0.0 : -1.0;
    exchange->AllReduceMinimum(found);
    const bool last = found.back() == 0.0;
    size_t kept = 0;
    for (size_t j = 0; j < open.size(); ++j)
    {
      if (!(found[j] < Infinity) && !last)
      {
        open[kept++] = open[j];
      }
    }
    open.resize(kept);
  }
  Reduce(onSurface, exchange);
  return onSurface;
}

//------------------------------------------------------------------------------
void vtkOFBStrokePath::PlaceDistributed(const std::vector<glm::dvec3>& points,
  const std::vector<std::pair<vtkIdType, vtkIdType>>& segments,
  vtkOFBStrokeExchange* exchange,
  std::vector<glm::dvec3>& at,
  std::vector<std::vector<glm::dvec3>>& paths)
{
  // The step and the frame's diagonal of the processes that have samples (a piece
  // without samples may have no frame).
  std::vector<double> frame = { -this->Step, -this->Diagonal };
  exchange->AllReduceMinimum(frame);
  this->Step = -frame[0];
  this->Diagonal = -frame[1];

  const std::vector<Candidate> onSurface = this->SnapDistributed(points, exchange);
  at.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i)
  {
    const double* p = onSurface[i].Position;
    at[i] = onSurface[i].Found() ? glm::dvec3(p[0], p[1], p[2]) : points[i];
  }

  // Every path walked at once, a step of each in every round: the candidates of every
  // process for each walk's next sample, reduced to the best.
  paths.assign(segments.size(), std::vector<glm::dvec3>());
  std::vector<Walk> walks(segments.size());
  for (size_t k = 0; k < segments.size(); ++k)
  {
    const Candidate& a = onSurface[segments[k].first];
    const Candidate& b = onSurface[segments[k].second];
    if (a.Found() && b.Found() && this->Step > 0.0)
    {
      walks[k] = this->Begin(a, b, paths[k]);
    }
    else
    {
      paths[k] = { at[segments[k].first], at[segments[k].second] };
      walks[k].Done = true;
    }
  }
  std::vector<size_t> active;
  std::vector<Candidate> next;
  for (;;)
  {
    active.clear();
    for (size_t k = 0; k < walks.size(); ++k)
    {
      if (this->Continue(walks[k], paths[k]))
      {
        active.push_back(k);
      }
    }
    if (active.empty())
    {
      break;
    }
    next.resize(active.size());
    for (size_t j = 0; j < active.size(); ++j)
    {
      next[j] = this->Next(walks[active[j]]);
    }
    Reduce(next, exchange);
    for (size_t j = 0; j < active.size(); ++j)
    {
      this->Take(walks[active[j]], next[j], paths[active[j]]);
    }
  }
}

//------------------------------------------------------------------------------
double vtkOFBStrokePath::Length(const std::vector<glm::dvec3>& path, size_t first, size_t last)
{
  double length = 0.0;
  for (size_t i = first + 1; i <= last && i < path.size(); ++i)
  {
    length += glm::length(path[i] - path[i - 1]);
  }
  return length;
}
