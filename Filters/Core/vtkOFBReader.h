/**
 * @class   vtkOFBReader
 * @brief   Read a vtkOFB from a file written by vtkOFBWriter (.ofb)
 *
 * vtkOFBReader reads the versioned, checksummed binary format described in
 * vtkOFBWriter and rebuilds the OFB exactly: frame, cell offsets, depths, every
 * sample array bit for bit with its attribute roles, and the cell index (not
 * stored; rebuilt with vtkOFB::BuildCellIndex()).
 *
 * The reader trusts nothing in the file. Before it allocates anything it checks
 * the magic bytes, the format version, the byte-order marker and the CRC-32 of
 * the header, and that the counts of the header (cells, samples, arrays) fit in
 * the size of the file, so that a forged count gives an error, never a huge
 * allocation. The frame must be possible: a finite origin, a positive cell size
 * with a finite inverse, a box within the range of float (depths and exported
 * coordinates are float) and fewer than 2^32 cells, their count matching the
 * dimensions. It then checks the CRC-32 of every section, that the cell offsets
 * start at 0, never decrease and end at the sample count, that the depths are
 * finite, sorted within each cell and within the box (0 to the cell size times the
 * number of cells along their axis), that every array has a known data type, one
 * tuple per sample and valid attribute roles, each played by an array of the type
 * and shape that the role's users expect (active scalars: unsigned char colours of
 * 1 to 4 components; normals and vectors: float, 3 components; texture
 * coordinates: float, 1 to 3 components; tensors: float or double, 6 or 9; global
 * ids: vtkIdType; ...), and that the trailer ends the file. Checksums prove that the
 * bytes are those written, not that they make sense: every check applies to files
 * whose checksums are valid.
 *
 * On any problem (no FileName, a missing, empty, truncated, corrupted or foreign
 * file, a FIFO or a device, an unsupported version) it reports an error naming the
 * file and the problem, sets the error code (vtkErrorCode) and produces an EMPTY
 * output; it never crashes nor waits. Progress events are sent while the file is read.
 *
 * @sa vtkOFBWriter vtkOFB
 */

#ifndef vtkOFBReader_h
#define vtkOFBReader_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBCoreModule.h" // for export macro

class VTKOFBCORE_EXPORT vtkOFBReader : public vtkOFBAlgorithm
{
public:
  static vtkOFBReader* New();
  vtkTypeMacro(vtkOFBReader, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Name of the file to read (required).
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /**
   * Whether `fileName` starts with the magic bytes of an OFB file (1) or not (0).
   * Reads 8 bytes; does not validate the rest of the file.
   */
  static int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkOFBReader();
  ~vtkOFBReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;

private:
  vtkOFBReader(const vtkOFBReader&) = delete;
  void operator=(const vtkOFBReader&) = delete;
};

#endif
