// The CPU scan conversion of vtkOFBSampler.
//
// The cells of the three grids are cut into bands of whole rows; a band is a
// contiguous range of global cells and therefore of samples. Every triangle is set
// up once (vtkOFBTriangleRaster: grid, fixed-point edges, plane), then listed in
// the bands its rows cross. Pass 1 finds, band by band, the spans (covered cells)
// of its triangles' rows and its number of samples. After a scan over the band
// totals, pass 2 takes each band on its own, while its data is in cache: samples
// per cell and their prefix sum (the cell offsets), then the fragments of its
// triangles in increasing id, a triangle at a time (depth, barycentrics and
// attributes, vtkOFBSampleShader), each given the next slot of its cell, and last
// cell by cell the fragments sorted by depth (stably: ties stay in triangle order)
// and written to the samples. A band belongs to one thread (no atomics) and is
// computed the same way whatever the number of threads, so the output does not
// depend on it.

#include "vtkOFBSampler.h"
#include "vtkOFBHugePages.h"

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBSampleShader.h"
#include "vtkOFBSurface.h"
#include "vtkOFBTriangleRaster.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

namespace
{
/// Cells of a band (rounded to whole rows): a few hundred KiB of offsets and samples.
constexpr vtkIdType BandCells = 16384;

/// Triangles per chunk of the setup pass.
constexpr vtkIdType SetupChunk = 4096;

/**
 * A band: rows [Row0, Row1) of grid Axis, that is cells [Cell0, Cell1), and its
 * samples [First, First + Count). Its triangles are BandTris[TriBegin, TriEnd),
 * the non-empty spans of their rows Spans[SpanBegin, SpanEnd).
 */
struct Band
{
  int Axis;
  vtkIdType Row0, Row1;
  vtkIdType Cell0, Cell1;
  vtkIdType First, Count;
  vtkIdType TriBegin, TriEnd;
  vtkIdType SpanBegin, SpanEnd;
};

/// Cells [Lo, Hi] of row Row covered by triangle Tri.
struct SpanRecord
{
  vtkTypeUInt32 Tri;
  int32_t Row, Lo, Hi;
};

/**
 * The sample arrays of a build: colours, normals, the vector field and the other
 * point arrays of the surface, allocated for n samples (uninitialised).
 */
struct SampleArrays
{
  vtkSmartPointer<vtkUnsignedCharArray> Colors;
  vtkSmartPointer<vtkFloatArray> Normals;
  vtkSmartPointer<vtkFloatArray> Vectors;
  std::vector<vtkSmartPointer<vtkDataArray>> Others;

  SampleArrays(const vtkOFBSurface& surface, vtkIdType n)
  {
    this->Colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    this->Colors->SetName("Colors");
    this->Colors->SetNumberOfComponents(4);
    this->Colors->SetNumberOfTuples(n);
    this->Normals = vtkSmartPointer<vtkFloatArray>::New();
    this->Normals->SetName("Normals");
    this->Normals->SetNumberOfComponents(3);
    this->Normals->SetNumberOfTuples(n);
    vtkofb::AdviseHugePages(this->Colors);
    vtkofb::AdviseHugePages(this->Normals);
    if (surface.Vectors)
    {
      this->Vectors = vtkSmartPointer<vtkFloatArray>::New();
      this->Vectors->SetName(surface.Vectors->GetName());
      this->Vectors->SetNumberOfComponents(3);
      this->Vectors->SetNumberOfTuples(n);
      vtkofb::AdviseHugePages(this->Vectors);
    }
    for (const auto& in : surface.Arrays)
    {
      vtkSmartPointer<vtkDataArray> out = vtk::TakeSmartPointer(in->NewInstance());
      out->SetName(in->GetName());
      out->SetNumberOfComponents(in->GetNumberOfComponents());
      out->SetNumberOfTuples(n);
      vtkofb::AdviseHugePages(out);
      this->Others.push_back(out);
    }
  }

