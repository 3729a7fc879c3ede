#include "ofbExampleData.h"
#include "ofbExampleErrors.h"
#include "ofbExampleMesh.h"
#include "ofbExampleOptions.h"

#include "vtkAppendPolyData.h"
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
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
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
#include <sstream>

namespace
{
using SystemTools = vtksys::SystemTools;

/// The formats told apart by content.
enum class Format
{
  XML,
  Collection,
  Legacy,
  PLY,
  STL,
  OBJ,
  Unknown
};

const char* FormatName(Format f)
{
  const char* names[] = {
    "VTK XML", "ParaView collection (.pvd)", "legacy VTK", "PLY", "STL", "OBJ", "unknown"
  };
  return names[static_cast<int>(f)];
}

/// The format of the file by its first bytes, else by its extension.
Format Detect(const std::string& path, long long size, std::string& xmlType)
{
  std::ifstream in(path, std::ios::binary);
  std::string head(1024, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  std::string text = head;
  text.erase(0, text.find_first_not_of(" \t\r\n\xEF\xBB\xBF"));
  if (text.compare(0, 5, "<?xml") == 0 || text.compare(0, 8, "<VTKFile") == 0)
  {
    const std::string::size_type t = text.find("type=\"");
    if (t != std::string::npos)
    {
      xmlType = text.substr(t + 6, text.find('"', t + 6) - t - 6);
    }
    return xmlType == "Collection" ? Format::Collection : Format::XML;
  }
  if (text.compare(0, 14, "# vtk DataFile") == 0)
  {
    return Format::Legacy;
  }
  if (text.compare(0, 4, "ply\n") == 0 || text.compare(0, 5, "ply\r\n") == 0)
  {
    return Format::PLY;
  }
  if (text.compare(0, 5, "solid") == 0)
  {
    return Format::STL;
  }
  if (head.size() >= 84)
  {
    const auto* b = reinterpret_cast<const unsigned char*>(head.data()) + 80;
    const long long triangles = static_cast<long long>(b[0]) | (b[1] << 8) | (b[2] << 16) |
      (static_cast<long long>(b[3]) << 24);
    if (size == 84 + 50 * triangles)
    {
      return Format::STL;
    }
  }
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path));
  if (ext == ".obj")
  {
    return Format::OBJ;
  }
  if (ext == ".stl")
  {
    return Format::STL; // a binary STL of the wrong size: its check says so
  }
  if (ext == ".ply")
  {
    return Format::PLY;
  }
  // An OBJ without the extension: its first statement is one of OBJ's.
  std::istringstream lines(head);
  for (std::string line; std::getline(lines, line);)
  {
    std::istringstream words(line);
    std::string word;
    if (!(words >> word) || word[0] == '#')
    {
      continue;
    }
    const char* obj[] = { "v", "vt", "vn", "f", "o", "g", "s", "mtllib", "usemtl", "l", "p" };
    return std::find(std::begin(obj), std::end(obj), word) != std::end(obj) ? Format::OBJ
                                                                            : Format::Unknown;
  }
  return Format::Unknown;
}

/// The step of `times` that the options ask for (0 without a time option); false with
/// `problem` naming the range.
bool ChooseStep(const std::vector<double>& times,
  const ofbexample::DataOptions& options,
  size_t& step,
  std::string& problem)
{
  step = 0;
  const bool asked = options.HasTime || options.TimeStep >= 0;
  if (times.empty())
  {
    problem = asked ? "the file has no time steps (--time and --time-step need a .pvd or a file "
                      "with time steps)"
                    : "";
    return !asked;
  }
  std::ostringstream range;
  range << times.size() << " time step" << (times.size() > 1 ? "s" : "") << ", times "
        << times.front() << " to " << times.back();
  if (options.TimeStep >= 0)
  {
    if (static_cast<size_t>(options.TimeStep) >= times.size())
    {
      problem = "time step " + std::to_string(options.TimeStep) + " is outside the file's " +
        range.str() + " (steps 0 to " + std::to_string(times.size() - 1) + ")";
      return false;
    }
    step = static_cast<size_t>(options.TimeStep);
    return true;
  }
  if (options.HasTime)
  {
    const double span = times.back() - times.front();
    const double slack = 1e-9 * std::max(1.0, std::abs(span));
    if (options.Time < times.front() - slack || options.Time > times.back() + slack)
    {
      std::ostringstream t;
      t << options.Time;
      problem = "time " + t.str() + " is outside the file's " + range.str();
      return false;
    }
    for (size_t i = 1; i < times.size(); ++i)
    {
      if (std::abs(times[i] - options.Time) < std::abs(times[step] - options.Time))
      {
        step = i;
      }
    }
  }
  return true;
}

