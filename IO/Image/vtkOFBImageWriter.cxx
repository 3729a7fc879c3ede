#include "vtkOFBImageWriter.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include "vtkOFBImageBackend.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

vtkStandardNewMacro(vtkOFBImageWriter);

namespace
{
/// The directory of `path` ("." when it has none) and its file name.
void SplitPath(const std::string& path, std::string& directory, std::string& name)
{
  const size_t slash = path.find_last_of('/');
  directory = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  name = slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The extension of `name` with its dot ("" when it has none).
std::string ExtensionOf(const std::string& name)
{
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
}
}

//------------------------------------------------------------------------------
vtkOFBImageWriter::vtkOFBImageWriter() = default;

//------------------------------------------------------------------------------
vtkOFBImageWriter::~vtkOFBImageWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
vtkImageData* vtkOFBImageWriter::GetInput()
{
  return vtkImageData::SafeDownCast(this->GetInputDataObject(0, 0));
}

//------------------------------------------------------------------------------
int vtkOFBImageWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOFBImageWriter::CanWriteExtension(const char* fileName)
{
  if (!fileName || ExtensionOf(fileName).empty())
  {
    return false;
  }
  std::string error;
  const vtkOFBImageBackendAPI* api = vtkOFBLoadImageBackend(error);
  return api && !api->WriterFormat(fileName).empty();
}

//------------------------------------------------------------------------------
void vtkOFBImageWriter::Fail(const std::string& problem, unsigned long code)
{
  this->SetErrorCode(code);
  vtkErrorMacro("Cannot write the image '" << (this->FileName ? this->FileName : "")
                                           << "': " << problem << ".");
}

//------------------------------------------------------------------------------
void vtkOFBImageWriter::WriteData()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    vtkErrorMacro("No FileName: nothing written.");
    return;
  }
  const std::string path = this->FileName;
  std::string directory, name;
  SplitPath(path, directory, name);
  const std::string extension = ExtensionOf(name);
  std::string error;
  const vtkOFBImageBackendAPI* api = vtkOFBLoadImageBackend(error);
  if (!api)
  {
    this->Fail(error, vtkErrorCode::UnknownError);
    return;
  }
  const std::string format = extension.empty() ? std::string() : api->WriterFormat(path.c_str());
  if (format.empty())
  {
    this->Fail(extension.empty()
        ? std::string("no extension to choose the format by (.png, .exr, .tif, ...)")
        : "no image format has the extension '" + extension + "'",
      vtkErrorCode::UnrecognizedFileTypeError);
    return;
  }
  struct stat status;
  if (stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode))
  {
    this->Fail("a directory", vtkErrorCode::CannotOpenFileError);
    return;
  }
  if (stat(directory.c_str(), &status) != 0 || !S_ISDIR(status.st_mode) ||
    access(directory.c_str(), W_OK) != 0)
  {
    this->Fail("its directory '" + directory + "' is missing or not writable",
      vtkErrorCode::CannotOpenFileError);
    return;
  }

  // The input: one slice of uchar, ushort or float scalars with 1 to 4 components.
  vtkImageData* image = this->GetInput();
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (image)
  {
    image->GetExtent(extent);
  }
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  const int w = extent[1] - extent[0] + 1, h = extent[3] - extent[2] + 1;
  const int type = scalars ? scalars->GetDataType() : 0;
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  std::string problem;
  if (!image || !scalars || w < 1 || h < 1)
  {
    problem = "no input image with pixels and scalars";
  }
  else if (extent[5] != extent[4])
  {
    problem =
      "the input has " + std::to_string(extent[5] - extent[4] + 1) + " slices (one is written)";
  }
  else if (scalars->GetNumberOfTuples() != static_cast<vtkIdType>(w) * h)
  {
    problem = "the scalars do not have one tuple a pixel";
  }
  else if (type != VTK_UNSIGNED_CHAR && type != VTK_UNSIGNED_SHORT && type != VTK_FLOAT)
  {
    problem = std::string("scalars of type ") + scalars->GetDataTypeAsString() +
      " (unsigned char, unsigned short or float are written: convert them first)";
  }
  else if (nc < 1 || nc > 4)
  {
    problem =
      std::to_string(nc) + " components (1 to 4 are written: grey, grey and alpha, RGB, RGBA)";
  }
  else if (format == "hdr" && nc != 3)
  {
    problem = std::to_string(nc) + " components: Radiance HDR stores RGB only";
  }
  if (!problem.empty())
  {
    this->Fail(problem, vtkErrorCode::FileFormatError);
    return;
  }

  // Written under a temporary name with the same extension (the format), then renamed.
  static std::atomic<unsigned> counter(0);
  const std::string staged =
    (directory == "." && path.find('/') == std::string::npos ? std::string() : directory + "/") +
    "." + name + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + extension;
  auto progress = [](void* self, float done) -> bool
  {
    auto* writer = static_cast<vtkOFBImageWriter*>(self);
    writer->UpdateProgress(done);
    return writer->GetAbortExecute() != 0;
  };
  bool ok = api->Write(staged.c_str(),
    type,
    w,
    h,
    nc,
    scalars->GetVoidPointer(0),
    this->HalfFloat,
    this->Quality,
    progress,
    this,
    problem);
  if (ok && std::rename(staged.c_str(), path.c_str()) != 0)
  {
    ok = false;
    problem = std::string("renaming it into place: ") + std::strerror(errno);
  }
  if (!ok)
  {
    std::remove(staged.c_str());
    if (!this->GetAbortExecute())
    {
      this->Fail(problem,
        problem.find("space") != std::string::npos ? vtkErrorCode::OutOfDiskSpaceError
                                                   : vtkErrorCode::UnknownError);
    }
    return;
  }
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkOFBImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "HalfFloat: " << (this->HalfFloat ? "On" : "Off") << "\n";
  os << indent << "Quality: " << this->Quality << "\n";
}
