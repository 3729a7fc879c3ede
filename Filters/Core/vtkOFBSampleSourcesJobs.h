/**
 * @file    vtkOFBSampleSourcesJobs.h
 * @brief   The per-array loops of an attribute-only re-sampling (private)
 *
 * vtkOFBSampleSources::Resample gives each sample array a job: a table of the
 * array's values at the corners of every triangle (or at its cell, for a cell
 * array), in the order the samples first reach the triangles (`ids`, 3 point ids a
 * triangle, and `cells` are in that order), and a loop that
 * gives each sample of a range the value at its recorded triangle and
 * barycentrics. The loops are those of vtkOFBAttributeInterpolator, operation for
 * operation (the same floats and doubles as a full build), over samples in the
 * order of the OFB instead of fragments.
 *
 * The sample arrays are larger than the caches and are written once: the loops
 * store them with non-temporal stores where the platform has them (SSE2), which
 * write to memory without reading the lines first. A caller runs every job over a
 * short block of samples in turn (the block's sources stay in the first-level
 * cache) and calls Fence() at the end of its range.
 */

#ifndef vtkOFBSampleSourcesJobs_h
#define vtkOFBSampleSourcesJobs_h

#include "vtkOFBAttributeInterpolator.h" // for VTK_OFB_RESTRICT and the inputs
#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// AVX on x86-64 with GCC or Clang, chosen at run time (the build targets SSE2).
#if defined(__SSE2__) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define VTK_OFB_RESAMPLE_AVX 1
#endif

namespace vtkofb
{
/// Samples per block: each job runs over a block in turn while its sources are in cache.
constexpr vtkIdType ResampleBlock = 128;

/**
 * Triangles per chunk of the parallel loops that fill the tables: small enough that
 * the tables of a mesh of a few thousand triangles (with a few million samples at
 * 1024) are filled on every thread, not on the calling thread alone.
 */
constexpr vtkIdType TableChunk = 512;

/// The memory of a table (kept by vtkOFBSampleSources between re-samplings).
template<typename T>
struct ResampleTable
{
  T* Data = nullptr;
  size_t Size = 0;
  T& operator[](size_t i) const { return this->Data[i]; }
  T* data() const { return this->Data; }
  bool empty() const { return this->Size == 0; }

