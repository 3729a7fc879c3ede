#include "vtkOFBGLSampler.h"
#include "vtkOFBGLSamplerInternals.h"

#include "vtkAlgorithm.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBSampleSources.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkTypeUInt32Array.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>
#include <sstream>

namespace
{
using namespace vtkofbgl;

constexpr GLuint BlockSize = 2048;  // counts per scan block (256 invocations x 8)
constexpr GLuint MaxGroups = 65535; // work groups per dispatch (the GL minimum)

/// Owns the buffers, vertex array and framebuffer of one build and deletes them,
/// whatever the way out.
class Resources
{
public:
  ~Resources()
  {
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
    for (GLuint binding = 0; binding < 7; ++binding)
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
    const GLuint* programs,
    std::string& error)
    : Programs(programs)
    , Surface(surface)
    , Output(output)
    , Side(side)
    , State(state)
    , Error(error)
    , NumberOfCells(output->GetNumberOfCells())
    , Blocks(static_cast<GLuint>((this->NumberOfCells + BlockSize - 1) / BlockSize))
  {
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
    for (GLuint program : { this->Programs[COUNT_PROGRAM], this->Programs[FILL_PROGRAM] })
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
    this->Draw(this->Programs[COUNT_PROGRAM]);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  /// Pass 2: the counts scanned into cell offsets (by block, the block sums, then
  /// the blocks again); the number of samples.
  vtkIdType ScanCounts()
  {
    const auto nCells = static_cast<GLuint>(this->NumberOfCells);
    const GLuint* scan = this->Programs + SCAN_PROGRAM;
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
    this->W1 = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, n * sizeof(float));
    this->W2 = this->GL.Buffer(GL_SHADER_STORAGE_BUFFER, n * sizeof(float));
    if (!this->Depths || !this->Triangles || !this->W1 || !this->W2)
    {
      this->Error = "cannot allocate the samples on the GPU";
      return false;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->Depths);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, this->Triangles);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, this->W1);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, this->W2);
    glBindVertexArray(this->GL.VAO);
    this->Draw(this->Programs[FILL_PROGRAM]);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return true;
  }

  /// Pass 4: the samples of each cell sorted by (depth, triangle).
  void SortCells()
  {
    const auto nCells = static_cast<GLuint>(this->NumberOfCells);
    glUseProgram(this->Programs[SORT_PROGRAM]);
    SetUniform(this->Programs[SORT_PROGRAM], "numberOfCells", nCells);
    Dispatch(this->Programs[SORT_PROGRAM], "firstCell", (nCells + 255) / 256, 256);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  }

  /// The offsets and depths into the output, triangles and weights for interpolation.
  bool ReadBack(vtkIdType n, vtkTypeUInt32* triangles, float* w1, float* w2)
  {
    if (!this->Output->AllocateSamples(n))
    {
      this->Error = "cannot allocate the samples";
      return false;
    }
    Download(this->Offsets,
      (this->NumberOfCells + 1) * sizeof(GLuint),
      this->Output->GetCellOffsets()->GetPointer(0));
    Download(this->Depths, n * sizeof(float), this->Output->GetDepths()->GetPointer(0));
    Download(this->Triangles, n * sizeof(GLuint), triangles);
    Download(this->W1, n * sizeof(float), w1);
    Download(this->W2, n * sizeof(float), w2);
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

  const GLuint* Programs; // NumberOfPrograms, compiled
  const vtkOFBSurface& Surface;
  vtkOFB* Output;
  const GLint Side;
  vtkOpenGLState* State;
  std::string& Error;
  const vtkIdType NumberOfCells;
  const GLuint Blocks;
  Resources GL;
  GLsizei NumberOfIndices = 0;
  GLuint Counts = 0, Offsets = 0, BlockSums = 0;
  GLuint Depths = 0, Triangles = 0, W1 = 0, W2 = 0;
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

struct vtkOFBGLSampler::Readback
{
  /// Points the arrays at the job's sample sources when it records them, else at
  /// arrays of its own (left uninitialised: the read-back fills them in parallel).
  bool Allocate(vtkIdType n, vtkOFBSampleSources* sources)
  {
    if (sources && sources->RecordSamples(n))
    {
      this->Triangles = sources->GetTriangles();
      this->W1 = sources->GetW1();
      this->W2 = sources->GetW2();
      return true;
    }
    try
    {
      this->OwnTriangles.reset(new vtkTypeUInt32[static_cast<size_t>(n)]);
      this->OwnW1.reset(new float[static_cast<size_t>(n)]);
      this->OwnW2.reset(new float[static_cast<size_t>(n)]);
    }
    catch (const std::bad_alloc&)
    {
      return false;
    }
    this->Triangles = this->OwnTriangles.get();
    this->W1 = this->OwnW1.get();
    this->W2 = this->OwnW2.get();
    return true;
  }

  std::unique_ptr<vtkTypeUInt32[]> OwnTriangles;
  std::unique_ptr<float[]> OwnW1, OwnW2;
  vtkTypeUInt32* Triangles = nullptr;
  float* W1 = nullptr;
  float* W2 = nullptr;
};

/// The build programs of the last context, kept between builds: compiling them
/// took 5 to 50 ms a build on an NVIDIA driver.
struct vtkOFBGLSampler::ProgramCache
{
  /// Whether Ids hold the programs of `window`'s current context, compiling them
  /// if not (the context is current). Programs of another window's context stay
  /// with that context and go with it.
  bool Ready(vtkOpenGLRenderWindow* window, std::string& error)
  {
    if (this->Window == window && this->ContextTime == window->GetContextCreationTime() &&
      this->Ids[SORT_PROGRAM] != 0)
    {
      return true;
    }
    std::fill(this->Ids, this->Ids + NumberOfPrograms, 0u);
    this->Window = window;
    this->ContextTime = window->GetContextCreationTime();
    return CompileBuildPrograms(this->Ids, error);
  }

  /// Deletes the programs in their context while its window lives.
  void Release()
  {
    if (this->Window && this->Ids[SORT_PROGRAM] != 0 &&
      this->ContextTime == this->Window->GetContextCreationTime())
    {
      this->Window->MakeCurrent();
      for (GLuint& program : this->Ids)
      {
        glDeleteProgram(program);
        program = 0;
      }
    }
  }

  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkMTimeType ContextTime = 0;
  GLuint Ids[NumberOfPrograms] = {};
};

//------------------------------------------------------------------------------
vtkOFBGLSampler::vtkOFBGLSampler()
  : Programs(new ProgramCache)
{
}

//------------------------------------------------------------------------------
vtkOFBGLSampler::~vtkOFBGLSampler()
{
  this->Programs->Release();
}

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
  Readback readback;
  this->LastPhaseTimes.clear();
  this->PhaseStart = vtkTimerLog::GetUniversalTime();
  window->PushContext();
  const bool rasterized = this->Rasterize(window, job, readback);
  window->PopContext();
  if (!rasterized)
  {
    return RESULT_UNAVAILABLE;
  }
  if (job.Algorithm)
  {
    job.Algorithm->UpdateProgress(0.7);
  }
  if (!output->BuildCellIndex())
  {
    return RESULT_FAILED;
  }
  this->EndPhase("cell index", false);
  if (!vtkOFBSamplerBackend::InterpolateAttributes(
        surface, output, readback.Triangles, readback.W1, readback.W2))
  {
    return RESULT_FAILED;
  }
  this->EndPhase("interpolate", false);
  return RESULT_BUILT;
}

