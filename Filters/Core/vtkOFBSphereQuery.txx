/**
 * @file   vtkOFBSphereQuery.txx
 * @brief  vtkOFBSphereQuery's inline and templated members, and vtkOFB's sphere queries
 *
 * Included by vtkOFBSphereQuery.h.
 */

#ifndef vtkOFBSphereQuery_txx
#define vtkOFBSphereQuery_txx

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
inline vtkOFBSphereQuery::vtkOFBSphereQuery(const vtkOFB& ofb)
  : CellSize(ofb.CellSize)
  , NumberOfSamples(ofb.Depths->GetNumberOfValues())
  , Offsets(ofb.CellOffsets->GetPointer(0))
  , Depths(ofb.Depths->GetPointer(0))
  , CellOf(ofb.CellIndex->GetNumberOfValues() == ofb.Depths->GetNumberOfValues()
        ? ofb.CellIndex->GetPointer(0)
        : nullptr)
{
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = ofb.Origin[a];
    this->Dimensions[a] = ofb.Dimensions[a];
  }
  for (int a = 0; a < 4; ++a)
  {
    this->CellBase[a] = ofb.CellBase[a];
  }
}

//------------------------------------------------------------------------------
template<typename Functor>
void vtkOFB::ForEachSampleInSphere(const double center[3], double radius, Functor&& f) const
{
  auto none = [](vtkIdType, vtkIdType) {};
  vtkOFBSphereQuery(*this).ForEachSampleInSphere(center, radius, f, none);
}

//------------------------------------------------------------------------------
template<typename Functor, typename Prefetch>
void vtkOFB::ForEachSampleInSphere(const double center[3],
  double radius,
  Functor&& f,
  Prefetch&& prefetch) const
{
  vtkOFBSphereQuery(*this).ForEachSampleInSphere(center, radius, f, prefetch);
}

//------------------------------------------------------------------------------
template<typename Sphere, typename Functor, typename Prefetch>
void vtkOFB::ForEachSampleInSpheres(vtkIdType n,
  Sphere&& sphere,
  Functor&& f,
  Prefetch&& prefetch) const
{
  vtkOFBSphereQuery(*this).ForEachSampleInSpheres(n, sphere, f, prefetch);
}

//------------------------------------------------------------------------------
inline bool vtkOFBSphereQuery::BeginGrid(int a,
  const double center[3],
  double radius,
  Grid& grid) const
{
  const int ua = (a + 1) % 3;
  const int va = (a + 2) % 3;
  const double s = this->CellSize;
  const vtkIdType nu = this->Dimensions[ua];
  const vtkIdType nv = this->Dimensions[va];
  // Cells whose centre lies within the projected box [c - r, c + r], clamped to the
  // grid before they become integers (a huge or infinite radius covers the grid).
  const double lu = (center[ua] - radius - this->Origin[ua]) / s - 0.5;
  const double hu = (center[ua] + radius - this->Origin[ua]) / s - 0.5;
  const double lv = (center[va] - radius - this->Origin[va]) / s - 0.5;
  const double hv = (center[va] + radius - this->Origin[va]) / s - 0.5;
  if (!(hu >= 0.0 && hv >= 0.0 && lu <= nu - 1 && lv <= nv - 1))
  {
    return false;
  }
  grid.U0 = static_cast<vtkIdType>(std::ceil(std::max(lu, 0.0)));
  grid.U1 = static_cast<vtkIdType>(std::floor(std::min(hu, nu - 1.0)));
  grid.V0 = static_cast<vtkIdType>(std::ceil(std::max(lv, 0.0)));
  grid.V1 = static_cast<vtkIdType>(std::floor(std::min(hv, nv - 1.0)));
  grid.CU = (center[ua] - this->Origin[ua]) / s - 0.5; // centre in cell units
  grid.InverseCellSize = 1.0 / s;
  grid.CV = center[va];
  grid.VAxis = va;
  grid.NU = nu;
  Row& base = grid.Base;
  base.RowBase = this->CellBase[a];
  base.D = center[a] - this->Origin[a];
  base.R2 = radius * radius;
  // Compared with float depths: a bound beyond the float range (a far origin or centre)
  // becomes an infinity in double first, which float holds.
  const double low = base.D - radius;
  constexpr double floatMax = 3.4028234663852886e38;
  base.DLow = static_cast<float>(low < -floatMax ? -HUGE_VAL : (low > floatMax ? HUGE_VAL : low));
  base.DHigh = base.D + radius;
  base.UCentre = center[ua];
  base.UAxis = ua;
  base.First = base.Last = 0;
  base.Offsets = this->Offsets;
  base.Depths = this->Depths;
  base.CellOf = this->CellOf;
  return true;
}

