#include "vtkOFBAtlasCharts.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>

namespace
{
glm::dvec3 Point(const double* x, vtkIdType id)
{
  return glm::dvec3(x[3 * id], x[3 * id + 1], x[3 * id + 2]);
}

bool Finite(const glm::dvec2& q)
{
  return std::isfinite(q.x) && std::isfinite(q.y);
}

/// Calls f(i, j) for each integer point strictly inside the triangle `q` (counter-clockwise,
/// texel coordinates); points on an edge belong to neither triangle sharing it, so two
/// triangles of a chart that only touch never claim the same texel centre.
template<typename Functor>
bool ForEachTexelInside(const glm::dvec2 q[3], Functor&& f)
{
  const glm::dvec2 e1 = q[1] - q[0];
  const glm::dvec2 e2 = q[2] - q[0];
  const double area = e1.x * e2.y - e1.y * e2.x;
  if (!(area > 0.0))
  {
    return true;
  }
  const double eps = 1e-9;
  const double i0 = std::ceil(std::min({ q[0].x, q[1].x, q[2].x }));
  const double i1 = std::floor(std::max({ q[0].x, q[1].x, q[2].x }));
  const double j0 = std::ceil(std::min({ q[0].y, q[1].y, q[2].y }));
  const double j1 = std::floor(std::max({ q[0].y, q[1].y, q[2].y }));
  for (double j = j0; j <= j1; ++j)
  {
    for (double i = i0; i <= i1; ++i)
    {
      const glm::dvec2 d = glm::dvec2(i, j) - q[0];
      const double w1 = (d.x * e2.y - d.y * e2.x) / area;
      const double w2 = (e1.x * d.y - e1.y * d.x) / area;
      if (w1 > eps && w2 > eps && 1.0 - w1 - w2 > eps &&
        !f(static_cast<long long>(i), static_cast<long long>(j)))
      {
        return false;
      }
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
glm::dvec2 vtkOFBAtlasCharts::Project(const glm::dvec3& p, int k) const
{
  const int a = k / 2;
  const int u = (a + 1) % 3;
  const int v = (a + 2) % 3;
  // Texel centres on cell centres: cell i's centre is at (i + 0.5) cells from the origin.
  const glm::dvec3 t = (p - this->Origin) * this->Scale;
  const double tu = t[u] - this->HalfCell;
  return glm::dvec2((k & 1) ? -tu : tu, t[v] - this->HalfCell);
}

//------------------------------------------------------------------------------
void vtkOFBAtlasCharts::Classify(const double* x, const vtkIdType* ids, vtkIdType n)
{
  this->Direction.assign(static_cast<size_t>(n), -1);
  for (vtkIdType t = 0; t < n; ++t)
  {
    const glm::dvec3 p0 = Point(x, ids[3 * t]);
    const glm::dvec3 normal =
      glm::cross(Point(x, ids[3 * t + 1]) - p0, Point(x, ids[3 * t + 2]) - p0);
    const glm::dvec3 m = glm::abs(normal);
    if (!std::isfinite(m.x + m.y + m.z) || !(m.x + m.y + m.z > 0.0))
    {
      continue;
    }
    const int a = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
    this->Direction[t] = static_cast<signed char>(2 * a + (normal[a] < 0.0 ? 1 : 0));
  }
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkOFBAtlasCharts::WeldPoints(const double* x,
  const vtkIdType* ids,
  vtkIdType n)
{
  std::vector<vtkIdType> used(ids, ids + 3 * n);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<vtkIdType> weld(static_cast<size_t>(used.empty() ? 0 : used.back() + 1), -1);
  for (vtkIdType p : used)
  {
    weld[p] = p; // a point not finite stays itself (and out of the sort)
  }
  // The finite ones sorted by position (then id): equal positions are neighbours, each
  // welded to the first of its run.
  used.erase(std::remove_if(used.begin(),
               used.end(),
               [x](vtkIdType p) { return !std::isfinite(x[3 * p] + x[3 * p + 1] + x[3 * p + 2]); }),
    used.end());
  auto position = [x](vtkIdType p)
  { return std::make_tuple(x[3 * p], x[3 * p + 1], x[3 * p + 2]); };
  std::sort(used.begin(),
    used.end(),
    [&position](vtkIdType a, vtkIdType b)
    { return std::make_pair(position(a), a) < std::make_pair(position(b), b); });
  for (size_t k = 1; k < used.size(); ++k)
  {
    if (position(used[k]) == position(used[k - 1]))
    {
      weld[used[k]] = weld[used[k - 1]];
    }
  }
  return weld;
}

//------------------------------------------------------------------------------
void vtkOFBAtlasCharts::FindNeighbours(const double* x, const vtkIdType* ids, vtkIdType n)
{
  // Edges as (low point, high point, triangle), sorted: triangles of one edge are adjacent.
  // Points are welded by position first: a mesh split at its seams (an OBJ's per-corner
  // normals or texture coordinates, an STL) still has neighbours across them.
  const std::vector<vtkIdType> weld = vtkOFBAtlasCharts::WeldPoints(x, ids, n);
  struct Edge
  {
    vtkIdType A, B, T;
  };
  std::vector<Edge> edges;
  edges.reserve(static_cast<size_t>(3 * n));
  for (vtkIdType t = 0; t < n; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = weld[ids[3 * t + k]];
      const vtkIdType b = weld[ids[3 * t + (k + 1) % 3]];
      if (a != b)
      {
        edges.push_back({ std::min(a, b), std::max(a, b), t });
      }
    }
  }
  std::sort(edges.begin(),
    edges.end(),
    [](const Edge& e, const Edge& f)
    { return e.A != f.A ? e.A < f.A : (e.B != f.B ? e.B < f.B : e.T < f.T); });
  this->NeighbourStart.assign(static_cast<size_t>(n + 1), 0);
  // Two passes over the groups of equal edges: count, then fill (every pair of a group).
  for (int pass = 0; pass < 2; ++pass)
  {
    std::vector<vtkIdType> next;
    if (pass == 1)
    {
      std::partial_sum(
        this->NeighbourStart.begin(), this->NeighbourStart.end(), this->NeighbourStart.begin());
      this->Neighbours.resize(static_cast<size_t>(this->NeighbourStart[n]));
      next.assign(this->NeighbourStart.begin(), this->NeighbourStart.end() - 1);
    }
    for (size_t g = 0; g < edges.size();)
    {
      size_t end = g + 1;
      while (end < edges.size() && edges[end].A == edges[g].A && edges[end].B == edges[g].B)
      {
        ++end;
      }
      for (size_t i = g; i < end; ++i)
      {
        for (size_t j = g; j < end; ++j)
        {
          if (i != j && edges[i].T != edges[j].T)
          {
            if (pass == 0)
            {
              ++this->NeighbourStart[edges[i].T + 1];
            }
            else
            {
              this->Neighbours[next[edges[i].T]++] = edges[j].T;
            }
          }
        }
      }
      g = end;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkOFBAtlasCharts::Grow(const double* x, const vtkIdType* ids, vtkIdType n)
{
  this->ChartOf.assign(static_cast<size_t>(n), -1);
  std::vector<int> tried(static_cast<size_t>(n), -1);
  std::vector<vtkIdType> queue;
  std::vector<int> stamp;
  for (int k = 0; k < 6; ++k)
  {
    // The texels the direction's triangles can cover: one stamp (chart id) each.
    glm::dvec2 lo(HUGE_VAL);
    glm::dvec2 hi(-HUGE_VAL);
    for (vtkIdType t = 0; t < n; ++t)
    {
      for (int c = 0; this->Direction[t] == k && c < 3; ++c)
      {
        const glm::dvec2 q = this->Project(Point(x, ids[3 * t + c]), k);
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
      }
    }
    if (!(lo.x <= hi.x && lo.y <= hi.y))
    {
      continue;
    }
    const glm::dvec2 first = glm::floor(lo);
    const double width = std::ceil(hi.x) - first.x + 1.0;
    const double height = std::ceil(hi.y) - first.y + 1.0;
    if (width * height > 67108864.0) // 2^26 texels of one direction's plane: too large
    {
      return false;
    }
    const long long w = static_cast<long long>(width);
    stamp.assign(static_cast<size_t>(width * height), -1);
    for (vtkIdType t0 = 0; t0 < n; ++t0)
    {
      if (this->Direction[t0] != k || this->ChartOf[t0] >= 0)
      {
        continue;
      }
      // A new chart, grown breadth first over shared edges from t0.
      const int chart = static_cast<int>(this->Axis.size());
      this->Axis.push_back(static_cast<signed char>(k));
      queue.assign(1, t0);
      tried[t0] = chart;
      for (size_t head = 0; head < queue.size(); ++head)
      {
        const vtkIdType t = queue[head];
        glm::dvec2 q[3];
        for (int c = 0; c < 3; ++c)
        {
          q[c] = this->Project(Point(x, ids[3 * t + c]), k) - first;
        }
        auto texel = [&](long long i, long long j) -> int& { return stamp[j * w + i]; };
        if (!ForEachTexelInside(q, [&](long long i, long long j) { return texel(i, j) != chart; }))
        {
          continue; // it would fold over the chart: left for a later chart
        }
        ForEachTexelInside(q,
          [&](long long i, long long j)
          {
            texel(i, j) = chart;
            return true;
          });
        this->ChartOf[t] = chart;
        for (vtkIdType e = this->NeighbourStart[t]; e < this->NeighbourStart[t + 1]; ++e)
        {
          const vtkIdType nb = this->Neighbours[e];
          if (this->Direction[nb] == k && this->ChartOf[nb] < 0 && tried[nb] != chart)
          {
            tried[nb] = chart;
            queue.push_back(nb);
          }
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBAtlasCharts::AdoptDegenerate(vtkIdType n)
{
  // A triangle without a normal joins a neighbour's chart (it covers no texel), else one
  // chart of its own for all such triangles.
  bool changed = true;
  for (int pass = 0; changed && pass < 64; ++pass)
  {
    changed = false;
    for (vtkIdType t = 0; t < n; ++t)
    {
      for (vtkIdType e = this->NeighbourStart[t];
           this->ChartOf[t] < 0 && e < this->NeighbourStart[t + 1];
           ++e)
      {
        this->ChartOf[t] = this->ChartOf[this->Neighbours[e]];
        changed = changed || this->ChartOf[t] >= 0;
      }
    }
  }
  int rest = -1;
  for (vtkIdType t = 0; t < n; ++t)
  {
    if (this->ChartOf[t] < 0)
    {
      if (rest < 0)
      {
        rest = static_cast<int>(this->Axis.size());
        this->Axis.push_back(0);
      }
      this->ChartOf[t] = rest;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkOFBAtlasCharts::Pack(const double* x,
  const vtkIdType* ids,
  vtkIdType n,
  int padding,
  int maximumSize)
{
  // Each chart's rectangle: its texel centres' range, the padding around.
  const int charts = this->GetNumberOfCharts();
  std::vector<glm::dvec2> lo(charts, glm::dvec2(HUGE_VAL));
  std::vector<glm::dvec2> hi(charts, glm::dvec2(-HUGE_VAL));
  for (vtkIdType t = 0; t < n; ++t)
  {
    const int c = this->ChartOf[t];
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec2 q = this->Project(Point(x, ids[3 * t + k]), this->Axis[c]);
      if (Finite(q))
      {
        lo[c] = glm::min(lo[c], q);
        hi[c] = glm::max(hi[c], q);
      }
    }
  }
  // (Packed whether or not it fits, so that a caller learns the size it would need.)
  std::vector<glm::dvec2> low(charts);
  std::vector<glm::ivec2> size(charts);
  for (int c = 0; c < charts; ++c)
  {
    const bool any = lo[c].x <= hi[c].x && lo[c].y <= hi[c].y;
    low[c] = any ? glm::floor(lo[c]) : glm::dvec2(0.0);
    const glm::dvec2 span = any ? glm::ceil(hi[c]) - low[c] : glm::dvec2(0.0);
    if (!(span.x + 2 * padding + 1 <= 1 << 30 && span.y + 2 * padding + 1 <= 1 << 30))
    {
      return false; // no packing to speak of
    }
    size[c] = glm::ivec2(span) + 2 * padding + 1;
  }
  // A chart wider or taller than the atlas may be: its side is the size needed (no
  // outlines of a size that cannot be used).
  long long columns = 0;
  glm::ivec2 largest(0);
  for (int c = 0; c < charts; ++c)
  {
    columns += size[c].x;
    largest = glm::max(largest, size[c]);
  }
  if (largest.x > maximumSize || largest.y > maximumSize || columns > (1 << 28))
  {
    this->Width = largest.x;
    this->Height = largest.y;
    return false;
  }
  const Outlines outlines = this->Outline(x, ids, n, padding, low, size);
  this->Drop(outlines, low, size, padding);
  this->Low.swap(low);
  return this->Width > 0 && this->Width <= maximumSize && this->Height <= maximumSize;
}

//------------------------------------------------------------------------------
vtkOFBAtlasCharts::Outlines vtkOFBAtlasCharts::Outline(const double* x,
  const vtkIdType* ids,
  vtkIdType n,
  int padding,
  const std::vector<glm::dvec2>& low,
  const std::vector<glm::ivec2>& size) const
{
  // Each chart's outline: per column of its rectangle the lowest and highest row its
  // triangles touch, grown by the padding.
  const int charts = this->GetNumberOfCharts();
  Outlines out;
  std::vector<int>& first = out.First;
  first.assign(charts + 1, 0);
  for (int c = 0; c < charts; ++c)
  {
    first[c + 1] = first[c] + size[c].x;
  }
  std::vector<int> bottom(first[charts], std::numeric_limits<int>::max());
  std::vector<int> top(first[charts], std::numeric_limits<int>::min());
  for (vtkIdType t = 0; t < n; ++t)
  {
    const int c = this->ChartOf[t];
    glm::dvec2 q[3];
    for (int k = 0; k < 3; ++k)
    {
      q[k] = this->Project(Point(x, ids[3 * t + k]), this->Axis[c]) - low[c] + double(padding);
    }
    // A column's extremes lie on the boundary: its edges, sampled every quarter texel.
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec2 a = q[k];
      const glm::dvec2 b = q[(k + 1) % 3];
      if (!Finite(a) || !Finite(b))
      {
        continue;
      }
      const int m = 1 + static_cast<int>(std::min(4.0 * glm::length(b - a), 1e7));
      for (int j = 0; j <= m; ++j)
      {
        const glm::dvec2 e = glm::floor(a + (b - a) * (double(j) / m) + 0.5);
        const int i = std::min(std::max(static_cast<int>(e.x), 0), size[c].x - 1);
        const int r = std::min(std::max(static_cast<int>(e.y), 0), size[c].y - 1);
        bottom[first[c] + i] = std::min(bottom[first[c] + i], r);
        top[first[c] + i] = std::max(top[first[c] + i], r + 1);
      }
    }
  }
  std::vector<int>& grownBottom = out.Bottom;
  std::vector<int>& grownTop = out.Top;
  grownBottom.resize(bottom.size());
  grownTop.resize(top.size());
  for (int c = 0; c < charts; ++c)
  {
    for (int i = 0; i < size[c].x; ++i)
    {
      int b = std::numeric_limits<int>::max();
      int e = std::numeric_limits<int>::min();
      for (int k = std::max(0, i - padding); k <= std::min(size[c].x - 1, i + padding); ++k)
      {
        b = std::min(b, bottom[first[c] + k]);
        e = std::max(e, top[first[c] + k]);
      }
      const bool used = b <= e;
      grownBottom[first[c] + i] = used ? std::max(0, b - padding) : std::numeric_limits<int>::max();
      grownTop[first[c] + i] = used ? std::min(size[c].y, e + padding) : 0;
    }
  }
  return out;
}

//------------------------------------------------------------------------------
void vtkOFBAtlasCharts::Drop(const Outlines& outlines,
  const std::vector<glm::dvec2>& low,
  const std::vector<glm::ivec2>& size,
  int padding)
{
  // Charts dropped onto the skyline of the atlas's columns (tallest first, each where it
  // comes to rest lowest, then leftmost): their outlines interlock where rectangles would
  // leave gaps. Widths tried: about the square of the outlines' area, wider while the atlas
  // comes out taller than wide; the squarest kept.
  const int charts = this->GetNumberOfCharts();
  const std::vector<int>& first = outlines.First;
  const std::vector<int>& grownBottom = outlines.Bottom;
  const std::vector<int>& grownTop = outlines.Top;
  double area = 0.0;
  int widest = 1;
  for (int c = 0; c < charts; ++c)
  {
    for (int i = 0; i < size[c].x; ++i)
    {
      area += std::max(0, grownTop[first[c] + i] - grownBottom[first[c] + i]);
    }
    widest = std::max(widest, size[c].x);
  }
  std::vector<int> order(charts);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(),
    order.end(),
    [&size](int a, int b)
    { return size[a].y != size[b].y ? size[a].y > size[b].y : size[a].x > size[b].x; });
  std::vector<glm::dvec2> shift(charts);
  std::vector<int> sky;
  double wide = std::max<double>(widest, std::ceil(std::sqrt(area * 1.25)));
  this->Width = this->Height = 0;
  for (int attempt = 0; attempt < 4 && wide <= 1 << 30; ++attempt)
  {
    const int width = static_cast<int>(wide);
    sky.assign(static_cast<size_t>(width), 0);
    long long height = 0;
    for (int c : order)
    {
      const int* b = grownBottom.data() + first[c];
      const int* e = grownTop.data() + first[c];
      long long bestY = std::numeric_limits<long long>::max();
      int bestX = 0;
      for (int px = 0; px + size[c].x <= width; ++px)
      {
        long long y = 0;
        for (int i = 0; i < size[c].x && y < bestY; ++i)
        {
          if (b[i] < e[i])
          {
            y = std::max<long long>(y, static_cast<long long>(sky[px + i]) - b[i]);
          }
        }
        if (y < bestY)
        {
          bestY = y;
          bestX = px;
        }
      }
      for (int i = 0; i < size[c].x; ++i)
      {
        if (b[i] < e[i])
        {
          sky[bestX + i] = static_cast<int>(std::min<long long>(bestY + e[i], 1 << 30));
        }
      }
      height = std::max(height, bestY + size[c].y);
      shift[c] = glm::dvec2(bestX + padding, bestY + padding) - low[c];
    }
    if (height > 1 << 30)
    {
      this->Width = this->Height = 0;
      return;
    }
    if (attempt == 0 || std::max<long long>(width, height) < std::max(this->Width, this->Height))
    {
      this->Width = width;
      this->Height = static_cast<int>(height);
      this->Shift = shift;
    }
    if (height <= 1.1 * width)
    {
      break;
    }
    wide = std::ceil(wide * std::sqrt(static_cast<double>(height) / width));
  }
}

//------------------------------------------------------------------------------
void vtkOFBAtlasCharts::Prepare(const double* x, const vtkIdType* ids, vtkIdType n)
{
  this->Classify(x, ids, n);
  this->FindNeighbours(x, ids, n);
}

//------------------------------------------------------------------------------
bool vtkOFBAtlasCharts::Build(const double* x,
  const vtkIdType* ids,
  vtkIdType n,
  const double origin[3],
  double cellSize,
  double density,
  int padding,
  int maximumSize)
{
  this->Origin = glm::dvec3(origin[0], origin[1], origin[2]);
  this->Scale = density / cellSize;
  this->HalfCell = 0.5 * density;
  this->Axis.clear();
  this->Shift.clear();
  this->Low.clear();
  this->Width = this->Height = 0;
  if (!this->Grow(x, ids, n))
  {
    return false;
  }
  this->AdoptDegenerate(n);
  return this->Pack(x, ids, n, padding, maximumSize);
}

//------------------------------------------------------------------------------
glm::dvec2 vtkOFBAtlasCharts::TexelCoordinates(const double p[3], int c) const
{
  const glm::dvec2 q = this->Project(glm::dvec3(p[0], p[1], p[2]), this->Axis[c]);
  return (Finite(q) ? q : this->Low[c]) + this->Shift[c] + 0.5;
}
