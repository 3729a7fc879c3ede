// Private header of vtkOFBLIC: the streamline tracer and the convolution of one sample
// (paper "Sample-based Surface Coloring", section 6.2.3, Eq. 4).
#ifndef vtkOFBLICTracer_h
#define vtkOFBLICTracer_h

#include "vtkOFB.h"
#include "vtkOFBPrefetch.h"
#include "vtkType.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// The step's functions inlined into the tracing loop (a call per step, through the
// shared library's PLT, otherwise).
#if defined(__GNUC__)
#define VTKOFB_LIC_INLINE __attribute__((always_inline)) inline
#else
#define VTKOFB_LIC_INLINE inline
#endif

/**
 * What a streamline step reads of a sample, packed in 40 bytes so that one step touches
 * one place: the position (in cells from the OFB's origin: the tracer's frame, in which
 * a cell's index is the integer part of a coordinate), the unit normal, the tangent field
 * (unit or relative to the strongest flow, zero where masked) and the flags (grid axis in
 * bits 0-1, masked in bit 2, the tile of vtkOFBLICTiles from bit 3).
 */
struct vtkOFBLICSample
{
  float Position[3];
  float Normal[3];
  float Field[3];
  vtkTypeInt32 Flags;

  int Axis() const { return this->Flags & 3; }
  bool Masked() const { return (this->Flags & 4) != 0; }
  vtkIdType Tile() const { return this->Flags >> 3; }
};

/**
 * The samples in cubic tiles of Size x Size x Size cells of the OFB's box (64, larger
 * only at high resolutions), whichever of the three grids holds them, numbered x
 * fastest: vtkOFBLIC traces and convolves tile by tile (the streamlines of a tile stay
 * in a neighbourhood that stays in a core's cache).
 * Where the surface turns from one grid to another a streamline stays in its tile, which
 * it left with square tiles of one grid's cells: cubic tiles give fewer and longer seed
 * streamlines, so fewer steps a sample. The tile of a sample is that of its position (TileOf); the
 * samples of each tile, in increasing order, are listed by vtkOFBLIC::PrepareSamples (First: where
 * each tile's list starts in Ids, one entry more than tiles).
 */
struct vtkOFBLICTiles
{
  vtkIdType Size = 64;               // cells along each edge of a tile
  vtkIdType Counts[3] = { 0, 0, 0 }; // tiles along x, y and z
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Scale = 0.0; // tiles per world unit
  const vtkIdType* First = nullptr;
  const vtkTypeInt32* Ids = nullptr;

