#include "vtkOFBGLSampler.h"

#include "vtkAlgorithm.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBSampleSources.h"
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
constexpr GLuint BlockSize = 2048;  // counts per scan block (256 invocations x 8)
constexpr GLuint MaxGroups = 65535; // work groups per dispatch (the GL minimum)

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
    // Clear earlier errors, at most 16 (a lost context may report one on every call).
    for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k)
    {
    }
    glBufferData(
      target, static_cast<GLsizeiptr>(std::max<size_t>(bytes, 4)), data, GL_DYNAMIC_COPY);
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

/**
 * The GL state a build changes (capabilities, viewports 0-2, bindings, program,
 * framebuffer), saved on construction and restored on destruction.
 */
class ScopedBuildState
{
public:
  explicit ScopedBuildState(vtkOpenGLState* state)
    : State(state)
    , Cull(state, GL_CULL_FACE)
    , Depth(state, GL_DEPTH_TEST)
    , Blend(state, GL_BLEND)
    , Scissor(state, GL_SCISSOR_TEST)
    , Multisample(state, GL_MULTISAMPLE)
    , Viewport0(state)
  {
    for (GLenum capability :
      { GL_CULL_FACE, GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST, GL_MULTISAMPLE })
    {
      state->vtkglDisable(capability);
    }
    glGetIntegerv(GL_CURRENT_PROGRAM, &this->Program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &this->VertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &this->ArrayBuffer);
    glGetFloati_v(GL_VIEWPORT, 1, this->Viewports[0]);
    glGetFloati_v(GL_VIEWPORT, 2, this->Viewports[1]);
    state->PushFramebufferBindings();
  }

