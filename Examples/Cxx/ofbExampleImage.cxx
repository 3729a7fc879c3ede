#include "ofbExampleImage.h"
#include "ofbExampleErrors.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOFBImageReader.h"
#include "vtkPointData.h"
#include "vtk_zlib.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace
{
enum class Format
{
  PNG,
  JPEG,
  BMP,
  PNM,
  TIFF,
  EXR,
  HDR
};

/// What a header claims.
struct Header
{
  long long Width = 0;
  long long Height = 0;
};

uint32_t BigEndian32(const unsigned char* p)
{
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | p[3];
}
uint32_t LittleEndian32(const unsigned char* p)
{
  return (uint32_t(p[3]) << 24) | (uint32_t(p[2]) << 16) | (uint32_t(p[1]) << 8) | p[0];
}
unsigned LittleEndian16(const unsigned char* p)
{
  return unsigned(p[0]) | (unsigned(p[1]) << 8);
}

/// The whole file at `path`, a regular file of at most MaximumImageFileBytes.
bool ReadWholeFile(const std::string& path, std::vector<unsigned char>& bytes, std::string& problem)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
  {
    problem = std::strerror(errno);
    return false;
  }
  if (!S_ISREG(info.st_mode))
  {
    problem = S_ISDIR(info.st_mode) ? "a directory, not an image file" : "not a regular file";
    return false;
  }
  if (info.st_size > ofbexample::MaximumImageFileBytes)
  {
    problem = "larger than the limit of " + std::to_string(ofbexample::MaximumImageFileBytes) +
      " bytes for an image file";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  bytes.resize(static_cast<size_t>(info.st_size));
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), info.st_size))
  {
    problem = "cannot read the file";
    return false;
  }
  return true;
}

/// The format from the file's first bytes.
bool Sniff(const std::vector<unsigned char>& b, Format& format, std::string& problem)
{
  const size_t n = b.size();
  if (n >= 8 && std::memcmp(b.data(), "\x89PNG\r\n\x1a\n", 8) == 0)
  {
    format = Format::PNG;
  }
  else if (n >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF)
  {
    format = Format::JPEG;
  }
  else if (n >= 2 && b[0] == 'B' && b[1] == 'M')
  {
    format = Format::BMP;
  }
  else if (n >= 2 && b[0] == 'P' && (b[1] == '5' || b[1] == '6'))
  {
    format = Format::PNM;
  }
  else if (n >= 4 &&
    (std::memcmp(b.data(), "II*\0", 4) == 0 || std::memcmp(b.data(), "MM\0*", 4) == 0))
  {
    format = Format::TIFF;
  }
  else if (n >= 4 && std::memcmp(b.data(), "\x76\x2f\x31\x01", 4) == 0)
  {
    format = Format::EXR;
  }
  else if ((n >= 10 && std::memcmp(b.data(), "#?RADIANCE", 10) == 0) ||
    (n >= 6 && std::memcmp(b.data(), "#?RGBE", 6) == 0))
  {
    format = Format::HDR;
  }
  else
  {
    problem = n == 0 ? "an empty file"
                     : "not an image this program reads (PNG, JPEG, uncompressed BMP, binary "
                       "PGM or PPM, TIFF, OpenEXR, Radiance HDR)";
    return false;
  }
  return true;
}

/// PNG's bytes per row of `width` pixels and the rows of each pass (one pass, or Adam7's
/// seven), each row one filter byte and its pixels.
std::vector<std::pair<long long, long long>> PNGRows(long long width,
  long long height,
  int bitsPerPixel,
  bool interlaced)
{
  auto rowBytes = [bitsPerPixel](long long w)
  { return w == 0 ? 0 : 1 + (w * bitsPerPixel + 7) / 8; };
  std::vector<std::pair<long long, long long>> rows;
  if (!interlaced)
  {
    rows.emplace_back(rowBytes(width), height);
    return rows;
  }
  const int x0[7] = { 0, 4, 0, 2, 0, 1, 0 }, dx[7] = { 8, 8, 4, 4, 2, 2, 1 };
  const int y0[7] = { 0, 0, 4, 0, 2, 0, 1 }, dy[7] = { 8, 8, 8, 4, 4, 2, 2 };
  for (int p = 0; p < 7; ++p)
  {
    const long long w = width > x0[p] ? (width - x0[p] + dx[p] - 1) / dx[p] : 0;
    const long long h = height > y0[p] ? (height - y0[p] + dy[p] - 1) / dy[p] : 0;
    if (w > 0 && h > 0)
    {
      rows.emplace_back(rowBytes(w), h);
    }
  }
  return rows;
}

