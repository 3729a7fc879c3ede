#include "vtkOFBSampler.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBArrayLength.h"
#include "vtkOFBCPUSampler.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkOFBSampleSources.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBSampler);

namespace
{
/**
 * Copy an array into an array-of-structures array of the same type (a no-op for
 * arrays already in that layout).
 */
vtkSmartPointer<vtkDataArray> AsAOS(vtkDataArray* array)
{
  if (array->HasStandardMemoryLayout())
  {
    return array;
  }
  vtkSmartPointer<vtkDataArray> copy =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(array->GetDataType()));
  copy->DeepCopy(array);
  return copy;
}

bool IsColorArray(vtkDataArray* array)
{
  return array && array->GetDataType() == VTK_UNSIGNED_CHAR &&
    (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4);
}

/**
 * Items per chunk of the parallel loops below. Their per-chunk results are combined
 * in chunk order, so that nothing depends on the number of threads.
 */
constexpr vtkIdType Chunk = 16384;

/// Copy n values to doubles in parallel; the index of the first non-finite one, or -1.
template<typename T>
vtkIdType CopyValues(const T* in, vtkIdType nValues, double* out)
{
  const vtkIdType nChunks = (nValues + Chunk - 1) / Chunk;
  std::vector<vtkIdType> firstBad(nChunks, -1);
  vtkSMPTools::For(0,
    nChunks,
    1,
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        const vtkIdType end = std::min(nValues, (c + 1) * Chunk);
        for (vtkIdType i = c * Chunk; i < end; ++i)
        {
          out[i] = static_cast<double>(in[i]);
          if (!std::isfinite(out[i]) && firstBad[c] < 0)
          {
            firstBad[c] = i;
          }
        }
      }
    });
  for (const vtkIdType bad : firstBad)
  {
    if (bad >= 0)
    {
      return bad;
    }
  }
  return -1;
}

/**
 * Copy the point coordinates (3 components) into `out` as doubles; the index of
 * the first point with a non-finite coordinate, or -1.
 */
vtkIdType CopyPointCoordinates(vtkDataArray* points, double* out)
{
  const vtkIdType nValues = 3 * points->GetNumberOfTuples();
  vtkIdType bad = -1;
  if (auto* f = vtkFloatArray::FastDownCast(points))
  {
    bad = CopyValues(f->GetPointer(0), nValues, out);
  }
  else if (auto* d = vtkDoubleArray::FastDownCast(points))
  {
    bad = CopyValues(d->GetPointer(0), nValues, out);
  }
  else
  {
    const auto range = vtk::DataArrayValueRange<3>(points);
    for (vtkIdType i = 0; i < nValues && bad < 0; ++i)
    {
      out[i] = range[i];
      bad = std::isfinite(out[i]) ? -1 : i;
    }
  }
  return bad < 0 ? -1 : bad / 3;
}

/**
 * The triangles of a cell array with non-zero area, in order, and the bounds of
 * their points, found in parallel. The point ids are valid (CheckInputCells).
 */
struct TriangleCollector
{
  const double* P;
  vtkIdType Skipped = 0;

  explicit TriangleCollector(const double* points)
    : P(points)
  {
  }

  /**
   * The triangles of `cells`; with `cellIds` (the input cell id of each of
   * `cells`), the input cell of each kept triangle too (surface.TriangleCells).
   */
  void Collect(vtkCellArray* cells, vtkOFBSurface& surface, const vtkIdType* cellIds)
  {
    if (cells->IsHomogeneous() == 3 && cells->IsStorage64Bit())
    {
      this->Collect(cells->GetConnectivityArray64()->GetPointer(0),
        cells->GetNumberOfCells(),
        cellIds,
        surface);
      return;
    }
    if (cells->IsHomogeneous() == 3)
    {
      this->Collect(cells->GetConnectivityArray32()->GetPointer(0),
        cells->GetNumberOfCells(),
        cellIds,
        surface);
      return;
    }
    // Mixed cells (not left by the triangulation in practice): their triangles.
    std::vector<vtkIdType> ids;
    std::vector<vtkIdType> triangleCellIds;
    auto iter = vtk::TakeSmartPointer(cells->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      if (npts == 3)
      {
        ids.insert(ids.end(), pts, pts + 3);
        if (cellIds)
        {
          triangleCellIds.push_back(cellIds[iter->GetCurrentCellId()]);
        }
      }
    }
    this->Collect(ids.data(),
      static_cast<vtkIdType>(ids.size() / 3),
      cellIds ? triangleCellIds.data() : nullptr,
      surface);
  }