  /// Hand the arrays to the sample data (only those that were interpolated).
  void Attach(const vtkOFBSurface& surface, vtkPointData* sd, const std::vector<bool>& done)
  {
    sd->SetScalars(this->Colors);
    sd->SetNormals(this->Normals);
    if (this->Vectors)
    {
      sd->SetVectors(this->Vectors);
    }
    for (size_t k = 0; k < this->Others.size(); ++k)
    {
      if (!done[k])
      {
        continue;
      }
      if (static_cast<int>(k) == surface.TCoordsIndex)
      {
        sd->SetTCoords(this->Others[k]);
      }
      else
      {
        sd->AddArray(this->Others[k]);
      }
    }
  }
};

/**
 * Per-thread scratch of pass 2: the fragments of a band in the order they are
 * made (depth, barycentrics, triangle, attributes), and the fragment of each of
 * its samples.
 */
struct BandScratch
{
  std::vector<float> Depth, W1, W2, N[3], V[3], Tmp;
  std::vector<unsigned char> RGBA;
  std::vector<vtkTypeUInt32> Tri, Order;

  void Reserve(vtkIdType n, bool vectors, bool colors)
  {
    if (static_cast<vtkIdType>(this->Depth.size()) >= n)
    {
      return;
    }
    for (auto* v :
      { &this->Depth, &this->W1, &this->W2, &this->N[0], &this->N[1], &this->N[2], &this->Tmp })
    {
      v->resize(n);
    }
    this->Tri.resize(n);
    this->Order.resize(n);
    for (int k = 0; vectors && k < 3; ++k)
    {
      this->V[k].resize(n);
    }
    this->RGBA.resize(colors ? 4 * n : 0);
  }

  /// Where Shader::Shade writes the attributes of fragments [f, ...).
  vtkOFBSampleShader::Run RunAt(vtkIdType f)
  {
    vtkOFBSampleShader::Run run;
    for (int k = 0; k < 3; ++k)
    {
      run.N[k] = this->N[k].data() + f;
      run.V[k] = this->V[k].empty() ? nullptr : this->V[k].data() + f;
    }
    run.RGBA = this->RGBA.empty() ? nullptr : this->RGBA.data() + 4 * f;
    run.Scratch = this->Tmp.data() + f;
    return run;
  }
};

/// Where pass 2 writes.
struct Output
{
  vtkTypeUInt32* Offsets;
  float* Depth;
  vtkTypeUInt32* CellIndex;
  unsigned char* Colors;
  float* Normals;
  float* Vectors;
  std::vector<vtkDataArray*> Others; // the other arrays that are interpolated
  std::vector<vtkDataArray*> OthersIn;
};

/**
 * A CPU build: the triangles set up, the bands with their triangles and spans,
 * and the passes over one band.
 */
class BandBuilder
{
public:
  BandBuilder(const vtkOFBSurface& surface, const vtkOFBRasterFrame& frame)
    : Surface(surface)
    , F(frame)
    , Shading(surface)
  {
  }

  /// Set up every triangle (in parallel); false if the setups cannot be allocated.
  bool SetupTriangles()
  {
    const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
    this->Setups.reset(new (std::nothrow) vtkOFBTriangleRaster[nTris]);
    if (!this->Setups)
    {
      return false;
    }
    vtkofb::AdviseHugePages(this->Setups.get(), sizeof(vtkOFBTriangleRaster) * nTris);
    const double* P = this->Surface.Points.data();
    const vtkIdType* T3 = this->Surface.Triangles.data();
    vtkOFBTriangleRaster* setups = this->Setups.get();
    const vtkOFBRasterFrame& f = this->F;
    vtkSMPTools::For(0, nTris, SetupChunk,
      [=, &f](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType t = begin; t < end; ++t)
        {
          setups[t].Setup(P, T3 + 3 * t, f);
        }
      });
    return true;
  }