  /// Room for n values in `store` (which keeps its memory between calls).
  static ResampleTable Reserve(std::vector<char>& store, size_t n)
  {
    store.resize(n * sizeof(T));
    return ResampleTable{ reinterpret_cast<T*>(store.data()), n };
  }
};

/// Store `v` at `p`, bypassing the cache for 4- and 8-byte values where SSE2 has it.
template<typename T>
inline void StreamValue(T* p, T v)
{
#if defined(__SSE2__)
  if constexpr (sizeof(T) == 4)
  {
    int bits;
    std::memcpy(&bits, &v, 4);
    _mm_stream_si32(reinterpret_cast<int*>(p), bits);
    return;
  }
#if defined(__x86_64__)
  if constexpr (sizeof(T) == 8)
  {
    long long bits;
    std::memcpy(&bits, &v, 8);
    _mm_stream_si64(reinterpret_cast<long long*>(p), bits);
    return;
  }
#endif
#endif
  *p = v;
}

/// The non-temporal stores of this thread ordered before what follows.
inline void Fence()
{
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

/// The re-sampling of one array over samples [begin, end) from their sources.
struct ResampleJob
{
  virtual ~ResampleJob() = default;
  virtual void Run(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* tri,
    const float* w1,
    const float* w2) const = 0;
};

/// The paint: the point colours interpolated as vtkOFBAttributeInterpolator does, else
/// DefaultColor.
struct ColorJob : ResampleJob
{
  ResampleTable<float> Table; // per triangle 3 corners x 4 components
  int NC;
  vtkTypeUInt32 Default;
  unsigned char* Out;

  ColorJob(const vtkOFBAttributeInterpolator& in,
    const vtkIdType* ids,
    vtkIdType nTriangles,
    std::vector<char>& store,
    unsigned char* out)
    : NC(in.ColorComponents)
    , Out(out)
  {
    std::memcpy(&this->Default, in.DefaultColor, 4);
    if (!in.PointColors)
    {
      return;
    }
    this->Table = ResampleTable<float>::Reserve(store, static_cast<size_t>(12 * nTriangles));
    const int nc = this->NC;
    vtkSMPTools::For(0,
      nTriangles,
      TableChunk,
      [&](vtkIdType t0, vtkIdType t1)
      {
        for (vtkIdType t = t0; t < t1; ++t)
        {
          for (int c = 0; c < 3; ++c)
          {
            for (int k = 0; k < 4; ++k)
            {
              this->Table[12 * t + 4 * c + k] =
                k < nc ? static_cast<float>(in.PointColors[nc * ids[3 * t + c] + k]) : 0.0f;
            }
          }
        }
      });
  }

  void Run(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* tri,
    const float* w1,
    const float* w2) const override
  {
    vtkTypeUInt32* out = reinterpret_cast<vtkTypeUInt32*>(this->Out);
    if (this->Table.empty())
    {
      vtkIdType i = begin;
#if defined(__SSE2__)
      // Four samples a store from one whose colour is 16-byte aligned.
      if (reinterpret_cast<uintptr_t>(out) % 16 == 0)
      {
        for (; i < end && (i & 3) != 0; ++i)
        {
          StreamValue(out + i, this->Default);
        }
        const __m128i four = _mm_set1_epi32(static_cast<int>(this->Default));
        for (; i + 4 <= end; i += 4)
        {
          _mm_stream_si128(reinterpret_cast<__m128i*>(out + i), four);
        }
      }
#endif
      for (; i < end; ++i)
      {
        StreamValue(out + i, this->Default);
      }
      return;
    }
    const int nc = this->NC;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* c = this->Table.data() + 12 * static_cast<size_t>(tri[i]);
      unsigned char rgba[4] = { 0, 0, 0, 255 }; // RGB or RGBA (IsColorArray)
      for (int k = 0; k < nc; ++k)
      {
        const float v = (1.0f - w1[i] - w2[i]) * c[k] + w1[i] * c[4 + k] + w2[i] * c[8 + k];
        rgba[k] = static_cast<unsigned char>(std::min(255.0f, v + 0.5f));
      }
      vtkTypeUInt32 bits;
      std::memcpy(&bits, rgba, 4);
      StreamValue(out + i, bits);
    }
  }
};

#if defined(VTK_OFB_RESAMPLE_AVX)
/// Whether the processor (and the system) has AVX.
inline bool HasAVX()
{
  static const bool avx = __builtin_cpu_supports("avx");
  return avx;
}

/**
 * The barycentrics of the samples from `i` (eight in floats, four in doubles): b1 and b2
 * the recorded ones, b0 = (1 - b1) - b2 (the scalar loops' order).
 */
__attribute__((target("avx"))) inline void LoadBarycentrics(const float* w1,
  const float* w2,
  vtkIdType i,
  __m256 b[3])
{
  b[1] = _mm256_loadu_ps(w1 + i);
  b[2] = _mm256_loadu_ps(w2 + i);
  b[0] = _mm256_sub_ps(_mm256_sub_ps(_mm256_set1_ps(1.0f), b[1]), b[2]);
}
__attribute__((target("avx"))) inline void LoadBarycentrics(const float* w1,
  const float* w2,
  vtkIdType i,
  __m256d b[3])
{
  b[1] = _mm256_cvtps_pd(_mm_loadu_ps(w1 + i));
  b[2] = _mm256_cvtps_pd(_mm_loadu_ps(w2 + i));
  b[0] = _mm256_sub_pd(_mm256_sub_pd(_mm256_set1_pd(1.0), b[1]), b[2]);
}

/// (b0 v0 + b1 v1) + b2 v2, lane by lane.
__attribute__((target("avx"))) inline __m256 Barycentric(const __m256* b, const __m256* v)
{
  return _mm256_add_ps(
    _mm256_add_ps(_mm256_mul_ps(b[0], v[0]), _mm256_mul_ps(b[1], v[1])), _mm256_mul_ps(b[2], v[2]));
}
__attribute__((target("avx"))) inline __m256d Barycentric(const __m256d* b, const __m256d* v)
{
  return _mm256_add_pd(
    _mm256_add_pd(_mm256_mul_pd(b[0], v[0]), _mm256_mul_pd(b[1], v[1])), _mm256_mul_pd(b[2], v[2]));
}

/// Four floats at `lo` and four at `hi` as the two halves of one register (Aligned: both
/// addresses 16-byte aligned, as the table's records are).
template<bool Aligned>
__attribute__((target("avx"))) inline __m256 LoadHalves(const float* lo, const float* hi)
{
  const __m128 l = Aligned ? _mm_load_ps(lo) : _mm_loadu_ps(lo);
  const __m128 h = Aligned ? _mm_load_ps(hi) : _mm_loadu_ps(hi);
  return _mm256_insertf128_ps(_mm256_castps128_ps256(l), h, 1);
}

/**
 * The vectors of samples [i, end) of VectorJob, eight at a time, with AVX (no FMA:
 * the same roundings as the scalar loop), from an i that is a multiple of 4; returns
 * the first sample not done. The two 128-bit halves of a register hold samples
 * i..i+3 and i+4..i+7, each half a component of four samples (structure of arrays):
 * the table's corners are transposed in each half, the normals de-interleaved, and
 * the results interleaved again into six non-temporal 16-byte stores. `out` is
 * 16-byte aligned; the table's records (x, y, z, 0) too.
 */
template<bool Projected>
__attribute__((target("avx"))) vtkIdType InterpolateVectorsAVX(vtkIdType i,
  vtkIdType end,
  const vtkTypeUInt32* VTK_OFB_RESTRICT tri,
  const float* VTK_OFB_RESTRICT w1,
  const float* VTK_OFB_RESTRICT w2,
  const float* VTK_OFB_RESTRICT table,
  const float* VTK_OFB_RESTRICT normals,
  float* VTK_OFB_RESTRICT out)
{
  for (; i + 8 <= end; i += 8)
  {
    __m256 b[3];
    LoadBarycentrics(w1, w2, i, b);
    const float* c[4];
    const float* d[4];
    for (int k = 0; k < 4; ++k)
    {
      c[k] = table + 12 * static_cast<size_t>(tri[i + k]);
      d[k] = table + 12 * static_cast<size_t>(tri[i + 4 + k]);
    }
    // Corner j of the eight samples as x, y, z of four samples in each half.
    __m256 x[3], y[3], z[3];
    for (int j = 0; j < 3; ++j)
    {
      __m256 r[4];
      for (int k = 0; k < 4; ++k)
      {
        r[k] = LoadHalves<true>(c[k] + 4 * j, d[k] + 4 * j);
      }
      const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]); // x0 x1 y0 y1
      const __m256 t1 = _mm256_unpacklo_ps(r[2], r[3]); // x2 x3 y2 y3
      const __m256 t2 = _mm256_unpackhi_ps(r[0], r[1]); // z0 z1 . .
      const __m256 t3 = _mm256_unpackhi_ps(r[2], r[3]); // z2 z3 . .
      x[j] = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(1, 0, 1, 0));
      y[j] = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(3, 2, 3, 2));
      z[j] = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(1, 0, 1, 0));
    }
    __m256 ox = Barycentric(b, x), oy = Barycentric(b, y), oz = Barycentric(b, z);
    if (Projected)
    {
      // n0x n0y n0z n1x | n1y n1z n2x n2y | n2z n3x n3y n3z in each half.
      const float* p = normals + 3 * i;
      const __m256 na = LoadHalves<false>(p, p + 12);
      const __m256 nb = LoadHalves<false>(p + 4, p + 16);
      const __m256 nc = LoadHalves<false>(p + 8, p + 20);
      const __m256 a = _mm256_shuffle_ps(na, nb, _MM_SHUFFLE(3, 2, 3, 0)); // n0x n1x n2x .
      const __m256 b = _mm256_shuffle_ps(nb, nc, _MM_SHUFFLE(1, 1, 2, 2)); // n2x . n3x .
      const __m256 nx = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 1, 0));
      const __m256 e = _mm256_shuffle_ps(na, nb, _MM_SHUFFLE(0, 0, 1, 1)); // n0y . n1y .
      const __m256 f = _mm256_shuffle_ps(nb, nc, _MM_SHUFFLE(2, 2, 3, 3)); // n2y . n3y .
      const __m256 ny = _mm256_shuffle_ps(e, f, _MM_SHUFFLE(2, 0, 2, 0));
      const __m256 g = _mm256_shuffle_ps(na, nb, _MM_SHUFFLE(1, 1, 2, 2)); // n0z . n1z .
      const __m256 nz = _mm256_shuffle_ps(g, nc, _MM_SHUFFLE(3, 0, 2, 0));
      const __m256 vn = _mm256_add_ps(
        _mm256_add_ps(_mm256_mul_ps(ox, nx), _mm256_mul_ps(oy, ny)), _mm256_mul_ps(oz, nz));
      ox = _mm256_sub_ps(ox, _mm256_mul_ps(vn, nx));
      oy = _mm256_sub_ps(oy, _mm256_mul_ps(vn, ny));
      oz = _mm256_sub_ps(oz, _mm256_mul_ps(vn, nz));
    }
    // x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3 in each half.
    const __m256 xy = _mm256_unpacklo_ps(ox, oy);                         // x0 y0 x1 y1
    const __m256 zx = _mm256_shuffle_ps(oz, ox, _MM_SHUFFLE(1, 1, 0, 0)); // z0 . x1 .
    const __m256 o0 = _mm256_shuffle_ps(xy, zx, _MM_SHUFFLE(2, 0, 1, 0));
    const __m256 yz = _mm256_shuffle_ps(oy, oz, _MM_SHUFFLE(1, 1, 1, 1)); // y1 . z1 .
    const __m256 xy2 = _mm256_unpackhi_ps(ox, oy);                        // x2 y2 x3 y3
    const __m256 o1 = _mm256_shuffle_ps(yz, xy2, _MM_SHUFFLE(1, 0, 2, 0));
    const __m256 zx3 = _mm256_shuffle_ps(oz, ox, _MM_SHUFFLE(3, 3, 2, 2)); // z2 . x3 .
    const __m256 yz3 = _mm256_shuffle_ps(oy, oz, _MM_SHUFFLE(3, 3, 3, 3)); // y3 . z3 .
    const __m256 o2 = _mm256_shuffle_ps(zx3, yz3, _MM_SHUFFLE(2, 0, 2, 0));
    float* o = out + 3 * i;
    _mm_stream_ps(o, _mm256_castps256_ps128(o0));
    _mm_stream_ps(o + 4, _mm256_castps256_ps128(o1));
    _mm_stream_ps(o + 8, _mm256_castps256_ps128(o2));
    _mm_stream_ps(o + 12, _mm256_extractf128_ps(o0, 1));
    _mm_stream_ps(o + 16, _mm256_extractf128_ps(o1, 1));
    _mm_stream_ps(o + 20, _mm256_extractf128_ps(o2, 1));
  }
  return i;
}

