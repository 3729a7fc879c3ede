#include "vtkOFBImageReader.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "vtkOFBImageBackend.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <new>

vtkStandardNewMacro(vtkOFBImageReader);

namespace
{
/// A code for a decoder's message: cut short, or damaged.
unsigned long CodeOf(const std::string& message)
{
  for (const char* word :
    { "end of file", "premature", "Premature", "truncated", "short", "EOF", "Read error" })
  {
    if (message.find(word) != std::string::npos)
    {
      return vtkErrorCode::PrematureEndOfFileError;
    }
  }
  return vtkErrorCode::FileFormatError;
}
}

//------------------------------------------------------------------------------
vtkOFBImageReader::vtkOFBImageReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOFBImageReader::~vtkOFBImageReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkOFBImageReader::CanReadFile(const char* fileName)
{
  struct stat info;
  if (!fileName || stat(fileName, &info) != 0 || !S_ISREG(info.st_mode))
  {
    return false;
  }
  std::string error;
  const vtkOFBImageBackendAPI* api = vtkOFBLoadImageBackend(error);
  vtkOFBImageHeader header;
  const bool ok = api && api->ReadHeader(fileName, header, error);
  return ok;
}

//------------------------------------------------------------------------------
void vtkOFBImageReader::Fail(const std::string& problem, unsigned long code)
{
  this->SetErrorCode(code);
  vtkErrorMacro(
    "Cannot read the image '" << (this->FileName ? this->FileName : "") << "': " << problem << ".");
}

//------------------------------------------------------------------------------
int vtkOFBImageReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  this->HeaderValid = false;
  this->FormatName.clear();
  this->FileBitsPerSample = 0;
  this->SetErrorCode(vtkErrorCode::NoError);
  const int empty[6] = { 0, -1, 0, -1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
  const double origin[3] = { 0.0, 0.0, 0.0 }, spacing[3] = { 1.0, 1.0, 1.0 };
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  info->Set(vtkDataObject::SPACING(), spacing, 3);

  if (!this->FileName || !*this->FileName)
  {
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    vtkErrorMacro("No FileName: nothing to read.");
    return 1;
  }
  struct stat status;
  if (stat(this->FileName, &status) != 0)
  {
    const int error = errno;
    this->Fail(std::strerror(error),
      error == ENOENT ? vtkErrorCode::FileNotFoundError : vtkErrorCode::CannotOpenFileError);
    return 1;
  }
  if (!S_ISREG(status.st_mode))
  {
    this->Fail(S_ISDIR(status.st_mode) ? "a directory, not an image file" : "not a regular file",
      vtkErrorCode::CannotOpenFileError);
    return 1;
  }
  if (status.st_size == 0)
  {
    this->Fail("an empty file", vtkErrorCode::PrematureEndOfFileError);
    return 1;
  }
  std::string error;
  const vtkOFBImageBackendAPI* api = vtkOFBLoadImageBackend(error);
  if (!api)
  {
    this->Fail(error, vtkErrorCode::UnknownError);
    return 1;
  }
  vtkOFBImageHeader spec;
  if (!api->ReadHeader(this->FileName, spec, error))
  {
    this->Fail("not an image file that OpenImageIO reads, or a damaged one (" +
        (error.empty() ? std::string("no format recognizes it") : error) + ")",
      vtkErrorCode::UnrecognizedFileTypeError);
    return 1;
  }
  this->FormatName = spec.Format;
  this->FileBitsPerSample = spec.BitsPerSample;
  const int type = spec.ScalarType;
  std::string problem;
  if (spec.Deep)
  {
    problem = "a deep image (several samples a pixel), which is not read";
  }
  else if (spec.Depth > 1)
  {
    problem = "a volume of " + std::to_string(spec.Depth) + " slices, which is not read";
  }
  else if (spec.Channels < 1 || spec.Channels > 4)
  {
    problem = std::to_string(spec.Channels) +
      " channels (1 to 4 are read: grey, grey and alpha, RGB, RGBA)";
  }
  else if (type == 0)
  {
    problem = "samples of type " + spec.TypeName +
      " (unsigned 8- or 16-bit integers, half, float or double are read)";
  }
  else if (spec.Width < 1 || spec.Height < 1)
  {
    problem = "a size of " + std::to_string(spec.Width) + " x " + std::to_string(spec.Height);
  }
  if (!problem.empty())
  {
    this->Fail(problem, vtkErrorCode::FileFormatError);
    return 1;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(spec.Width) * spec.Height;
  if (pixels > this->MaximumNumberOfPixels)
  {
    this->Fail("a size of " + std::to_string(spec.Width) + " x " + std::to_string(spec.Height) +
        ", over the limit of " + std::to_string(this->MaximumNumberOfPixels) +
        " pixels (MaximumNumberOfPixels)",
      vtkErrorCode::OutOfDiskSpaceError);
    return 1;
  }
  this->Width = spec.Width;
  this->Height = spec.Height;
  this->Components = spec.Channels;
  this->ScalarType = type;
  this->HeaderValid = true;
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, this->ScalarType, this->Components);
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBImageReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (!this->HeaderValid)
  {
    return 1; // RequestInformation said why
  }
  std::string error;
  const vtkOFBImageBackendAPI* api = vtkOFBLoadImageBackend(error);
  if (!api)
  {
    this->Fail(error, vtkErrorCode::UnknownError);
    return 1;
  }
  vtkSmartPointer<vtkDataArray> pixels;
  try
  {
    pixels = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(this->ScalarType));
    pixels->SetName("Pixels");
    pixels->SetNumberOfComponents(this->Components);
    pixels->SetNumberOfTuples(static_cast<vtkIdType>(this->Width) * this->Height);
  }
  catch (const std::bad_alloc&)
  {
    this->Fail("not enough memory for its " + std::to_string(this->Width) + " x " +
        std::to_string(this->Height) + " pixels",
      vtkErrorCode::OutOfDiskSpaceError);
    return 1;
  }
  auto progress = [](void* self, float done) -> bool
  {
    auto* reader = static_cast<vtkOFBImageReader*>(self);
    reader->UpdateProgress(done);
    return reader->GetAbortExecute() != 0; // true stops the read
  };
  if (!api->ReadPixels(this->FileName,
        this->ScalarType,
        this->Width,
        this->Height,
        this->Components,
        pixels->GetVoidPointer(0),
        progress,
        this,
        error))
  {
    if (!this->GetAbortExecute())
    {
      this->Fail("the decoder failed: " + error, CodeOf(error));
    }
    return 1;
  }
  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->GetPointData()->SetScalars(pixels);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "MaximumNumberOfPixels: " << this->MaximumNumberOfPixels << "\n";
  os << indent << "FormatName: " << (this->FormatName.empty() ? "(none)" : this->FormatName)
     << "\n";
  os << indent << "FileBitsPerSample: " << this->FileBitsPerSample << "\n";
  os << indent << "ErrorCode: " << vtkErrorCode::GetStringFromErrorCode(this->GetErrorCode())
     << "\n";
}
