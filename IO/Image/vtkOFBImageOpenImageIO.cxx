// libvtkOFBIOImageOpenImageIO: the calls to OpenImageIO of vtkOFBImageReader and
// vtkOFBImageWriter, in a module loaded at the first image (vtkOFBImageBackend.h).
#include "vtkOFBImageBackend.h"

#include "vtkType.h"

#include <OpenImageIO/imageio.h>

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

size_t SizeOf(int scalarType)
{
  return scalarType == VTK_UNSIGNED_CHAR ? 1 : (scalarType == VTK_UNSIGNED_SHORT ? 2 : 4);
}

/// The reader's configuration: alpha as the file stores it (no premultiplication).
OIIO::ImageSpec ReadConfiguration()
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

/// OpenImageIO's pending error message of `object` (or its global one), trimmed; both
/// cleared.
template<typename T>
std::string PendingError(const T* object)
{
  std::string message = object ? object->geterror() : std::string();
  const std::string global = OIIO::geterror();
  if (message.empty())
  {
    message = global;
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message;
}

bool ReadHeader(const char* path, vtkOFBImageHeader& header, std::string& error)
{
  const OIIO::ImageSpec config = ReadConfiguration();
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    error = PendingError<OIIO::ImageInput>(nullptr);
    return false;
  }
  const OIIO::ImageSpec& spec = input->spec();
  header.Format = input->format_name();
  header.Width = spec.width;
  header.Height = spec.height;
  header.Depth = spec.depth;
  header.Channels = spec.nchannels;
  header.Deep = spec.deep;
  header.BitsPerSample =
    spec.get_int_attribute("oiio:BitsPerSample", static_cast<int>(8 * spec.format.size()));
  int type = ScalarTypeOf(spec.format);
  for (const OIIO::TypeDesc& channelType : spec.channelformats)
  {
    type = Wider(type, ScalarTypeOf(channelType));
  }
  header.ScalarType = type;
  header.TypeName = spec.format.c_str();
  input->close();
  PendingError(input.get());
  return true;
}

bool ReadPixels(const char* path,
  int scalarType,
  int width,
  int height,
  int channels,
  void* data,
  vtkOFBImageProgress progress,
  void* user,
  std::string& error)
{
  const OIIO::ImageSpec config = ReadConfiguration();
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    error = "it cannot be opened again (" + PendingError<OIIO::ImageInput>(nullptr) + ")";
    return false;
  }
  // One thread: a decoder's errors are kept per thread, and those of OpenImageIO's worker
  // threads would not reach this one (a file cut short would read as complete).
  input->threads(1);
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != width || spec.height != height || spec.nchannels != channels)
  {
    error = "it changed on the disk while it was read";
    return false;
  }
  // The file's top row first: start at the last row and go down.
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(channels * SizeOf(scalarType));
  const OIIO::stride_t rowBytes = pixelBytes * width;
  char* last = static_cast<char*>(data) + rowBytes * (static_cast<OIIO::stride_t>(height) - 1);
  const bool read = input->read_image(0,
    0,
    0,
    channels,
    TypeDescOf(scalarType),
    last,
    pixelBytes,
    -rowBytes,
    OIIO::AutoStride,
    progress,
    user);
  // Some decoders (libtiff's missing strips, libjpeg's premature end) return success
  // with a message and grey pixels: any message is a failure.
  error = PendingError(input.get());
  input->close();
  if (read && error.empty())
  {
    return true;
  }
  if (error.empty())
  {
    error = "no reason given";
  }
  return false;
}

std::string WriterFormat(const char* path)
{
  auto output = OIIO::ImageOutput::create(path);
  if (!output)
  {
    PendingError<OIIO::ImageOutput>(nullptr);
    return std::string();
  }
  return output->format_name();
}

bool Write(const char* path,
  int scalarType,
  int width,
  int height,
  int channels,
  const void* data,
  bool half,
  int quality,
  vtkOFBImageProgress progress,
  void* user,
  std::string& error)
{
  auto output = OIIO::ImageOutput::create(path);
  if (!output)
  {
    error = PendingError<OIIO::ImageOutput>(nullptr);
    return false;
  }
  output->threads(1); // as for reading: every error on this thread
  const std::string format = output->format_name();
  const OIIO::TypeDesc memory = TypeDescOf(scalarType);
  OIIO::TypeDesc file = memory;
  if (format == "openexr" && scalarType == VTK_FLOAT)
  {
    file = half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
  }
  OIIO::ImageSpec spec(width, height, channels, file);
  spec.alpha_channel = channels == 2 || channels == 4 ? channels - 1 : -1;
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (format == "jpeg")
  {
    spec.attribute("Compression", "jpeg:" + std::to_string(quality));
  }
  else if (format == "openexr" || format == "tiff")
  {
    spec.attribute("Compression", "zip");
  }
  if (!output->open(path, spec))
  {
    error = PendingError(output.get());
    return false;
  }
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(channels * SizeOf(scalarType));
  const OIIO::stride_t rowBytes = pixelBytes * width;
  const char* last =
    static_cast<const char*>(data) + rowBytes * (static_cast<OIIO::stride_t>(height) - 1);
  bool ok =
    output->write_image(memory, last, pixelBytes, -rowBytes, OIIO::AutoStride, progress, user);
  error = ok ? std::string() : PendingError(output.get());
  if (!output->close() && ok)
  {
    ok = false;
    error = PendingError(output.get());
  }
  if (!ok && error.empty())
  {
    error = "the write failed";
  }
  return ok;
}

const vtkOFBImageBackendAPI Table = { 1, ReadHeader, ReadPixels, WriterFormat, Write };
}

extern "C" __attribute__((visibility("default"))) const vtkOFBImageBackendAPI*
vtkOFBImageBackendGet()
{
  return &Table;
}