/// Record (c0, c1, c2, 0) of a one-component table, in doubles.
__attribute__((target("avx"))) inline __m256d LoadScalarRecord(const double* r)
{
  return _mm256_loadu_pd(r);
}
__attribute__((target("avx"))) inline __m256d LoadScalarRecord(const float* r)
{
  return _mm256_cvtps_pd(_mm_load_ps(r));
}

/// Four values of v, stored as T (two 16-byte non-temporal stores of doubles, one of floats).
__attribute__((target("avx"))) inline void StreamScalars(double* o, __m256d v)
{
  _mm_stream_pd(o, _mm256_castpd256_pd128(v));
  _mm_stream_pd(o + 2, _mm256_extractf128_pd(v, 1));
}
__attribute__((target("avx"))) inline void StreamScalars(float* o, __m256d v)
{
  _mm_stream_ps(o, _mm256_cvtpd_ps(v));
}

/**
 * A one-component float or double array of TupleJob (records c0, c1, c2, 0,
 * 16-byte aligned) over samples [i, end), four at a time in doubles with AVX (the
 * operations of the scalar loop), from an i that is a multiple of 4 (`out`
 * 16-byte aligned); returns the first sample not done.
 */
template<typename T>
__attribute__((target("avx"))) vtkIdType InterpolateScalarsAVX(vtkIdType i,
  vtkIdType end,
  const vtkTypeUInt32* VTK_OFB_RESTRICT tri,
  const float* VTK_OFB_RESTRICT w1,
  const float* VTK_OFB_RESTRICT w2,
  const T* VTK_OFB_RESTRICT table,
  T* VTK_OFB_RESTRICT out)
{
  for (; i + 4 <= end; i += 4)
  {
    __m256d b[3];
    LoadBarycentrics(w1, w2, i, b);
    __m256d r[4];
    for (int k = 0; k < 4; ++k)
    {
      r[k] = LoadScalarRecord(table + 4 * static_cast<size_t>(tri[i + k]));
    }
    // The records transposed: corner j of the four samples.
    const __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]); // c0 c0 | c2 c2
    const __m256d t1 = _mm256_unpackhi_pd(r[0], r[1]); // c1 c1 | 0 0
    const __m256d t2 = _mm256_unpacklo_pd(r[2], r[3]);
    const __m256d t3 = _mm256_unpackhi_pd(r[2], r[3]);
    const __m256d c[3] = { _mm256_permute2f128_pd(t0, t2, 0x20),
      _mm256_permute2f128_pd(t1, t3, 0x20),
      _mm256_permute2f128_pd(t0, t2, 0x31) };
    StreamScalars(out + i, Barycentric(b, c));
  }
  return i;
}
#endif

