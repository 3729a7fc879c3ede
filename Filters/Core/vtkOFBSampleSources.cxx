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
#include <memory>
#include <new>
#include <type_traits>

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

/// The memory of a table (vtkOFBSampleSources::Tables: kept between re-samplings).
template<typename T>
struct TableView
{
  T* Data = nullptr;
  size_t Size = 0;
  T& operator[](size_t i) const { return this->Data[i]; }
  T* data() const { return this->Data; }
  bool empty() const { return this->Size == 0; }
};

/// Room for n values of type T in `store` (which keeps its memory between calls).
template<typename T>
TableView<T> Reserve(std::vector<char>& store, size_t n)
{
  store.resize(n * sizeof(T));
  return TableView<T>{ reinterpret_cast<T*>(store.data()), n };
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
  TableView<float> Table; // per triangle 3 corners x 4 components
  int NC;
  unsigned char Default[4];
  unsigned char* Out;

  ColorJob(const vtkOFBAttributeInterpolator& in,
    const vtkIdType* ids,
    const vtkTypeUInt32* order,
    vtkIdType nTriangles,
    std::vector<char>& store,
    unsigned char* out)
    : NC(in.ColorComponents)
    , Out(out)
  {
    std::memcpy(this->Default, in.DefaultColor, 4);
    if (!in.PointColors)
    {
      return;
    }
    this->Table = Reserve<float>(store, static_cast<size_t>(12 * nTriangles));
    const int nc = this->NC;
    vtkSMPTools::For(0,
      nTriangles,
      Chunk,
      [&](vtkIdType t0, vtkIdType t1)
      {
        for (vtkIdType t = t0; t < t1; ++t)
        {
          for (int c = 0; c < 3; ++c)
          {
            for (int k = 0; k < 4; ++k)
            {
              this->Table[12 * t + 4 * c + k] =
                k < nc ? static_cast<float>(in.PointColors[nc * ids[3 * order[t] + c] + k]) : 0.0f;
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
    unsigned char* out = this->Out;
    if (this->Table.empty())
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::memcpy(out + 4 * i, this->Default, 4);
      }
      return;
    }
    const int nc = this->NC;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* c = this->Table.data() + 12 * static_cast<size_t>(tri[i]);
      for (int k = 0; k < nc; ++k)
      {
        const float v = (1.0f - w1[i] - w2[i]) * c[k] + w1[i] * c[4 + k] + w2[i] * c[8 + k];
        out[4 * i + k] = static_cast<unsigned char>(std::min(255.0f, v + 0.5f));
      }
      if (nc == 3)
      {
        out[4 * i + 3] = 255;
      }
    }
  }
};

/**
 * The vector field interpolated and projected on the kept normals, in the
 * operations of vtkOFBAttributeInterpolator::InterpolateVectors.
 */
struct VectorJob : ResampleJob
{
  TableView<float> Table; // per triangle 3 corners x 3 components
  bool Project;
  const float* Normals;
  float* Out;

  VectorJob(const vtkOFBAttributeInterpolator& in,
    const vtkIdType* ids,
    const vtkTypeUInt32* order,
    vtkIdType nTriangles,
    std::vector<char>& store,
    const float* normals,
    float* out)
    : Project(in.ProjectVectors)
    , Normals(normals)
    , Out(out)
  {
    this->Table = Reserve<float>(store, static_cast<size_t>(9 * nTriangles));
    vtkSMPTools::For(0,
      nTriangles,
      Chunk,
      [&](vtkIdType t0, vtkIdType t1)
      {
        for (vtkIdType t = t0; t < t1; ++t)
        {
          for (int c = 0; c < 3; ++c)
          {
            std::copy_n(
              in.PointVectors + 3 * ids[3 * order[t] + c], 3, &this->Table[9 * t + 3 * c]);
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
    // Locals that alias nothing: the loop keeps them in registers.
    const float* VTK_OFB_RESTRICT table = this->Table.data();
    const float* VTK_OFB_RESTRICT normals = this->Normals;
    float* VTK_OFB_RESTRICT out = this->Out;
    const float project = this->Project ? 1.0f : 0.0f;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* c = table + 9 * static_cast<size_t>(tri[i]);
      const float b1 = w1[i], b2 = w2[i], b0 = 1.0f - b1 - b2;
      const float vx = b0 * c[0] + b1 * c[3] + b2 * c[6];
      const float vy = b0 * c[1] + b1 * c[4] + b2 * c[7];
      const float vz = b0 * c[2] + b1 * c[5] + b2 * c[8];
      const float nx = normals[3 * i], ny = normals[3 * i + 1], nz = normals[3 * i + 2];
      const float vn = project * (vx * nx + vy * ny + vz * nz);
      out[3 * i] = vx - vn * nx;
      out[3 * i + 1] = vy - vn * ny;
      out[3 * i + 2] = vz - vn * nz;
    }
  }
};

/**
 * Another point array, interpolated as vtkOFBAttributeInterpolator::InterpolateTuples
 * does, or a cell array, the tuple of each sample's triangle's cell.
 */
template<typename T>
struct TupleJob : ResampleJob
{
  TableView<T> Table; // per triangle 3 corners x NC values, or NC for a cell array
  int NC;
  bool PerCell;
  T* Out;

  TupleJob(const T* in,
    int nc,
    const vtkIdType* ids,
    const vtkTypeUInt32* order,
    const vtkIdType* cells,
    vtkIdType nTriangles,
    std::vector<char>& store,
    T* out)
    : NC(nc)
    , PerCell(cells != nullptr)
    , Out(out)
  {
    const int corners = cells ? 1 : 3;
    this->Table = Reserve<T>(store, static_cast<size_t>(corners * nc * nTriangles));
    vtkSMPTools::For(0,
      nTriangles,
      Chunk,
      [&](vtkIdType t0, vtkIdType t1)
      {
        for (vtkIdType t = t0; t < t1; ++t)
        {
          for (int c = 0; c < corners; ++c)
          {
            const vtkIdType source = cells ? cells[order[t]] : ids[3 * order[t] + c];
            std::copy_n(in + nc * source, nc, &this->Table[(corners * t + c) * nc]);
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
        std::copy(tuple, tuple + nc, this->Out + i * nc);
      }
      return;
    }
    // The common component counts with the count known to the compiler.
    switch (nc)
    {
      case 1:
        this->Interpolate<1>(begin, end, tri, w1, w2, 1);
        break;
      case 3:
        this->Interpolate<3>(begin, end, tri, w1, w2, 3);
        break;
      default:
        this->Interpolate<0>(begin, end, tri, w1, w2, nc);
        break;
    }
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
      const T* c = table + 3 * static_cast<size_t>(tri[i]) * n;
      const double b1 = w1[i], b2 = w2[i], b0 = 1.0 - b1 - b2;
      for (int k = 0; k < n; ++k)
      {
        const double v = b0 * c[k] + b1 * c[n + k] + b2 * c[2 * n + k];
        if (std::is_integral<T>::value)
        {
          out[i * n + k] = static_cast<T>(std::llround(v));
        }
        else
        {
          out[i * n + k] = static_cast<T>(v);
        }
      }
    }
  }
};

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
    key.Backend != this->Kept.Backend || !std::equal(key.Sizes, key.Sizes + 3, this->Kept.Sizes))
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
void vtkOFBSampleSources::Keep(vtkOFB* output,
  vtkPolyData* input,
  Key& key,
  const vtkOFBSurface& surface)
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
  this->SurfaceTriangles = surface.Triangles;
  this->TriangleCells = surface.TriangleCells;
  // The triangles renumbered in the order the samples first reach them, so that
  // the tables of a re-sampling (a record per triangle) are read in about the
  // order they are laid out: the input's own order may be anything.
  const vtkIdType nTriangles = surface.GetNumberOfTriangles();
  std::vector<vtkTypeUInt32> renumbered(static_cast<size_t>(nTriangles), VTK_TYPE_UINT32_MAX);
  this->Order.clear();
  for (vtkTypeUInt32& t : this->Triangles)
  {
    if (renumbered[t] == VTK_TYPE_UINT32_MAX)
    {
      renumbered[t] = static_cast<vtkTypeUInt32>(this->Order.size());
      this->Order.push_back(t);
    }
    t = renumbered[t];
  }
}

//------------------------------------------------------------------------------
bool vtkOFBSampleSources::HasTriangleCells() const
{
  return !this->TriangleCells.empty();
}

//------------------------------------------------------------------------------
std::vector<char>& vtkOFBSampleSources::Table(size_t k)
{
  if (this->Tables.size() <= k)
  {
    this->Tables.resize(k + 1);
  }
  return this->Tables[k];
}

//------------------------------------------------------------------------------
void vtkOFBSampleSources::Reset()
{
  this->Structure = nullptr;
  this->Normals = nullptr;
  this->Kept = Key();
  std::vector<vtkIdType>().swap(this->SurfaceTriangles);
  std::vector<vtkIdType>().swap(this->TriangleCells);
  std::vector<vtkTypeUInt32>().swap(this->Order);
  this->Tables.clear();
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
  // The arrays of the previous output that the pipeline recycled are taken before
  // the structure is set (vtkOFB::ShallowCopy lets the spare arrays go): a
  // re-sampling writes over the memory of the last one.
  const vtkIdType n = this->Structure->GetNumberOfSamples();
  if (n != static_cast<vtkIdType>(this->Triangles.size()))
  {
    return false;
  }
  vtkSmartPointer<vtkUnsignedCharArray> colors =
    vtkUnsignedCharArray::SafeDownCast(vtkOFBSampleArrays::NewArray(
      output, vtkOFB::ColorsArrayName(), VTK_UNSIGNED_CHAR, nullptr, 4, n));
  vtkSmartPointer<vtkFloatArray> vectors;
  if (surface.Vectors)
  {
    vectors = vtkFloatArray::SafeDownCast(
      vtkOFBSampleArrays::NewArray(output, surface.Vectors->GetName(), VTK_FLOAT, nullptr, 3, n));
  }
  std::vector<vtkSmartPointer<vtkDataArray>> others;
  for (const auto& in : surface.Arrays)
  {
    others.push_back(vtkOFBAttributeInterpolator::IsInterpolable(in)
        ? vtkOFBSampleArrays::NewArray(
            output, in->GetName(), in->GetDataType(), in, in->GetNumberOfComponents(), n)
        : nullptr);
  }
  output->ShallowCopy(this->Structure);
  const vtkIdType* ids = this->SurfaceTriangles.data();
  // The tables have a record per triangle that a sample lies on, in the order of
  // this->Order.
  const vtkIdType nTriangles = static_cast<vtkIdType>(this->Order.size());
  const vtkTypeUInt32* order = this->Order.data();

  // One job per array, each with a table of its values at the corners of every
  // triangle (or of its cell, for a cell array), so that a sample reads one record
  // of its triangle; the samples go in chunks, every job over a chunk in turn while
  // its sources are in cache.
  std::vector<std::unique_ptr<ResampleJob>> jobs;
  const vtkOFBAttributeInterpolator interpolator(surface);
  jobs.emplace_back(
    new ColorJob(interpolator, ids, order, nTriangles, this->Table(0), colors->GetPointer(0)));
  if (vectors && interpolator.PointVectors)
  {
    jobs.emplace_back(new VectorJob(interpolator,
      ids,
      order,
      nTriangles,
      this->Table(1),
      vtkFloatArray::SafeDownCast(this->Normals)->GetPointer(0),
      vectors->GetPointer(0)));
  }
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
    vtkDataArray* out = others[k];
    if (!out)
    {
      continue;
    }
    const bool perCell = k < surface.ArraysPerCell.size() && surface.ArraysPerCell[k];
    const vtkIdType* cells = perCell ? this->TriangleCells.data() : nullptr;
    switch (in->GetDataType())
    {
      vtkTemplateMacro(
        jobs.emplace_back(new TupleJob<VTK_TT>(static_cast<const VTK_TT*>(in->GetVoidPointer(0)),
          in->GetNumberOfComponents(),
          ids,
          order,
          cells,
          nTriangles,
          this->Table(2 + k),
          static_cast<VTK_TT*>(out->GetVoidPointer(0)))));
    }
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
  const vtkTypeUInt32* tri = this->Triangles.data();
  const float* w1 = this->W1.data();
  const float* w2 = this->W2.data();
  vtkSMPTools::For(0,
    n,
    Chunk,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (const auto& job : jobs)
      {
        job->Run(begin, end, tri, w1, w2);
      }
    });
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