//------------------------------------------------------------------------------
inline bool vtkOFBSphereQuery::Chord(const Grid& grid, vtkIdType iv, Row& row) const
{
  // Only the cells under the circle's chord, one cell wider on each side than exact
  // arithmetic needs (the distance test decides), clamped before they become
  // integers as above. False if the row misses the sphere.
  const double s = this->CellSize;
  const double dv = this->Origin[grid.VAxis] + (iv + 0.5) * s - grid.CV;
  if (dv * dv > grid.Base.R2)
  {
    return false;
  }
  row = grid.Base;
  row.DV2 = dv * dv;
  row.RowBase = grid.Base.RowBase + iv * grid.NU;
  const double half = std::sqrt(row.R2 - row.DV2) * grid.InverseCellSize;
  row.U0 =
    static_cast<vtkIdType>(std::max(static_cast<double>(grid.U0), std::floor(grid.CU - half)));
  row.U1 =
    static_cast<vtkIdType>(std::min(static_cast<double>(grid.U1), std::ceil(grid.CU + half)));
  if (row.U0 > row.U1)
  {
    return false;
  }
  VTKOFB_PREFETCH(row.Offsets + row.RowBase + row.U0); // read by FetchRow
  VTKOFB_PREFETCH(row.Offsets + row.RowBase + row.U1 + 1);
  return true;
}

//------------------------------------------------------------------------------
template<typename Prefetch>
inline void vtkOFBSphereQuery::FetchRow(Row& row, Prefetch& prefetch) const
{
  row.First = row.Offsets[row.RowBase + row.U0];
  row.Last = row.Offsets[row.RowBase + row.U1 + 1];
  const vtkIdType last = std::min<vtkIdType>(row.Last, row.First + 512);
  const float* depths = row.Depths;
  // Without a cell index (never scanned then) the depths, 4 bytes a sample too, are
  // prefetched twice: no branch in the loop.
  const vtkTypeUInt32* cellIndex =
    row.CellOf ? row.CellOf : reinterpret_cast<const vtkTypeUInt32*>(depths);
  for (vtkIdType i = row.First; i < last; i += 16)
  {
    VTKOFB_PREFETCH(depths + i);
    VTKOFB_PREFETCH(cellIndex + i);
  }
  if (row.First < last)
  {
    VTKOFB_PREFETCH(depths + last - 1);
    VTKOFB_PREFETCH(cellIndex + last - 1);
    prefetch(row.First, last);
  }
}

