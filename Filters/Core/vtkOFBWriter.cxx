#include "vtkOFBWriter.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkOFB.h"
#include "vtkOFBFileFormat.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtk_zlib.h"

#include <vtksys/Directory.hxx>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#if defined(_WIN32)
#include <io.h>
#include <process.h>
#include <windows.h>
#else
#include "vtkOFBTemporaryNames.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

vtkStandardNewMacro(vtkOFBWriter);

namespace
{
namespace format = vtkofb::format;

/// What the writer writes: the OFB's storage and sample arrays, and the file size.
struct Contents
{
  vtkIdType NumberOfCells = 0;
  vtkIdType NumberOfSamples = 0;
  const vtkTypeUInt32* Offsets = nullptr;
  const float* Depths = nullptr;
  std::vector<vtkSmartPointer<vtkDataArray>> Arrays; // standard memory layout
  std::vector<vtkTypeUInt32> Roles;                  // attribute bit masks
  vtkTypeUInt64 FileSize = 0;
};

const vtkTypeUInt32 NoOffsets = 0;

/// Take the frame's storage into `c`; a problem when the reader would refuse it.
std::string CollectStorage(vtkOFB* ofb, Contents& c)
{
  c.NumberOfCells = ofb->GetNumberOfCells();
  c.NumberOfSamples = ofb->GetNumberOfSamples();
  const vtkIdType nOffsets = ofb->GetCellOffsets()->GetNumberOfValues();
  c.Offsets = nOffsets > 0 ? ofb->GetCellOffsets()->GetPointer(0) : &NoOffsets;
  c.Depths = c.NumberOfSamples > 0 ? ofb->GetDepths()->GetPointer(0) : nullptr;
  // What the reader checks: offsets from 0 to the sample count, finite sorted depths.
  const vtkTypeUInt32* o = c.Offsets;
  const vtkIdType nCells = c.NumberOfCells;
  bool valid = (nOffsets == nCells + 1 || (nCells == 0 && nOffsets == 0)) && o[0] == 0 &&
    static_cast<vtkIdType>(o[nCells]) == c.NumberOfSamples;
  for (vtkIdType cell = 0; cell < nCells && valid; ++cell)
  {
    valid = o[cell] <= o[cell + 1];
    for (vtkTypeUInt32 i = o[cell]; i < o[cell + 1] && valid; ++i)
    {
      valid = std::isfinite(c.Depths[i]) && (i == o[cell] || c.Depths[i - 1] <= c.Depths[i]);
    }
  }
  if (!valid)
  {
    return "the OFB is inconsistent (" + std::to_string(nOffsets) + " cell offsets for " +
      std::to_string(nCells) + " cells and " + std::to_string(c.NumberOfSamples) +
      " samples, decreasing offsets, or depths not finite or not sorted within a cell)";
  }
  if (nCells > 0)
  {
    const vtkIdType* d = ofb->GetDimensions();
    const double dims[3] = {
      static_cast<double>(d[0]), static_cast<double>(d[1]), static_cast<double>(d[2])
    };
    const std::string frame = format::FrameProblem(ofb->GetOrigin(), ofb->GetCellSize(), dims);
    if (!frame.empty())
    {
      return "the frame cannot be stored: " + frame;
    }
    if (!format::DepthsWithinBox(o, c.Depths, ofb->GetCellSize(), d))
    {
      return "a depth lies outside the box of the frame";
    }
  }
  c.FileSize = vtkOFBWriter::HeaderSize + 4 * (nCells + 1) + 4 + 4 * c.NumberOfSamples + 4 + 8;
  return std::string();
}

/// Take the sample arrays with their attribute roles into `c`; a problem if one cannot be stored.
std::string CollectArrays(vtkOFB* ofb, Contents& c)
{
  vtkPointData* sd = ofb->GetSampleData();
  for (int i = 0; i < sd->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* abstract = sd->GetAbstractArray(i);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    const std::string name = abstract && abstract->GetName() ? abstract->GetName() : "";
    if (!array || array->GetDataType() == VTK_BIT)
    {
      return "sample array " + std::to_string(i) + " '" + name + "' is not a numeric array (" +
        (abstract ? abstract->GetClassName() : "null") + ")";
    }
    if (name.size() > 65536)
    {
      return "the name of sample array " + std::to_string(i) + " is longer than 65536 bytes";
    }
    if (array->GetNumberOfTuples() != c.NumberOfSamples)
    {
      return "sample array '" + name + "' has " + std::to_string(array->GetNumberOfTuples()) +
        " tuples for " + std::to_string(c.NumberOfSamples) + " samples";
    }
    vtkSmartPointer<vtkDataArray> aos = array;
    if (!array->HasStandardMemoryLayout())
    {
      aos =
        vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(array->GetDataType()));
      aos->DeepCopy(array);
    }
    vtkTypeUInt32 mask = 0;
    for (int k = 0; k < vtkOFBWriter::NumberOfRoleBits; ++k)
    {
      mask |= sd->GetAbstractAttribute(k) == abstract ? 1u << k : 0u;
    }
    for (int k = 0; k < vtkOFBWriter::NumberOfRoleBits; ++k)
    {
      const std::string needed = ((mask >> k) & 1u)
        ? format::RoleRequirement(k, array->GetDataType(), array->GetNumberOfComponents())
        : std::string();
      if (!needed.empty())
      {
        return "sample array " + std::to_string(i) + " '" + name + "' is " +
          array->GetDataTypeAsString() + " with " + std::to_string(array->GetNumberOfComponents()) +
          " components, but as the active " + vtkDataSetAttributes::GetAttributeTypeAsString(k) +
          " it must hold " + needed + " (vtkOFBReader would refuse it)";
      }
    }
    c.Arrays.push_back(aos);
    c.Roles.push_back(mask);
    c.FileSize += 4 + name.size() + 28 + 4 +
      static_cast<vtkTypeUInt64>(c.NumberOfSamples) * array->GetNumberOfComponents() *
        array->GetDataTypeSize();
  }
  return std::string();
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
    for (vtkTypeUInt64 first = 0; first < count && !this->Failed; first += chunk)
    {
      const size_t n = static_cast<size_t>(std::min<vtkTypeUInt64>(chunk, count - first));
      const unsigned char* src = p + first * elementSize;
      if (!format::HostIsLittleEndian() && elementSize > 1)
      {
        this->Swapped.assign(src, src + n * elementSize);
        format::SwapLittleEndian(this->Swapped.data(), n, elementSize);
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
    format::PutLE(bytes, this->CRC, 4);
    this->Raw(bytes.data(), bytes.size());
    this->CRC = 0;
  }

  void Header(vtkOFB* ofb, const Contents& c)
  {
    std::vector<unsigned char> bytes(vtkOFBWriter::Magic, vtkOFBWriter::Magic + 8);
    format::PutLE(bytes, vtkOFBWriter::GetFormatVersion(), 4);
    format::PutLE(bytes, vtkOFBWriter::ByteOrderMark, 4);
    for (int a = 0; a < 3; ++a)
    {
      format::PutDouble(bytes, ofb->GetOrigin()[a]);
    }
    format::PutDouble(bytes, ofb->GetCellSize());
    for (int a = 0; a < 3; ++a)
    {
      format::PutLE(bytes, static_cast<vtkTypeUInt64>(ofb->GetDimensions()[a]), 8);
    }
    format::PutLE(bytes, static_cast<vtkTypeUInt64>(c.NumberOfCells), 8);
    format::PutLE(bytes, static_cast<vtkTypeUInt64>(c.NumberOfSamples), 8);
    format::PutLE(bytes, c.Arrays.size(), 4);
    this->Raw(bytes.data(), bytes.size());
    this->EndSection();
  }

  void Storage(const Contents& c)
  {
    this->Values(c.Offsets, static_cast<vtkTypeUInt64>(c.NumberOfCells) + 1, 4);
    this->EndSection();
    this->Values(c.Depths, c.NumberOfSamples, 4);
    this->EndSection();
  }

  void Arrays(const Contents& c)
  {
    for (size_t i = 0; i < c.Arrays.size(); ++i)
    {
      vtkDataArray* array = c.Arrays[i];
      const std::string name = array->GetName() ? array->GetName() : "";
      std::vector<unsigned char> bytes;
      format::PutLE(bytes, name.size(), 4);
      bytes.insert(bytes.end(), name.begin(), name.end());
      format::PutLE(bytes, static_cast<vtkTypeUInt32>(array->GetDataType()), 4);
      format::PutLE(bytes, static_cast<vtkTypeUInt32>(array->GetDataTypeSize()), 4);
      format::PutLE(bytes, static_cast<vtkTypeUInt32>(array->GetNumberOfComponents()), 4);
      format::PutLE(bytes, static_cast<vtkTypeUInt64>(c.NumberOfSamples), 8);
      format::PutLE(bytes, c.Roles[i], 4);
      this->Raw(bytes.data(), bytes.size());
      this->EndSection();
      this->Values(c.NumberOfSamples > 0 ? array->GetVoidPointer(0) : nullptr,
        static_cast<vtkTypeUInt64>(c.NumberOfSamples) * array->GetNumberOfComponents(),
        array->GetDataTypeSize());
      this->EndSection();
    }
  }
};

std::atomic<unsigned int> TemporaryCounter(0);

long ProcessId()
{
#if defined(_WIN32)
  return static_cast<long>(_getpid());
#else
  return static_cast<long>(getpid());
#endif
}

/// The directory part of `path` ("." when it has none).
std::string DirectoryOf(const std::string& path)
{
  const std::string::size_type slash = path.find_last_of("/\\");
  return slash == std::string::npos ? std::string(".")
                                    : (slash == 0 ? std::string("/") : path.substr(0, slash));
}

/// The file that `path` names once its symbolic links are followed (it may not exist).
std::string FollowLinks(const std::string& path)
{
  std::string file = path;
#if !defined(_WIN32)
  for (int hop = 0; hop < 40; ++hop)
  {
    struct stat info;
    if (lstat(file.c_str(), &info) != 0 || !S_ISLNK(info.st_mode))
    {
      break;
    }
    std::vector<char> link(static_cast<size_t>(std::max<off_t>(info.st_size, PATH_MAX)) + 1);
    const ssize_t n = readlink(file.c_str(), link.data(), link.size() - 1);
    if (n <= 0)
    {
      break;
    }
    const std::string to(link.data(), static_cast<size_t>(n));
    file = to[0] == '/' ? to : DirectoryOf(file) + "/" + to;
  }
#endif
  return file;
}

/**
 * What `target` (its symbolic links followed) is when it exists and is not a regular
 * file, or an empty string. Renaming the new file over a device, a FIFO or a socket would
 * replace it with a regular file (as root, /dev/null itself), and a directory cannot be
 * replaced: the writer refuses such targets.
 */
std::string NotARegularFile(const std::string& target)
{
#if !defined(_WIN32)
  struct stat info;
  if (lstat(target.c_str(), &info) != 0)
  {
    return errno == ENOENT ? std::string() : "a path that cannot be examined";
  }
  if (S_ISREG(info.st_mode))
  {
    return std::string();
  }
  if (S_ISDIR(info.st_mode))
  {
    return "a directory";
  }
  if (S_ISFIFO(info.st_mode))
  {
    return "a FIFO (named pipe)";
  }
  if (S_ISCHR(info.st_mode))
  {
    return "a character device";
  }
  if (S_ISBLK(info.st_mode))
  {
    return "a block device";
  }
  if (S_ISSOCK(info.st_mode))
  {
    return "a socket";
  }
  if (S_ISLNK(info.st_mode))
  {
    return "a chain of symbolic links that does not end (a loop)";
  }
  return "a special file";
#else
  const DWORD attributes = GetFileAttributesA(target.c_str());
  return attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_DIRECTORY)
    ? "a directory"
    : std::string();
#endif
}

