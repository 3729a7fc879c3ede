/**
 * @class   vtkOFBWriter
 * @brief   Write a vtkOFB to a versioned, checksummed binary file (.ofb)
 *
 * vtkOFBWriter stores everything a vtkOFB needs to be rebuilt exactly: the frame,
 * the cell offsets, the depths and every sample array, bit for bit, with its
 * attribute roles (active scalars, normals, vectors, texture coordinates, ...).
 * The cell index is not stored: vtkOFBReader rebuilds it from the offsets.
 *
 * File layout (version 1). Every number is little-endian whatever the host, and
 * every section ends with the CRC-32 (IEEE 802.3 polynomial, as in zlib and PNG)
 * of its bytes, so that any single flipped bit is detected:
 *
 * | bytes | content |
 * |-------|---------|
 * | 8     | magic `89 4F 46 42 0D 0A 1A 0A` ("\x89OFB\r\n\x1a\n") |
 * | 4     | uint32 format version (1) |
 * | 4     | uint32 byte-order marker 0x01020304 (on disk `04 03 02 01`) |
 * | 24    | float64 origin[3] |
 * | 8     | float64 cell size (0 for an empty OFB) |
 * | 24    | int64 dimensions[3] (0 0 0 for an empty OFB) |
 * | 8     | uint64 number of cells over the three grids |
 * | 8     | uint64 number of samples n |
 * | 4     | uint32 number of sample arrays |
 * | 4     | uint32 CRC-32 of the 92 bytes above (header: 96 bytes in all) |
 * | 4 (cells + 1) + 4 | uint32 cell offsets, then their CRC-32 |
 * | 4 n + 4 | float32 depths, then their CRC-32 |
 *
 * then for every sample array, in the order of the vtkPointData:
 *
 * | bytes | content |
 * |-------|---------|
 * | 4 + L | uint32 name length L, then the name (UTF-8, no terminator; L = 0: unnamed) |
 * | 4     | uint32 VTK data type (VTK_FLOAT, VTK_INT, ...) |
 * | 4     | uint32 element size in bytes |
 * | 4     | uint32 number of components c |
 * | 8     | uint64 number of tuples (always n) |
 * | 4     | uint32 attribute roles (bit mask, see below) |
 * | 4     | uint32 CRC-32 of the array header above |
 * | n c size + 4 | the values, tuple after tuple, then their CRC-32 |
 *
 * Bit k of the attribute roles is set when the array is the active attribute k
 * of vtkDataSetAttributes: 1 scalars, 2 vectors, 4 normals, 8 texture
 * coordinates, 16 tensors, ..., 256 tangents (bits 0 to 10); 0 means none.
 *
 * and finally the 8-byte trailer `4F 46 42 45 4E 44 1A 0A` ("OFBEND\x1a\n"), which
 * must end the file.
 *
 * Guarantees: the target file is replaced atomically. The writer writes a new
 * file in the same directory, flushes it to the disk, checks that every write
 * succeeded, and only then renames it over FileName and flushes the directory, so
 * that the replacement survives a power cut. Where the system allows it (Linux's
 * O_TMPFILE), the new file has no name until it is complete, so a writer killed
 * mid-write leaves nothing behind; elsewhere it is FileName + ".tmp-<host>-<pid>-<n>",
 * and the next write of FileName removes such temporaries of processes of the same
 * machine that no longer exist (a temporary of another machine sharing the folder is
 * kept). The replacement keeps the permissions (and, where allowed, the owner) of
 * the file it replaces; a FileName that is a symbolic link is followed, so the file
 * it points to is replaced and the link kept. On any failure the writer removes its
 * temporary file, leaves an existing FileName untouched, reports an error and sets
 * the error code (Write() then returns 0). An empty OFB can be written and reads
 * back empty. What vtkOFBReader would refuse is refused before the file is touched:
 * an inconsistent OFB (offsets that do not match the frame or the samples, depths
 * outside the box, arrays whose tuple count is not the sample count), a frame beyond
 * the range of float, non-numeric sample arrays (strings, variants, bits) and arrays
 * that do not fit their attribute role (see vtkOFBReader). So is a FileName that is
 * not a regular file, directly or through symbolic links (a directory, a FIFO, a
 * device, a socket): renaming over it would replace it (as root, /dev/null itself);
 * it is left as it is and nothing is written. Not stored:
 * component names, array information keys, lookup tables, field data.
 *
 * @sa vtkOFBReader vtkOFB
 */

#ifndef vtkOFBWriter_h
#define vtkOFBWriter_h

#include "vtkOFBCoreModule.h" // for export macro
#include "vtkWriter.h"

#include <cstddef> // for size_t
#include <string>  // for ReportWriteError

class vtkOFB;

class VTKOFBCORE_EXPORT vtkOFBWriter : public vtkWriter
{
public:
  static vtkOFBWriter* New();
  vtkTypeMacro(vtkOFBWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Name of the file to write (required). An existing file is replaced atomically.
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * The input OFB.
   */
  vtkOFB* GetInput();
  vtkOFB* GetInput(int port);
  ///@}

  /**
   * Version of the file format this writer produces (and the newest that
   * vtkOFBReader accepts).
   */
  static int GetFormatVersion() { return 1; }

#ifndef __VTK_WRAP__
  ///@{
  /**
   * Constants of the format, shared with vtkOFBReader (see the class documentation).
   */
  static constexpr char Magic[9] = "\x89OFB\r\n\x1a\n";
  static constexpr char Trailer[9] = "OFBEND\x1a\n";
  static constexpr unsigned int ByteOrderMark = 0x01020304u;
  static constexpr int HeaderSize = 96;
  static constexpr int NumberOfRoleBits = 11;
  ///@}

  /**
   * Continue the CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320; zlib's
   * crc32) `crc` over `size` bytes. Start with 0: UpdateCRC32(0, "123456789", 9) is
   * 0xCBF43926.
   */
  static unsigned int UpdateCRC32(unsigned int crc, const void* data, size_t size);
#endif

protected:
  vtkOFBWriter();
  ~vtkOFBWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * Report that writing FileName failed because of `problem`, with error `code`.
   */
  void ReportWriteError(const std::string& problem, unsigned long code);

  char* FileName;

private:
  vtkOFBWriter(const vtkOFBWriter&) = delete;
  void operator=(const vtkOFBWriter&) = delete;
};

#endif
