/**
 * @class   vtkOFBAttributeInterpolator
 * @brief   OFB sample attributes interpolated on the CPU from triangle and barycentrics (private)
 *
 * Attributes of the samples of a triangle, n at a time (structure of arrays, so
 * that the loops vectorize): unit normals (the face normal where the point normals
 * cancel), the vector field projected into the tangent plane, RGBA colours, and
 * the other point arrays of the surface, in plain C++ (no GLSL: the OpenGL
 * backend reads its samples' triangles and barycentrics back and interpolates
 * them here too). The CPU backend (vtkOFBCPUSampler) and
 * vtkOFBSamplerBackend::InterpolateAttributes (used by the OpenGL backend) both
 * use it, so both give the same attributes.
 */

#ifndef vtkOFBAttributeInterpolator_h
#define vtkOFBAttributeInterpolator_h

#include "vtkFloatArray.h"
#include "vtkOFBSurface.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// Outputs that alias nothing else, so that the loops below vectorize.
#if defined(__GNUC__) || defined(__clang__) || defined(_MSC_VER)
#define VTK_OFB_RESTRICT __restrict
#else
#define VTK_OFB_RESTRICT
#endif

struct vtkOFBAttributeInterpolator
{
  const double* Points;              ///< xyz per point
  const vtkIdType* TrianglePointIds; ///< 3 per triangle
  const float* PointNormals;         ///< unit, 3 per point
  const float* PointVectors;         ///< 3 per point, or null
  const unsigned char* PointColors;  ///< ColorComponents per point, or null
  int ColorComponents;               ///< 3 (RGB) or 4 (RGBA); 0 without colours
  unsigned char DefaultColor[4];
  bool ProjectVectors;

  explicit vtkOFBAttributeInterpolator(const vtkOFBSurface& s)
    : Points(s.Points.data())
    , TrianglePointIds(s.Triangles.data())
    , PointNormals(s.Normals.data())
    , PointVectors(s.Vectors ? vtkFloatArray::SafeDownCast(s.Vectors)->GetPointer(0) : nullptr)
    , PointColors(s.Colors ? s.Colors->GetPointer(0) : nullptr)
    , ColorComponents(s.Colors ? s.Colors->GetNumberOfComponents() : 0)
    , ProjectVectors(s.ProjectVectors)
  {
    std::memcpy(this->DefaultColor, s.DefaultColor, 4);
  }

  /**
   * Where a run of samples goes: normals and vectors by component, colours 4 bytes
   * a sample (written only when the surface has colours), and room for n floats
   * of temporaries.
   */
  struct Run
  {
    float* Normals[3];
    float* Vectors[3];
    unsigned char* RGBA;
    float* Scratch;
  };

  /// Attributes of n samples of triangle tri at barycentrics (w1, w2) in the triangle.
  void Interpolate(vtkIdType tri,
    vtkIdType n,
    const float* w1,
    const float* w2,
    const Run& out) const
  {
    const vtkIdType* t = this->TrianglePointIds + 3 * tri;
    this->Interpolate(t, n, w1, w2, out, this->MayCancel(t));
  }

