/**
 * @file   ofbExampleFiles.h
 * @brief  How the example applications write files: checked, and replacing the old ones
 *         only when complete
 *
 * Every file an application writes (screenshots, exported meshes, their .mtl and texture)
 * goes through vtkOFBStagedFiles (OFB::Core): first written into a private staging
 * directory beside its target, "<directory>/.<target name>.tmp-<host>-<pid>-<n>/", every write
 * checked and the file flushed to the disk, then renamed over its target (one step per
 * file: a reader sees the old file or the new one, never a part). On any failure the
 * staging directory and everything in it are removed and the targets are untouched; a
 * failure's message gives its cause (strerror of the failed call). Staging directories of
 * processes that died (kill -9) are removed by the next write into the same directory.
 */
#ifndef ofbExampleFiles_h
#define ofbExampleFiles_h

#include <string>

class vtkAlgorithm;
class vtkImageData;
class vtkRenderWindow;

namespace ofbexample
{
/// `image` encoded as PNG in memory (vtkPNGWriter), or false with `message` the reason.
bool EncodePNG(vtkImageData* image, std::string& bytes, std::string& message);

/// The first output of `source` (updated, its errors observed) as the PNG `path`, written
/// as above; false with `message` the reason ("cannot write 'PATH': ...").
bool WritePNG(vtkAlgorithm* source, const std::string& path, std::string& message);

/// What `window` shows (RGB; vtkWindowToImageFilter renders it again and reads its back
/// buffer, or with `frontBuffer` its front buffer) as the PNG `path`, written by WritePNG.
bool WriteWindowPNG(vtkRenderWindow* window,
  const std::string& path,
  std::string& message,
  bool frontBuffer = false);
}

#endif