/**
 * The vector field interpolated and projected on the kept normals, in the
 * operations of vtkOFBAttributeInterpolator::InterpolateVectors: per component
 * (1 - w1 - w2) v0 + w1 v1 + w2 v2, then v - (v . n) n with the dot product summed
 * x, y, z. With SSE2, a sample's three components go in the lanes of one register
 * (the same operations on each), four samples at a time.
 */
struct VectorJob : ResampleJob
{
  ResampleTable<float> Table; // per triangle 3 corners x 4 (x, y, z, 0)
  bool Project;
  const float* Normals;
  float* Out;

  VectorJob(const vtkOFBAttributeInterpolator& in,
    const vtkIdType* ids,
    vtkIdType nTriangles,
    std::vector<char>& store,
    const float* normals,
    float* out)
    : Project(in.ProjectVectors)
    , Normals(normals)
    , Out(out)
  {
    this->Table = ResampleTable<float>::Reserve(store, static_cast<size_t>(12 * nTriangles));
    vtkSMPTools::For(0,
      nTriangles,
      TableChunk,
      [&](vtkIdType t0, vtkIdType t1)
      {
        for (vtkIdType t = t0; t < t1; ++t)
        {
          for (int c = 0; c < 3; ++c)
          {
            float* corner = &this->Table[12 * t + 4 * c];
            const float* v = in.PointVectors + 3 * ids[3 * t + c];
            corner[0] = v[0];
            corner[1] = v[1];
            corner[2] = v[2];
            corner[3] = 0.0f;
          }
        }
      });
  }