  /**
   * Cut the grids into bands of whole rows, list the triangles of each band in
   * increasing id and count the rows of their spans (SpanRows).
   */
  void MakeBands()
  {
    vtkIdType firstBand[3], rowsPerBand[3];
    for (int a = 0; a < 3; ++a)
    {
      const vtkIdType nu = this->F.Dims[(a + 1) % 3];
      const vtkIdType nv = this->F.Dims[(a + 2) % 3];
      rowsPerBand[a] = std::max<vtkIdType>(1, std::min(nv, BandCells / nu));
      firstBand[a] = static_cast<vtkIdType>(this->Bands.size());
      for (vtkIdType r = 0; r < nv; r += rowsPerBand[a])
      {
        Band band;
        band.Axis = a;
        band.Row0 = r;
        band.Row1 = std::min(nv, r + rowsPerBand[a]);
        band.Cell0 = this->F.CellBase[a] + band.Row0 * nu;
        band.Cell1 = this->F.CellBase[a] + band.Row1 * nu;
        band.First = band.Count = band.TriBegin = band.TriEnd = 0;
        band.SpanBegin = band.SpanEnd = 0;
        this->Bands.push_back(band);
      }
    }
    // Counting sort of the (triangle, band) pairs by band; rows of each band.
    const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
    const vtkOFBTriangleRaster* setups = this->Setups.get();
    const size_t nBands = this->Bands.size();
    std::vector<vtkIdType> start(nBands + 1, 0), rows(nBands + 1, 0);
    for (int pass = 0; pass < 2; ++pass)
    {
      for (vtkIdType t = 0; t < nTris; ++t)
      {
        const vtkOFBTriangleRaster& ts = setups[t];
        if (ts.Axis < 0)
        {
          continue;
        }
        const vtkIdType b0 = firstBand[ts.Axis] + ts.V0 / rowsPerBand[ts.Axis];
        const vtkIdType b1 = firstBand[ts.Axis] + ts.V1 / rowsPerBand[ts.Axis];
        for (vtkIdType b = b0; b <= b1; ++b)
        {
          if (pass == 0)
          {
            ++start[b + 1];
            rows[b + 1] += std::min<vtkIdType>(ts.V1, this->Bands[b].Row1 - 1) -
              std::max<vtkIdType>(ts.V0, this->Bands[b].Row0) + 1;
          }
          else
          {
            this->BandTris[start[b]++] = static_cast<vtkTypeUInt32>(t);
          }
        }
      }
      if (pass == 0)
      {
        for (size_t b = 0; b < nBands; ++b)
        {
          start[b + 1] += start[b];
          rows[b + 1] += rows[b];
          this->Bands[b].TriBegin = start[b];
          this->Bands[b].TriEnd = start[b + 1];
          this->Bands[b].SpanBegin = this->Bands[b].SpanEnd = rows[b];
        }
        this->BandTris.resize(start.back());
      }
    }
    this->SpanRows = rows.back();
  }

  /// Room for the spans of the bands' rows; false if it cannot be allocated.
  bool AllocateSpans()
  {
    this->Spans.reset(new (std::nothrow) SpanRecord[std::max<vtkIdType>(1, this->SpanRows)]);
    if (!this->Spans)
    {
      return false;
    }
    vtkofb::AdviseHugePages(this->Spans.get(), sizeof(SpanRecord) * this->SpanRows);
    return true;
  }

