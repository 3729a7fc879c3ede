#include "vtkOFBTextureProjector.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkOFBFanTriangles.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBPyramidResampler.h" // vtkOFBSampleNormals
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkOFBTextureProjector);

namespace
{
/// Barycentric coordinates of the point of triangle (a, b, c) closest to p (C. Ericson,
/// Real-Time Collision Detection, 5.1.5).
glm::dvec3 ClosestOnTriangle(const glm::dvec3& p,
  const glm::dvec3& a,
  const glm::dvec3& b,
  const glm::dvec3& c)
{
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return { 1.0, 0.0, 0.0 };
  }
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return { 0.0, 1.0, 0.0 };
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double v = d1 / (d1 - d3);
    return { 1.0 - v, v, 0.0 };
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return { 0.0, 0.0, 1.0 };
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double w = d2 / (d2 - d6);
    return { 1.0 - w, 0.0, w };
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return { 0.0, 1.0 - w, w };
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return { 1.0 - v - w, v, w };
}

/// The mesh's triangles (fans of its polygons): corners, positions and unit normals.
struct Triangles
{
  std::vector<vtkIdType> Corners;
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Normals;

  void Build(vtkPolyData* mesh)
  {
    vtkOFBForEachFanTriangle(mesh,
      [this](vtkIdType, const vtkIdType corner[3], const glm::dvec3 x[3])
      {
        const glm::dvec3 n = glm::cross(x[1] - x[0], x[2] - x[0]);
        const double length = glm::length(n);
        if (!(length > 0.0) || !std::isfinite(length))
        {
          return; // no area, or not finite: nothing to project
        }
        for (int c = 0; c < 3; ++c)
        {
          this->Corners.push_back(corner[c]);
          this->Points.push_back(x[c]);
        }
        this->Normals.push_back(n / length);
      });
  }
  vtkIdType Size() const { return static_cast<vtkIdType>(this->Normals.size()); }
};

/// A texel value as a fraction of the type's range, times 255: bytes as they are, 16-bit
/// integers scaled by 255 / 65535, floats clamped to [0, 1] (NaN as 0) and scaled by 255.
inline double Texel255(unsigned char v)
{
  return v;
}
inline double Texel255(unsigned short v)
{
  return v * (255.0 / 65535.0);
}
inline double Texel255(float v)
{
  return v > 0.0f ? (v < 1.0f ? 255.0 * v : 255.0) : 0.0;
}

/// A texture of unsigned char, unsigned short or float texels (1 to 4 components) read
/// as RGBA in [0, 255].
template<typename T>
struct Texture
{
  const T* Texels = nullptr;
  int Components = 0;
  int Width = 0;
  int Height = 0;
  bool Repeat = true;
  bool Interpolate = true;

  int Wrap(int i, int n) const
  {
    return this->Repeat ? ((i % n) + n) % n : std::min(std::max(i, 0), n - 1);
  }
  void Texel(int i, int j, double rgba[4]) const
  {
    const T* t = this->Texels + this->Components * (static_cast<vtkIdType>(j) * this->Width + i);
    const bool grey = this->Components < 3;
    for (int c = 0; c < 3; ++c)
    {
      rgba[c] = Texel255(t[grey ? 0 : c]);
    }
    rgba[3] =
      this->Components == 2 || this->Components == 4 ? Texel255(t[this->Components - 1]) : 255.0;
  }
  /// The texture at (u, v): the nearest texel, or the bilinear mean of four.
  void Lookup(double u, double v, double rgba[4]) const
  {
    double x = u * this->Width - (this->Interpolate ? 0.5 : 0.0);
    double y = v * this->Height - (this->Interpolate ? 0.5 : 0.0);
    // Brought into range before they become integers: a period of the texture, or just
    // past its edges.
    x = this->Repeat ? std::fmod(x, this->Width) : std::min(std::max(x, -1.0), 1.0 * this->Width);
    y = this->Repeat ? std::fmod(y, this->Height) : std::min(std::max(y, -1.0), 1.0 * this->Height);
    if (!(std::isfinite(x) && std::isfinite(y)))
    {
      x = y = 0.0; // a non-finite coordinate (fmod, max and min keep NaN) has no texel
    }
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    if (!this->Interpolate)
    {
      this->Texel(this->Wrap(i, this->Width), this->Wrap(j, this->Height), rgba);
      return;
    }
    const double tx = x - i, ty = y - j;
    double corner[4][4];
    for (int k = 0; k < 4; ++k)
    {
      this->Texel(
        this->Wrap(i + (k & 1), this->Width), this->Wrap(j + (k >> 1), this->Height), corner[k]);
    }
    for (int c = 0; c < 4; ++c)
    {
      const double bottom = corner[0][c] + tx * (corner[1][c] - corner[0][c]);
      const double top = corner[2][c] + tx * (corner[3][c] - corner[2][c]);
      rgba[c] = bottom + ty * (top - bottom);
    }
  }
};

