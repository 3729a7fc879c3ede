/**
 * @file   ofbExampleFiles.h
 * @brief  How the example applications write files: checked, and replacing the old ones
 *         only when complete
 *
 * Every file an application writes (screenshots, exported meshes, their .mtl and texture)
 * is first written into a private staging directory beside its target,
 * "<directory>/.<target name>.tmp-<pid>-<n>/", every write checked and the file flushed
 * to the disk, then renamed over its target (one step per file: a reader sees the old file
 * or the new one, never a part). On any failure the staging directory and everything in it
 * are removed and the targets are untouched; a failure's message gives its cause
 * (strerror of the failed call). Staging directories of processes that died (kill -9) are
 * removed by the next write into the same directory. This follows vtkOFBWriter's
 * temporary-and-rename scheme; a directory rather than a file because VTK's OBJ writer
 * names its .mtl after its own file.
 */
#ifndef ofbExampleFiles_h
#define ofbExampleFiles_h

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkImageData;

namespace ofbexample
{
/// Why `path` cannot be written ("" when it can): it is a directory, or its directory is
/// missing, not a directory or not writable.
std::string WhyNotWritable(const std::string& path);

/// Files staged beside `target` and put in place together by Commit.
class StagedFiles
{
public:
  explicit StagedFiles(const std::string& target);
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;

  /// Check that each of `names` (file names in the target's directory, the target's among
  /// them) can be written, remove stale staging directories, create this one; false with
  /// `message` the reason.
  bool Begin(const std::vector<std::string>& names, std::string& message);
  /// Where the file `name` is staged (give it to a VTK writer).
  std::string Staged(const std::string& name) const;
  /// The final path of the file `name`.
  std::string Final(const std::string& name) const;
  /// Write `bytes` as the staged file `name`, every write checked and flushed.
  bool Write(const std::string& name, const std::string& bytes, std::string& message);
  /// A staged file written by someone else (a VTK writer): present, not empty, flushed.
  bool Check(const std::string& name, std::string& message);
  /// For a staged file found incomplete (a VTK writer that does not check its writes):
  /// sets `message` to its cause, found by trying to write more to it (the full disk's
  /// ENOSPC, the size limit's EFBIG), or "the writer stopped early"; returns false.
  bool Incomplete(const std::string& name, std::string& message);
  /// Rename the staged files over their targets in this order (put the file that refers to
  /// the others last); false with `message` the reason.
  bool Commit(const std::vector<std::string>& names, std::string& message);

private:
  std::string Directory; // the targets'
  std::string Stage;     // the staging directory, "" before Begin or after Commit
};

/// `image` encoded as PNG in memory (vtkPNGWriter), or false with `message` the reason.
bool EncodePNG(vtkImageData* image, std::string& bytes, std::string& message);

/// The first output of `source` (updated, its errors observed) as the PNG `path`, written
/// as above; false with `message` the reason ("cannot write 'PATH': ...").
bool WritePNG(vtkAlgorithm* source, const std::string& path, std::string& message);
}

#endif
