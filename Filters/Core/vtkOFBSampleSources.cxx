#include "vtkOFBSampleSources.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBAttributeInterpolator.h"
#include "vtkOFBSampleArrays.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstring>
#include <new>

vtkStandardNewMacro(vtkOFBSampleSources);

namespace
{
/// Samples per chunk of the parallel loops.
constexpr vtkIdType Chunk = 16384;

/// Bytes per chunk of the parallel hash.
constexpr vtkIdType HashChunk = 1 << 16;

/// A 64-bit mix (the finalizer of MurmurHash3).
inline uint64_t Mix(uint64_t h)
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

/// Hash of n bytes, 8 at a time (the tail zero-padded).
uint64_t HashBytes(const unsigned char* p, vtkIdType n, uint64_t seed)
{
  uint64_t h = seed ^ (static_cast<uint64_t>(n) * 0x9e3779b97f4a7c15ULL);
  vtkIdType i = 0;
  for (; i + 8 <= n; i += 8)
  {
    uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = (h ^ Mix(w + 0x9e3779b97f4a7c15ULL)) * 0x100000001b3ULL;
  }
  uint64_t tail = 0;
  std::memcpy(&tail, p + i, static_cast<size_t>(n - i));
  return Mix(h ^ Mix(tail + static_cast<uint64_t>(n - i)));
}

/// Hash of the values of an array (in parallel over chunks, combined in order).
uint64_t HashArray(vtkDataArray* array, uint64_t seed)
{
  if (!array)
  {
    return Mix(seed + 1);
  }
  const vtkIdType nValues = array->GetNumberOfValues();
  std::vector<double> copy; // arrays of another layout hashed through doubles
  const unsigned char* bytes = nullptr;
  vtkIdType n = 0;
  if (array->HasStandardMemoryLayout())
  {
    bytes = static_cast<const unsigned char*>(array->GetVoidPointer(0));
    n = nValues * array->GetDataTypeSize();
  }
  else
  {
    copy.resize(static_cast<size_t>(nValues));
    for (vtkIdType i = 0; i < nValues; ++i)
    {
      copy[i] = array->GetVariantValue(i).ToDouble();
    }
    bytes = reinterpret_cast<const unsigned char*>(copy.data());
    n = nValues * static_cast<vtkIdType>(sizeof(double));
  }
  const vtkIdType nChunks = (n + HashChunk - 1) / HashChunk;
  std::vector<uint64_t> hashes(static_cast<size_t>(nChunks));
  vtkSMPTools::For(0,
    nChunks,
    1,
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        const vtkIdType first = c * HashChunk;
        hashes[c] = HashBytes(bytes + first, std::min(HashChunk, n - first), c);
      }
    });
  uint64_t h = Mix(seed ^ static_cast<uint64_t>(array->GetDataType()) ^
    (static_cast<uint64_t>(array->GetNumberOfComponents()) << 8));
  for (const uint64_t c : hashes)
  {
    h = Mix(h ^ c);
  }
  return Mix(h ^ static_cast<uint64_t>(n));
}

/// The arrays of a geometry: points, offsets and connectivity of polygons and strips, normals.
void GeometryArrays(vtkPolyData* input, vtkDataArray* arrays[6])
{
  arrays[0] = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  arrays[1] = input->GetPolys()->GetOffsetsArray();
  arrays[2] = input->GetPolys()->GetConnectivityArray();
  arrays[3] = input->GetStrips()->GetOffsetsArray();
  arrays[4] = input->GetStrips()->GetConnectivityArray();
  arrays[5] = input->GetPointData()->GetNormals();
}
}

//------------------------------------------------------------------------------
vtkOFBSampleSources::vtkOFBSampleSources() = default;

//------------------------------------------------------------------------------
vtkOFBSampleSources::~vtkOFBSampleSources() = default;