/// Sample positions as a glm vector.
glm::dvec3 SamplePosition(vtkOFB* ofb, vtkIdType i)
{
  double x[3];
  ofb->GetSamplePosition(i, x);
  return glm::dvec3(x[0], x[1], x[2]);
}

/// None: no triangle within reach of the sample.
constexpr vtkTypeUInt64 NoTriangle = std::numeric_limits<vtkTypeUInt64>::max();

/**
 * Each sample's closest triangle within `reach` that it does not face away from: the
 * smallest (squared distance, triangle) pair, packed in 64 bits for an atomic minimum
 * (NoTriangle where none), so the same with any number of threads.
 */
void FindClosestTriangles(vtkOFB* input,
  const Triangles& triangles,
  double reach,
  std::vector<std::atomic<vtkTypeUInt64>>& best)
{
  const vtkIdType n = input->GetNumberOfSamples();
  vtkDataArray* normals = vtkOFBSampleNormals(input->GetSampleData());
  auto* floatNormals = vtkFloatArray::FastDownCast(normals);
  const float* sn =
    floatNormals && normals->GetNumberOfTuples() == n ? floatNormals->GetPointer(0) : nullptr;
  vtkSMPTools::For(0,
    n,
    65536,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        best[i].store(NoTriangle, std::memory_order_relaxed);
      }
    });
  vtkSMPTools::For(0,
    triangles.Size(),
    256,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        const glm::dvec3* x = &triangles.Points[3 * t];
        const glm::dvec3 centre = (x[0] + x[1] + x[2]) / 3.0;
        const double radius = std::sqrt(std::max({ glm::dot(x[0] - centre, x[0] - centre),
                                glm::dot(x[1] - centre, x[1] - centre),
                                glm::dot(x[2] - centre, x[2] - centre) })) +
          reach;
        const double c[3] = { centre.x, centre.y, centre.z };
        input->ForEachSampleInSphere(c,
          radius,
          [&](vtkIdType i, double)
          {
            if (sn &&
              glm::dot(glm::dvec3(sn[3 * i], sn[3 * i + 1], sn[3 * i + 2]), triangles.Normals[t]) <
                0.0)
            {
              return;
            }
            const glm::dvec3 p = SamplePosition(input, i);
            const glm::dvec3 b = ClosestOnTriangle(p, x[0], x[1], x[2]);
            const glm::dvec3 q = b.x * x[0] + b.y * x[1] + b.z * x[2];
            const float d2 = static_cast<float>(glm::dot(p - q, p - q));
            if (!(d2 <= reach * reach))
            {
              return;
            }
            vtkTypeUInt32 bits;
            std::memcpy(&bits, &d2, 4); // non-negative floats order as their bits
            const vtkTypeUInt64 key = (vtkTypeUInt64(bits) << 32) | vtkTypeUInt64(t);
            vtkTypeUInt64 seen = best[i].load(std::memory_order_relaxed);
            while (key < seen && !best[i].compare_exchange_weak(seen, key))
            {
            }
          });
      }
    });
}

/**
 * Lay the texture at each reached sample's closest point over its colour in `rgba`;
 * the number of samples reached.
 */
