/**
 * @class   vtkOFBImageReader
 * @brief   Read an image file of any format OpenImageIO knows into a vtkImageData
 *
 * vtkOFBImageReader reads the pixels of an image file through OpenImageIO: PNG, JPEG,
 * TIFF, OpenEXR, Radiance HDR, BMP, PNM, TGA and the other formats of the OpenImageIO
 * build (found from the file's contents, not its name). It is how decals, brush images
 * and textures come into vtkOFB: the output goes to vtkOFBTextureProjector as it is.
 * OpenImageIO is loaded at the first file read (libvtkOFBIOImageOpenImageIO.so, beside
 * this library), not when the program starts.
 *
 * Output: a 2-D vtkImageData of the file's width x height (origin 0, spacing 1; extent
 * [0, W-1] x [0, H-1] x [0, 0]) whose scalars, named "Pixels", keep the file's channels
 * (1 grey, 2 grey and alpha, 3 RGB, 4 RGBA; alpha unassociated, as the file stores it)
 * and its sample type: 8-bit files give unsigned char, 16-bit files unsigned short, and
 * half, float and double files float (a file that mixes channel types takes the widest).
 * Row 0 is the bottom row of the picture, as VTK and texture coordinates (v = 0 at the
 * bottom) expect: the file's first scanline, its top, is the output's last row. An
 * OpenEXR data window is read whole (its offset dropped); only the first subimage and
 * its full-resolution level are read. The values are those of the file, converted
 * exactly: no colour-space or gamma conversion.
 *
 * Errors (an empty output, an error naming the file and the cause, and GetErrorCode() a
 * vtkErrorCode: NoFileNameError, FileNotFoundError, CannotOpenFileError,
 * UnrecognizedFileTypeError, FileFormatError, PrematureEndOfFileError,
 * OutOfDiskSpaceError for an image over the limit or the memory, UnknownError when
 * OpenImageIO's module cannot be loaded): no
 * FileName, a file that does not exist or is not a regular file, one that no format
 * recognizes or that is damaged or cut short (the decoder's message is given), a
 * layout that is not read (a deep image, a volume, more than 4 channels, signed or
 * 32-bit integer samples), and more than MaximumNumberOfPixels pixels (checked from
 * the header, before anything is allocated).
 *
 * @sa vtkOFBImageWriter vtkOFBTextureProjector
 */

#ifndef vtkOFBImageReader_h
#define vtkOFBImageReader_h

#include "vtkImageAlgorithm.h"
#include "vtkOFBIOImageModule.h" // for export macro

#include <string> // for the header's problem

class VTKOFBIOIMAGE_EXPORT vtkOFBImageReader : public vtkImageAlgorithm
{
public:
  static vtkOFBImageReader* New();
  vtkTypeMacro(vtkOFBImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The image file to read (required).
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * The largest image read, in pixels (default 2^28, 268 million; at least 1). A
   * larger header is refused before any pixel is allocated.
   */
  vtkSetClampMacro(MaximumNumberOfPixels, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfPixels, vtkIdType);
  ///@}

  /**
   * OpenImageIO's name of the last file's format ("png", "jpeg", "tiff", "openexr",
   * "hdr", ...), empty before a read or when the file could not be opened.
   */
  const char* GetFormatName() const { return this->FormatName.c_str(); }

  /**
   * Bits a sample in the last file (8, 16, 32, ...; 0 before a read), whatever the output
   * type: a half-float OpenEXR says 16 and is read as float.
   */
  vtkGetMacro(FileBitsPerSample, int);

  /**
   * Whether OpenImageIO can read the file (a format recognizes its contents); the
   * pixels are not read.
   */
  static bool CanReadFile(const char* fileName);

protected:
  vtkOFBImageReader();
  ~vtkOFBImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// An error about the file (with its name), and the error code.
  void Fail(const std::string& problem, unsigned long code);

  char* FileName = nullptr;
  vtkIdType MaximumNumberOfPixels = vtkIdType(1) << 28;
  std::string FormatName;
  int FileBitsPerSample = 0;

  // The header of the last RequestInformation.
  bool HeaderValid = false;
  int Width = 0;
  int Height = 0;
  int Components = 0;
  int ScalarType = 0;

private:
  vtkOFBImageReader(const vtkOFBImageReader&) = delete;
  void operator=(const vtkOFBImageReader&) = delete;
};

#endif