  ~ScopedBuildState()
  {
    for (GLuint binding = 0; binding < 6; ++binding)
    {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindVertexArray(static_cast<GLuint>(this->VertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(this->ArrayBuffer));
    glUseProgram(static_cast<GLuint>(this->Program));
    glViewportIndexedfv(1, this->Viewports[0]);
    glViewportIndexedfv(2, this->Viewports[1]);
    this->State->PopFramebufferBindings();
  }

  ScopedBuildState(const ScopedBuildState&) = delete;
  ScopedBuildState& operator=(const ScopedBuildState&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglEnableDisable Cull, Depth, Blend, Scissor, Multisample;
  vtkOpenGLState::ScopedglViewport Viewport0;
  GLint Program = 0, VertexArray = 0, ArrayBuffer = 0;
  GLfloat Viewports[2][4];
};

/**
 * The passes of one OpenGL build over the GL objects it owns: count the samples
 * of each cell (draw), scan the counts into offsets (compute), fill depth,
 * triangle and barycentrics of every sample (draw), sort each cell (compute),
 * read back. Each step returns false with `Error` set on failure.
 */
class GLBuild
{
public:
  GLBuild(const vtkOFBSurface& surface,
    vtkOFB* output,
    GLint side,
    vtkOpenGLState* state,
    std::string& error)
    : Surface(surface)
    , Output(output)
    , Side(side)
    , State(state)
    , Error(error)
    , NumberOfCells(output->GetNumberOfCells())
    , Blocks(static_cast<GLuint>((this->NumberOfCells + BlockSize - 1) / BlockSize))
  {
  }

  /// The counting and filling draws, the three scan kernels and the sort.
  bool CompilePrograms()
  {
    const std::string vertex = Source(vtkOFBBuildVS, "");
    const std::string geometry = Source(vtkOFBBuildGS, "");
    this->CountProgram = this->GL.Compile({ { GL_VERTEX_SHADER, vertex },
                                            { GL_GEOMETRY_SHADER, geometry },
                                            { GL_FRAGMENT_SHADER, Source(vtkOFBBuildFS, "") } },
      this->Error);
    if (!this->CountProgram)
    {
      return false;
    }
    this->FillProgram =
      this->GL.Compile({ { GL_VERTEX_SHADER, vertex },
                         { GL_GEOMETRY_SHADER, geometry },
                         { GL_FRAGMENT_SHADER, Source(vtkOFBBuildFS, "#define FILL 1\n") } },
        this->Error);
    if (!this->FillProgram)
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::string kernel = "#define KERNEL " + std::to_string(k) + "\n";
      this->ScanPrograms[k] =
        this->GL.Compile({ { GL_COMPUTE_SHADER, Source(vtkOFBScanCS, kernel) } }, this->Error);
      if (!this->ScanPrograms[k])
      {
        return false;
      }
    }
    this->SortProgram =
      this->GL.Compile({ { GL_COMPUTE_SHADER, Source(vtkOFBSortCS, "") } }, this->Error);
    return this->SortProgram != 0;
  }

  /// The points in cell units of the frame (doubles) and the triangles' indices.
  bool UploadGeometry()
  {
    const double* origin = this->Output->GetOrigin();
    const double cellSize = this->Output->GetCellSize();
    const std::vector<double>& points = this->Surface.Points;
    std::vector<double> cells(points.size());
    for (size_t i = 0; i < points.size() / 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        cells[3 * i + k] = (points[3 * i + k] - origin[k]) / cellSize;
      }
    }
    const std::vector<GLuint> indices(
      this->Surface.Triangles.begin(), this->Surface.Triangles.end());
    this->NumberOfIndices = static_cast<GLsizei>(indices.size());
    glGenVertexArrays(1, &this->GL.VAO);
    glBindVertexArray(this->GL.VAO);
    const GLuint vertices =
      this->GL.Buffer(GL_ARRAY_BUFFER, cells.size() * sizeof(double), cells.data());
    const GLuint elements =
      this->GL.Buffer(GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(GLuint), indices.data());
    if (!vertices || !elements)
    {
      this->Error = "cannot allocate the vertex buffers";
      return false;
    }
    for (GLuint program : { this->CountProgram, this->FillProgram })
    {
      const GLint location = glGetAttribLocation(program, "vertexCells");
      glBindBuffer(GL_ARRAY_BUFFER, vertices);
      glEnableVertexAttribArray(location);
      glVertexAttribLPointer(location, 3, GL_DOUBLE, 0, nullptr);
    }
    return true;
  }

  /// The per-cell counters and offsets, and the framebuffer without attachments.
  bool AllocateCounters()
  {
    const vtkIdType nCells = this->NumberOfCells;
    this->Counts = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, nCells * sizeof(GLuint));
    this->Offsets = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, (nCells + 1) * sizeof(GLuint));
    this->BlockSums =
      this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, (this->Blocks + 1) * sizeof(GLuint));
    if (!this->Counts || !this->Offsets || !this->BlockSums)
    {
      this->Error = "cannot allocate the cell counters on the GPU";
      return false;
    }
    const GLuint zero = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Counts);
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glGenFramebuffers(1, &this->GL.FBO);
    this->State->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->GL.FBO);
    glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, this->Side);
    glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, this->Side);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    {
      this->Error = "the framebuffer without attachments is incomplete";
      return false;
    }
    for (int a = 0; a < 3; ++a)
    {
      glViewportIndexedf(
        a, 0.0f, 0.0f, static_cast<float>(this->Side), static_cast<float>(this->Side));
    }
    return true;
  }

  /// Pass 1: the samples of each cell counted by the fragment shader.
  void CountSamples()
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->Counts);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->Offsets);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, this->BlockSums);
    this->Draw(this->CountProgram);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  /// Pass 2: the counts scanned into cell offsets (by block, the block sums, then
  /// the blocks again); the number of samples.
  vtkIdType ScanCounts()
  {
    const auto nCells = static_cast<GLuint>(this->NumberOfCells);
    const GLuint* scan = this->ScanPrograms;
    glUseProgram(scan[0]);
    SetUniform(scan[0], "numberOfValues", nCells);
    Dispatch(scan[0], "firstBlock", this->Blocks, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(scan[1]);
    SetUniform(scan[1], "numberOfValues", this->Blocks);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(scan[2]);
    SetUniform(scan[2], "numberOfValues", nCells);
    Dispatch(scan[2], "firstBlock", this->Blocks, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint total = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->BlockSums);
    glGetBufferSubData(
      GL_SHADER_STORAGE_BUFFER, this->Blocks * sizeof(GLuint), sizeof(GLuint), &total);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Offsets);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, nCells * sizeof(GLuint), sizeof(GLuint), &total);
    return total;
  }

  /// Pass 3: depth, triangle and barycentrics of each of the n samples.
  bool FillSamples(vtkIdType n)
  {
    this->Depths = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, n * sizeof(float));
    this->Triangles = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, n * sizeof(GLuint));
    this->Barycentrics = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, 2 * n * sizeof(float));
    if (!this->Depths || !this->Triangles || !this->Barycentrics)
    {
      this->Error = "cannot allocate the samples on the GPU";
      return false;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->Depths);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, this->Triangles);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, this->Barycentrics);
    glBindVertexArray(this->GL.VAO);
    this->Draw(this->FillProgram);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return true;
  }

  /// Pass 4: the samples of each cell sorted by (depth, triangle).
  void SortCells()
  {
    const auto nCells = static_cast<GLuint>(this->NumberOfCells);
    glUseProgram(this->SortProgram);
    SetUniform(this->SortProgram, "numberOfCells", nCells);
    Dispatch(this->SortProgram, "firstCell", (nCells + 255) / 256, 256);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  }

  /// The offsets and depths into the output, triangles and barycentrics for interpolation.
  bool ReadBack(vtkIdType n,
    std::vector<vtkTypeUInt32>& triangles,
    std::vector<float>& barycentrics)
  {
    if (!this->Output->AllocateSamples(n))
    {
      this->Error = "cannot allocate the samples";
      return false;
    }
    triangles.resize(n);
    barycentrics.resize(2 * n);
    Download(this->Offsets,
      (this->NumberOfCells + 1) * sizeof(GLuint),
      this->Output->GetCellOffsets()->GetPointer(0));
    Download(this->Depths, n * sizeof(float), this->Output->GetDepths()->GetPointer(0));
    Download(this->Triangles, n * sizeof(GLuint), triangles.data());
    Download(this->Barycentrics, 2 * n * sizeof(float), barycentrics.data());
    if (glGetError() != GL_NO_ERROR)
    {
      this->Error = "an OpenGL error occurred";
      return false;
    }
    return true;
  }