//------------------------------------------------------------------------------
template<typename Functor, typename Prefetch>
void vtkOFBSphereQuery::ForEachSampleInSphere(const double center[3],
  double radius,
  Functor& f,
  Prefetch& prefetch) const
{
  if (this->CellSize <= 0.0 || !(radius >= 0.0) || this->NumberOfSamples == 0)
  {
    return;
  }
  for (int a = 0; a < 3; ++a)
  {
    Grid grid;
    if (!this->BeginGrid(a, center, radius, grid))
    {
      continue;
    }
    // Rows are computed three ahead (their offsets prefetched) and their samples are
    // prefetched two ahead: a sphere's rows lie far apart in memory.
    constexpr vtkIdType PlanAhead = 3;
    constexpr vtkIdType FetchAhead = 2;
    constexpr vtkIdType Ring = 4;
    Row ring[Ring];
    bool valid[Ring] = { false, false, false, false };
    auto plan = [&](vtkIdType iv) { valid[iv % Ring] = this->Chord(grid, iv, ring[iv % Ring]); };
    auto fetch = [&](vtkIdType iv)
    {
      if (valid[iv % Ring])
      {
        this->FetchRow(ring[iv % Ring], prefetch);
      }
    };
    for (vtkIdType iv = grid.V0; iv <= std::min(grid.V1, grid.V0 + PlanAhead - 1); ++iv)
    {
      plan(iv);
    }
    for (vtkIdType iv = grid.V0; iv <= std::min(grid.V1, grid.V0 + FetchAhead - 1); ++iv)
    {
      fetch(iv);
    }
    for (vtkIdType iv = grid.V0; iv <= grid.V1; ++iv)
    {
      if (iv + PlanAhead <= grid.V1)
      {
        plan(iv + PlanAhead);
      }
      if (iv + FetchAhead <= grid.V1)
      {
        fetch(iv + FetchAhead);
      }
      if (valid[iv % Ring])
      {
        this->ForEachSampleInRow(ring[iv % Ring], f);
      }
    }
  }
}

//------------------------------------------------------------------------------
template<typename Sphere, typename Functor, typename Prefetch>
void vtkOFBSphereQuery::ForEachSampleInSpheres(vtkIdType n,
  Sphere& sphere,
  Functor& f,
  Prefetch& prefetch) const
{
  if (n <= 0 || this->CellSize <= 0.0 || this->NumberOfSamples == 0)
  {
    return;
  }
  // A sphere of a few cells has a few rows, each a separate place in memory: one
  // sphere at a time waits for memory at every row. Here the rows of sphere k + 2
  // are found and their cell offsets prefetched, sphere k + 1's samples are
  // prefetched, and sphere k's are visited, so that each sphere's memory latency
  // overlaps the work of the two before it. Spheres of more rows than a plan holds
  // are queried alone (their rows hide each other's latency).
  constexpr int MaxRows = 48;
  struct Plan
  {
    double Center[3];
    double Radius;
    int NumberOfRows;
    bool Alone;
    Row Rows[MaxRows];
  };
  constexpr vtkIdType PlanAhead = 2;
  constexpr vtkIdType FetchAhead = 1;
  constexpr vtkIdType Ring = PlanAhead + 1;
  Plan plans[Ring];
  auto plan = [&](vtkIdType k, Plan& p)
  {
    sphere(k, p.Center, p.Radius);
    p.NumberOfRows = 0;
    p.Alone = false;
    if (!(p.Radius >= 0.0))
    {
      return;
    }
    for (int a = 0; a < 3; ++a)
    {
      Grid grid;
      if (!this->BeginGrid(a, p.Center, p.Radius, grid))
      {
        continue;
      }
      if (p.NumberOfRows + (grid.V1 - grid.V0 + 1) > MaxRows)
      {
        p.Alone = true;
        return;
      }
      for (vtkIdType iv = grid.V0; iv <= grid.V1; ++iv)
      {
        Row& row = p.Rows[p.NumberOfRows];
        if (this->Chord(grid, iv, row))
        {
          ++p.NumberOfRows;
        }
      }
    }
  };
  auto fetch = [&](Plan& p)
  {
    for (int j = 0; j < p.NumberOfRows; ++j)
    {
      this->FetchRow(p.Rows[j], prefetch);
    }
  };
  for (vtkIdType k = 0; k < std::min<vtkIdType>(n, PlanAhead); ++k)
  {
    plan(k, plans[k % Ring]);
  }
  for (vtkIdType k = 0; k < std::min<vtkIdType>(n, FetchAhead); ++k)
  {
    fetch(plans[k % Ring]);
  }
  for (vtkIdType k = 0; k < n; ++k)
  {
    if (k + PlanAhead < n)
    {
      plan(k + PlanAhead, plans[(k + PlanAhead) % Ring]);
    }
    if (k + FetchAhead < n)
    {
      fetch(plans[(k + FetchAhead) % Ring]);
    }
    Plan& p = plans[k % Ring];
    auto fk = [&f, k](vtkIdType i, double d2) { f(k, i, d2); };
    if (p.Alone)
    {
      this->ForEachSampleInSphere(p.Center, p.Radius, fk, prefetch);
      continue;
    }
    for (int j = 0; j < p.NumberOfRows; ++j)
    {
      this->ForEachSampleInRow(p.Rows[j], fk);
    }
  }
}