  template<typename IdT>
  void Collect(const IdT* ids, vtkIdType n, const vtkIdType* cellIds, vtkOFBSurface& surface)
  {
    const vtkIdType nChunks = (n + Chunk - 1) / Chunk;
    std::vector<vtkIdType> kept(nChunks + 1, 0);
    std::vector<double> bounds(6 * nChunks);
    std::vector<unsigned char> valid(n);
    vtkSMPTools::For(0,
      nChunks,
      1,
      [&](vtkIdType c0, vtkIdType c1)
      {
        for (vtkIdType c = c0; c < c1; ++c)
        {
          kept[c + 1] =
            this->Check(ids, c * Chunk, std::min(n, (c + 1) * Chunk), valid.data(), &bounds[6 * c]);
        }
      });
    for (vtkIdType c = 0; c < nChunks; ++c)
    {
      kept[c + 1] += kept[c];
    }
    this->Skipped = n - kept[nChunks];
    surface.Triangles.resize(3 * kept[nChunks]);
    surface.TriangleCells.resize(cellIds ? kept[nChunks] : 0);
    vtkIdType* out = surface.Triangles.data();
    vtkIdType* outCells = surface.TriangleCells.data();
    vtkSMPTools::For(0,
      nChunks,
      1,
      [&](vtkIdType c0, vtkIdType c1)
      {
        for (vtkIdType c = c0; c < c1; ++c)
        {
          vtkIdType k = 3 * kept[c];
          for (vtkIdType t = c * Chunk; t < std::min(n, (c + 1) * Chunk); ++t)
          {
            if (cellIds && valid[t])
            {
              outCells[k / 3] = cellIds[t];
            }
            for (int j = 0; valid[t] && j < 3; ++j)
            {
              out[k++] = static_cast<vtkIdType>(ids[3 * t + j]);
            }
          }
        }
      });
    // Bounds of the points the triangles use (min and max: exact in any order).
    double* b = surface.Bounds;
    b[0] = b[2] = b[4] = VTK_DOUBLE_MAX;
    b[1] = b[3] = b[5] = -VTK_DOUBLE_MAX;
    for (vtkIdType c = 0; c < nChunks; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        b[2 * k] = std::min(b[2 * k], bounds[6 * c + 2 * k]);
        b[2 * k + 1] = std::max(b[2 * k + 1], bounds[6 * c + 2 * k + 1]);
      }
    }
  }

  /**
   * Triangles [begin, end): flags of those with non-zero area, their count and
   * bounds.
   */
  template<typename IdT>
  vtkIdType Check(const IdT* ids,
    vtkIdType begin,
    vtkIdType end,
    unsigned char* valid,
    double bounds[6]) const
  {
    bounds[0] = bounds[2] = bounds[4] = VTK_DOUBLE_MAX;
    bounds[1] = bounds[3] = bounds[5] = -VTK_DOUBLE_MAX;
    vtkIdType count = 0;
    for (vtkIdType t = begin; t < end; ++t)
    {
      const IdT* tri = ids + 3 * t;
      valid[t] = 0;
      const double* p0 = this->P + 3 * tri[0];
      const double* p1 = this->P + 3 * tri[1];
      const double* p2 = this->P + 3 * tri[2];
      double e1[3], e2[3], n[3];
      for (int k = 0; k < 3; ++k)
      {
        e1[k] = p1[k] - p0[k];
        e2[k] = p2[k] - p0[k];
      }
      vtkMath::Cross(e1, e2, n);
      if (vtkMath::Dot(n, n) == 0.0)
      {
        continue;
      }
      valid[t] = 1;
      ++count;
      for (const double* p : { p0, p1, p2 })
      {
        for (int k = 0; k < 3; ++k)
        {
          bounds[2 * k] = std::min(bounds[2 * k], p[k]);
          bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
        }
      }
    }
    return count;
  }
};

/**
 * Area-weighted point normals of the surface's triangles: the face normals summed
 * per point in triangle order, in one serial pass (the same sums whatever the
 * number of threads), normalized in parallel.
 */
