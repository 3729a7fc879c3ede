/**
 * @class   vtkOFBStagedFiles
 * @brief   Files written beside their targets and renamed over them only when complete
 *
 * The writers of several files at once (a textured OBJ with its .mtl and texture, an
 * export, a screenshot) write through this class, so that a failure or a kill never
 * leaves a partial file under a target's name:
 *
 * - Begin() checks that every target can be written (WhyNotWritable), removes the
 *   staging directories of processes of this machine that died (kill -9; those of other
 *   machines sharing the directory are kept) and creates a private staging directory
 *   beside the targets, "<directory>/.<last name>.tmp-<host>-<pid>-<n>/";
 * - the files are written there (Staged() gives a path for a VTK writer; Write() writes
 *   bytes with every write checked and the file flushed to the disk) and checked
 *   (Check(), Incomplete());
 * - Commit() renames them over their targets in the order given (one step a file: a
 *   reader sees the old file or the new one, never a part; a replaced file keeps its
 *   permissions) and flushes the directory.
 *
 * On any failure, or when the object goes out of scope before Commit(), the staging
 * directory and everything in it are removed and the targets are untouched. A failure's
 * message names the target and gives its cause (strerror of the failed call). A
 * directory rather than a temporary name because VTK's OBJ writer names its .mtl after
 * its own file. POSIX only (it is not wrapped).
 *
 * @sa vtkOFBWriter (one file, staged under a temporary name)
 */
#ifndef vtkOFBStagedFiles_h
#define vtkOFBStagedFiles_h

#include "vtkOFBCoreModule.h" // for export macro

#include <string> // for the paths
#include <vector> // for the names

class VTKOFBCORE_EXPORT vtkOFBStagedFiles
{
public:
  /// Files staged beside `target` (a path; its directory is the targets').
  explicit vtkOFBStagedFiles(const std::string& target);
  /// Removes the staging directory unless committed.
  ~vtkOFBStagedFiles();
  vtkOFBStagedFiles(const vtkOFBStagedFiles&) = delete;
  vtkOFBStagedFiles& operator=(const vtkOFBStagedFiles&) = delete;

  /// Why `path` cannot be written ("" when it can): it is a directory, or its directory is
  /// missing, not a directory or not writable.
  static std::string WhyNotWritable(const std::string& path);

  /// Check that each of `names` (file names in the target's directory, the target's among
  /// them) can be written, remove stale staging directories, create this one (named after
  /// the last of `names`); false with `message` the reason.
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

#endif