//------------------------------------------------------------------------------
template<typename Functor>
void vtkOFBSphereQuery::ForEachSampleInRow(const Row& row, Functor& f) const
{
  // A row's samples are consecutive: where its cells hold few samples each, one
  // linear pass over them all beats a search of each cell's depth range.
  if (row.CellOf && row.Last - row.First <= 6 * (row.U1 - row.U0 + 1))
  {
    this->ForEachSampleInRowScan(row, f);
  }
  else
  {
    this->ForEachSampleInRowCells(row, f);
  }
}

//------------------------------------------------------------------------------
template<typename Functor>
void vtkOFBSphereQuery::ForEachSampleInRowScan(const Row& row, Functor& f) const
{
  // Every sample of the row's cells, tested without a branch into a small batch of
  // hits, then handed to `f` in order. The squared distance is computed as in
  // ForEachSampleInRowCells, to the bit.
  const vtkTypeUInt32* cellOf = row.CellOf;
  const float* depths = row.Depths;
  const double s = this->CellSize;
  const double ou = this->Origin[row.UAxis];
  constexpr int Batch = 64;
  vtkIdType hit[Batch];
  double hitD2[Batch];
  vtkIdType i = row.First;
  const vtkIdType end = row.Last;
  while (i < end)
  {
    const vtkIdType stop = std::min(end, i + Batch);
    int n = 0;
    for (; i < stop; ++i)
    {
      const double iu = static_cast<double>(static_cast<vtkIdType>(cellOf[i]) - row.RowBase);
      const double du = ou + (iu + 0.5) * s - row.UCentre;
      const double duv2 = du * du + row.DV2;
      const double dd = depths[i] - row.D;
      const double dist2 = duv2 + dd * dd;
      hit[n] = i;
      hitD2[n] = dist2;
      n += dist2 <= row.R2;
    }
    for (int k = 0; k < n; ++k)
    {
      f(hit[k], hitD2[k]);
    }
  }
}

//------------------------------------------------------------------------------
template<typename Functor>
void vtkOFBSphereQuery::ForEachSampleInRowCells(const Row& row, Functor& f) const
{
  // Cell by cell: a cell's first sample at depth >= d - r by a linear scan over the
  // few samples of a typical cell, a binary search over many.
  const vtkTypeUInt32* offsets = row.Offsets;
  const float* depths = row.Depths;
  const double s = this->CellSize;
  const double ou = this->Origin[row.UAxis];
  for (vtkIdType iu = row.U0; iu <= row.U1; ++iu)
  {
    const double du = ou + (iu + 0.5) * s - row.UCentre;
    const double duv2 = du * du + row.DV2;
    if (duv2 > row.R2)
    {
      continue;
    }
    const vtkIdType cell = row.RowBase + iu;
    vtkIdType i = offsets[cell];
    const vtkIdType end = offsets[cell + 1];
    if (end - i > 8)
    {
      i = this->LowerBound(i, end, row.DLow);
    }
    else
    {
      while (i < end && depths[i] < row.DLow)
      {
        ++i;
      }
    }
    for (; i < end; ++i)
    {
      if (depths[i] > row.DHigh)
      {
        break;
      }
      const double dd = depths[i] - row.D;
      const double dist2 = duv2 + dd * dd;
      if (dist2 <= row.R2)
      {
        f(i, dist2);
      }
    }
  }
}

//------------------------------------------------------------------------------
inline vtkIdType vtkOFBSphereQuery::LowerBound(vtkIdType begin, vtkIdType end, float d) const
{
  return static_cast<vtkIdType>(
    std::lower_bound(this->Depths + begin, this->Depths + end, d) - this->Depths);
}

#endif