void AreaWeightedNormals(vtkOFBSurface& surface)
{
  const double* P = surface.Points.data();
  const vtkIdType* T = surface.Triangles.data();
  const vtkIdType nTris = surface.GetNumberOfTriangles();
  const vtkIdType nPoints = static_cast<vtkIdType>(surface.Points.size() / 3);
  std::vector<double> acc(3 * nPoints, 0.0);
  for (vtkIdType t = 0; t < nTris; ++t)
  {
    const vtkIdType* tri = T + 3 * t;
    double e1[3], e2[3], face[3];
    for (int k = 0; k < 3; ++k)
    {
      e1[k] = P[3 * tri[1] + k] - P[3 * tri[0] + k];
      e2[k] = P[3 * tri[2] + k] - P[3 * tri[0] + k];
    }
    vtkMath::Cross(e1, e2, face); // length is twice the area: area weighting
    for (int c = 0; c < 3; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        acc[3 * tri[c] + k] += face[k];
      }
    }
  }
  vtkSMPTools::For(0,
    nPoints,
    Chunk,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double len = vtkMath::Norm(&acc[3 * i]);
        for (int k = 0; k < 3; ++k)
        {
          surface.Normals[3 * i + k] = len > 0.0 ? static_cast<float>(acc[3 * i + k] / len) : 0.0f;
        }
      }
    });
}

/**
 * The triangles of a cell array of polygons or strips (n - 2 for a cell of n
 * points), from its sizes alone.
 */
vtkIdType CountTriangles(vtkCellArray* cells)
{
  if (!cells)
  {
    return 0;
  }
  const vtkIdType ids = cells->GetNumberOfConnectivityIds();
  return std::max<vtkIdType>(0, ids - 2 * cells->GetNumberOfCells());
}

/**
 * The point arrays of `pd` (of `nPoints` tuples) to interpolate into the samples:
 * every named, non-bit array but those already used (`used`: normals, vectors,
 * colours) or named as the samples' own arrays.
 */
void CollectOtherArrays(vtkPointData* pd,
  vtkIdType nPoints,
  std::initializer_list<vtkDataArray*> used,
  vtkOFBSurface& surface)
{
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = pd->GetArray(i);
    if (!array || std::find(used.begin(), used.end(), array) != used.end() ||
      array->GetDataType() == VTK_BIT || array->GetNumberOfTuples() != nPoints ||
      !array->GetName() || !std::strcmp(array->GetName(), vtkOFB::ColorsArrayName()) ||
      !std::strcmp(array->GetName(), vtkOFB::NormalsArrayName()) ||
      (surface.Vectors && !std::strcmp(array->GetName(), surface.Vectors->GetName())))
    {
      continue;
    }
    if (array == pd->GetTCoords())
    {
      surface.TCoordsIndex = static_cast<int>(surface.Arrays.size());
    }
    surface.Arrays.push_back(AsAOS(array));
  }
}
}

namespace
{
/**
 * Re-emits the errors and warnings of an inner algorithm as those of `Target`, where the
 * target's observers see them: the text after VTK's "Class (address): " prefix.
 */
class MessageForwarder : public vtkCommand
{
public:
  static MessageForwarder* New() { return new MessageForwarder; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    std::string text = data ? static_cast<const char*>(data) : "";
    const size_t prefix = text.find("): ");
    text = prefix == std::string::npos ? text : text.substr(prefix + 3);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    if (event == vtkCommand::ErrorEvent)
    {
      vtkErrorWithObjectMacro(this->Target, << text);
    }
    else
    {
      vtkWarningWithObjectMacro(this->Target, << text);
    }
  }
  vtkObject* Target = nullptr;
};

/// Index in surface.Arrays of the array named `name`, or -1.
int FindArray(const vtkOFBSurface& surface, const char* name)
{
  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    if (!std::strcmp(surface.Arrays[k]->GetName(), name))
    {
      return static_cast<int>(k);
    }
  }
  return -1;
}

/**
 * The cell arrays of `cd` (of `nCells` tuples) that the samples take from their
 * triangle's cell: every named, non-bit array but those named as the samples' own
 * arrays or the vector field. One named as a point array already in
 * surface.Arrays replaces it when `cellsFirst`, else is left out. The cell data's
 * active vectors become the samples' when they have no other vector field, and its
 * active scalars (unless RGB(A) bytes, colours) the samples' when the input has no
 * active point scalars (`pointScalars`).
 */
