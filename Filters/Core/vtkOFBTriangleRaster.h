/**
 * @class   vtkOFBTriangleRaster
 * @brief   A triangle set up for scan conversion into an OFB grid (private)
 *
 * Used by the CPU backend of vtkOFBSampler (vtkOFBCPUSampler,
 * vtkOFBSamplerBands.cxx). Each triangle goes to the grid of the axis closest to its
 * face normal. Coverage is decided on a fixed-point lattice of 1/2^SubBits cell
 * (cell centres on its integer multiples of 2^SubBits) by three edge functions,
 * inside where all are >= 0: edge i at cell (iu, iv) is
 * Edge[i] + StepV(i) * (iv - V0) + StepU(i) * (iu - U0). A centre
 * exactly on an edge belongs to the triangle for which that edge is a left or
 * bottom edge: the top-left rule of raster (y-down) coordinates, as Mesa's OpenGL
 * rasterizer, so that the OpenGL backend covers the same centres and a shared edge
 * gives neither a hole nor a duplicate. Depth and barycentrics are linear
 * functions of the cell, from the true (unsnapped) geometry.
 */

#ifndef vtkOFBTriangleRaster_h
#define vtkOFBTriangleRaster_h

#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

/// The frame of an OFB as the rasterizer needs it.
struct vtkOFBRasterFrame
{
  double Origin[3];
  double InvCell;
  vtkIdType Dims[3];
  vtkIdType CellBase[3];
};

struct vtkOFBTriangleRaster
{
  /// Sub-cell bits of the fixed-point lattice that decides coverage.
  static constexpr int SubBits = 8;
  // With at most 65536 cells a side, lattice coordinates stay below 2^(16 + SubBits)
  // and edge functions below 2^(33 + 2 SubBits): int64_t while SubBits <= 14.
  static_assert(SubBits <= 14, "edge functions must fit in 64-bit integers");

  // 160 bytes a triangle, written once and read by both passes: kept small.
  // Read by the span pass: the rows and the edge functions.
  int64_t Edge[3];        // edge functions at (U0, V0)
  int32_t DX[3], DY[3];   // lattice vectors of the edges (coordinates < 2^(16 + SubBits))
  int32_t U0, U1, V0, V1; // cells of the bounding box, clipped to the grid (inclusive)
  // Read by the sample pass: barycentrics, depths and the triangle.
  // w1 = A1*iu + B1*iv + C1, w2 = A2*iu + B2*iv + C2
  double A1, B1, C1, A2, B2, C2;
  double D0, D1, D2;    // depths of the vertices (world units from the grid plane)
  vtkTypeUInt32 Ids[3]; // point ids of the vertices (beside the plane: no other lookup)
  vtkTypeUInt32 Tri;    // index of the triangle in the surface
  int8_t Axis;          // grid, or -1 when the triangle covers no cell centre
  bool MayCancel;       // its point normals may cancel (set by the sampler, not by Setup)

  /// The point ids of the vertices, as the attribute interpolator takes them.
  void GetPointIds(vtkIdType ids[3]) const
  {
    ids[0] = this->Ids[0];
    ids[1] = this->Ids[1];
    ids[2] = this->Ids[2];
  }

  ///@{
  /// The change of edge function i from a cell to the next along u, and along v.
  int64_t StepU(int i) const
  {
    return -static_cast<int64_t>(this->DY[i]) * (int64_t(1) << SubBits);
  }
  int64_t StepV(int i) const { return static_cast<int64_t>(this->DX[i]) * (int64_t(1) << SubBits); }
  ///@}

