#include "vtkOFBReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBFileFormat.h"
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

#if !defined(_WIN32)
#include <sys/stat.h>
#endif

vtkStandardNewMacro(vtkOFBReader);

namespace
{
using Writer = vtkOFBWriter;
using vtkofb::format::GetDouble;
using vtkofb::format::GetLE;

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
      vtkofb::format::SwapLittleEndian(dst, static_cast<size_t>(n), elementSize);
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

/// The fields of an .ofb header (see vtkOFBWriter).
struct Header
{
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double CellSize = 0.0;
  vtkTypeUInt64 StoredDimensions[3] = { 0, 0, 0 };
  vtkIdType Dimensions[3] = { 0, 0, 0 };
  vtkTypeUInt64 NumberOfCells = 0;
  vtkTypeUInt64 NumberOfSamples = 0;
  vtkTypeUInt64 NumberOfArrays = 0;
  bool Empty = true; // an empty OFB: no frame, no cells, no samples
};

using Code = vtkErrorCode::ErrorIds;

/// Whether `fileName` (its symbolic links followed) is a regular file.
bool IsRegularFile(const char* fileName)
{
#if defined(_WIN32)
  (void)fileName;
  return true;
#else
  struct stat info;
  return stat(fileName, &info) == 0 && S_ISREG(info.st_mode);
#endif
}

/// Open `fileName` and measure it.
bool OpenFile(const char* fileName, Source& src)
{
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
  if (!IsRegularFile(fileName))
  {
    // Opening a FIFO would wait for a writer; a device has no size to check counts with.
    return src.Fail(
      "it is not a regular file (a FIFO, a device or a socket)", Code::CannotOpenFileError);
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
  return true;
}

/// Read the header: signature, checksum, version and byte order, then its fields.
bool ReadHeader(Source& src, Header& header)
{
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
  header.CellSize = GetDouble(h + 40);
  for (int a = 0; a < 3; ++a)
  {
    header.Origin[a] = GetDouble(h + 16 + 8 * a);
    header.StoredDimensions[a] = GetLE(h + 48 + 8 * a, 8);
    header.Dimensions[a] = static_cast<vtkIdType>(header.StoredDimensions[a] & 0xFFFFFFFFu);
  }
  header.NumberOfCells = GetLE(h + 72, 8);
  header.NumberOfSamples = GetLE(h + 80, 8);
  header.NumberOfArrays = GetLE(h + 88, 4);
  const vtkTypeUInt64* d = header.StoredDimensions;
  header.Empty = header.CellSize == 0.0 && d[0] == 0 && d[1] == 0 && d[2] == 0;
  return true;
}

/// What is wrong with the frame and counts of `header`, or an empty string.
std::string CheckFrame(const Header& header)
{
  const vtkTypeUInt64 limit = std::numeric_limits<vtkTypeUInt32>::max();
  const vtkTypeUInt64* d = header.StoredDimensions;
  const vtkTypeUInt64 nCells = header.NumberOfCells;
  const vtkTypeUInt64 nSamples = header.NumberOfSamples;
  std::ostringstream msg;
  if (header.Empty)
  {
    if (nCells != 0 || nSamples != 0)
    {
      msg << "an empty frame with " << nCells << " cells and " << nSamples << " samples";
    }
    return msg.str();
  }
  vtkTypeUInt64 cells = 0;
  bool valid = true;
  for (int a = 0; a < 3; ++a)
  {
    valid = valid && d[a] >= 1 && d[a] < limit;
  }
  for (int a = 0; a < 3 && valid; ++a)
  {
    // Each dimension < 2^32: a product < 2^64; each product < 2^32: no overflow in the sum.
    const vtkTypeUInt64 grid = d[(a + 1) % 3] * d[(a + 2) % 3];
    valid = grid < limit;
    cells += valid ? grid : 0;
  }
  if (!valid)
  {
    msg << "invalid dimensions " << d[0] << " " << d[1] << " " << d[2]
        << " (each at least 1, fewer than 2^32 cells in all)";
    return msg.str();
  }
  const double dims[3] = {
    static_cast<double>(d[0]), static_cast<double>(d[1]), static_cast<double>(d[2])
  };
  const std::string frame = vtkofb::format::FrameProblem(header.Origin, header.CellSize, dims);
  if (!frame.empty())
  {
    msg << "an impossible frame: " << frame;
  }
  else if (cells >= limit || cells != nCells)
  {
    msg << nCells << " cells for dimensions " << d[0] << " " << d[1] << " " << d[2];
  }
  else if (nSamples >= limit)
  {
    msg << "an invalid sample count " << nSamples;
  }
  return msg.str();
}

/// Check the header's frame and that its counts fit in the file, before allocating.
bool CheckHeader(Source& src, const Header& header)
{
  std::string problem = CheckFrame(header);
  // Each array takes at least 36 bytes; cells, samples < 2^32 here: no overflow.
  const vtkTypeUInt64 least = Writer::HeaderSize + 4 * (header.NumberOfCells + 1) + 4 +
    4 * header.NumberOfSamples + 4 + 36 * header.NumberOfArrays + 8;
  if (problem.empty() && least > src.Size)
  {
    problem = std::to_string(header.NumberOfCells) + " cells, " +
      std::to_string(header.NumberOfSamples) + " samples and " +
      std::to_string(header.NumberOfArrays) + " arrays, which need at least " +
      std::to_string(least) + " bytes, but the file has " + std::to_string(src.Size) +
      " bytes (truncated or corrupted)";
  }
  return problem.empty() ? true : src.Fail("the header announces " + problem);
}

/// Set the frame and read the cell offsets: 0, non-decreasing, ending at the sample count.
bool ReadCellOffsets(Source& src, const Header& header, vtkOFB* output)
{
  const vtkTypeUInt64 nCells = header.NumberOfCells;
  vtkTypeUInt32 emptyOffset = 0;
  vtkTypeUInt32* offsets = &emptyOffset;
  if (!header.Empty)
  {
    if (!output->SetFrame(header.Origin, header.CellSize, header.Dimensions))
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
  bool valid = offsets[0] == 0 && offsets[nCells] == header.NumberOfSamples;
  for (vtkTypeUInt64 c = 0; c < nCells && valid; ++c)
  {
    valid = offsets[c] <= offsets[c + 1];
  }
  return valid
    ? true
    : src.Fail("the cell offsets do not run from 0 to the sample count without decreasing");
}

/// Allocate the samples and read their depths: finite and sorted within each cell.
bool ReadDepths(Source& src, const Header& header, vtkOFB* output)
{
  const vtkTypeUInt64 nSamples = header.NumberOfSamples;
  if (!output->AllocateSamples(static_cast<vtkIdType>(nSamples)))
  {
    return src.Fail("cannot allocate " + std::to_string(nSamples) + " samples", Code::UnknownError);
  }
  float* depths = nSamples > 0 ? output->GetDepths()->GetPointer(0) : nullptr;
  if (!src.Values(depths, nSamples, 4, "the depths") || !src.EndSection("the depths"))
  {
    return false;
  }
  const vtkTypeUInt32* offsets = header.Empty ? nullptr : output->GetCellOffsets()->GetPointer(0);
  bool valid = true;
  for (vtkTypeUInt64 c = 0; c < header.NumberOfCells && valid; ++c)
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
  if (!header.Empty &&
    !vtkofb::format::DepthsWithinBox(offsets, depths, header.CellSize, header.Dimensions))
  {
    return src.Fail("a depth lies outside the box of the frame (depths run from 0 to the "
                    "cell size times the number of cells along their axis)");
  }
  return true;
}

/// The header of a stored sample array (see vtkOFBWriter).
struct ArrayHeader
{
  std::string Name;
  vtkTypeUInt64 Type = 0;
  vtkTypeUInt64 ElementSize = 0;
  vtkTypeUInt64 Components = 0;
  vtkTypeUInt64 Tuples = 0;
  vtkTypeUInt64 Roles = 0;
};

/// Read the header of sample array `k`: name, type, shape and attribute roles.
bool ReadArrayHeader(Source& src, vtkTypeUInt64 k, ArrayHeader& array)
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
  array.Name.assign(static_cast<size_t>(nameLength), '\0');
  if ((nameLength > 0 && !src.Raw(&array.Name[0], nameLength, where)) || !src.Raw(f, 24, where) ||
    !src.EndSection(where))
  {
    return false;
  }
  if (array.Name.find('\0') != std::string::npos)
  {
    return src.Fail(where + ": the array name contains a NUL byte");
  }
  array.Type = GetLE(f, 4);
  array.ElementSize = GetLE(f + 4, 4);
  array.Components = GetLE(f + 8, 4);
  array.Tuples = GetLE(f + 12, 8);
  array.Roles = GetLE(f + 20, 4);
  return true;
}

/**
 * Read sample array `k` into the sample data of `output`, with its attribute roles
 * (none of them in `usedRoles`, to which they are added).
 */
bool ReadSampleArray(Source& src,
  const Header& header,
  vtkTypeUInt64 k,
  vtkOFB* output,
  WarningCatcher* catcher,
  vtkTypeUInt64& usedRoles)
{
  ArrayHeader a;
  if (!ReadArrayHeader(src, k, a))
  {
    return false;
  }
  vtkPointData* sd = output->GetSampleData();
  const int localType = LocalType(a.Type, a.ElementSize);
  const std::string named = "sample array " + std::to_string(k) + " '" + a.Name + "'";
  if (localType < 0)
  {
    return src.Fail(named + " has an unknown data type " + std::to_string(a.Type) + " of " +
      std::to_string(a.ElementSize) + " bytes");
  }
  if (a.Components < 1 || a.Components > (1u << 20) || a.Tuples != header.NumberOfSamples ||
    (a.Roles >> Writer::NumberOfRoleBits) != 0 || (a.Roles & usedRoles) != 0)
  {
    return src.Fail(named + " has " + std::to_string(a.Tuples) + " tuples of " +
      std::to_string(a.Components) + " components and roles " + std::to_string(a.Roles) +
      " (expected one tuple per sample, " + std::to_string(header.NumberOfSamples) +
      ", and roles not taken by another array)");
  }
  for (int r = 0; r < Writer::NumberOfRoleBits; ++r)
  {
    const std::string needed = ((a.Roles >> r) & 1u)
      ? vtkofb::format::RoleRequirement(r, localType, static_cast<int>(a.Components))
      : std::string();
    if (!needed.empty())
    {
      return src.Fail(named + " is " + vtkImageScalarTypeNameMacro(localType) + " with " +
        std::to_string(a.Components) + " components, but as the active " +
        vtkDataSetAttributes::GetAttributeTypeAsString(r) + " it must hold " + needed);
    }
  }
  // Components * element size < 2^24 and tuples < 2^32: no overflow.
  const vtkTypeUInt64 bytes = a.Tuples * a.Components * a.ElementSize;
  if (bytes + 4 + 8 > src.Remaining())
  {
    return src.Fail(named + " needs " + std::to_string(bytes) + " bytes of values, then 12 " +
        "bytes of checksum and trailer, but only " + std::to_string(src.Remaining()) +
        " bytes remain (truncated or corrupted)",
      Code::PrematureEndOfFileError);
  }
  if (!a.Name.empty() && sd->HasArray(a.Name.c_str()))
  {
    return src.Fail(named + " has the name of an earlier array");
  }
  auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(localType));
  array->SetNumberOfComponents(static_cast<int>(a.Components));
  if (a.Tuples > 0 && !array->Resize(static_cast<vtkIdType>(a.Tuples)))
  {
    return src.Fail("cannot allocate " + named, Code::UnknownError);
  }
  array->SetNumberOfTuples(static_cast<vtkIdType>(a.Tuples));
  if (!src.Values(a.Tuples > 0 ? array->GetVoidPointer(0) : nullptr,
        a.Tuples * a.Components,
        static_cast<int>(a.ElementSize),
        named) ||
    !src.EndSection(named))
  {
    return false;
  }
  if (!a.Name.empty())
  {
    array->SetName(a.Name.c_str());
  }
  const int index = sd->AddArray(array);
  for (int r = 0; r < Writer::NumberOfRoleBits; ++r)
  {
    if (((a.Roles >> r) & 1u) && sd->SetActiveAttribute(index, r) < 0)
    {
      return src.Fail(named + " cannot be the active " +
        vtkDataSetAttributes::GetAttributeTypeAsString(r) + " (" + catcher->Text + ")");
    }
  }
  usedRoles |= a.Roles;
  return true;
}

/// Read every sample array; the warnings of refused attribute roles explain the error.
bool ReadSampleArrays(Source& src, const Header& header, vtkOFB* output)
{
  vtkPointData* sd = output->GetSampleData();
  vtkNew<WarningCatcher> catcher;
  const unsigned long tag = sd->AddObserver(vtkCommand::WarningEvent, catcher);
  vtkTypeUInt64 usedRoles = 0;
  bool ok = true;
  for (vtkTypeUInt64 k = 0; k < header.NumberOfArrays && ok; ++k)
  {
    ok = ReadSampleArray(src, header, k, output, catcher, usedRoles);
  }
  sd->RemoveObserver(tag);
  return ok;
}

/// Read the trailer, which must end the file.
bool ReadTrailer(Source& src)
{
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
  return true;
}

/// Read an OFB file into `output`; false with the problem in `src`.
bool ReadOFB(const char* fileName, vtkOFB* output, Source& src)
{
  Header header;
  if (!OpenFile(fileName, src) || !ReadHeader(src, header) || !CheckHeader(src, header) ||
    !ReadCellOffsets(src, header, output) || !ReadDepths(src, header, output) ||
    !ReadSampleArrays(src, header, output) || !ReadTrailer(src))
  {
    return false;
  }
  return output->BuildCellIndex() ? true : src.Fail("cannot rebuild the cell index");
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
  if (!fileName || !IsRegularFile(fileName))
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