template<typename T>
vtkIdType ApplyTexture(vtkOFB* input,
  const Triangles& triangles,
  vtkDataArray* tcoords,
  const Texture<T>& texture,
  double opacity,
  const std::vector<std::atomic<vtkTypeUInt64>>& best,
  unsigned char* rgba)
{
  const vtkIdType n = input->GetNumberOfSamples();
  std::atomic<vtkIdType> projected(0);
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType first, vtkIdType last)
    {
      vtkIdType count = 0;
      for (vtkIdType i = first; i < last; ++i)
      {
        const vtkTypeUInt64 key = best[i].load(std::memory_order_relaxed);
        if (key == NoTriangle)
        {
          continue;
        }
        const vtkIdType t = static_cast<vtkIdType>(key & 0xffffffffu);
        const glm::dvec3* x = &triangles.Points[3 * t];
        const glm::dvec3 b = ClosestOnTriangle(SamplePosition(input, i), x[0], x[1], x[2]);
        double uv[2] = { 0.0, 0.0 };
        for (int c = 0; c < 3; ++c)
        {
          for (int k = 0; k < 2; ++k)
          {
            uv[k] += b[c] * tcoords->GetComponent(triangles.Corners[3 * t + c], k);
          }
        }
        if (!std::isfinite(uv[0]) || !std::isfinite(uv[1]))
        {
          continue;
        }
        double texel[4];
        texture.Lookup(uv[0], uv[1], texel);
        unsigned char* s = rgba + 4 * i;
        const double a = opacity * texel[3] / 255.0;
        for (int c = 0; c < 3; ++c)
        {
          s[c] = static_cast<unsigned char>(std::lround(s[c] + a * (texel[c] - s[c])));
        }
        s[3] = static_cast<unsigned char>(std::lround(s[3] + a * (255.0 - s[3])));
        ++count;
      }
      projected += count;
    });
  return projected;
}
}

//------------------------------------------------------------------------------
vtkOFBTextureProjector::vtkOFBTextureProjector()
{
  this->SetNumberOfInputPorts(3);
}

//------------------------------------------------------------------------------
vtkOFBTextureProjector::~vtkOFBTextureProjector() = default;

//------------------------------------------------------------------------------
void vtkOFBTextureProjector::SetMeshConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkOFBTextureProjector::SetMeshData(vtkPolyData* mesh)
{
  this->SetInputDataInternal(1, mesh);
}

//------------------------------------------------------------------------------
void vtkOFBTextureProjector::SetTextureConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(2, output);
}

//------------------------------------------------------------------------------
void vtkOFBTextureProjector::SetTextureData(vtkImageData* image)
{
  this->SetInputDataInternal(2, image);
}

