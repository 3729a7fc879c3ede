// The CPU scan conversion of vtkOFBSampler.
//
// The cells of the three grids are cut into bands of 2^k whole rows; a band is a
// contiguous range of global cells and therefore of samples. The triangles are
// set up (vtkOFBTriangleRaster: grid, fixed-point edges, plane) in the order of
// the band of their lowest vertex, so that a band reads its setups from nearby
// memory, those facing against the grid's axis first (see SortCells), and listed
// in the bands their rows cross. Pass 1 finds, band by band,
// the spans (covered cells) of its triangles' rows and its number of samples.
// After a scan over the band totals, pass 2 takes each band on its own, while its
// data is in cache: the samples of each cell and their prefix sum (the cell
// offsets, written once); the fragments of its triangles, a triangle at a time
// (depth, barycentrics and attributes, vtkOFBSampleShader), each given the next
// slot of its cell; the slots of each cell sorted by (depth, triangle id), the
// order of the OpenGL backend; and the samples written in slot order. A band
// belongs to one thread (no atomics) and is computed the same way whatever the
// number of threads, so the output does not depend on it.

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
#include <numeric>
#include <type_traits>
#include <vector>

namespace
{
/**
 * Cells of a band (rounded to whole rows): 32 rows of 2048 cells, a triangle of a
 * 100K-triangle mesh at resolution 2048 crossing few band borders. Measured: 65536
 * builds the bunny and the horse at 2048 3-4 % faster than 16384 or 32768.
 */
constexpr vtkIdType BandCells = 65536;

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

  /// Reuses the spare arrays of `ofb` (vtkOFB::Recycle) that fit.
  SampleArrays(const vtkOFBSurface& surface, vtkIdType n, vtkOFB* ofb)
  {
    this->Colors = vtkUnsignedCharArray::SafeDownCast(
      NewArray(ofb, "Colors", VTK_UNSIGNED_CHAR, nullptr, 4, n));
    this->Normals = vtkFloatArray::SafeDownCast(NewArray(ofb, "Normals", VTK_FLOAT, nullptr, 3, n));
    if (surface.Vectors)
    {
      this->Vectors = vtkFloatArray::SafeDownCast(
        NewArray(ofb, surface.Vectors->GetName(), VTK_FLOAT, nullptr, 3, n));
    }
    for (const auto& in : surface.Arrays)
    {
      this->Others.push_back(
        NewArray(ofb, in->GetName(), in->GetDataType(), in, in->GetNumberOfComponents(), n));
    }
  }