  /**
   * Tiles of 64 cells, or of twice as many as often as needed to keep their number at
   * most 4096 or one per 256 samples: the tiles of a box grow with the cube of the
   * resolution, the samples of a surface with its square (at 16384 cells, 64-cell tiles
   * would be 16.8 M, about 1 GB of per-tile bookkeeping).
   */
  vtkOFBLICTiles(const vtkIdType dims[3],
    const double origin[3],
    double cellSize,
    vtkIdType numberOfSamples)
  {
    const vtkIdType most = std::max<vtkIdType>(4096, numberOfSamples / 256);
    for (;; this->Size *= 2)
    {
      for (int a = 0; a < 3; ++a)
      {
        this->Counts[a] = std::max<vtkIdType>(1, (dims[a] + this->Size - 1) / this->Size);
      }
      if (this->GetNumberOfTiles() <= most)
      {
        break;
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      this->Origin[a] = origin[a];
    }
    this->Scale = 1.0 / (cellSize * this->Size);
  }

  vtkIdType GetNumberOfTiles() const { return this->Counts[0] * this->Counts[1] * this->Counts[2]; }

  /**
   * The cells of grid a under tile t: u (along axis (a + 1) % 3) in [range[0], range[1])
   * and v (along (a + 2) % 3) in [range[2], range[3]), within the grid's dims.
   */
  void GetCellRange(vtkIdType t, int a, const vtkIdType dims[3], vtkIdType range[4]) const
  {
    const vtkIdType c[3] = { t % this->Counts[0],
      (t / this->Counts[0]) % this->Counts[1],
      t / (this->Counts[0] * this->Counts[1]) };
    for (int k = 0; k < 2; ++k)
    {
      const int axis = (a + 1 + k) % 3;
      range[2 * k] = std::min(dims[axis], c[axis] * this->Size);
      range[2 * k + 1] = std::min(dims[axis], (c[axis] + 1) * this->Size);
    }
  }

  /// The tile of position x (clamped to the box).
  vtkIdType TileOf(const double x[3]) const
  {
    vtkIdType t[3];
    for (int a = 0; a < 3; ++a)
    {
      const double f = (x[a] - this->Origin[a]) * this->Scale;
      // Clamped in double before the conversion (NaN, from an infinite position, to 0).
      t[a] =
        f > 0.0 ? static_cast<vtkIdType>(std::min(f, static_cast<double>(this->Counts[a] - 1))) : 0;
    }
    return (t[2] * this->Counts[1] + t[1]) * this->Counts[0] + t[0];
  }

  /// Call f(i) for every sample of tile t, in increasing order.
  template<typename F>
  void ForEachSample(vtkIdType t, F&& f) const
  {
    for (vtkIdType k = this->First[t], end = this->First[t + 1]; k < end; ++k)
    {
      f(static_cast<vtkIdType>(this->Ids[k]));
    }
  }
};

/**
 * Keeps the compiler from dropping the loads whose values went into v: vtkOFBLIC reads
 * a tile's data once in order before tracing it (see vtkOFBLIC::TraceTile).
 */
VTKOFB_LIC_INLINE void vtkOFBLICKeep(vtkTypeUInt32 v)
{
#if defined(__GNUC__)
  __asm__ __volatile__("" : : "r"(v));
#else
  static volatile vtkTypeUInt32 sink;
  sink = v;
#endif
}

/**
 * Traces a streamline forward and backward from a sample over the surface the OFB
 * samples, recording the samples it meets (Trace), and returns the kernel-weighted mean
 * of a per-sample input (the noise, or the first pass's result) over those samples
 * (Gather, Eq. 4). A streamline is 2 NumberOfSteps sample ids: the forward steps, then
 * the backward steps, each direction ended early by -1 where the streamline stops.
 * Tracing depends only on the geometry and the field, the weights only on the kernel
 * and AnimationPhase: vtkOFBLIC keeps the streamlines and re-convolves by gathering.
 *
 * A step moves the 3-D position by the field of the current sample (in its tangent
 * plane, StepSize cells long when normalized), looks up the sample there
 * (in the cell under it of the grid of the current sample, else of the other two grids
 * in the order of the normal's components, else as vtkOFB::FindClosestSample within
 * sqrt(3) cells over all three grids, so that a
 * streamline crosses from one grid to another and over edges of the surface) and
 * projects the position onto that sample's tangent plane, which keeps it on the
 * surface. A streamline stops at a masked sample, where no sample is near (the border
 * of an open surface), or where the normal turns by more than 120 degrees in one step
 * (a jump to another sheet of a thin part).
 *
 * Every member is read-only while tracing: one tracer serves all threads.
 */
class vtkOFBLICTracer
{
public:
  const vtkOFB* OFB = nullptr;
  const vtkOFBLICSample* Samples = nullptr;
  int NumberOfSteps = 0;
  float Step = 0.0f;          // cells
  double SearchRadius = 0.0;  // world units
  double FieldRadius = 0.0;   // world units; > 0: inverse-distance field, else nearest
  float ReuseDistance = 0.0f; // cells; fast LIC: see vtkOFBLIC::TraceTile

  // The OFB's frame and storage, read directly in the inner loop.
  const vtkTypeUInt32* Offsets = nullptr;
  const float* Depths = nullptr;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double CellSize = 0.0;
  double InverseCellSize = 0.0;
  vtkIdType Dimensions[3] = { 0, 0, 0 };
  vtkIdType CellBase[4] = { 0, 0, 0, 0 };
  // Per grid, what FindInGrid reads: the axes across it, their cells, the first cell.
  struct Grid
  {
    int U;
    int V;
    vtkTypeUInt32 CellsU;
    vtkTypeUInt32 CellsV;
    vtkIdType Base;
  };
  Grid Grids[3];
  float CellSizeF = 0.0f;

