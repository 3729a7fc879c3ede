/**
 * @file    vtkOFBSamplerBands.h
 * @brief   The band builder of the CPU backend of vtkOFBSampler (private)
 *
 * The cells of the three grids are cut into bands of 2^k whole rows; a band is a
 * contiguous range of global cells and therefore of samples. The triangles are
 * set up (vtkOFBTriangleRaster: grid, fixed-point edges, plane) in the order of
 * the band of their lowest vertex, so that a band reads its setups from nearby
 * memory, those entering the surface first (see SortCells), and listed
 * in the bands their rows cross. Pass 1 finds, band by band, the spans (covered
 * cells) of its triangles' rows and its number of samples. After a scan over the
 * band totals, pass 2 takes each band on its own, while its data is in cache: the
 * samples of each cell and their prefix sum (the cell offsets, written once); the
 * fragments of its triangles, a triangle at a time (depth, barycentrics and
 * attributes, vtkOFBAttributeInterpolator), each given the next slot of its cell; the slots
 * of each cell sorted by (depth, triangle id), the order of the OpenGL backend;
 * and the samples written in slot order. A band belongs to one thread (no
 * atomics) and is computed the same way whatever the number of threads, so the
 * output does not depend on it.
 *
 * vtkOFBSamplerBands.cxx sets up the triangles, lists them by band, finds their
 * spans (pass 1); vtkOFBSamplerBandsFill.cxx fills a band (pass 2); vtkOFBCPUSampler runs
 * the build.
 */

#ifndef vtkOFBSamplerBands_h
#define vtkOFBSamplerBands_h

#include "vtkOFBAttributeInterpolator.h"
#include "vtkOFBHugePages.h"
#include "vtkOFBTriangleRaster.h"
#include "vtkSMPThreadLocal.h"
#include "vtkType.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

class vtkOFBSurface;

