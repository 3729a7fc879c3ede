#include "ofbExampleMesh.h"
#include "ofbExampleErrors.h"

#include "vtkAbstractPolyDataReader.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtksys/SystemTools.hxx"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace
{
using SystemTools = vtksys::SystemTools;

/// A PLY scalar type: its size in bytes, and whether it is a float or a signed integer.
struct PLYType
{
  int Size = 0;
  bool Float = false;
  bool Signed = false;
};

bool FindPLYType(const std::string& name, PLYType& type)
{
  // clang-format off
  static const std::map<std::string, PLYType> types = {
    { "char", { 1, false, true } }, { "int8", { 1, false, true } },
    { "uchar", { 1, false, false } }, { "uint8", { 1, false, false } },
    { "short", { 2, false, true } }, { "int16", { 2, false, true } },
    { "ushort", { 2, false, false } }, { "uint16", { 2, false, false } },
    { "int", { 4, false, true } }, { "int32", { 4, false, true } },
    { "uint", { 4, false, false } }, { "uint32", { 4, false, false } },
    { "float", { 4, true, true } }, { "float32", { 4, true, true } },
    { "double", { 8, true, true } }, { "float64", { 8, true, true } } };
  // clang-format on
  const auto found = types.find(name);
  type = found == types.end() ? type : found->second;
  return found != types.end();
}

struct PLYProperty
{
  std::string Name;
  bool List = false;
  PLYType Count; // a list's count
  PLYType Item;  // the value, or a list's items
};

struct PLYElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PLYProperty> Properties;
  /// The face element's vertex index list: its indices are checked.
  bool IsIndexList(const PLYProperty& p) const
  {
    return this->Name == "face" && p.List &&
      (p.Name == "vertex_indices" || p.Name == "vertex_index");
  }
};

struct PLYHeader
{
  bool Ascii = false;
  bool BigEndian = false;
  std::vector<PLYElement> Elements;
  long long Vertices = 0;
  long long BodyStart = 0;
};

bool Fail(std::string& problem, const std::string& text)
{
  problem = text;
  return false;
}

/// One header line into `header`.
bool PLYHeaderLine(const std::string& line, PLYHeader& header, std::string& problem)
{
  std::istringstream words(line);
  std::string key, a, b, c;
  words >> key;
  if (key == "format")
  {
    words >> a;
    header.Ascii = a == "ascii";
    header.BigEndian = a == "binary_big_endian";
    return a == "ascii" || a == "binary_little_endian" || header.BigEndian
      ? true
      : Fail(problem, "an unknown PLY format '" + a + "'");
  }
  if (key == "element")
  {
    PLYElement element;
    if (!(words >> element.Name >> element.Count) || element.Count < 0)
    {
      return Fail(problem, "a bad PLY element line '" + line + "'");
    }
    if (element.Count > ofbexample::MaximumMeshElements)
    {
      return Fail(problem,
        "the PLY header claims " + std::to_string(element.Count) + " " + element.Name +
          " elements, over the limit of " + std::to_string(ofbexample::MaximumMeshElements));
    }
    header.Vertices = element.Name == "vertex" ? element.Count : header.Vertices;
    header.Elements.push_back(element);
    return true;
  }
  if (key == "property")
  {
    PLYProperty property;
    words >> a;
    property.List = a == "list";
    const bool known = property.List ? (words >> b >> c >> property.Name) &&
        FindPLYType(b, property.Count) && !property.Count.Float && FindPLYType(c, property.Item)
                                     : (words >> property.Name) && FindPLYType(a, property.Item);
    if (!known || header.Elements.empty())
    {
      return Fail(problem, "a bad PLY property line '" + line + "'");
    }
    header.Elements.back().Properties.push_back(property);
  }
  return true; // comments, obj_info
}

/// The header of the PLY file at `path`; `fileSize` its size.
bool ReadPLYHeader(const std::string& path,
  long long fileSize,
  PLYHeader& header,
  std::string& problem)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    return Fail(problem, "not a PLY file");
  }
  while (std::getline(in, line) && line.size() < 4096)
  {
    line.erase(line.find_last_not_of('\r') + 1);
    if (line == "end_header")
    {
      header.BodyStart = static_cast<long long>(in.tellg());
      return header.BodyStart > 0 && header.BodyStart <= fileSize
        ? true
        : Fail(problem, "the PLY header is cut short");
    }
    if (!PLYHeaderLine(line, header, problem))
    {
      return false;
    }
  }
  return Fail(problem, "the PLY header has no end_header");
}