  /// Pass 1: the non-empty spans of a band's rows and its number of samples.
  void SpanBand(Band& band) const
  {
    SpanRecord* spans = this->Spans.get();
    vtkIdType end = band.SpanBegin;
    vtkIdType total = 0;
    for (vtkIdType i = band.TriBegin; i < band.TriEnd; ++i)
    {
      const vtkTypeUInt32 t = this->BandTris[i];
      const vtkOFBTriangleRaster& ts = this->Setups[t];
      const int64_t v0 = std::max<int64_t>(ts.V0, band.Row0);
      const int64_t v1 = std::min<int64_t>(ts.V1, band.Row1 - 1);
      for (int64_t iv = v0; iv <= v1; ++iv)
      {
        int64_t lo, hi;
        ts.Span(iv, lo, hi);
        if (lo <= hi)
        {
          spans[end++] = { t, static_cast<int32_t>(iv), static_cast<int32_t>(lo),
            static_cast<int32_t>(hi) };
          total += hi - lo + 1;
        }
      }
    }
    band.SpanEnd = end;
    band.Count = total;
  }

  /**
   * Pass 2 over a band: its offsets; its fragments, a triangle at a time (depth,
   * barycentrics, attributes), each given the next slot of its cell; then cell by
   * cell, the fragments sorted by depth (stable: equal depths stay in triangle
   * order) and written to the samples.
   */
  void FillBand(const Band& band, const Output& out, BandScratch& s) const
  {
    // offsets[c + 1] (zero from SetFrame): the number of samples of cell c, then
    // the start of cell c, then (once the fragments are placed) its end.
    const SpanRecord* spans = this->Spans.get();
    vtkTypeUInt32* cursor = out.Offsets + 1;
    const vtkIdType rowLength = this->F.Dims[(band.Axis + 1) % 3];
    const vtkIdType base = this->F.CellBase[band.Axis];
    for (vtkIdType i = band.SpanBegin; i < band.SpanEnd; ++i)
    {
      const SpanRecord& span = spans[i];
      vtkTypeUInt32* row = cursor + base + span.Row * rowLength;
      for (int32_t iu = span.Lo; iu <= span.Hi; ++iu)
      {
        ++row[iu];
      }
    }
    auto start = static_cast<vtkTypeUInt32>(band.First);
    for (vtkIdType c = band.Cell0; c < band.Cell1; ++c)
    {
      const vtkTypeUInt32 count = cursor[c];
      cursor[c] = start;
      start += count;
    }

    s.Reserve(band.Count, out.Vectors != nullptr, this->Shading.C != nullptr);
    vtkTypeUInt32* order = s.Order.data(); // fragment of each sample of the band
    vtkTypeUInt32 f = 0;
    for (vtkIdType first = band.SpanBegin, end = first; first < band.SpanEnd; first = end)
    {
      const vtkTypeUInt32 t = spans[first].Tri;
      const vtkOFBTriangleRaster& ts = this->Setups[t];
      const vtkTypeUInt32 f0 = f;
      for (end = first; end < band.SpanEnd && spans[end].Tri == t; ++end)
      {
        const SpanRecord& span = spans[end];
        SpanSamples(ts, span, f, s);
        vtkTypeUInt32* cell = cursor + base + span.Row * rowLength;
        for (int32_t iu = span.Lo; iu <= span.Hi; ++iu)
        {
          order[cell[iu]++ - band.First] = f++;
        }
      }
      std::fill(s.Tri.begin() + f0, s.Tri.begin() + f, t);
      this->Shading.Shade(t, f - f0, s.W1.data() + f0, s.W2.data() + f0, s.RunAt(f0));
    }
    this->WriteSamples(band, out, s);
  }

