// Pass 2 of the CPU backend of vtkOFBSampler: one band filled (see
// vtkOFBSamplerBands.h).

#include "vtkOFBSamplerBands.h"

#include "vtkOFBSurface.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace vtkofb
{
//------------------------------------------------------------------------------
void BandBuilder::FillBand(const Band& band, const Output& out, BandScratch& s) const
{
  const SpanRecord* spans = this->Spans;
  const vtkIdType nCells = band.Cell1 - band.Cell0;
  const vtkIdType rowLength = this->Frame.Dims[(band.Axis + 1) % 3];
  const bool vectors = out.Vectors != nullptr;
  const bool colors = this->Interpolator.PointColors != nullptr;
  // The other arrays are interpolated after the sort, from fragments kept till then
  // (and the sources of the samples recorded from them).
  const bool keepFragments = !out.Others.empty() || out.SourceTri != nullptr;
  s.Reserve(band.Count, nCells, vectors, colors, keepFragments);
  // slot[c]: the change in the number of samples from cell c - 1 to cell c (+1
  // where a span starts, -1 after it ends), then the first slot of cell c, then
  // (once the fragments are placed) its end.
  vtkTypeUInt32* slot = s.Slot.data();
  std::fill(slot, slot + nCells + 1, 0u);
  unsigned char* touched = s.Touched.data(); // groups of 8 cells with a change
  std::fill(touched, touched + nCells / 8 + 1, 0);
  for (vtkIdType i = band.SpanBegin; i < band.SpanEnd; ++i)
  {
    const SpanRecord& span = spans[i];
    const vtkIdType rowStart = (span.Row - band.Row0) * rowLength;
    ++slot[rowStart + span.Lo];
    --slot[rowStart + span.Hi + 1];
    touched[(rowStart + span.Lo) >> 3] = 1;
    touched[(rowStart + span.Hi + 1) >> 3] = 1;
  }
  // Their prefix sum is the number of samples of each cell, and its prefix sum
  // the first slot; the cell index of each slot is written here. Eight cells with
  // no sample and no change (empty space, most of a grid: `touched` marks the
  // groups of eight with a change) only get their offsets.
  vtkTypeUInt32* offsets = out.Offsets + band.Cell0;
  vtkTypeUInt32* cellOf = out.CellIndex + band.First; // cell of each slot
  const auto first = static_cast<vtkTypeUInt32>(band.First);
  const auto cell0 = static_cast<vtkTypeUInt32>(band.Cell0);
  vtkTypeUInt32 count = 0, start = 0;
  auto cell = [&](vtkIdType c)
  {
    count += slot[c];
    slot[c] = start;
    offsets[c] = first + start;
    for (vtkTypeUInt32 k = 0; k < count; ++k)
    {
      cellOf[start + k] = cell0 + static_cast<vtkTypeUInt32>(c);
    }
    start += count;
  };
  vtkIdType c = 0;
  for (; c + 8 <= nCells; c += 8)
  {
    if ((count | touched[c >> 3]) == 0)
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
      for (int32_t iu = span.Lo; iu <= span.Hi; ++iu)
      {
        order[cell[iu]++] = f++;
      }
    }
    if (s.KeepFragments)
    {
      std::fill(s.Tri.begin() + f0, s.Tri.begin() + f, ts.Tri);
    }
    s.VisitStart.push_back(f0);
    s.VisitTri.push_back(ts.Tri);
    vtkIdType ids[3];
    ts.GetPointIds(ids);
    const bool padded = true; // the scratch has room for 8 more fragments
    this->Interpolator.Interpolate(
      ids, f - f0, s.W1.data() + f0 - w0, s.W2.data() + f0 - w0, s.RunAt(f0), ts.MayCancel, padded);
  }
  SortCells(band.Count, cellOf, s);
  this->WriteSamples(band, out, s);
}

//------------------------------------------------------------------------------
void BandBuilder::SpanSamples(const vtkOFBTriangleRaster& ts,
  const SpanRecord& span,
  float* VTK_OFB_RESTRICT depth,
  float* VTK_OFB_RESTRICT w1,
  float* VTK_OFB_RESTRICT w2)
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
    if (n <= 8)
    {
      for (int k = 0; k < 8; ++k)
      {
        depth[k] = static_cast<float>(dLo + k * dStep);
        w1[k] = f1 + static_cast<float>(k) * s1;
        w2[k] = f2 + static_cast<float>(k) * s2;
      }
      return;
    }
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

