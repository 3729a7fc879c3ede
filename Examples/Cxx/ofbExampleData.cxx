#include "ofbExampleData.h"
#include "ofbExampleDataFile.h"
#include "ofbExampleErrors.h"
#include "ofbExampleMesh.h"
#include "ofbExampleOptions.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLGenericDataObjectReader.h"
#include "vtksys/SystemTools.hxx"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
using SystemTools = vtksys::SystemTools;

/// A leaf data set of the file and its flat index and name.
struct Leaf
{
  unsigned int Index = 0;
  std::string Name;
  vtkDataSet* Data = nullptr;
};

std::vector<Leaf> Leaves(vtkDataObject* data)
{
  std::vector<Leaf> leaves;
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    leaves.push_back(Leaf{ 0, "", ds });
    return leaves;
  }
  auto* tree = vtkDataObjectTree::SafeDownCast(data);
  if (!tree)
  {
    return leaves;
  }
  auto it = vtk::TakeSmartPointer(tree->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  it->SkipEmptyNodesOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    Leaf leaf;
    leaf.Index = it->GetCurrentFlatIndex();
    leaf.Data = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
    {
      leaf.Name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    }
    if (leaf.Data)
    {
      leaves.push_back(leaf);
    }
  }
  return leaves;
}

std::string DescribeLeaves(const std::vector<Leaf>& leaves)
{
  std::string s;
  for (const Leaf& leaf : leaves)
  {
    s += (s.empty() ? "" : ", ") + std::to_string(leaf.Index) +
      (leaf.Name.empty() ? "" : " (" + leaf.Name + ")");
  }
  return s.empty() ? "none" : s;
}

/// The leaves named by `list` (flat indices or names, comma-separated; "" for all).
bool ChooseLeaves(const std::vector<Leaf>& leaves,
  const std::string& list,
  std::vector<Leaf>& chosen,
  std::string& problem)
{
  if (list.empty())
  {
    chosen = leaves;
    return true;
  }
  std::istringstream items(list);
  for (std::string item; std::getline(items, item, ',');)
  {
    auto found = std::find_if(leaves.begin(),
      leaves.end(),
      [&](const Leaf& l) { return l.Name == item || std::to_string(l.Index) == item; });
    if (found == leaves.end())
    {
      problem =
        "no block '" + item + "'; its blocks (flat index and name): " + DescribeLeaves(leaves);
      return false;
    }
    chosen.push_back(*found);
  }
  return true;
}

/// Finite points and cell point ids in range before any filter reads them.
bool CheckLeaf(const Leaf& leaf, std::string& problem)
{
  if (auto* poly = vtkPolyData::SafeDownCast(leaf.Data))
  {
    return poly->GetNumberOfCells() == 0 || ofbexample::CheckPolyData(poly, problem);
  }
  auto* points = vtkPointSet::SafeDownCast(leaf.Data);
  const vtkIdType n = leaf.Data->GetNumberOfPoints();
  for (vtkIdType i = 0; points && i < n; ++i)
  {
    const double* p = points->GetPoint(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      problem = "point " + std::to_string(i) + " is not finite";
      return false;
    }
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(leaf.Data))
  {
    vtkCellArray* cells = grid->GetCells();
    const vtkIdType count = cells ? cells->GetNumberOfCells() : 0;
    if (count != grid->GetNumberOfCells())
    {
      problem = "the cell types and cells disagree";
      return false;
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < count; ++c)
    {
      cells->GetCellAtId(c, ids);
      for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
      {
        if (ids->GetId(j) < 0 || ids->GetId(j) >= n)
        {
          problem = "cell " + std::to_string(c) + " uses point " + std::to_string(ids->GetId(j)) +
            ", not one of the " + std::to_string(n) + " points";
          return false;
        }
      }
    }
  }
  return true;
}

/**
 * The chosen blocks as one surface. A data set: its polygons (a vtkPolyData as it is) or
 * its outer surface (vtkDataSetSurfaceFilter). A composite data set: vtkOFBMergeBlocks on
 * the chosen blocks (the others left empty, so that the flat indices stay the file's), the
 * step by which vtkOFBSampler builds one OFB of a composite input: a cell array
 * "BlockIndex", points shared by blocks merged, the union of the blocks' arrays.
 */