  const vtkOFBSurface& Surface;
  const vtkOFBRasterFrame F;
  const vtkOFBSampleShader Shading;
  std::unique_ptr<vtkOFBTriangleRaster[]> Setups;
  std::vector<Band> Bands;
  std::vector<vtkTypeUInt32> BandTris;
  std::unique_ptr<SpanRecord[]> Spans;
  vtkIdType SpanRows = 0;

private:
  /**
   * Depth (the triangle's plane at the cell centre, even for centres a lattice
   * step outside the triangle: the same point as its neighbour's) and barycentrics
   * (clamped to the triangle) of the samples of a span, from index `at` of the
   * scratch. The barycentrics are linear along the span: when they are inside the
   * triangle at both ends, they are everywhere and the clamp is skipped (a loop
   * that vectorizes).
   */
  static void SpanSamples(
    const vtkOFBTriangleRaster& ts, const SpanRecord& span, int at, BandScratch& s)
  {
    // w = A * iu + B * iv + C, evaluated in this order for every sample.
    const double a1 = ts.A1, a2 = ts.A2, c1 = ts.C1, c2 = ts.C2;
    const double row1 = ts.B1 * span.Row;
    const double row2 = ts.B2 * span.Row;
    const double d0 = ts.D0, d10 = ts.D1 - ts.D0, d20 = ts.D2 - ts.D0;
    const int n = span.Hi - span.Lo + 1;
    const double lo = span.Lo, hi = span.Hi;
    const double b1Lo = a1 * lo + row1 + c1, b1Hi = a1 * hi + row1 + c1;
    const double b2Lo = a2 * lo + row2 + c2, b2Hi = a2 * hi + row2 + c2;
    const double margin = 1e-9;
    const bool inside = std::min(b1Lo, b1Hi) > margin && std::min(b2Lo, b2Hi) > margin &&
      std::min(1.0 - b1Lo - b2Lo, 1.0 - b1Hi - b2Hi) > margin;
    float* depth = s.Depth.data() + at;
    float* w1 = s.W1.data() + at;
    float* w2 = s.W2.data() + at;
    if (inside)
    {
      for (int k = 0; k < n; ++k)
      {
        const double iu = span.Lo + k;
        const double b1 = a1 * iu + row1 + c1;
        const double b2 = a2 * iu + row2 + c2;
        depth[k] = static_cast<float>(d0 + b1 * d10 + b2 * d20);
        w1[k] = static_cast<float>(b1);
        w2[k] = static_cast<float>(b2);
      }
      return;
    }
    for (int k = 0; k < n; ++k)
    {
      const double iu = span.Lo + k;
      double b1 = a1 * iu + row1 + c1;
      double b2 = a2 * iu + row2 + c2;
      depth[k] = static_cast<float>(d0 + b1 * d10 + b2 * d20);
      b1 = std::min(std::max(b1, 0.0), 1.0);
      b2 = std::min(std::max(b2, 0.0), 1.0 - b1);
      w1[k] = static_cast<float>(b1);
      w2[k] = static_cast<float>(b2);
    }
  }

