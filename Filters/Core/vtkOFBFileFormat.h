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
#include "vtkDataSetAttributes.h" // for the attribute roles
#include "vtkEndian.h"            // for VTK_WORDS_BIGENDIAN
#include "vtkType.h"

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
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

/**
 * What an array must be to play attribute role `role` (a
 * vtkDataSetAttributes::AttributeTypes), or an empty string when an array of VTK type
 * `dataType` with `components` components fits it. The rules are those of the arrays the
 * library gives these roles (RGBA unsigned char colours, float normals and vectors,
 * float texture coordinates) and those that VTK's filters and writers assume when they
 * take an attribute (vtkPLYWriter reads texture coordinates as float, for instance), so
 * that a file cannot hand them an array they would misread. vtkOFBWriter refuses to
 * write, and vtkOFBReader to read, an array that does not fit its role.
 */
inline std::string RoleRequirement(int role, int dataType, int components)
{
  const bool isFloat = dataType == VTK_FLOAT;
  const bool isReal = isFloat || dataType == VTK_DOUBLE;
  const bool isInteger = !isReal && dataType != VTK_BIT;
  switch (role)
  {
    case vtkDataSetAttributes::SCALARS:
      return dataType == VTK_UNSIGNED_CHAR && components >= 1 && components <= 4
        ? std::string()
        : "unsigned char colours of 1 to 4 components";
    case vtkDataSetAttributes::VECTORS:
      return isFloat && components == 3 ? std::string() : "float vectors of 3 components";
    case vtkDataSetAttributes::NORMALS:
      return isFloat && components == 3 ? std::string() : "float normals of 3 components";
    case vtkDataSetAttributes::TCOORDS:
      return isFloat && components >= 1 && components <= 3
        ? std::string()
        : "float texture coordinates of 1 to 3 components";
    case vtkDataSetAttributes::TENSORS:
      return isReal && (components == 6 || components == 9)
        ? std::string()
        : "float or double tensors of 6 or 9 components";
    case vtkDataSetAttributes::GLOBALIDS:
      return dataType == VTK_ID_TYPE && components == 1 ? std::string()
                                                        : "vtkIdType ids of 1 component";
    case vtkDataSetAttributes::PEDIGREEIDS:
      return isInteger && components == 1 ? std::string() : "integer ids of 1 component";
    case vtkDataSetAttributes::EDGEFLAG:
      return isInteger && components == 1 ? std::string() : "integer flags of 1 component";
    case vtkDataSetAttributes::TANGENTS:
      return isReal && components == 3 ? std::string() : "float or double tangents of 3 components";
    case vtkDataSetAttributes::RATIONALWEIGHTS:
      return isReal && components == 1 ? std::string() : "float or double weights of 1 component";
    case vtkDataSetAttributes::HIGHERORDERDEGREES:
      return isInteger && components == 3 ? std::string() : "integer degrees of 3 components";
    default:
      return "a known attribute role";
  }
}

/**
 * What is wrong with a frame (low corner `origin`, cell edge `cellSize`, `dims` cells
 * along x, y and z), or an empty string. Besides what vtkOFB::SetFrame checks (a finite
 * origin, a positive finite cell size, dimensions of at least 1), the box must lie
 * within the range of float: depths are float, and exporters write float coordinates,
 * so a larger box would overflow them. The inverse of the cell size must be finite too:
 * queries find cells by multiplying with it.
 */
inline std::string FrameProblem(const double origin[3], double cellSize, const double dims[3])
{
  if (!(cellSize > 0.0) || !std::isfinite(cellSize) || !std::isfinite(1.0 / cellSize))
  {
    return "an invalid cell size " + std::to_string(cellSize);
  }
  for (int a = 0; a < 3; ++a)
  {
    const double far = origin[a] + cellSize * dims[a];
    if (!std::isfinite(origin[a]) || !(dims[a] >= 1.0) || !(std::fabs(origin[a]) <= FLT_MAX) ||
      !(std::fabs(far) <= FLT_MAX))
    {
      return "a box beyond the range of float along axis " + std::to_string(a) + " (origin " +
        std::to_string(origin[a]) + ", cell size " + std::to_string(cellSize) + ", " +
        std::to_string(dims[a]) + " cells)";
    }
  }
  return std::string();
}

/**
 * Whether the depths of the samples of every cell lie within the box: depth d of a
 * sample of grid `a` is measured from the plane x[a] = origin[a], so 0 <= d <=
 * cellSize * dims[a]. `offsets` has `numberOfCells` + 1 entries, over the cells of the
 * X, then Y, then Z grid; `dims` are the dimensions of the frame.
 */
inline bool DepthsWithinBox(const vtkTypeUInt32* offsets,
  const float* depths,
  double cellSize,
  const vtkIdType dims[3])
{
  vtkIdType first = 0;
  for (int a = 0; a < 3; ++a)
  {
    const vtkIdType cells = dims[(a + 1) % 3] * dims[(a + 2) % 3];
    const double extent = cellSize * static_cast<double>(dims[a]);
    const vtkTypeUInt32 begin = offsets[first];
    const vtkTypeUInt32 end = offsets[first + cells];
    for (vtkTypeUInt32 i = begin; i < end; ++i)
    {
      const double d = depths[i];
      if (!(d >= 0.0 && d <= extent))
      {
        return false;
      }
    }
    first += cells;
  }
  return true;
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
