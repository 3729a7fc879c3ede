#include "vtkOFBSamplePack.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"

#include <algorithm>
#include <cmath>
#include <numeric>

vtkStandardNewMacro(vtkOFBSamplePack);

namespace
{
const char* const GhostName = "vtkGhostType";
const char* const FrameSuffix = "Frame";
const char* const CellSuffix = "Cell";
const char* const DepthSuffix = "Depth";
const char* const SampleSuffix = "Sample_"; // + a sample array's name
const char* const AttributesSuffix = "Attributes";

/// Calls `visit` with the field data of `data` and of each of its blocks.
template<typename Visit>
void ForEachFieldData(vtkDataObject* data, Visit&& visit)
{
  if (data && data->GetFieldData())
  {
    visit(data->GetFieldData());
  }
  if (auto composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      vtkDataObject* block = it->GetCurrentDataObject();
      if (block && block->GetFieldData())
      {
        visit(block->GetFieldData());
      }
    }
  }
}

struct Sample
{
  vtkTypeUInt32 Cell;
  float Depth;
  int Pack;
  vtkIdType Index;
};

/// The frame of a pack (`frame`, 7 values) as origin, cell size and dimensions; false
/// where a value is not finite or a dimension not an integer in [1, 2^31).
bool ReadFrame(vtkDataArray* frame, double origin[3], double& cellSize, vtkIdType dims[3])
{
  if (!frame || frame->GetNumberOfTuples() * frame->GetNumberOfComponents() != 7)
  {
    return false;
  }
  double values[7];
  for (int i = 0; i < 7; ++i)
  {
    values[i] =
      frame->GetComponent(i / frame->GetNumberOfComponents(), i % frame->GetNumberOfComponents());
    if (!std::isfinite(values[i]))
    {
      return false;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    origin[i] = values[i];
    const double d = values[4 + i];
    if (!(d >= 1.0 && d < 2147483648.0) || d != std::floor(d))
    {
      return false;
    }
    dims[i] = static_cast<vtkIdType>(d);
  }
  cellSize = values[3];
  return cellSize > 0.0;
}

/// What Merge collects from the packs.
struct Collected
{
  double Origin[3] = { 0, 0, 0 };
  double CellSize = 0.0;
  vtkIdType Dims[3] = { 0, 0, 0 };
  std::vector<Sample> Samples;
  std::vector<vtkIdType> Counts; // samples a pack
  int First = -1;                // the first pack with samples: the arrays to merge
};

/// The samples of every pack (cell, depth, pack, index) and their common frame: Merge's
/// first step. False with `problem` set where a pack is inconsistent or the frames differ.
bool CollectSamples(const std::vector<vtkOFBSamplePack::PackRef>& packs,
  Collected& c,
  std::string& problem)
{
  c.Counts.assign(packs.size(), 0);
  double& cellSize = c.CellSize;
  double* origin = c.Origin;
  vtkIdType* dims = c.Dims;
  std::vector<Sample>& samples = c.Samples;
  std::vector<vtkIdType>& counts = c.Counts;
  int& first = c.First;
  for (size_t p = 0; p < packs.size(); ++p)
  {
    vtkFieldData* fields = packs[p].Fields;
    const std::string& prefix = packs[p].Prefix;
    vtkAbstractArray* frameArray =
      fields ? fields->GetAbstractArray((prefix + FrameSuffix).c_str()) : nullptr;
    if (!frameArray)
    {
      continue;
    }
    double o[3];
    double size;
    vtkIdType d[3];
    if (!ReadFrame(vtkDataArray::SafeDownCast(frameArray), o, size, d))
    {
      problem = "the frame '" + prefix + FrameSuffix + "' is not 7 finite values";
      return false;
    }
    if (!(cellSize > 0.0))
    {
      std::copy(o, o + 3, origin);
      std::copy(d, d + 3, dims);
      cellSize = size;
    }
    if (size != cellSize || !std::equal(o, o + 3, origin) || !std::equal(d, d + 3, dims))
    {
      problem = "the processes' OFBs have different frames (sample them with one frame: "
                "vtkOFBPSampler, OFB Sampler)";
      return false;
    }
    // The legacy format the controller sends reads vtkTypeUInt32 back as unsigned int.
    vtkAbstractArray* cellArray = fields->GetAbstractArray((prefix + CellSuffix).c_str());
    vtkAbstractArray* depthArray = fields->GetAbstractArray((prefix + DepthSuffix).c_str());
    if (!cellArray && !depthArray)
    {
      continue; // a piece without samples
    }
    auto cells = vtkUnsignedIntArray::SafeDownCast(cellArray);
    auto depths = vtkFloatArray::SafeDownCast(depthArray);
    if (!cells || !depths || cells->GetNumberOfComponents() != 1 ||
      depths->GetNumberOfComponents() != 1 ||
      cells->GetNumberOfTuples() != depths->GetNumberOfTuples())
    {
      problem = "the cells and depths of '" + prefix +
        "' are missing, of other types than unsigned int and float, or of different lengths";
      return false;
    }
    first = first < 0 ? static_cast<int>(p) : first;
    counts[p] = cells->GetNumberOfTuples();
    for (vtkIdType i = 0; i < cells->GetNumberOfTuples(); ++i)
    {
      if (!std::isfinite(depths->GetValue(i)))
      {
        problem = "a depth of '" + prefix + "' is not finite";
        return false;
      }
      samples.push_back({ cells->GetValue(i), depths->GetValue(i), static_cast<int>(p), i });
    }
  }
  return true;
}

/// The merged OFB's frame, cells and depths from the collected samples, sorted per cell
/// by depth (ties in pack order): Merge's second step. Null where there is no frame; null
/// with `problem` set where the frame or the samples do not fit.
vtkSmartPointer<vtkOFB> BuildStructure(Collected& c, std::string& problem)
{
  double& cellSize = c.CellSize;
  double* origin = c.Origin;
  vtkIdType* dims = c.Dims;
  std::vector<Sample>& samples = c.Samples;
  auto ofb = vtkSmartPointer<vtkOFB>::New();
  if (!(cellSize > 0.0))
  {
    return nullptr;
  }
  if (!ofb->SetFrame(origin, cellSize, dims))
  {
    problem = "the frame cannot be set (too many cells)";
    return nullptr;
  }
  std::stable_sort(samples.begin(),
    samples.end(),
    [](const Sample& a, const Sample& b)
    { return a.Cell != b.Cell ? a.Cell < b.Cell : a.Depth < b.Depth; });
  const vtkIdType n = static_cast<vtkIdType>(samples.size());
  vtkTypeUInt32Array* offsets = ofb->GetCellOffsets();
  const vtkIdType numberOfCells = ofb->GetNumberOfCells();
  if (!samples.empty() && static_cast<vtkIdType>(samples.back().Cell) >= numberOfCells)
  {
    problem = "a sample's cell is outside the frame";
    return nullptr;
  }
  std::vector<vtkTypeUInt32> cellCounts(numberOfCells + 1, 0);
  for (const Sample& sample : samples)
  {
    ++cellCounts[sample.Cell + 1];
  }
  std::partial_sum(cellCounts.begin(), cellCounts.end(), cellCounts.begin());
  std::copy(cellCounts.begin(), cellCounts.end(), offsets->GetPointer(0));
  if (!ofb->AllocateSamples(n))
  {
    problem = "the samples cannot be allocated";
    return nullptr;
  }
  float* depthValues = ofb->GetDepths()->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    depthValues[i] = samples[i].Depth;
  }
  if (!ofb->BuildCellIndex())
  {
    problem = "the cell index cannot be built";
    return nullptr;
  }
  return ofb;
}

