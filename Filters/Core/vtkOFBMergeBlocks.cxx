#include "vtkOFBMergeBlocks.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFBInputChecks.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstring>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkOFBMergeBlocks);

namespace
{
/// One block of the output: its flat index and its surface.
struct Block
{
  unsigned int FlatIndex = 0;
  vtkSmartPointer<vtkPolyData> Surface;
};

/// An array of the output: its name, type and components (from the first block that has it).
struct ArraySpec
{
  std::string Name;
  int Type = VTK_FLOAT;
  int Components = 1;
};

/// The surface of a dataset: a vtkPolyData as it is, any other through vtkDataSetSurfaceFilter.
vtkSmartPointer<vtkPolyData> SurfaceOf(vtkDataSet* dataSet)
{
  if (auto* polyData = vtkPolyData::SafeDownCast(dataSet))
  {
    return polyData;
  }
  vtkNew<vtkDataSetSurfaceFilter> extract;
  extract->SetInputData(dataSet);
  extract->Update();
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(extract->GetOutput());
  return surface;
}

/// Whether `array` can be merged: a named, numeric, non-bit array.
bool IsMergeable(vtkAbstractArray* array)
{
  auto* data = vtkDataArray::SafeDownCast(array);
  return data && data->GetName() && data->GetDataType() != VTK_BIT;
}

/// The arrays of `field` in every block (`cells`: cell data, else point data), by first name.
std::vector<ArraySpec> UnionOfArrays(const std::vector<Block>& blocks, bool cells)
{
  std::vector<ArraySpec> specs;
  for (const Block& block : blocks)
  {
    vtkDataSetAttributes* field = cells
      ? static_cast<vtkDataSetAttributes*>(block.Surface->GetCellData())
      : static_cast<vtkDataSetAttributes*>(block.Surface->GetPointData());
    for (int i = 0; i < field->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* array = field->GetAbstractArray(i);
      if (!IsMergeable(array) ||
        (cells && !std::strcmp(array->GetName(), vtkOFBMergeBlocks::BlockIndexArrayName())))
      {
        continue;
      }
      bool known = false;
      for (const ArraySpec& spec : specs)
      {
        known = known || spec.Name == array->GetName();
      }
      if (!known)
      {
        specs.push_back({ array->GetName(), array->GetDataType(), array->GetNumberOfComponents() });
      }
    }
  }
  return specs;
}

/// An array of `spec` with `n` tuples, each the fill (NaN, or `integerFill`).
vtkSmartPointer<vtkDataArray> NewFilledArray(const ArraySpec& spec, vtkIdType n, double integerFill)
{
  auto array = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(spec.Type));
  array->SetName(spec.Name.c_str());
  array->SetNumberOfComponents(spec.Components);
  array->SetNumberOfTuples(n);
  const bool real = spec.Type == VTK_FLOAT || spec.Type == VTK_DOUBLE;
  const double fill = real ? vtkMath::Nan() : integerFill;
  for (int c = 0; c < spec.Components; ++c)
  {
    array->FillComponent(c, fill);
  }
  return array;
}

/**
 * The array of `spec` in `field` of a block with `tuples` tuples, converted to the spec's
 * type; null (after a warning for a wrong length or components) when the block lacks it.
 */
vtkSmartPointer<vtkDataArray> BlockArray(vtkOFBMergeBlocks* self,
  vtkDataSetAttributes* field,
  const ArraySpec& spec,
  vtkIdType tuples,
  const Block& block,
  const char* what)
{
  auto* array = vtkDataArray::SafeDownCast(field->GetAbstractArray(spec.Name.c_str()));
  if (!array)
  {
    return nullptr;
  }
  if (array->GetNumberOfTuples() != tuples || array->GetNumberOfComponents() != spec.Components)
  {
    std::string text = "Block " + std::to_string(block.FlatIndex) + ": the " + what + " array " +
      vtkOFBArrayLength(array, tuples, what == std::string("point") ? "points" : "cells");
    if (array->GetNumberOfComponents() != spec.Components)
    {
      text = "Block " + std::to_string(block.FlatIndex) + ": the " + what + " array '" + spec.Name +
        "' has " + std::to_string(array->GetNumberOfComponents()) + " components, not " +
        std::to_string(spec.Components) + " as in the first block";
    }
    vtkWarningWithObjectMacro(self, << text << ": filled instead.");
    return nullptr;
  }
  if (array->GetDataType() == spec.Type)
  {
    return array;
  }
  auto converted = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(spec.Type));
  converted->DeepCopy(array);
  return converted;
}

