/**
 * @class   vtkOFBGLSampler
 * @brief   OFB construction with OpenGL in a VTK render window's context (private)
 *
 * Used by vtkOFBBuilder. In the current context of an OpenGL 4.3+ render window:
 * a geometry shader routes each triangle to the viewport of its grid in a
 * framebuffer without attachments; the fragment shader counts samples per cell
 * with SSBO atomics; a compute shader scans the counts into cell offsets; a
 * second draw fills depth, triangle and barycentric coordinates of every sample;
 * a compute shader sorts each cell by (depth, triangle). The results are read
 * back into the vtkOFB (offsets, depths) and into the caller's triangle and
 * barycentric arrays, from which the sample arrays are interpolated on the CPU
 * exactly as the CPU backend does. GL state is restored afterwards.
 */

#ifndef vtkOFBGLSampler_h
#define vtkOFBGLSampler_h

#include "vtkType.h"

#include <string>
#include <vector>

class vtkOFB;
class vtkOFBSurface;
class vtkOpenGLRenderWindow;

class vtkOFBGLSampler
{
public:
  /**
   * Whether the window's context can build an OFB (OpenGL 4.3 with three
   * viewports); makes the context current. `why` says what is missing.
   */
  static bool IsSupported(vtkOpenGLRenderWindow* window, std::string& why);

  /**
   * Whether the context's renderer is a software one (llvmpipe, softpipe, ...).
   */
  static bool IsSoftwareRenderer(vtkOpenGLRenderWindow* window);

  /**
   * Sample `surface` into `output`, whose frame is already set (SetFrame). On
   * success the output has its offsets, samples and depths, and `triangles` and
   * `barycentrics` (2 per sample) hold what attribute interpolation needs.
   * `error` explains a failure (context, limits, allocation); `limitBytes` bounds
   * the memory of the samples, checked once their number is known.
   */
  static bool Sample(vtkOpenGLRenderWindow* window, const vtkOFBSurface& surface, vtkOFB* output,
    double limitBytes, double bytesPerSample, std::vector<vtkTypeUInt32>& triangles,
    std::vector<float>& barycentrics, std::string& error);
};

#endif
