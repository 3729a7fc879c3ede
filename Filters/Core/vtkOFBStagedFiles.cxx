#include "vtkOFBStagedFiles.h"
#include "vtkOFBTemporaryNames.h"

#include "vtksys/Directory.hxx"
#include "vtksys/SystemTools.hxx"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace
{
using SystemTools = vtksys::SystemTools;

std::atomic<unsigned> StageCounter(0);

std::string DirectoryOf(const std::string& path)
{
  const std::string::size_type slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

std::string NameOf(const std::string& path)
{
  return path.substr(path.find_last_of('/') + 1);
}

std::string Cause(int error)
{
  return std::strerror(error);
}

/// Remove the staging directories ".<name>.tmp-<tag>" in `directory` whose process is
/// gone (it was killed before it committed or cleaned up; vtkOFBTemporaryNames.h).
void RemoveStaleStages(const std::string& directory)
{
  vtksys::Directory listing;
  if (!listing.Load(directory))
  {
    return;
  }
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string name = listing.GetFile(i);
    const std::string::size_type mark = name.rfind(".tmp-");
    if (name.empty() || name[0] != '.' || mark == std::string::npos)
    {
      continue;
    }
    if (vtkofbtemporary::IsStale(name.substr(mark + 5)) &&
      SystemTools::FileIsDirectory(directory + "/" + name))
    {
      SystemTools::RemoveADirectory(directory + "/" + name);
    }
  }
}

/// Write all of `bytes` to the new file `path`, flush it to the disk; errno on failure.
int WriteNewFile(const std::string& path, const std::string& bytes)
{
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    return errno;
  }
  size_t done = 0;
  int error = 0;
  while (done < bytes.size() && error == 0)
  {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    error = n < 0 ? (errno == EINTR ? 0 : errno) : (n == 0 ? EIO : 0);
    done += n > 0 ? static_cast<size_t>(n) : 0;
  }
  error = error == 0 && fsync(fd) != 0 ? errno : error;
  error = close(fd) != 0 && error == 0 ? errno : error;
  return error;
}
}

//------------------------------------------------------------------------------
std::string vtkOFBStagedFiles::WhyNotWritable(const std::string& path)
{
  struct stat info;
  if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
  {
    return "it is a directory";
  }
  const std::string directory = DirectoryOf(path);
  if (stat(directory.c_str(), &info) != 0)
  {
    return "its directory '" + directory + "': " + Cause(errno);
  }
  if (!S_ISDIR(info.st_mode))
  {
    return "'" + directory + "' is not a directory";
  }
  if (access(directory.c_str(), W_OK | X_OK) != 0)
  {
    return "its directory '" + directory + "': " + Cause(errno);
  }
  return "";
}

//------------------------------------------------------------------------------
vtkOFBStagedFiles::vtkOFBStagedFiles(const std::string& target)
  : Directory(DirectoryOf(target))
{
}

//------------------------------------------------------------------------------
vtkOFBStagedFiles::~vtkOFBStagedFiles()
{
  if (!this->Stage.empty())
  {
    SystemTools::RemoveADirectory(this->Stage);
  }
}

//------------------------------------------------------------------------------
bool vtkOFBStagedFiles::Begin(const std::vector<std::string>& names, std::string& message)
{
  for (const std::string& name : names)
  {
    const std::string why = WhyNotWritable(this->Final(name));
    if (!why.empty())
    {
      message = "cannot write '" + this->Final(name) + "': " + why;
      return false;
    }
  }
  RemoveStaleStages(this->Directory);
  const std::string stage =
    this->Directory + "/." + NameOf(names.back()) + ".tmp-" + vtkofbtemporary::Tag(StageCounter++);
  if (mkdir(stage.c_str(), 0700) != 0)
  {
    message = "cannot write '" + this->Final(names.back()) + "': cannot create the staging " +
      "directory " + stage + ": " + Cause(errno);
    return false;
  }
  this->Stage = stage;
  return true;
}

//------------------------------------------------------------------------------
std::string vtkOFBStagedFiles::Staged(const std::string& name) const
{
  return this->Stage + "/" + name;
}

//------------------------------------------------------------------------------
std::string vtkOFBStagedFiles::Final(const std::string& name) const
{
  return this->Directory + "/" + name;
}

//------------------------------------------------------------------------------
bool vtkOFBStagedFiles::Write(const std::string& name,
  const std::string& bytes,
  std::string& message)
{
  const int error = WriteNewFile(this->Staged(name), bytes);
  if (error != 0)
  {
    message = "cannot write '" + this->Final(name) + "': " + Cause(error);
  }
  return error == 0;
}

//------------------------------------------------------------------------------
bool vtkOFBStagedFiles::Check(const std::string& name, std::string& message)
{
  const int fd = open(this->Staged(name).c_str(), O_RDWR | O_CLOEXEC);
  struct stat info;
  int error = fd < 0 ? errno : 0;
  error = error == 0 && fstat(fd, &info) != 0 ? errno : error;
  error = error == 0 && info.st_size == 0 ? EIO : error;
  error = error == 0 && fsync(fd) != 0 ? errno : error;
  if (fd >= 0)
  {
    close(fd);
  }
  if (error != 0)
  {
    message = "cannot write '" + this->Final(name) +
      "': " + (error == EIO ? std::string("the writer left it empty") : Cause(error));
  }
  return error == 0;
}

//------------------------------------------------------------------------------
bool vtkOFBStagedFiles::Incomplete(const std::string& name, std::string& message)
{
  int error = 0;
  const int fd = open(this->Staged(name).c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  struct stat info;
  if (fd >= 0 && fstat(fd, &info) == 0)
  {
    const std::string probe(4096, '\0');
    error = write(fd, probe.data(), probe.size()) < 0 ? errno : 0;
    error = error == 0 && fsync(fd) != 0 ? errno : error;
    (void)!ftruncate(fd, info.st_size);
  }
  if (fd >= 0)
  {
    close(fd);
  }
  message = "cannot write '" + this->Final(name) +
    "': " + (error != 0 ? Cause(error) : std::string("the writer stopped early"));
  return false;
}

//------------------------------------------------------------------------------
bool vtkOFBStagedFiles::Commit(const std::vector<std::string>& names, std::string& message)
{
  for (const std::string& name : names)
  {
    // A replaced file keeps its permissions.
    struct stat old;
    if (stat(this->Final(name).c_str(), &old) == 0 && S_ISREG(old.st_mode))
    {
      chmod(this->Staged(name).c_str(), old.st_mode & 07777);
    }
    if (std::rename(this->Staged(name).c_str(), this->Final(name).c_str()) != 0)
    {
      message = "cannot write '" + this->Final(name) + "': renaming it into place: " + Cause(errno);
      return false;
    }
  }
  const int directory = open(this->Directory.c_str(), O_RDONLY | O_CLOEXEC);
  if (directory >= 0)
  {
    fsync(directory); // the new names survive a power cut
    close(directory);
  }
  SystemTools::RemoveADirectory(this->Stage);
  this->Stage.clear();
  return true;
}
