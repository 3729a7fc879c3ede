// vtkOFBParticleAdvector on a surface distributed over processes (with Exchange set by
// vtkOFBPParticleAdvector): which triangles and particles this process owns, the seeds
// located over every process, and the exchange of the particles after each step.
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleAdvectorInternals.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLine.h"
#include "vtkNew.h"
#include "vtkOFBParticleExchange.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
// A particle's state as sent after a step: id, rank, position, previous position,
// sub-step, age, status, painted, colour, left (its triangle is a ghost), and where it
// left: the centroid of its triangle and its barycentric coordinates there.
constexpr int RecordSize = 23;
constexpr double Unclaimed = std::numeric_limits<double>::max();

/// The centroid of triangle t of `triangles` (the same on every process that has it).
void Centroid(vtkPolyData* triangles, vtkIdType t, double c[3])
{
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  triangles->GetCellPoints(t, npts, pts);
  c[0] = c[1] = c[2] = 0.0;
  for (vtkIdType k = 0; k < npts; ++k)
  {
    double x[3];
    triangles->GetPoint(pts[k], x);
    for (int j = 0; j < 3; ++j)
    {
      c[j] += x[j];
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    c[j] /= static_cast<double>(npts > 0 ? npts : 1);
  }
}
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::FindOwnedTriangles(vtkPolyData* surface,
  const std::vector<vtkIdType>& polygonCells)
{
  // A triangle is owned unless its input cell is a ghost cell.
  std::vector<unsigned char>& owned = this->Internals->TriangleOwned;
  const vtkIdType n = this->Internals->Walker.GetTriangles()->GetNumberOfCells();
  owned.assign(n, 1);
  vtkDataArray* ghosts = surface->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  for (vtkIdType t = 0; ghosts && static_cast<vtkIdType>(polygonCells.size()) == n && t < n; ++t)
  {
    const vtkIdType cell = polygonCells[t];
    owned[t] = cell >= 0 && cell < ghosts->GetNumberOfTuples() && ghosts->GetTuple1(cell) == 0.0;
  }
  this->FindPieceBorder();
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::FindPieceBorder()
{
  // Ghost levels are rings of triangles that share a point with the ring inside them
  // (vtkExtractPolyDataPiece's and ParaView's GhostCellsGenerator's): every triangle of
  // the inner rings has its neighbours in the piece, so a boundary edge there is a
  // boundary of the surface, and the piece ends at the boundary edges of the outermost
  // ring. The rings are found again here, from the owned triangles out through the
  // points (points that are one point of the surface are one).
  vtkInternals& in = *this->Internals;
  in.PieceBorder.clear();
  in.CheckedReach = -1.0;
  const std::vector<unsigned char>& owned = in.TriangleOwned;
  const vtkOFBTriangleWalker& walker = in.Walker;
  const vtkIdType n = walker.GetNumberOfTriangles();
  if (owned.empty() || std::all_of(owned.begin(), owned.end(), [](unsigned char o) { return o; }))
  {
    return;
  }
  // The triangles of each point (by its key), in compressed rows.
  const vtkIdType numPoints = walker.GetTriangles()->GetNumberOfPoints();
  std::vector<vtkIdType> start(static_cast<size_t>(numPoints) + 1, 0);
  for (vtkIdType t = 0; t < n; ++t)
  {
    for (int i = 0; i < 3; ++i)
    {
      ++start[walker.GetPointKey(walker.GetCorner(t, i)) + 1];
    }
  }
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    start[p + 1] += start[p];
  }
  std::vector<vtkIdType> fill(start.begin(), start.end() - 1);
  std::vector<vtkIdType> triangles(static_cast<size_t>(start.back()));
  for (vtkIdType t = 0; t < n; ++t)
  {
    for (int i = 0; i < 3; ++i)
    {
      triangles[fill[walker.GetPointKey(walker.GetCorner(t, i))]++] = t;
    }
  }
  // The rings: 0 for the owned triangles, then outwards.
  std::vector<int> ring(static_cast<size_t>(n), -1);
  std::vector<vtkIdType> front;
  for (vtkIdType t = 0; t < n; ++t)
  {
    if (owned[t])
    {
      ring[t] = 0;
      front.push_back(t);
    }
  }
  int outermost = 0;
  std::vector<vtkIdType> next;
  while (!front.empty())
  {
    next.clear();
    for (vtkIdType t : front)
    {
      for (int i = 0; i < 3; ++i)
      {
        const vtkIdType key = walker.GetPointKey(walker.GetCorner(t, i));
        for (vtkIdType k = start[key]; k < start[key + 1]; ++k)
        {
          const vtkIdType u = triangles[k];
          if (ring[u] < 0)
          {
            ring[u] = ring[t] + 1;
            next.push_back(u);
          }
        }
      }
    }
    if (!next.empty())
    {
      outermost = ring[next.front()];
    }
    front.swap(next);
  }
  for (vtkIdType t = 0; outermost > 0 && t < n; ++t)
  {
    for (int i = 0; ring[t] == outermost && i < 3; ++i)
    {
      if (walker.GetRecord(t).Next[i] < 0)
      {
        in.PieceBorder.emplace_back(t, i);
      }
    }
  }
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::GhostCellsCover(double reach)
{
  // A walk from a triangle this process owns goes at most `reach` (its length) from
  // it: the ghost cells cover it when no owned triangle is within `reach` of an edge
  // where the piece ends (the distance between the edge and the triangle's edges or
  // the edge's ends and the triangle).
  vtkInternals& in = *this->Internals;
  if (reach == in.CheckedReach)
  {
    return in.CoversReach;
  }
  in.CheckedReach = reach;
  in.CoversReach = true;
  vtkPolyData* triangles = in.Walker.GetTriangles();
  vtkNew<vtkIdList> candidates;
  vtkNew<vtkGenericCell> triangle;
  const double reach2 = reach * reach;
  for (const auto& border : in.PieceBorder)
  {
    double a[3], b[3];
    triangles->GetPoint(in.Walker.GetCorner(border.first, (border.second + 1) % 3), a);
    triangles->GetPoint(in.Walker.GetCorner(border.first, (border.second + 2) % 3), b);
    double box[6];
    for (int j = 0; j < 3; ++j)
    {
      box[2 * j] = std::min(a[j], b[j]) - reach;
      box[2 * j + 1] = std::max(a[j], b[j]) + reach;
    }
    in.Locator->FindCellsWithinBounds(box, candidates);
    for (vtkIdType k = 0; k < candidates->GetNumberOfIds(); ++k)
    {
      const vtkIdType t = candidates->GetId(k);
      if (!in.TriangleOwned[t])
      {
        continue;
      }
      triangles->GetCell(t, triangle);
      double closest[3], pcoords[3], weights[3], dist2 = 0.0;
      int subId = 0;
      double nearest = VTK_DOUBLE_MAX;
      for (const double* x : { a, b })
      {
        triangle->EvaluatePosition(x, closest, subId, pcoords, dist2, weights);
        nearest = std::min(nearest, dist2);
      }
      for (int i = 0; i < 3; ++i)
      {
        double p[3], q[3], u = 0.0, v = 0.0;
        triangles->GetPoint(in.Walker.GetCorner(t, i), p);
        triangles->GetPoint(in.Walker.GetCorner(t, (i + 1) % 3), q);
        double c1[3], c2[3];
        nearest = std::min(nearest, vtkLine::DistanceBetweenLineSegments(a, b, p, q, c1, c2, u, v));
      }
      if (nearest < reach2)
      {
        in.CoversReach = false;
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::AskForDeeperGhostCells(vtkInformation* request,
  vtkInformationVector** inputVector,
  bool hasPiece)
{
  // The length of a walk of one step: each stage and the final walk go at most the
  // step's length (the slopes are at most 1); Cash-Karp's stages combine up to 6.6
  // sub-steps, within a step of sub-steps.
  vtkInternals& in = *this->Internals;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  const int current =
    inInfo && inInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    ? inInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
  constexpr int MaximumGhostLevels = 64;
  int wanted = 0;
  if (hasPiece)
  {
    const double reach = this->StepSize * in.CellSize * (this->Integrator == RK45 ? 8.0 : 1.0);
    const vtkIdType count = in.Walker.GetNumberOfTriangles();
    const bool covered = this->GhostCellsCover(reach);
    // A piece that did not grow with more levels cannot (its producer gives no more).
    const bool stuck =
      in.CheckedLevels >= 0 && current > in.CheckedLevels && count == in.CheckedTriangles;
    if (!covered && !stuck && current < MaximumGhostLevels)
    {
      wanted = std::min(MaximumGhostLevels, std::max(current + 1, 2 * current));
    }
    else if (!covered && current != in.CheckedLevels)
    {
      vtkWarningMacro("The ghost cells of this process's piece ("
        << current << " levels) end less than a step (" << reach
        << ") from its own triangles: particles that reach their end stop there.");
    }
    in.CheckedLevels = current;
    in.CheckedTriangles = count;
  }
  const int all = static_cast<int>(this->Exchange->AllReduceMaximum(static_cast<double>(wanted)));
  if (all > 0)
  {
    this->RequiredGhostLevels = std::max(this->RequiredGhostLevels, all);
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
    return true;
  }
  request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
  return false;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBParticleAdvector::CanonicalTriangle(const double x[3],
  vtkIdType cell,
  bool ownedOnly,
  double centroid[3])
{
  vtkInternals& in = *this->Internals;
  vtkPolyData* triangles = in.Walker.GetTriangles();
  const double tolerance = 1e-9 * in.CellSize;
  double box[6];
  for (int j = 0; j < 3; ++j)
  {
    box[2 * j] = x[j] - tolerance;
    box[2 * j + 1] = x[j] + tolerance;
  }
  vtkNew<vtkIdList> candidates;
  in.Locator->FindCellsWithinBounds(box, candidates);
  vtkIdType best = -1;
  double bestCentroid[3] = { 0.0, 0.0, 0.0 };
  vtkNew<vtkGenericCell> triangle;
  for (vtkIdType j = -1; j < candidates->GetNumberOfIds(); ++j)
  {
    const vtkIdType t = j < 0 ? cell : candidates->GetId(j);
    if (t < 0 || (ownedOnly && !in.TriangleOwned.empty() && !in.TriangleOwned[t]))
    {
      continue;
    }
    triangles->GetCell(t, triangle);
    double closest[3], pcoords[3], weights[3], dist2 = 0.0;
    int subId = 0;
    triangle->EvaluatePosition(x, closest, subId, pcoords, dist2, weights);
    if (dist2 > tolerance * tolerance)
    {
      continue;
    }
    double c[3];
    Centroid(triangles, t, c);
    if (best < 0 || std::lexicographical_compare(c, c + 3, bestCentroid, bestCentroid + 3))
    {
      best = t;
      std::copy(c, c + 3, bestCentroid);
    }
  }
  if (best < 0)
  {
    best = cell;
    if (cell >= 0)
    {
      Centroid(triangles, cell, bestCentroid);
    }
  }
  std::copy(bestCentroid, bestCentroid + 3, centroid);
  return best;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::OutputsParticle(vtkIdType i) const
{
  const std::vector<unsigned char>& owned = this->Internals->Owned;
  return !this->Exchange || owned.empty() || owned[i];
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::LocateSeedsOverProcesses(vtkDataSet* seeds)
{
  // Each process finds the closest point of its piece to every seed. Its claim is the
  // squared distance when that point is on a triangle it owns (else none); a seed is
  // kept when some process claims it within MaximumSeedDistance, and goes to the
  // process with the closest claim; among equal ones (a seed on a piece border), to the
  // one that owns the triangle of smallest centroid through that point, the triangle
  // one process starts on (CanonicalTriangle). Every process keeps every seed, so the
  // particle ids are the same everywhere.
  vtkInternals& in = *this->Internals;
  const vtkIdType n = seeds->GetNumberOfPoints();
  std::vector<double> claims(n, Unclaimed);
  std::vector<double> centroids(3 * n, Unclaimed);
  std::vector<vtkOFBSurfacePoint> points(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], closest[3];
    seeds->GetPoint(i, x);
    vtkIdType cell = -1;
    int subId = 0;
    double dist2 = 0.0;
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      continue;
    }
    in.Locator->FindClosestPoint(x, closest, cell, subId, dist2);
    if (cell < 0)
    {
      continue;
    }
    const vtkIdType t = this->CanonicalTriangle(closest, cell, true, &centroids[3 * i]);
    points[i] = in.Walker.Locate(t >= 0 ? t : cell, closest);
    if (t >= 0 && (in.TriangleOwned.empty() || in.TriangleOwned[t]))
    {
      claims[i] = dist2;
    }
  }
  std::vector<double> best = claims;
  this->Exchange->AllReduceMinimum(best);
  // The claims at the closest distance (to rounding) compare their triangles' centroids,
  // x, then y, then z, then the ranks.
  const double tolerance2 = 1e-18 * in.CellSize * in.CellSize;
  std::vector<bool> tied(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    tied[i] = claims[i] != Unclaimed && claims[i] <= best[i] + tolerance2;
  }
  for (int j = 0; j < 3; ++j)
  {
    std::vector<double> key(n, Unclaimed);
    for (vtkIdType i = 0; i < n; ++i)
    {
      key[i] = tied[i] ? centroids[3 * i + j] : Unclaimed;
    }
    std::vector<double> least = key;
    this->Exchange->AllReduceMinimum(least);
    for (vtkIdType i = 0; i < n; ++i)
    {
      tied[i] = tied[i] && key[i] == least[i];
    }
  }
  const double rank = static_cast<double>(this->Exchange->GetRank());
  std::vector<double> owners(n, Unclaimed);
  for (vtkIdType i = 0; i < n; ++i)
  {
    owners[i] = tied[i] ? rank : Unclaimed;
  }
  this->Exchange->AllReduceMinimum(owners);

  // The seeds kept, their colours (as LocateSeeds) and owners.
  vtkOFBParticleSystem& system = in.System;
  system.Seeds.clear();
  system.SeedColors.clear();
  in.SeedOwned.clear();
  vtkDataArray* colors = this->SeedColorArrayName
    ? seeds->GetPointData()->GetArray(this->SeedColorArrayName)
    : seeds->GetPointData()->GetScalars();
  if (colors && colors->GetNumberOfTuples() < n)
  {
    colors = nullptr;
  }
  const double radius = this->MaximumSeedDistance * in.CellSize;
  vtkIdType rejected = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (best[i] == Unclaimed || best[i] > radius * radius)
    {
      ++rejected;
      continue;
    }
    system.Seeds.push_back(points[i]);
    in.SeedOwned.push_back(owners[i] == rank ? 1 : 0);
    float rgba[4] = { static_cast<float>(this->Color[0]),
      static_cast<float>(this->Color[1]),
      static_cast<float>(this->Color[2]),
      1.f };
    if (colors)
    {
      const int nc = colors->GetNumberOfComponents();
      const double scale = colors->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
      float c[4] = { 1.f, 1.f, 1.f, 1.f };
      for (int k = 0; k < std::min(nc, 4); ++k)
      {
        c[k] = static_cast<float>(std::min(1.0, std::max(0.0, scale * colors->GetComponent(i, k))));
      }
      rgba[0] = c[0];
      rgba[1] = nc >= 3 ? c[1] : c[0];
      rgba[2] = nc >= 3 ? c[2] : c[0];
      rgba[3] = nc == 4 ? c[3] : (nc == 2 ? c[1] : 1.f);
    }
    system.SeedColors.insert(system.SeedColors.end(), rgba, rgba + 4);
  }
  if (rejected > 0)
  {
    vtkWarningMacro(<< rejected << " seed point(s) non-finite or farther than MaximumSeedDistance ("
                    << this->MaximumSeedDistance << " cells) from the surface rejected.");
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::ExchangeParticles()
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  std::vector<unsigned char>& owned = in.Owned;
  const double rank = static_cast<double>(this->Exchange->GetRank());
  const vtkIdType n = static_cast<vtkIdType>(system.Particles.size());
  if (static_cast<vtkIdType>(owned.size()) != n)
  {
    return;
  }

  // The state of every particle advanced here.
  std::vector<double> local;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkOFBParticleSystem::Particle& p = system.Particles[i];
    if (!owned[i])
    {
      continue;
    }
    const vtkIdType t = p.Point.Triangle;
    const bool left = p.Status != vtkOFBParticleSystem::WAITING && t >= 0 &&
      !in.TriangleOwned.empty() && !in.TriangleOwned[t];
    double centroid[3] = { 0.0, 0.0, 0.0 };
    if (left)
    {
      Centroid(in.Walker.GetTriangles(), t, centroid);
    }
    const double record[RecordSize] = { static_cast<double>(i),
      rank,
      p.Position[0],
      p.Position[1],
      p.Position[2],
      p.Previous[0],
      p.Previous[1],
      p.Previous[2],
      p.SubStep,
      static_cast<double>(p.Age),
      static_cast<double>(p.Status),
      p.Painted ? 1.0 : 0.0,
      p.Color[0],
      p.Color[1],
      p.Color[2],
      p.Color[3],
      left ? 1.0 : 0.0,
      centroid[0],
      centroid[1],
      centroid[2],
      p.Point.Bary[0],
      p.Point.Bary[1],
      p.Point.Bary[2] };
    local.insert(local.end(), record, record + RecordSize);
  }
  std::vector<double> all;
  this->Exchange->AllGather(local, all);
  std::vector<vtkIdType> leaving;
  this->ReceiveStates(all, leaving);
  if (!leaving.empty())
  {
    this->HandOff(all, leaving);
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::ReceiveStates(const std::vector<double>& all,
  std::vector<vtkIdType>& leaving)
{
  // Every other process's particles: their states, and their trails as they grew.
  vtkOFBParticleSystem& system = this->Internals->System;
  const double rank = static_cast<double>(this->Exchange->GetRank());
  const size_t count = all.size() / RecordSize;
  for (size_t r = 0; r < count; ++r)
  {
    const double* record = all.data() + r * RecordSize;
    const auto i = static_cast<vtkIdType>(record[0]);
    if (record[16] != 0.0)
    {
      leaving.push_back(static_cast<vtkIdType>(r));
    }
    if (record[1] == rank)
    {
      continue;
    }
    vtkOFBParticleSystem::Particle& p = system.Particles[i];
    const auto status = static_cast<vtkOFBParticleSystem::State>(static_cast<int>(record[10]));
    const bool released =
      p.Status == vtkOFBParticleSystem::WAITING && status != vtkOFBParticleSystem::WAITING;
    p.Position = glm::dvec3(record[2], record[3], record[4]);
    p.Previous = glm::dvec3(record[5], record[6], record[7]);
    p.SubStep = record[8];
    p.Age = static_cast<int>(record[9]);
    p.Status = status;
    p.Painted = record[11] != 0.0;
    for (int c = 0; c < 4; ++c)
    {
      p.Color[c] = static_cast<float>(record[12 + c]);
    }
    if (released)
    {
      // Released at its seed this step: a new trail there.
      system.TrailCount[i] = 0;
      system.TrailHead[i] = 0;
      system.PushTrail(i, p.Position);
    }
    else if (p.Painted)
    {
      system.PushTrail(i, p.Position);
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::HandOff(const std::vector<double>& all,
  const std::vector<vtkIdType>& leaving)
{
  // Particles whose step ended on a ghost triangle of their process: to the process
  // that owns that triangle (the one with the same centroid), where they take the same
  // barycentric coordinates, so that they go on as on one process. Failing that (no
  // such triangle), to the process whose own triangle is closest to their position
  // (the lowest rank of equal ones); kept where they were if no process owns a
  // triangle there.
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  std::vector<unsigned char>& owned = in.Owned;
  const double rank = static_cast<double>(this->Exchange->GetRank());
  const size_t m = leaving.size();
  this->NumberOfHandOffs += static_cast<vtkIdType>(m);
  std::vector<double> claims(m, Unclaimed);
  std::vector<vtkOFBSurfacePoint> points(m);
  vtkNew<vtkIdList> candidates;
  vtkPolyData* triangles = in.Walker.GetTriangles();
  for (size_t k = 0; k < m; ++k)
  {
    const double* record = all.data() + leaving[k] * RecordSize;
    double x[3] = { record[2], record[3], record[4] };
    // A particle on an edge or a corner (a step that ended exactly on a piece border)
    // may be a rounding error outside its triangle's bounds.
    const double tolerance = 1e-9 * in.CellSize;
    double box[6] = { x[0] - tolerance,
      x[0] + tolerance,
      x[1] - tolerance,
      x[1] + tolerance,
      x[2] - tolerance,
      x[2] + tolerance };
    in.Locator->FindCellsWithinBounds(box, candidates);
    for (vtkIdType j = 0; j < candidates->GetNumberOfIds(); ++j)
    {
      const vtkIdType t = candidates->GetId(j);
      double c[3];
      Centroid(triangles, t, c);
      if (in.TriangleOwned[t] && c[0] == record[17] && c[1] == record[18] && c[2] == record[19])
      {
        claims[k] = -1.0; // the particle's own triangle
        points[k].Triangle = t;
        points[k].Bary = glm::dvec3(record[20], record[21], record[22]);
        break;
      }
    }
    if (claims[k] != Unclaimed)
    {
      continue;
    }
    double closest[3];
    vtkIdType cell = -1;
    int subId = 0;
    double dist2 = 0.0;
    in.Locator->FindClosestPoint(x, closest, cell, subId, dist2);
    if (cell >= 0 && in.TriangleOwned[cell])
    {
      claims[k] = dist2;
      points[k] = in.Walker.Locate(cell, closest);
    }
  }
  std::vector<double> best = claims;
  this->Exchange->AllReduceMinimum(best);
  std::vector<double> owners(m, Unclaimed);
  for (size_t k = 0; k < m; ++k)
  {
    owners[k] = claims[k] != Unclaimed && claims[k] == best[k] ? rank : Unclaimed;
  }
  this->Exchange->AllReduceMinimum(owners);
  for (size_t k = 0; k < m; ++k)
  {
    const double* record = all.data() + leaving[k] * RecordSize;
    const auto i = static_cast<vtkIdType>(record[0]);
    const double owner = owners[k] == Unclaimed ? record[1] : owners[k];
    owned[i] = owner == rank ? 1 : 0;
    if (owner == rank && claims[k] != Unclaimed)
    {
      system.Particles[i].Point = points[k];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::StartWithoutPiece(vtkDataSet* seeds)
{
  // StartParticles: its checks agreed on, the largest speed, the seeds located.
  vtkOFBParticleExchange* exchange = this->Exchange;
  const bool ok = seeds && this->Lifetime == 0;
  if (exchange->AllReduceMaximum(ok ? 0.0 : 1.0) > 0.0)
  {
    return false;
  }
  exchange->AllReduceMaximum(0.0);
  const vtkIdType n = seeds->GetNumberOfPoints();
  for (int call = 0; call < 5; ++call)
  {
    std::vector<double> none(n, Unclaimed);
    exchange->AllReduceMinimum(none);
  }
  this->Internals->System.CurrentStep = 0;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBParticleAdvector::PlanPathlineWithoutPiece(vtkInformation* request,
  vtkDataSet* seeds,
  vtkInformationVector* outputVector)
{
  vtkInternals& in = *this->Internals;
  vtkOFBParticleExchange* exchange = this->Exchange;
  const double requested = vtkOFBParticleAdvector::RequestedTime(outputVector, in.TimeNew);
  if (!std::isfinite(requested))
  {
    vtkErrorMacro("The requested time is not finite: no particles.");
    return false;
  }
  // The start when time goes backwards, then the others' plan (as no process with a
  // piece gives infinity, infinity means that no process has one).
  if (exchange->AllReduceMaximum(0.0) > 0.0 && !this->StartWithoutPiece(seeds))
  {
    return false;
  }
  std::vector<double> plan = { std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  exchange->AllReduceMinimum(plan);
  if (!std::isfinite(plan[0]))
  {
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    return false;
  }
  // What RequestUpdateExtent reads to ask the input for the same time step as the others.
  in.Unsteady = true;
  in.Started = true;
  in.Goal = plan[0];
  in.TimeNew = plan[1];
  if (in.Goal < requested)
  {
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
  }
  else
  {
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
  }
  exchange->AllReduceMaximum(0.0); // PlanUnsteadySteps: the largest speed
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBParticleAdvector::ParticipateWithoutPiece(vtkInformation* request,
  vtkDataSet* seeds,
  vtkInformationVector* outputVector,
  bool unsteady)
{
  // The collective calls of RequestData, with nothing to contribute.
  vtkInternals& in = *this->Internals;
  vtkOFBParticleSystem& system = in.System;
  vtkOFBParticleExchange* exchange = this->Exchange;
  if (exchange->AllReduceMaximum(0.0) > 0.0 && !this->StartWithoutPiece(seeds))
  {
    in.PendingSteps = 0;
    return;
  }
  vtkIdType target = system.CurrentStep;
  if (unsteady)
  {
    if (!this->PlanPathlineWithoutPiece(request, seeds, outputVector))
    {
      in.PendingSteps = 0;
      return;
    }
    target = system.CurrentStep; // the others' steps (it may have started again)
  }
  else if (in.PendingSteps > 0)
  {
    target += in.PendingSteps;
  }
  else
  {
    target = vtkOFBParticleAdvector::RequestedStep(outputVector, target);
    if (target < system.CurrentStep && !this->StartWithoutPiece(seeds))
    {
      return;
    }
  }
  in.PendingSteps = 0;
  const vtkIdType steps = static_cast<vtkIdType>(
    exchange->AllReduceMaximum(static_cast<double>(target - system.CurrentStep)));
  for (vtkIdType step = 0; step < steps; ++step)
  {
    // ExchangeParticles with no particles: the states, then the hand-offs' claims.
    std::vector<double> all;
    exchange->AllGather(std::vector<double>(), all);
    size_t leaving = 0;
    for (size_t r = 0; r + RecordSize <= all.size(); r += RecordSize)
    {
      leaving += all[r + 16] != 0.0 ? 1 : 0;
    }
    this->NumberOfHandOffs += static_cast<vtkIdType>(leaving);
    for (int call = 0; leaving > 0 && call < 2; ++call)
    {
      std::vector<double> none(leaving, Unclaimed);
      exchange->AllReduceMinimum(none);
    }
  }
  system.CurrentStep += steps;
  if (unsteady)
  {
    in.ParticleTime = in.Goal;
    for (int i = 0; i < 3; ++i)
    {
      vtkDataObject::GetData(outputVector, i)
        ->GetInformation()
        ->Set(vtkDataObject::DATA_TIME_STEP(), in.ParticleTime);
    }
  }
}