/// The elements' smallest possible size fits in the body: fails fast on huge counts.
bool CheckPLYCounts(const PLYHeader& header, long long fileSize, std::string& problem)
{
  long long needed = 0;
  for (const PLYElement& e : header.Elements)
  {
    long long each = 0;
    for (const PLYProperty& p : e.Properties)
    {
      each += header.Ascii ? 2 : (p.List ? p.Count.Size : p.Item.Size);
    }
    needed += e.Count * each;
  }
  const long long body = fileSize - header.BodyStart;
  if (needed > body)
  {
    return Fail(problem,
      "the file is too short for its header (" + std::to_string(header.Vertices) +
        " vertices; its elements need at least " + std::to_string(needed) + " bytes, it has " +
        std::to_string(body) + ")");
  }
  return true;
}

/// A walk over the PLY body, value by value (binary or ASCII).
class PLYWalker
{
public:
  PLYWalker(const PLYHeader& header, const std::vector<char>& body)
    : Header(header)
    , Body(body)
  {
  }

  bool Walk(std::string& problem)
  {
    for (const PLYElement& e : this->Header.Elements)
    {
      for (long long i = 0; i < e.Count; ++i)
      {
        for (const PLYProperty& p : e.Properties)
        {
          if (!this->Property(e, p, i, problem))
          {
            return false;
          }
        }
      }
    }
    return true;
  }

private:
  bool Property(const PLYElement& e, const PLYProperty& p, long long i, std::string& problem)
  {
    const std::string where = "PLY " + e.Name + " " + std::to_string(i);
    double count = 1.0;
    if (p.List && (!this->Value(p.Count, count) || count < 0 || count != std::floor(count)))
    {
      return Fail(problem, where + ": the file is cut short or a list count is bad");
    }
    for (double k = 0; k < count; ++k)
    {
      double v = 0.0;
      if (!this->Value(p.Item, v))
      {
        return Fail(problem, where + ": the file is cut short");
      }
      if (e.IsIndexList(p) && !(v >= 0 && v < this->Header.Vertices && v == std::floor(v)))
      {
        return Fail(problem,
          where + " has vertex index " + std::to_string(static_cast<long long>(v)) +
            ", not one of the " + std::to_string(this->Header.Vertices) + " vertices");
      }
    }
    return true;
  }

  /// The next value; false at the end of the body or on a word that is not a number.
  bool Value(const PLYType& type, double& value)
  {
    return this->Header.Ascii ? this->AsciiValue(value) : this->BinaryValue(type, value);
  }

  bool AsciiValue(double& value)
  {
    const size_t n = this->Body.size();
    while (this->At < n && std::isspace(static_cast<unsigned char>(this->Body[this->At])))
    {
      ++this->At;
    }
    const size_t start = this->At;
    while (this->At < n && !std::isspace(static_cast<unsigned char>(this->Body[this->At])))
    {
      ++this->At;
    }
    if (start == this->At || this->At - start > 64)
    {
      return false;
    }
    const std::string word(&this->Body[start], this->At - start);
    char* end = nullptr;
    value = std::strtod(word.c_str(), &end);
    return *end == '\0';
  }

  bool BinaryValue(const PLYType& type, double& value)
  {
    if (this->Body.size() - this->At < static_cast<size_t>(type.Size))
    {
      return false;
    }
    unsigned char b[8];
    std::memcpy(b, &this->Body[this->At], type.Size);
    this->At += type.Size;
    const bool swap = this->Header.BigEndian != IsBigEndianHost();
    if (swap)
    {
      std::reverse(b, b + type.Size);
    }
    value = Decode(type, b);
    return true;
  }

  static bool IsBigEndianHost()
  {
    const uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 0;
  }