/**
 * Remove the named temporaries "<target>.tmp-<tag>" that writers of this machine left
 * behind when their process died (killed, or crashed) before renaming them
 * (vtkOFBTemporaryNames.h). A temporary of a living process (this one included), or of
 * another machine, is kept.
 */
void RemoveStaleTemporaries(const std::string& target)
{
#if !defined(_WIN32)
  const std::string directory = DirectoryOf(target);
  const std::string prefix = target.substr(target.find_last_of('/') + 1) + ".tmp-";
  vtksys::Directory listing;
  if (!listing.Load(directory))
  {
    return;
  }
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string name = listing.GetFile(i);
    if (name.compare(0, prefix.size(), prefix) == 0 &&
      vtkofbtemporary::IsStale(name.substr(prefix.size())))
    {
      unlink((directory + "/" + name).c_str());
    }
  }
#else
  (void)target;
#endif
}

/**
 * The file that replaces the target: written, flushed to the disk, then renamed over
 * the target in one step, with the target's permissions. Where the system allows it
 * (Linux's O_TMPFILE), the file has no name until it is complete, so a crash leaves
 * nothing behind; otherwise it is "<target>.tmp-<host>-<pid>-<n>", which
 * RemoveStaleTemporaries removes after a crash.
 */
class ReplacementFile
{
public:
  ~ReplacementFile() { this->Discard(); }

