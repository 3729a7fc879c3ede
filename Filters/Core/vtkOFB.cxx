#include "vtkOFB.h"
#include "vtkOFBHugePages.h"
#include "vtkOFBModifiedRanges.h"

#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkOFB);

//------------------------------------------------------------------------------
struct vtkOFB::vtkInternals
{
  /// Arrays that Recycle() found free, for the next SetFrame, AllocateSamples and
  /// TakeSpareArray.
  std::vector<vtkSmartPointer<vtkDataArray>> Spares;

  /// The structure that Recycle() let go: a shallow copy of the same arrays in the same
  /// frame (a filter re-executing over an unchanged input) keeps its StructureTime, so
  /// that consumers (the mapper's uploads) see only the arrays that changed.
  struct RecycledStructure
  {
    vtkWeakPointer<vtkTypeUInt32Array> CellOffsets;
    vtkWeakPointer<vtkFloatArray> Depths;
    vtkWeakPointer<vtkTypeUInt32Array> CellIndex;
    double Origin[3];
    vtkIdType Dimensions[3];
    double CellSize;
    vtkTimeStamp Time;
  };
  RecycledStructure Recycled;

  /// The sample ranges marked modified (see MarkSamplesModified).
  vtkOFBModifiedRanges ModifiedRanges;

  /// The exclusive writer (see BeginExclusiveWrite), null when none.
  std::atomic<const void*> Writer{ nullptr };
};

namespace
{
/**
 * n values in a spare array of `ofb` of this name and type (see vtkOFB::Recycle),
 * else in a new one; null if it cannot be allocated.
 */
template<typename ArrayT>
vtkSmartPointer<ArrayT> SpareOrNew(vtkOFB* ofb, const char* name, int type, vtkIdType n)
{
  vtkSmartPointer<ArrayT> array = ArrayT::SafeDownCast(ofb->TakeSpareArray(name, type, 1, n));
  if (array)
  {
    return array;
  }
  array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  if (n > 0 && !array->Allocate(n))
  {
    return nullptr;
  }
  array->SetNumberOfValues(n);
  vtkofb::AdviseHugePages(array);
  return array;
}
}

//------------------------------------------------------------------------------
vtkOFB::vtkOFB()
  : Internals(new vtkInternals)
{
  this->CellOffsets = vtkSmartPointer<vtkTypeUInt32Array>::New();
  this->CellOffsets->SetName("CellOffsets");
  this->Depths = vtkSmartPointer<vtkFloatArray>::New();
  this->Depths->SetName("Depths");
  this->CellIndex = vtkSmartPointer<vtkTypeUInt32Array>::New();
  this->CellIndex->SetName("CellIndex");
  this->SampleData = vtkSmartPointer<vtkPointData>::New();
  this->Origin[0] = this->Origin[1] = this->Origin[2] = 0.0;
  this->CellSize = 0.0;
  this->Dimensions[0] = this->Dimensions[1] = this->Dimensions[2] = 0;
  this->CellBase[0] = this->CellBase[1] = this->CellBase[2] = this->CellBase[3] = 0;
  this->CellOffsets->SetNumberOfValues(1);
  this->CellOffsets->SetValue(0, 0);
}

//------------------------------------------------------------------------------
vtkOFB::~vtkOFB() = default;

//------------------------------------------------------------------------------
void vtkOFB::Initialize()
{
  if (!this->CheckNotBeingWritten("Initialize"))
  {
    return;
  }
  this->Internals->Spares.clear();
  this->Reset();
}

