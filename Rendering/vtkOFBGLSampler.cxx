#include "vtkOFBGLSampler.h"

#include "vtkAlgorithm.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTypeUInt32Array.h"
#include "vtk_glew.h"

#include "vtkOFBBuildFS.h"
#include "vtkOFBBuildGS.h"
#include "vtkOFBBuildVS.h"
#include "vtkOFBScanCS.h"
#include "vtkOFBSortCS.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
constexpr GLuint BlockSize = 2048;    // counts per scan block (256 invocations x 8)
constexpr GLuint MaxGroups = 65535;   // work groups per dispatch (the GL minimum)

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

/// Owns the GL objects of one build and deletes them, whatever the way out.
class Resources
{
public:
  ~Resources()
  {
    for (GLuint p : this->Programs)
    {
      glDeleteProgram(p);
    }
    if (!this->Buffers.empty())
    {
      glDeleteBuffers(static_cast<GLsizei>(this->Buffers.size()), this->Buffers.data());
    }
    if (this->VAO)
    {
      glDeleteVertexArrays(1, &this->VAO);
    }
    if (this->FBO)
    {
      glDeleteFramebuffers(1, &this->FBO);
    }
  }

  GLuint Compile(std::initializer_list<std::pair<GLenum, std::string>> stages, std::string& error)
  {
    GLuint program = glCreateProgram();
    this->Programs.push_back(program);
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
      return 0;
    }
    return program;
  }

  /// A buffer of `bytes` (at least 4) with optional data; 0 on an allocation error.
  GLuint Buffer(GLenum target, size_t bytes, const void* data = nullptr)
  {
    GLuint b = 0;
    glGenBuffers(1, &b);
    this->Buffers.push_back(b);
    glBindBuffer(target, b);
    while (glGetError() != GL_NO_ERROR)
    {
    }
    glBufferData(target, static_cast<GLsizeiptr>(std::max<size_t>(bytes, 4)), data, GL_DYNAMIC_COPY);
    return glGetError() == GL_NO_ERROR ? b : 0;
  }

  std::vector<GLuint> Programs;
  std::vector<GLuint> Buffers;
  GLuint VAO = 0;
  GLuint FBO = 0;
};

void SetUniform(GLuint program, const char* name, GLuint value)
{
  glUniform1ui(glGetUniformLocation(program, name), value);
}

/// Dispatch `groups` work groups in slices of at most MaxGroups, `first` uniform per slice.
void Dispatch(GLuint program, const char* first, GLuint groups, GLuint groupSize)
{
  for (GLuint g = 0; g < groups; g += MaxGroups)
  {
    SetUniform(program, first, g * groupSize);
    glDispatchCompute(std::min(MaxGroups, groups - g), 1, 1);
  }
}

/// Read `bytes` of buffer `b` into `out`.
void Download(GLuint b, size_t bytes, void* out)
{
  if (bytes == 0)
  {
    return;
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, b);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), out);
}
}

vtkStandardNewMacro(vtkOFBGLSampler);

//------------------------------------------------------------------------------
vtkOFBGLSampler::vtkOFBGLSampler() = default;

