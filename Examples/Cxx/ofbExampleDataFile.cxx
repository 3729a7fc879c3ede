// The files of ofbExampleData: the format by content or extension, VTK XML and legacy
// files at a time step, .pvd collections, meshes through ofbExampleMesh's checks.
#include "ofbExampleDataFile.h"
#include "ofbExampleErrors.h"
#include "ofbExampleMesh.h"

#include "vtkCompositeDataSet.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
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
#include <vector>

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
    vtkSmartPointer<vtkDataObject> part =
      ofbexample::ReadDataFile(file, options, true, partSummary, problem);
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
}

namespace ofbexample
{
vtkSmartPointer<vtkDataObject> ReadDataFile(const std::string& path,
  const DataOptions& options,
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
      return ReadVTK(path, format, inCollection ? DataOptions() : options, summary, problem);
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
}