  /// Take the frame and storage of `ofb` (which the tracer then only reads).
  void SetOFB(vtkOFB* ofb)
  {
    this->OFB = ofb;
    this->Offsets = ofb->GetCellOffsets()->GetPointer(0);
    this->Depths = ofb->GetDepths()->GetPointer(0);
    ofb->GetOrigin(this->Origin);
    this->CellSize = ofb->GetCellSize();
    this->InverseCellSize = 1.0 / this->CellSize;
    ofb->GetDimensions(this->Dimensions);
    for (int a = 0; a < 4; ++a)
    {
      this->CellBase[a] = ofb->GetGridCellBase(a);
    }
    for (int a = 0; a < 3; ++a)
    {
      Grid& g = this->Grids[a];
      g.U = (a + 1) % 3;
      g.V = (a + 2) % 3;
      g.CellsU = static_cast<vtkTypeUInt32>(this->Dimensions[g.U]);
      g.CellsV = static_cast<vtkTypeUInt32>(this->Dimensions[g.V]);
      g.Base = this->CellBase[a];
    }
    this->CellSizeF = static_cast<float>(this->CellSize);
  }

  /// A position of the tracer's frame (cells from the origin) in world coordinates.
  glm::dvec3 World(const float* x) const
  {
    return glm::dvec3(this->Origin[0] + this->CellSize * x[0],
      this->Origin[1] + this->CellSize * x[1],
      this->Origin[2] + this->CellSize * x[2]);
  }

  /**
   * The sample of grid `a` closest in depth to q (in cells from the origin) in the cell
   * under q, within one cell (vtkOFB::FindSample for a known grid, with a linear scan:
   * cells hold few samples). A coordinate in [-1, 0) must not truncate to cell 0: the
   * cell index is that of the coordinate plus one, less one, unsigned (below 0 it wraps
   * to a large number, as does a NaN's or an infinity's conversion).
   */
  VTKOFB_LIC_INLINE vtkIdType FindInGrid(int a, const float q[3]) const
  {
    const Grid& g = this->Grids[a];
    const vtkTypeUInt32 iu = static_cast<vtkTypeUInt32>(static_cast<int>(q[g.U] + 1.0f)) - 1u;
    const vtkTypeUInt32 iv = static_cast<vtkTypeUInt32>(static_cast<int>(q[g.V] + 1.0f)) - 1u;
    if (!(iu < g.CellsU && iv < g.CellsV))
    {
      return -1;
    }
    const vtkIdType cell = g.Base + static_cast<vtkIdType>(iv) * g.CellsU + iu;
    // The depth of q in world units from the origin, as the OFB keeps depths.
    const float d = q[a] * this->CellSizeF;
    const vtkIdType begin = this->Offsets[cell];
    const vtkIdType end = this->Offsets[cell + 1];
    // The record of the cell's first sample, the likely answer, is fetched while the
    // depths are compared: the two misses of the step's chain overlap.
    VTKOFB_PREFETCH(this->Samples + begin);
    vtkIdType best = -1;
    float bestDistance = this->CellSizeF;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float distance = std::fabs(this->Depths[i] - d);
      const bool take = distance <= bestDistance;
      best = take ? i : best;
      bestDistance = take ? distance : bestDistance;
    }
    return best;
  }

  /**
   * vtkOFB::FindClosestSample(q, SearchRadius) for the few cells of a radius of
   * sqrt(3) cells: the same candidates, distances computed as vtkOFB computes them and
   * the same tie-break (the lowest id), so the same sample, without the general sphere
   * query's planning and prefetching of rows.
   */
  vtkIdType FindClosest(const glm::dvec3& q) const
  {
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
    {
      return -1;
    }
    const double s = this->CellSize;
    const double r = this->SearchRadius;
    const double r2 = r * r;
    vtkIdType best = -1;
    double bestDistance2 = r2;
    for (int a = 0; a < 3; ++a)
    {
      const int ua = (a + 1) % 3;
      const int va = (a + 2) % 3;
      const vtkIdType nu = this->Dimensions[ua];
      const vtkIdType nv = this->Dimensions[va];
      const double lu = (q[ua] - r - this->Origin[ua]) / s - 0.5;
      const double hu = (q[ua] + r - this->Origin[ua]) / s - 0.5;
      const double lv = (q[va] - r - this->Origin[va]) / s - 0.5;
      const double hv = (q[va] + r - this->Origin[va]) / s - 0.5;
      if (!(hu >= 0.0 && hv >= 0.0 && lu <= nu - 1 && lv <= nv - 1))
      {
        continue;
      }
      const vtkIdType u0 = static_cast<vtkIdType>(std::ceil(std::max(lu, 0.0)));
      const vtkIdType u1 = static_cast<vtkIdType>(std::floor(std::min(hu, nu - 1.0)));
      const vtkIdType v0 = static_cast<vtkIdType>(std::ceil(std::max(lv, 0.0)));
      const vtkIdType v1 = static_cast<vtkIdType>(std::floor(std::min(hv, nv - 1.0)));
      const double d = q[a] - this->Origin[a];
      for (vtkIdType v = v0; v <= v1; ++v)
      {
        const double dv = this->Origin[va] + (v + 0.5) * s - q[va];
        const double dv2 = dv * dv;
        if (dv2 > r2)
        {
          continue;
        }
        const vtkIdType row = this->CellBase[a] + v * nu;
        for (vtkIdType u = u0; u <= u1; ++u)
        {
          const double du = this->Origin[ua] + (u + 0.5) * s - q[ua];
          const double duv2 = du * du + dv2;
          if (duv2 > r2)
          {
            continue;
          }
          for (vtkIdType i = this->Offsets[row + u], end = this->Offsets[row + u + 1]; i < end; ++i)
          {
            const double dd = this->Depths[i] - d;
            const double distance2 = duv2 + dd * dd;
            if (distance2 < bestDistance2 || (distance2 == bestDistance2 && best < 0))
            {
              bestDistance2 = distance2;
              best = i;
            }
          }
        }
      }
    }
    return best;
  }