std::string TimeSummary(const std::vector<double>& times, size_t step)
{
  if (times.empty())
  {
    return "";
  }
  std::ostringstream s;
  s << ", time step " << step << " of 0-" << times.size() - 1 << " (t = " << times[step] << ")";
  return s.str();
}

/// A VTK XML or legacy file, at the options' time step.
vtkSmartPointer<vtkDataObject> ReadVTK(const std::string& path,
  Format format,
  const ofbexample::DataOptions& options,
  std::string& summary,
  std::string& problem)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  vtkNew<ofbexample::FirstError> errors;
  if (format == Format::XML)
  {
    auto xml = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
    xml->AddObserver(vtkCommand::ErrorEvent, errors);
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  else
  {
    auto legacy = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    legacy->AddObserver(vtkCommand::ErrorEvent, errors);
    legacy->SetFileName(path.c_str());
    legacy->ReadAllScalarsOn();
    legacy->ReadAllVectorsOn();
    legacy->ReadAllNormalsOn();
    legacy->ReadAllTensorsOn();
    legacy->ReadAllFieldsOn();
    reader = legacy;
  }
  reader->UpdateInformation();
  std::vector<double> times;
  vtkInformation* info = errors->Count == 0 ? reader->GetOutputInformation(0) : nullptr;
  if (info && info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    const double* t = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    times.assign(t, t + info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  }
  size_t step = 0;
  if (errors->Count == 0 && !ChooseStep(times, options, step, problem))
  {
    return nullptr;
  }
  if (errors->Count == 0)
  {
    if (times.empty())
    {
      reader->Update();
    }
    else
    {
      reader->UpdateTimeStep(times[step]);
    }
  }
  vtkDataObject* data = reader->GetOutputDataObject(0);
  if (errors->Count > 0 || !data)
  {
    problem = errors->Text.empty() ? "the reader failed" : errors->Text;
    return nullptr;
  }
  summary = std::string(FormatName(format)) + " " + data->GetClassName() + TimeSummary(times, step);
  return data;
}

/// The data of one file: a VTK file, or a mesh through ReadMeshChecked.
vtkSmartPointer<vtkDataObject> ReadFile(const std::string& path,
  const ofbexample::DataOptions& options,
  bool inCollection,
  std::string& summary,
  std::string& problem);

/// A .pvd: its DataSet entries (timestep, part, file); the parts of the chosen step as
/// the blocks of a multiblock, in the order of their part numbers.
vtkSmartPointer<vtkDataObject> ReadCollection(const std::string& path,
  const ofbexample::DataOptions& options,
  std::string& summary,
  std::string& problem)
{
  vtkNew<vtkXMLDataParser> parser;
  vtkNew<ofbexample::FirstError> errors;
  parser->AddObserver(vtkCommand::ErrorEvent, errors);
  parser->SetFileName(path.c_str());
  vtkXMLDataElement* root =
    parser->Parse() && errors->Count == 0 ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* collection = root ? root->FindNestedElementWithName("Collection") : nullptr;
  if (!collection)
  {
    problem = "not a readable .pvd collection" + errors->Suffix();
    return nullptr;
  }
  struct Entry
  {
    double Time;
    int Part;
    std::string File;
  };
  std::vector<Entry> entries;
  std::vector<double> times;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    if (!e->GetName() || std::strcmp(e->GetName(), "DataSet") != 0)
    {
      continue;
    }
    Entry entry{ 0.0, 0, e->GetAttribute("file") ? e->GetAttribute("file") : "" };
    e->GetScalarAttribute("timestep", entry.Time);
    e->GetScalarAttribute("part", entry.Part);
    if (entry.File.empty() || !std::isfinite(entry.Time))
    {
      problem = "DataSet entry " + std::to_string(i) + " has no file or a bad timestep";
      return nullptr;
    }
    entries.push_back(entry);
    times.push_back(entry.Time);
  }
  if (entries.empty())
  {
    problem = "the collection lists no DataSet";
    return nullptr;
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  size_t step = 0;
  if (!ChooseStep(times, options, step, problem))
  {
    return nullptr;
  }
  std::stable_sort(
    entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.Part < b.Part; });
  const std::string directory = SystemTools::GetFilenamePath(path);
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  for (const Entry& entry : entries)
  {
    if (entry.Time != times[step])
    {
      continue;
    }
    const std::string file = SystemTools::FileIsFullPath(entry.File)
      ? entry.File
      : (directory.empty() ? entry.File : directory + "/" + entry.File);
    std::string partSummary;
    vtkSmartPointer<vtkDataObject> part = ReadFile(file, options, true, partSummary, problem);
    if (!part)
    {
      problem = "its file '" + entry.File + "': " + problem;
      return nullptr;
    }
    const unsigned int b = blocks->GetNumberOfBlocks();
    blocks->SetBlock(b, part);
    blocks->GetMetaData(b)->Set(
      vtkCompositeDataSet::NAME(), SystemTools::GetFilenameWithoutLastExtension(entry.File));
  }
  summary = std::string(FormatName(Format::Collection)) + " of " +
    std::to_string(blocks->GetNumberOfBlocks()) + " part(s)" + TimeSummary(times, step);
  return blocks;
}

