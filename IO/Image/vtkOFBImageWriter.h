/**
 * @class   vtkOFBImageWriter
 * @brief   Write a vtkImageData to an image file of any format OpenImageIO writes
 *
 * vtkOFBImageWriter writes a 2-D image through OpenImageIO, in the format its file
 * name's extension names: .png, .jpg/.jpeg, .tif/.tiff, .exr, .hdr, .bmp, .tga, .pnm and
 * the others of the OpenImageIO build. It is how baked textures leave vtkOFB: a float
 * bake of vtkOFBTextureBaker (a LIC, a scalar field) goes to a 32-bit float OpenEXR
 * without quantization, the paint to a PNG. OpenImageIO is loaded at the first file
 * written (libvtkOFBIOImageOpenImageIO.so, beside this library).
 *
 * Input: a vtkImageData of one slice (extent [x0, x1] x [y0, y1] x [z, z]) whose active
 * scalars are unsigned char, unsigned short or float with 1 to 4 components (grey, grey
 * and alpha, RGB, RGBA; alpha unassociated, written as such). Row 0 is the bottom of the
 * picture (VTK's convention, the one vtkOFBImageReader reads back): it becomes the
 * file's last scanline.
 *
 * The samples are written in their own type where the format has it: unsigned char as
 * 8 bits everywhere; unsigned short as 16 bits (PNG, TIFF, PNM); float as 32-bit float
 * in OpenEXR and TIFF, or as 16-bit half float in OpenEXR with `HalfFloat` on. A format
 * without the type converts as OpenImageIO does, integers taken as fractions of their
 * range: to 8 bits for JPEG and BMP (float clamped to [0, 1] then scaled), to half
 * float for 8- and 16-bit integers in OpenEXR (value / 255 or / 65535), to float for
 * Radiance HDR (which stores RGB only: other channel counts are refused). Lossless compression
 * (OpenEXR zip, TIFF zip) except for JPEG, whose `Quality` is a setting.
 *
 * The file is written under a temporary name in its directory and renamed over
 * FileName when complete: a failed write leaves an existing file untouched.
 *
 * Errors (nothing written, an error naming the file and the cause, GetErrorCode() set,
 * Write() returns 0): no FileName, an extension no format has, a directory that is
 * missing or not writable, no input, an input that is not one slice or has no pixels,
 * scalars of another type (convert them first, e.g. vtkImageCast to float) or with
 * another number of components, a layout the format cannot store, a failed write,
 * OpenImageIO's module that cannot be loaded.
 *
 * @sa vtkOFBImageReader vtkOFBTextureBaker
 */

#ifndef vtkOFBImageWriter_h
#define vtkOFBImageWriter_h

#include "vtkOFBIOImageModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for Fail

class vtkImageData;

class VTKOFBIOIMAGE_EXPORT vtkOFBImageWriter : public vtkWriter
{
public:
  static vtkOFBImageWriter* New();
  vtkTypeMacro(vtkOFBImageWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to write (required); its extension chooses the format. An existing file
   * is replaced once the new one is complete.
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * Float images as 16-bit half floats in OpenEXR (default off: 32-bit float, exact).
   * Other formats ignore it.
   */
  vtkSetMacro(HalfFloat, bool);
  vtkGetMacro(HalfFloat, bool);
  vtkBooleanMacro(HalfFloat, bool);
  ///@}

  ///@{
  /**
   * JPEG quality, 1 to 100 (default 95). Other formats are written losslessly.
   */
  vtkSetClampMacro(Quality, int, 1, 100);
  vtkGetMacro(Quality, int);
  ///@}

  /**
   * The input image.
   */
  vtkImageData* GetInput();

  /**
   * Whether OpenImageIO has a writer for the extension of `fileName` (".exr", ...).
   */
  static bool CanWriteExtension(const char* fileName);

protected:
  vtkOFBImageWriter();
  ~vtkOFBImageWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;
  /// An error about the file (with its name), and the error code.
  void Fail(const std::string& problem, unsigned long code);

  char* FileName = nullptr;
  bool HalfFloat = false;
  int Quality = 95;

private:
  vtkOFBImageWriter(const vtkOFBImageWriter&) = delete;
  void operator=(const vtkOFBImageWriter&) = delete;
};

#endif