/// Every sample array of the first pack with samples, filled pack by pack in the merged
/// order, with its attribute role: Merge's last step. False with `problem` set where a
/// pack's array does not fit its samples.
bool MergeArrays(const std::vector<vtkOFBSamplePack::PackRef>& packs,
  const Collected& c,
  vtkOFB* ofb,
  std::string& problem)
{
  const std::vector<Sample>& samples = c.Samples;
  const std::vector<vtkIdType>& counts = c.Counts;
  const int first = c.First;
  const vtkIdType n = static_cast<vtkIdType>(samples.size());
  // The sample arrays of the first pack with samples, filled pack by pack.
  std::vector<vtkSmartPointer<vtkIdList>> from(packs.size()), to(packs.size());
  for (size_t p = 0; p < packs.size(); ++p)
  {
    from[p] = vtkSmartPointer<vtkIdList>::New();
    to[p] = vtkSmartPointer<vtkIdList>::New();
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    from[samples[i].Pack]->InsertNextId(samples[i].Index);
    to[samples[i].Pack]->InsertNextId(i);
  }
  const std::string modelPrefix = packs[first].Prefix + SampleSuffix;
  vtkFieldData* model = packs[first].Fields;
  auto attributes = vtkIntArray::SafeDownCast(
    model->GetAbstractArray((packs[first].Prefix + AttributesSuffix).c_str()));
  int packed = 0; // the rank of the sample array among the packed ones
  for (int a = 0; a < model->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* modelArray = vtkDataArray::SafeDownCast(model->GetAbstractArray(a));
    const std::string name =
      modelArray && modelArray->GetName() ? modelArray->GetName() : std::string();
    if (name.compare(0, modelPrefix.size(), modelPrefix) != 0)
    {
      continue;
    }
    const std::string sampleName = name.substr(modelPrefix.size());
    vtkSmartPointer<vtkDataArray> merged;
    merged.TakeReference(modelArray->NewInstance());
    merged->SetName(sampleName.c_str());
    merged->SetNumberOfComponents(modelArray->GetNumberOfComponents());
    merged->SetNumberOfTuples(n);
    merged->Fill(0.0);
    for (size_t p = 0; p < packs.size(); ++p)
    {
      if (to[p]->GetNumberOfIds() == 0)
      {
        continue;
      }
      vtkDataArray* source = vtkDataArray::SafeDownCast(
        packs[p].Fields->GetAbstractArray((packs[p].Prefix + SampleSuffix + sampleName).c_str()));
      if (!source)
      {
        continue; // this piece's samples keep zeros
      }
      if (source->GetNumberOfComponents() != merged->GetNumberOfComponents() ||
        source->GetNumberOfTuples() != counts[p])
      {
        problem = "the sample array '" + sampleName + "' of '" + packs[p].Prefix +
          "' has other components or another length than its samples";
        return false;
      }
      merged->InsertTuples(to[p], from[p], source);
    }
    vtkPointData* data = ofb->GetSampleData();
    data->AddArray(merged);
    for (int t = 0; t < vtkDataSetAttributes::NUM_ATTRIBUTES; ++t)
    {
      const bool active = attributes
        ? attributes->GetNumberOfValues() == vtkDataSetAttributes::NUM_ATTRIBUTES &&
          attributes->GetValue(t) == packed
        : (t == vtkDataSetAttributes::SCALARS && sampleName == vtkOFB::ColorsArrayName()) ||
          (t == vtkDataSetAttributes::NORMALS && sampleName == vtkOFB::NormalsArrayName());
      if (active)
      {
        data->SetActiveAttribute(merged->GetName(), t);
      }
    }
    ++packed;
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkOFBSamplePack::vtkOFBSamplePack()
  : MergedPacksTime(0)
{
}

//------------------------------------------------------------------------------
vtkOFBSamplePack::~vtkOFBSamplePack() = default;

//------------------------------------------------------------------------------
vtkIdType vtkOFBSamplePack::Pack(vtkOFB* ofb, vtkFieldData* fields, const char* prefix)
{
  if (!ofb || !fields || !prefix || !(ofb->GetCellSize() > 0.0))
  {
    return -1;
  }
  const std::string base = prefix;
  vtkNew<vtkDoubleArray> frame;
  frame->SetName((base + FrameSuffix).c_str());
  frame->SetNumberOfValues(7);
  for (int i = 0; i < 3; ++i)
  {
    frame->SetValue(i, ofb->GetOrigin()[i]);
    frame->SetValue(4 + i, static_cast<double>(ofb->GetDimensions()[i]));
  }
  frame->SetValue(3, ofb->GetCellSize());
  fields->AddArray(frame);

  // The owned samples: a zero (or no) ghost value.
  vtkPointData* data = ofb->GetSampleData();
  vtkDataArray* ghosts = data->GetArray(GhostName);
  auto bytes = vtkUnsignedCharArray::SafeDownCast(ghosts);
  vtkNew<vtkIdList> owned;
  for (vtkIdType i = 0, n = ofb->GetNumberOfSamples(); i < n; ++i)
  {
    if (!ghosts || (bytes ? bytes->GetValue(i) == 0 : ghosts->GetComponent(i, 0) == 0.0))
    {
      owned->InsertNextId(i);
    }
  }
  if (owned->GetNumberOfIds() == 0)
  {
    return 0;
  }
  auto take = [&](vtkAbstractArray* source, const std::string& name)
  {
    vtkSmartPointer<vtkAbstractArray> copy;
    copy.TakeReference(source->NewInstance());
    copy->SetNumberOfComponents(source->GetNumberOfComponents());
    copy->SetName(name.c_str());
    copy->SetNumberOfTuples(owned->GetNumberOfIds());
    source->GetTuples(owned, copy);
    fields->AddArray(copy);
  };
  take(ofb->GetCellIndex(), base + CellSuffix);
  take(ofb->GetDepths(), base + DepthSuffix);
  // The attributes (active scalars, vectors, normals, ...): the rank of their array among
  // the packed sample arrays, -1 for none.
  vtkNew<vtkIntArray> attributes;
  attributes->SetName((base + AttributesSuffix).c_str());
  attributes->SetNumberOfValues(vtkDataSetAttributes::NUM_ATTRIBUTES);
  attributes->Fill(-1);
  int packed = 0;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
    if (array && array->GetName() && std::string(array->GetName()) != GhostName)
    {
      take(array, base + SampleSuffix + array->GetName());
      for (int t = 0; t < vtkDataSetAttributes::NUM_ATTRIBUTES; ++t)
      {
        if (data->GetAttribute(t) == array)
        {
          attributes->SetValue(t, packed);
        }
      }
      ++packed;
    }
  }
  fields->AddArray(attributes);
  return owned->GetNumberOfIds();
}

//------------------------------------------------------------------------------
void vtkOFBSamplePack::RemovePacks(vtkFieldData* fields, const char* prefix)
{
  if (!fields || !prefix)
  {
    return;
  }
  const std::string base = prefix;
  for (int a = fields->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    const char* name =
      fields->GetAbstractArray(a) ? fields->GetAbstractArray(a)->GetName() : nullptr;
    if (name && std::string(name).compare(0, base.size(), base) == 0)
    {
      fields->RemoveArray(a);
    }
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBSamplePack::GetBytesPerSample(vtkOFB* ofb)
{
  vtkIdType bytes = 8;
  vtkPointData* data = ofb ? ofb->GetSampleData() : nullptr;
  for (int a = 0; data && a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
    if (array && array->GetName() && std::string(array->GetName()) != GhostName)
    {
      bytes += array->GetNumberOfComponents() * array->GetDataTypeSize();
    }
  }
  return bytes;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBSamplePack::PackIntoBlocks(vtkDataObject* blocks, vtkOFB* ofb, int rank)
{
  auto multiBlock = vtkMultiBlockDataSet::SafeDownCast(blocks);
  if (!multiBlock || !ofb)
  {
    return -1;
  }
  for (unsigned int b = 0; b < multiBlock->GetNumberOfBlocks(); ++b)
  {
    auto block = vtkPolyData::SafeDownCast(multiBlock->GetBlock(b));
    if (!block)
    {
      continue;
    }
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    piece->ShallowCopy(block);
    vtkNew<vtkFieldData> fields;
    fields->ShallowCopy(block->GetFieldData());
    vtkOFBSamplePack::RemovePacks(fields, vtkOFBSamplePack::PiecePrefix());
    const std::string prefix = vtkOFBSamplePack::PiecePrefix() + std::to_string(rank) + "_";
    const vtkIdType packed = vtkOFBSamplePack::Pack(ofb, fields, prefix.c_str());
    if (packed < 0)
    {
      return -1;
    }
    piece->SetFieldData(fields);
    multiBlock->SetBlock(b, piece);
    return packed;
  }
  return -1;
}

//------------------------------------------------------------------------------
std::vector<vtkOFBSamplePack::PackRef> vtkOFBSamplePack::FindPacks(vtkFieldData* fields,
  const char* base)
{
  std::vector<PackRef> packs;
  const std::string start = base ? base : "";
  const std::string suffix = FrameSuffix;
  for (int a = 0; fields && a < fields->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = fields->GetAbstractArray(a);
    const std::string name = array && array->GetName() ? array->GetName() : "";
    if (name.size() >= start.size() + suffix.size() && name.compare(0, start.size(), start) == 0 &&
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
    {
      packs.push_back({ fields, name.substr(0, name.size() - suffix.size()) });
    }
  }
  std::sort(packs.begin(),
    packs.end(),
    [](const PackRef& a, const PackRef& b)
    {
      return a.Prefix.size() != b.Prefix.size() ? a.Prefix.size() < b.Prefix.size()
                                                : a.Prefix < b.Prefix;
    });
  return packs;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkOFB> vtkOFBSamplePack::Merge(const std::vector<PackRef>& packs,
  std::string& problem)
{
  Collected collected;
  if (!CollectSamples(packs, collected, problem))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkOFB> ofb = BuildStructure(collected, problem);
  if (!ofb || collected.First < 0)
  {
    return ofb;
  }
  return MergeArrays(packs, collected, ofb, problem) ? ofb : nullptr;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkOFB> vtkOFBSamplePack::MergeFromBlocks(vtkDataObject* data, std::string& problem)
{
  std::vector<PackRef> packs;
  ForEachFieldData(data,
    [&packs](vtkFieldData* fields)
    {
      std::vector<PackRef> found = vtkOFBSamplePack::FindPacks(fields, PiecePrefix());
      packs.insert(packs.end(), found.begin(), found.end());
    });
  return packs.empty() ? nullptr : vtkOFBSamplePack::Merge(packs, problem);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBSamplePack::GetPacksMTime(vtkDataObject* data)
{
  vtkMTimeType sum = 0;
  const std::string prefix = PiecePrefix();
  ForEachFieldData(data,
    [&sum, &prefix](vtkFieldData* fields)
    {
      for (int a = 0; a < fields->GetNumberOfArrays(); ++a)
      {
        vtkAbstractArray* array = fields->GetAbstractArray(a);
        if (array && array->GetName() &&
          std::string(array->GetName()).compare(0, prefix.size(), prefix) == 0)
        {
          sum += array->GetMTime();
        }
      }
    });
  return sum;
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBSamplePack::UpdateMergedOFB(vtkDataObject* data)
{
  const vtkMTimeType packs = vtkOFBSamplePack::GetPacksMTime(data);
  if (packs == this->MergedPacksTime)
  {
    return this->MergedOFB;
  }
  this->MergedPacksTime = packs;
  std::string problem;
  this->MergedOFB = packs ? vtkOFBSamplePack::MergeFromBlocks(data, problem) : nullptr;
  if (!problem.empty() && problem != this->MergeProblem)
  {
    vtkErrorMacro("The OFB delivered with the surface cannot be used ("
      << problem << "): the OFB is built from the surface.");
  }
  this->MergeProblem = problem;
  return this->MergedOFB;
}

//------------------------------------------------------------------------------
void vtkOFBSamplePack::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PiecePrefix: " << vtkOFBSamplePack::PiecePrefix() << "\n";
  os << indent << "MergedOFB: " << this->MergedOFB.Get() << "\n";
  os << indent << "MergeProblem: " << this->MergeProblem << "\n";
}