//------------------------------------------------------------------------------
vtkOFBSampleSources::Key vtkOFBSampleSources::MakeKey(vtkPolyData* input,
  int resolution,
  const void* backend)
{
  Key key;
  vtkDataArray* arrays[6];
  GeometryArrays(input, arrays);
  for (int i = 0; i < 6; ++i)
  {
    key.Arrays[i] = arrays[i];
    key.Times[i] = arrays[i] ? arrays[i]->GetMTime() : 0;
  }
  key.Sizes[0] = input->GetNumberOfPoints();
  key.Sizes[1] = input->GetNumberOfPolys();
  key.Sizes[2] = input->GetNumberOfStrips();
  key.Resolution = resolution;
  key.Backend = backend;
  return key;
}

//------------------------------------------------------------------------------
uint64_t vtkOFBSampleSources::HashGeometry(vtkPolyData* input)
{
  vtkDataArray* arrays[6];
  GeometryArrays(input, arrays);
  uint64_t h = 0x243f6a8885a308d3ULL;
  for (int i = 0; i < 6; ++i)
  {
    h = Mix(h ^ HashArray(arrays[i], static_cast<uint64_t>(i)));
  }
  return h;
}

//------------------------------------------------------------------------------
bool vtkOFBSampleSources::Matches(vtkPolyData* input, Key& key)
{
  if (!this->Structure || key.Resolution != this->Kept.Resolution ||
    key.Backend != this->Kept.Backend ||
    !std::equal(key.Sizes, key.Sizes + 3, this->Kept.Sizes))
  {
    return false;
  }
  if (std::equal(key.Arrays, key.Arrays + 6, this->Kept.Arrays) &&
    std::equal(key.Times, key.Times + 6, this->Kept.Times))
  {
    key.Hash = this->Kept.Hash;
    return true;
  }
  key.Hash = vtkOFBSampleSources::HashGeometry(input);
  return key.Hash == this->Kept.Hash;
}