void CollectCellArrays(vtkCellData* cd,
  vtkIdType nCells,
  bool cellsFirst,
  bool pointScalars,
  vtkOFBSurface& surface)
{
  surface.ArraysPerCell.resize(surface.Arrays.size(), false);
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = cd->GetArray(i);
    if (!array || array->GetDataType() == VTK_BIT || array->GetNumberOfTuples() != nCells ||
      !array->GetName() || !std::strcmp(array->GetName(), vtkOFB::ColorsArrayName()) ||
      !std::strcmp(array->GetName(), vtkOFB::NormalsArrayName()) ||
      (surface.Vectors && !std::strcmp(array->GetName(), surface.Vectors->GetName())))
    {
      continue;
    }
    int k = FindArray(surface, array->GetName());
    if (k >= 0 && (!cellsFirst || surface.ArraysPerCell[k]))
    {
      continue; // the point array wins (or a cell array of the same name came first)
    }
    if (k < 0)
    {
      k = static_cast<int>(surface.Arrays.size());
      surface.Arrays.emplace_back();
      surface.ArraysPerCell.push_back(true);
    }
    surface.Arrays[k] = AsAOS(array);
    surface.ArraysPerCell[k] = true;
    surface.TCoordsIndex = surface.TCoordsIndex == k ? -1 : surface.TCoordsIndex;
    if (array == cd->GetVectors() && !surface.Vectors && array->GetNumberOfComponents() == 3)
    {
      surface.CellVectorsIndex = k;
    }
    if (array == cd->GetScalars() && !pointScalars && !IsColorArray(array))
    {
      surface.CellScalarsIndex = k;
    }
  }
}
}

//------------------------------------------------------------------------------
vtkOFBSampler::vtkOFBSampler()
  : Resolution(1024)
  , MemoryLimit(8192)
  , UseInputColors(true)
  , PassPointArrays(true)
  , PassCellArrays(true)
  , ArrayPrecedence(POINT_ARRAYS_FIRST)
  , ProjectVectors(true)
  , StructureReuse(STRUCTURE_REUSE_TIME_SERIES)
  , LastUpdateResampled(false)
  , NumberOfSkippedTriangles(0)
  , LastBuildTime(0.0)
{
  this->DefaultColor[0] = this->DefaultColor[1] = this->DefaultColor[2] = 255;
  this->DefaultColor[3] = 255;
  this->CPUBackend = vtk::TakeSmartPointer(vtkOFBCPUSampler::New());
  this->Sources = vtk::TakeSmartPointer(vtkOFBSampleSources::New());
}

