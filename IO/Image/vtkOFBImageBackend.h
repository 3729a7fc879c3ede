/**
 * @file   vtkOFBImageBackend.h
 * @brief  The OpenImageIO side of vtkOFBImageReader and vtkOFBImageWriter (private)
 *
 * OpenImageIO's library links about 270 others (OpenCV, FFmpeg, DCMTK, OpenVDB, ...),
 * whose loading and static initialization take a second or more at every program start.
 * So vtkOFBIOImage does not link it: the calls to OpenImageIO live in a module of their
 * own, libvtkOFBIOImageOpenImageIO.so beside libvtkOFBIOImage.so, loaded (dlopen) at the
 * first image read or written. A program that reads no image never loads OpenImageIO.
 *
 * The module exports one C function, vtkOFBImageBackendGet, which returns the table
 * below; both sides are built together, so the table is plain C++.
 */
#ifndef vtkOFBImageBackend_h
#define vtkOFBImageBackend_h

#include <string>

/// Called during a read or write with the part done; true stops it.
using vtkOFBImageProgress = bool (*)(void* user, float done);

/// What a file's header says.
struct vtkOFBImageHeader
{
  std::string Format; // OpenImageIO's name: "png", "openexr", ...
  int Width = 0;
  int Height = 0;
  int Depth = 1; // slices (a volume when over 1)
  int Channels = 0;
  bool Deep = false;
  int BitsPerSample = 0; // in the file
  int ScalarType = 0;    // VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT, or 0: not read
  std::string TypeName;  // the file's sample type ("uint8", "int32", ...)
};

struct vtkOFBImageBackendAPI
{
  int Version; // 1
  /// The header of `path`, or false with `error` (no format recognizes it, or damaged).
  bool (*ReadHeader)(const char* path, vtkOFBImageHeader& header, std::string& error);
  /**
   * The pixels of `path` as `scalarType` (a VTK type of ReadHeader), `channels` a pixel,
   * into `data` (width x height pixels, row 0 the bottom of the picture); false with
   * `error` where the decoder failed or only warned (a file cut short).
   */
  bool (*ReadPixels)(const char* path,
    int scalarType,
    int width,
    int height,
    int channels,
    void* data,
    vtkOFBImageProgress progress,
    void* user,
    std::string& error);
  /// The name of the format that writes files named `path` ("" when none does).
  std::string (*WriterFormat)(const char* path);
  /**
   * Write `data` (width x height pixels of `channels` `scalarType` values, row 0 the
   * bottom) to `path` in `format`; floats in OpenEXR as half with `half`; JPEG at
   * `quality`. False with `error`.
   */
  bool (*Write)(const char* path,
    int scalarType,
    int width,
    int height,
    int channels,
    const void* data,
    bool half,
    int quality,
    vtkOFBImageProgress progress,
    void* user,
    std::string& error);
};

/// The table, loading the module on the first call; null with `error` where it cannot be
/// loaded (the message names the file looked for).
const vtkOFBImageBackendAPI* vtkOFBLoadImageBackend(std::string& error);

#endif
