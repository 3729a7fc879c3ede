// The CPU backend of vtkOFBSampler: the triangles set up and listed by band, the
// spans of their rows (pass 1) and the build; vtkOFBSamplerFill.cxx fills a band
// (pass 2). vtkOFBSamplerBands.h describes the algorithm.

#include "vtkOFBSampler.h"
#include "vtkOFBHugePages.h"
#include "vtkOFBSamplerBands.h"

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

using vtkofb::Band;
using vtkofb::BandBuilder;
using vtkofb::BandRange;
using vtkofb::BandScratch;
using vtkofb::Output;
using vtkofb::SetupChunk;
using vtkofb::SpanRecord;

namespace
{
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
}

namespace vtkofb
{
//------------------------------------------------------------------------------
void BandBuilder::CutBands()
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

//------------------------------------------------------------------------------
bool BandBuilder::SetupTriangles()
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
  // Six times the signed volume the triangles enclose, by chunk (a sum that does
  // not depend on the number of threads): negative when they are wound inwards.
  const vtkIdType nChunks = (nTris + SetupChunk - 1) / SetupChunk;
  std::vector<double> volume(nChunks, 0.0);
  vtkSMPTools::For(0, nChunks, 1,
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        double sum = 0.0;
        for (vtkIdType t = c * SetupChunk; t < std::min(nTris, (c + 1) * SetupChunk); ++t)
        {
          const double* p[3] = { P + 3 * T3[3 * t], P + 3 * T3[3 * t + 1],
            P + 3 * T3[3 * t + 2] };
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
  if (std::accumulate(volume.begin(), volume.end(), 0.0) < 0.0)
  {
    // Wound inwards: the triangles facing along the axis enter a closed surface.
    // Swap the two halves of each band's keys so that they come first.
    std::vector<vtkTypeUInt32> swapped(this->FirstKey[2] + 2 * this->F.Dims[1]);
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
        ts.MayCancel = this->Shading.MayCancel(ids);
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

//------------------------------------------------------------------------------
bool BandBuilder::AllocateSpans()
{
  if (!this->B.Spans.Reserve(this->SpanRows))
  {
    return false;
  }
  this->Spans = this->B.Spans.Get();
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
        spans[end++] = { t, static_cast<int32_t>(iv), static_cast<int32_t>(lo),
          static_cast<int32_t>(hi) };
        total += hi - lo + 1;
      }
    }
  }
  band.SpanEnd = end;
  band.Count = total;
}

}


//------------------------------------------------------------------------------
bool vtkOFBSampler::SampleOnCPU(const vtkOFBSurface& surface, vtkOFB* output)
{
  // Point and triangle ids are kept in 32 bits (vtkOFBTriangleRaster).
  const auto nPoints = static_cast<uint64_t>(surface.Points.size() / 3);
  const auto nTriangles = static_cast<uint64_t>(surface.GetNumberOfTriangles());
  if (nPoints >= UINT32_MAX || nTriangles >= UINT32_MAX)
  {
    vtkErrorMacro("The CPU backend samples surfaces of fewer than 2^32 points and triangles; "
      << "this one has " << nPoints << " points and " << nTriangles << " triangles.");
    return false;
  }
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