vtkSmartPointer<vtkPolyData> MergeBlocks(vtkDataObject* object,
  const std::vector<Leaf>& chosen,
  std::string& problem)
{
  for (const Leaf& leaf : chosen)
  {
    if (!CheckLeaf(leaf, problem))
    {
      problem = "block " + std::to_string(leaf.Index) + ": " + problem;
      return nullptr;
    }
  }
  vtkNew<ofbexample::FirstError> errors;
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  auto* tree = vtkDataObjectTree::SafeDownCast(object);
  if (!tree)
  {
    if (auto* poly = vtkPolyData::SafeDownCast(object))
    {
      merged->ShallowCopy(poly);
    }
    else
    {
      vtkNew<vtkDataSetSurfaceFilter> filter;
      filter->AddObserver(vtkCommand::ErrorEvent, errors);
      filter->SetInputData(object);
      filter->Update();
      merged->ShallowCopy(filter->GetOutput());
    }
  }
  else
  {
    auto blocks = vtk::TakeSmartPointer(vtkDataObjectTree::SafeDownCast(tree->NewInstance()));
    blocks->CopyStructure(tree);
    auto it = vtk::TakeSmartPointer(tree->NewTreeIterator());
    it->VisitOnlyLeavesOn();
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      const unsigned int index = it->GetCurrentFlatIndex();
      if (std::any_of(
            chosen.begin(), chosen.end(), [index](const Leaf& l) { return l.Index == index; }))
      {
        blocks->SetDataSet(it, it->GetCurrentDataObject());
      }
    }
    vtkNew<vtkOFBMergeBlocks> merge;
    merge->AddObserver(vtkCommand::ErrorEvent, errors);
    merge->SetInputData(blocks);
    merge->Update();
    merged->ShallowCopy(merge->GetOutput());
  }
  if (errors->Count > 0)
  {
    problem = errors->Text;
    return nullptr;
  }
  if (!ofbexample::CheckPolyData(merged, problem))
  {
    return nullptr;
  }
  return merged;
}

void ListArrays(vtkFieldData* data, bool vectors, std::vector<std::string>& names)
{
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = data->GetArray(i);
    if (a && a->GetName() && (a->GetNumberOfComponents() == 3) == vectors)
    {
      names.push_back(a->GetName());
    }
  }
}

std::string Join(const std::vector<std::string>& names)
{
  std::string s;
  for (const std::string& n : names)
  {
    s += (s.empty() ? "" : ", ") + n;
  }
  return s;
}
}