  /**
   * Up to `steps` steps each way from sample i: the samples met forward to ahead[] and
   * backward to back[], their numbers returned in nAhead and nBack. The two directions
   * advance together: two independent chains of dependent loads, which the processor
   * overlaps. A direction also stops once its last `idle` samples all failed
   * `useful(k, p, dir, step)` (k the sample met at position p, the step-th step of
   * direction dir; fast LIC: the samples a seed streamline can still give a window to);
   * `ended` is
   * true for a direction that stopped by itself (masked sample, border, fold), not for
   * one that ran out of steps or went idle.
   */
  template<typename Useful>
  void TraceBoth(vtkIdType i,
    int steps,
    int idle,
    Useful&& useful,
    vtkTypeInt32* ahead,
    int& nAhead,
    bool& aheadEnded,
    vtkTypeInt32* back,
    int& nBack,
    bool& backEnded) const
  {
    glm::vec3 pf = Vec3(this->Samples[i].Position);
    glm::vec3 pb = pf;
    vtkIdType jf = i;
    vtkIdType jb = i;
    nAhead = 0;
    nBack = 0;
    aheadEnded = false;
    backEnded = false;
    int idleAhead = 0;
    int idleBack = 0;
    bool forward = steps > 0;
    bool backward = steps > 0;
    while (forward || backward)
    {
      if (forward)
      {
        jf = this->Advance(pf, jf, 1);
        aheadEnded = jf < 0;
        forward = !aheadEnded;
        if (forward)
        {
          ahead[nAhead++] = static_cast<vtkTypeInt32>(jf);
          idleAhead = (idleAhead + 1) * !useful(jf, pf, 1, nAhead - 1);
          forward = nAhead < steps && idleAhead < idle;
        }
      }
      if (backward)
      {
        jb = this->Advance(pb, jb, -1);
        backEnded = jb < 0;
        backward = !backEnded;
        if (backward)
        {
          back[nBack++] = static_cast<vtkTypeInt32>(jb);
          idleBack = (idleBack + 1) * !useful(jb, pb, -1, nBack - 1);
          backward = nBack < steps && idleBack < idle;
        }
      }
    }
  }

  /// The streamline of sample i into line[0, 2 NumberOfSteps) (see the class comment).
  void Trace(vtkIdType i, vtkTypeInt32* line) const
  {
    const int n = this->NumberOfSteps;
    int ahead, back;
    bool aheadEnded, backEnded;
    this->TraceBoth(
      i,
      n,
      n + 1,
      [](vtkIdType, const glm::vec3&, int, int) { return true; },
      line,
      ahead,
      aheadEnded,
      line + n,
      back,
      backEnded);
    std::fill(line + ahead, line + n, -1);
    std::fill(line + n + back, line + 2 * n, -1);
  }

