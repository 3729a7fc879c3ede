// The CPU backend's band builder (vtkOFBSamplerBands.h): the bands cut, the
// triangles set up and listed by band, and pass 1 (the spans of a band's rows);
// vtkOFBSamplerBandsFill.cxx has pass 2.

#include "vtkOFBSamplerBands.h"

#include "vtkOFBSurface.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace vtkofb
{
//------------------------------------------------------------------------------
void BandBuilder::CutBands()
{
  vtkIdType rows = 0;
  for (int a = 0; a < 3; ++a)
  {
    const vtkIdType nu = this->Frame.Dims[(a + 1) % 3];
    const vtkIdType nv = this->Frame.Dims[(a + 2) % 3];
    this->FirstKey[a] = 2 * rows;
    rows += nv;
    this->Shift[a] = 0;
    while ((nu << (this->Shift[a] + 1)) <= BandCells)
    {
      ++this->Shift[a];
    }
    this->FirstBandOfGrid[a] = static_cast<vtkIdType>(this->Bands.size());
    for (vtkIdType r = 0; r < nv; r += vtkIdType(1) << this->Shift[a])
    {
      Band band;
      band.Axis = a;
      band.Row0 = r;
      band.Row1 = std::min(nv, r + (vtkIdType(1) << this->Shift[a]));
      band.Cell0 = this->Frame.CellBase[a] + band.Row0 * nu;
      band.Cell1 = this->Frame.CellBase[a] + band.Row1 * nu;
      band.First = band.Count = band.TriBegin = band.TriEnd = 0;
      band.SpanBegin = band.SpanEnd = 0;
      this->Bands.push_back(band);
    }
  }
}

//------------------------------------------------------------------------------
bool BandBuilder::SetupTriangles()
{
  const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
  if (!this->Buffers.Setups.Reserve(nTris) || !this->Buffers.Ranges.Reserve(nTris) ||
    !this->Buffers.Key.Reserve(nTris) || !this->Buffers.Order.Reserve(nTris))
  {
    return false;
  }
  this->Setups = this->Buffers.Setups.Get();
  this->Ranges = this->Buffers.Ranges.Get();
  if (this->ComputeSetupKeys() < 0.0)
  {
    this->PutInwardKeysFirst();
  }
  this->SortBySetupKey();
  this->SetUpInOrder();
  return true;
}

//------------------------------------------------------------------------------
double BandBuilder::ComputeSetupKeys()
{
  const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
  const double* P = this->Surface.Points.data();
  const vtkIdType* T3 = this->Surface.Triangles.data();
  const vtkOFBRasterFrame& f = this->Frame;
  vtkTypeUInt32* key = this->Buffers.Key.Get();
  // Six times the signed volume the triangles enclose, by chunk (a sum that does
  // not depend on the number of threads): negative when they are wound inwards.
  const vtkIdType nChunks = (nTris + SetupChunk - 1) / SetupChunk;
  std::vector<double> volume(nChunks, 0.0);
  vtkSMPTools::For(0,
    nChunks,
    1,
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        double sum = 0.0;
        for (vtkIdType t = c * SetupChunk; t < std::min(nTris, (c + 1) * SetupChunk); ++t)
        {
          const double* p[3] = { P + 3 * T3[3 * t], P + 3 * T3[3 * t + 1], P + 3 * T3[3 * t + 2] };
          bool front;
          double n[3];
          const int a = vtkOFBTriangleRaster::DominantAxis(p[0], p[1], p[2], front, n);
          sum += p[0][0] * n[0] + p[0][1] * n[1] + p[0][2] * n[2];
          const int va = (a + 2) % 3;
          const double v = std::min({ p[0][va], p[1][va], p[2][va] });
          const double row = std::floor((v - f.Origin[va]) * f.InvCell - 0.5);
          const double last = static_cast<double>(f.Dims[va] - 1);
          const auto r = static_cast<vtkIdType>(std::min(std::max(row, 0.0), last));
          // Band b of rows [Row0, Row1) has keys FirstKey + 2 Row0 + [0, 2 (Row1 - Row0)):
          // first those facing against the axis (entering a surface wound outwards),
          // then the others, each by row.
          const vtkIdType row0 = (r >> this->Shift[a]) << this->Shift[a];
          const vtkIdType rows =
            std::min(f.Dims[va], row0 + (vtkIdType(1) << this->Shift[a])) - row0;
          key[t] = static_cast<vtkTypeUInt32>(this->FirstKey[a] + row0 + r + (front ? 0 : rows));
        }
        volume[c] = sum;
      }
    });
  return std::accumulate(volume.begin(), volume.end(), 0.0);
}

//------------------------------------------------------------------------------
void BandBuilder::PutInwardKeysFirst()
{
  // Wound inwards: the triangles facing along the axis enter a closed surface.
  // Swap the two halves of each band's keys so that they come first.
  const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
  vtkTypeUInt32* key = this->Buffers.Key.Get();
  std::vector<vtkTypeUInt32> swapped(this->FirstKey[2] + 2 * this->Frame.Dims[1]);
  for (const Band& band : this->Bands)
  {
    const vtkIdType k0 = this->FirstKey[band.Axis] + 2 * band.Row0;
    const vtkIdType rows = band.Row1 - band.Row0;
    for (vtkIdType x = 0; x < 2 * rows; ++x)
    {
      swapped[k0 + x] = static_cast<vtkTypeUInt32>(k0 + (x < rows ? x + rows : x - rows));
    }
  }
  for (vtkIdType t = 0; t < nTris; ++t)
  {
    key[t] = swapped[key[t]];
  }
}

