#include "vtkOFBSampleSources.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBAttributeInterpolator.h"
#include "vtkOFBSampleArrays.h"
#include "vtkOFBSampleSourcesJobs.h"
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

vtkStandardNewMacro(vtkOFBSampleSources);

using vtkofb::ColorJob;
using vtkofb::ResampleJob;
using vtkofb::TupleJob;
using vtkofb::VectorJob;

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
  // The triangles renumbered in the order the samples first reach them, so that
  // the tables of a re-sampling (a record per triangle) are read in about the
  // order they are laid out: the input's own order may be anything. Their point
  // ids and cells are kept in that order, read in sequence when the tables are
  // filled.
  const vtkIdType nTriangles = surface.GetNumberOfTriangles();
  std::vector<vtkTypeUInt32> renumbered(static_cast<size_t>(nTriangles), VTK_TYPE_UINT32_MAX);
  std::vector<vtkTypeUInt32> order;
  for (vtkTypeUInt32& t : this->Triangles)
  {
    if (renumbered[t] == VTK_TYPE_UINT32_MAX)
    {
      renumbered[t] = static_cast<vtkTypeUInt32>(order.size());
      order.push_back(t);
    }
    t = renumbered[t];
  }
  this->Corners.resize(3 * order.size());
  this->Cells.resize(surface.TriangleCells.empty() ? 0 : order.size());
  for (size_t t = 0; t < order.size(); ++t)
  {
    std::copy_n(&surface.Triangles[3 * static_cast<size_t>(order[t])], 3, &this->Corners[3 * t]);
    if (!this->Cells.empty())
    {
      this->Cells[t] = surface.TriangleCells[order[t]];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkOFBSampleSources::HasTriangleCells() const
{
  return !this->Cells.empty();
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
  std::vector<vtkIdType>().swap(this->Corners);
  std::vector<vtkIdType>().swap(this->Cells);
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
  // The tables have a record per triangle that a sample lies on, in the order of
  // this->Corners.
  const vtkIdType* ids = this->Corners.data();
  const vtkIdType nTriangles = static_cast<vtkIdType>(this->Corners.size() / 3);

  // One job per array, each with a table of its values at the corners of every
  // triangle (or of its cell, for a cell array), so that a sample reads one record
  // of its triangle; the samples go in chunks, every job over a short block of a
  // chunk in turn while the block's sources are in cache.
  std::vector<std::unique_ptr<ResampleJob>> jobs;
  const vtkOFBAttributeInterpolator interpolator(surface);
  jobs.emplace_back(
    new ColorJob(interpolator, ids, nTriangles, this->Table(0), colors->GetPointer(0)));
  if (vectors && interpolator.PointVectors)
  {
    jobs.emplace_back(new VectorJob(interpolator,
      ids,
      nTriangles,
      this->Table(1),
      vtkFloatArray::SafeDownCast(this->Normals)->GetPointer(0),
      vectors->GetPointer(0)));
  }
  // The arrays attached as a full build does (vtkOFBSampleArrays::Attach): the paint
  // is the active scalars unless a cell array takes them.
  vtkPointData* sampleData = output->GetSampleData();
  const int cellScalars = surface.CellScalarsIndex;
  if (cellScalars >= 0 && cellScalars < static_cast<int>(others.size()) && others[cellScalars])
  {
    sampleData->AddArray(colors);
  }
  else
  {
    sampleData->SetScalars(colors);
  }
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
    const vtkIdType* cells = perCell ? this->Cells.data() : nullptr;
    switch (in->GetDataType())
    {
      vtkTemplateMacro(
        jobs.emplace_back(new TupleJob<VTK_TT>(static_cast<const VTK_TT*>(in->GetVoidPointer(0)),
          in->GetNumberOfComponents(),
          ids,
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
    else if (static_cast<int>(k) == cellScalars)
    {
      sampleData->SetScalars(out);
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
      for (vtkIdType first = begin; first < end; first += vtkofb::ResampleBlock)
      {
        const vtkIdType last = std::min(end, first + vtkofb::ResampleBlock);
        for (const auto& job : jobs)
        {
          job->Run(first, last, tri, w1, w2);
        }
      }
      vtkofb::Fence();
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