/// The bits a pixel takes for a valid IHDR bit depth and colour type; 0 when invalid.
int PNGBitsPerPixel(int depth, int colorType)
{
  const bool anyDepth = depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
  switch (colorType)
  {
    case 0:
      return anyDepth ? depth : 0; // grey
    case 2:
      return depth == 8 || depth == 16 ? 3 * depth : 0; // RGB
    case 3:
      return anyDepth && depth != 16 ? depth : 0; // palette
    case 4:
      return depth == 8 || depth == 16 ? 2 * depth : 0; // grey and alpha
    case 6:
      return depth == 8 || depth == 16 ? 4 * depth : 0; // RGBA
    default:
      return 0;
  }
}

/// The IDAT stream inflates to exactly the rows of `rows`, each with a filter byte <= 4.
bool InflatePNG(const std::vector<std::pair<const unsigned char*, uint32_t>>& idat,
  const std::vector<std::pair<long long, long long>>& rows,
  std::string& problem)
{
  z_stream z;
  std::memset(&z, 0, sizeof(z));
  if (inflateInit(&z) != Z_OK)
  {
    problem = "zlib cannot start";
    return false;
  }
  std::vector<unsigned char> buffer(1 << 16);
  size_t pass = 0;
  long long row = 0, inRow = 0; // position in the expected rows
  int status = Z_OK;
  for (size_t c = 0; c < idat.size() && status == Z_OK; ++c)
  {
    z.next_in = const_cast<unsigned char*>(idat[c].first);
    z.avail_in = idat[c].second;
    while (status == Z_OK && (z.avail_in > 0 || z.avail_out == 0))
    {
      z.next_out = buffer.data();
      z.avail_out = static_cast<uInt>(buffer.size());
      status = inflate(&z, Z_NO_FLUSH);
      if (status == Z_BUF_ERROR && z.avail_in == 0)
      {
        status = Z_OK; // more input in the next chunk
        break;
      }
      const size_t produced = buffer.size() - z.avail_out;
      for (size_t i = 0; i < produced && (status == Z_OK || status == Z_STREAM_END);)
      {
        if (pass == rows.size())
        {
          status = Z_NEED_DICT; // more data than the image has
          problem = "more image data than the image's size";
          break;
        }
        if (inRow == 0 && buffer[i] > 4)
        {
          status = Z_NEED_DICT;
          problem = "a bad row filter in the image data";
          break;
        }
        const long long step = std::min<long long>(produced - i, rows[pass].first - inRow);
        i += static_cast<size_t>(step);
        inRow += step;
        if (inRow == rows[pass].first) // the next row, or the next pass's first
        {
          inRow = 0;
          if (++row == rows[pass].second)
          {
            row = 0;
            ++pass;
          }
        }
      }
    }
  }
  const std::string zlibMessage = z.msg ? z.msg : "";
  inflateEnd(&z);
  if (status == Z_STREAM_END && pass == rows.size())
  {
    return true;
  }
  if (problem.empty())
  {
    problem = status == Z_DATA_ERROR || status == Z_STREAM_ERROR || status == Z_MEM_ERROR
      ? "corrupt compressed image data (zlib: " + zlibMessage + ")"
      : (status == Z_STREAM_END ? "the image data ends before the image does"
                                : "the compressed image data is cut short");
  }
  return false;
}

