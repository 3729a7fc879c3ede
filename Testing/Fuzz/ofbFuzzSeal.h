// Resealing of fuzzed .ofb files: recompute the CRC-32 of every section that can be
// found, so that a mutation reaches the reader's checks of the content (frame, offsets,
// depths, array types and roles) instead of stopping at a checksum mismatch.
#ifndef ofbFuzzSeal_h
#define ofbFuzzSeal_h

#include "vtkOFBWriter.h"

#include <cstdint>
#include <vector>

namespace ofbfuzz
{
inline uint64_t GetLE(const std::vector<uint8_t>& b, size_t at, int size)
{
  uint64_t v = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    v = (v << 8) | b[at + i];
  }
  return v;
}

/// Store the CRC-32 of [begin, end) at `end` (little-endian), as vtkOFBWriter does.
inline void Seal(std::vector<uint8_t>& b, size_t begin, size_t end)
{
  const unsigned int crc = vtkOFBWriter::UpdateCRC32(0, b.data() + begin, end - begin);
  for (int i = 0; i < 4; ++i)
  {
    b[end + i] = static_cast<uint8_t>(crc >> (8 * i));
  }
}

/**
 * Recompute the CRCs of `b` in place, following the layout of vtkOFBWriter as far as the
 * bytes allow: the header, the cell offsets and depths (sized by the header's counts),
 * then each sample array (sized by its own header). Sections that do not fit are left
 * as they are.
 */
inline void Reseal(std::vector<uint8_t>& b)
{
  const size_t header = vtkOFBWriter::HeaderSize;
  if (b.size() < header)
  {
    return;
  }
  Seal(b, 0, header - 4);
  const uint64_t cells = GetLE(b, 72, 8);
  const uint64_t samples = GetLE(b, 80, 8);
  const uint64_t arrays = GetLE(b, 88, 4);
  const uint64_t size = b.size();
  // Counts beyond the file cannot be sealed (and are refused before any section).
  if (cells >= size || samples >= size)
  {
    return;
  }
  uint64_t at = header + 4 * (cells + 1);
  if (at + 4 > size)
  {
    return;
  }
  Seal(b, header, static_cast<size_t>(at));
  const uint64_t depths = at + 4;
  at = depths + 4 * samples;
  if (at + 4 > size)
  {
    return;
  }
  Seal(b, static_cast<size_t>(depths), static_cast<size_t>(at));
  at += 4;
  for (uint64_t k = 0; k < arrays && at + 4 <= size; ++k)
  {
    const uint64_t start = at;
    const uint64_t name = GetLE(b, static_cast<size_t>(at), 4);
    const uint64_t fields = at + 4 + name;
    if (name >= size || fields + 24 + 4 > size)
    {
      return;
    }
    Seal(b, static_cast<size_t>(start), static_cast<size_t>(fields + 24));
    const uint64_t elementSize = GetLE(b, static_cast<size_t>(fields + 4), 4);
    const uint64_t components = GetLE(b, static_cast<size_t>(fields + 8), 4);
    const uint64_t tuples = GetLE(b, static_cast<size_t>(fields + 12), 8);
    const uint64_t values = fields + 24 + 4;
    // Each factor below the file size (< 2^32 here): the product cannot wrap.
    if (elementSize >= size || components >= size || tuples >= size ||
      elementSize * components > size || elementSize * components * tuples > size - values)
    {
      return;
    }
    at = values + elementSize * components * tuples;
    if (at + 4 > size)
    {
      return;
    }
    Seal(b, static_cast<size_t>(values), static_cast<size_t>(at));
    at += 4;
  }
}
}

#endif
