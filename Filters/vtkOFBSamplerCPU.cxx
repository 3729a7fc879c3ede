// The CPU scan conversion of vtkOFBSampler: count, prefix sum, fill, sort, attributes.

#include "vtkOFBSampler.h"

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBSurface.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace
{
/// Sub-cell bits of the fixed-point lattice that decides coverage.
constexpr int SubBits = 8;
constexpr double SubScale = static_cast<double>(1 << SubBits);

/// The frame as the rasterizer needs it.
struct Frame
{
  double Origin[3];
  double InvCell;
  vtkIdType Dims[3];
  vtkIdType CellBase[3];
};

/**
 * One triangle set up for its grid: fixed-point vertices in cell units (cell
 * centres on the integer lattice), counter-clockwise, and the linear functions
 * that give depth and barycentric coordinates at a cell centre.
 */
struct TriangleSetup
{
  int Axis;
  int64_t X[3], Y[3];
  // w1 = A1*U + B1*V + C1, w2 = A2*U + B2*V + C2 (true, unsnapped geometry).
  double A1, B1, C1, A2, B2, C2;
  double D0, D1, D2; // depths of the vertices (world units from the grid plane)

  bool Setup(const double* P, const vtkIdType* tri, const Frame& f)
  {
    const double* p0 = P + 3 * tri[0];
    const double* p1 = P + 3 * tri[1];
    const double* p2 = P + 3 * tri[2];
    double e1[3], e2[3];
    for (int k = 0; k < 3; ++k)
    {
      e1[k] = p1[k] - p0[k];
      e2[k] = p2[k] - p0[k];
    }
    const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    int a = 0;
    if (std::fabs(n[1]) > std::fabs(n[a]))
    {
      a = 1;
    }
    if (std::fabs(n[2]) > std::fabs(n[a]))
    {
      a = 2;
    }
    this->Axis = a;
    const int ua = (a + 1) % 3;
    const int va = (a + 2) % 3;
    const double* p[3] = { p0, p1, p2 };
    double U[3], V[3];
    for (int i = 0; i < 3; ++i)
    {
      U[i] = (p[i][ua] - f.Origin[ua]) * f.InvCell - 0.5;
      V[i] = (p[i][va] - f.Origin[va]) * f.InvCell - 0.5;
      this->X[i] = static_cast<int64_t>(std::llround(U[i] * SubScale));
      this->Y[i] = static_cast<int64_t>(std::llround(V[i] * SubScale));
    }
    const int64_t area =
      (this->X[1] - this->X[0]) * (this->Y[2] - this->Y[0]) -
      (this->Y[1] - this->Y[0]) * (this->X[2] - this->X[0]);
    if (area == 0)
    {
      return false; // covers no cell centre
    }
    const double denom = (U[1] - U[0]) * (V[2] - V[0]) - (V[1] - V[0]) * (U[2] - U[0]);
    if (denom == 0.0)
    {
      return false;
    }
    this->D0 = p0[a] - f.Origin[a];
    this->D1 = p1[a] - f.Origin[a];
    this->D2 = p2[a] - f.Origin[a];
    const double inv = 1.0 / denom;
    this->A1 = (V[2] - V[0]) * inv;
    this->B1 = -(U[2] - U[0]) * inv;
    this->C1 = -(this->A1 * U[0] + this->B1 * V[0]);
    this->A2 = -(V[1] - V[0]) * inv;
    this->B2 = (U[1] - U[0]) * inv;
    this->C2 = -(this->A2 * U[0] + this->B2 * V[0]);
    if (area < 0)
    {
      std::swap(this->X[1], this->X[2]);
      std::swap(this->Y[1], this->Y[2]);
    }
    return true;
  }

  /**
   * Call f(cell, iu, iv) for each cell centre covered. A centre exactly on an edge
   * belongs to the triangle for which that edge is a left or bottom edge: the
   * top-left rule of raster (y-down) coordinates, which is the rule Mesa's OpenGL
   * rasterizer applies, so that the OpenGL backend covers the same centres.
   */
  template <typename F>
  void Rasterize(const Frame& frame, F&& f) const
  {
    const int a = this->Axis;
    const vtkIdType nu = frame.Dims[(a + 1) % 3];
    const vtkIdType nv = frame.Dims[(a + 2) % 3];
    const int64_t one = int64_t(1) << SubBits;
    const int64_t minX = std::min({ this->X[0], this->X[1], this->X[2] });
    const int64_t maxX = std::max({ this->X[0], this->X[1], this->X[2] });
    const int64_t minY = std::min({ this->Y[0], this->Y[1], this->Y[2] });
    const int64_t maxY = std::max({ this->Y[0], this->Y[1], this->Y[2] });
    // Cells whose centre (iu * one, iv * one) lies in the bounding box.
    const int64_t u0 = std::max<int64_t>(0, (minX + one - 1) >> SubBits);
    const int64_t u1 = std::min<int64_t>(nu - 1, maxX >> SubBits);
    const int64_t v0 = std::max<int64_t>(0, (minY + one - 1) >> SubBits);
    const int64_t v1 = std::min<int64_t>(nv - 1, maxY >> SubBits);
    if (u0 > u1 || v0 > v1)
    {
      return;
    }
    // Edge i runs from vertex i+1 to vertex i+2; inside is E >= 0 (strictly > 0
    // on edges that are not left or bottom edges).
    int64_t dx[3], dy[3], row[3];
    for (int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3;
      const int k = (i + 2) % 3;
      dx[i] = this->X[k] - this->X[j];
      dy[i] = this->Y[k] - this->Y[j];
      const bool owned = dy[i] < 0 || (dy[i] == 0 && dx[i] > 0);
      row[i] = dx[i] * (v0 * one - this->Y[j]) - dy[i] * (u0 * one - this->X[j]) -
        (owned ? 0 : 1);
    }
    const vtkIdType base = frame.CellBase[a];
    for (int64_t iv = v0; iv <= v1; ++iv)
    {
      int64_t e0 = row[0], e1 = row[1], e2 = row[2];
      const vtkIdType rowCell = base + iv * nu;
      for (int64_t iu = u0; iu <= u1; ++iu)
      {
        if ((e0 | e1 | e2) >= 0)
        {
          f(rowCell + iu, iu, iv);
        }
        e0 -= dy[0] * one;
        e1 -= dy[1] * one;
        e2 -= dy[2] * one;
      }
      row[0] += dx[0] * one;
      row[1] += dx[1] * one;
      row[2] += dx[2] * one;
    }
  }
};

/// Exclusive prefix sum of counts into offsets (n + 1 entries); returns the total.
uint64_t PrefixSum(const vtkTypeUInt32* counts, vtkTypeUInt32* offsets, vtkIdType n)
{
  const vtkIdType blockSize = 1 << 16;
  const vtkIdType nBlocks = (n + blockSize - 1) / blockSize;
  std::vector<uint64_t> sums(nBlocks + 1, 0);
  vtkSMPTools::For(0, nBlocks, 1,
    [&](vtkIdType b0, vtkIdType b1)
    {
      for (vtkIdType b = b0; b < b1; ++b)
      {
        uint64_t s = 0;
        const vtkIdType end = std::min(n, (b + 1) * blockSize);
        for (vtkIdType i = b * blockSize; i < end; ++i)
        {
          s += counts[i];
        }
        sums[b + 1] = s;
      }
    });
  for (vtkIdType b = 0; b < nBlocks; ++b)
  {
    sums[b + 1] += sums[b];
  }
  const uint64_t total = sums[nBlocks];
  if (total >= UINT32_MAX)
  {
    return total;
  }
  vtkSMPTools::For(0, nBlocks, 1,
    [&](vtkIdType b0, vtkIdType b1)
    {
      for (vtkIdType b = b0; b < b1; ++b)
      {
        auto s = static_cast<vtkTypeUInt32>(sums[b]);
        const vtkIdType end = std::min(n, (b + 1) * blockSize);
        for (vtkIdType i = b * blockSize; i < end; ++i)
        {
          offsets[i] = s;
          s += counts[i];
        }
      }
    });
  offsets[n] = static_cast<vtkTypeUInt32>(total);
  return total;
}

/// Barycentric interpolation of an array-of-structures array into the samples.
template <typename T>
void InterpolateArray(const T* in, T* out, int nc, vtkIdType n, const vtkTypeUInt32* tri,
  const float* w1, const float* w2, const vtkIdType* T3)
{
  vtkSMPTools::For(0, n, 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType* t = T3 + 3 * static_cast<vtkIdType>(tri[i]);
        const double b1 = w1[i], b2 = w2[i], b0 = 1.0 - b1 - b2;
        for (int k = 0; k < nc; ++k)
        {
          const double v = b0 * in[t[0] * nc + k] + b1 * in[t[1] * nc + k] + b2 * in[t[2] * nc + k];
          if (std::is_integral<T>::value)
          {
            out[i * nc + k] = static_cast<T>(std::llround(v));
          }
          else
          {
            out[i * nc + k] = static_cast<T>(v);
          }
        }
      }
    });
}
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::SampleOnCPU(const vtkOFBSurface& surface, vtkOFB* output)
{
  double origin[3], cellSize;
  vtkIdType dims[3];
  if (!this->ComputeFrame(surface, origin, cellSize, dims))
  {
    return false;
  }
  const double limit = 1024.0 * 1024.0 * static_cast<double>(this->MemoryLimit);
  const double estimate = this->EstimateBytes(surface, dims, cellSize);
  if (estimate > limit)
  {
    vtkErrorMacro("Resolution " << this->Resolution << " needs about " << estimate / 1048576.0
                                << " MiB, over the memory limit of " << this->MemoryLimit
                                << " MiB. Lower the resolution or raise MemoryLimit.");
    return false;
  }
  if (!output->SetFrame(origin, cellSize, dims))
  {
    return false;
  }
  Frame frame;
  for (int a = 0; a < 3; ++a)
  {
    frame.Origin[a] = origin[a];
    frame.Dims[a] = dims[a];
    frame.CellBase[a] = output->GetGridCellBase(a);
  }
  frame.InvCell = 1.0 / cellSize;
  const vtkIdType nCells = output->GetNumberOfCells();
  const vtkIdType nTris = surface.GetNumberOfTriangles();
  const double* P = surface.Points.data();
  const vtkIdType* T3 = surface.Triangles.data();

  std::unique_ptr<vtkTypeUInt32[]> counts(new (std::nothrow) vtkTypeUInt32[nCells]);
  if (!counts)
  {
    vtkErrorMacro("Cannot allocate the counters of " << nCells << " cells.");
    return false;
  }
  vtkTypeUInt32* C = counts.get();
  vtkSMPTools::Fill(C, C + nCells, 0u);

  // Pass 1: count the samples of each cell.
  vtkSMPTools::For(0, nTris, 256,
    [&](vtkIdType begin, vtkIdType end)
    {
      TriangleSetup ts;
      for (vtkIdType t = begin; t < end; ++t)
      {
        if (ts.Setup(P, T3 + 3 * t, frame))
        {
          ts.Rasterize(frame, [C](vtkIdType cell, int64_t, int64_t)
            { __atomic_fetch_add(C + cell, 1u, __ATOMIC_RELAXED); });
        }
      }
    });
  this->UpdateProgress(0.3);
  if (this->GetAbortExecute())
  {
    return false;
  }

  vtkTypeUInt32* offsets = output->GetCellOffsets()->GetPointer(0);
  const uint64_t total = PrefixSum(C, offsets, nCells);
  if (total >= UINT32_MAX)
  {
    vtkErrorMacro("The OFB would hold " << total << " samples, more than 2^32. Lower the "
                                        << "resolution.");
    return false;
  }
  const vtkIdType n = static_cast<vtkIdType>(total);
  const double exact = this->EstimateBytes(surface, dims, cellSize, static_cast<double>(n));
  if (exact > limit)
  {
    vtkErrorMacro("Resolution " << this->Resolution << " gives " << n << " samples needing "
                                << exact / 1048576.0 << " MiB, over the memory limit of "
                                << this->MemoryLimit << " MiB.");
    return false;
  }

  if (!output->AllocateSamples(n))
  {
    return false;
  }
  std::unique_ptr<vtkTypeUInt32[]> triOf(new (std::nothrow) vtkTypeUInt32[n > 0 ? n : 1]);
  std::unique_ptr<float[]> w1(new (std::nothrow) float[n > 0 ? n : 1]);
  std::unique_ptr<float[]> w2(new (std::nothrow) float[n > 0 ? n : 1]);
  if (!triOf || !w1 || !w2)
  {
    vtkErrorMacro("Cannot allocate the temporaries of " << n << " samples.");
    return false;
  }
  float* depth = output->GetDepths()->GetPointer(0);
  vtkTypeUInt32* cellOf = output->GetCellIndex()->GetPointer(0);
  vtkTypeUInt32* triP = triOf.get();
  float* w1P = w1.get();
  float* w2P = w2.get();

  // Pass 2: fill depth, cell, triangle and barycentrics; the counters run back to 0.
  vtkSMPTools::For(0, nTris, 256,
    [&](vtkIdType begin, vtkIdType end)
    {
      TriangleSetup ts;
      for (vtkIdType t = begin; t < end; ++t)
      {
        if (!ts.Setup(P, T3 + 3 * t, frame))
        {
          continue;
        }
        ts.Rasterize(frame,
          [&](vtkIdType cell, int64_t iu, int64_t iv)
          {
            const vtkTypeUInt32 slot =
              offsets[cell] + __atomic_sub_fetch(C + cell, 1u, __ATOMIC_RELAXED);
            double b1 = ts.A1 * iu + ts.B1 * iv + ts.C1;
            double b2 = ts.A2 * iu + ts.B2 * iv + ts.C2;
            // The depth of the triangle's plane at the cell centre, even for centres
            // a lattice step outside the triangle (the same point as its neighbour's);
            // the attributes' barycentrics are clamped to the triangle.
            depth[slot] = static_cast<float>(ts.D0 + b1 * (ts.D1 - ts.D0) + b2 * (ts.D2 - ts.D0));
            b1 = std::min(std::max(b1, 0.0), 1.0);
            b2 = std::min(std::max(b2, 0.0), 1.0 - b1);
            cellOf[slot] = static_cast<vtkTypeUInt32>(cell);
            triP[slot] = static_cast<vtkTypeUInt32>(t);
            w1P[slot] = static_cast<float>(b1);
            w2P[slot] = static_cast<float>(b2);
          });
      }
    });
  counts.reset();
  this->UpdateProgress(0.6);
  if (this->GetAbortExecute())
  {
    return false;
  }

  // Pass 3: sort each cell by (depth, triangle): deterministic whatever the threads.
  vtkSMPTools::For(0, nCells, 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const vtkTypeUInt32 b = offsets[c];
        const vtkTypeUInt32 e = offsets[c + 1];
        for (vtkTypeUInt32 i = b + 1; i < e; ++i)
        {
          const float d = depth[i];
          const vtkTypeUInt32 t = triP[i];
          const float x1 = w1P[i], x2 = w2P[i];
          vtkTypeUInt32 j = i;
          while (j > b && (depth[j - 1] > d || (depth[j - 1] == d && triP[j - 1] > t)))
          {
            depth[j] = depth[j - 1];
            triP[j] = triP[j - 1];
            w1P[j] = w1P[j - 1];
            w2P[j] = w2P[j - 1];
            --j;
          }
          depth[j] = d;
          triP[j] = t;
          w1P[j] = x1;
          w2P[j] = x2;
        }
      }
    });
  this->UpdateProgress(0.7);

  // Pass 4: attributes.
  return this->InterpolateAttributes(surface, output, triP, w1P, w2P);
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::InterpolateAttributes(const vtkOFBSurface& surface, vtkOFB* output,
  const vtkTypeUInt32* triP, const float* w1P, const float* w2P)
{
  const vtkIdType n = output->GetNumberOfSamples();
  const double* P = surface.Points.data();
  const vtkIdType* T3 = surface.Triangles.data();
  vtkPointData* sd = output->GetSampleData();
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("Colors");
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(n);
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkSmartPointer<vtkFloatArray> vectors;
  if (surface.Vectors)
  {
    vectors = vtkSmartPointer<vtkFloatArray>::New();
    vectors->SetName(surface.Vectors->GetName());
    vectors->SetNumberOfComponents(3);
    vectors->SetNumberOfTuples(n);
  }
  unsigned char* outC = colors->GetPointer(0);
  float* outN = normals->GetPointer(0);
  float* outV = vectors ? vectors->GetPointer(0) : nullptr;
  const float* inN = surface.Normals.data();
  const float* inV =
    surface.Vectors ? vtkFloatArray::SafeDownCast(surface.Vectors)->GetPointer(0) : nullptr;
  const unsigned char* inC = surface.Colors ? surface.Colors->GetPointer(0) : nullptr;
  const int ncC = surface.Colors ? surface.Colors->GetNumberOfComponents() : 0;
  const unsigned char* defaultColor = surface.DefaultColor;
  const bool project = surface.ProjectVectors;
  vtkSMPTools::For(0, n, 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType* t = T3 + 3 * static_cast<vtkIdType>(triP[i]);
        const float b1 = w1P[i], b2 = w2P[i], b0 = 1.0f - b1 - b2;
        const float* n0 = inN + 3 * t[0];
        const float* n1 = inN + 3 * t[1];
        const float* n2 = inN + 3 * t[2];
        float nrm[3];
        for (int k = 0; k < 3; ++k)
        {
          nrm[k] = b0 * n0[k] + b1 * n1[k] + b2 * n2[k];
        }
        float len2 = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
        if (!(len2 > 1e-12f))
        {
          // Opposing or missing point normals: use the face normal.
          const double* p0 = P + 3 * t[0];
          const double* p1 = P + 3 * t[1];
          const double* p2 = P + 3 * t[2];
          const double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
          const double e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
          nrm[0] = static_cast<float>(e1[1] * e2[2] - e1[2] * e2[1]);
          nrm[1] = static_cast<float>(e1[2] * e2[0] - e1[0] * e2[2]);
          nrm[2] = static_cast<float>(e1[0] * e2[1] - e1[1] * e2[0]);
          len2 = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
        }
        const float inv = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
        for (int k = 0; k < 3; ++k)
        {
          nrm[k] *= inv;
          outN[3 * i + k] = nrm[k];
        }
        if (outV)
        {
          float v[3];
          for (int k = 0; k < 3; ++k)
          {
            v[k] = b0 * inV[3 * t[0] + k] + b1 * inV[3 * t[1] + k] + b2 * inV[3 * t[2] + k];
          }
          if (project)
          {
            const float vn = v[0] * nrm[0] + v[1] * nrm[1] + v[2] * nrm[2];
            for (int k = 0; k < 3; ++k)
            {
              v[k] -= vn * nrm[k];
            }
          }
          for (int k = 0; k < 3; ++k)
          {
            outV[3 * i + k] = v[k];
          }
        }
        if (inC)
        {
          for (int k = 0; k < ncC; ++k)
          {
            const float c = b0 * inC[ncC * t[0] + k] + b1 * inC[ncC * t[1] + k] +
              b2 * inC[ncC * t[2] + k];
            outC[4 * i + k] = static_cast<unsigned char>(std::min(255.0f, c + 0.5f));
          }
          if (ncC == 3)
          {
            outC[4 * i + 3] = 255;
          }
        }
        else
        {
          for (int k = 0; k < 4; ++k)
          {
            outC[4 * i + k] = defaultColor[k];
          }
        }
      }
    });
  sd->SetScalars(colors);
  sd->SetNormals(normals);
  if (vectors)
  {
    sd->SetVectors(vectors);
  }
  this->UpdateProgress(0.85);

  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    vtkDataArray* in = surface.Arrays[k];
    vtkSmartPointer<vtkDataArray> out = vtk::TakeSmartPointer(in->NewInstance());
    out->SetName(in->GetName());
    out->SetNumberOfComponents(in->GetNumberOfComponents());
    out->SetNumberOfTuples(n);
    const int nc = in->GetNumberOfComponents();
    switch (in->GetDataType())
    {
      vtkTemplateMacro(InterpolateArray(static_cast<const VTK_TT*>(in->GetVoidPointer(0)),
        static_cast<VTK_TT*>(out->GetVoidPointer(0)), nc, n, triP, w1P, w2P, T3));
      default:
        continue;
    }
    if (static_cast<int>(k) == surface.TCoordsIndex)
    {
      sd->SetTCoords(out);
    }
    else
    {
      sd->AddArray(out);
    }
  }
  return true;
}
