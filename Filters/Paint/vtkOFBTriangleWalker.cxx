#include "vtkOFBTriangleWalker.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkOFBInputChecks.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <array>
#include <cmath>

static_assert(sizeof(vtkOFBWalkerTriangle) == 64, "a walker record is one cache line");

namespace
{
// A walk that crosses more edges than this for one displacement circles a vertex
// without progress (rounding at a corner): it stops where it is.
constexpr int MaximumCrossings = 100000;

// Barycentrics made a valid convex combination again after rounding.
inline void Normalize(glm::dvec3& b)
{
  b = glm::max(b, glm::dvec3(0.0));
  const double sum = b[0] + b[1] + b[2];
  b = sum > 0.0 ? b / sum : glm::dvec3(1.0 / 3.0);
}
}

//------------------------------------------------------------------------------
bool vtkOFBTriangleWalker::Build(vtkPolyData* surface,
  vtkDataArray* vectors,
  std::string& error,
  const vtkIdType* polygonCells,
  double mergeTolerance)
{
  const vtkIdType numPoints = surface ? surface->GetNumberOfPoints() : 0;
  // The callers check their input first; the walker, shared between modules, does not
  // rely on it before it indexes points and vectors.
  if (surface && !vtkOFBCheckCellPointIds(surface, error))
  {
    error = "the surface is invalid: " + error;
    return false;
  }
  if (!vtkOFBCheckArrayLength(vectors, numPoints, "points", error, 3))
  {
    error = "the vector field " + error;
    return false;
  }
  this->Points.resize(numPoints);
  this->Vectors.assign(numPoints, glm::dvec3(0.0));
  this->Records.clear();
  this->Turns.clear();
  this->MaximumSpeed = 0.0;
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double x[3];
    surface->GetPoint(i, x);
    this->Points[i] = glm::dvec3(x[0], x[1], x[2]);
    if (vectors)
    {
      double v[3];
      vectors->GetTuple(i, v);
      this->Vectors[i] = glm::dvec3(v[0], v[1], v[2]);
      this->MaximumSpeed = std::max(this->MaximumSpeed, glm::length(this->Vectors[i]));
    }
  }

  // Triangles of non-zero area, in input order.
  this->Corners.clear();
  this->Cells.clear();
  if (surface && surface->GetPolys())
  {
    auto it = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
    vtkIdType polygon = -1;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      ++polygon;
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      if (n != 3)
      {
        continue;
      }
      const glm::dvec3& a = this->Points[ids[0]];
      const glm::dvec3 e1 = this->Points[ids[1]] - a;
      const glm::dvec3 e2 = this->Points[ids[2]] - a;
      const double scale = std::max(glm::dot(e1, e1), glm::dot(e2, e2));
      const double area2 = glm::length(glm::cross(e1, e2));
      if (!(area2 > 1e-12 * scale) || !std::isfinite(area2))
      {
        continue;
      }
      this->Corners.insert(this->Corners.end(), ids, ids + 3);
      this->Cells.push_back(polygonCells ? polygonCells[polygon] : polygon);
    }
  }
  if (this->Corners.empty())
  {
    error = "the surface has no triangle of non-zero area";
    return false;
  }
  if (this->Corners.size() / 3 >= static_cast<size_t>(VTK_INT_MAX))
  {
    error = "the surface has 2^31 triangles or more";
    return false;
  }
  this->BuildGeometry();
  this->BuildAdjacency(mergeTolerance);

  this->Triangles = vtkSmartPointer<vtkPolyData>::New();
  this->Triangles->SetPoints(surface->GetPoints());
  vtkNew<vtkCellArray> polys;
  const vtkIdType numTriangles = this->GetNumberOfTriangles();
  polys->AllocateExact(numTriangles, 3 * numTriangles);
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    polys->InsertNextCell(3, &this->Corners[3 * t]);
  }
  this->Triangles->SetPolys(polys);
  // Only the projected corner vectors and the records' gradients are kept.
  this->Vectors.clear();
  this->Vectors.shrink_to_fit();
  this->Gradients.clear();
  this->Gradients.shrink_to_fit();
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::SetPointVectors(const double* vectors)
{
  const vtkIdType numTriangles = this->GetNumberOfTriangles();
  double largest = 0.0;
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    const glm::dvec3& ex = this->Axes[2 * t];
    const glm::dvec3& ey = this->Axes[2 * t + 1];
    vtkOFBWalkerTriangle& r = this->Records[t];
    for (int i = 0; i < 3; ++i)
    {
      const double* v = vectors + 3 * this->Corners[3 * t + i];
      const glm::dvec3 w(v[0], v[1], v[2]);
      r.Vector[i] = glm::vec2(glm::dot(w, ex), glm::dot(w, ey));
      largest = std::max(largest, glm::dot(w, w));
    }
  }
  this->MaximumSpeed = std::sqrt(largest);
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::SetCellVectors(const double* vectors)
{
  const vtkIdType numTriangles = this->GetNumberOfTriangles();
  double largest = 0.0;
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    const double* v = vectors + 3 * this->Cells[t];
    const glm::dvec3 w(v[0], v[1], v[2]);
    const glm::vec2 projected(glm::dot(w, this->Axes[2 * t]), glm::dot(w, this->Axes[2 * t + 1]));
    vtkOFBWalkerTriangle& r = this->Records[t];
    r.Vector[0] = r.Vector[1] = r.Vector[2] = projected;
    largest = std::max(largest, glm::dot(w, w));
  }
  this->MaximumSpeed = std::sqrt(largest);
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::BuildGeometry()
{
  const vtkIdType numTriangles = this->GetNumberOfTriangles();
  this->Records.resize(numTriangles);
  this->Turns.resize(numTriangles);
  this->Gradients.resize(3 * numTriangles);
  this->Normals.resize(numTriangles);
  this->CornerPoints.resize(3 * numTriangles);
  this->Axes.resize(2 * numTriangles);
  this->Area.resize(numTriangles);
  double area = 0.0;
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    const vtkIdType* c = &this->Corners[3 * t];
    const glm::dvec3 p[3] = { this->Points[c[0]], this->Points[c[1]], this->Points[c[2]] };
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double area2 = glm::length(n);
    const glm::dvec3 unit = n / area2;
    const glm::dvec3 ex = glm::normalize(p[1] - p[0]);
    const glm::dvec3 ey = glm::cross(unit, ex);
    this->Normals[t] = unit;
    std::copy_n(p, 3, &this->CornerPoints[3 * t]);
    this->Axes[2 * t] = ex;
    this->Axes[2 * t + 1] = ey;
    vtkOFBWalkerTriangle& r = this->Records[t];
    for (int i = 0; i < 3; ++i)
    {
      // Gradient of barycentric i: towards corner i, of length 1 / height.
      const glm::dvec3 edge = p[(i + 2) % 3] - p[(i + 1) % 3];
      const glm::dvec3 g = glm::cross(unit, edge) / area2;
      this->Gradients[3 * t + i] = glm::dvec2(glm::dot(g, ex), glm::dot(g, ey));
      if (i < 2)
      {
        r.Gradient[i] = glm::vec2(this->Gradients[3 * t + i]);
      }
      const glm::dvec3& v = this->Vectors[c[i]];
      r.Vector[i] = glm::vec2(glm::dot(v, ex), glm::dot(v, ey));
      r.Next[i] = -1;
      r.Link[i] = 0;
      this->Turns[t].Turn[i] = glm::vec2(1.f, 0.f);
    }
    area += 0.5 * area2;
    this->Area[t] = area;
  }
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::BuildAdjacency(double mergeTolerance)
{
  const vtkIdType numTriangles = this->GetNumberOfTriangles();
  // Points at the same position are one point of the surface (a mesh may repeat its points
  // per face, as an OBJ with texture coordinates does): each point's id for adjacency is
  // the smallest id at its position.
  const vtkIdType numPoints = static_cast<vtkIdType>(this->Points.size());
  std::vector<vtkIdType> order(static_cast<size_t>(numPoints));
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    order[i] = i;
  }
  auto less = [this](vtkIdType a, vtkIdType b)
  {
    const glm::dvec3& p = this->Points[a];
    const glm::dvec3& q = this->Points[b];
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : (p.z != q.z ? p.z < q.z : a < b));
  };
  std::sort(order.begin(), order.end(), less);
  this->Canonical.resize(static_cast<size_t>(numPoints));
  for (vtkIdType k = 0; k < numPoints; ++k)
  {
    const bool same = k > 0 && this->Points[order[k]] == this->Points[order[k - 1]];
    this->Canonical[order[k]] = same ? this->Canonical[order[k - 1]] : order[k];
  }
  if (mergeTolerance > 0.0)
  {
    this->MergeClosePoints(mergeTolerance);
  }
  // Half-edges keyed by their sorted point ids; equal keys share an edge.
  struct HalfEdge
  {
    vtkIdType A, B, Triangle;
    int Corner;
  };
  std::vector<HalfEdge> edges(3 * numTriangles);
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    for (int i = 0; i < 3; ++i)
    {
      const vtkIdType a = this->Canonical[this->Corners[3 * t + (i + 1) % 3]];
      const vtkIdType b = this->Canonical[this->Corners[3 * t + (i + 2) % 3]];
      edges[3 * t + i] = { std::min(a, b), std::max(a, b), t, i };
    }
  }
  std::sort(edges.begin(),
    edges.end(),
    [](const HalfEdge& x, const HalfEdge& y)
    { return x.A != y.A ? x.A < y.A : (x.B != y.B ? x.B < y.B : x.Triangle < y.Triangle); });
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && edges[j].A == edges[i].A && edges[j].B == edges[i].B)
    {
      ++j;
    }
    if (j - i == 2) // a manifold edge; others stay boundaries
    {
      this->Link(edges[i].Triangle, edges[i].Corner, edges[i + 1].Triangle, edges[i + 1].Corner);
      this->Link(edges[i + 1].Triangle, edges[i + 1].Corner, edges[i].Triangle, edges[i].Corner);
    }
    i = j;
  }
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::MergeClosePoints(double tolerance)
{
  // The points of the triangles within `tolerance` of each other, joined (union-find
  // over the canonical ids), each group named by its smallest id.
  const vtkIdType numPoints = static_cast<vtkIdType>(this->Points.size());
  std::vector<vtkIdType> parent(this->Canonical);
  auto root = [&parent](vtkIdType i)
  {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  std::vector<unsigned char> used(static_cast<size_t>(numPoints), 0);
  for (vtkIdType c : this->Corners)
  {
    used[c] = 1;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    if (used[i] && this->Canonical[i] == i)
    {
      points->InsertNextPoint(&this->Points[i][0]);
      ids.push_back(i);
    }
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  vtkNew<vtkIdList> close;
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(ids.size()); ++k)
  {
    locator->FindPointsWithinRadius(tolerance, &this->Points[ids[k]][0], close);
    for (vtkIdType j = 0; j < close->GetNumberOfIds(); ++j)
    {
      const vtkIdType a = root(ids[k]);
      const vtkIdType b = root(ids[close->GetId(j)]);
      if (a != b)
      {
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    this->Canonical[i] = root(this->Canonical[i]);
  }
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::Link(vtkIdType t, int edge, vtkIdType next, int opposite)
{
  vtkOFBWalkerTriangle& r = this->Records[t];
  const int a = (edge + 1) % 3;
  const vtkIdType* nc = &this->Corners[3 * next];
  const vtkIdType* canonical = this->Canonical.data();
  const int na = canonical[nc[(opposite + 1) % 3]] == canonical[this->Corners[3 * t + a]]
    ? (opposite + 1) % 3
    : (opposite + 2) % 3;
  r.Next[edge] = static_cast<int>(next);

  // The turn about the shared edge (the unfolding of the two triangles into one
  // plane) in the two frames: the edge direction stays, the direction out of t
  // becomes the direction into the neighbour.
  const glm::dvec3 e = glm::normalize(
    this->Points[this->Corners[3 * t + (edge + 2) % 3]] - this->Points[this->Corners[3 * t + a]]);
  const glm::dvec3* axes = &this->Axes[2 * t];
  const glm::dvec3* nextAxes = &this->Axes[2 * next];
  const glm::dvec2 e2(glm::dot(e, axes[0]), glm::dot(e, axes[1]));
  const glm::dvec2 ne2(glm::dot(e, nextAxes[0]), glm::dot(e, nextAxes[1]));
  const glm::dvec2 out = -glm::normalize(this->Gradients[3 * t + edge]);
  const glm::dvec2 in = glm::normalize(this->Gradients[3 * next + opposite]);
  const glm::dmat2 turn = glm::outerProduct(ne2, e2) + glm::outerProduct(in, out);
  this->Turns[t].Turn[edge] = glm::vec2(glm::normalize(turn[0]));
  const bool reflect = glm::determinant(turn) < 0.0;
  r.Link[edge] = static_cast<unsigned char>(opposite | (na << 2) | (reflect ? 16 : 0));
}

//------------------------------------------------------------------------------
double vtkOFBTriangleWalker::Interpolate(vtkDataArray* array,
  int component,
  const vtkOFBSurfacePoint& p) const
{
  const vtkIdType* c = &this->Corners[3 * p.Triangle];
  return p.Bary[0] * array->GetComponent(c[0], component) +
    p.Bary[1] * array->GetComponent(c[1], component) +
    p.Bary[2] * array->GetComponent(c[2], component);
}

//------------------------------------------------------------------------------
inline bool vtkOFBTriangleWalker::CrossLane(vtkOFBWalkLanes& w, int j, bool withFrame) const
{
  // Moves lane j in barycentric coordinates (the gradients of the barycentrics
  // give their rates along d) to the first edge its path meets, at the fraction
  // `exit` of d, or to the end of d.
  const vtkIdType t = w.Triangle[j];
  const vtkOFBWalkerTriangle& r = this->Records[t];
  const glm::dvec2 d(w.D[0][j], w.D[1][j]);
  const glm::dvec3 db = r.Rates(d);
  double b[3] = { w.Bary[0][j], w.Bary[1][j], w.Bary[2][j] };
  // Both tests of an edge in one branch (`&`, not `&&`): which edges a walk meets
  // is unpredictable, and each mispredicted branch costs more than a comparison.
  double exit = 1.0;
  int edge = -1;
  for (int i = 0; i < 3; ++i)
  {
    if ((db[i] < 0.0) & (b[i] < -db[i] * exit))
    {
      exit = b[i] / -db[i];
      edge = i;
    }
  }
  if (edge < 0)
  {
    // The gradients sum to zero, so the sum stays 1; only rounding below 0 is cut.
    for (int i = 0; i < 3; ++i)
    {
      const double x = b[i] + db[i];
      w.Bary[i][j] = x < 0.0 ? 0.0 : x;
    }
    w.Result[j] = WALK_INSIDE;
    return true;
  }
  // On the edge: the barycentric of its opposite corner is 0, the other two sum
  // to 1 (the second is 1 - the first rather than a division of both by their sum).
  const int a = edge == 2 ? 0 : edge + 1;
  const double ba = std::min(1.0, std::max(0.0, b[a] + exit * db[a]));
  const int next = r.Next[edge];
  if (next < 0)
  {
    b[edge] = 0.0;
    b[a] = ba;
    b[3 - edge - a] = 1.0 - ba;
    for (int i = 0; i < 3; ++i)
    {
      w.Bary[i][j] = b[i];
    }
    w.Result[j] = WALK_BOUNDARY;
    return true;
  }
  // Into the neighbour, with the rest of d and the frame turned about the edge.
  const int na = r.NextA(edge);
  const int opposite = r.Opposite(edge);
  w.Bary[na][j] = ba;
  w.Bary[3 - opposite - na][j] = 1.0 - ba;
  w.Bary[opposite][j] = 0.0;
  const vtkOFBWalkerTurn& turn = this->Turns[t];
  const bool reflect = r.Reflect(edge);
  const glm::dvec2 turned = (1.0 - exit) * turn.Apply(edge, reflect, d);
  w.D[0][j] = turned[0];
  w.D[1][j] = turned[1];
  if (withFrame)
  {
    const glm::dvec2 f0 = turn.Apply(edge, reflect, glm::dvec2(w.Frame[0][j], w.Frame[1][j]));
    const glm::dvec2 f1 = turn.Apply(edge, reflect, glm::dvec2(w.Frame[2][j], w.Frame[3][j]));
    w.Frame[0][j] = f0[0];
    w.Frame[1][j] = f0[1];
    w.Frame[2][j] = f1[0];
    w.Frame[3][j] = f1[1];
  }
  w.Triangle[j] = next;
  return false;
}

//------------------------------------------------------------------------------
void vtkOFBTriangleWalker::Walk(vtkOFBWalkLanes& w, bool withFrame) const
{
  // The lanes still walking, kept in order by a compaction after each round.
  int active[vtkOFBWalkLanes::Size];
  int count = 0;
  for (int j = 0; j < w.Count; ++j)
  {
    active[count++] = j;
  }
  for (int crossing = 0; count > 0 && crossing < MaximumCrossings; ++crossing)
  {
    int left = 0;
    for (int k = 0; k < count; ++k)
    {
      const int j = active[k];
      active[left] = j;
      left += this->CrossLane(w, j, withFrame) ? 0 : 1;
    }
    count = left;
  }
  for (int k = 0; k < count; ++k)
  {
    w.Result[active[k]] = WALK_STUCK;
  }
}

//------------------------------------------------------------------------------
vtkOFBTriangleWalker::WalkResult vtkOFBTriangleWalker::Walk(vtkOFBSurfacePoint& p,
  glm::dvec2 d,
  glm::dmat2* frame) const
{
  // One lane of the walks below.
  vtkOFBWalkLanes lane;
  lane.Count = 1;
  lane.Set(0, p, d[0], d[1]);
  if (frame)
  {
    lane.Frame[0][0] = (*frame)[0][0];
    lane.Frame[1][0] = (*frame)[0][1];
    lane.Frame[2][0] = (*frame)[1][0];
    lane.Frame[3][0] = (*frame)[1][1];
  }
  this->Walk(lane, frame != nullptr);
  lane.Get(0, p);
  if (frame)
  {
    *frame = glm::dmat2(lane.Frame[0][0], lane.Frame[1][0], lane.Frame[2][0], lane.Frame[3][0]);
  }
  return static_cast<WalkResult>(lane.Result[0]);
}

//------------------------------------------------------------------------------
vtkOFBSurfacePoint vtkOFBTriangleWalker::Locate(vtkIdType t, const double x[3]) const
{
  vtkOFBSurfacePoint p;
  p.Triangle = t;
  const glm::dvec3 r3 = glm::dvec3(x[0], x[1], x[2]) - this->Points[this->Corners[3 * t]];
  const glm::dvec2 r(glm::dot(r3, this->Axes[2 * t]), glm::dot(r3, this->Axes[2 * t + 1]));
  // Barycentrics of the projection: b_i = b_i(corner 0) + g_i . r
  const glm::dvec3 rates = this->Records[t].Rates(r);
  p.Bary = glm::dvec3(1.0 + rates[0], rates[1], rates[2]);
  if (!std::isfinite(p.Bary[0] + p.Bary[1] + p.Bary[2]))
  {
    p.Bary = glm::dvec3(1.0 / 3.0);
  }
  Normalize(p.Bary);
  return p;
}

//------------------------------------------------------------------------------
vtkOFBSurfacePoint vtkOFBTriangleWalker::Sample(double u0, double u1, double u2) const
{
  vtkOFBSurfacePoint p;
  const double target = u0 * this->Area.back();
  const auto it = std::upper_bound(this->Area.begin(), this->Area.end(), target);
  p.Triangle = std::min<vtkIdType>(
    static_cast<vtkIdType>(it - this->Area.begin()), this->GetNumberOfTriangles() - 1);
  // Uniform in the triangle: b = (1 - sqrt(u1), sqrt(u1) (1 - u2), sqrt(u1) u2).
  const double s = std::sqrt(u1);
  p.Bary = glm::dvec3(1.0 - s, s * (1.0 - u2), s * u2);
  return p;
}