//------------------------------------------------------------------------------
void BandBuilder::SortCells(vtkIdType n, const vtkTypeUInt32* cellOf, BandScratch& s)
{
  vtkTypeUInt32* order = s.Order.data();
  const float* depth = s.Depth.data();
  auto before = [&](vtkTypeUInt32 f, vtkTypeUInt32 g)
  { return depth[f] < depth[g] || (depth[f] == depth[g] && s.TriangleOf(f) < s.TriangleOf(g)); };
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

//------------------------------------------------------------------------------
void BandBuilder::WriteSamples(const Band& band, const Output& out, const BandScratch& s) const
{
  const vtkIdType n = band.Count;
  const vtkTypeUInt32* order = s.Order.data();
  const float* depth = s.Depth.data();
  const float* nx = s.Normals[0].data();
  const float* ny = s.Normals[1].data();
  const float* nz = s.Normals[2].data();
  const bool colors = this->Interpolator.PointColors != nullptr;
  const unsigned char* rgba = colors ? s.RGBA.data() : this->Interpolator.DefaultColor;
  const int stride = colors ? 4 : 0;
  float* outDepth = out.Depth + band.First;
  float* outNormals = out.Normals + 3 * band.First;
  unsigned char* outColors = out.Colors + 4 * band.First;
  auto write = [&](vtkIdType k)
  {
    const vtkTypeUInt32 f = order[k];
    outDepth[k] = depth[f];
    outNormals[3 * k] = nx[f];
    outNormals[3 * k + 1] = ny[f];
    outNormals[3 * k + 2] = nz[f];
    std::memcpy(outColors + 4 * k, rgba + stride * f, 4);
  };
  vtkIdType k = 0;
#if defined(__SSE2__)
  // Four samples at a time from the first whose normal is 16-byte aligned: their
  // normals (12 bytes a sample, the largest stream) in three non-temporal stores
  // that bypass the cache, where the band's scratch stays; the depths and colours
  // are stored normally, since they are small enough to gain nothing from
  // bypassing the cache.
  if (reinterpret_cast<uintptr_t>(out.Normals) % 16 == 0)
  {
    for (; k < n && ((band.First + k) & 3) != 0; ++k)
    {
      write(k);
    }
    for (; k + 4 <= n; k += 4)
    {
      const vtkTypeUInt32 f0 = order[k], f1 = order[k + 1], f2 = order[k + 2], f3 = order[k + 3];
      _mm_storeu_ps(outDepth + k, _mm_setr_ps(depth[f0], depth[f1], depth[f2], depth[f3]));
      float* o = outNormals + 3 * k;
      _mm_stream_ps(o, _mm_setr_ps(nx[f0], ny[f0], nz[f0], nx[f1]));
      _mm_stream_ps(o + 4, _mm_setr_ps(ny[f1], nz[f1], nx[f2], ny[f2]));
      _mm_stream_ps(o + 8, _mm_setr_ps(nz[f2], nx[f3], ny[f3], nz[f3]));
      int c[4];
      std::memcpy(c, rgba + stride * f0, 4);
      std::memcpy(c + 1, rgba + stride * f1, 4);
      std::memcpy(c + 2, rgba + stride * f2, 4);
      std::memcpy(c + 3, rgba + stride * f3, 4);
      _mm_storeu_si128(
        reinterpret_cast<__m128i*>(outColors + 4 * k), _mm_setr_epi32(c[0], c[1], c[2], c[3]));
    }
    _mm_sfence(); // the streamed normals visible before the band is done
  }
#endif
  for (; k < n; ++k)
  {
    write(k);
  }
  if (out.Vectors)
  {
    float* outVectors = out.Vectors + 3 * band.First;
    for (vtkIdType k = 0; k < n; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        outVectors[3 * k + c] = s.Vectors[c][order[k]];
      }
    }
  }
  if (out.SourceTri)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkTypeUInt32 f = order[k];
      out.SourceTri[band.First + k] = s.Tri[f];
      out.SourceW1[band.First + k] = s.W1[f];
      out.SourceW2[band.First + k] = s.W2[f];
    }
  }
  for (size_t k = 0; k < out.Others.size(); ++k)
  {
    vtkOFBAttributeInterpolator::InterpolateArray(out.OthersIn[k],
      out.Others[k],
      band.First,
      band.Count,
      this->Surface.Triangles.data(),
      s.Tri.data(),
      s.W1.data(),
      s.W2.data(),
      order,
      out.OthersCells[k]);
  }
}

}