/// A 3-D point as a hash key (-0 is 0, so that equal coordinates give equal keys).
struct PointKey
{
  double X[3];
  bool operator==(const PointKey& o) const
  {
    return this->X[0] == o.X[0] && this->X[1] == o.X[1] && this->X[2] == o.X[2];
  }
};

struct PointKeyHash
{
  size_t operator()(const PointKey& k) const
  {
    size_t h = 0;
    for (double x : k.X)
    {
      h = h * 1000003u ^ std::hash<double>()(x + 0.0);
    }
    return h;
  }
};

/// The four cell arrays of a polydata, in vtkPolyData's cell order.
vtkCellArray* CellsOfKind(vtkPolyData* data, int kind)
{
  switch (kind)
  {
    case 0:
      return data->GetVerts();
    case 1:
      return data->GetLines();
    case 2:
      return data->GetPolys();
    default:
      return data->GetStrips();
  }
}
}

//------------------------------------------------------------------------------
struct vtkOFBMergeBlocks::vtkInternals
{
  vtkOFBMergeBlocks* Self;
  std::vector<Block> Blocks;
  /// Output point of each block's points.
  std::vector<std::vector<vtkIdType>> PointMap;
  /// Per block, the output points it brings (ids in the block, then in the output).
  std::vector<vtkSmartPointer<vtkIdList>> NewPointsIn, NewPointsOut;
  vtkIdType NumberOfPoints = 0;
  /// Point arrays that some output points lack (filled there).
  std::set<std::string> IncompletePointArrays;

  /// The dataset blocks with cells, with warnings for those that are not datasets.
  bool CollectBlocks(vtkDataObject* input)
  {
    auto* composite = vtkCompositeDataSet::SafeDownCast(input);
    if (!composite)
    {
      auto* dataSet = vtkDataSet::SafeDownCast(input);
      if (dataSet && dataSet->GetNumberOfCells() > 0)
      {
        this->Blocks.push_back({ 0, SurfaceOf(dataSet) });
      }
      return this->CheckBlocks();
    }
    auto iter = vtk::TakeSmartPointer(composite->NewIterator());
    iter->SkipEmptyNodesOn();
    for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
    {
      vtkDataObject* node = iter->GetCurrentDataObject();
      auto* dataSet = vtkDataSet::SafeDownCast(node);
      if (!dataSet)
      {
        vtkWarningWithObjectMacro(this->Self,
          "Block " << iter->GetCurrentFlatIndex() << " is a " << node->GetClassName()
                   << ", not a dataset: left out.");
        continue;
      }
      if (dataSet->GetNumberOfCells() > 0)
      {
        this->Blocks.push_back({ iter->GetCurrentFlatIndex(), SurfaceOf(dataSet) });
      }
    }
    return this->CheckBlocks();
  }

  /// Whether there is a block with cells, all of whose cells name existing points.
  bool CheckBlocks()
  {
    for (const Block& block : this->Blocks)
    {
      std::string error;
      if (!vtkOFBCheckCellPointIds(block.Surface, error))
      {
        vtkErrorWithObjectMacro(
          this->Self, "Block " << block.FlatIndex << " is invalid: " << error << ".");
        return false;
      }
    }
    if (this->Blocks.empty())
    {
      vtkErrorWithObjectMacro(this->Self,
        "The input has no dataset block with cells: nothing to merge (empty blocks and "
        "blocks that are not datasets are left out).");
      return false;
    }
    return true;
  }

  /// The output point of every block point (merged with earlier blocks' when asked), and
  /// the output points.
  vtkSmartPointer<vtkPoints> MapPoints(bool merge)
  {
    int type = VTK_FLOAT;
    vtkIdType total = 0;
    for (const Block& block : this->Blocks)
    {
      vtkPoints* points = block.Surface->GetPoints();
      type = points && points->GetDataType() == VTK_DOUBLE ? VTK_DOUBLE : type;
      total += block.Surface->GetNumberOfPoints();
    }
    std::unordered_map<PointKey, vtkIdType, PointKeyHash> earlier;
    if (merge && this->Blocks.size() > 1)
    {
      earlier.reserve(static_cast<size_t>(total));
    }
    auto out = vtkSmartPointer<vtkPoints>::New();
    out->SetDataType(type);
    out->Allocate(total);
    for (const Block& block : this->Blocks)
    {
      const vtkIdType n = block.Surface->GetNumberOfPoints();
      std::vector<vtkIdType> map(n);
      auto in = vtkSmartPointer<vtkIdList>::New();
      auto outIds = vtkSmartPointer<vtkIdList>::New();
      for (vtkIdType i = 0; i < n; ++i)
      {
        PointKey key;
        block.Surface->GetPoint(i, key.X);
        for (double& x : key.X)
        {
          x += 0.0;
        }
        const auto found = merge ? earlier.find(key) : earlier.end();
        if (found != earlier.end())
        {
          map[i] = found->second;
          continue;
        }
        map[i] = out->InsertNextPoint(key.X);
        in->InsertNextId(i);
        outIds->InsertNextId(map[i]);
      }
      if (merge && this->Blocks.size() > 1)
      {
        for (vtkIdType i = 0; i < n; ++i)
        {
          PointKey key;
          block.Surface->GetPoint(i, key.X);
          for (double& x : key.X)
          {
            x += 0.0;
          }
          earlier.emplace(key, map[i]); // keeps the first
        }
      }
      this->PointMap.push_back(std::move(map));
      this->NewPointsIn.push_back(in);
      this->NewPointsOut.push_back(outIds);
    }
    this->NumberOfPoints = out->GetNumberOfPoints();
    return out;
  }