//------------------------------------------------------------------------------
void vtkOFBGLSampler::EndPhase(const char* name, bool gpu)
{
  if (!this->MeasurePhases)
  {
    return;
  }
  if (gpu)
  {
    glFinish();
  }
  const double now = vtkTimerLog::GetUniversalTime();
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(1);
  os << (this->LastPhaseTimes.empty() ? "" : ", ") << name << " "
     << 1000.0 * (now - this->PhaseStart);
  this->LastPhaseTimes += os.str();
  this->PhaseStart = now;
}

//------------------------------------------------------------------------------
void vtkOFBGLSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderWindow: " << this->RenderWindow.GetPointer() << "\n";
  os << indent << "MeasurePhases: " << this->MeasurePhases << "\n";
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
bool vtkOFBGLSampler::Rasterize(vtkOpenGLRenderWindow* window, Job& job, Readback& readback)
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
  ScopedBuildState saved(window->GetState());
  if (!this->Programs->Ready(window, job.Error))
  {
    return false;
  }
  this->EndPhase("compile", true);
  GLBuild build(*job.Surface, job.Output, side, window->GetState(), this->Programs->Ids, job.Error);
  if (!build.UploadGeometry() || !build.AllocateCounters())
  {
    return false;
  }
  this->EndPhase("upload", true);
  build.CountSamples();
  this->EndPhase("count", true);
  const vtkIdType n = build.ScanCounts();
  this->EndPhase("scan", true);
  const double bytes = this->EstimateBytes(*job.Surface, job.Output->GetDimensions(), n);
  if (!vtkOFBSamplerBackend::CheckMemoryLimit(bytes, job.MemoryLimit, job.Error) ||
    !build.FillSamples(n))
  {
    return false;
  }
  this->EndPhase("fill", true);
  build.SortCells();
  this->EndPhase("sort", true);
  if (!readback.Allocate(n, job.Sources))
  {
    job.Error = "cannot allocate the samples' triangles and weights";
    return false;
  }
  const bool read = build.ReadBack(n, readback.Triangles, readback.W1, readback.W2);
  this->EndPhase("read back", true);
  return read;
}