  void Run(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* tri,
    const float* w1,
    const float* w2) const override
  {
    if (this->Project)
    {
      this->Interpolate<true>(begin, end, tri, w1, w2);
    }
    else
    {
      this->Interpolate<false>(begin, end, tri, w1, w2);
    }
  }

  /// One sample, one component at a time.
  template<bool Projected>
  void InterpolateOne(vtkIdType i, const vtkTypeUInt32* tri, const float* w1, const float* w2) const
  {
    const float* c = this->Table.data() + 12 * static_cast<size_t>(tri[i]);
    const float b1 = w1[i], b2 = w2[i], b0 = 1.0f - b1 - b2;
    const float vx = b0 * c[0] + b1 * c[4] + b2 * c[8];
    const float vy = b0 * c[1] + b1 * c[5] + b2 * c[9];
    const float vz = b0 * c[2] + b1 * c[6] + b2 * c[10];
    float* out = this->Out + 3 * i;
    if (!Projected)
    {
      out[0] = vx;
      out[1] = vy;
      out[2] = vz;
      return;
    }
    const float* n = this->Normals + 3 * i;
    const float vn = vx * n[0] + vy * n[1] + vz * n[2];
    out[0] = vx - vn * n[0];
    out[1] = vy - vn * n[1];
    out[2] = vz - vn * n[2];
  }