/// Both sides in [1, MaximumImageSide] and at most `maxPixels` pixels.
bool CheckSize(const Header& header, long long maxPixels, std::string& problem)
{
  const long long side = ofbexample::MaximumImageSide;
  if (header.Width < 1 || header.Height < 1)
  {
    problem = "a claimed size of " + std::to_string(header.Width) + " x " +
      std::to_string(header.Height) + " (a side of 0)";
    return false;
  }
  if (header.Width > side || header.Height > side || header.Width * header.Height > maxPixels)
  {
    problem = "a claimed size of " + std::to_string(header.Width) + " x " +
      std::to_string(header.Height) + ", over the limit of " + std::to_string(side) +
      " a side and " + std::to_string(maxPixels) + " pixels";
    return false;
  }
  return true;
}

/// PNG: signature, chunks and their CRCs, IHDR, PLTE, IEND, then the image data.
bool CheckPNG(const std::vector<unsigned char>& b,
  long long maxPixels,
  Header& header,
  std::string& problem)
{
  size_t at = 8;
  int bitsPerPixel = 0, colorType = -1;
  bool interlaced = false, palette = false, ended = false, idatDone = false;
  std::vector<std::pair<const unsigned char*, uint32_t>> idat;
  long long idatBytes = 0;
  for (int chunk = 0; !ended; ++chunk)
  {
    if (b.size() - at < 12)
    {
      problem = chunk == 0 ? "the PNG header is cut short" : "the file is cut short (no IEND)";
      return false;
    }
    const uint32_t length = BigEndian32(&b[at]);
    const unsigned char* type = &b[at + 4];
    if (length > 0x7FFFFFFFu || b.size() - at - 12 < length)
    {
      problem = chunk == 0 ? "the PNG header is cut short" : "the file is cut short";
      return false;
    }
    const unsigned char* data = type + 4;
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type, static_cast<uInt>(length + 4));
    if (crc != BigEndian32(data + length))
    {
      problem = "a bad CRC in chunk '" + std::string(reinterpret_cast<const char*>(type), 4) + "'";
      return false;
    }
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if ((chunk == 0) != (name == "IHDR"))
    {
      problem = "IHDR is not the first chunk";
      return false;
    }
    if (name == "IHDR")
    {
      if (length != 13)
      {
        problem = "a bad IHDR chunk";
        return false;
      }
      header.Width = BigEndian32(data);
      header.Height = BigEndian32(data + 4);
      colorType = data[9];
      bitsPerPixel = PNGBitsPerPixel(data[8], colorType);
      interlaced = data[12] == 1;
      if (bitsPerPixel == 0 || data[10] != 0 || data[11] != 0 || data[12] > 1)
      {
        problem = "an invalid bit depth, colour type, compression, filter or interlace method";
        return false;
      }
      if (!CheckSize(header, maxPixels, problem))
      {
        return false;
      }
    }
    else if (name == "PLTE")
    {
      palette = length > 0 && length % 3 == 0 && length <= 3 * 256;
    }
    else if (name == "IDAT")
    {
      if (idatDone)
      {
        problem = "image data chunks that are not consecutive";
        return false;
      }
      idat.emplace_back(data, length);
      idatBytes += length;
    }
    else if (name == "IEND")
    {
      ended = true;
    }
    else if (!(type[0] & 0x20))
    {
      problem = "an unknown critical chunk '" + name + "'";
      return false;
    }
    idatDone = !idat.empty() && name != "IDAT";
    at += 12 + length;
  }
  if (colorType == 3 && !palette)
  {
    problem = "a palette image without a valid palette";
    return false;
  }
  if (idat.empty())
  {
    problem = "no image data";
    return false;
  }
  const auto rows = PNGRows(header.Width, header.Height, bitsPerPixel, interlaced);
  long long raw = 0;
  for (const auto& r : rows)
  {
    raw += r.first * r.second;
  }
  // Deflate shrinks data by at most about 1032 to 1: fewer bytes cannot hold the image.
  if (idatBytes * 1032 + 1024 < raw)
  {
    problem = "too little image data for its claimed size of " + std::to_string(header.Width) +
      " x " + std::to_string(header.Height);
    return false;
  }
  return InflatePNG(idat, rows, problem);
}

