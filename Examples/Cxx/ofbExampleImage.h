/**
 * @file   ofbExampleImage.h
 * @brief  The one way the example applications read an image (decals, imported textures)
 *
 * Images are decoded by vtkOFBImageReader (OFB::IOImage, through OpenImageIO), in the
 * file's own sample type: 8-bit, 16-bit or float, as decals and textures take them.
 * ReadImageChecked first checks the file itself, so that no decoder sees a damaged
 * stream of the formats most often passed around and no header makes it allocate
 * gigabytes, then decodes it and checks what came out:
 *
 * - the path is a regular file of at most MaximumImageFileBytes;
 * - PNG: the signature, every chunk's length and CRC-32, an IHDR first with a valid bit
 *   depth and colour type, a PLTE for a palette image, an IEND; the zlib stream of the IDAT
 *   chunks inflates (into a small buffer, nothing kept) to exactly the bytes the image
 *   needs, every row with a valid filter byte;
 * - JPEG: the frame header (SOF) before the scan; BMP: an uncompressed 8- or 24-bit bitmap
 *   whose pixel rows fit in the file; PNM: a binary P5 (grey) or P6 (RGB) with a maximum
 *   value of at most 255 whose pixels fit in the file;
 * - TIFF, OpenEXR and Radiance HDR (found by their signatures) go to the decoder, which
 *   refuses a header of more than `maxPixels` pixels before it allocates, and refuses
 *   files cut short or damaged with the decoder's message;
 * - both sides at least 1 and at most MaximumImageSide, and at most `maxPixels` pixels;
 * - other formats (ASCII PNM, GIF, ...) are refused;
 * - after decoding: no error, and an image of the size the header gave, with scalars.
 *
 * Every image the applications read goes through here.
 */
#ifndef ofbExampleImage_h
#define ofbExampleImage_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;

namespace ofbexample
{
/// The largest width or height accepted.
constexpr long long MaximumImageSide = 32768;
/// The default pixel limit: 64 Mpixels (256 MB as RGBA).
constexpr long long DefaultMaximumImagePixels = 1LL << 26;
/// The largest image file accepted: 1 GiB.
constexpr long long MaximumImageFileBytes = 1LL << 30;

/// The image at `path` (PNG, JPEG, BMP, binary PNM, TIFF, OpenEXR, Radiance HDR) checked
/// as above, or null with `message` saying what is wrong ("cannot read 'PATH': ...").
/// Its scalars are unsigned char, unsigned short or float, as in the file.
vtkSmartPointer<vtkImageData> ReadImageChecked(const std::string& path,
  long long maxPixels,
  std::string& message);
}

#endif