namespace ofbexample
{
const char* DataOptionsUsage()
{
  return "[--field NAME] [--block I|NAME[,...]] [--time T | --time-step N]";
}

bool ParseDataOption(int argc, char* argv[], int& i, DataOptions& options, bool& ok)
{
  const std::string arg = argv[i];
  if (arg != "--field" && arg != "--block" && arg != "--time" && arg != "--time-step")
  {
    return false;
  }
  if (i + 1 >= argc)
  {
    ok = false;
    return true;
  }
  const std::string value = argv[++i];
  if (arg == "--field")
  {
    options.Field = value;
    ok = ok && !value.empty();
  }
  else if (arg == "--block")
  {
    options.Blocks = value;
    ok = ok && !value.empty();
  }
  else if (arg == "--time")
  {
    options.HasTime = true;
    ok = ParseDouble(value, -1e300, 1e300, options.Time) && ok;
  }
  else
  {
    ok = ParseInt(value, 0, 1000000000, options.TimeStep) && ok;
  }
  return true;
}

std::string DescribeArrays(vtkPolyData* surface)
{
  std::vector<std::string> parts;
  const char* kinds[4] = {
    "point vectors: ", "cell vectors: ", "other point arrays: ", "other cell arrays: "
  };
  for (int k = 0; k < 4; ++k)
  {
    std::vector<std::string> names;
    ListArrays(k % 2 == 0 ? static_cast<vtkFieldData*>(surface->GetPointData())
                          : static_cast<vtkFieldData*>(surface->GetCellData()),
      k < 2,
      names);
    if (!names.empty())
    {
      parts.push_back(kinds[k] + Join(names));
    }
  }
  std::string s;
  for (const std::string& part : parts)
  {
    s += (s.empty() ? "" : "; ") + part;
  }
  return parts.empty() ? "no point or cell arrays" : s;
}

bool ReadDataSurface(const std::string& path,
  const DataOptions& options,
  bool vectors,
  DataSurface& data,
  std::string& message)
{
  std::string problem;
  std::string summary;
  vtkSmartPointer<vtkDataObject> object =
    ofbexample::ReadDataFile(path, options, false, summary, problem);
  std::vector<Leaf> chosen;
  vtkSmartPointer<vtkPolyData> surface;
  if (object)
  {
    const std::vector<Leaf> leaves = Leaves(object);
    if (leaves.empty())
    {
      problem = std::string("no data set in the file (") + object->GetClassName() + ")";
    }
    else if (ChooseLeaves(leaves, options.Blocks, chosen, problem))
    {
      surface = MergeBlocks(object, chosen, problem);
    }
  }
  if (!surface)
  {
    message = "cannot read '" + path + "': " + problem;
    return false;
  }
  data.Surface = surface;
  data.Field = nullptr;
  data.FieldOnCells = false;
  if (!options.Field.empty())
  {
    data.Field = surface->GetPointData()->GetArray(options.Field.c_str());
    if (!data.Field)
    {
      data.Field = surface->GetCellData()->GetArray(options.Field.c_str());
      data.FieldOnCells = data.Field != nullptr;
    }
    if (!data.Field)
    {
      message = "'" + path + "' has no point or cell array '" + options.Field +
        "'; its arrays: " + DescribeArrays(surface);
      return false;
    }
    if (vectors && data.Field->GetNumberOfComponents() != 3)
    {
      message = "'" + options.Field + "' of '" + path + "' has " +
        std::to_string(data.Field->GetNumberOfComponents()) +
        " component(s), not a vector field; its arrays: " + DescribeArrays(surface);
      return false;
    }
  }
  data.Summary = summary + ", " + std::to_string(chosen.size()) + " block(s) (" +
    DescribeLeaves(chosen) + "), " + std::to_string(surface->GetNumberOfCells()) + " cells" +
    (data.Field ? std::string(", field '") + options.Field + "' on " +
          (data.FieldOnCells ? "cells" : "points")
                : std::string());
  return true;
}

bool ReadDataTriangles(const std::string& path,
  const DataOptions& options,
  bool vectors,
  DataSurface& data,
  std::string& message)
{
  if (!ReadDataSurface(path, options, vectors, data, message))
  {
    return false;
  }
  vtkSmartPointer<vtkPolyData> surface = TrianglesWithNormals(data.Surface, path, message);
  if (!surface)
  {
    return false;
  }
  data.Surface = surface;
  if (data.Field)
  {
    data.Field = data.FieldOnCells ? surface->GetCellData()->GetArray(options.Field.c_str())
                                   : surface->GetPointData()->GetArray(options.Field.c_str());
  }
  return true;
}

bool ReadDataReported(const char* application,
  const std::string& path,
  const DataOptions& options,
  bool vectors,
  bool triangles,
  DataSurface& data)
{
  std::string message;
  const bool ok = triangles ? ReadDataTriangles(path, options, vectors, data, message)
                            : ReadDataSurface(path, options, vectors, data, message);
  if (!ok)
  {
    std::cerr << application << ": " << message << "\n";
    return false;
  }
  std::cout << "read " << path << ": " << data.Summary << "\n";
  return true;
}

void SetFieldAsVectors(DataSurface& data)
{
  vtkDataSetAttributes* points = data.Surface->GetPointData();
  vtkDataSetAttributes* cells = data.Surface->GetCellData();
  (data.FieldOnCells ? points : cells)->SetActiveAttribute(-1, vtkDataSetAttributes::VECTORS);
  (data.FieldOnCells ? cells : points)->SetVectors(data.Field);
}

void UseFieldAsVectors(DataSurface& data, double range[2])
{
  SetFieldAsVectors(data);
  vtkDataSetAttributes* on = data.FieldOnCells
    ? static_cast<vtkDataSetAttributes*>(data.Surface->GetCellData())
    : static_cast<vtkDataSetAttributes*>(data.Surface->GetPointData());
  vtkNew<vtkFloatArray> speed;
  speed->SetName("Speed");
  speed->SetNumberOfTuples(data.Field->GetNumberOfTuples());
  for (vtkIdType i = 0; i < data.Field->GetNumberOfTuples(); ++i)
  {
    double v[3];
    data.Field->GetTuple(i, v);
    const double m = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    speed->SetValue(i, static_cast<float>(std::isfinite(m) ? m : 0.0));
  }
  on->AddArray(speed);
  speed->GetRange(range);
}
}