/// JPEG: the frame header (SOF) before the first scan, and an end-of-image marker near the
/// end of the file.
bool CheckJPEG(const std::vector<unsigned char>& b, Header& header, std::string& problem)
{
  size_t at = 2;
  while (true)
  {
    while (at < b.size() && b[at] == 0xFF)
    {
      ++at;
    }
    if (at + 3 > b.size() || b[at - 1] != 0xFF)
    {
      problem = "the JPEG header is cut short or damaged";
      return false;
    }
    const unsigned char marker = b[at++];
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8))
    {
      continue; // markers without a segment
    }
    const size_t length = (size_t(b[at]) << 8) | b[at + 1];
    if (length < 2 || at + length > b.size() || marker == 0xDA || marker == 0xD9)
    {
      problem = marker == 0xDA || marker == 0xD9 ? "no JPEG frame header before the image data"
                                                 : "the JPEG header is cut short";
      return false;
    }
    const bool frame =
      marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame)
    {
      if (length < 8)
      {
        problem = "a bad JPEG frame header";
        return false;
      }
      header.Height = (static_cast<long long>(b[at + 3]) << 8) | b[at + 4];
      header.Width = (static_cast<long long>(b[at + 5]) << 8) | b[at + 6];
      break;
    }
    at += length;
  }
  // The end-of-image marker, possibly followed by some padding.
  const size_t tail = std::min<size_t>(b.size(), 4096);
  for (size_t i = b.size() - tail; i + 1 < b.size(); ++i)
  {
    if (b[i] == 0xFF && b[i + 1] == 0xD9)
    {
      return true;
    }
  }
  problem = "the JPEG file is cut short (no end-of-image marker)";
  return false;
}

/// BMP: an uncompressed bottom-up bitmap of 8 or 24 bits with the header vtkBMPReader reads
/// (12 or 40 bytes), whose palette and rows fit in the file.
bool CheckBMP(const std::vector<unsigned char>& b, Header& header, std::string& problem)
{
  if (b.size() < 26)
  {
    problem = "the BMP header is cut short";
    return false;
  }
  const uint32_t offset = LittleEndian32(&b[10]), dib = LittleEndian32(&b[14]);
  long long width = 0, height = 0;
  unsigned bits = 0;
  uint32_t compression = 0;
  if (dib == 12)
  {
    width = LittleEndian16(&b[18]);
    height = LittleEndian16(&b[20]);
    bits = LittleEndian16(&b[24]);
  }
  else if (dib == 40 && b.size() >= 54)
  {
    width = static_cast<int32_t>(LittleEndian32(&b[18]));
    height = static_cast<int32_t>(LittleEndian32(&b[22]));
    bits = LittleEndian16(&b[28]);
    compression = LittleEndian32(&b[30]);
  }
  else
  {
    problem = "an unknown or cut short BMP header";
    return false;
  }
  if ((bits != 8 && bits != 24) || compression != 0)
  {
    problem = "a BMP that is not an uncompressed 8- or 24-bit bitmap";
    return false;
  }
  if (height < 0)
  {
    problem = "a top-down BMP (negative height), which is not read";
    return false;
  }
  // vtkBMPReader reads a 256-entry palette after the header of an 8-bit bitmap, then the
  // pixels from the offset: both must lie in the file, the pixels after the palette.
  const long long palette = bits == 8 ? 256LL * (dib == 12 ? 3 : 4) : 0;
  if (offset < 14 + dib + palette || 14 + dib + palette > static_cast<long long>(b.size()))
  {
    problem = "a BMP whose pixel data offset (" + std::to_string(offset) +
      ") does not follow its header and palette";
    return false;
  }
  header.Width = width;
  header.Height = height;
  const long long rowBytes = (width * bits + 31) / 32 * 4;
  if (width > 0 && height > 0 &&
    (offset > b.size() || (static_cast<long long>(b.size()) - offset) / rowBytes < height))
  {
    problem = "the file is too short for its claimed size of " + std::to_string(width) + " x " +
      std::to_string(height);
    return false;
  }
  return true;
}