  /**
   * Cell by cell, sort the band's fragments by depth (insertion sort of the
   * fragment order; stable) and write them to the samples of the cell.
   */
  void WriteSamples(const Band& band, const Output& out, BandScratch& s) const
  {
    const vtkTypeUInt32* cursor = out.Offsets + 1; // end of each cell
    vtkTypeUInt32* order = s.Order.data(); // fragment of each sample of the band
    const float* depth = s.Depth.data();
    const float* nx = s.N[0].data();
    const float* ny = s.N[1].data();
    const float* nz = s.N[2].data();
    const bool colors = this->Shading.C != nullptr;
    const unsigned char* rgba = colors ? s.RGBA.data() : this->Shading.DefaultColor;
    const int stride = colors ? 4 : 0;
    float* outDepth = out.Depth;
    vtkTypeUInt32* outCell = out.CellIndex;
    float* outNormals = out.Normals;
    unsigned char* outColors = out.Colors;
    const vtkIdType first = band.First;
    vtkIdType b = first;
    for (vtkIdType c = band.Cell0; c < band.Cell1; ++c)
    {
      const vtkIdType e = cursor[c];
      if (e == b)
      {
        continue; // most cells are empty
      }
      if (e - b == 2)
      {
        // The most common case after one sample (a ray through a closed surface),
        // without a branch on the unpredictable order.
        const vtkTypeUInt32 f0 = order[b - first], f1 = order[b + 1 - first];
        const bool swap = depth[f0] > depth[f1];
        order[b - first] = swap ? f1 : f0;
        order[b + 1 - first] = swap ? f0 : f1;
      }
      for (vtkIdType i = b + 1 - first; e - b > 2 && i < e - first; ++i)
      {
        const vtkTypeUInt32 f = order[i];
        vtkIdType j = i;
        for (; j > b - first && depth[order[j - 1]] > depth[f]; --j)
        {
          order[j] = order[j - 1];
        }
        order[j] = f;
      }
      for (vtkIdType i = b; i < e; ++i)
      {
        const vtkIdType f = order[i - first];
        outDepth[i] = depth[f];
        outCell[i] = static_cast<vtkTypeUInt32>(c);
        float* normal = outNormals + 3 * i;
        normal[0] = nx[f];
        normal[1] = ny[f];
        normal[2] = nz[f];
        std::memcpy(outColors + 4 * i, rgba + stride * f, 4);
      }
      b = e;
    }
    if (out.Vectors)
    {
      float* outVectors = out.Vectors + 3 * band.First;
      for (vtkIdType i = 0; i < band.Count; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          outVectors[3 * i + k] = s.V[k][order[i]];
        }
      }
    }
    for (size_t k = 0; k < out.Others.size(); ++k)
    {
      vtkOFBSampleShader::InterpolateArray(out.OthersIn[k], out.Others[k], band.First, band.Count,
        this->Surface.Triangles.data(), s.Tri.data(), s.W1.data(), s.W2.data(), order);
    }
  }
};
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::SampleOnCPU(const vtkOFBSurface& surface, vtkOFB* output)
{
  if (!this->SetUpFrame(surface, output))
  {
    return false;
  }
  const double* origin = output->GetOrigin();
  const vtkIdType* dims = output->GetDimensions();
  const double cellSize = output->GetCellSize();
  const double limit = 1024.0 * 1024.0 * static_cast<double>(this->MemoryLimit);
  const double estimate = this->EstimateBytes(surface, dims, cellSize);
  vtkOFBRasterFrame frame;
  for (int a = 0; a < 3; ++a)
  {
    frame.Origin[a] = origin[a];
    frame.Dims[a] = dims[a];
    frame.CellBase[a] = output->GetGridCellBase(a);
  }
  frame.InvCell = 1.0 / cellSize;

  BandBuilder builder(surface, frame);
  if (!builder.SetupTriangles())
  {
    vtkErrorMacro(
      "Cannot allocate the setup of " << surface.GetNumberOfTriangles() << " triangles.");
    return false;
  }
  builder.MakeBands();
  // The spans (one record per row of a triangle) are a temporary the estimate
  // does not count: check them too before allocating them.
  const double spanBytes = static_cast<double>(builder.SpanRows) * sizeof(SpanRecord);
  if (estimate + spanBytes > limit)
  {
    vtkErrorMacro("Resolution " << this->Resolution << " needs about "
                                << (estimate + spanBytes) / 1048576.0
                                << " MiB, over the memory limit of " << this->MemoryLimit
                                << " MiB. Lower the resolution or raise MemoryLimit.");
    return false;
  }
  if (!builder.AllocateSpans())
  {
    vtkErrorMacro("Cannot allocate the spans of " << builder.SpanRows << " rows.");
    return false;
  }
  std::vector<Band>& bands = builder.Bands;
  const vtkIdType nBands = static_cast<vtkIdType>(bands.size());

  // Pass 1: the spans and samples of each band.
  vtkSMPTools::For(0, nBands, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        builder.SpanBand(bands[b]);
      }
    });
  this->UpdateProgress(0.3);
  if (this->GetAbortExecute())
  {
    return false;
  }
  uint64_t total = 0;
  for (Band& band : bands)
  {
    band.First = static_cast<vtkIdType>(total);
    total += static_cast<uint64_t>(band.Count);
  }
  if (total >= UINT32_MAX)
  {
    vtkErrorMacro("The OFB would hold " << total << " samples, more than 2^32. Lower the "
                                        << "resolution.");
    return false;
  }
  const vtkIdType n = static_cast<vtkIdType>(total);
  const double exact =
    this->EstimateBytes(surface, dims, cellSize, static_cast<double>(n)) + spanBytes;
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
  SampleArrays arrays(surface, n);
  Output out;
  vtkTypeUInt32* offsets = output->GetCellOffsets()->GetPointer(0);
  out.Offsets = offsets;
  out.Depth = output->GetDepths()->GetPointer(0);
  out.CellIndex = output->GetCellIndex()->GetPointer(0);
  out.Colors = arrays.Colors->GetPointer(0);
  out.Normals = arrays.Normals->GetPointer(0);
  out.Vectors = arrays.Vectors ? arrays.Vectors->GetPointer(0) : nullptr;
  std::vector<bool> interpolable;
  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    interpolable.push_back(vtkOFBSampleShader::IsInterpolable(surface.Arrays[k]));
    if (interpolable.back())
    {
      out.OthersIn.push_back(surface.Arrays[k]);
      out.Others.push_back(arrays.Others[k]);
    }
  }

  // Pass 2: each band on its own.
  vtkSMPThreadLocal<BandScratch> scratch;
  vtkSMPTools::For(0, nBands, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      BandScratch& local = scratch.Local();
      for (vtkIdType b = begin; b < end; ++b)
      {
        builder.FillBand(bands[b], out, local);
      }
    });
  offsets[output->GetNumberOfCells()] = static_cast<vtkTypeUInt32>(n);
  arrays.Attach(surface, output->GetSampleData(), interpolable);
  this->UpdateProgress(0.85);
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::InterpolateAttributes(const vtkOFBSurface& surface, vtkOFB* output,
  const vtkTypeUInt32* triP, const float* w1P, const float* w2P)
{
  const vtkIdType n = output->GetNumberOfSamples();
  SampleArrays arrays(surface, n);
  unsigned char* outC = arrays.Colors->GetPointer(0);
  float* outN = arrays.Normals->GetPointer(0);
  float* outV = arrays.Vectors ? arrays.Vectors->GetPointer(0) : nullptr;
  const vtkOFBSampleShader shader(surface);
  vtkSMPTools::For(0, n, 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      float nrm[3], vec[3], tmp;
      vtkOFBSampleShader::Run run;
      for (int k = 0; k < 3; ++k)
      {
        run.N[k] = nrm + k;
        run.V[k] = vec + k;
      }
      run.Scratch = &tmp;
      for (vtkIdType i = begin; i < end; ++i)
      {
        run.RGBA = outC + 4 * i;
        shader.Shade(triP[i], 1, w1P + i, w2P + i, run);
        if (!shader.C)
        {
          std::memcpy(run.RGBA, shader.DefaultColor, 4);
        }
        std::copy(nrm, nrm + 3, outN + 3 * i);
        if (outV)
        {
          std::copy(vec, vec + 3, outV + 3 * i);
        }
      }
    });
  this->UpdateProgress(0.85);
  std::vector<bool> interpolable;
  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    vtkDataArray* in = surface.Arrays[k];
    vtkDataArray* outArray = arrays.Others[k];
    interpolable.push_back(vtkOFBSampleShader::IsInterpolable(in));
    if (interpolable.back())
    {
      vtkSMPTools::For(0, n, 4096,
        [&](vtkIdType begin, vtkIdType end)
        {
          vtkOFBSampleShader::InterpolateArray(in, outArray, begin, end - begin,
            surface.Triangles.data(), triP + begin, w1P + begin, w2P + begin, nullptr);
        });
    }
  }
  arrays.Attach(surface, output->GetSampleData(), interpolable);
  return true;
}