  static double Decode(const PLYType& type, const unsigned char* b)
  {
    if (type.Float && type.Size == 4)
    {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    if (type.Float)
    {
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
    switch (type.Size)
    {
      case 1:
        return type.Signed ? static_cast<int8_t>(b[0]) : b[0];
      case 2:
      {
        uint16_t u;
        std::memcpy(&u, b, 2);
        return type.Signed ? static_cast<int16_t>(u) : u;
      }
      default:
      {
        uint32_t u;
        std::memcpy(&u, b, 4);
        return type.Signed ? static_cast<int32_t>(u) : u;
      }
    }
  }

  const PLYHeader& Header;
  const std::vector<char>& Body;
  size_t At = 0;
};

/// The PLY file's header, counts and body, before vtkPLYReader sees it.
bool CheckPLY(const std::string& path, long long fileSize, std::string& problem)
{
  PLYHeader header;
  if (!ReadPLYHeader(path, fileSize, header, problem) || !CheckPLYCounts(header, fileSize, problem))
  {
    return false;
  }
  if (fileSize > ofbexample::MaximumPLYFileBytes)
  {
    return Fail(problem,
      "larger than the limit of " + std::to_string(ofbexample::MaximumPLYFileBytes) +
        " bytes for a PLY file");
  }
  std::vector<char> body(static_cast<size_t>(fileSize - header.BodyStart));
  std::ifstream in(path, std::ios::binary);
  if (!in.seekg(header.BodyStart) ||
    !in.read(body.data(), static_cast<std::streamsize>(body.size())))
  {
    return Fail(problem, "cannot read the PLY body");
  }
  PLYWalker walker(header, body);
  return walker.Walk(problem) &&
    (vtkPLYReader::CanReadFile(path.c_str()) ||
      Fail(problem, "vtkPLYReader cannot read this PLY file"));
}

/**
 * The OBJ's face, line and point elements refer to vertices, texture coordinates and
 * normals the file has (vtkOBJReader indexes its arrays with them unchecked: a texture
 * coordinate or normal index past the end crashes it). Negative indices count back from
 * the last element read; 0 is invalid.
 */
class OBJIndexCheck
{
public:
  bool Run(const std::string& path, std::string& problem)
  {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    for (long long number = 1; std::getline(in, line); ++number)
    {
      const size_t start = line.find_first_not_of(" \t");
      if (start == std::string::npos || line.size() - start < 2)
      {
        continue;
      }
      const char c0 = line[start], c1 = line[start + 1];
      const bool blank = c1 == ' ' || c1 == '\t';
      if (c0 == 'v' && (blank || ((c1 == 't' || c1 == 'n') && line.size() > start + 2)))
      {
        ++this->Count[blank ? 0 : (c1 == 't' ? 1 : 2)];
      }
      else if ((c0 == 'f' || c0 == 'l' || c0 == 'p') && blank &&
        !this->Element(line.c_str() + start + 2, number, problem))
      {
        return false;
      }
    }
    for (int kind = 0; kind < 3; ++kind)
    {
      if (this->Largest[kind] > this->Count[kind])
      {
        return this->Bad(kind, this->Largest[kind], this->LargestLine[kind], problem);
      }
    }
    return true;
  }

private:
  /// The "v/vt/vn" groups of one element line.
  bool Element(const char* text, long long number, std::string& problem)
  {
    while (*text)
    {
      while (*text == ' ' || *text == '\t' || *text == '\r')
      {
        ++text;
      }
      for (int kind = 0; kind < 3 && *text && *text != ' ' && *text != '\t' && *text != '\r';
           ++kind)
      {
        char* end = nullptr;
        const long long index = std::strtoll(text, &end, 10);
        if (end != text && !this->Index(kind, index, number, problem))
        {
          return false;
        }
        text = *end == '/' ? end + 1 : end;
        if (end == text && *end != '/' && *end && *end != ' ' && *end != '\t' && *end != '\r')
        {
          return Fail(problem, "OBJ line " + std::to_string(number) + ": a bad element");
        }
      }
    }
    return true;
  }

  bool Index(int kind, long long index, long long number, std::string& problem)
  {
    if (index == 0 || (index < 0 && -index > this->Count[kind]))
    {
      return this->Bad(kind, index, number, problem);
    }
    if (index > this->Largest[kind])
    {
      this->Largest[kind] = index;
      this->LargestLine[kind] = number;
    }
    return true;
  }

  bool Bad(int kind, long long index, long long number, std::string& problem) const
  {
    const char* names[3] = { "vertex", "texture coordinate", "normal" };
    const char* plural[3] = { "vertices", "texture coordinates", "normals" };
    return Fail(problem,
      "OBJ line " + std::to_string(number) + ": " + names[kind] + " index " +
        std::to_string(index) + ", not one of the " + std::to_string(this->Count[kind]) + " " +
        plural[kind]);
  }

  long long Count[3] = { 0, 0, 0 };
  long long Largest[3] = { 0, 0, 0 };
  long long LargestLine[3] = { 0, 0, 0 };
};

/// A binary STL has exactly 84 + 50 x (its triangle count) bytes; an ASCII one starts with
/// "solid".
bool CheckSTL(const std::string& path, long long fileSize, std::string& problem)
{
  std::ifstream in(path, std::ios::binary);
  unsigned char start[84] = {};
  in.read(reinterpret_cast<char*>(start), 84);
  const long long triangles = static_cast<long long>(start[80]) | (start[81] << 8) |
    (start[82] << 16) | (static_cast<long long>(start[83]) << 24);
  if (fileSize >= 84 && fileSize == 84 + 50 * triangles)
  {
    return true;
  }
  std::string text(reinterpret_cast<char*>(start), static_cast<size_t>(std::min(fileSize, 84LL)));
  text.erase(0, text.find_first_not_of(" \t\r\n"));
  return text.compare(0, 5, "solid") == 0
    ? true
    : Fail(problem,
        "a binary STL of " + std::to_string(fileSize) + " bytes claiming " +
          std::to_string(triangles) + " triangles (it needs " +
          std::to_string(84 + 50 * triangles) + ")");
}

/// Finite points, and every cell's point ids in [0, points).
bool CheckCells(vtkPolyData* mesh, std::string& problem)
{
  vtkPoints* points = mesh->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double* p = points->GetPoint(i);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return Fail(problem, "point " + std::to_string(i) + " is not finite");
    }
  }
  const char* kinds[4] = { "vertex", "line", "polygon", "strip" };
  vtkCellArray* arrays[4] = {
    mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips()
  };
  for (int k = 0; k < 4; ++k)
  {
    auto cells = vtk::TakeSmartPointer(arrays[k]->NewIterator());
    for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      cells->GetCurrentCell(size, ids);
      for (vtkIdType j = 0; j < size; ++j)
      {
        if (ids[j] < 0 || ids[j] >= n)
        {
          return Fail(problem,
            std::string(kinds[k]) + " " + std::to_string(cells->GetCurrentCellId()) +
              " uses point " + std::to_string(ids[j]) + ", not one of the " + std::to_string(n) +
              " points");
        }
      }
    }
  }
  return mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() > 0
    ? true
    : Fail(problem, "no polygons in the file");
}