//------------------------------------------------------------------------------
bool vtkOFBSampleSources::RecordSamples(vtkIdType n)
{
  try
  {
    this->Triangles.resize(static_cast<size_t>(n));
    this->W1.resize(static_cast<size_t>(n));
    this->W2.resize(static_cast<size_t>(n));
  }
  catch (const std::bad_alloc&)
  {
    this->Reset();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBSampleSources::Keep(vtkOFB* output, vtkPolyData* input, Key& key)
{
  if (static_cast<vtkIdType>(this->Triangles.size()) != output->GetNumberOfSamples())
  {
    this->Reset();
    return;
  }
  if (key.Hash == 0)
  {
    key.Hash = vtkOFBSampleSources::HashGeometry(input);
  }
  this->Kept = key;
  this->Structure = vtkSmartPointer<vtkOFB>::New();
  this->Structure->ShallowCopy(output); // its own sample data: cleared below, not output's
  this->Normals = output->GetSampleData()->GetNormals();
  this->Structure->GetSampleData()->Initialize();
}

//------------------------------------------------------------------------------
void vtkOFBSampleSources::Reset()
{
  this->Structure = nullptr;
  this->Normals = nullptr;
  this->Kept = Key();
  std::vector<vtkTypeUInt32>().swap(this->Triangles);
  std::vector<float>().swap(this->W1);
  std::vector<float>().swap(this->W2);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBSampleSources::GetSourceBytes() const
{
  return static_cast<vtkIdType>(
    this->Triangles.size() * sizeof(vtkTypeUInt32) + 2 * this->W1.size() * sizeof(float));
}

//------------------------------------------------------------------------------
bool vtkOFBSampleSources::Resample(const vtkOFBSurface& surface, vtkOFB* output)
{
  if (!this->Structure || !this->Normals)
  {
    return false;
  }
  output->ShallowCopy(this->Structure);
  const vtkIdType n = output->GetNumberOfSamples();
  if (n != static_cast<vtkIdType>(this->Triangles.size()))
  {
    return false;
  }
  const vtkTypeUInt32* tri = this->Triangles.data();
  const float* w1 = this->W1.data();
  const float* w2 = this->W2.data();
  const vtkIdType* ids = surface.Triangles.data();
  const float* normals = vtkFloatArray::SafeDownCast(this->Normals)->GetPointer(0);

  // Colours: the input's point colours interpolated as the backends do, else DefaultColor.
  vtkSmartPointer<vtkUnsignedCharArray> colors =
    vtkUnsignedCharArray::SafeDownCast(vtkOFBSampleArrays::NewArray(
    output, vtkOFB::ColorsArrayName(), VTK_UNSIGNED_CHAR, nullptr, 4, n));
  unsigned char* rgba = colors->GetPointer(0);
  const vtkOFBAttributeInterpolator interpolator(surface);
  vtkSMPTools::For(0,
    n,
    Chunk,
    [&](vtkIdType begin, vtkIdType end)
    {
      if (!interpolator.PointColors)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          std::memcpy(rgba + 4 * i, interpolator.DefaultColor, 4);
        }
        return;
      }
      for (vtkIdType i = begin; i < end; ++i)
      {
        interpolator.InterpolateColors(ids + 3 * tri[i], 1, w1 + i, w2 + i, rgba + 4 * i);
      }
    });

  // The vector field: interpolated and projected on the kept normals, in the
  // operations of vtkOFBAttributeInterpolator::InterpolateVectors.
  vtkSmartPointer<vtkFloatArray> vectors;
  if (interpolator.PointVectors)
  {
    vectors = vtkFloatArray::SafeDownCast(vtkOFBSampleArrays::NewArray(
      output, surface.Vectors->GetName(), VTK_FLOAT, nullptr, 3, n));
    float* out = vectors->GetPointer(0);
    const float* in = interpolator.PointVectors;
    const bool project = interpolator.ProjectVectors;
    vtkSMPTools::For(0,
      n,
      Chunk,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const vtkIdType* t = ids + 3 * tri[i];
          const float* v0 = in + 3 * t[0];
          const float* v1 = in + 3 * t[1];
          const float* v2 = in + 3 * t[2];
          const float b1 = w1[i], b2 = w2[i];
          float v[3];
          for (int k = 0; k < 3; ++k)
          {
            v[k] = (1.0f - b1 - b2) * v0[k] + b1 * v1[k] + b2 * v2[k];
          }
          if (project)
          {
            const float* nn = normals + 3 * i;
            const float vn = v[0] * nn[0] + v[1] * nn[1] + v[2] * nn[2];
            for (int k = 0; k < 3; ++k)
            {
              v[k] -= vn * nn[k];
            }
          }
          std::copy(v, v + 3, out + 3 * i);
        }
      });
  }

  // The other point and cell arrays, as vtkOFBSamplerBackend::InterpolateAttributes.
  vtkPointData* sampleData = output->GetSampleData();
  sampleData->SetScalars(colors);
  sampleData->SetNormals(this->Normals);
  if (vectors)
  {
    sampleData->SetVectors(vectors);
  }
  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    vtkDataArray* in = surface.Arrays[k];
    if (!vtkOFBAttributeInterpolator::IsInterpolable(in))
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> out = vtkOFBSampleArrays::NewArray(
      output, in->GetName(), in->GetDataType(), in, in->GetNumberOfComponents(), n);
    const vtkIdType* cells = surface.GetArrayCells(k);
    vtkSMPTools::For(0,
      n,
      Chunk,
      [&](vtkIdType begin, vtkIdType end)
      {
        vtkOFBAttributeInterpolator::InterpolateArray(
          in, out, begin, end - begin, ids, tri + begin, w1 + begin, w2 + begin, nullptr, cells);
      });
    if (static_cast<int>(k) == surface.TCoordsIndex)
    {
      sampleData->SetTCoords(out);
    }
    else if (static_cast<int>(k) == surface.CellVectorsIndex)
    {
      sampleData->SetVectors(out);
    }
    else
    {
      sampleData->AddArray(out);
    }
  }
  output->MarkAllSamplesModified();
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBSampleSources::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Samples: " << this->Triangles.size() << "\n";
  os << indent << "SourceBytes: " << this->GetSourceBytes() << "\n";
  os << indent << "HasBuild: " << (this->HasBuild() ? "yes" : "no") << "\n";
}