  /**
   * Whether interpolated point normals of the triangle of point ids t[3] may
   * cancel. With clamped barycentrics, |n|^2 is at least the smallest dot product
   * of two point normals: when that is clearly positive, no sample needs the face
   * normal.
   */
  bool MayCancel(const vtkIdType* t) const
  {
    float smallest = 1.0f;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        const float* a = this->PointNormals + 3 * t[i];
        const float* b = this->PointNormals + 3 * t[j];
        smallest = std::min(smallest, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
      }
    }
    return !(smallest > 1e-3f);
  }

  /**
   * The same for the triangle of point ids t[3], whose normals may cancel or not
   * (MayCancel, known to the caller). `padded`: w1, w2 and the normals have room
   * for n rounded up to a multiple of 4, whose normals may then be computed from
   * whatever those extra w1, w2 hold (finite floats).
   */
  void Interpolate(const vtkIdType* t,
    vtkIdType n,
    const float* w1,
    const float* w2,
    const Run& out,
    bool mayCancel,
    bool padded = false) const
  {
    // The point normals interpolated and their squared length, in one loop that
    // vectorizes (structure of arrays).
    float* nx = out.Normals[0];
    float* ny = out.Normals[1];
    float* nz = out.Normals[2];
    if (!mayCancel)
    {
      InterpolateUnitNormals(padded ? (n + 3) & ~vtkIdType(3) : n,
        w1,
        w2,
        this->PointNormals + 3 * t[0],
        this->PointNormals + 3 * t[1],
        this->PointNormals + 3 * t[2],
        nx,
        ny,
        nz);
      this->InterpolateVectorsAndColors(t, n, w1, w2, out);
      return;
    }
    float* len2 = out.Scratch;
    InterpolateNormals(n,
      w1,
      w2,
      this->PointNormals + 3 * t[0],
      this->PointNormals + 3 * t[1],
      this->PointNormals + 3 * t[2],
      nx,
      ny,
      nz,
      len2);
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (!(len2[i] > 1e-12f))
      {
        float face[3];
        this->FaceNormal(t, face);
        len2[i] = face[0] * face[0] + face[1] * face[1] + face[2] * face[2];
        const bool zero = !(len2[i] > 0.0f);
        nx[i] = zero ? 0.0f : face[0];
        ny[i] = zero ? 0.0f : face[1];
        nz[i] = zero ? 0.0f : face[2];
        len2[i] = zero ? 1.0f : len2[i];
      }
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      const float inv = 1.0f / std::sqrt(len2[i]);
      nx[i] *= inv;
      ny[i] *= inv;
      nz[i] *= inv;
    }
    this->InterpolateVectorsAndColors(t, n, w1, w2, out);
  }

  /// The vectors and colours of n samples (Interpolate, once their normals are known).
  void InterpolateVectorsAndColors(const vtkIdType* t,
    vtkIdType n,
    const float* w1,
    const float* w2,
    const Run& out) const
  {
    if (this->PointVectors)
    {
      this->InterpolateVectors(t, n, w1, w2, out);
    }
    if (this->PointColors)
    {
      this->InterpolateColors(t, n, w1, w2, out.RGBA);
    }
  }

  /**
   * Normals n0, n1, n2 interpolated at n barycentrics (w1, w2), by component, and
   * their squared length (restrict: the loop vectorizes).
   */
  static void InterpolateNormals(vtkIdType n,
    const float* VTK_OFB_RESTRICT w1,
    const float* VTK_OFB_RESTRICT w2,
    const float* n0,
    const float* n1,
    const float* n2,
    float* VTK_OFB_RESTRICT nx,
    float* VTK_OFB_RESTRICT ny,
    float* VTK_OFB_RESTRICT nz,
    float* VTK_OFB_RESTRICT len2)
  {
    const float x0 = n0[0], y0 = n0[1], z0 = n0[2];
    const float x1 = n1[0], y1 = n1[1], z1 = n1[2];
    const float x2 = n2[0], y2 = n2[1], z2 = n2[2];
    for (vtkIdType i = 0; i < n; ++i)
    {
      const float b1 = w1[i], b2 = w2[i], b0 = 1.0f - b1 - b2;
      const float x = b0 * x0 + b1 * x1 + b2 * x2;
      const float y = b0 * y0 + b1 * y1 + b2 * y2;
      const float z = b0 * z0 + b1 * z1 + b2 * z2;
      nx[i] = x;
      ny[i] = y;
      nz[i] = z;
      len2[i] = x * x + y * y + z * z;
    }
  }

  /**
   * The same normalized, in one loop, where they cannot cancel (the same
   * operations: the same floats), four at a time, then one at a time. The squared
   * length, at least 1e-3 where they cannot cancel, is kept from zero for the
   * padding of Interpolate.
   */
  static void InterpolateUnitNormals(vtkIdType n,
    const float* VTK_OFB_RESTRICT w1,
    const float* VTK_OFB_RESTRICT w2,
    const float* n0,
    const float* n1,
    const float* n2,
    float* VTK_OFB_RESTRICT nx,
    float* VTK_OFB_RESTRICT ny,
    float* VTK_OFB_RESTRICT nz)
  {
    vtkIdType i = 0;
#if defined(__SSE2__)
    const __m128 x0 = _mm_set1_ps(n0[0]), y0 = _mm_set1_ps(n0[1]), z0 = _mm_set1_ps(n0[2]);
    const __m128 x1 = _mm_set1_ps(n1[0]), y1 = _mm_set1_ps(n1[1]), z1 = _mm_set1_ps(n1[2]);
    const __m128 x2 = _mm_set1_ps(n2[0]), y2 = _mm_set1_ps(n2[1]), z2 = _mm_set1_ps(n2[2]);
    const __m128 one = _mm_set1_ps(1.0f), tiny = _mm_set1_ps(1e-30f);
    auto dot = [](__m128 b0, __m128 b1, __m128 b2, __m128 v0, __m128 v1, __m128 v2)
    { return _mm_add_ps(_mm_add_ps(_mm_mul_ps(b0, v0), _mm_mul_ps(b1, v1)), _mm_mul_ps(b2, v2)); };
    for (; i + 4 <= n; i += 4)
    {
      const __m128 b1 = _mm_loadu_ps(w1 + i), b2 = _mm_loadu_ps(w2 + i);
      const __m128 b0 = _mm_sub_ps(_mm_sub_ps(one, b1), b2);
      const __m128 x = dot(b0, b1, b2, x0, x1, x2);
      const __m128 y = dot(b0, b1, b2, y0, y1, y2);
      const __m128 z = dot(b0, b1, b2, z0, z1, z2);
      const __m128 inv = _mm_div_ps(one, _mm_sqrt_ps(_mm_max_ps(dot(x, y, z, x, y, z), tiny)));
      _mm_storeu_ps(nx + i, _mm_mul_ps(x, inv));
      _mm_storeu_ps(ny + i, _mm_mul_ps(y, inv));
      _mm_storeu_ps(nz + i, _mm_mul_ps(z, inv));
    }
#endif
    for (; i < n; ++i)
    {
      const float b1 = w1[i], b2 = w2[i], b0 = 1.0f - b1 - b2;
      const float x = b0 * n0[0] + b1 * n1[0] + b2 * n2[0];
      const float y = b0 * n0[1] + b1 * n1[1] + b2 * n2[1];
      const float z = b0 * n0[2] + b1 * n1[2] + b2 * n2[2];
      const float inv = 1.0f / std::sqrt(std::max(x * x + y * y + z * z, 1e-30f));
      nx[i] = x * inv;
      ny[i] = y * inv;
      nz[i] = z * inv;
    }
  }

  /// The face normal of triangle t (length: twice its area).
  void FaceNormal(const vtkIdType* t, float face[3]) const
  {
    const double* p0 = this->Points + 3 * t[0];
    const double* p1 = this->Points + 3 * t[1];
    const double* p2 = this->Points + 3 * t[2];
    const double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    const double e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
    face[0] = static_cast<float>(e1[1] * e2[2] - e1[2] * e2[1]);
    face[1] = static_cast<float>(e1[2] * e2[0] - e1[0] * e2[2]);
    face[2] = static_cast<float>(e1[0] * e2[1] - e1[1] * e2[0]);
  }

  /// The vector field interpolated, projected into the plane of the normals.
  void InterpolateVectors(const vtkIdType* t,
    vtkIdType n,
    const float* w1,
    const float* w2,
    const Run& out) const
  {
    for (int k = 0; k < 3; ++k)
    {
      const float v0 = this->PointVectors[3 * t[0] + k];
      const float v1 = this->PointVectors[3 * t[1] + k];
      const float v2 = this->PointVectors[3 * t[2] + k];
      for (vtkIdType i = 0; i < n; ++i)
      {
        out.Vectors[k][i] = (1.0f - w1[i] - w2[i]) * v0 + w1[i] * v1 + w2[i] * v2;
      }
    }
    if (!this->ProjectVectors)
    {
      return;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      const float vn = out.Vectors[0][i] * out.Normals[0][i] +
        out.Vectors[1][i] * out.Normals[1][i] + out.Vectors[2][i] * out.Normals[2][i];
      for (int k = 0; k < 3; ++k)
      {
        out.Vectors[k][i] -= vn * out.Normals[k][i];
      }
    }
  }

  /// The point colours interpolated, rounded (RGB gets an opaque alpha).
  void InterpolateColors(const vtkIdType* t,
    vtkIdType n,
    const float* w1,
    const float* w2,
    unsigned char* rgba) const
  {
    const int nc = this->ColorComponents;
    for (int k = 0; k < nc; ++k)
    {
      const float c0 = this->PointColors[nc * t[0] + k];
      const float c1 = this->PointColors[nc * t[1] + k];
      const float c2 = this->PointColors[nc * t[2] + k];
      for (vtkIdType i = 0; i < n; ++i)
      {
        const float c = (1.0f - w1[i] - w2[i]) * c0 + w1[i] * c1 + w2[i] * c2;
        rgba[4 * i + k] = static_cast<unsigned char>(std::min(255.0f, c + 0.5f));
      }
    }
    for (vtkIdType i = 0; nc == 3 && i < n; ++i)
    {
      rgba[4 * i + 3] = 255;
    }
  }

  /**
   * Barycentric interpolation of an array-of-structures array into n samples:
   * sample i from fragment f = order[i] (i without order), of triangle tri[f] at
   * barycentrics (w1[f], w2[f]). With triangleCells (a cell array), sample i
   * takes the tuple of the input cell triangleCells[tri[f]] instead.
   */
  template<typename T>
  static void InterpolateTuples(const T* in,
    T* out,
    int nc,
    vtkIdType n,
    const vtkIdType* trianglePointIds,
    const vtkTypeUInt32* tri,
    const float* w1,
    const float* w2,
    const vtkTypeUInt32* order,
    const vtkIdType* triangleCells)
  {
    if (triangleCells)
    {
      for (vtkIdType i = 0; i < n; ++i)
      {
        const vtkIdType f = order ? order[i] : i;
        const T* tuple = in + triangleCells[tri[f]] * nc;
        std::copy(tuple, tuple + nc, out + i * nc);
      }
      return;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType f = order ? order[i] : i;
      const vtkIdType* t = trianglePointIds + 3 * static_cast<vtkIdType>(tri[f]);
      const double b1 = w1[f], b2 = w2[f], b0 = 1.0 - b1 - b2;
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
  }

  /**
   * Interpolate samples [first, first + n) of one of the surface's other arrays
   * (copy them from the cells, for a cell array: triangleCells, see
   * vtkOFBSurface::GetArrayCells).
   */
  static bool InterpolateArray(vtkDataArray* in,
    vtkDataArray* out,
    vtkIdType first,
    vtkIdType n,
    const vtkIdType* trianglePointIds,
    const vtkTypeUInt32* tri,
    const float* w1,
    const float* w2,
    const vtkTypeUInt32* order,
    const vtkIdType* triangleCells = nullptr)
  {
    const int nc = in->GetNumberOfComponents();
    switch (in->GetDataType())
    {
      vtkTemplateMacro(InterpolateTuples(static_cast<const VTK_TT*>(in->GetVoidPointer(0)),
        static_cast<VTK_TT*>(out->GetVoidPointer(first * nc)),
        nc,
        n,
        trianglePointIds,
        tri,
        w1,
        w2,
        order,
        triangleCells));
      default:
        return false;
    }
    return true;
  }

  /// Whether InterpolateArray handles arrays of this type.
  static bool IsInterpolable(vtkDataArray* array)
  {
    switch (array->GetDataType())
    {
      vtkTemplateMacro(return true);
      default:
        return false;
    }
  }
};

#endif
