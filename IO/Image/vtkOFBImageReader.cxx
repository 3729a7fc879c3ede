#include "vtkOFBImageReader.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <OpenImageIO/imageio.h>

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <new>

vtkStandardNewMacro(vtkOFBImageReader);

namespace
{
/// The VTK type for OpenImageIO's sample type: VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT,
/// VTK_FLOAT, or 0 for a type that is not read.
int ScalarTypeOf(OIIO::TypeDesc type)
{
  switch (type.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      return VTK_UNSIGNED_CHAR;
    case OIIO::TypeDesc::UINT16:
      return VTK_UNSIGNED_SHORT;
    case OIIO::TypeDesc::HALF:
    case OIIO::TypeDesc::FLOAT:
    case OIIO::TypeDesc::DOUBLE:
      return VTK_FLOAT;
    default:
      return 0;
  }
}

/// The wider of two VTK scalar types of ScalarTypeOf (0 stays 0).
int Wider(int a, int b)
{
  if (a == 0 || b == 0)
  {
    return 0;
  }
  auto rank = [](int t) { return t == VTK_UNSIGNED_CHAR ? 0 : (t == VTK_UNSIGNED_SHORT ? 1 : 2); };
  return rank(a) >= rank(b) ? a : b;
}

OIIO::TypeDesc TypeDescOf(int scalarType)
{
  return scalarType == VTK_UNSIGNED_CHAR
    ? OIIO::TypeDesc::UINT8
    : (scalarType == VTK_UNSIGNED_SHORT ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::FLOAT);
}

/// The reader's configuration: alpha as the file stores it (no premultiplication).
OIIO::ImageSpec ReadConfiguration()
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

/// OpenImageIO's pending error message (it keeps one per thread), or `fallback`.
std::string PendingError(const OIIO::ImageInput* input, const std::string& fallback)
{
  std::string message = input ? input->geterror() : std::string();
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

/// A code for a decoder's message: cut short, or damaged.
unsigned long CodeOf(const std::string& message)
{
  for (const char* word : { "end of file", "premature", "truncated", "short", "EOF", "Read error" })
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
  const OIIO::ImageSpec config = ReadConfiguration();
  auto input = OIIO::ImageInput::open(fileName, &config);
  const bool ok = input != nullptr;
  if (!ok)
  {
    OIIO::geterror(); // clear it
  }
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
  const OIIO::ImageSpec config = ReadConfiguration();
  auto input = OIIO::ImageInput::open(this->FileName, &config);
  if (!input)
  {
    this->Fail("not an image file that OpenImageIO reads, or a damaged one (" +
        PendingError(nullptr, "no format recognizes it") + ")",
      vtkErrorCode::UnrecognizedFileTypeError);
    return 1;
  }
  this->FormatName = input->format_name();
  const OIIO::ImageSpec& spec = input->spec();
  this->FileBitsPerSample = spec.get_int_attribute("oiio:BitsPerSample", 8 * spec.format.size());
  int type = ScalarTypeOf(spec.format);
  for (const OIIO::TypeDesc& channelType : spec.channelformats)
  {
    type = Wider(type, ScalarTypeOf(channelType));
  }
  std::string problem;
  if (spec.deep)
  {
    problem = "a deep image (several samples a pixel), which is not read";
  }
  else if (spec.depth > 1)
  {
    problem = "a volume of " + std::to_string(spec.depth) + " slices, which is not read";
  }
  else if (spec.nchannels < 1 || spec.nchannels > 4)
  {
    problem = std::to_string(spec.nchannels) +
      " channels (1 to 4 are read: grey, grey and alpha, RGB, RGBA)";
  }
  else if (type == 0)
  {
    problem = std::string("samples of type ") + spec.format.c_str() +
      " (unsigned 8- or 16-bit integers, half, float or double are read)";
  }
  else if (spec.width < 1 || spec.height < 1)
  {
    problem = "a size of " + std::to_string(spec.width) + " x " + std::to_string(spec.height);
  }
  if (!problem.empty())
  {
    this->Fail(problem, vtkErrorCode::FileFormatError);
    return 1;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(spec.width) * spec.height;
  if (pixels > this->MaximumNumberOfPixels)
  {
    this->Fail("a size of " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
        ", over the limit of " + std::to_string(this->MaximumNumberOfPixels) +
        " pixels (MaximumNumberOfPixels)",
      vtkErrorCode::OutOfDiskSpaceError);
    return 1;
  }
  this->Width = spec.width;
  this->Height = spec.height;
  this->Components = spec.nchannels;
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
  const OIIO::ImageSpec config = ReadConfiguration();
  auto input = OIIO::ImageInput::open(this->FileName, &config);
  if (!input)
  {
    this->Fail("it cannot be opened again (" + PendingError(nullptr, "changed on the disk?") + ")",
      vtkErrorCode::CannotOpenFileError);
    return 1;
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != this->Width || spec.height != this->Height ||
    spec.nchannels != this->Components)
  {
    this->Fail("it changed on the disk while it was read", vtkErrorCode::FileFormatError);
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
  // The file's top row first: start at the output's last row and go down.
  const OIIO::stride_t pixelBytes =
    static_cast<OIIO::stride_t>(this->Components) * pixels->GetDataTypeSize();
  const OIIO::stride_t rowBytes = pixelBytes * this->Width;
  char* last = static_cast<char*>(pixels->GetVoidPointer(0)) +
    rowBytes * (static_cast<vtkIdType>(this->Height) - 1);
  auto progress = [](void* self, float done) -> bool
  {
    auto* reader = static_cast<vtkOFBImageReader*>(self);
    reader->UpdateProgress(done);
    return reader->GetAbortExecute() != 0; // true stops the read
  };
  const bool read = input->read_image(0,
    0,
    0,
    this->Components,
    TypeDescOf(this->ScalarType),
    last,
    pixelBytes,
    -rowBytes,
    OIIO::AutoStride,
    progress,
    this);
  // Some decoders (libtiff's missing strips, libjpeg's premature end) return success
  // with a message and grey pixels: any message is a failure.
  const std::string problem = PendingError(input.get(), "");
  input->close();
  if (!read || !problem.empty())
  {
    if (this->GetAbortExecute())
    {
      return 1;
    }
    this->Fail(
      "the decoder failed: " + (problem.empty() ? std::string("no reason given") : problem),
      CodeOf(problem));
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