/// The next number of a PNM header (after whitespace and comments); -1 if none.
long long PNMNumber(const std::vector<unsigned char>& b, size_t& at)
{
  while (at < b.size() && (std::isspace(b[at]) || b[at] == '#'))
  {
    if (b[at] == '#')
    {
      while (at < b.size() && b[at] != '\n')
      {
        ++at;
      }
    }
    else
    {
      ++at;
    }
  }
  long long value = 0;
  int digits = 0;
  for (; at < b.size() && std::isdigit(b[at]) && digits < 12; ++at, ++digits)
  {
    value = 10 * value + (b[at] - '0');
  }
  return digits > 0 && digits < 12 ? value : -1;
}

/// PNM: binary P5 or P6, maximum value 1-255, its pixels within the file.
bool CheckPNM(const std::vector<unsigned char>& b, Header& header, std::string& problem)
{
  size_t at = 2;
  header.Width = PNMNumber(b, at);
  header.Height = PNMNumber(b, at);
  const long long maximum = PNMNumber(b, at);
  if (header.Width < 0 || header.Height < 0 || maximum < 0 || at >= b.size() ||
    !std::isspace(b[at]))
  {
    problem = "the PNM header is cut short or damaged";
    return false;
  }
  if (maximum < 1 || maximum > 255)
  {
    problem = "a PNM maximum value of " + std::to_string(maximum) + " (1-255 are read)";
    return false;
  }
  const long long channels = b[1] == '6' ? 3 : 1;
  const long long body = static_cast<long long>(b.size() - at - 1);
  if (header.Width > 0 && header.Height > 0 && body / channels / header.Width < header.Height)
  {
    problem = "the file is too short for its claimed size of " + std::to_string(header.Width) +
      " x " + std::to_string(header.Height);
    return false;
  }
  return true;
}

/// The format's own checks, then the size limits.
bool CheckHeader(const std::vector<unsigned char>& bytes,
  Format format,
  long long maxPixels,
  Header& header,
  std::string& problem)
{
  switch (format)
  {
    case Format::PNG:
      return CheckPNG(bytes, maxPixels, header, problem);
    case Format::JPEG:
      return CheckJPEG(bytes, header, problem) && CheckSize(header, maxPixels, problem);
    case Format::BMP:
      return CheckBMP(bytes, header, problem) && CheckSize(header, maxPixels, problem);
    case Format::PNM:
      return CheckPNM(bytes, header, problem) && CheckSize(header, maxPixels, problem);
    default:
      return true; // TIFF, OpenEXR, HDR: the reader checks the size from the header
  }
}
}

namespace ofbexample
{
vtkSmartPointer<vtkImageData> ReadImageChecked(const std::string& path,
  long long maxPixels,
  std::string& message)
{
  std::vector<unsigned char> bytes;
  Format format = Format::PNG;
  Header header;
  std::string problem;
  if (!ReadWholeFile(path, bytes, problem) || !Sniff(bytes, format, problem) ||
    !CheckHeader(bytes, format, maxPixels, header, problem))
  {
    message = "cannot read '" + path + "': " + problem;
    return nullptr;
  }
  bytes.clear();
  bytes.shrink_to_fit();
  const bool checked = format == Format::PNG || format == Format::JPEG || format == Format::BMP ||
    format == Format::PNM;
  vtkNew<vtkOFBImageReader> reader;
  vtkNew<FirstError> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->SetMaximumNumberOfPixels(maxPixels);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  const int* dims = image->GetDimensions();
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (errors->Count > 0 || reader->GetErrorCode() != vtkErrorCode::NoError || !scalars ||
    dims[0] < 1 || dims[1] < 1 || dims[0] > MaximumImageSide || dims[1] > MaximumImageSide ||
    dims[2] != 1 || (checked && (dims[0] != header.Width || dims[1] != header.Height)) ||
    scalars->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    // The reader's message without its "Cannot read the image 'PATH': " and final dot.
    std::string cause = errors->Text;
    const std::string::size_type named = cause.find("': ");
    cause = named == std::string::npos ? cause : cause.substr(named + 3);
    if (!cause.empty() && cause.back() == '.')
    {
      cause.pop_back();
    }
    message = "cannot read '" + path + "': " +
      (cause.empty() ? std::string("the decoder gave no image of the claimed size")
                     : "the decoder failed: " + cause);
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> result = vtkSmartPointer<vtkImageData>::New();
  result->ShallowCopy(image);
  return result;
}
}