  template<bool Projected>
  void Interpolate(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* VTK_OFB_RESTRICT tri,
    const float* VTK_OFB_RESTRICT w1,
    const float* VTK_OFB_RESTRICT w2) const
  {
    vtkIdType i = begin;
#if defined(__SSE2__)
    // Four samples at a time from one whose output is 16-byte aligned: their 48
    // bytes in three non-temporal stores. The table's records are 16-byte aligned
    // (operator new's alignment): its loads fold into the multiplications.
    if (reinterpret_cast<uintptr_t>(this->Out) % 16 == 0 &&
      reinterpret_cast<uintptr_t>(this->Table.data()) % 16 == 0)
    {
      for (; i < end && (i & 3) != 0; ++i)
      {
        this->InterpolateOne<Projected>(i, tri, w1, w2);
      }
      const float* VTK_OFB_RESTRICT table = this->Table.data();
      const float* VTK_OFB_RESTRICT normals = this->Normals;
      float* VTK_OFB_RESTRICT out = this->Out;
#if defined(VTK_OFB_RESAMPLE_AVX)
      if (HasAVX())
      {
        i = InterpolateVectorsAVX<Projected>(i, end, tri, w1, w2, table, normals, out);
      }
#endif
      const __m128 one = _mm_set1_ps(1.0f);
      for (; i + 4 <= end; i += 4)
      {
        const __m128 b1 = _mm_loadu_ps(w1 + i);
        const __m128 b2 = _mm_loadu_ps(w2 + i);
        const __m128 b0 = _mm_sub_ps(_mm_sub_ps(one, b1), b2);
        __m128 r[4];
        // The normals of the four samples, each in lanes x, y, z.
        __m128 n[4];
        if (Projected)
        {
          const float* p = normals + 3 * i;
          n[0] = _mm_loadu_ps(p);
          n[1] = _mm_loadu_ps(p + 3);
          n[2] = _mm_loadu_ps(p + 6);
          const __m128 last = _mm_loadu_ps(p + 8); // not past the four samples' normals
          n[3] = _mm_shuffle_ps(last, last, _MM_SHUFFLE(3, 3, 2, 1));
        }
        for (int k = 0; k < 4; ++k)
        {
          const float* c = table + 12 * static_cast<size_t>(tri[i + k]);
          const __m128 s0 = Lane(b0, k), s1 = Lane(b1, k), s2 = Lane(b2, k);
          const __m128 v = _mm_add_ps(
            _mm_add_ps(_mm_mul_ps(s0, _mm_load_ps(c)), _mm_mul_ps(s1, _mm_load_ps(c + 4))),
            _mm_mul_ps(s2, _mm_load_ps(c + 8)));
          if (!Projected)
          {
            r[k] = v;
            continue;
          }
          // (vx nx + vy ny) + vz nz in lane 0, then in every lane.
          const __m128 p = _mm_mul_ps(v, n[k]);
          __m128 vn = _mm_add_ss(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
          vn = _mm_add_ss(vn, _mm_movehl_ps(p, p));
          vn = _mm_shuffle_ps(vn, vn, _MM_SHUFFLE(0, 0, 0, 0));
          r[k] = _mm_sub_ps(v, _mm_mul_ps(vn, n[k]));
        }
        // x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3
        const __m128 z0x1 = _mm_shuffle_ps(r[0], r[1], _MM_SHUFFLE(0, 0, 2, 2));
        const __m128 z2x3 = _mm_shuffle_ps(r[2], r[3], _MM_SHUFFLE(0, 0, 2, 2));
        float* o = out + 3 * i;
        _mm_stream_ps(o, _mm_shuffle_ps(r[0], z0x1, _MM_SHUFFLE(2, 0, 1, 0)));
        _mm_stream_ps(o + 4, _mm_shuffle_ps(r[1], r[2], _MM_SHUFFLE(1, 0, 2, 1)));
        _mm_stream_ps(o + 8, _mm_shuffle_ps(z2x3, r[3], _MM_SHUFFLE(2, 1, 2, 0)));
      }
    }
#endif
    for (; i < end; ++i)
    {
      this->InterpolateOne<Projected>(i, tri, w1, w2);
    }
  }

#if defined(__SSE2__)
  /// Lane k of v in every lane.
  static __m128 Lane(__m128 v, int k)
  {
    switch (k)
    {
      case 0:
        return _mm_shuffle_ps(v, v, _MM_SHUFFLE(0, 0, 0, 0));
      case 1:
        return _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 1, 1, 1));
      case 2:
        return _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 2, 2, 2));
      default:
        return _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 3, 3, 3));
    }
  }