  /**
   * n tuples of a spare array of `ofb` of this name and type (and of the class of
   * `like` when given), else of a new one.
   */
  static vtkSmartPointer<vtkDataArray> NewArray(
    vtkOFB* ofb, const char* name, int type, vtkDataArray* like, int nc, vtkIdType n)
  {
    vtkSmartPointer<vtkDataArray> array = ofb->TakeSpareArray(name, type, nc, n);
    if (array && (!like || std::strcmp(array->GetClassName(), like->GetClassName()) == 0))
    {
      return array;
    }
    array = vtk::TakeSmartPointer(
      like ? like->NewInstance() : vtkDataArray::CreateDataArray(type));
    array->SetName(name);
    array->SetNumberOfComponents(nc);
    array->SetNumberOfTuples(n);
    vtkofb::AdviseHugePages(array);
    return array;
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
 * made (depth, attributes); the fragment and the cell of each of its slots
 * (samples); the slots of each of its cells; the first fragment and the triangle
 * of each triangle (visit) of the band. The barycentrics and the triangle of each
 * fragment are kept for the whole band only when other point arrays are
 * interpolated from them after the sort (KeepFragments); else the barycentrics
 * are those of the current triangle only, and the band's scratch stays small
 * enough for the cache.
 */
struct BandScratch
{
  std::vector<float> Depth, W1, W2, N[3], V[3], Tmp;
  std::vector<unsigned char> RGBA;
  std::vector<vtkTypeUInt32> Tri, Order, CellOf, Slot, VisitStart, VisitTri;
  bool KeepFragments = false;

  /**
   * Room for n fragments and nCells cells, each array on its own: the scratch is
   * kept from build to build, whose surfaces may differ in vectors and colours.
   */
  void Reserve(vtkIdType n, vtkIdType nCells, bool vectors, bool colors, bool keep)
  {
    this->KeepFragments = keep;
    this->VisitStart.clear();
    this->VisitTri.clear();
    auto grow = [](auto& v, vtkIdType size)
    {
      if (static_cast<vtkIdType>(v.size()) < size)
      {
        v.resize(size);
      }
    };
    grow(this->Slot, nCells + 1);
    for (auto* v :
      { &this->Depth, &this->W1, &this->W2, &this->N[0], &this->N[1], &this->N[2], &this->Tmp })
    {
      grow(*v, n);
    }
    if (keep)
    {
      grow(this->Tri, n);
    }
    grow(this->Order, n);
    grow(this->CellOf, n);
    for (int k = 0; vectors && k < 3; ++k)
    {
      grow(this->V[k], n);
    }
    if (colors)
    {
      grow(this->RGBA, 4 * n);
    }
  }

  /// The triangle of fragment f.
  vtkTypeUInt32 TriangleOf(vtkTypeUInt32 f) const
  {
    if (this->KeepFragments)
    {
      return this->Tri[f];
    }
    const auto it = std::upper_bound(this->VisitStart.begin(), this->VisitStart.end(), f);
    return this->VisitTri[(it - this->VisitStart.begin()) - 1];
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
    run.Scratch = this->Tmp.data(); // only for one call
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
 * An uninitialized array kept from build to build (see vtkOFBSamplerBuffers): a
 * rebuild writes over memory it already has.
 */
template <typename T>
struct Buffer
{
  std::unique_ptr<T[]> Data;
  size_t Capacity = 0;

  /// Room for n items (a new array when much smaller); false if it cannot be allocated.
  bool Reserve(vtkIdType count)
  {
    const size_t n = static_cast<size_t>(std::max<vtkIdType>(count, 1));
    if (n <= this->Capacity && n >= this->Capacity / 4)
    {
      return true;
    }
    this->Data.reset();
    this->Capacity = 0;
    this->Data.reset(new (std::nothrow) T[n]);
    if (!this->Data)
    {
      return false;
    }
    this->Capacity = n;
    vtkofb::AdviseHugePages(this->Data.get(), sizeof(T) * n);
    return true;
  }

  T* Get() const { return this->Data.get(); }
};

/// The bands [B0, B1] and rows [V0, V1] of a set-up triangle (none when B0 > B1).
struct BandRange
{
  vtkTypeUInt32 B0, B1;
  int32_t V0, V1;
};
}

/// The buffers of the CPU backend, kept by the sampler between builds.
class vtkOFBSamplerBuffers
{
public:
  Buffer<vtkOFBTriangleRaster> Setups;
  Buffer<SpanRecord> Spans;
  Buffer<BandRange> Ranges;
  Buffer<vtkTypeUInt32> Key, Order, BandTris;
  vtkSMPThreadLocal<BandScratch> Scratch;
};

namespace
{
/**
 * A CPU build: the bands, the triangles sorted by band and set up, the triangles
 * and spans of each band, and the passes over one band.
 */
class BandBuilder
{
public:
  BandBuilder(
    const vtkOFBSurface& surface, const vtkOFBRasterFrame& frame, vtkOFBSamplerBuffers& buffers)
    : Surface(surface)
    , F(frame)
    , Shading(surface)
    , B(buffers)
  {
  }

  /**
   * Cut each grid into bands of 2^Shift[a] whole rows, at most BandCells cells
   * (one row where a row is longer).
   */
  void CutBands()
  {
    vtkIdType rows = 0;
    for (int a = 0; a < 3; ++a)
    {
      const vtkIdType nu = this->F.Dims[(a + 1) % 3];
      const vtkIdType nv = this->F.Dims[(a + 2) % 3];
      this->FirstKey[a] = 2 * rows;
      rows += nv;
      this->Shift[a] = 0;
      while ((nu << (this->Shift[a] + 1)) <= BandCells)
      {
        ++this->Shift[a];
      }
      this->FirstBand[a] = static_cast<vtkIdType>(this->Bands.size());
      for (vtkIdType r = 0; r < nv; r += vtkIdType(1) << this->Shift[a])
      {
        Band band;
        band.Axis = a;
        band.Row0 = r;
        band.Row1 = std::min(nv, r + (vtkIdType(1) << this->Shift[a]));
        band.Cell0 = this->F.CellBase[a] + band.Row0 * nu;
        band.Cell1 = this->F.CellBase[a] + band.Row1 * nu;
        band.First = band.Count = band.TriBegin = band.TriEnd = 0;
        band.SpanBegin = band.SpanEnd = 0;
        this->Bands.push_back(band);
      }
    }
  }

  /**
   * Set up every triangle (in parallel), in the order of the band of their lowest
   * vertex, so that a band reads its setups from nearby memory, in each band those
   * facing against the grid's axis before the others (see SortCells), then by that
   * lowest row (a counting sort, stable); false if the setups cannot be allocated.
   */
  bool SetupTriangles()
  {
    const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
    if (!this->B.Setups.Reserve(nTris) || !this->B.Ranges.Reserve(nTris) ||
      !this->B.Key.Reserve(nTris) || !this->B.Order.Reserve(nTris))
    {
      return false;
    }
    this->Setups = this->B.Setups.Get();
    this->Ranges = this->B.Ranges.Get();
    const double* P = this->Surface.Points.data();
    const vtkIdType* T3 = this->Surface.Triangles.data();
    const vtkOFBRasterFrame& f = this->F;
    vtkTypeUInt32* key = this->B.Key.Get();
    vtkTypeUInt32* order = this->B.Order.Get();
    vtkSMPTools::For(0, nTris, SetupChunk,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType t = begin; t < end; ++t)
        {
          const double* p[3] = { P + 3 * T3[3 * t], P + 3 * T3[3 * t + 1], P + 3 * T3[3 * t + 2] };
          bool front;
          const int a = vtkOFBTriangleRaster::DominantAxis(p[0], p[1], p[2], front);
          const int va = (a + 2) % 3;
          const double v = std::min({ p[0][va], p[1][va], p[2][va] });
          const double row = std::floor((v - f.Origin[va]) * f.InvCell - 0.5);
          const double last = static_cast<double>(f.Dims[va] - 1);
          const auto r = static_cast<vtkIdType>(std::min(std::max(row, 0.0), last));
          // Band b of rows [Row0, Row1) has keys FirstKey + 2 Row0 + [0, 2 (Row1 - Row0)):
          // first those facing against the axis, then the others, each by row.
          const vtkIdType row0 = (r >> this->Shift[a]) << this->Shift[a];
          const vtkIdType rows = std::min(f.Dims[va], row0 + (vtkIdType(1) << this->Shift[a])) - row0;
          key[t] = static_cast<vtkTypeUInt32>(this->FirstKey[a] + row0 + r + (front ? 0 : rows));
        }
      });
    std::vector<vtkIdType> start(this->FirstKey[2] + 2 * this->F.Dims[1] + 1, 0);
    for (vtkIdType t = 0; t < nTris; ++t)
    {
      ++start[key[t] + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (vtkIdType t = 0; t < nTris; ++t)
    {
      order[start[key[t]]++] = static_cast<vtkTypeUInt32>(t);
    }
    vtkOFBTriangleRaster* setups = this->Setups;
    vtkSMPTools::For(0, nTris, SetupChunk,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          vtkOFBTriangleRaster& ts = setups[i];
          const vtkTypeUInt32 t = order[i];
          ts.Setup(P, T3 + 3 * static_cast<vtkIdType>(t), this->AxisOfKey(key[t]), f);
          ts.Tri = t;
          ts.MayCancel = this->Shading.MayCancel(ts.Ids);
          BandRange& range = this->Ranges[i];
          range.B0 = 1;
          range.B1 = 0;
          if (ts.Axis >= 0)
          {
            range.B0 = static_cast<vtkTypeUInt32>(
              this->FirstBand[ts.Axis] + (ts.V0 >> this->Shift[ts.Axis]));
            range.B1 = static_cast<vtkTypeUInt32>(
              this->FirstBand[ts.Axis] + (ts.V1 >> this->Shift[ts.Axis]));
            range.V0 = ts.V0;
            range.V1 = ts.V1;
          }
        }
      });
    return true;
  }

  /**
   * List the triangles of each band in setup order and count the rows of their
   * spans; false if the lists cannot be allocated. In parallel over chunks of
   * triangles: the triangles and rows of each band in each chunk, their prefix
   * sums in (band, chunk) order, then each chunk's part of the lists.
   */
  bool ListBandTriangles()
  {
    const vtkIdType nBands = static_cast<vtkIdType>(this->Bands.size());
    const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
    const vtkIdType nChunks = (nTris + SetupChunk - 1) / SetupChunk;
    // start[c * nBands + b], rows[...]: the triangles and rows of band b in chunk c.
    std::vector<vtkIdType> start(nChunks * nBands, 0), rows(nChunks * nBands, 0);
    auto forChunks = [&](auto&& fn)
    {
      vtkSMPTools::For(0, nChunks, 1,
        [&](vtkIdType c0, vtkIdType c1)
        {
          for (vtkIdType c = c0; c < c1; ++c)
          {
            const vtkIdType end = std::min(nTris, (c + 1) * SetupChunk);
            for (vtkIdType i = c * SetupChunk; i < end; ++i)
            {
              const BandRange& range = this->Ranges[i];
              for (vtkTypeUInt32 b = range.B0; b <= range.B1; ++b)
              {
                fn(c * nBands + b, range, b, static_cast<vtkTypeUInt32>(i));
              }
            }
          }
        });
    };
    forChunks(
      [&](vtkIdType cb, const BandRange& range, vtkTypeUInt32 b, vtkTypeUInt32)
      {
        ++start[cb];
        rows[cb] += std::min<vtkIdType>(range.V1, this->Bands[b].Row1 - 1) -
          std::max<vtkIdType>(range.V0, this->Bands[b].Row0) + 1;
      });
    vtkIdType tris = 0, spans = 0;
    for (vtkIdType b = 0; b < nBands; ++b)
    {
      this->Bands[b].TriBegin = tris;
      this->Bands[b].SpanBegin = this->Bands[b].SpanEnd = spans;
      for (vtkIdType c = 0; c < nChunks; ++c)
      {
        const vtkIdType cb = c * nBands + b;
        std::swap(tris, start[cb]);
        tris += start[cb];
        spans += rows[cb];
      }
      this->Bands[b].TriEnd = tris;
    }
    if (!this->B.BandTris.Reserve(tris))
    {
      return false;
    }
    this->BandTris = this->B.BandTris.Get();
    forChunks([&](vtkIdType cb, const BandRange&, vtkTypeUInt32, vtkTypeUInt32 i)
      { this->BandTris[start[cb]++] = i; });
    this->SpanRows = spans;
    return true;
  }

  /// Room for the spans of the bands' rows; false if it cannot be allocated.
  bool AllocateSpans()
  {
    if (!this->B.Spans.Reserve(this->SpanRows))
    {
      return false;
    }
    this->Spans = this->B.Spans.Get();
    return true;
  }

  /// Pass 1: the non-empty spans of a band's rows and its number of samples.
  void SpanBand(Band& band) const
  {
    SpanRecord* spans = this->Spans;
    vtkIdType end = band.SpanBegin;
    vtkIdType total = 0;
    for (vtkIdType i = band.TriBegin; i < band.TriEnd; ++i)
    {
      const vtkTypeUInt32 t = this->BandTris[i];
      const vtkOFBTriangleRaster& ts = this->Setups[t];
      const int64_t v0 = std::max<int64_t>(ts.V0, band.Row0);
      const int64_t v1 = std::min<int64_t>(ts.V1, band.Row1 - 1);
      vtkOFBTriangleRaster::RowWalker walker(ts, v0);
      for (int64_t iv = v0; iv <= v1; ++iv, walker.Next())
      {
        int64_t lo, hi;
        walker.Span(lo, hi);
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
   * Pass 2 over a band: the samples of each cell and the cell offsets; its
   * fragments, a triangle at a time (depth, barycentrics, attributes), each given
   * the next slot of its cell; the slots of each cell sorted by (depth, triangle);
   * and the samples written in slot order.
   */
  void FillBand(const Band& band, const Output& out, BandScratch& s) const
  {
    const SpanRecord* spans = this->Spans;
    const vtkIdType nCells = band.Cell1 - band.Cell0;
    const vtkIdType rowLength = this->F.Dims[(band.Axis + 1) % 3];
    s.Reserve(band.Count, nCells, out.Vectors != nullptr, this->Shading.C != nullptr,
      !out.Others.empty());
    // slot[c]: the change in the number of samples from cell c - 1 to cell c (+1
    // where a span starts, -1 after it ends), then the first slot of cell c, then
    // (once the fragments are placed) its end.
    vtkTypeUInt32* slot = s.Slot.data();
    std::fill(slot, slot + nCells + 1, 0u);
    for (vtkIdType i = band.SpanBegin; i < band.SpanEnd; ++i)
    {
      const SpanRecord& span = spans[i];
      vtkTypeUInt32* row = slot + (span.Row - band.Row0) * rowLength;
      ++row[span.Lo];
      --row[span.Hi + 1];
    }
    // Their prefix sum is the number of samples of each cell, and its prefix sum
    // the first slot. Eight cells with no sample and no change (empty space, most
    // of a grid) only get their offsets.
    vtkTypeUInt32* offsets = out.Offsets + band.Cell0;
    const auto first = static_cast<vtkTypeUInt32>(band.First);
    vtkTypeUInt32 count = 0, start = 0;
    auto cell = [&](vtkIdType c)
    {
      count += slot[c];
      slot[c] = start;
      offsets[c] = first + start;
      start += count;
    };
    vtkIdType c = 0;
    for (; c + 8 <= nCells; c += 8)
    {
      vtkTypeUInt32 any = count;
      for (int k = 0; k < 8; ++k)
      {
        any |= slot[c + k];
      }
      if (any == 0)
      {
        std::fill(offsets + c, offsets + c + 8, first + start);
        continue;
      }
      for (int k = 0; k < 8; ++k)
      {
        cell(c + k);
      }
    }
    for (; c < nCells; ++c)
    {
      cell(c);
    }

    vtkTypeUInt32* order = s.Order.data(); // fragment of each slot
    vtkTypeUInt32* cellOf = s.CellOf.data(); // cell of each slot
    vtkTypeUInt32 f = 0;
    for (vtkIdType begin = band.SpanBegin, end = begin; begin < band.SpanEnd; begin = end)
    {
      const vtkOFBTriangleRaster& ts = this->Setups[spans[begin].Tri];
      const vtkTypeUInt32 f0 = f;
      const vtkTypeUInt32 w0 = s.KeepFragments ? 0 : f0; // first fragment in W1, W2
      for (end = begin; end < band.SpanEnd && spans[end].Tri == spans[begin].Tri; ++end)
      {
        const SpanRecord& span = spans[end];
        SpanSamples(ts, span, s.Depth.data() + f, s.W1.data() + f - w0, s.W2.data() + f - w0);
        const vtkIdType rowStart = (span.Row - band.Row0) * rowLength;
        vtkTypeUInt32* cell = slot + rowStart;
        auto c = static_cast<vtkTypeUInt32>(band.Cell0 + rowStart + span.Lo);
        for (int32_t iu = span.Lo; iu <= span.Hi; ++iu)
        {
          const vtkTypeUInt32 k = cell[iu]++;
          order[k] = f++;
          cellOf[k] = c++;
        }
      }
      if (s.KeepFragments)
      {
        std::fill(s.Tri.begin() + f0, s.Tri.begin() + f, ts.Tri);
      }
      s.VisitStart.push_back(f0);
      s.VisitTri.push_back(ts.Tri);
      this->Shading.Shade(ts.Ids, f - f0, s.W1.data() + f0 - w0, s.W2.data() + f0 - w0,
        s.RunAt(f0), ts.MayCancel);
    }
    SortCells(band.Count, s);
    this->WriteSamples(band, out, s);
  }

  const vtkOFBSurface& Surface;
  const vtkOFBRasterFrame F;
  const vtkOFBSampleShader Shading;
  vtkOFBSamplerBuffers& B;
  vtkOFBTriangleRaster* Setups = nullptr;
  BandRange* Ranges = nullptr;
  std::vector<Band> Bands;
  vtkTypeUInt32* BandTris = nullptr;
  SpanRecord* Spans = nullptr;
  vtkIdType SpanRows = 0;

private:
  int Shift[3] = { 0, 0, 0 };
  vtkIdType FirstBand[3] = { 0, 0, 0 };
  vtkIdType FirstKey[3] = { 0, 0, 0 }; // setup order keys of each grid (SetupTriangles)

  /// The grid of a setup order key.
  int AxisOfKey(vtkTypeUInt32 key) const
  {
    return key >= this->FirstKey[2] ? 2 : (key >= this->FirstKey[1] ? 1 : 0);
  }

  /**
   * Depth (the triangle's plane at the cell centre, even for centres a lattice
   * step outside the triangle: the same point as its neighbour's) and barycentrics
   * (clamped to the triangle) of the n samples of a span, to depth[0, n), w1 and
   * w2. The barycentrics are linear along the span: when they are inside the
   * triangle at both ends, they are everywhere and the clamp is skipped (a loop
   * that vectorizes).
   */
  static void SpanSamples(const vtkOFBTriangleRaster& ts, const SpanRecord& span,
    float* VTK_OFB_RESTRICT depth, float* VTK_OFB_RESTRICT w1, float* VTK_OFB_RESTRICT w2)
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
    if (inside)
    {
      // Linear along the span: from its first cell in steps of one cell.
      const double dLo = d0 + b1Lo * d10 + b2Lo * d20;
      const double dStep = a1 * d10 + a2 * d20;
      const auto f1 = static_cast<float>(b1Lo), s1 = static_cast<float>(a1);
      const auto f2 = static_cast<float>(b2Lo), s2 = static_cast<float>(a2);
      for (int k = 0; k < n; ++k)
      {
        depth[k] = static_cast<float>(dLo + k * dStep);
        w1[k] = f1 + static_cast<float>(k) * s1;
        w2[k] = f2 + static_cast<float>(k) * s2;
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
   * Sort the slots of each cell by (depth, triangle), the order of the OpenGL
   * backend: an insertion sort, whose inner loop seldom runs. The fragments of a
   * cell mostly arrive in depth order: the triangles of each band facing against
   * its grid's axis are set up (and so listed) before the others, and on a closed
   * surface the first sample of a cell enters it, the next leaves it.
   */
  static void SortCells(vtkIdType n, BandScratch& s)
  {
    vtkTypeUInt32* order = s.Order.data();
    const vtkTypeUInt32* cellOf = s.CellOf.data();
    const float* depth = s.Depth.data();
    auto before = [&](vtkTypeUInt32 f, vtkTypeUInt32 g) {
      return depth[f] < depth[g] || (depth[f] == depth[g] && s.TriangleOf(f) < s.TriangleOf(g));
    };
    float last = n > 0 ? depth[order[0]] : 0.0f;
    for (vtkIdType k = 1; k < n; ++k)
    {
      const vtkTypeUInt32 f = order[k];
      const float d = depth[f];
      // Out of order only if in the cell of the previous slot and not deeper.
      const bool check = (cellOf[k] == cellOf[k - 1]) & !(last < d);
      last = d;
      if (!check || !before(f, order[k - 1]))
      {
        continue;
      }
      vtkIdType j = k;
      for (; j > 0 && cellOf[j - 1] == cellOf[k] && before(f, order[j - 1]); --j)
      {
        order[j] = order[j - 1];
      }
      order[j] = f;
      last = depth[order[k]];
    }
  }

  /// Write the samples of a band in slot order from their fragments.
  void WriteSamples(const Band& band, const Output& out, const BandScratch& s) const
  {
    const vtkIdType n = band.Count;
    const vtkTypeUInt32* order = s.Order.data();
    const float* depth = s.Depth.data();
    const float* nx = s.N[0].data();
    const float* ny = s.N[1].data();
    const float* nz = s.N[2].data();
    const bool colors = this->Shading.C != nullptr;
    const unsigned char* rgba = colors ? s.RGBA.data() : this->Shading.DefaultColor;
    const int stride = colors ? 4 : 0;
    float* outDepth = out.Depth + band.First;
    float* outNormals = out.Normals + 3 * band.First;
    unsigned char* outColors = out.Colors + 4 * band.First;
    std::copy(s.CellOf.data(), s.CellOf.data() + n, out.CellIndex + band.First);
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkTypeUInt32 f = order[k];
      outDepth[k] = depth[f];
      outNormals[3 * k] = nx[f];
      outNormals[3 * k + 1] = ny[f];
      outNormals[3 * k + 2] = nz[f];
      std::memcpy(outColors + 4 * k, rgba + stride * f, 4);
    }
    if (out.Vectors)
    {
      float* outVectors = out.Vectors + 3 * band.First;
      for (vtkIdType k = 0; k < n; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          outVectors[3 * k + c] = s.V[c][order[k]];
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
  // The samples are counted exactly after the setup and checked against the
  // limit before they are allocated: the first estimate is of the cells only.
  double estimate = 0.0;
  if (!this->SetUpFrame(surface, output, false, &estimate, false))
  {
    return false;
  }
  const double* origin = output->GetOrigin();
  const vtkIdType* dims = output->GetDimensions();
  const double cellSize = output->GetCellSize();
  const double limit = 1024.0 * 1024.0 * static_cast<double>(this->MemoryLimit);
  vtkOFBRasterFrame frame;
  for (int a = 0; a < 3; ++a)
  {
    frame.Origin[a] = origin[a];
    frame.Dims[a] = dims[a];
    frame.CellBase[a] = output->GetGridCellBase(a);
  }
  frame.InvCell = 1.0 / cellSize;

  if (!this->Buffers)
  {
    this->Buffers = new vtkOFBSamplerBuffers;
  }
  BandBuilder builder(surface, frame, *this->Buffers);
  builder.CutBands();
  if (!builder.SetupTriangles())
  {
    vtkErrorMacro(
      "Cannot allocate the setup of " << surface.GetNumberOfTriangles() << " triangles.");
    return false;
  }
  if (!builder.ListBandTriangles())
  {
    vtkErrorMacro("Cannot allocate the band lists of " << surface.GetNumberOfTriangles()
                                                       << " triangles.");
    return false;
  }
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
  SampleArrays arrays(surface, n, output);
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
  vtkSMPThreadLocal<BandScratch>& scratch = this->Buffers->Scratch;
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
  SampleArrays arrays(surface, n, output);
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

//------------------------------------------------------------------------------
void vtkOFBSampler::ReleaseBuffers()
{
  delete this->Buffers;
  this->Buffers = nullptr;
}
