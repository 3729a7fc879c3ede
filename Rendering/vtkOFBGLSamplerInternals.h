// The OpenGL helpers of vtkOFBGLSampler (private): the build programs' sources and
// compilation, and the read back of GPU buffers.
#ifndef vtkOFBGLSamplerInternals_h
#define vtkOFBGLSamplerInternals_h

#include "vtk_glew.h"

#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>

namespace vtkofbgl
{
/// The source with its //VTK::System::Dec marker replaced by a version and defines.
std::string Source(const char* body, const std::string& defines);

/// A program of `stages`; 0 with `error` set when a stage does not compile or link.
GLuint CompileProgram(std::initializer_list<std::pair<GLenum, std::string>> stages,
  std::string& error);

/// The programs of a build, by index into a GLuint[NumberOfPrograms].
enum ProgramIndex
{
  COUNT_PROGRAM,
  FILL_PROGRAM,
  SCAN_PROGRAM, // three kernels: SCAN_PROGRAM + 0, 1, 2
  SORT_PROGRAM = SCAN_PROGRAM + 3,
  NumberOfPrograms
};

/// The counting and filling draws, the three scan kernels and the sort, in the
/// current context; on failure none is kept and `error` says why.
bool CompileBuildPrograms(GLuint programs[NumberOfPrograms], std::string& error);

/**
 * Read `bytes` of buffer `b` into `out`. With buffer storage (OpenGL 4.4), through
 * a staging buffer in client memory: the GPU copies chunks into it at bus speed and
 * the threads copy them out. Else with glGetBufferSubData, which some drivers do
 * through a slow synchronous path (0.6 GB/s measured on an NVIDIA H200).
 */
void Download(GLuint b, size_t bytes, void* out);
}

#endif
