#include "vtkOFBReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBWriter.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkOFBReader);

namespace
{
using Writer = vtkOFBWriter;

bool HostIsLittleEndian()
{
  const vtkTypeUInt32 one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Decode `size` little-endian bytes.
vtkTypeUInt64 GetLE(const unsigned char* p, int size)
{
  vtkTypeUInt64 value = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    value = (value << 8) | p[i];
  }
  return value;
}

double GetDouble(const unsigned char* p)
{
  const vtkTypeUInt64 bits = GetLE(p, 8);
  double value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

/**
 * The local VTK type of a stored type and element size, or -1 if unknown. The
 * integers whose size depends on the platform (long, vtkIdType) map to the
 * fixed-size integer of the stored size.
 */
int LocalType(vtkTypeUInt64 type, vtkTypeUInt64 size)
{
  // VTK_CHAR (2) to VTK_ID_TYPE (12), VTK_SIGNED_CHAR (15) to VTK_UNSIGNED_LONG_LONG (17).
  const int t = static_cast<int>(std::min<vtkTypeUInt64>(type, 1024));
  if (!(t >= VTK_CHAR && t <= VTK_ID_TYPE) &&
    !(t >= VTK_SIGNED_CHAR && t <= VTK_UNSIGNED_LONG_LONG))
  {
    return -1;
  }
  if (static_cast<vtkTypeUInt64>(vtkDataArray::GetDataTypeSize(t)) == size)
  {
    return t;
  }
  if ((t == VTK_LONG || t == VTK_ID_TYPE) && (size == 4 || size == 8))
  {
    return size == 4 ? VTK_TYPE_INT32 : VTK_TYPE_INT64;
  }
  if (t == VTK_UNSIGNED_LONG && (size == 4 || size == 8))
  {
    return size == 4 ? VTK_TYPE_UINT32 : VTK_TYPE_UINT64;
  }
  return -1;
}

/// Keeps the last warning of the objects it observes (the attribute checks).
class WarningCatcher : public vtkCommand
{
public:
  static WarningCatcher* New() { return new WarningCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Text = data ? static_cast<const char*>(data) : "";
  }
  std::string Text;
};

/**
 * The file being read: every read is bounded by the file size, checksummed and
 * reported as progress; the first problem met is kept with its error code.
 */
struct Source
{
  vtksys::ifstream File;
  vtkAlgorithm* Owner = nullptr;
  vtkTypeUInt64 Size = 0;
  vtkTypeUInt64 Position = 0;
  vtkTypeUInt32 CRC = 0;
  std::string Problem;
  unsigned long Code = vtkErrorCode::FileFormatError;

  vtkTypeUInt64 Remaining() const { return this->Size - this->Position; }

  bool Fail(const std::string& problem, unsigned long code = vtkErrorCode::FileFormatError)
  {
    this->Problem = problem;
    this->Code = code;
    return false;
  }

  /// Read `size` bytes; on a short read, fail with "truncated (in `what`)".
  bool Raw(void* data, vtkTypeUInt64 size, const std::string& what)
  {
    if (size > this->Remaining())
    {
      return this->Fail(
        "the file is truncated (in " + what + ")", vtkErrorCode::PrematureEndOfFileError);
    }
    this->File.read(static_cast<char*>(data), static_cast<std::streamsize>(size));
    if (static_cast<vtkTypeUInt64>(this->File.gcount()) != size)
    {
      return this->Fail("reading failed (in " + what + ")", vtkErrorCode::PrematureEndOfFileError);
    }
    this->CRC = Writer::UpdateCRC32(this->CRC, data, static_cast<size_t>(size));
    this->Position += size;
    return true;
  }

  /// Read `count` little-endian values of `elementSize` bytes, in chunks.
  bool Values(void* data, vtkTypeUInt64 count, int elementSize, const std::string& what)
  {
    const vtkTypeUInt64 chunk = (vtkTypeUInt64(1) << 22) / elementSize;
    unsigned char* p = static_cast<unsigned char*>(data);
    for (vtkTypeUInt64 first = 0; first < count; first += chunk)
    {
      const vtkTypeUInt64 n = std::min(chunk, count - first);
      unsigned char* dst = p + first * elementSize;
      if (!this->Raw(dst, n * elementSize, what))
      {
        return false;
      }
      if (elementSize > 1 && !HostIsLittleEndian())
      {
        for (vtkTypeUInt64 i = 0; i < n; ++i)
        {
          std::reverse(dst + i * elementSize, dst + (i + 1) * elementSize);
        }
      }
      this->Owner->UpdateProgress(static_cast<double>(this->Position) / this->Size);
    }
    return true;
  }

  /// Read the CRC that ends a section and compare it with the bytes read.
  bool EndSection(const std::string& what)
  {
    const vtkTypeUInt32 computed = this->CRC;
    unsigned char stored[4];
    if (!this->Raw(stored, 4, "the checksum of " + what))
    {
      return false;
    }
    this->CRC = 0;
    if (GetLE(stored, 4) != computed)
    {
      return this->Fail("checksum mismatch in " + what + ": the file is corrupted");
    }
    return true;
  }
};

/// Read an OFB file into `output`; false with the problem in `src`.
bool ReadOFB(const char* fileName, vtkOFB* output, Source& src)
{
  using Code = vtkErrorCode::ErrorIds;
  if (!fileName || !*fileName)
  {
    return src.Fail("No FileName: set the name of the .ofb file to read", Code::NoFileNameError);
  }
  if (!vtksys::SystemTools::FileExists(fileName))
  {
    return src.Fail("the file does not exist", Code::FileNotFoundError);
  }
  if (vtksys::SystemTools::FileIsDirectory(fileName))
  {
    return src.Fail("it is a directory, not a file", Code::CannotOpenFileError);
  }
  src.File.open(fileName, std::ios::in | std::ios::binary);
  const std::streamoff size =
    src.File.is_open() && src.File.seekg(0, std::ios::end) ? std::streamoff(src.File.tellg()) : -1;
  if (size < 0 || !src.File.seekg(0, std::ios::beg))
  {
    return src.Fail("the file cannot be opened", Code::CannotOpenFileError);
  }
  src.Size = static_cast<vtkTypeUInt64>(size);
  if (src.Size == 0)
  {
    return src.Fail("the file is empty", Code::PrematureEndOfFileError);
  }

  // Header: signature, checksum, version, then the counts against the file size.
  unsigned char h[Writer::HeaderSize];
  const vtkTypeUInt64 got = std::min<vtkTypeUInt64>(src.Size, Writer::HeaderSize);
  if (!src.Raw(h, got, "the header"))
  {
    return false;
  }
  if (std::memcmp(h, Writer::Magic, static_cast<size_t>(std::min<vtkTypeUInt64>(got, 8))) != 0)
  {
    return src.Fail(
      "not an OFB file (no OFB signature at the start)", Code::UnrecognizedFileTypeError);
  }
  if (got < static_cast<vtkTypeUInt64>(Writer::HeaderSize))
  {
    return src.Fail("the file is truncated (" + std::to_string(got) + " bytes, in the header)",
      Code::PrematureEndOfFileError);
  }
  if (Writer::UpdateCRC32(0, h, Writer::HeaderSize - 4) != GetLE(h + Writer::HeaderSize - 4, 4))
  {
    return src.Fail("checksum mismatch in the header: the file is corrupted");
  }
  src.CRC = 0;
  const vtkTypeUInt64 version = GetLE(h + 8, 4);
  if (version != static_cast<vtkTypeUInt64>(Writer::GetFormatVersion()))
  {
    return src.Fail("unsupported format version " + std::to_string(version) +
      " (this reader supports version " + std::to_string(Writer::GetFormatVersion()) + ")");
  }
  if (GetLE(h + 12, 4) != Writer::ByteOrderMark)
  {
    return src.Fail("unsupported byte-order marker");
  }
  double origin[3], cellSize = GetDouble(h + 40);
  vtkTypeUInt64 udims[3];
  vtkIdType dims[3];
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = GetDouble(h + 16 + 8 * a);
    udims[a] = GetLE(h + 48 + 8 * a, 8);
    dims[a] = static_cast<vtkIdType>(udims[a] & 0xFFFFFFFFu);
  }
  const vtkTypeUInt64 nCells = GetLE(h + 72, 8);
  const vtkTypeUInt64 nSamples = GetLE(h + 80, 8);
  const vtkTypeUInt64 nArrays = GetLE(h + 88, 4);
  const vtkTypeUInt64 limit = std::numeric_limits<vtkTypeUInt32>::max();
  const bool empty = cellSize == 0.0 && udims[0] == 0 && udims[1] == 0 && udims[2] == 0;
  std::ostringstream msg;
  if (empty && (nCells != 0 || nSamples != 0))
  {
    msg << "an empty frame with " << nCells << " cells and " << nSamples << " samples";
  }
  else if (!empty &&
    (!(cellSize > 0.0) || !std::isfinite(cellSize) || !std::isfinite(origin[0]) ||
      !std::isfinite(origin[1]) || !std::isfinite(origin[2])))
  {
    msg << "an invalid frame (cell size " << cellSize << ", origin " << origin[0] << " "
        << origin[1] << " " << origin[2] << ")";
  }
  else if (!empty)
  {
    vtkTypeUInt64 cells = 0;
    bool valid = true;
    for (int a = 0; a < 3; ++a)
    {
      const vtkTypeUInt64 nu = udims[(a + 1) % 3], nv = udims[(a + 2) % 3];
      valid = valid && udims[a] >= 1 && udims[a] < limit;
      cells += valid ? nu * nv : 0; // each dimension < 2^32: no overflow
    }
    if (!valid)
    {
      msg << "invalid dimensions " << udims[0] << " " << udims[1] << " " << udims[2];
    }
    else if (cells >= limit || cells != nCells)
    {
      msg << nCells << " cells for dimensions " << udims[0] << " " << udims[1] << " " << udims[2];
    }
    else if (nSamples >= limit)
    {
      msg << "an invalid sample count " << nSamples;
    }
  }
  // Each array takes at least 36 bytes; cells, samples < 2^32 here: no overflow.
  const vtkTypeUInt64 least =
    Writer::HeaderSize + 4 * (nCells + 1) + 4 + 4 * nSamples + 4 + 36 * nArrays + 8;
  if (msg.tellp() == 0 && least > src.Size)
  {
    msg << nCells << " cells, " << nSamples << " samples and " << nArrays
        << " arrays, which need at least " << least << " bytes, but the file has " << src.Size
        << " bytes (truncated or corrupted)";
  }
  if (msg.tellp() != 0)
  {
    return src.Fail("the header announces " + msg.str());
  }

  // Cell offsets: 0, non-decreasing, ending at the sample count.
  vtkTypeUInt32 emptyOffset = 0;
  vtkTypeUInt32* offsets = &emptyOffset;
  if (!empty)
  {
    if (!output->SetFrame(origin, cellSize, dims))
    {
      return src.Fail("cannot allocate " + std::to_string(nCells) + " cells", Code::UnknownError);
    }
    offsets = output->GetCellOffsets()->GetPointer(0);
  }
  if (!src.Values(offsets, nCells + 1, 4, "the cell offsets") ||
    !src.EndSection("the cell offsets"))
  {
    return false;
  }
  bool valid = offsets[0] == 0 && offsets[nCells] == nSamples;
  for (vtkTypeUInt64 c = 0; c < nCells && valid; ++c)
  {
    valid = offsets[c] <= offsets[c + 1];
  }
  if (!valid)
  {
    return src.Fail("the cell offsets do not run from 0 to the sample count without decreasing");
  }

  // Depths: finite and sorted within each cell.
  if (!output->AllocateSamples(static_cast<vtkIdType>(nSamples)))
  {
    return src.Fail("cannot allocate " + std::to_string(nSamples) + " samples", Code::UnknownError);
  }
  float* depths = nSamples > 0 ? output->GetDepths()->GetPointer(0) : nullptr;
  if (!src.Values(depths, nSamples, 4, "the depths") || !src.EndSection("the depths"))
  {
    return false;
  }
  for (vtkTypeUInt64 c = 0; c < nCells && valid; ++c)
  {
    for (vtkTypeUInt32 i = offsets[c]; i < offsets[c + 1] && valid; ++i)
    {
      valid = std::isfinite(depths[i]) && (i == offsets[c] || depths[i - 1] <= depths[i]);
    }
  }
  if (!valid)
  {
    return src.Fail("the depths are not finite or not sorted within their cells");
  }

  // Sample arrays.
  vtkPointData* sd = output->GetSampleData();
  vtkTypeUInt64 usedRoles = 0;
  vtkNew<WarningCatcher> catcher;
  const unsigned long tag = sd->AddObserver(vtkCommand::WarningEvent, catcher);
  for (vtkTypeUInt64 k = 0; k < nArrays; ++k)
  {
    const std::string where = "the header of sample array " + std::to_string(k);
    unsigned char f[24];
    if (!src.Raw(f, 4, where))
    {
      return false;
    }
    const vtkTypeUInt64 nameLength = GetLE(f, 4);
    if (nameLength > 65536 || nameLength + 24 > src.Remaining())
    {
      return src.Fail(where + ": invalid name length " + std::to_string(nameLength));
    }
    std::string name(static_cast<size_t>(nameLength), '\0');
    if ((nameLength > 0 && !src.Raw(&name[0], nameLength, where)) || !src.Raw(f, 24, where) ||
      !src.EndSection(where))
    {
      return false;
    }
    const vtkTypeUInt64 type = GetLE(f, 4), elementSize = GetLE(f + 4, 4);
    const vtkTypeUInt64 comps = GetLE(f + 8, 4), tuples = GetLE(f + 12, 8);
    const vtkTypeUInt64 roles = GetLE(f + 20, 4);
    const int localType = LocalType(type, elementSize);
    const std::string named = "sample array " + std::to_string(k) + " '" + name + "'";
    if (localType < 0)
    {
      return src.Fail(named + " has an unknown data type " + std::to_string(type) + " of " +
        std::to_string(elementSize) + " bytes");
    }
    if (comps < 1 || comps > (1u << 20) || tuples != nSamples ||
      (roles >> Writer::NumberOfRoleBits) != 0 || (roles & usedRoles) != 0)
    {
      return src.Fail(named + " has " + std::to_string(tuples) + " tuples of " +
        std::to_string(comps) + " components and roles " + std::to_string(roles) +
        " (expected one tuple per sample, " + std::to_string(nSamples) +
        ", and roles not taken by another array)");
    }
    // comps * elementSize < 2^24 and tuples < 2^32: no overflow.
    const vtkTypeUInt64 bytes = tuples * comps * elementSize;
    if (bytes + 4 + 8 > src.Remaining())
    {
      return src.Fail(named + " needs " + std::to_string(bytes) + " bytes of values, then 12 " +
          "bytes of checksum and trailer, but only " + std::to_string(src.Remaining()) +
          " bytes remain (truncated or corrupted)",
        Code::PrematureEndOfFileError);
    }
    if (!name.empty() && sd->HasArray(name.c_str()))
    {
      return src.Fail(named + " has the name of an earlier array");
    }
    auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(localType));
    array->SetNumberOfComponents(static_cast<int>(comps));
    if (tuples > 0 && !array->Resize(static_cast<vtkIdType>(tuples)))
    {
      return src.Fail("cannot allocate " + named, Code::UnknownError);
    }
    array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
    if (!src.Values(tuples > 0 ? array->GetVoidPointer(0) : nullptr,
          tuples * comps,
          static_cast<int>(elementSize),
          named) ||
      !src.EndSection(named))
    {
      return false;
    }
    if (!name.empty())
    {
      array->SetName(name.c_str());
    }
    const int index = sd->AddArray(array);
    for (int r = 0; r < Writer::NumberOfRoleBits; ++r)
    {
      if (((roles >> r) & 1u) && sd->SetActiveAttribute(index, r) < 0)
      {
        return src.Fail(named + " cannot be the active " +
          vtkDataSetAttributes::GetAttributeTypeAsString(r) + " (" + catcher->Text + ")");
      }
    }
    usedRoles |= roles;
  }
  sd->RemoveObserver(tag);

