#include "vtkOFBGLSamplerInternals.h"

#include "vtkSMPTools.h"

#include "vtkOFBBuildFS.h"
#include "vtkOFBBuildGS.h"
#include "vtkOFBBuildVS.h"
#include "vtkOFBScanCS.h"
#include "vtkOFBSortCS.h"

#include <algorithm>
#include <cstring>

namespace vtkofbgl
{
/// The source with its //VTK::System::Dec marker replaced by a version and defines.
std::string Source(const char* body, const std::string& defines)
{
  std::string s = body;
  const std::string marker = "//VTK::System::Dec";
  const size_t at = s.find(marker);
  const std::string header = "#version 430 core\n" + defines;
  if (at == std::string::npos)
  {
    return header + s;
  }
  return s.replace(at, marker.size(), header);
}

/// A program of `stages`; 0 with `error` set when a stage does not compile or link.
GLuint CompileProgram(std::initializer_list<std::pair<GLenum, std::string>> stages,
  std::string& error)
{
  GLuint program = glCreateProgram();
  for (const auto& stage : stages)
  {
    GLuint shader = glCreateShader(stage.first);
    const char* text = stage.second.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok)
    {
      char log[2048] = { 0 };
      glGetShaderInfoLog(shader, sizeof(log) - 1, nullptr, log);
      error = std::string("shader compilation failed: ") + log;
      glDeleteShader(shader);
      glDeleteProgram(program);
      return 0;
    }
    glAttachShader(program, shader);
    glDeleteShader(shader); // freed with the program
  }
  glLinkProgram(program);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    char log[2048] = { 0 };
    glGetProgramInfoLog(program, sizeof(log) - 1, nullptr, log);
    error = std::string("shader link failed: ") + log;
    glDeleteProgram(program);
    return 0;
  }
  return program;
}

/// The counting and filling draws, the three scan kernels and the sort, in the
/// current context; on failure none is kept and `error` says why.
bool CompileBuildPrograms(GLuint programs[NumberOfPrograms], std::string& error)
{
  const std::string vertex = Source(vtkOFBBuildVS, "");
  const std::string geometry = Source(vtkOFBBuildGS, "");
  programs[COUNT_PROGRAM] = CompileProgram({ { GL_VERTEX_SHADER, vertex },
                                             { GL_GEOMETRY_SHADER, geometry },
                                             { GL_FRAGMENT_SHADER, Source(vtkOFBBuildFS, "") } },
    error);
  programs[FILL_PROGRAM] =
    CompileProgram({ { GL_VERTEX_SHADER, vertex },
                     { GL_GEOMETRY_SHADER, geometry },
                     { GL_FRAGMENT_SHADER, Source(vtkOFBBuildFS, "#define FILL 1\n") } },
      error);
  for (int k = 0; k < 3; ++k)
  {
    const std::string kernel = "#define KERNEL " + std::to_string(k) + "\n";
    programs[SCAN_PROGRAM + k] =
      CompileProgram({ { GL_COMPUTE_SHADER, Source(vtkOFBScanCS, kernel) } }, error);
  }
  programs[SORT_PROGRAM] =
    CompileProgram({ { GL_COMPUTE_SHADER, Source(vtkOFBSortCS, "") } }, error);
  if (std::find(programs, programs + NumberOfPrograms, 0u) == programs + NumberOfPrograms)
  {
    return true;
  }
  for (int k = 0; k < NumberOfPrograms; ++k)
  {
    glDeleteProgram(programs[k]); // 0 is ignored
    programs[k] = 0;
  }
  return false;
}

/**
 * Read `bytes` of buffer `b` into `out`. With buffer storage (OpenGL 4.4), through
 * a staging buffer in client memory: the GPU copies chunks into it at bus speed and
 * the threads copy them out. Else with glGetBufferSubData, which some drivers do
 * through a slow synchronous path (0.6 GB/s measured on an NVIDIA H200).
 */
void Download(GLuint b, size_t bytes, void* out)
{
  if (bytes == 0)
  {
    return;
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 44 || !glBufferStorage)
  {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, b);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), out);
    return;
  }
  constexpr size_t Chunk = size_t(64) << 20;
  const size_t stagingBytes = std::min(bytes, Chunk);
  GLuint staging = 0;
  glGenBuffers(1, &staging);
  glBindBuffer(GL_COPY_WRITE_BUFFER, staging);
  glBufferStorage(GL_COPY_WRITE_BUFFER,
    static_cast<GLsizeiptr>(stagingBytes),
    nullptr,
    GL_MAP_READ_BIT | GL_CLIENT_STORAGE_BIT);
  glBindBuffer(GL_COPY_READ_BUFFER, b);
  auto* target = static_cast<unsigned char*>(out);
  for (size_t at = 0; at < bytes; at += Chunk)
  {
    const size_t n = std::min(Chunk, bytes - at);
    glCopyBufferSubData(GL_COPY_READ_BUFFER,
      GL_COPY_WRITE_BUFFER,
      static_cast<GLintptr>(at),
      0,
      static_cast<GLsizeiptr>(n));
    const auto* source = static_cast<const unsigned char*>(
      glMapBufferRange(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(n), GL_MAP_READ_BIT));
    if (!source)
    {
      break; // the caller's glGetError reports it
    }
    constexpr size_t Piece = size_t(1) << 20;
    vtkSMPTools::For(0,
      static_cast<vtkIdType>((n + Piece - 1) / Piece),
      [&](vtkIdType first, vtkIdType last)
      {
        const size_t begin = static_cast<size_t>(first) * Piece;
        const size_t end = std::min(n, static_cast<size_t>(last) * Piece);
        std::memcpy(target + at + begin, source + begin, end - begin);
      });
    glUnmapBuffer(GL_COPY_WRITE_BUFFER);
  }
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glDeleteBuffers(1, &staging);
}
}