  /// The cells of one kind of every block, point ids mapped, in block order.
  vtkSmartPointer<vtkCellArray> AppendCells(int kind)
  {
    vtkIdType nCells = 0, nIds = 0;
    for (const Block& block : this->Blocks)
    {
      vtkCellArray* cells = CellsOfKind(block.Surface, kind);
      nCells += cells ? cells->GetNumberOfCells() : 0;
      nIds += cells ? cells->GetNumberOfConnectivityIds() : 0;
    }
    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    offsets->SetNumberOfValues(nCells + 1);
    connectivity->SetNumberOfValues(nIds);
    vtkIdType* o = offsets->GetPointer(0);
    vtkIdType* c = connectivity->GetPointer(0);
    vtkIdType cell = 0, id = 0;
    o[0] = 0;
    for (size_t b = 0; b < this->Blocks.size(); ++b)
    {
      vtkCellArray* cells = CellsOfKind(this->Blocks[b].Surface, kind);
      if (!cells || cells->GetNumberOfCells() == 0)
      {
        continue;
      }
      const std::vector<vtkIdType>& map = this->PointMap[b];
      auto iter = vtk::TakeSmartPointer(cells->NewIterator());
      for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
      {
        vtkIdType npts;
        const vtkIdType* pts;
        iter->GetCurrentCell(npts, pts);
        for (vtkIdType k = 0; k < npts; ++k)
        {
          c[id++] = map[pts[k]];
        }
        o[++cell] = id;
      }
    }
    auto out = vtkSmartPointer<vtkCellArray>::New();
    out->SetData(offsets, connectivity);
    return out;
  }

  /**
   * The point arrays of the output: each point's values from the first block that has
   * the array and the point, else the fill. Arrays some point lacks are noted in
   * IncompletePointArrays.
   */
  void MergePointData(vtkPointData* out, double integerFill)
  {
    for (const ArraySpec& spec : UnionOfArrays(this->Blocks, false))
    {
      vtkSmartPointer<vtkDataArray> merged =
        NewFilledArray(spec, this->NumberOfPoints, integerFill);
      std::vector<char> set(this->NumberOfPoints, 0);
      for (size_t b = 0; b < this->Blocks.size(); ++b)
      {
        vtkPolyData* surface = this->Blocks[b].Surface;
        vtkSmartPointer<vtkDataArray> array = BlockArray(this->Self,
          surface->GetPointData(),
          spec,
          surface->GetNumberOfPoints(),
          this->Blocks[b],
          "point");
        if (!array)
        {
          continue;
        }
        // The block's own points at once, then its points shared with earlier blocks that
        // have no value yet.
        merged->InsertTuples(this->NewPointsOut[b], this->NewPointsIn[b], array);
        const std::vector<vtkIdType>& map = this->PointMap[b];
        for (vtkIdType k = 0; k < this->NewPointsOut[b]->GetNumberOfIds(); ++k)
        {
          set[this->NewPointsOut[b]->GetId(k)] = 1;
        }
        for (vtkIdType i = 0; i < static_cast<vtkIdType>(map.size()); ++i)
        {
          if (!set[map[i]])
          {
            merged->SetTuple(map[i], i, array);
            set[map[i]] = 1;
          }
        }
      }
      if (std::find(set.begin(), set.end(), 0) != set.end())
      {
        this->IncompletePointArrays.insert(spec.Name);
      }
      out->AddArray(merged);
    }
  }