//------------------------------------------------------------------------------
vtkOFBGLSampler::~vtkOFBGLSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBGLSampler::SetRenderWindow(vtkOpenGLRenderWindow* window)
{
  if (this->RenderWindow != window)
  {
    this->RenderWindow = window;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkOFBGLSampler::EstimateWorkBytes(vtkIdType points, vtkIdType triangles, double samples) const
{
  // On the host: the points in cell units (doubles), the 32-bit indices, and the
  // interleaved barycentrics read back beside the two arrays interpolation takes.
  return 24.0 * static_cast<double>(points) + 12.0 * static_cast<double>(triangles) +
    8.0 * samples;
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend::Result vtkOFBGLSampler::Sample(Job& job)
{
  const vtkOFBSurface& surface = *job.Surface;
  vtkOFB* output = job.Output;
  vtkOpenGLRenderWindow* window = this->RenderWindow;
  if (!window)
  {
    job.Error = "no render window";
    return Unavailable;
  }
  const double samples = vtkOFBSamplerBackend::EstimateSamples(surface, job.CellSize);
  const bool zeroOffsets = true; // the scan writes them from zero counts
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(
        this->EstimateBytes(surface, job.Dimensions, samples), job.MemoryLimit, job.Error) ||
    !output->SetFrame(job.Origin, job.CellSize, job.Dimensions, zeroOffsets))
  {
    return Failed;
  }
  if (job.Algorithm)
  {
    job.Algorithm->UpdateProgress(0.1);
  }
  std::vector<vtkTypeUInt32> triangles;
  std::vector<float> barycentrics;
  window->PushContext();
  const bool rasterized = this->Rasterize(window, job, triangles, barycentrics);
  window->PopContext();
  if (!rasterized)
  {
    return Unavailable;
  }
  if (job.Algorithm)
  {
    job.Algorithm->UpdateProgress(0.7);
  }
  const vtkIdType n = output->GetNumberOfSamples();
  std::vector<float> w1(n), w2(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    w1[i] = barycentrics[2 * i];
    w2[i] = barycentrics[2 * i + 1];
  }
  barycentrics.clear();
  if (!output->BuildCellIndex() ||
    !vtkOFBSamplerBackend::InterpolateAttributes(surface, output, triangles.data(), w1.data(), w2.data()))
  {
    return Failed;
  }
  return Built;
}

//------------------------------------------------------------------------------
void vtkOFBGLSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderWindow: " << this->RenderWindow.GetPointer() << "\n";
}

//------------------------------------------------------------------------------
bool vtkOFBGLSampler::IsSupported(vtkOpenGLRenderWindow* window, std::string& why)
{
  if (!window)
  {
    why = "no OpenGL render window";
    return false;
  }
  window->Initialize();
  window->MakeCurrent();
  if (!window->IsCurrent())
  {
    why = "the render window has no current OpenGL context";
    return false;
  }
  GLint major = 0, minor = 0, viewports = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 43)
  {
    std::ostringstream os;
    os << "OpenGL " << major << "." << minor << " is older than 4.3";
    why = os.str();
    return false;
  }
  glGetIntegerv(GL_MAX_VIEWPORTS, &viewports);
  if (viewports < 3)
  {
    why = "fewer than 3 viewports";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBGLSampler::IsSoftwareRenderer(vtkOpenGLRenderWindow* window)
{
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::string name = renderer ? renderer : "";
  std::transform(name.begin(), name.end(), name.begin(), ::tolower);
  (void)window;
  for (const char* software : { "llvmpipe", "softpipe", "swrast", "swiftshader", "software" })
  {
    if (name.find(software) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkOFBGLSampler::Rasterize(vtkOpenGLRenderWindow* window, Job& job,
  std::vector<vtkTypeUInt32>& triangles, std::vector<float>& barycentrics)
{
  const vtkOFBSurface& surface = *job.Surface;
  vtkOFB* output = job.Output;
  std::string& error = job.Error;
  if (!vtkOFBGLSampler::IsSupported(window, error))
  {
    return false;
  }
  const vtkIdType* dims = output->GetDimensions();
  GLint maxViewport[2] = { 0, 0 }, maxWidth = 0, maxHeight = 0;
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &maxWidth);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxHeight);
  // Viewports of a power-of-two side: window coordinates map exactly to NDC.
  const vtkIdType longest = std::max({ dims[0], dims[1], dims[2] });
  GLint side = 1;
  while (side < longest)
  {
    side *= 2;
  }
  if (side > std::min<vtkIdType>({ maxViewport[0], maxViewport[1], maxWidth, maxHeight }))
  {
    std::ostringstream os;
    os << "the frame's " << longest << " cells need a " << side << " pixel viewport, larger than "
       << "the context's largest (" << std::min({ maxViewport[0], maxWidth }) << ")";
    error = os.str();
    return false;
  }

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable multisample(state, GL_MULTISAMPLE);
  vtkOpenGLState::ScopedglViewport viewport0(state);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_MULTISAMPLE);
  GLint previousProgram = 0, previousVAO = 0, previousArrayBuffer = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &previousVAO);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &previousArrayBuffer);
  GLfloat previousViewports[2][4];
  glGetFloati_v(GL_VIEWPORT, 1, previousViewports[0]);
  glGetFloati_v(GL_VIEWPORT, 2, previousViewports[1]);
  state->PushFramebufferBindings();

  bool ok = false;
  {
    Resources gl;
    ok = [&]() -> bool
    {
      // Programs.
      const GLuint count = gl.Compile({ { GL_VERTEX_SHADER, Source(vtkOFBBuildVS, "") },
                                        { GL_GEOMETRY_SHADER, Source(vtkOFBBuildGS, "") },
                                        { GL_FRAGMENT_SHADER, Source(vtkOFBBuildFS, "") } },
        error);
      const GLuint fill = count ? gl.Compile({ { GL_VERTEX_SHADER, Source(vtkOFBBuildVS, "") },
                                               { GL_GEOMETRY_SHADER, Source(vtkOFBBuildGS, "") },
                                               { GL_FRAGMENT_SHADER,
                                                 Source(vtkOFBBuildFS, "#define FILL 1\n") } },
                                    error)
                                : 0;
      GLuint scan[3] = { 0, 0, 0 };
      for (int k = 0; k < 3 && fill; ++k)
      {
        scan[k] = gl.Compile(
          { { GL_COMPUTE_SHADER,
            Source(vtkOFBScanCS, "#define KERNEL " + std::to_string(k) + "\n") } },
          error);
        if (!scan[k])
        {
          return false;
        }
      }
      const GLuint sort = fill ? gl.Compile({ { GL_COMPUTE_SHADER, Source(vtkOFBSortCS, "") } }, error) : 0;
      if (!sort)
      {
        return false;
      }

      // Geometry in cell units of the frame.
      const double* origin = output->GetOrigin();
      const double s = output->GetCellSize();
      const size_t np = surface.Points.size() / 3;
      std::vector<double> cells(3 * np);
      for (size_t i = 0; i < np; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          cells[3 * i + k] = (surface.Points[3 * i + k] - origin[k]) / s;
        }
      }
      std::vector<GLuint> indices(surface.Triangles.begin(), surface.Triangles.end());
      glGenVertexArrays(1, &gl.VAO);
      glBindVertexArray(gl.VAO);
      const GLuint vbo = gl.Buffer(GL_ARRAY_BUFFER, cells.size() * sizeof(double), cells.data());
      const GLuint ebo =
        gl.Buffer(GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(GLuint), indices.data());
      if (!vbo || !ebo)
      {
        error = "cannot allocate the vertex buffers";
        return false;
      }
      for (GLuint program : { count, fill })
      {
        const GLint location = glGetAttribLocation(program, "vertexCells");
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glEnableVertexAttribArray(location);
        glVertexAttribLPointer(location, 3, GL_DOUBLE, 0, nullptr);
      }

      // Counters, offsets and the framebuffer without attachments.
      const vtkIdType nCells = output->GetNumberOfCells();
      const GLuint blocks = static_cast<GLuint>((nCells + BlockSize - 1) / BlockSize);
      const GLuint counts = gl.Buffer(GL_SHADER_STORAGE_BUFFER, nCells * sizeof(GLuint));
      const GLuint offsets = gl.Buffer(GL_SHADER_STORAGE_BUFFER, (nCells + 1) * sizeof(GLuint));
      const GLuint sums = gl.Buffer(GL_SHADER_STORAGE_BUFFER, (blocks + 1) * sizeof(GLuint));
      if (!counts || !offsets || !sums)
      {
        error = "cannot allocate the cell counters on the GPU";
        return false;
      }
      const GLuint zero = 0;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, counts);
      glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
      glGenFramebuffers(1, &gl.FBO);
      state->vtkglBindFramebuffer(GL_FRAMEBUFFER, gl.FBO);
      glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, side);
      glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, side);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      {
        error = "the framebuffer without attachments is incomplete";
        return false;
      }
      GLuint base[3], width[3], height[3];
      for (int a = 0; a < 3; ++a)
      {
        base[a] = static_cast<GLuint>(output->GetGridCellBase(a));
        width[a] = static_cast<GLuint>(dims[(a + 1) % 3]);
        height[a] = static_cast<GLuint>(dims[(a + 2) % 3]);
        glViewportIndexedf(a, 0.0f, 0.0f, static_cast<float>(side), static_cast<float>(side));
      }
      const GLsizei nIndices = static_cast<GLsizei>(indices.size());
      auto draw = [&](GLuint program)
      {
        glUseProgram(program);
        glUniform1d(glGetUniformLocation(program, "viewportSize"), static_cast<double>(side));
        glUniform3ui(glGetUniformLocation(program, "gridBase"), base[0], base[1], base[2]);
        glUniform3i(glGetUniformLocation(program, "gridWidth"), width[0], width[1], width[2]);
        glUniform3i(glGetUniformLocation(program, "gridHeight"), height[0], height[1], height[2]);
        glUniform1d(glGetUniformLocation(program, "cellSize"), s);
        glDrawElements(GL_TRIANGLES, nIndices, GL_UNSIGNED_INT, nullptr);
      };

      // Pass 1: count.
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counts);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, offsets);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, sums);
      draw(count);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

      // Pass 2: scan.
      glUseProgram(scan[0]);
      SetUniform(scan[0], "numberOfValues", static_cast<GLuint>(nCells));
      Dispatch(scan[0], "firstBlock", blocks, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      glUseProgram(scan[1]);
      SetUniform(scan[1], "numberOfValues", blocks);
      glDispatchCompute(1, 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      glUseProgram(scan[2]);
      SetUniform(scan[2], "numberOfValues", static_cast<GLuint>(nCells));
      Dispatch(scan[2], "firstBlock", blocks, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
      GLuint total = 0;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, sums);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, blocks * sizeof(GLuint), sizeof(GLuint), &total);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, offsets);
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, nCells * sizeof(GLuint), sizeof(GLuint), &total);
      const vtkIdType n = total;
      if (!vtkOFBSamplerBackend::CheckMemoryLimit(
            this->EstimateBytes(surface, dims, static_cast<double>(n)), job.MemoryLimit, error))
      {
        return false;
      }

      // Pass 3: fill.
      const GLuint depths = gl.Buffer(GL_SHADER_STORAGE_BUFFER, n * sizeof(float));
      const GLuint tris = gl.Buffer(GL_SHADER_STORAGE_BUFFER, n * sizeof(GLuint));
      const GLuint bary = gl.Buffer(GL_SHADER_STORAGE_BUFFER, 2 * n * sizeof(float));
      if (!depths || !tris || !bary)
      {
        error = "cannot allocate the samples on the GPU";
        return false;
      }
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, depths);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, tris);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, bary);
      glBindVertexArray(gl.VAO);
      draw(fill);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

      // Pass 4: sort each cell.
      glUseProgram(sort);
      SetUniform(sort, "numberOfCells", static_cast<GLuint>(nCells));
      Dispatch(sort, "firstCell", static_cast<GLuint>((nCells + 255) / 256), 256);
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

      // Read back.
      if (!output->AllocateSamples(n))
      {
        error = "cannot allocate the samples";
        return false;
      }
      triangles.resize(n);
      barycentrics.resize(2 * n);
      Download(offsets, (nCells + 1) * sizeof(GLuint), output->GetCellOffsets()->GetPointer(0));
      Download(depths, n * sizeof(float), output->GetDepths()->GetPointer(0));
      Download(tris, n * sizeof(GLuint), triangles.data());
      Download(bary, 2 * n * sizeof(float), barycentrics.data());
      for (GLuint binding = 0; binding < 6; ++binding)
      {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
      }
      if (glGetError() != GL_NO_ERROR)
      {
        error = "an OpenGL error occurred";
        return false;
      }
      return true;
    }();
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindVertexArray(static_cast<GLuint>(previousVAO));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(previousArrayBuffer));
    glUseProgram(static_cast<GLuint>(previousProgram));
  }
  glViewportIndexedfv(1, previousViewports[0]);
  glViewportIndexedfv(2, previousViewports[1]);
  state->PopFramebufferBindings();
  return ok;
}