//------------------------------------------------------------------------------
void BandBuilder::SortBySetupKey()
{
  const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
  const vtkTypeUInt32* key = this->Buffers.Key.Get();
  vtkTypeUInt32* order = this->Buffers.Order.Get();
  std::vector<vtkIdType> start(this->FirstKey[2] + 2 * this->Frame.Dims[1] + 1, 0);
  for (vtkIdType t = 0; t < nTris; ++t)
  {
    ++start[key[t] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  for (vtkIdType t = 0; t < nTris; ++t)
  {
    order[start[key[t]]++] = static_cast<vtkTypeUInt32>(t);
  }
}

//------------------------------------------------------------------------------
void BandBuilder::SetUpInOrder()
{
  const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
  const double* P = this->Surface.Points.data();
  const vtkIdType* T3 = this->Surface.Triangles.data();
  const vtkOFBRasterFrame& f = this->Frame;
  const vtkTypeUInt32* key = this->Buffers.Key.Get();
  const vtkTypeUInt32* order = this->Buffers.Order.Get();
  vtkOFBTriangleRaster* setups = this->Setups;
  vtkSMPTools::For(0,
    nTris,
    SetupChunk,
    [&](vtkIdType begin, vtkIdType end)
    {
      // The triangles come in setup order, their points from anywhere: fetched
      // ahead, the ids 16 triangles ahead, the points and normals 8 ahead.
      const float* normals = this->Surface.Normals.data();
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (i + 16 < end)
        {
          const vtkIdType t16 = order[i + 16];
          vtkofb::Prefetch(T3 + 3 * t16);
          vtkofb::Prefetch(key + t16);
        }
        if (i + 8 < end)
        {
          const vtkIdType* t8 = T3 + 3 * static_cast<vtkIdType>(order[i + 8]);
          for (int k = 0; k < 3; ++k)
          {
            vtkofb::Prefetch(P + 3 * t8[k]);
            vtkofb::Prefetch(normals + 3 * t8[k]);
          }
        }
        vtkOFBTriangleRaster& ts = setups[i];
        const vtkTypeUInt32 t = order[i];
        ts.Setup(P, T3 + 3 * static_cast<vtkIdType>(t), this->AxisOfKey(key[t]), f);
        ts.Tri = t;
        vtkIdType ids[3];
        ts.GetPointIds(ids);
        ts.MayCancel = this->Interpolator.MayCancel(ids);
        BandRange& range = this->Ranges[i];
        range.FirstBand = 1;
        range.LastBand = 0;
        if (ts.Axis >= 0)
        {
          range.FirstBand = static_cast<vtkTypeUInt32>(
            this->FirstBandOfGrid[ts.Axis] + (ts.V0 >> this->Shift[ts.Axis]));
          range.LastBand = static_cast<vtkTypeUInt32>(
            this->FirstBandOfGrid[ts.Axis] + (ts.V1 >> this->Shift[ts.Axis]));
          range.FirstRow = ts.V0;
          range.LastRow = ts.V1;
        }
      }
    });
}

//------------------------------------------------------------------------------
bool BandBuilder::ListBandTriangles()
{
  const vtkIdType nBands = static_cast<vtkIdType>(this->Bands.size());
  const vtkIdType nTris = this->Surface.GetNumberOfTriangles();
  const vtkIdType nChunks = (nTris + SetupChunk - 1) / SetupChunk;
  // start[c * nBands + b], rows[...]: the triangles and rows of band b in chunk c.
  std::vector<vtkIdType> start(nChunks * nBands, 0), rows(nChunks * nBands, 0);
  auto forChunks = [&](auto&& fn)
  {
    vtkSMPTools::For(0,
      nChunks,
      1,
      [&](vtkIdType c0, vtkIdType c1)
      {
        for (vtkIdType c = c0; c < c1; ++c)
        {
          const vtkIdType end = std::min(nTris, (c + 1) * SetupChunk);
          for (vtkIdType i = c * SetupChunk; i < end; ++i)
          {
            const BandRange& range = this->Ranges[i];
            for (vtkTypeUInt32 b = range.FirstBand; b <= range.LastBand; ++b)
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
      rows[cb] += std::min<vtkIdType>(range.LastRow, this->Bands[b].Row1 - 1) -
        std::max<vtkIdType>(range.FirstRow, this->Bands[b].Row0) + 1;
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
  if (!this->Buffers.BandTris.Reserve(tris))
  {
    return false;
  }
  this->BandTris = this->Buffers.BandTris.Get();
  forChunks([&](vtkIdType cb, const BandRange&, vtkTypeUInt32, vtkTypeUInt32 i)
    { this->BandTris[start[cb]++] = i; });
  this->SpanRows = spans;
  return true;
}

//------------------------------------------------------------------------------
bool BandBuilder::AllocateSpans()
{
  if (!this->Buffers.Spans.Reserve(this->SpanRows))
  {
    return false;
  }
  this->Spans = this->Buffers.Spans.Get();
  return true;
}

//------------------------------------------------------------------------------
void BandBuilder::SpanBand(Band& band) const
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
        spans[end++] = {
          t, static_cast<int32_t>(iv), static_cast<int32_t>(lo), static_cast<int32_t>(hi)
        };
        total += hi - lo + 1;
      }
    }
  }
  band.SpanEnd = end;
  band.Count = total;
}

}
