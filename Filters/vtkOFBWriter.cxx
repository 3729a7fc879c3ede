#include "vtkOFBWriter.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#if defined(_WIN32)
#include <io.h>
#include <process.h>
#include <windows.h>
#else
#include <unistd.h>
#endif

vtkStandardNewMacro(vtkOFBWriter);

namespace
{
bool HostIsLittleEndian()
{
  const vtkTypeUInt32 one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Append `value` to `out` as `size` little-endian bytes.
void PutLE(std::vector<unsigned char>& out, vtkTypeUInt64 value, int size)
{
  for (int i = 0; i < size; ++i)
  {
    out.push_back(static_cast<unsigned char>((value >> (8 * i)) & 0xFFu));
  }
}

void PutDouble(std::vector<unsigned char>& out, double value)
{
  vtkTypeUInt64 bits;
  std::memcpy(&bits, &value, sizeof(bits));
  PutLE(out, bits, 8);
}

/**
 * A file being written: every write is checked, checksummed and counted for the
 * progress of the writer.
 */
struct Sink
{
  std::FILE* File = nullptr;
  vtkAlgorithm* Owner = nullptr;
  vtkTypeUInt32 CRC = 0;
  vtkTypeUInt64 Done = 0;
  vtkTypeUInt64 Total = 1;
  bool Failed = false;
  int Errno = 0;
  std::vector<unsigned char> Swapped;

  void Raw(const void* data, size_t size)
  {
    if (this->Failed || size == 0)
    {
      return;
    }
    if (std::fwrite(data, 1, size, this->File) != size)
    {
      this->Failed = true;
      this->Errno = errno;
      return;
    }
    this->CRC = vtkOFBWriter::UpdateCRC32(this->CRC, data, size);
    this->Done += size;
  }

  /// Write `count` values of `elementSize` bytes, little-endian, in chunks.
  void Values(const void* data, vtkTypeUInt64 count, int elementSize)
  {
    const size_t chunk = (size_t(1) << 22) / elementSize;
    const unsigned char* p = static_cast<const unsigned char*>(data);
    const bool swap = elementSize > 1 && !HostIsLittleEndian();
    for (vtkTypeUInt64 first = 0; first < count && !this->Failed; first += chunk)
    {
      const size_t n = static_cast<size_t>(std::min<vtkTypeUInt64>(chunk, count - first));
      const unsigned char* src = p + first * elementSize;
      if (swap)
      {
        this->Swapped.assign(src, src + n * elementSize);
        for (size_t i = 0; i < n; ++i)
        {
          std::reverse(&this->Swapped[i * elementSize], &this->Swapped[(i + 1) * elementSize]);
        }
        src = this->Swapped.data();
      }
      this->Raw(src, n * elementSize);
      this->Owner->UpdateProgress(static_cast<double>(this->Done) / this->Total);
    }
  }

  /// End a section with the CRC of its bytes, and start the next one.
  void EndSection()
  {
    std::vector<unsigned char> bytes;
    PutLE(bytes, this->CRC, 4);
    this->Raw(bytes.data(), bytes.size());
    this->CRC = 0;
  }
};

/// Flush the data of an open file to the disk; false on failure.
bool SyncToDisk(std::FILE* file)
{
#if defined(_WIN32)
  return _commit(_fileno(file)) == 0;
#else
  return fsync(fileno(file)) == 0;
#endif
}

std::atomic<unsigned int> TemporaryCounter(0);
}

//------------------------------------------------------------------------------
vtkOFBWriter::vtkOFBWriter()
  : FileName(nullptr)
{
}

//------------------------------------------------------------------------------
vtkOFBWriter::~vtkOFBWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBWriter::GetInput()
{
  return this->GetInput(0);
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBWriter::GetInput(int port)
{
  return vtkOFB::SafeDownCast(this->Superclass::GetInput(port));
}

//------------------------------------------------------------------------------
int vtkOFBWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
unsigned int vtkOFBWriter::UpdateCRC32(unsigned int crc, const void* data, size_t size)
{
  static const struct Table
  {
    vtkTypeUInt32 Entries[256];
    Table()
    {
      for (vtkTypeUInt32 i = 0; i < 256; ++i)
      {
        vtkTypeUInt32 c = i;
        for (int k = 0; k < 8; ++k)
        {
          c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
        }
        this->Entries[i] = c;
      }
    }
  } table;
  const unsigned char* p = static_cast<const unsigned char*>(data);
  vtkTypeUInt32 c = ~static_cast<vtkTypeUInt32>(crc);
  for (size_t i = 0; i < size; ++i)
  {
    c = table.Entries[(c ^ p[i]) & 0xFFu] ^ (c >> 8);
  }
  return ~c;
}

//------------------------------------------------------------------------------
void vtkOFBWriter::WriteData()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName: set the name of the .ofb file to write.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  vtkOFB* ofb = this->GetInput();
  if (!ofb)
  {
    vtkErrorMacro("Cannot write " << this->FileName << ": the input is not a vtkOFB.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  this->UpdateProgress(0.0);

#if defined(_WIN32)
  const long pid = static_cast<long>(_getpid());
#else
  const long pid = static_cast<long>(getpid());
#endif
  const std::string temporary = std::string(this->FileName) + ".tmp-" + std::to_string(pid) + "-" +
    std::to_string(TemporaryCounter++);
  if (!this->WriteToTemporary(ofb, temporary.c_str()))
  {
    std::remove(temporary.c_str());
    return;
  }
#if defined(_WIN32)
  // std::rename does not replace an existing file on Windows.
  const bool renamed =
    MoveFileExA(
      temporary.c_str(), this->FileName, MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) != 0;
#else
  const bool renamed = std::rename(temporary.c_str(), this->FileName) == 0;
#endif
  if (!renamed)
  {
    const int error = errno;
    std::remove(temporary.c_str());
    vtkErrorMacro("Cannot write " << this->FileName << ": renaming the temporary file " << temporary
                                  << " over it failed (" << std::strerror(error)
                                  << "); the existing file is unchanged.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
bool vtkOFBWriter::WriteToTemporary(vtkOFB* ofb, const char* path)
{
  // Check the OFB and collect the arrays before touching the disk.
  const vtkIdType nCells = ofb->GetNumberOfCells();
  const vtkIdType nSamples = ofb->GetNumberOfSamples();
  vtkTypeUInt32Array* offsets = ofb->GetCellOffsets();
  const vtkTypeUInt32 zero = 0;
  const vtkIdType nOffsets = offsets->GetNumberOfValues();
  const vtkTypeUInt32* o = nOffsets > 0 ? offsets->GetPointer(0) : &zero;
  const float* depths = nSamples > 0 ? ofb->GetDepths()->GetPointer(0) : nullptr;
  // What the reader checks: offsets from 0 to the sample count, finite sorted depths.
  bool valid = (nOffsets == nCells + 1 || (nCells == 0 && nOffsets == 0)) && o[0] == 0 &&
    static_cast<vtkIdType>(o[nCells]) == nSamples;
  for (vtkIdType c = 0; c < nCells && valid; ++c)
  {
    valid = o[c] <= o[c + 1];
    for (vtkTypeUInt32 i = o[c]; i < o[c + 1] && valid; ++i)
    {
      valid = std::isfinite(depths[i]) && (i == o[c] || depths[i - 1] <= depths[i]);
    }
  }
  if (!valid)
  {
    vtkErrorMacro("Cannot write " << this->FileName << ": the OFB is inconsistent (" << nOffsets
                                  << " cell offsets for " << nCells << " cells and " << nSamples
                                  << " samples, decreasing offsets, or depths not finite or not "
                                     "sorted within a cell).");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return false;
  }
  vtkPointData* sd = ofb->GetSampleData();
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  std::vector<vtkTypeUInt32> roles;
  vtkTypeUInt64 total = HeaderSize + 4 * (nCells + 1) + 4 + 4 * nSamples + 4 + 8;
  for (int i = 0; i < sd->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* abstract = sd->GetAbstractArray(i);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    const char* name = abstract && abstract->GetName() ? abstract->GetName() : "";
    if (!array || array->GetDataType() == VTK_BIT)
    {
      vtkErrorMacro("Cannot write " << this->FileName << ": sample array " << i << " '" << name
                                    << "' is not a numeric array ("
                                    << (abstract ? abstract->GetClassName() : "null") << ").");
      this->SetErrorCode(vtkErrorCode::UnknownError);
      return false;
    }
    if (std::strlen(name) > 65536)
    {
      vtkErrorMacro("Cannot write " << this->FileName << ": the name of sample array " << i
                                    << " is longer than 65536 bytes.");
      this->SetErrorCode(vtkErrorCode::UnknownError);
      return false;
    }
    if (array->GetNumberOfTuples() != nSamples)
    {
      vtkErrorMacro("Cannot write " << this->FileName << ": sample array '" << name << "' has "
                                    << array->GetNumberOfTuples() << " tuples for " << nSamples
                                    << " samples.");
      this->SetErrorCode(vtkErrorCode::UnknownError);
      return false;
    }
    vtkSmartPointer<vtkDataArray> aos = array;
    if (!array->HasStandardMemoryLayout())
    {
      aos =
        vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(array->GetDataType()));
      aos->DeepCopy(array);
    }
    vtkTypeUInt32 mask = 0;
    for (int k = 0; k < NumberOfRoleBits; ++k)
    {
      if (sd->GetAbstractAttribute(k) == abstract)
      {
        mask |= 1u << k;
      }
    }
    arrays.push_back(aos);
    roles.push_back(mask);
    total += 4 + std::strlen(name) + 28 + 4 +
      static_cast<vtkTypeUInt64>(nSamples) * array->GetNumberOfComponents() *
        array->GetDataTypeSize();
  }

  Sink sink;
  sink.Owner = this;
  sink.Total = total;
  sink.File = std::fopen(path, "wb");
  if (!sink.File)
  {
    const int error = errno;
    vtkErrorMacro("Cannot write " << this->FileName << ": cannot create the temporary file " << path
                                  << " (" << std::strerror(error) << ").");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return false;
  }

  // Header.
  std::vector<unsigned char> bytes(Magic, Magic + 8);
  PutLE(bytes, GetFormatVersion(), 4);
  PutLE(bytes, ByteOrderMark, 4);
  for (int a = 0; a < 3; ++a)
  {
    PutDouble(bytes, ofb->GetOrigin()[a]);
  }
  PutDouble(bytes, ofb->GetCellSize());
  for (int a = 0; a < 3; ++a)
  {
    PutLE(bytes, static_cast<vtkTypeUInt64>(ofb->GetDimensions()[a]), 8);
  }
  PutLE(bytes, static_cast<vtkTypeUInt64>(nCells), 8);
  PutLE(bytes, static_cast<vtkTypeUInt64>(nSamples), 8);
  PutLE(bytes, arrays.size(), 4);
  sink.Raw(bytes.data(), bytes.size());
  sink.EndSection();

  // Cell offsets and depths.
  sink.Values(o, static_cast<vtkTypeUInt64>(nCells) + 1, 4);
  sink.EndSection();
  sink.Values(depths, nSamples, 4);
  sink.EndSection();

  // Sample arrays.
  for (size_t i = 0; i < arrays.size(); ++i)
  {
    vtkDataArray* array = arrays[i];
    const std::string name = array->GetName() ? array->GetName() : "";
    bytes.clear();
    PutLE(bytes, name.size(), 4);
    bytes.insert(bytes.end(), name.begin(), name.end());
    PutLE(bytes, static_cast<vtkTypeUInt32>(array->GetDataType()), 4);
    PutLE(bytes, static_cast<vtkTypeUInt32>(array->GetDataTypeSize()), 4);
    PutLE(bytes, static_cast<vtkTypeUInt32>(array->GetNumberOfComponents()), 4);
    PutLE(bytes, static_cast<vtkTypeUInt64>(nSamples), 8);
    PutLE(bytes, roles[i], 4);
    sink.Raw(bytes.data(), bytes.size());
    sink.EndSection();
    sink.Values(nSamples > 0 ? array->GetVoidPointer(0) : nullptr,
      static_cast<vtkTypeUInt64>(nSamples) * array->GetNumberOfComponents(),
      array->GetDataTypeSize());
    sink.EndSection();
  }
  sink.Raw(Trailer, 8);

  // Flush to the disk and close, checking each step.
  if (!sink.Failed && std::fflush(sink.File) != 0)
  {
    sink.Failed = true;
    sink.Errno = errno;
  }
  if (!sink.Failed && !SyncToDisk(sink.File))
  {
    sink.Failed = true;
    sink.Errno = errno;
  }
  if (std::fclose(sink.File) != 0 && !sink.Failed)
  {
    sink.Failed = true;
    sink.Errno = errno;
  }
  if (sink.Failed || sink.Done != total)
  {
    vtkErrorMacro("Cannot write " << this->FileName << ": writing the temporary file " << path
                                  << " failed after " << sink.Done << " of " << total << " bytes ("
                                  << std::strerror(sink.Errno)
                                  << "); the existing file is unchanged.");
    this->SetErrorCode(
      sink.Errno == ENOSPC ? vtkErrorCode::OutOfDiskSpaceError : vtkErrorCode::UnknownError);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FormatVersion: " << vtkOFBWriter::GetFormatVersion() << "\n";
}