  /**
   * Eq. 4 at sample i over the per-sample values `input`, along its streamline `line`;
   * `weights` has 2 n + 1 entries, index n is t = 0; `inverseTotal` is 1 over their sum
   * in the order summed here (a full streamline multiplies by it instead of dividing).
   */
  static float Gather(vtkIdType i,
    const vtkTypeInt32* line,
    int n,
    const double* weights,
    double inverseTotal,
    const float* input)
  {
    double acc = weights[n] * input[i];
    double sum = weights[n];
    int full = 0;
    for (int dir = 1; dir >= -1; dir -= 2)
    {
      const vtkTypeInt32* ids = line + (dir > 0 ? 0 : n);
      const double* w = weights + n + dir;
      int s = 0;
      for (; s < n && ids[s] >= 0; ++s, w += dir)
      {
        acc += *w * input[ids[s]];
        sum += *w;
      }
      full += s;
    }
    if (full == 2 * n && inverseTotal > 0.0)
    {
      return static_cast<float>(acc * inverseTotal);
    }
    return sum > 1e-9 ? static_cast<float>(acc / sum) : input[i];
  }

  /**
   * Eq. 4 as Gather, along a streamline kept in a run of fast LIC: at[0] is the sample,
   * at[s] and at[-s] its steps forward and backward, -1 where the streamline stops, and
   * v[s] the input value at at[s] (the run's values copied beside it, so that the window
   * is read contiguously; a gather through the ids waited on its loads).
   */
  template<typename Values>
  static float GatherRun(const vtkTypeInt32* at,
    const Values& v,
    int n,
    const double* weights,
    double inverseTotal)
  {
    double acc = weights[n] * v[0];
    double sum = weights[n];
    int s = 1;
    for (; s <= n && at[s] >= 0; ++s)
    {
      acc += weights[n + s] * v[s];
      sum += weights[n + s];
    }
    int b = 1;
    for (; b <= n && at[-b] >= 0; ++b)
    {
      acc += weights[n - b] * v[-b];
      sum += weights[n - b];
    }
    if (s + b == 2 * n + 2 && inverseTotal > 0.0)
    {
      return static_cast<float>(acc * inverseTotal);
    }
    return sum > 1e-9 ? static_cast<float>(acc / sum) : v[0];
  }

  /**
   * GatherRun where the window is whole, at[-n .. n] all samples (no -1 of a run's
   * end; the caller makes sure that they lie in the run store) and the weights' total
   * is above 1e-9 (inverseTotal > 0): the weighted sum in four independent
   * accumulators, times inverseTotal, into `out`. False, with nothing written,
   * otherwise. (A run's values are contiguous, so the chain of additions of one
   * accumulator, not the loads, is what GatherRun waits on.)
   */
  template<typename Values>
  static bool GatherWhole(const vtkTypeInt32* at,
    const Values& v,
    int n,
    const double* weights,
    double inverseTotal,
    float& out)
  {
    vtkTypeInt32 sign = 0;
    for (int s = -n; s <= n; ++s)
    {
      sign |= at[s];
    }
    if (sign < 0 || !(inverseTotal > 0.0))
    {
      return false;
    }
    // v[k - n] is the value at position k - n, weights[k] its weight.
    const int count = 2 * n + 1;
    double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0;
    int k = 0;
    for (; k + 4 <= count; k += 4)
    {
      a0 += weights[k] * v[k - n];
      a1 += weights[k + 1] * v[k + 1 - n];
      a2 += weights[k + 2] * v[k + 2 - n];
      a3 += weights[k + 3] * v[k + 3 - n];
    }
    for (; k < count; ++k)
    {
      a0 += weights[k] * v[k - n];
    }
    out = static_cast<float>(((a0 + a1) + (a2 + a3)) * inverseTotal);
    return true;
  }

  /**
   * The values of a window read through its ids: (*this)[s] is input[at[s]] (for
   * GatherRun and GatherWhole without a copy of the run's values).
   */
  struct ThroughIds
  {
    const vtkTypeInt32* At;
    const float* Input;
    float operator[](int s) const { return this->Input[this->At[s]]; }
  };

  /**
   * 1 over the sum of the 2 n + 1 weights in the order Gather and GatherRun add them
   * (the centre, then forward, then backward), 0 where it is not above 1e-9 (the
   * division and its fallback then apply).
   */
  static double InverseTotal(const double* weights, int n)
  {
    double sum = weights[n];
    for (int s = 1; s <= n; ++s)
    {
      sum += weights[n + s];
    }
    for (int s = 1; s <= n; ++s)
    {
      sum += weights[n - s];
    }
    return sum > 1e-9 ? 1.0 / sum : 0.0;
  }