//------------------------------------------------------------------------------
void vtkOFB::Reset()
{
  this->Superclass::Initialize();
  this->Origin[0] = this->Origin[1] = this->Origin[2] = 0.0;
  this->CellSize = 0.0;
  this->Dimensions[0] = this->Dimensions[1] = this->Dimensions[2] = 0;
  this->CellBase[0] = this->CellBase[1] = this->CellBase[2] = this->CellBase[3] = 0;
  // New arrays: a shallow copy may still share the old ones.
  this->CellOffsets = vtkSmartPointer<vtkTypeUInt32Array>::New();
  this->CellOffsets->SetName("CellOffsets");
  this->CellOffsets->SetNumberOfValues(1);
  this->CellOffsets->SetValue(0, 0);
  this->Depths = vtkSmartPointer<vtkFloatArray>::New();
  this->Depths->SetName("Depths");
  this->CellIndex = vtkSmartPointer<vtkTypeUInt32Array>::New();
  this->CellIndex->SetName("CellIndex");
  this->SampleData = vtkSmartPointer<vtkPointData>::New();
  this->Internals->ModifiedRanges.Clear();
  this->StructureTime.Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOFB::Recycle()
{
  if (!this->CheckNotBeingWritten("Recycle"))
  {
    return;
  }
  // An array is free when this OFB (or its sample data, itself held by nobody
  // else) holds the only reference.
  std::vector<vtkSmartPointer<vtkDataArray>> spares = std::move(this->Internals->Spares);
  auto keep = [&spares](vtkDataArray* array)
  {
    if (array && array->GetReferenceCount() == 1 && array->HasStandardMemoryLayout())
    {
      spares.emplace_back(array);
    }
  };
  this->Internals->Recycled.CellOffsets = this->CellOffsets;
  this->Internals->Recycled.Depths = this->Depths;
  this->Internals->Recycled.CellIndex = this->CellIndex;
  for (int a = 0; a < 3; ++a)
  {
    this->Internals->Recycled.Origin[a] = this->Origin[a];
    this->Internals->Recycled.Dimensions[a] = this->Dimensions[a];
  }
  this->Internals->Recycled.CellSize = this->CellSize;
  this->Internals->Recycled.Time = this->StructureTime;
  keep(this->CellOffsets);
  keep(this->Depths);
  keep(this->CellIndex);
  if (this->SampleData->GetReferenceCount() == 1)
  {
    for (int i = 0; i < this->SampleData->GetNumberOfArrays(); ++i)
    {
      keep(this->SampleData->GetArray(i));
    }
  }
  this->Initialize();
  this->Internals->Spares = std::move(spares);
}

//------------------------------------------------------------------------------
void vtkOFB::PrepareForNewData()
{
  this->Recycle();
}

//------------------------------------------------------------------------------
void vtkOFB::ReleaseSpareArrays()
{
  this->Internals->Spares.clear();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetNumberOfSpareArrays() const
{
  return static_cast<vtkIdType>(this->Internals->Spares.size());
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> vtkOFB::TakeSpareArray(const char* name,
  int dataType,
  int numberOfComponents,
  vtkIdType numberOfTuples)
{
  for (auto it = this->Internals->Spares.begin(); name && it != this->Internals->Spares.end(); ++it)
  {
    vtkDataArray* array = *it;
    if (array->GetDataType() != dataType || array->GetNumberOfComponents() != numberOfComponents ||
      !array->GetName() || std::strcmp(array->GetName(), name) != 0 ||
      array->GetSize() < numberOfTuples * numberOfComponents)
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> taken = *it;
    this->Internals->Spares.erase(it);
    // As a new array: no lookup table, no cached ranges or other information.
    taken->SetNumberOfTuples(numberOfTuples);
    taken->SetLookupTable(nullptr);
    if (taken->HasInformation())
    {
      taken->GetInformation()->Clear();
    }
    taken->Modified();
    return taken;
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkOFB::SetFrame(const double origin[3],
  double cellSize,
  const vtkIdType dims[3],
  bool zeroOffsets)
{
  if (!this->CheckNotBeingWritten("SetFrame"))
  {
    return false;
  }
  this->Reset();
  if (!(cellSize > 0.0) || !std::isfinite(cellSize) || !std::isfinite(origin[0]) ||
    !std::isfinite(origin[1]) || !std::isfinite(origin[2]))
  {
    vtkErrorMacro("SetFrame: the cell size must be positive and the origin finite.");
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (dims[a] < 1)
    {
      vtkErrorMacro("SetFrame: every dimension must be at least 1, got " << dims[a] << ".");
      return false;
    }
  }
  vtkIdType base[4] = { 0, 0, 0, 0 };
  for (int a = 0; a < 3; ++a)
  {
    const double cells =
      static_cast<double>(dims[(a + 1) % 3]) * static_cast<double>(dims[(a + 2) % 3]);
    if (cells + base[a] >= static_cast<double>(std::numeric_limits<vtkTypeUInt32>::max()))
    {
      vtkErrorMacro(
        "SetFrame: " << cells + base[a] << " cells exceed the 2^32 cell indices of an OFB.");
      return false;
    }
    base[a + 1] = base[a] + static_cast<vtkIdType>(cells);
  }
  vtkSmartPointer<vtkTypeUInt32Array> offsets =
    SpareOrNew<vtkTypeUInt32Array>(this, "CellOffsets", VTK_TYPE_UINT32, base[3] + 1);
  if (!offsets)
  {
    vtkErrorMacro("SetFrame: cannot allocate " << base[3] + 1 << " cell offsets.");
    return false;
  }
  vtkTypeUInt32* p = offsets->GetPointer(0);
  if (zeroOffsets)
  {
    vtkSMPTools::Fill(p, p + base[3] + 1, 0u);
  }
  p[0] = 0;
  this->CellOffsets = offsets;
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = origin[a];
    this->Dimensions[a] = dims[a];
    this->CellBase[a] = base[a];
  }
  this->CellBase[3] = base[3];
  this->CellSize = cellSize;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFB::AllocateSamples(vtkIdType n)
{
  if (!this->CheckNotBeingWritten("AllocateSamples"))
  {
    return false;
  }
  if (n < 0 || n >= static_cast<vtkIdType>(std::numeric_limits<vtkTypeUInt32>::max()))
  {
    vtkErrorMacro("AllocateSamples: invalid number of samples " << n << ".");
    return false;
  }
  this->SampleData = vtkSmartPointer<vtkPointData>::New();
  vtkSmartPointer<vtkFloatArray> depths = SpareOrNew<vtkFloatArray>(this, "Depths", VTK_FLOAT, n);
  vtkSmartPointer<vtkTypeUInt32Array> index =
    SpareOrNew<vtkTypeUInt32Array>(this, "CellIndex", VTK_TYPE_UINT32, n);
  if (!depths || !index)
  {
    vtkErrorMacro("AllocateSamples: cannot allocate " << n << " samples.");
    return false;
  }
  this->Internals->Recycled = vtkInternals::RecycledStructure();
  this->Depths = depths;
  this->CellIndex = index;
  this->Internals->ModifiedRanges.Clear();
  this->StructureTime.Modified();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFB::BuildCellIndex()
{
  const vtkIdType nCells = this->CellBase[3];
  const vtkIdType n = this->Depths->GetNumberOfValues();
  if (this->CellOffsets->GetNumberOfValues() != nCells + 1 ||
    this->CellIndex->GetNumberOfValues() != n)
  {
    vtkErrorMacro("BuildCellIndex: array sizes do not match the frame.");
    return false;
  }
  const vtkTypeUInt32* offsets = this->CellOffsets->GetPointer(0);
  if (offsets[0] != 0 || static_cast<vtkIdType>(offsets[nCells]) != n)
  {
    vtkErrorMacro("BuildCellIndex: the cell offsets do not run from 0 to the sample count.");
    return false;
  }
  vtkTypeUInt32* index = this->CellIndex->GetPointer(0);
  // Written by the SMP threads that meet a bad offset, read after they all finished.
  std::atomic<bool> valid(true);
  vtkSMPTools::For(0,
    nCells,
    65536,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const vtkTypeUInt32 b = offsets[c];
        const vtkTypeUInt32 e = offsets[c + 1];
        if (e < b || static_cast<vtkIdType>(e) > n)
        {
          valid.store(false, std::memory_order_relaxed);
          return;
        }
        for (vtkTypeUInt32 i = b; i < e; ++i)
        {
          index[i] = static_cast<vtkTypeUInt32>(c);
        }
      }
    });
  if (!valid.load())
  {
    vtkErrorMacro("BuildCellIndex: the cell offsets decrease or exceed the sample count.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFB::GetOrigin(double o[3]) const
{
  o[0] = this->Origin[0];
  o[1] = this->Origin[1];
  o[2] = this->Origin[2];
}

//------------------------------------------------------------------------------
void vtkOFB::GetDimensions(vtkIdType d[3]) const
{
  d[0] = this->Dimensions[0];
  d[1] = this->Dimensions[1];
  d[2] = this->Dimensions[2];
}

//------------------------------------------------------------------------------
void vtkOFB::GetBounds(double bounds[6]) const
{
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = this->Origin[a];
    bounds[2 * a + 1] = this->Origin[a] + this->Dimensions[a] * this->CellSize;
  }
}

//------------------------------------------------------------------------------
void vtkOFB::GetGridDimensions(int axis, vtkIdType& nu, vtkIdType& nv) const
{
  if (axis < 0 || axis > 2)
  {
    nu = nv = 0;
    return;
  }
  nu = this->Dimensions[(axis + 1) % 3];
  nv = this->Dimensions[(axis + 2) % 3];
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetNumberOfGridCells(int axis) const
{
  if (axis < 0 || axis > 2)
  {
    return 0;
  }
  return this->CellBase[axis + 1] - this->CellBase[axis];
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetNumberOfSamples() const
{
  return this->Depths->GetNumberOfValues();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetGridFirstSample(int axis) const
{
  if (axis < 0 || axis > 3 || this->CellOffsets->GetNumberOfValues() != this->CellBase[3] + 1)
  {
    return 0;
  }
  return this->CellOffsets->GetValue(this->CellBase[axis]);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetNumberOfSamples(int axis) const
{
  if (axis < 0 || axis > 2)
  {
    return 0;
  }
  return this->GetGridFirstSample(axis + 1) - this->GetGridFirstSample(axis);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetDepthComplexity(int axis) const
{
  if (axis < 0 || axis > 2 || this->GetNumberOfSamples() == 0)
  {
    return 0;
  }
  const vtkTypeUInt32* offsets = this->CellOffsets->GetPointer(0);
  vtkTypeUInt32 most = 0;
  for (vtkIdType c = this->CellBase[axis]; c < this->CellBase[axis + 1]; ++c)
  {
    most = std::max(most, offsets[c + 1] - offsets[c]);
  }
  return most;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetDepthComplexity() const
{
  return std::max(
    { this->GetDepthComplexity(0), this->GetDepthComplexity(1), this->GetDepthComplexity(2) });
}

//------------------------------------------------------------------------------
int vtkOFB::GetSampleAxis(vtkIdType id) const
{
  if (id < 0 || id >= this->GetNumberOfSamples())
  {
    return -1;
  }
  const vtkIdType cell = this->CellIndex->GetValue(id);
  return cell < this->CellBase[1] ? 0 : (cell < this->CellBase[2] ? 1 : 2);
}

//------------------------------------------------------------------------------
bool vtkOFB::GetSamplePosition(vtkIdType id, double x[3]) const
{
  if (id < 0 || id >= this->GetNumberOfSamples())
  {
    return false;
  }
  const vtkIdType cell = this->CellIndex->GetValue(id);
  const int a = cell < this->CellBase[1] ? 0 : (cell < this->CellBase[2] ? 1 : 2);
  const int ua = (a + 1) % 3;
  const int va = (a + 2) % 3;
  const vtkIdType local = cell - this->CellBase[a];
  const vtkIdType nu = this->Dimensions[ua];
  const vtkIdType iu = local % nu;
  const vtkIdType iv = local / nu;
  x[a] = this->Origin[a] + this->Depths->GetValue(id);
  x[ua] = this->Origin[ua] + (iu + 0.5) * this->CellSize;
  x[va] = this->Origin[va] + (iv + 0.5) * this->CellSize;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFB::LocateCell(int axis, const double x[3], vtkIdType& cell) const
{
  if (this->CellSize <= 0.0)
  {
    return false;
  }
  const int ua = (axis + 1) % 3;
  const int va = (axis + 2) % 3;
  const double fu = std::floor((x[ua] - this->Origin[ua]) / this->CellSize);
  const double fv = std::floor((x[va] - this->Origin[va]) / this->CellSize);
  if (!(fu >= 0.0 && fv >= 0.0 && fu < this->Dimensions[ua] && fv < this->Dimensions[va]))
  {
    return false;
  }
  cell = this->CellBase[axis] + static_cast<vtkIdType>(fv) * this->Dimensions[ua] +
    static_cast<vtkIdType>(fu);
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::FindSample(const double x[3], const double n[3]) const
{
  if (this->GetNumberOfSamples() == 0 || !std::isfinite(x[0]) || !std::isfinite(x[1]) ||
    !std::isfinite(x[2]))
  {
    return -1;
  }
  int a = 0;
  double best = std::fabs(n[0]);
  for (int i = 1; i < 3; ++i)
  {
    if (std::fabs(n[i]) > best)
    {
      best = std::fabs(n[i]);
      a = i;
    }
  }
  vtkIdType cell;
  if (!this->LocateCell(a, x, cell))
  {
    return -1;
  }
  const vtkTypeUInt32* offsets = this->CellOffsets->GetPointer(0);
  const float* depths = this->Depths->GetPointer(0);
  const double d = x[a] - this->Origin[a];
  const double s = this->CellSize;
  const vtkIdType begin = offsets[cell];
  const vtkIdType end = offsets[cell + 1];
  const vtkIdType i = static_cast<vtkIdType>(
    std::lower_bound(depths + begin, depths + end, static_cast<float>(d)) - depths);
  // The closest depth is at i or just before it.
  vtkIdType result = -1;
  double bestDist = s;
  if (i < end && std::fabs(depths[i] - d) <= bestDist)
  {
    result = i;
    bestDist = std::fabs(depths[i] - d);
  }
  if (i > begin && std::fabs(depths[i - 1] - d) <= bestDist)
  {
    result = i - 1;
  }
  return result;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::FindClosestSample(const double x[3]) const
{
  return this->FindClosestSample(x, std::sqrt(3.0) * this->CellSize);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::FindClosestSample(const double x[3], double radius) const
{
  if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
  {
    return -1;
  }
  vtkIdType result = -1;
  double best = std::numeric_limits<double>::max();
  this->ForEachSampleInSphere(x,
    radius,
    [&](vtkIdType id, double d2)
    {
      if (d2 < best || (d2 == best && id < result))
      {
        best = d2;
        result = id;
      }
    });
  return result;
}

//------------------------------------------------------------------------------
void vtkOFB::FindSamplesInSphere(const double center[3], double radius, vtkIdList* ids) const
{
  if (!ids)
  {
    return;
  }
  ids->Reset();
  if (!std::isfinite(center[0]) || !std::isfinite(center[1]) || !std::isfinite(center[2]))
  {
    return;
  }
  this->ForEachSampleInSphere(
    center, radius, [ids](vtkIdType id, double) { ids->InsertNextId(id); });
}

//------------------------------------------------------------------------------
void vtkOFB::MarkSamplesModified(vtkIdType first, vtkIdType last)
{
  first = std::max<vtkIdType>(first, 0);
  last = std::min(last, this->GetNumberOfSamples());
  if (first >= last)
  {
    return;
  }
  this->Internals->ModifiedRanges.Mark(first, last);
}

//------------------------------------------------------------------------------
void vtkOFB::MarkAllSamplesModified()
{
  this->MarkSamplesModified(0, this->GetNumberOfSamples());
}

//------------------------------------------------------------------------------
void vtkOFB::GetSampleRangesModifiedSince(vtkMTimeType t, vtkIdTypeArray* ranges) const
{
  if (!ranges)
  {
    return;
  }
  ranges->Initialize();
  ranges->SetNumberOfComponents(2);
  const vtkIdType n = this->GetNumberOfSamples();
  if (n == 0)
  {
    return;
  }
  if (this->StructureTime.GetMTime() > t)
  {
    const vtkIdType all[2] = { 0, n };
    ranges->InsertNextTypedTuple(all);
    return;
  }
  this->Internals->ModifiedRanges.GetRangesSince(t, n, ranges);
}

//------------------------------------------------------------------------------
unsigned long vtkOFB::GetActualMemorySize()
{
  unsigned long size = this->Superclass::GetActualMemorySize();
  size += this->CellOffsets->GetActualMemorySize();
  size += this->Depths->GetActualMemorySize();
  size += this->CellIndex->GetActualMemorySize();
  size += this->SampleData->GetActualMemorySize();
  return size;
}

//------------------------------------------------------------------------------
double vtkOFB::GetBytesPerSample()
{
  const vtkIdType n = this->GetNumberOfSamples();
  return n > 0 ? 1024.0 * this->GetActualMemorySize() / n : 0.0;
}

//------------------------------------------------------------------------------
void vtkOFB::ShallowCopy(vtkDataObject* src)
{
  this->CopyFrom(src, false);
}

//------------------------------------------------------------------------------
void vtkOFB::DeepCopy(vtkDataObject* src)
{
  this->CopyFrom(src, true);
}

//------------------------------------------------------------------------------
void vtkOFB::CopyFrom(vtkDataObject* src, bool deep)
{
  vtkOFB* ofb = vtkOFB::SafeDownCast(src);
  if (!ofb)
  {
    vtkErrorMacro(<< (deep ? "DeepCopy" : "ShallowCopy") << ": the source is not a vtkOFB.");
    return;
  }
  if (ofb == this || !this->CheckNotBeingWritten(deep ? "DeepCopy" : "ShallowCopy"))
  {
    return;
  }
  this->Internals->Spares.clear();
  if (deep)
  {
    this->Superclass::DeepCopy(src);
  }
  else
  {
    this->Superclass::ShallowCopy(src);
  }
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = ofb->Origin[a];
    this->Dimensions[a] = ofb->Dimensions[a];
  }
  for (int a = 0; a < 4; ++a)
  {
    this->CellBase[a] = ofb->CellBase[a];
  }
  this->CellSize = ofb->CellSize;
  this->SampleData = vtkSmartPointer<vtkPointData>::New();
  if (deep)
  {
    this->CellOffsets = vtkSmartPointer<vtkTypeUInt32Array>::New();
    this->CellOffsets->DeepCopy(ofb->CellOffsets);
    this->Depths = vtkSmartPointer<vtkFloatArray>::New();
    this->Depths->DeepCopy(ofb->Depths);
    this->CellIndex = vtkSmartPointer<vtkTypeUInt32Array>::New();
    this->CellIndex->DeepCopy(ofb->CellIndex);
    this->SampleData->DeepCopy(ofb->SampleData);
  }
  else
  {
    this->CellOffsets = ofb->CellOffsets;
    this->Depths = ofb->Depths;
    this->CellIndex = ofb->CellIndex;
    this->SampleData->ShallowCopy(ofb->SampleData);
  }
  this->Internals->ModifiedRanges.Clear();
  this->StructureTime.Modified();
  if (!deep && this->CellOffsets &&
    this->CellOffsets.Get() == this->Internals->Recycled.CellOffsets.Get() &&
    this->Depths.Get() == this->Internals->Recycled.Depths.Get() &&
    this->CellIndex.Get() == this->Internals->Recycled.CellIndex.Get() &&
    this->CellSize == this->Internals->Recycled.CellSize &&
    std::equal(this->Origin, this->Origin + 3, this->Internals->Recycled.Origin) &&
    std::equal(this->Dimensions, this->Dimensions + 3, this->Internals->Recycled.Dimensions))
  {
    // The structure this OFB had before Recycle(): not a change; the source's modified
    // ranges carry over.
    this->StructureTime = this->Internals->Recycled.Time;
    this->Internals->ModifiedRanges = ofb->Internals->ModifiedRanges;
  }
  this->Internals->Recycled = vtkInternals::RecycledStructure();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkOFB::BeginExclusiveWrite(const void* owner)
{
  const void* none = nullptr;
  return owner && this->Internals->Writer.compare_exchange_strong(none, owner);
}

//------------------------------------------------------------------------------
void vtkOFB::EndExclusiveWrite(const void* owner)
{
  const void* expected = owner;
  this->Internals->Writer.compare_exchange_strong(expected, nullptr);
}

//------------------------------------------------------------------------------
bool vtkOFB::IsBeingWritten() const
{
  return this->Internals->Writer.load() != nullptr;
}

//------------------------------------------------------------------------------
bool vtkOFB::CheckNotBeingWritten(const char* what)
{
  if (this->Internals->Writer.load() != nullptr)
  {
    vtkErrorMacro(<< what
                  << ": the OFB is being painted (called from an observer of the paint "
                     "call?): refused, nothing changed.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFB::GetData(vtkInformation* info)
{
  return info ? vtkOFB::SafeDownCast(info->Get(DATA_OBJECT())) : nullptr;
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFB::GetData(vtkInformationVector* v, int i)
{
  return vtkOFB::GetData(v->GetInformationObject(i));
}

//------------------------------------------------------------------------------
void vtkOFB::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "CellSize: " << this->CellSize << "\n";
  os << indent << "Dimensions: (" << this->Dimensions[0] << ", " << this->Dimensions[1] << ", "
     << this->Dimensions[2] << ")\n";
  os << indent << "NumberOfCells: " << this->GetNumberOfCells() << "\n";
  os << indent << "NumberOfSamples: " << this->GetNumberOfSamples() << " (X "
     << this->GetNumberOfSamples(0) << ", Y " << this->GetNumberOfSamples(1) << ", Z "
     << this->GetNumberOfSamples(2) << ")\n";
  os << indent << "DepthComplexity: (" << this->GetDepthComplexity(0) << ", "
     << this->GetDepthComplexity(1) << ", " << this->GetDepthComplexity(2) << ")\n";
  os << indent << "NumberOfSpareArrays: " << this->Internals->Spares.size() << "\n";
  os << indent << "SampleData:\n";
  this->SampleData->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
vtkFieldData* vtkOFB::GetAttributesAsFieldData(int type)
{
  if (type == vtkDataObject::POINT)
  {
    return this->GetSampleData();
  }
  return this->Superclass::GetAttributesAsFieldData(type);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFB::GetNumberOfElements(int type)
{
  if (type == vtkDataObject::POINT)
  {
    return this->GetNumberOfSamples();
  }
  return this->Superclass::GetNumberOfElements(type);
}