namespace vtkofb
{
/**
 * Cells of a band (rounded to whole rows): 32 rows of 2048 cells, small enough
 * for the band's scratch to stay in cache, large enough that a triangle of a
 * 100K-triangle mesh at resolution 2048 crosses few band borders.
 */
constexpr vtkIdType BandCells = 65536;

/// Ask for the cache line of p ahead of its use (a hint; nothing where unsupported).
inline void Prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

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
 * Per-thread scratch of pass 2: the fragments of a band in the order they are
 * made (depth, attributes); the fragment of each of its slots (samples; their
 * cells are written straight to the output's cell indices); the slots of each of
 * its cells, and which groups of 8 cells the spans change (Touched); the first
 * fragment and the triangle of each triangle (visit) of the band. The
 * barycentrics and the triangle of each fragment are kept for the whole band only
 * when other point arrays are interpolated from them after the sort
 * (KeepFragments); else the barycentrics are those of the current triangle only,
 * and the band's scratch stays small enough for the cache.
 */
struct BandScratch
{
  std::vector<float> Depth, W1, W2, Normals[3], Vectors[3], Tmp;
  std::vector<unsigned char> RGBA, Touched;
  std::vector<vtkTypeUInt32> Tri, Order, Slot, VisitStart, VisitTri;
  bool KeepFragments = false;

  /**
   * Start a band: room for n fragments (8 more for SpanSamples) and nCells cells,
   * each array on its own (the scratch is kept from build to build, whose surfaces
   * may differ in vectors and colours), an empty list of the band's triangles, and
   * whether the fragments' barycentrics and triangles are kept for the whole band.
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
    grow(this->Touched, nCells / 8 + 1);
    for (auto* v : { &this->Depth,
           &this->W1,
           &this->W2,
           &this->Normals[0],
           &this->Normals[1],
           &this->Normals[2],
           &this->Tmp })
    {
      grow(*v, n + 8);
    }
    if (keep)
    {
      grow(this->Tri, n);
    }
    grow(this->Order, n);
    for (int k = 0; vectors && k < 3; ++k)
    {
      grow(this->Vectors[k], n);
    }
    if (colors)
    {
      grow(this->RGBA, 4 * n);
    }
  }

  /// The triangle of fragment f (from the list of the band's triangles).
  vtkTypeUInt32 TriangleOf(vtkTypeUInt32 f) const
  {
    const auto it = std::upper_bound(this->VisitStart.begin(), this->VisitStart.end(), f);
    return this->VisitTri[(it - this->VisitStart.begin()) - 1];
  }

  /// Where vtkOFBAttributeInterpolator::Interpolate writes the attributes of fragments [f, ...).
  vtkOFBAttributeInterpolator::Run RunAt(vtkIdType f)
  {
    vtkOFBAttributeInterpolator::Run run;
    for (int k = 0; k < 3; ++k)
    {
      run.Normals[k] = this->Normals[k].data() + f;
      run.Vectors[k] = this->Vectors[k].empty() ? nullptr : this->Vectors[k].data() + f;
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
  std::vector<const vtkIdType*> OthersCells; // input cell per triangle, for cell arrays
  // The triangle and barycentrics of each sample (vtkOFBSampleSources), or null.
  vtkTypeUInt32* SourceTri = nullptr;
  float* SourceW1 = nullptr;
  float* SourceW2 = nullptr;
};

/**
 * An uninitialized array kept from build to build (see vtkOFBSamplerBuffers): a
 * rebuild writes over memory it already has.
 */
template<typename T>
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

/// The bands [FirstBand, LastBand] and rows [FirstRow, LastRow] of a set-up triangle
/// (none when FirstBand > LastBand).
struct BandRange
{
  vtkTypeUInt32 FirstBand, LastBand;
  int32_t FirstRow, LastRow;
};
}

/// The buffers of the CPU backend, kept by the sampler between builds.
class vtkOFBSamplerBuffers
{
public:
  vtkofb::Buffer<vtkOFBTriangleRaster> Setups;
  vtkofb::Buffer<vtkofb::SpanRecord> Spans;
  vtkofb::Buffer<vtkofb::BandRange> Ranges;
  vtkofb::Buffer<vtkTypeUInt32> Key, Order, BandTris;
  vtkSMPThreadLocal<vtkofb::BandScratch> Scratch;
};

namespace vtkofb
{
/**
 * A CPU build: the bands, the triangles sorted by band and set up, the triangles
 * and spans of each band, and the passes over one band.
 */
class BandBuilder
{
public:
  BandBuilder(const vtkOFBSurface& surface,
    const vtkOFBRasterFrame& frame,
    vtkOFBSamplerBuffers& buffers)
    : Surface(surface)
    , Frame(frame)
    , Interpolator(surface)
    , Buffers(buffers)
  {
  }

  /**
   * Cut each grid into bands of 2^Shift[a] whole rows, at most BandCells cells
   * (one row where a row is longer).
   */
  void CutBands();

  /**
   * Set up every triangle (in parallel), in the order of the band of their lowest
   * vertex, so that a band reads its setups from nearby memory, in each band those
   * that enter the surface before the others (see SortCells), then by that lowest
   * row (a counting sort, stable); false if the setups cannot be allocated. The
   * triangles facing against their grid's axis enter a surface wound outwards,
   * those facing along it one wound inwards (six times the volume it encloses,
   * the sum of p0 . n over its triangles, is negative).
   */
  bool SetupTriangles();

  /**
   * List the triangles of each band in setup order and count the rows of their
   * spans; false if the lists cannot be allocated. In parallel over chunks of
   * triangles: the triangles and rows of each band in each chunk, their prefix
   * sums in (band, chunk) order, then each chunk's part of the lists.
   */
  bool ListBandTriangles();

  /// Room for the spans of the bands' rows; false if it cannot be allocated.
  bool AllocateSpans();

  /// Pass 1: the non-empty spans of a band's rows and its number of samples.
  void SpanBand(Band& band) const;

  /**
   * Pass 2 over a band: the samples of each cell and the cell offsets; its
   * fragments, a triangle at a time (depth, barycentrics, attributes), each given
   * the next slot of its cell; the slots of each cell sorted by (depth, triangle);
   * and the samples written in slot order.
   */
  void FillBand(const Band& band, const Output& out, BandScratch& s) const;

  const vtkOFBSurface& Surface;
  const vtkOFBRasterFrame Frame;
  const vtkOFBAttributeInterpolator Interpolator;
  vtkOFBSamplerBuffers& Buffers;
  vtkOFBTriangleRaster* Setups = nullptr;
  BandRange* Ranges = nullptr;
  std::vector<Band> Bands;
  vtkTypeUInt32* BandTris = nullptr;
  SpanRecord* Spans = nullptr;
  vtkIdType SpanRows = 0;

private:
  int Shift[3] = { 0, 0, 0 };
  vtkIdType FirstBandOfGrid[3] = { 0, 0, 0 };
  vtkIdType FirstKey[3] = { 0, 0, 0 }; // setup order keys of each grid (SetupTriangles)

  ///@{
  /**
   * The steps of SetupTriangles: the setup order key of every triangle (the band
   * and row of its lowest vertex, entering or leaving; returns six times the
   * volume the triangles enclose), the keys swapped so that the triangles
   * entering a surface wound inwards come first, the triangles sorted by key (a
   * counting sort, stable), and every triangle set up in that order (in
   * parallel) with its band range.
   */
  double ComputeSetupKeys();
  void PutInwardKeysFirst();
  void SortBySetupKey();
  void SetUpInOrder();
  ///@}

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
   * that vectorizes; one of 8 samples for a shorter span, whose trip count the
   * branch predictor knows: the arrays have room for 8 more).
   */
  static void SpanSamples(const vtkOFBTriangleRaster& ts,
    const SpanRecord& span,
    float* VTK_OFB_RESTRICT depth,
    float* VTK_OFB_RESTRICT w1,
    float* VTK_OFB_RESTRICT w2);

  /**
   * Sort the slots of each cell by (depth, triangle), the order of the OpenGL
   * backend: an insertion sort, whose inner loop seldom runs. The fragments of a
   * cell mostly arrive in depth order: the triangles of each band that enter the
   * surface are set up (and so listed) before the others, and on a closed surface
   * the first sample of a cell enters it, the next leaves it.
   */
  static void SortCells(vtkIdType n, const vtkTypeUInt32* cellOf, BandScratch& s);

  /// Write the samples of a band in slot order from their fragments.
  void WriteSamples(const Band& band, const Output& out, const BandScratch& s) const;
};
}

#endif