  /**
   * One step from position p at sample j in direction dir (+1 forward, -1 backward):
   * p becomes the new position on the surface; returns the new sample, or -1 where
   * the streamline stops.
   */
  VTKOFB_LIC_INLINE vtkIdType Advance(glm::vec3& p, vtkIdType j, int dir) const
  {
    const vtkOFBLICSample& sj = this->Samples[j];
    // The nearest field (the default) inline: the sample's own vector.
    const glm::vec3 v = this->FieldRadius > 0.0 ? this->FieldAt(p, j) : Vec3(sj.Field);
    float q[3];
    const float step = dir > 0 ? this->Step : -this->Step;
    for (int c = 0; c < 3; ++c)
    {
      q[c] = p[c] + step * v[c];
    }
    // The grid of sample j first (the surface mostly goes on in the same grid), then the
    // other two in the order of the normal's components (where the surface goes on in
    // another grid, the cell under q mostly holds its sample), then all three within
    // sqrt(3) cells.
    const int axis = sj.Axis();
    vtkIdType k = this->FindInGrid(axis, q);
    if (k < 0)
    {
      const int b = (axis + 1) % 3;
      const int c = (axis + 2) % 3;
      const bool bFirst = std::fabs(sj.Normal[b]) >= std::fabs(sj.Normal[c]);
      k = this->FindInGrid(bFirst ? b : c, q);
      if (k < 0)
      {
        k = this->FindInGrid(bFirst ? c : b, q);
      }
      if (k < 0)
      {
        k = this->FindClosest(this->World(q));
      }
    }
    if (k < 0 || this->Samples[k].Masked())
    {
      return -1;
    }
    const vtkOFBLICSample& sk = this->Samples[k];
    const glm::vec3 nk = Vec3(sk.Normal);
    if (glm::dot(Vec3(sj.Normal), nk) < -0.5f)
    {
      return -1;
    }
    const glm::vec3 qv(q[0], q[1], q[2]);
    p = qv - glm::dot(qv - Vec3(sk.Position), nk) * nk;
    return k;
  }

  /**
   * The field at p on the surface near sample j: the sample's own vector, or with
   * FieldRadius > 0 the Shepard-weighted mean of the unmasked samples within FieldRadius
   * whose normal is within 60 degrees of j's, projected into j's tangent plane and given
   * the length of j's vector.
   */
  glm::vec3 FieldAt(const glm::vec3& p, vtkIdType j) const
  {
    const glm::dvec3 vj = Vec(this->Samples[j].Field);
    if (this->FieldRadius <= 0.0)
    {
      return glm::vec3(vj);
    }
    const glm::dvec3 nj = Vec(this->Samples[j].Normal);
    const double eps = 1e-4 * this->CellSize * this->CellSize;
    const glm::dvec3 x = this->World(&p.x);
    glm::dvec3 sum(0.0);
    this->OFB->ForEachSampleInSphere(&x.x,
      this->FieldRadius,
      [&](vtkIdType k, double d2)
      {
        const vtkOFBLICSample& sk = this->Samples[k];
        if (!sk.Masked() && glm::dot(Vec(sk.Normal), nj) > 0.5)
        {
          sum += Vec(sk.Field) / (d2 + eps);
        }
      });
    sum -= glm::dot(sum, nj) * nj;
    const double length = glm::length(sum);
    return glm::vec3(length > 0.0 ? sum * (glm::length(vj) / length) : vj);
  }

  /// The axis of the largest component of n (the grid vtkOFB::FindSample searches).
  static int Dominant(const glm::dvec3& n)
  {
    const glm::dvec3 a = glm::abs(n);
    return a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
  }

  static glm::dvec3 Vec(const float* a) { return glm::dvec3(a[0], a[1], a[2]); }

  static glm::vec3 Vec3(const float* a) { return glm::vec3(a[0], a[1], a[2]); }

  static glm::dvec3 Vec(const float* a, vtkIdType i)
  {
    return glm::dvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
  }
};

/**
 * One sample's window of the first pass of fast LIC with Animate on, as sums that do not
 * depend on AnimationPhase (see vtkOFBLICKernelParts): over the window's steps s in
 * [Low, High], A = sum K(s) v(s), C = sum K(s) cos(2 pi s / n) v(s) and
 * S = sum K(s) sin(2 pi s / n) v(s), v the noise (16 bytes a sample).
 */