  // Trailer, which must end the file.
  char trailer[8];
  if (!src.Raw(trailer, 8, "the trailer") || std::memcmp(trailer, Writer::Trailer, 8) != 0)
  {
    return src.Fail("the end-of-data marker is missing or damaged");
  }
  if (src.Remaining() != 0)
  {
    return src.Fail(
      std::to_string(src.Remaining()) + " unexpected bytes follow the end of the data");
  }
  if (!output->BuildCellIndex())
  {
    return src.Fail("cannot rebuild the cell index");
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkOFBReader::vtkOFBReader()
  : FileName(nullptr)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOFBReader::~vtkOFBReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkOFBReader::CanReadFile(const char* fileName)
{
  if (!fileName || vtksys::SystemTools::FileIsDirectory(fileName))
  {
    return 0;
  }
  vtksys::ifstream in(fileName, std::ios::in | std::ios::binary);
  char magic[8];
  if (!in.read(magic, 8))
  {
    return 0;
  }
  return std::memcmp(magic, Writer::Magic, 8) == 0 ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkOFBReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outVec)
{
  vtkOFB* output = vtkOFB::GetData(outVec);
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  this->UpdateProgress(0.0);
  Source src;
  src.Owner = this;
  if (!ReadOFB(this->FileName, output, src))
  {
    output->Initialize();
    vtkErrorMacro("Cannot read OFB file " << (this->FileName ? this->FileName : "(none)") << ": "
                                          << src.Problem << ".");
    this->SetErrorCode(src.Code);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