vtkSmartPointer<vtkDataObject> ReadFile(const std::string& path,
  const ofbexample::DataOptions& options,
  bool inCollection,
  std::string& summary,
  std::string& problem)
{
  struct stat info;
  const bool found = stat(path.c_str(), &info) == 0;
  if (!found || !S_ISREG(info.st_mode))
  {
    problem = !found
      ? (errno == ENOENT ? "no such file" : std::strerror(errno))
      : (S_ISDIR(info.st_mode) ? "a directory, not a data file" : "not a regular file");
    return nullptr;
  }
  std::string xmlType;
  const Format format = Detect(path, info.st_size, xmlType);
  switch (format)
  {
    case Format::Collection:
      if (inCollection)
      {
        problem = "a collection inside a collection";
        return nullptr;
      }
      return ReadCollection(path, options, summary, problem);
    case Format::XML:
    case Format::Legacy:
      // Time options apply to the collection's steps, not to the files of a step.
      return ReadVTK(
        path, format, inCollection ? ofbexample::DataOptions() : options, summary, problem);
    case Format::PLY:
    case Format::STL:
    case Format::OBJ:
    {
      if (!inCollection && (options.HasTime || options.TimeStep >= 0))
      {
        problem = "the file has no time steps (--time and --time-step need a .pvd or a file "
                  "with time steps)";
        return nullptr;
      }
      const char* ext = format == Format::PLY ? ".ply" : (format == Format::STL ? ".stl" : ".obj");
      std::string message;
      vtkSmartPointer<vtkPolyData> mesh = ofbexample::ReadMeshChecked(path, message, ext);
      if (!mesh)
      {
        const std::string prefix = "cannot read '" + path + "': ";
        problem =
          message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size()) : message;
        return nullptr;
      }
      summary = FormatName(format);
      return mesh;
    }
    default:
      break;
  }
  problem = "unknown format: not a VTK XML (.vtp, .vtu, .vtm, ...), .pvd, legacy .vtk, PLY, "
            "STL or OBJ file (extension '" +
    SystemTools::GetFilenameLastExtension(path) + "')";
  return nullptr;
}

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
 * The chosen blocks as one surface: the outer surface of each (vtkDataSetSurfaceFilter;
 * polydata as they are), appended, with (for the blocks of a composite file) the cell array
 * "BlockIndex" (each block's flat index). vtkAppendPolyData keeps the arrays that every
 * block has.
 */
vtkSmartPointer<vtkPolyData> MergeBlocks(const std::vector<Leaf>& chosen,
  bool composite,
  std::string& problem)
{
  vtkNew<ofbexample::FirstError> errors;
  vtkNew<vtkAppendPolyData> append;
  append->AddObserver(vtkCommand::ErrorEvent, errors);
  for (const Leaf& leaf : chosen)
  {
    if (!CheckLeaf(leaf, problem))
    {
      problem = "block " + std::to_string(leaf.Index) + ": " + problem;
      return nullptr;
    }
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    if (auto* poly = vtkPolyData::SafeDownCast(leaf.Data))
    {
      surface->ShallowCopy(poly);
    }
    else
    {
      vtkNew<vtkDataSetSurfaceFilter> filter;
      filter->AddObserver(vtkCommand::ErrorEvent, errors);
      filter->SetInputData(leaf.Data);
      filter->Update();
      surface->ShallowCopy(filter->GetOutput());
    }
    if (composite)
    {
      vtkNew<vtkIntArray> index;
      index->SetName("BlockIndex");
      index->SetNumberOfTuples(surface->GetNumberOfCells());
      index->FillValue(static_cast<int>(leaf.Index));
      surface->GetCellData()->AddArray(index);
    }
    append->AddInputData(surface);
  }
  append->Update();
  vtkSmartPointer<vtkPolyData> merged = append->GetOutput();
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
  vtkSmartPointer<vtkDataObject> object = ReadFile(path, options, false, summary, problem);
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
      surface = MergeBlocks(chosen, vtkDataSet::SafeDownCast(object) == nullptr, problem);
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
  vtkNew<FirstError> errors;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->AddObserver(vtkCommand::ErrorEvent, errors);
  triangles->SetInputData(data.Surface);
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->AddObserver(vtkCommand::ErrorEvent, errors);
  normals->SetInputConnection(triangles->GetOutputPort());
  normals->SplittingOff(); // keep the points: the OFB interpolates point arrays
  normals->Update();
  vtkSmartPointer<vtkPolyData> surface = normals->GetOutput();
  if (errors->Count > 0 || !surface || surface->GetNumberOfPolys() == 0)
  {
    message = "cannot read '" + path +
      "': " + (errors->Text.empty() ? std::string("no triangles in the file") : errors->Text);
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

void UseFieldAsVectors(DataSurface& data, double range[2])
{
  vtkDataSetAttributes* on = data.FieldOnCells
    ? static_cast<vtkDataSetAttributes*>(data.Surface->GetCellData())
    : static_cast<vtkDataSetAttributes*>(data.Surface->GetPointData());
  vtkDataSetAttributes* off = data.FieldOnCells
    ? static_cast<vtkDataSetAttributes*>(data.Surface->GetPointData())
    : static_cast<vtkDataSetAttributes*>(data.Surface->GetCellData());
  off->SetActiveAttribute(-1, vtkDataSetAttributes::VECTORS);
  on->SetVectors(data.Field);
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

vtkSmartPointer<vtkDataArray> CellFieldToPoints(vtkPolyData* surface, vtkDataArray* field)
{
  const int nc = field->GetNumberOfComponents();
  auto points = vtkSmartPointer<vtkDoubleArray>::New();
  points->SetName(field->GetName());
  points->SetNumberOfComponents(nc);
  points->SetNumberOfTuples(surface->GetNumberOfPoints());
  points->Fill(0.0);
  std::vector<int> count(surface->GetNumberOfPoints(), 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
    {
      const vtkIdType p = ids->GetId(j);
      for (int k = 0; k < nc; ++k)
      {
        points->SetComponent(p, k, points->GetComponent(p, k) + field->GetComponent(c, k));
      }
      ++count[p];
    }
  }
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    for (int k = 0; count[p] > 1 && k < nc; ++k)
    {
      points->SetComponent(p, k, points->GetComponent(p, k) / count[p]);
    }
  }
  return points;
}
}
