// A scratch directory for one GoogleTest unit (the file I/O tests of OFB::Core and
// OFB::IOImage): fresh when made, removed with everything in it at the end of the test.
#ifndef vtkOFBTempDirectory_h
#define vtkOFBTempDirectory_h

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#if defined(_WIN32)
#include <process.h>
#define getpid _getpid
#else
#include <unistd.h>
#endif

namespace vtkofbtest
{
/// A fresh directory under GoogleTest's temporary directory (else /tmp), named
/// "<prefix><pid>-<n>", removed at the end of the test.
class TempDirectory
{
public:
  explicit TempDirectory(const std::string& prefix = "vtkofb-io-")
  {
    static int counter = 0;
    std::string base = testing::TempDir();
    if (base.empty())
    {
      base = "/tmp/";
    }
    if (base.back() != '/')
    {
      base += '/';
    }
    this->Path = base + prefix + std::to_string(getpid()) + "-" + std::to_string(counter++);
    vtksys::SystemTools::RemoveADirectory(this->Path);
    vtksys::SystemTools::MakeDirectory(this->Path);
  }
  ~TempDirectory() { vtksys::SystemTools::RemoveADirectory(this->Path); }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  /// The path of the file `name` in the directory.
  std::string File(const std::string& name) const { return this->Path + "/" + name; }
  /// The names of the directory's entries ("." and ".." left out).
  std::vector<std::string> List() const
  {
    std::vector<std::string> names;
    vtksys::Directory dir;
    dir.Load(this->Path);
    for (unsigned long i = 0; i < dir.GetNumberOfFiles(); ++i)
    {
      const std::string name = dir.GetFile(i);
      if (name != "." && name != "..")
      {
        names.push_back(name);
      }
    }
    return names;
  }
  std::string Path;
};
}

#endif