struct vtkOFBLICMoments
{
  float A;
  float C;
  float S;
  vtkTypeInt16 Low;
  vtkTypeInt16 High;
};

/**
 * The animated kernel of fast LIC in three parts, so that another AnimationPhase needs
 * no gathering: the weight of step s, K(s) (1 + cos(2 pi (s / n + phase))) / 2
 * (vtkOFBLIC::ComputeKernel, K the kernel without the animation), is half of
 * K(s) + c K(s) cos(2 pi s / n) - d K(s) sin(2 pi s / n), c = cos(2 pi phase) and
 * d = sin(2 pi phase). A sample's window is gathered once into its vtkOFBLICMoments
 * (Gather) and each phase combines them (Combine: O(1) a sample, the weights' total
 * over the window from prefix sums). The first computation and a re-convolution both
 * combine, so they give the same values bit for bit.
 */
struct vtkOFBLICKernelParts
{
  int N = 0;
  std::vector<double> Base; // 2 n + 1 entries each, index n is s = 0
  std::vector<double> Cos;
  std::vector<double> Sin;
  std::vector<double> Prefix[3]; // 2 n + 2 entries: the sums of Base, Cos, Sin below index j
  double C = 1.0;
  double S = 0.0;

  /// `base`: the 2 n + 1 weights of the kernel without the animation.
  void Set(const std::vector<double>& base, int n, double phase)
  {
    const double pi = 3.141592653589793;
    this->N = n;
    this->Base = base;
    this->Cos.assign(2 * n + 1, 0.0);
    this->Sin.assign(2 * n + 1, 0.0);
    for (int s = -n; s <= n; ++s)
    {
      const double t = n > 0 ? 2.0 * pi * s / n : 0.0;
      this->Cos[s + n] = base[s + n] * std::cos(t);
      this->Sin[s + n] = base[s + n] * std::sin(t);
    }
    const std::vector<double>* parts[3] = { &this->Base, &this->Cos, &this->Sin };
    for (int k = 0; k < 3; ++k)
    {
      this->Prefix[k].assign(2 * n + 2, 0.0);
      for (int j = 0; j <= 2 * n; ++j)
      {
        this->Prefix[k][j + 1] = this->Prefix[k][j] + (*parts[k])[j];
      }
    }
    this->C = std::cos(2.0 * pi * phase);
    this->S = std::sin(2.0 * pi * phase);
  }

  /**
   * The moments of the window of a kept run (as vtkOFBLICTracer::GatherRun: at[0] the
   * sample, at[s] and at[-s] its steps, -1 where the streamline stops, v[s] the value).
   */
  template<typename Values>
  void Gather(const vtkTypeInt32* at, const Values& v, vtkOFBLICMoments& m) const
  {
    const int n = this->N;
    const double* base = this->Base.data() + n;
    const double* cs = this->Cos.data() + n;
    const double* sn = this->Sin.data() + n;
    double a = base[0] * v[0];
    double c = cs[0] * v[0];
    double d = 0.0;
    int f = 1;
    for (; f <= n && at[f] >= 0; ++f)
    {
      a += base[f] * v[f];
      c += cs[f] * v[f];
      d += sn[f] * v[f];
    }
    int b = 1;
    for (; b <= n && at[-b] >= 0; ++b)
    {
      a += base[-b] * v[-b];
      c += cs[-b] * v[-b];
      d += sn[-b] * v[-b];
    }
    m.A = static_cast<float>(a);
    m.C = static_cast<float>(c);
    m.S = static_cast<float>(d);
    m.Low = static_cast<vtkTypeInt16>(1 - b);
    m.High = static_cast<vtkTypeInt16>(f - 1);
  }

  /// Eq. 4 for the current phase from a sample's moments; `own`: its input value (the
  /// result where the weights' total is not above 1e-9, as in Gather).
  float Combine(const vtkOFBLICMoments& m, float own) const
  {
    const int lo = m.Low + this->N;
    const int hi = m.High + this->N + 1;
    const double total = (this->Prefix[0][hi] - this->Prefix[0][lo]) +
      this->C * (this->Prefix[1][hi] - this->Prefix[1][lo]) -
      this->S * (this->Prefix[2][hi] - this->Prefix[2][lo]);
    const double acc = static_cast<double>(m.A) + this->C * m.C - this->S * m.S;
    return total > 2e-9 ? static_cast<float>(acc / total) : own;
  }
};

#endif