  /// Create the file beside `target`; false with the problem in Problem.
  bool Create(const std::string& target)
  {
    this->Target = target;
#if defined(_WIN32)
    this->Name =
      target + ".tmp-" + std::to_string(ProcessId()) + "-" + std::to_string(TemporaryCounter++);
#else
    this->Name = target + ".tmp-" + vtkofbtemporary::Tag(TemporaryCounter++);
#endif
#if defined(_WIN32)
    this->Stream = std::fopen(this->Name.c_str(), "wb");
    return this->Stream ? true : this->Fail("cannot create the temporary file " + this->Name);
#else
    struct stat existing;
    const bool keepMode = stat(target.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
    // A new file gets 0666 less the umask, as fopen gives; a replacement starts private
    // and takes the target's mode and owner.
    const mode_t mode = keepMode ? 0600 : 0666;
    this->Descriptor = this->OpenUnnamed(mode);
    this->Unnamed = this->Descriptor >= 0;
    if (!this->Unnamed)
    {
      this->Descriptor = open(this->Name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    }
    if (this->Descriptor < 0)
    {
      return this->Fail("cannot create the temporary file " + this->Name);
    }
    if (keepMode)
    {
      (void)!fchown(this->Descriptor, existing.st_uid, existing.st_gid); // may be refused
      if (fchmod(this->Descriptor, existing.st_mode & 07777) != 0)
      {
        return this->Fail("cannot give the temporary file the permissions of the target");
      }
    }
    this->Stream = fdopen(this->Descriptor, "wb");
    if (!this->Stream)
    {
      return this->Fail("cannot open a stream on the temporary file");
    }
    this->Descriptor = -1; // owned by the stream now
    return true;
#endif
  }

  std::FILE* GetStream() const
  {
    return this->Stream;
  }
  bool IsUnnamed() const
  {
    return this->Unnamed;
  }

  /// Flush the data to the disk; false with the problem in Problem.
  bool Flush()
  {
    if (std::fflush(this->Stream) != 0)
    {
      return this->Fail("flushing the temporary file failed");
    }
#if defined(_WIN32)
    const bool synced = _commit(_fileno(this->Stream)) == 0;
#else
    const bool synced = fsync(fileno(this->Stream)) == 0;
#endif
    return synced ? true : this->Fail("flushing the temporary file to the disk failed");
  }

  /**
   * Put the complete file in place of the target: name it (if unnamed), rename it
   * over the target, and flush the directory so that the new name survives a power
   * cut. False with the problem in Problem; the target is then unchanged.
   */
  bool Commit()
  {
#if defined(_WIN32)
    std::fclose(this->Stream);
    this->Stream = nullptr;
    // std::rename does not replace an existing file on Windows.
    if (MoveFileExA(this->Name.c_str(),
          this->Target.c_str(),
          MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) == 0)
    {
      return this->Fail("renaming the temporary file " + this->Name + " over it failed");
    }
    this->Name.clear();
    return true;
#else
    if (this->Unnamed)
    {
      const std::string self = "/proc/self/fd/" + std::to_string(fileno(this->Stream));
      if (linkat(AT_FDCWD, self.c_str(), AT_FDCWD, this->Name.c_str(), AT_SYMLINK_FOLLOW) != 0)
      {
        return this->Fail("naming the temporary file " + this->Name + " failed");
      }
      this->Unnamed = false;
    }
    if (std::fclose(this->Stream) != 0)
    {
      this->Stream = nullptr;
      return this->Fail("closing the temporary file " + this->Name + " failed");
    }
    this->Stream = nullptr;
    if (std::rename(this->Name.c_str(), this->Target.c_str()) != 0)
    {
      return this->Fail("renaming the temporary file " + this->Name + " over it failed");
    }
    this->Name.clear();
    const int directory = open(DirectoryOf(this->Target).c_str(), O_RDONLY | O_CLOEXEC);
    if (directory >= 0)
    {
      fsync(directory);
      close(directory);
    }
    return true;
#endif
  }

  /// Close and remove the file if it was not committed.
  void Discard()
  {
    if (this->Stream)
    {
      std::fclose(this->Stream);
      this->Stream = nullptr;
    }
#if !defined(_WIN32)
    if (this->Descriptor >= 0)
    {
      close(this->Descriptor);
      this->Descriptor = -1;
    }
#endif
    if (!this->Unnamed && !this->Name.empty())
    {
      std::remove(this->Name.c_str());
    }
    this->Name.clear();
  }

  std::string Problem;
  int Errno = 0;

private:
  bool Fail(const std::string& problem)
  {
    this->Errno = errno;
    this->Problem = problem + " (" + std::strerror(this->Errno) + ")";
    return false;
  }

#if !defined(_WIN32)
  /// An unnamed file in the target's directory, or -1 where the system has none.
  int OpenUnnamed(mode_t mode) const
  {
#if defined(O_TMPFILE)
    // Naming it later goes through /proc/self/fd.
    if (access("/proc/self/fd", X_OK) == 0)
    {
      return open(DirectoryOf(this->Target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
    }
#endif
    (void)mode;
    return -1;
  }
  int Descriptor = -1;
#endif

  std::string Target;
  std::string Name;
  std::FILE* Stream = nullptr;
  bool Unnamed = false;
};
/**
 * Write the file's bytes to `file` and flush them to the disk; false with the
 * problem and the system's error number otherwise.
 */
bool WriteContents(vtkAlgorithm* owner,
  vtkOFB* ofb,
  const Contents& contents,
  ReplacementFile& file,
  std::string& problem,
  int& error)
{
  Sink sink;
  sink.Owner = owner;
  sink.File = file.GetStream();
  sink.Total = contents.FileSize;
  sink.Header(ofb, contents);
  sink.Storage(contents);
  sink.Arrays(contents);
  sink.Raw(vtkOFBWriter::Trailer, 8);
  if (!sink.Failed && !file.Flush())
  {
    sink.Failed = true;
    sink.Errno = file.Errno;
  }
  if (sink.Failed || sink.Done != contents.FileSize)
  {
    error = sink.Errno;
    problem = "writing the temporary file failed after " + std::to_string(sink.Done) + " of " +
      std::to_string(contents.FileSize) + " bytes (" + std::strerror(sink.Errno) + ")";
    return false;
  }
  return true;
}
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
  // zlib takes at most 2^32 - 1 bytes at a time.
  const Bytef* p = static_cast<const Bytef*>(data);
  uLong c = crc;
  while (size > 0)
  {
    const uInt n = static_cast<uInt>(std::min<size_t>(size, size_t(1) << 30));
    c = crc32(c, p, n);
    p += n;
    size -= n;
  }
  return static_cast<unsigned int>(c);
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
  Contents contents;
  std::string problem = CollectStorage(ofb, contents);
  problem = problem.empty() ? CollectArrays(ofb, contents) : problem;
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot write " << this->FileName << ": " << problem << ".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  // Through a symbolic link, replace the file it points to and keep the link.
  const std::string target = FollowLinks(this->FileName);
  const std::string special = NotARegularFile(target);
  if (!special.empty())
  {
    vtkErrorMacro("Cannot write " << this->FileName << ": "
                                  << (target == this->FileName ? "it" : target.c_str()) << " is "
                                  << special << ", not a regular file; nothing was written.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  RemoveStaleTemporaries(target);
  ReplacementFile file;
  int error = 0;
  if (!file.Create(target))
  {
    this->ReportWriteError(file.Problem, vtkErrorCode::CannotOpenFileError);
  }
  else if (!WriteContents(this, ofb, contents, file, problem, error))
  {
    this->ReportWriteError(
      problem, error == ENOSPC ? vtkErrorCode::OutOfDiskSpaceError : vtkErrorCode::UnknownError);
  }
  else if (!file.Commit())
  {
    this->ReportWriteError(file.Problem, vtkErrorCode::CannotOpenFileError);
  }
  else
  {
    this->UpdateProgress(1.0);
  }
}

//------------------------------------------------------------------------------
void vtkOFBWriter::ReportWriteError(const std::string& problem, unsigned long code)
{
  vtkErrorMacro(
    "Cannot write " << this->FileName << ": " << problem << "; the existing file is unchanged.");
  this->SetErrorCode(code);
}

//------------------------------------------------------------------------------
void vtkOFBWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FormatVersion: " << vtkOFBWriter::GetFormatVersion() << "\n";
}
