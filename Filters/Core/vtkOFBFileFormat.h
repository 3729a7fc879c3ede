/**
 * @file    vtkOFBFileFormat.h
 * @brief   Byte-level helpers of the .ofb format, shared by vtkOFBWriter and vtkOFBReader (private)
 *
 * Every number of an .ofb file is little-endian (see vtkOFBWriter). Header fields
 * are encoded and decoded byte by byte; runs of values are converted in place with
 * vtkByteSwap, which does nothing on little-endian hosts. The CRC-32 is zlib's.
 */

#ifndef vtkOFBFileFormat_h
#define vtkOFBFileFormat_h

#include "vtkByteSwap.h"
#include "vtkEndian.h" // for VTK_WORDS_BIGENDIAN
#include "vtkType.h"

#include <cstddef>
#include <cstring>
#include <vector>

namespace vtkofb
{
namespace format
{
/// Append `value` to `out` as `size` little-endian bytes.
inline void PutLE(std::vector<unsigned char>& out, vtkTypeUInt64 value, int size)
{
  for (int i = 0; i < size; ++i)
  {
    out.push_back(static_cast<unsigned char>((value >> (8 * i)) & 0xFFu));
  }
}

/// Append the bits of `value` as 8 little-endian bytes.
inline void PutDouble(std::vector<unsigned char>& out, double value)
{
  vtkTypeUInt64 bits;
  std::memcpy(&bits, &value, sizeof(bits));
  PutLE(out, bits, 8);
}

/// Decode `size` little-endian bytes.
inline vtkTypeUInt64 GetLE(const unsigned char* p, int size)
{
  vtkTypeUInt64 value = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    value = (value << 8) | p[i];
  }
  return value;
}

/// Decode a double from 8 little-endian bytes.
inline double GetDouble(const unsigned char* p)
{
  const vtkTypeUInt64 bits = GetLE(p, 8);
  double value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

/**
 * Convert `count` values of `size` bytes (1, 2, 4 or 8) between little-endian and
 * the host's byte order, in place; nothing to do on a little-endian host.
 */
inline void SwapLittleEndian(void* data, size_t count, int size)
{
  switch (size)
  {
    case 2:
      vtkByteSwap::SwapLERange(static_cast<vtkTypeUInt16*>(data), count);
      break;
    case 4:
      vtkByteSwap::SwapLERange(static_cast<vtkTypeUInt32*>(data), count);
      break;
    case 8:
      vtkByteSwap::SwapLERange(static_cast<vtkTypeUInt64*>(data), count);
      break;
    default:
      break;
  }
}

/// Whether the host stores numbers little-endian (no conversion needed).
constexpr bool HostIsLittleEndian()
{
#ifdef VTK_WORDS_BIGENDIAN
  return false;
#else
  return true;
#endif
}
}
}

#endif