/// The reader for the file's extension, after the checks of its format.
vtkSmartPointer<vtkAbstractPolyDataReader> MakeReader(const std::string& path,
  const std::string& ext,
  long long fileSize,
  std::string& problem)
{
  if (ext == ".obj")
  {
    OBJIndexCheck check;
    return check.Run(path, problem) ? vtkSmartPointer<vtkOBJReader>::New() : nullptr;
  }
  if (ext == ".ply")
  {
    return CheckPLY(path, fileSize, problem) ? vtkSmartPointer<vtkPLYReader>::New() : nullptr;
  }
  if (ext == ".stl")
  {
    return CheckSTL(path, fileSize, problem) ? vtkSmartPointer<vtkSTLReader>::New() : nullptr;
  }
  problem = "unsupported extension '" + ext + "' (use .obj, .ply, .stl or .vtp)";
  return nullptr;
}
}

namespace ofbexample
{
bool CheckPolyData(vtkPolyData* mesh, std::string& problem)
{
  return CheckCells(mesh, problem);
}

vtkSmartPointer<vtkPolyData> ReadMeshChecked(const std::string& path,
  std::string& message,
  const std::string& format)
{
  struct stat info;
  std::string problem;
  const bool found = stat(path.c_str(), &info) == 0;
  if (!found || !S_ISREG(info.st_mode))
  {
    problem = !found
      ? (errno == ENOENT ? "no such file" : std::strerror(errno))
      : (S_ISDIR(info.st_mode) ? "a directory, not a mesh file" : "not a regular file");
    message = "cannot read '" + path + "': " + problem;
    return nullptr;
  }
  vtkNew<FirstError> errors;
  vtkSmartPointer<vtkPolyData> mesh;
  const std::string ext =
    format.empty() ? SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path)) : format;
  const bool vtp = ext == ".vtp";
  if (vtp)
  {
    vtkNew<vtkXMLPolyDataReader> reader; // an XML reader, not a vtkAbstractPolyDataReader
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  else if (vtkSmartPointer<vtkAbstractPolyDataReader> reader =
             MakeReader(path, ext, info.st_size, problem))
  {
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  if (problem.empty() && (errors->Count > 0 || !mesh))
  {
    problem = errors->Text.empty() ? "the reader failed" : errors->Text;
  }
  if (!problem.empty() || !CheckCells(mesh, problem))
  {
    message = "cannot read '" + path + "': " + problem;
    return nullptr;
  }
  return mesh;
}

bool CheckPLYFile(const std::string& path, std::string& message)
{
  struct stat info;
  std::string problem;
  if (stat(path.c_str(), &info) != 0 || !CheckPLY(path, info.st_size, problem))
  {
    message = "'" + path + "' is not a complete PLY file" + (problem.empty() ? "" : ": " + problem);
    return false;
  }
  return true;
}

vtkSmartPointer<vtkPolyData> TrianglesWithNormals(vtkPolyData* mesh,
  const std::string& path,
  std::string& message)
{
  vtkNew<FirstError> errors;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->AddObserver(vtkCommand::ErrorEvent, errors);
  triangles->SetInputData(mesh);
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
    return nullptr;
  }
  return surface;
}

vtkSmartPointer<vtkPolyData> ReadSurfaceChecked(const std::string& path, std::string& message)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshChecked(path, message);
  if (!mesh)
  {
    return nullptr;
  }
  return TrianglesWithNormals(mesh, path, message);
}
}