  /**
   * The grid of a triangle: the axis of the largest component of its normal n
   * (twice its area, by its winding; copied to `normal` when given); `front`
   * tells whether n points against that axis (n[a] < 0).
   */
  static int DominantAxis(const double* p0,
    const double* p1,
    const double* p2,
    bool& front,
    double* normal = nullptr)
  {
    double e1[3], e2[3];
    for (int k = 0; k < 3; ++k)
    {
      e1[k] = p1[k] - p0[k];
      e2[k] = p2[k] - p0[k];
    }
    const double n[3] = {
      e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]
    };
    int a = 0;
    if (std::fabs(n[1]) > std::fabs(n[a]))
    {
      a = 1;
    }
    if (std::fabs(n[2]) > std::fabs(n[a]))
    {
      a = 2;
    }
    front = n[a] < 0.0;
    if (normal)
    {
      std::copy(n, n + 3, normal);
    }
    return a;
  }

  /**
   * x rounded to the nearest integer, halves away from zero (std::llround, inline):
   * for |x| < 2^62, where the truncation and the remainder are exact.
   */
  static int64_t Round(double x)
  {
    const auto t = static_cast<int64_t>(x);
    const double rest = x - static_cast<double>(t);
    return t + (rest >= 0.5) - (rest <= -0.5);
  }

  /**
   * Set up triangle `tri` (three point ids, below 2^32) of the points P (xyz) for
   * frame f, in the grid of axis a (its DominantAxis).
   */
  void Setup(const double* P, const vtkIdType* tri, int a, const vtkOFBRasterFrame& f)
  {
    this->Axis = -1;
    this->Ids[0] = static_cast<vtkTypeUInt32>(tri[0]);
    this->Ids[1] = static_cast<vtkTypeUInt32>(tri[1]);
    this->Ids[2] = static_cast<vtkTypeUInt32>(tri[2]);
    const double* p[3] = { P + 3 * tri[0], P + 3 * tri[1], P + 3 * tri[2] };
    const int ua = (a + 1) % 3;
    const int va = (a + 2) % 3;
    const int64_t one = int64_t(1) << SubBits;
    double U[3], V[3];
    int64_t X[3], Y[3];
    for (int i = 0; i < 3; ++i)
    {
      U[i] = (p[i][ua] - f.Origin[ua]) * f.InvCell - 0.5;
      V[i] = (p[i][va] - f.Origin[va]) * f.InvCell - 0.5;
      X[i] = Round(U[i] * one);
      Y[i] = Round(V[i] * one);
    }
    const int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
    const double denom = (U[1] - U[0]) * (V[2] - V[0]) - (V[1] - V[0]) * (U[2] - U[0]);
    if (area == 0 || denom == 0.0)
    {
      return; // covers no cell centre
    }
    if (area < 0)
    {
      std::swap(X[1], X[2]);
      std::swap(Y[1], Y[2]);
    }
    // Cells whose centre lies in the bounding box, clipped to the grid.
    const int64_t minX = std::min({ X[0], X[1], X[2] });
    const int64_t maxX = std::max({ X[0], X[1], X[2] });
    const int64_t minY = std::min({ Y[0], Y[1], Y[2] });
    const int64_t maxY = std::max({ Y[0], Y[1], Y[2] });
    const int64_t u0 = std::max<int64_t>(0, (minX + one - 1) >> SubBits);
    const int64_t u1 = std::min<int64_t>(f.Dims[ua] - 1, maxX >> SubBits);
    const int64_t v0 = std::max<int64_t>(0, (minY + one - 1) >> SubBits);
    const int64_t v1 = std::min<int64_t>(f.Dims[va] - 1, maxY >> SubBits);
    if (u0 > u1 || v0 > v1)
    {
      return;
    }
    this->U0 = static_cast<int>(u0);
    this->U1 = static_cast<int>(u1);
    this->V0 = static_cast<int>(v0);
    this->V1 = static_cast<int>(v1);
    // Edge i runs from vertex i+1 to vertex i+2; strictly inside (> 0) on the edges
    // that are not left or bottom edges.
    for (int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3;
      const int k = (i + 2) % 3;
      const int64_t dx = X[k] - X[j];
      const int64_t dy = Y[k] - Y[j];
      const bool owned = dy < 0 || (dy == 0 && dx > 0);
      this->Edge[i] = dx * (v0 * one - Y[j]) - dy * (u0 * one - X[j]) - (owned ? 0 : 1);
      this->DX[i] = static_cast<int32_t>(dx);
      this->DY[i] = static_cast<int32_t>(dy);
    }
    this->D0 = p[0][a] - f.Origin[a];
    this->D1 = p[1][a] - f.Origin[a];
    this->D2 = p[2][a] - f.Origin[a];
    const double inv = 1.0 / denom;
    this->A1 = (V[2] - V[0]) * inv;
    this->B1 = -(U[2] - U[0]) * inv;
    this->C1 = -(this->A1 * U[0] + this->B1 * V[0]);
    this->A2 = -(V[1] - V[0]) * inv;
    this->B2 = (U[1] - U[0]) * inv;
    this->C2 = -(this->A2 * U[0] + this->B2 * V[0]);
    this->Axis = static_cast<int8_t>(a);
  }

  /**
   * The covered cells of the rows of a set-up triangle, one row after the other,
   * in exact integer arithmetic. Each edge function e + s * k (k = iu - U0) bounds
   * the span on one side, at its root -e / s: from below by ceil(-e / s) =
   * -floor(e / s) when s > 0, from above by floor(e / |s|) when s < 0 (a
   * horizontal edge, s = 0, covers the whole row or none of it). The walker keeps
   * floor(e / |s|) and its remainder and steps them from row to row: a division
   * per edge on the first row, additions after it.
   */
  class RowWalker
  {
  public:
    /// Start at row iv of triangle t.
    RowWalker(const vtkOFBTriangleRaster& t, int64_t iv)
      : Width(t.U1 - t.U0)
      , U0(t.U0)
    {
      for (int i = 0; i < 3; ++i)
      {
        const int64_t stepV = t.StepV(i);
        const int64_t e = t.Edge[i] + stepV * (iv - t.V0);
        const int64_t s = t.StepU(i);
        this->Sign[i] = (s > 0) - (s < 0);
        this->M[i] = s < 0 ? -s : s;
        if (s == 0)
        {
          this->Q[i] = e;
          this->R[i] = 0;
          this->DQ[i] = stepV;
          this->DR[i] = 0;
          this->M[i] = 1;
          continue;
        }
        this->Q[i] = FloorDiv(e, this->M[i]);
        this->R[i] = e - this->Q[i] * this->M[i];
        this->DQ[i] = FloorDiv(stepV, this->M[i]);
        this->DR[i] = stepV - this->DQ[i] * this->M[i];
      }
    }

    /// The covered cells [first, last] of the current row (first > last when none).
    void Span(int64_t& first, int64_t& last) const
    {
      int64_t lo = 0, hi = this->Width;
      for (int i = 0; i < 3; ++i)
      {
        const int64_t q = this->Q[i];
        if (this->Sign[i] > 0)
        {
          lo = std::max(lo, -q);
        }
        else if (this->Sign[i] < 0)
        {
          hi = std::min(hi, q);
        }
        else if (q < 0)
        {
          hi = -1; // outside a horizontal edge
        }
      }
      first = this->U0 + lo;
      last = this->U0 + hi;
    }

    /// Go to the next row.
    void Next()
    {
      for (int i = 0; i < 3; ++i)
      {
        this->Q[i] += this->DQ[i];
        this->R[i] += this->DR[i];
        const bool carry = this->R[i] >= this->M[i];
        this->Q[i] += carry;
        this->R[i] -= carry ? this->M[i] : 0;
      }
    }

  private:
    int64_t Q[3], R[3], M[3], DQ[3], DR[3];
    int Sign[3];
    int64_t Width;
    int64_t U0;

    /// floor(a / m) for m > 0.
    static int64_t FloorDiv(int64_t a, int64_t m)
    {
      const int64_t q = a / m;
      return q - ((a % m != 0) & (a < 0));
    }
  };
};

#endif
