#include "vtkOFBImageWriter.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <OpenImageIO/imageio.h>

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
/// OpenImageIO's pending error message of `output` (or its global one), or `fallback`.
std::string PendingError(const OIIO::ImageOutput* output, const std::string& fallback)
{
  std::string message = output ? output->geterror() : std::string();
  const std::string global = OIIO::geterror();
  if (message.empty())
  {
    message = global;
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message.empty() ? fallback : message;
}

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
  auto output = OIIO::ImageOutput::create(fileName);
  if (!output)
  {
    OIIO::geterror(); // clear it
  }
  return output != nullptr;
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
  auto output = extension.empty() ? nullptr : OIIO::ImageOutput::create(path);
  if (!output)
  {
    OIIO::geterror();
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
  else if (output->format_name() == std::string("hdr") && nc != 3)
  {
    problem = std::to_string(nc) + " components: Radiance HDR stores RGB only";
  }
  if (!problem.empty())
  {
    this->Fail(problem, vtkErrorCode::FileFormatError);
    return;
  }

  const OIIO::TypeDesc data = type == VTK_UNSIGNED_CHAR
    ? OIIO::TypeDesc::UINT8
    : (type == VTK_UNSIGNED_SHORT ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::FLOAT);
  const std::string format = output->format_name();
  OIIO::TypeDesc file = data;
  if (format == "openexr" && type == VTK_FLOAT)
  {
    file = this->HalfFloat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
  }
  OIIO::ImageSpec spec(w, h, nc, file);
  spec.alpha_channel = nc == 2 || nc == 4 ? nc - 1 : -1;
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (format == "jpeg")
  {
    spec.attribute("Compression", "jpeg:" + std::to_string(this->Quality));
  }
  else if (format == "openexr" || format == "tiff")
  {
    spec.attribute("Compression", "zip");
  }

  // Written under a temporary name with the same extension (the format), then renamed.
  static std::atomic<unsigned> counter(0);
  const std::string staged =
    (directory == "." && path.find('/') == std::string::npos ? std::string() : directory + "/") +
    "." + name + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + extension;
  if (!output->open(staged, spec))
  {
    problem = PendingError(output.get(), "it cannot be created");
    std::remove(staged.c_str());
    this->Fail(problem, vtkErrorCode::CannotOpenFileError);
    return;
  }
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(nc) * scalars->GetDataTypeSize();
  const OIIO::stride_t rowBytes = pixelBytes * w;
  const char* last = static_cast<const char*>(scalars->GetVoidPointer(0)) +
    rowBytes * (static_cast<vtkIdType>(h) - 1);
  auto progress = [](void* self, float done) -> bool
  {
    auto* writer = static_cast<vtkOFBImageWriter*>(self);
    writer->UpdateProgress(done);
    return writer->GetAbortExecute() != 0;
  };
  bool ok =
    output->write_image(data, last, pixelBytes, -rowBytes, OIIO::AutoStride, progress, this);
  problem = ok ? std::string() : PendingError(output.get(), "the write failed");
  const bool closed = output->close();
  if (ok && !closed)
  {
    ok = false;
    problem = PendingError(output.get(), "closing the file failed");
  }
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