//------------------------------------------------------------------------------
int vtkOFBTextureProjector::FillInputPortInformation(int port, vtkInformation* info)
{
  const char* types[3] = { "vtkOFB", "vtkPolyData", "vtkImageData" };
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), types[port]);
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBTextureProjector::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkOFB* input = vtkOFB::GetData(inputVector[0]);
  vtkPolyData* mesh = vtkPolyData::GetData(inputVector[1]);
  vtkImageData* image = vtkImageData::GetData(inputVector[2]);
  vtkOFB* output = vtkOFB::GetData(outputVector);
  this->NumberOfProjectedSamples = 0;
  if (!output)
  {
    return 0;
  }
  output->Initialize();
  vtkDataArray* tcoords = mesh ? mesh->GetPointData()->GetTCoords() : nullptr;
  vtkDataArray* texels = image ? image->GetPointData()->GetScalars() : nullptr;
  const int texelType = texels ? texels->GetDataType() : 0;
  vtkDataArray* colors =
    input ? input->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()) : nullptr;
  if (!input || input->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("The input OFB is missing or has no samples: empty output.");
    return 1;
  }
  std::string error;
  if (mesh && !vtkOFBCheckCellPointIds(mesh, error))
  {
    vtkErrorMacro("The mesh (input port 1) is invalid: " << error << ".");
    return 1;
  }
  if (!tcoords || tcoords->GetNumberOfComponents() < 2 ||
    tcoords->GetNumberOfTuples() != mesh->GetNumberOfPoints())
  {
    vtkErrorMacro("No mesh with texture coordinates (2 components, one pair a point) on port 1.");
    return 1;
  }
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (!texels || texels->GetNumberOfComponents() < 1 || texels->GetNumberOfComponents() > 4 ||
    dims[2] != 1 || texels->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1] ||
    dims[0] < 1 || dims[1] < 1 ||
    (texelType != VTK_UNSIGNED_CHAR && texelType != VTK_UNSIGNED_SHORT && texelType != VTK_FLOAT))
  {
    vtkErrorMacro("No texture on port 2: a 2-D image of unsigned char, unsigned short or float "
                  "scalars (grey, grey and alpha, RGB or RGBA)"
      << (texels ? std::string(", not ") + texels->GetDataTypeAsString() + " with " +
               std::to_string(texels->GetNumberOfComponents()) + " components"
                 : std::string())
      << ".");
    return 1;
  }
  if (colors &&
    (!vtkUnsignedCharArray::SafeDownCast(colors) || colors->GetNumberOfComponents() != 4 ||
      colors->GetNumberOfTuples() != input->GetNumberOfSamples()))
  {
    vtkErrorMacro("The OFB's \"Colors\" are not RGBA bytes, one a sample.");
    return 1;
  }
  if (!(this->MaximumDistance > 0.0) || !std::isfinite(this->MaximumDistance))
  {
    vtkErrorMacro("MaximumDistance " << this->MaximumDistance << " is not positive and finite.");
    return 1;
  }

  // The output: the input's arrays shared, new colours.
  output->ShallowCopy(input);
  const vtkIdType n = input->GetNumberOfSamples();
  auto out = vtkSmartPointer<vtkUnsignedCharArray>::New();
  out->SetName(vtkOFB::ColorsArrayName());
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(n);
  if (colors)
  {
    out->DeepCopy(colors);
  }
  else
  {
    out->Fill(255);
  }
  vtkPointData* pd = output->GetSampleData();
  pd->RemoveArray(vtkOFB::ColorsArrayName());
  pd->AddArray(out);
  if (!colors || input->GetSampleData()->GetScalars() == colors)
  {
    pd->SetScalars(out);
  }

  // Each sample's closest triangle within reach, then the texture there.
  Triangles triangles;
  triangles.Build(mesh);
  std::vector<std::atomic<vtkTypeUInt64>> best(static_cast<size_t>(n));
  FindClosestTriangles(input, triangles, this->MaximumDistance * input->GetCellSize(), best);
  this->UpdateProgress(0.7);
  auto project = [&](auto* first)
  {
    using T = std::remove_const_t<std::remove_pointer_t<decltype(first)>>;
    const Texture<T> texture{ first,
      texels->GetNumberOfComponents(),
      dims[0],
      dims[1],
      this->RepeatTexture,
      this->InterpolateTexture };
    return ApplyTexture(
      input, triangles, tcoords, texture, this->Opacity, best, out->GetPointer(0));
  };
  const void* first = texels->GetVoidPointer(0);
  this->NumberOfProjectedSamples = texelType == VTK_UNSIGNED_CHAR
    ? project(static_cast<const unsigned char*>(first))
    : (texelType == VTK_UNSIGNED_SHORT ? project(static_cast<const unsigned short*>(first))
                                       : project(static_cast<const float*>(first)));
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBTextureProjector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumDistance: " << this->MaximumDistance << " cells\n";
  os << indent << "InterpolateTexture: " << (this->InterpolateTexture ? "On" : "Off") << "\n";
  os << indent << "RepeatTexture: " << (this->RepeatTexture ? "On" : "Off") << "\n";
  os << indent << "Opacity: " << this->Opacity << "\n";
  os << indent << "NumberOfProjectedSamples: " << this->NumberOfProjectedSamples << "\n";
}