#endif
};

/**
 * Another point array, interpolated as vtkOFBAttributeInterpolator::InterpolateTuples
 * does, or a cell array, the tuple of each sample's triangle's cell.
 */
template<typename T>
struct TupleJob : ResampleJob
{
  ResampleTable<T> Table; // per triangle 3 corners x NC values, or NC for a cell array
  int NC;
  bool PerCell;
  int Record; // values per triangle: 3 NC (4 for one floating-point component), or NC
  T* Out;

  TupleJob(const T* in,
    int nc,
    const vtkIdType* ids,
    const vtkIdType* cells,
    vtkIdType nTriangles,
    std::vector<char>& store,
    T* out)
    : NC(nc)
    , PerCell(cells != nullptr)
    , Record(cells ? nc : (nc == 1 && std::is_floating_point<T>::value ? 4 : 3 * nc))
    , Out(out)
  {
    const int corners = cells ? 1 : 3;
    const int record = this->Record;
    this->Table = ResampleTable<T>::Reserve(store, static_cast<size_t>(record * nTriangles));
    vtkSMPTools::For(0,
      nTriangles,
      TableChunk,
      [&](vtkIdType t0, vtkIdType t1)
      {
        for (vtkIdType t = t0; t < t1; ++t)
        {
          for (int c = 0; c < corners; ++c)
          {
            const vtkIdType source = cells ? cells[t] : ids[3 * t + c];
            for (int k = 0; k < nc; ++k)
            {
              this->Table[record * t + c * nc + k] = in[nc * source + k];
            }
          }
          for (int k = corners * nc; k < record; ++k)
          {
            this->Table[record * t + k] = T(0);
          }
        }
      });
  }