  /// The cell arrays of the output, in the output's cell order (kinds, then blocks).
  void MergeCellData(vtkCellData* out, double integerFill, vtkIdType nCells)
  {
    // Where each block's cells of each kind start, in the block and in the output.
    const size_t nBlocks = this->Blocks.size();
    std::vector<vtkIdType> inStart(4 * nBlocks), outStart(4 * nBlocks), count(4 * nBlocks);
    vtkIdType next = 0;
    for (int kind = 0; kind < 4; ++kind)
    {
      for (size_t b = 0; b < nBlocks; ++b)
      {
        vtkPolyData* surface = this->Blocks[b].Surface;
        vtkCellArray* cells = CellsOfKind(surface, kind);
        count[4 * b + kind] = cells ? cells->GetNumberOfCells() : 0;
        inStart[4 * b + kind] = kind == 0 ? 0 : inStart[4 * b + kind - 1] + count[4 * b + kind - 1];
        outStart[4 * b + kind] = next;
        next += count[4 * b + kind];
      }
    }
    vtkNew<vtkIntArray> blockIndex;
    blockIndex->SetName(vtkOFBMergeBlocks::BlockIndexArrayName());
    blockIndex->SetNumberOfValues(nCells);
    for (size_t b = 0; b < nBlocks; ++b)
    {
      for (int kind = 0; kind < 4; ++kind)
      {
        std::fill_n(blockIndex->GetPointer(outStart[4 * b + kind]),
          count[4 * b + kind],
          static_cast<int>(this->Blocks[b].FlatIndex));
      }
    }
    for (const ArraySpec& spec : UnionOfArrays(this->Blocks, true))
    {
      vtkSmartPointer<vtkDataArray> merged = NewFilledArray(spec, nCells, integerFill);
      for (size_t b = 0; b < nBlocks; ++b)
      {
        vtkPolyData* surface = this->Blocks[b].Surface;
        vtkSmartPointer<vtkDataArray> array = BlockArray(this->Self,
          surface->GetCellData(),
          spec,
          surface->GetNumberOfCells(),
          this->Blocks[b],
          "cell");
        for (int kind = 0; array && kind < 4; ++kind)
        {
          if (count[4 * b + kind] > 0)
          {
            merged->InsertTuples(
              outStart[4 * b + kind], count[4 * b + kind], inStart[4 * b + kind], array);
          }
        }
      }
      out->AddArray(merged);
    }
    out->AddArray(blockIndex);
  }

  /// The active attributes of `out`: those of the first block with each, by name.
  void SetActiveAttributes(vtkDataSetAttributes* out, bool cells)
  {
    for (int attribute : { vtkDataSetAttributes::SCALARS,
           vtkDataSetAttributes::VECTORS,
           vtkDataSetAttributes::NORMALS,
           vtkDataSetAttributes::TCOORDS })
    {
      for (const Block& block : this->Blocks)
      {
        vtkDataSetAttributes* field = cells
          ? static_cast<vtkDataSetAttributes*>(block.Surface->GetCellData())
          : static_cast<vtkDataSetAttributes*>(block.Surface->GetPointData());
        vtkDataArray* active = field->GetAttribute(attribute);
        // Normals that some points lack are not the normals (vtkOFBSampler computes them).
        const bool incompleteNormals = !cells && active && active->GetName() &&
          attribute == vtkDataSetAttributes::NORMALS &&
          this->IncompletePointArrays.count(active->GetName()) > 0;
        if (active && active->GetName() && out->GetArray(active->GetName()) && !incompleteNormals)
        {
          out->SetActiveAttribute(active->GetName(), attribute);
          break;
        }
      }
    }
  }
};

//------------------------------------------------------------------------------
vtkOFBMergeBlocks::vtkOFBMergeBlocks()
  : MergePoints(true)
  , IntegerFillValue(0.0)
{
}

//------------------------------------------------------------------------------
vtkOFBMergeBlocks::~vtkOFBMergeBlocks() = default;

//------------------------------------------------------------------------------
int vtkOFBMergeBlocks::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBMergeBlocks::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkInternals internals;
  internals.Self = this;
  if (!internals.CollectBlocks(vtkDataObject::GetData(inputVector[0])))
  {
    output->Initialize();
    return 1;
  }
  this->UpdateProgress(0.2);
  output->SetPoints(internals.MapPoints(this->MergePoints));
  this->UpdateProgress(0.5);
  output->SetVerts(internals.AppendCells(0));
  output->SetLines(internals.AppendCells(1));
  output->SetPolys(internals.AppendCells(2));
  output->SetStrips(internals.AppendCells(3));
  this->UpdateProgress(0.7);
  internals.MergePointData(output->GetPointData(), this->IntegerFillValue);
  internals.MergeCellData(
    output->GetCellData(), this->IntegerFillValue, output->GetNumberOfCells());
  internals.SetActiveAttributes(output->GetPointData(), false);
  internals.SetActiveAttributes(output->GetCellData(), true);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBMergeBlocks::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MergePoints: " << (this->MergePoints ? "On" : "Off") << "\n";
  os << indent << "IntegerFillValue: " << this->IntegerFillValue << "\n";
}