//------------------------------------------------------------------------------
vtkOFBSampler::~vtkOFBSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBSampler::ReleaseBuffers()
{
  this->CPUBackend->ReleaseBuffers();
  this->Sources->Reset();
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend* vtkOFBSampler::SelectBackend()
{
  return this->CPUBackend;
}

//------------------------------------------------------------------------------
int vtkOFBSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  // Composite datasets are merged here (vtkOFBMergeBlocks), not block by block by the
  // pipeline: one OFB on one frame over all blocks.
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBSampler::GetSurface(vtkDataObject* input)
{
  // A polydata is sampled as it is (no copy); any other dataset through its
  // outer surface, with its point and cell arrays; a composite dataset as the
  // surface of all its blocks, with their block index (vtkOFBMergeBlocks).
  if (auto* polyData = vtkPolyData::SafeDownCast(input))
  {
    return polyData;
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  if (vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkNew<vtkOFBMergeBlocks> merge;
    merge->SetInputData(input);
    vtkNew<MessageForwarder> forward;
    forward->Target = this;
    merge->AddObserver(vtkCommand::ErrorEvent, forward);
    merge->AddObserver(vtkCommand::WarningEvent, forward);
    merge->Update();
    surface->ShallowCopy(merge->GetOutput());
    return surface;
  }
  if (!vtkDataSet::SafeDownCast(input))
  {
    return surface;
  }
  auto extract = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
  extract->SetInputData(input);
  extract->Update();
  surface->ShallowCopy(extract->GetOutput());
  return surface;
}

//------------------------------------------------------------------------------
int vtkOFBSampler::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkSmartPointer<vtkPolyData> input = this->GetSurface(vtkDataObject::GetData(inputVector[0]));
  vtkOFB* output = vtkOFB::GetData(outputVector);
  // The pipeline has recycled the previous output (vtkOFB::PrepareForNewData):
  // SetFrame, AllocateSamples and the sample arrays reuse its memory, and
  // vtkOFBAlgorithm frees what is left after this.
  this->NumberOfSkippedTriangles = 0;
  this->LastBuildTime = 0.0;
  this->LastUpdateResampled = false;

  const double start = vtkTimerLog::GetUniversalTime();
  vtkOFBSamplerBackend* backend = this->SelectBackend();
  this->LastBuildBackend = backend;
  this->UpdateProgress(0.0);
  vtkOFBSurface surface;
  vtkOFBSamplerBackend::Job job;
  job.Surface = &surface;
  job.Output = output;
  job.MemoryLimit = 1024.0 * 1024.0 * static_cast<double>(this->MemoryLimit);
  job.Algorithm = this;
  if (this->ResampleAttributes(inputVector[0]->GetInformationObject(0), input, job))
  {
    this->LastBuildTime = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
    this->UpdateProgress(1.0);
    return 1;
  }
  if (!this->CheckInputCells(input) || !this->CheckInputMemory(input, backend, job) ||
    !this->PrepareSurface(input, surface) || !this->ComputeFrame(surface, job))
  {
    output->Initialize();
    this->Sources->Reset();
    return 1;
  }
  this->UpdateProgress(0.05);
  auto key = vtkOFBSampleSources::MakeKey(input, this->Resolution, backend);
  if (this->RunBackend(backend, job) != vtkOFBSamplerBackend::RESULT_BUILT)
  {
    this->Sources->Reset();
    return 1;
  }
  if (job.Sources)
  {
    key.Backend = this->LastBuildBackend.GetPointer();
    this->Sources->Keep(output, input, key, surface);
  }
  this->ProjectCellVectors(surface, output);
  this->LastBuildTime = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend::Result vtkOFBSampler::RunBackend(vtkOFBSamplerBackend* backend,
  vtkOFBSamplerBackend::Job& job)
{
  vtkOFBSamplerBackend::Result result = backend->Sample(job);
  if (result == vtkOFBSamplerBackend::RESULT_UNAVAILABLE && backend != this->CPUBackend)
  {
    vtkWarningMacro("The " << backend->GetBackendName() << " build failed (" << job.Error
                           << "); building on the CPU instead.");
    job.Output->Initialize();
    job.Error.clear();
    this->LastBuildBackend = this->CPUBackend;
    result = this->CPUBackend->Sample(job);
  }
  if (result != vtkOFBSamplerBackend::RESULT_BUILT)
  {
    if (!job.Error.empty())
    {
      vtkErrorMacro(<< job.Error);
    }
    job.Output->Initialize();
  }
  return result;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::PrepareSurface(vtkPolyData* input, vtkOFBSurface& surface)
{
  if (!this->CopyPoints(input, surface) || !this->CollectTriangles(input, surface))
  {
    return false;
  }
  vtkDataArray* normals = this->PrepareNormals(input, surface);
  return this->PrepareAttributes(input, normals, surface);
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::PrepareAttributes(vtkPolyData* input,
  vtkDataArray* normals,
  vtkOFBSurface& surface)
{
  vtkDataArray* vectors = nullptr;
  if (!this->SelectVectors(input, surface, vectors))
  {
    return false;
  }
  vtkDataArray* colors = this->SelectColors(input, surface);
  // Point arrays of another length than the points (vtkPolyData does not enforce it)
  // are left out: normals are then computed, colours are DefaultColor.
  vtkPointData* pd = input->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = pd->GetArray(i);
    if (array && array->GetNumberOfTuples() != input->GetNumberOfPoints())
    {
      vtkWarningMacro("The point array "
        << vtkOFBArrayLength(array, input->GetNumberOfPoints(), "points") << ": left out.");
    }
  }
  if (this->PassPointArrays)
  {
    CollectOtherArrays(pd, input->GetNumberOfPoints(), { normals, vectors, colors }, surface);
  }
  vtkCellData* cd = input->GetCellData();
  for (int i = 0; this->PassCellArrays && i < cd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = cd->GetArray(i);
    if (array && array->GetNumberOfTuples() != input->GetNumberOfCells())
    {
      vtkWarningMacro("The cell array "
        << vtkOFBArrayLength(array, input->GetNumberOfCells(), "cells") << ": left out.");
    }
  }
  if (this->PassCellArrays)
  {
    CollectCellArrays(input->GetCellData(),
      input->GetNumberOfCells(),
      this->ArrayPrecedence == CELL_ARRAYS_FIRST,
      pd->GetScalars() != nullptr,
      surface);
  }
  if (std::find(surface.ArraysPerCell.begin(), surface.ArraysPerCell.end(), true) ==
    surface.ArraysPerCell.end())
  {
    // No cell array: the triangles' cells are not needed.
    surface.ArraysPerCell.clear();
    surface.TriangleCells.clear();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::NeedsTriangleCells(vtkPolyData* input) const
{
  vtkCellData* cd = input->GetCellData();
  return this->PassCellArrays && cd->GetNumberOfArrays() > 0;
}

//------------------------------------------------------------------------------
void vtkOFBSampler::ProjectCellVectors(const vtkOFBSurface& surface, vtkOFB* output)
{
  // Point vectors are projected as they are interpolated (vtkOFBAttributeInterpolator);
  // cell vectors, copied from the cells, are projected here on the sample normals.
  vtkPointData* sd = output->GetSampleData();
  vtkDataArray* vectors = sd->GetVectors();
  vtkDataArray* normals = sd->GetNormals();
  if (surface.CellVectorsIndex < 0 || !this->ProjectVectors || !vectors || !normals)
  {
    return;
  }
  vtkSMPTools::For(0,
    vectors->GetNumberOfTuples(),
    Chunk,
    [&](vtkIdType begin, vtkIdType end)
    {
      double v[3], n[3];
      for (vtkIdType i = begin; i < end; ++i)
      {
        vectors->GetTuple(i, v);
        normals->GetTuple(i, n);
        const double vn = vtkMath::Dot(v, n);
        for (int k = 0; k < 3; ++k)
        {
          v[k] -= vn * n[k];
        }
        vectors->SetTuple(i, v);
      }
    });
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::CheckInputCells(vtkPolyData* input)
{
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input surface is empty: no points.");
    return false;
  }
  // Before anything (the triangulation included) reads a cell's points.
  std::string error;
  if (!vtkOFBCheckCellPointIds(input, error))
  {
    vtkErrorMacro("The input surface is invalid: " << error << ".");
    return false;
  }
  const vtkIdType nLinesVerts = input->GetNumberOfLines() + input->GetNumberOfVerts();
  if (nLinesVerts > 0)
  {
    vtkWarningMacro("Ignoring " << input->GetNumberOfLines() << " lines and "
                                << input->GetNumberOfVerts() << " vertices of the input.");
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips: nothing to sample.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::CheckInputMemory(vtkPolyData* input,
  vtkOFBSamplerBackend* backend,
  vtkOFBSamplerBackend::Job& job)
{
  const vtkIdType points = input->GetNumberOfPoints();
  const vtkIdType triangles =
    CountTriangles(input->GetPolys()) + CountTriangles(input->GetStrips());
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(
        backend->EstimateBytes(points, triangles), job.MemoryLimit, job.Error))
  {
    vtkErrorMacro(<< job.Error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::CopyPoints(vtkPolyData* input, vtkOFBSurface& surface)
{
  surface.Points.resize(3 * input->GetNumberOfPoints());
  const vtkIdType badPoint =
    CopyPointCoordinates(input->GetPoints()->GetData(), surface.Points.data());
  if (badPoint >= 0)
  {
    vtkErrorMacro(
      "The input has non-finite (NaN or Inf) point coordinates, point " << badPoint << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::CollectTriangles(vtkPolyData* input, vtkOFBSurface& surface)
{
  // Triangles: the input's own cells when they are all triangles, else a triangulation.
  // With cell arrays to pass, the input cell id of each triangle too: polygons
  // follow the vertices and lines in vtkPolyData's cell ids.
  const bool needCells = this->NeedsTriangleCells(input);
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkSmartPointer<vtkPolyData> mesh = input;
  vtkCellArray* polys = input->GetPolys();
  std::vector<vtkIdType> polyCells;
  const vtkIdType* cellIds = nullptr;
  if (input->GetNumberOfStrips() > 0 || polys->IsHomogeneous() != 3)
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->SetPoints(input->GetPoints());
    copy->SetPolys(input->GetPolys());
    copy->SetStrips(input->GetStrips());
    if (needCells)
    {
      // The triangle filter carries this id from each polygon or strip to its triangles.
      auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
      ids->SetName("vtkOFBInputCellIds");
      ids->SetNumberOfTuples(copy->GetNumberOfCells());
      for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
      {
        ids->SetValue(i, firstPoly + i);
      }
      copy->GetCellData()->AddArray(ids);
    }
    auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
    triangulate->SetInputData(copy);
    triangulate->PassLinesOff();
    triangulate->PassVertsOff();
    triangulate->Update();
    mesh = triangulate->GetOutput();
    auto* triangleIds =
      vtkIdTypeArray::SafeDownCast(mesh->GetCellData()->GetArray("vtkOFBInputCellIds"));
    if (needCells && !triangleIds)
    {
      vtkErrorMacro("The triangulation lost the input cell ids of its triangles: cannot pass "
                    "the cell arrays.");
      return false;
    }
    cellIds = needCells ? triangleIds->GetPointer(0) : nullptr;
  }
  else if (needCells)
  {
    polyCells.resize(polys->GetNumberOfCells());
    std::iota(polyCells.begin(), polyCells.end(), firstPoly);
    cellIds = polyCells.data();
  }
  TriangleCollector triangles(surface.Points.data());
  triangles.Collect(mesh->GetPolys(), surface, cellIds);
  this->NumberOfSkippedTriangles = triangles.Skipped;
  if (this->NumberOfSkippedTriangles > 0)
  {
    vtkWarningMacro("Skipped " << this->NumberOfSkippedTriangles << " zero-area triangles.");
  }
  if (surface.Triangles.empty())
  {
    vtkErrorMacro("The input has no triangle of non-zero area: nothing to sample.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBSampler::PrepareNormals(vtkPolyData* input, vtkOFBSurface& surface)
{
  const vtkIdType nPoints = input->GetNumberOfPoints();
  // Normals: the input's point normals, else area-weighted ones.
  vtkDataArray* inNormals = input->GetPointData()->GetNormals();
  surface.Normals.resize(3 * nPoints);
  if (inNormals && inNormals->GetNumberOfComponents() == 3 &&
    inNormals->GetNumberOfTuples() == nPoints)
  {
    vtkFloatArray* floats = vtkFloatArray::FastDownCast(inNormals); // read directly
    vtkSMPTools::For(0,
      nPoints,
      Chunk,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          double n[3];
          if (floats)
          {
            const float* f = floats->GetPointer(3 * i);
            n[0] = f[0];
            n[1] = f[1];
            n[2] = f[2];
          }
          else
          {
            inNormals->GetTuple(i, n);
          }
          const double len = vtkMath::Norm(n);
          const bool unit = std::isfinite(len) && len > 0.0;
          for (int k = 0; k < 3; ++k)
          {
            surface.Normals[3 * i + k] = unit ? static_cast<float>(n[k] / len) : 0.0f;
          }
        }
      });
  }
  else
  {
    inNormals = nullptr;
    AreaWeightedNormals(surface);
  }
  return inNormals;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::SelectVectors(vtkPolyData* input,
  vtkOFBSurface& surface,
  vtkDataArray*& vectors)
{
  // The vector field: the array chosen with SetInputArrayToProcess, else the vectors.
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  if (arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_ASSOCIATION()))
  {
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    vectors = this->GetInputArrayToProcess(0, input, association);
    if (!vectors || association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      vtkErrorMacro("The vector field chosen with SetInputArrayToProcess is not a point array "
                    "of the input.");
      return false;
    }
  }
  else
  {
    vectors = input->GetPointData()->GetVectors();
  }
  if (vectors && vectors->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The vector field '" << (vectors->GetName() ? vectors->GetName() : "")
                                       << "' must have 3 components, it has "
                                       << vectors->GetNumberOfComponents() << ".");
    return false;
  }
  if (vectors && vectors->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro(
      "The vector field " << vtkOFBArrayLength(vectors, input->GetNumberOfPoints(), "points."));
    return false;
  }
  if (vectors)
  {
    auto v = vtkSmartPointer<vtkFloatArray>::New();
    v->DeepCopy(vectors);
    v->SetName(vectors->GetName() ? vectors->GetName() : "Vectors");
    surface.Vectors = v;
  }
  surface.ProjectVectors = this->ProjectVectors;
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBSampler::SelectColors(vtkPolyData* input, vtkOFBSurface& surface)
{
  vtkPointData* pd = input->GetPointData();
  // Initial paint.
  std::memcpy(surface.DefaultColor, this->DefaultColor, 4);
  vtkDataArray* colors = nullptr;
  if (this->UseInputColors)
  {
    if (IsColorArray(pd->GetScalars()))
    {
      colors = pd->GetScalars();
    }
    else if (IsColorArray(pd->GetArray(vtkOFB::ColorsArrayName())))
    {
      colors = pd->GetArray(vtkOFB::ColorsArrayName());
    }
  }
  if (colors && colors->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    colors = nullptr; // named by PrepareSurface's warning; the samples take DefaultColor
  }
  if (colors)
  {
    surface.Colors = vtkUnsignedCharArray::SafeDownCast(AsAOS(colors));
  }
  return colors;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::ComputeFrame(const vtkOFBSurface& surface, vtkOFBSamplerBackend::Job& job)
{
  if (this->Resolution < 3 || this->Resolution > 65536)
  {
    vtkErrorMacro("Resolution must be in [3, 65536], it is " << this->Resolution << ".");
    return false;
  }
  const double* b = surface.Bounds;
  const double longest = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  if (!std::isfinite(longest))
  {
    // Finite coordinates whose extent is not (e.g. -1e308 and 1e308).
    vtkErrorMacro("The input bounds overflow a double (extent of the coordinates too large): "
                  "nothing to sample.");
    return false;
  }
  if (!(longest > 0.0))
  {
    vtkErrorMacro("The input bounds are degenerate: nothing to sample.");
    return false;
  }
  const double cellSize = longest / (this->Resolution - 2);
  job.CellSize = cellSize;
  for (int a = 0; a < 3; ++a)
  {
    const double cells = std::ceil((b[2 * a + 1] - b[2 * a]) / cellSize - 1e-9);
    job.Dimensions[a] = std::max<vtkIdType>(1, static_cast<vtkIdType>(cells)) + 2;
    job.Origin[a] = 0.5 * (b[2 * a] + b[2 * a + 1]) - 0.5 * job.Dimensions[a] * cellSize;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkOFBSampler::EstimateMemory(vtkDataObject* dataSet)
{
  vtkSmartPointer<vtkPolyData> input = this->GetSurface(dataSet);
  vtkOFBSurface surface;
  vtkOFBSamplerBackend::Job job;
  if (!this->CheckInputCells(input) || !this->PrepareSurface(input, surface) ||
    !this->ComputeFrame(surface, job))
  {
    return -1.0;
  }
  const double samples = vtkOFBSamplerBackend::EstimateSamples(surface, job.CellSize);
  return this->CPUBackend->EstimateBytes(surface, job.Dimensions, samples);
}

//------------------------------------------------------------------------------
void vtkOFBSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "DefaultColor: (" << static_cast<int>(this->DefaultColor[0]) << ", "
     << static_cast<int>(this->DefaultColor[1]) << ", " << static_cast<int>(this->DefaultColor[2])
     << ", " << static_cast<int>(this->DefaultColor[3]) << ")\n";
  os << indent << "UseInputColors: " << (this->UseInputColors ? "On" : "Off") << "\n";
  os << indent << "PassPointArrays: " << (this->PassPointArrays ? "On" : "Off") << "\n";
  os << indent << "PassCellArrays: " << (this->PassCellArrays ? "On" : "Off") << "\n";
  os << indent << "ArrayPrecedence: "
     << (this->ArrayPrecedence == CELL_ARRAYS_FIRST ? "CELL_ARRAYS_FIRST" : "POINT_ARRAYS_FIRST")
     << "\n";
  os << indent << "ProjectVectors: " << (this->ProjectVectors ? "On" : "Off") << "\n";
  os << indent << "StructureReuse: " << this->StructureReuse << "\n";
  os << indent << "LastUpdateResampled: " << (this->LastUpdateResampled ? "yes" : "no") << "\n";
  os << indent << "NumberOfSkippedTriangles: " << this->NumberOfSkippedTriangles << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << " ms\n";
}