  void Run(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* tri,
    const float* w1,
    const float* w2) const override
  {
    const int nc = this->NC;
    if (this->PerCell)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const T* tuple = this->Table.data() + static_cast<size_t>(tri[i]) * nc;
        for (int k = 0; k < nc; ++k)
        {
          StreamValue(this->Out + i * nc + k, tuple[k]);
        }
      }
      return;
    }
    // The common component counts with the count known to the compiler.
    switch (nc)
    {
      case 1:
        this->InterpolateScalars(begin, end, tri, w1, w2);
        break;
      case 3:
        this->Interpolate<3>(begin, end, tri, w1, w2, 3);
        break;
      default:
        this->Interpolate<0>(begin, end, tri, w1, w2, nc);
        break;
    }
  }

  /**
   * One component: with SSE2, floating-point values two samples at a time in the
   * lanes of a register of doubles (the operations of Interpolate<1>).
   */
  void InterpolateScalars(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* VTK_OFB_RESTRICT tri,
    const float* VTK_OFB_RESTRICT w1,
    const float* VTK_OFB_RESTRICT w2) const
  {
    vtkIdType i = begin;
#if defined(__SSE2__) && defined(__x86_64__)
    if constexpr (std::is_same<T, double>::value || std::is_same<T, float>::value)
    {
      const T* VTK_OFB_RESTRICT table = this->Table.data();
      T* VTK_OFB_RESTRICT out = this->Out;
      const bool aligned = reinterpret_cast<uintptr_t>(out) % 16 == 0;
#if defined(VTK_OFB_RESAMPLE_AVX)
      if (HasAVX() && aligned && reinterpret_cast<uintptr_t>(table) % 16 == 0)
      {
        const vtkIdType first = std::min(end, (i + 3) & ~vtkIdType(3));
        this->Interpolate<1>(i, first, tri, w1, w2, 1);
        i = InterpolateScalarsAVX(first, end, tri, w1, w2, table, out);
      }
#endif
      if (i < end && (i & 1) != 0)
      {
        this->Interpolate<1>(i, i + 1, tri, w1, w2, 1);
        ++i;
      }
      const __m128d one = _mm_set1_pd(1.0);
      for (; i + 2 <= end; i += 2)
      {
        const T* a = table + 4 * static_cast<size_t>(tri[i]);
        const T* b = table + 4 * static_cast<size_t>(tri[i + 1]);
        const __m128d b1 =
          _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(w1 + i))));
        const __m128d b2 =
          _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(w2 + i))));
        const __m128d b0 = _mm_sub_pd(_mm_sub_pd(one, b1), b2);
        const __m128d c0 = _mm_set_pd(static_cast<double>(b[0]), static_cast<double>(a[0]));
        const __m128d c1 = _mm_set_pd(static_cast<double>(b[1]), static_cast<double>(a[1]));
        const __m128d c2 = _mm_set_pd(static_cast<double>(b[2]), static_cast<double>(a[2]));
        const __m128d v =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(b0, c0), _mm_mul_pd(b1, c1)), _mm_mul_pd(b2, c2));
        if (std::is_same<T, double>::value && aligned)
        {
          _mm_stream_pd(reinterpret_cast<double*>(out + i), v);
        }
        else if (std::is_same<T, double>::value)
        {
          StreamValue(out + i, static_cast<T>(_mm_cvtsd_f64(v)));
          StreamValue(out + i + 1, static_cast<T>(_mm_cvtsd_f64(_mm_unpackhi_pd(v, v))));
        }
        else
        {
          long long bits;
          const __m128 f = _mm_cvtpd_ps(v);
          std::memcpy(&bits, &f, 8);
          _mm_stream_si64(reinterpret_cast<long long*>(out + i), bits);
        }
      }
    }
#endif
    this->Interpolate<1>(i, end, tri, w1, w2, 1);
  }

  /// The interpolation of samples [begin, end): NC components (0: `nc`, known at run time).
  template<int NCT>
  void Interpolate(vtkIdType begin,
    vtkIdType end,
    const vtkTypeUInt32* VTK_OFB_RESTRICT tri,
    const float* VTK_OFB_RESTRICT w1,
    const float* VTK_OFB_RESTRICT w2,
    int nc) const
  {
    const int n = NCT > 0 ? NCT : nc;
    const T* VTK_OFB_RESTRICT table = this->Table.data();
    T* VTK_OFB_RESTRICT out = this->Out;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const T* c = table + static_cast<size_t>(tri[i]) * this->Record;
      const double b1 = w1[i], b2 = w2[i], b0 = 1.0 - b1 - b2;
      for (int k = 0; k < n; ++k)
      {
        const double v = b0 * c[k] + b1 * c[n + k] + b2 * c[2 * n + k];
        if (std::is_integral<T>::value)
        {
          StreamValue(out + i * n + k, static_cast<T>(std::llround(v)));
        }
        else
        {
          StreamValue(out + i * n + k, static_cast<T>(v));
        }
      }
    }
  }
};
}

#endif