private:
  /// Draw every triangle with `program` into the three grids' viewports.
  void Draw(GLuint program) const
  {
    const vtkIdType* dims = this->Output->GetDimensions();
    GLuint base[3];
    GLint width[3], height[3];
    for (int a = 0; a < 3; ++a)
    {
      base[a] = static_cast<GLuint>(this->Output->GetGridCellBase(a));
      width[a] = static_cast<GLint>(dims[(a + 1) % 3]);
      height[a] = static_cast<GLint>(dims[(a + 2) % 3]);
    }
    glUseProgram(program);
    glUniform1d(glGetUniformLocation(program, "viewportSize"), static_cast<double>(this->Side));
    glUniform3ui(glGetUniformLocation(program, "gridBase"), base[0], base[1], base[2]);
    glUniform3i(glGetUniformLocation(program, "gridWidth"), width[0], width[1], width[2]);
    glUniform3i(glGetUniformLocation(program, "gridHeight"), height[0], height[1], height[2]);
    glUniform1d(glGetUniformLocation(program, "cellSize"), this->Output->GetCellSize());
    glDrawElements(GL_TRIANGLES, this->NumberOfIndices, GL_UNSIGNED_INT, nullptr);
  }

  const vtkOFBSurface& Surface;
  vtkOFB* Output;
  const GLint Side;
  vtkOpenGLState* State;
  std::string& Error;
  const vtkIdType NumberOfCells;
  const GLuint Blocks;
  Resources GL;
  GLuint CountProgram = 0, FillProgram = 0, ScanPrograms[3] = { 0, 0, 0 }, SortProgram = 0;
  GLsizei NumberOfIndices = 0;
  GLuint Counts = 0, Offsets = 0, BlockSums = 0;
  GLuint Depths = 0, Triangles = 0, Barycentrics = 0;
};

/**
 * The side of the square viewports of a frame of `dims` cells: the power of two
 * at or above its longest side (window coordinates then map exactly to NDC); 0,
 * with `error` set, when the context's viewports or framebuffers are smaller.
 */
GLint ViewportSide(const vtkIdType dims[3], std::string& error)
{
  GLint maxViewport[2] = { 0, 0 }, maxWidth = 0, maxHeight = 0;
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &maxWidth);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxHeight);
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
    return 0;
  }
  return side;
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
double vtkOFBGLSampler::EstimateWorkBytes(vtkIdType points,
  vtkIdType triangles,
  double samples) const
{
  // On the host: the points in cell units (doubles), the 32-bit indices, and the
  // interleaved barycentrics read back beside the two arrays interpolation takes.
  return 24.0 * static_cast<double>(points) + 12.0 * static_cast<double>(triangles) + 8.0 * samples;
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
    return RESULT_UNAVAILABLE;
  }
  const double samples = vtkOFBSamplerBackend::EstimateSamples(surface, job.CellSize);
  const bool zeroOffsets = true; // the scan writes them from zero counts
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(
        this->EstimateBytes(surface, job.Dimensions, samples), job.MemoryLimit, job.Error) ||
    !output->SetFrame(job.Origin, job.CellSize, job.Dimensions, zeroOffsets))
  {
    return RESULT_FAILED;
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
    return RESULT_UNAVAILABLE;
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
  if (job.Sources && job.Sources->RecordSamples(n))
  {
    std::copy(triangles.begin(), triangles.end(), job.Sources->GetTriangles());
    std::copy(w1.begin(), w1.end(), job.Sources->GetW1());
    std::copy(w2.begin(), w2.end(), job.Sources->GetW2());
  }
  if (!output->BuildCellIndex() ||
    !vtkOFBSamplerBackend::InterpolateAttributes(
      surface, output, triangles.data(), w1.data(), w2.data()))
  {
    return RESULT_FAILED;
  }
  return RESULT_BUILT;
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
bool vtkOFBGLSampler::Rasterize(vtkOpenGLRenderWindow* window,
  Job& job,
  std::vector<vtkTypeUInt32>& triangles,
  std::vector<float>& barycentrics)
{
  if (!vtkOFBGLSampler::IsSupported(window, job.Error))
  {
    return false;
  }
  const GLint side = ViewportSide(job.Output->GetDimensions(), job.Error);
  if (!side)
  {
    return false;
  }
  GLBuild build(*job.Surface, job.Output, side, window->GetState(), job.Error);
  ScopedBuildState saved(window->GetState());
  if (!build.CompilePrograms() || !build.UploadGeometry() || !build.AllocateCounters())
  {
    return false;
  }
  build.CountSamples();
  const vtkIdType n = build.ScanCounts();
  const double bytes = this->EstimateBytes(*job.Surface, job.Output->GetDimensions(), n);
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(bytes, job.MemoryLimit, job.Error) ||
    !build.FillSamples(n))
  {
    return false;
  }
  build.SortCells();
  return build.ReadBack(n, triangles, barycentrics);
}
