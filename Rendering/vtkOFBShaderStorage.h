/**
 * @class   vtkOFBShaderStorage
 * @brief   Shader storage buffers holding vtkOFB levels for vtkOFBPolyDataMapper (private)
 *
 * Owns the OpenGL shader storage buffer objects (SSBOs) that the lookup fragment shader
 * (shaders/vtkOFBLookupFS.glsl) reads: the cell offsets of every level, the samples (two
 * 32-bit words per sample: the depth, in cells of its level, and the colour attribute next
 * to it, either the paint colour as packed RGBA8 or a scalar as a float, so that one read
 * gives both and they share a cache line), and optional per-sample arrays (intensity as
 * floats, normals as three floats). Each buffer holds the levels one after the other.
 * Uploads are whole (structure change) or partial (glBufferSubData of modified sample
 * ranges). Buffers are bound to fixed binding points only around a draw and unbound
 * afterwards. All calls need the owning window's context current.
 */

#ifndef vtkOFBShaderStorage_h
#define vtkOFBShaderStorage_h

#include "vtkType.h"

#include <string>
#include <vector>

class vtkDataArray;
class vtkIdTypeArray;
class vtkOFB;
class vtkOpenGLRenderWindow;
class vtkScalarsToColors;
class vtkShaderProgram;

class vtkOFBShaderStorage
{
public:
  enum BufferId
  {
    Offsets = 0,
    Samples,
    Intensity,
    Normals,
    LUT,
    NumberOfBuffers
  };

  /// The colour attributes that GetArray resolves besides Intensity and Normals: one of them
  /// is the second word of every sample in the Samples buffer.
  enum AttributeId
  {
    Colors = NumberOfBuffers,
    Scalars
  };

  /// Most levels a storage holds (size of the shader's per-level uniform arrays).
  static constexpr int MaximumNumberOfLevels = 16;

  /// Entries of the lookup-table buffer.
  static constexpr int LUTSize = 1024;

  /**
   * Which sample arrays to upload. Null names leave the buffer out.
   */
  struct Selection
  {
    bool Colors = true;
    std::string ScalarName;
    int ScalarComponent = 0; // -1: magnitude
    std::string IntensityName;
    bool Normals = false;
    bool operator==(const Selection& o) const
    {
      return this->Colors == o.Colors && this->ScalarName == o.ScalarName &&
        this->ScalarComponent == o.ScalarComponent && this->IntensityName == o.IntensityName &&
        this->Normals == o.Normals;
    }
  };

  vtkOFBShaderStorage();
  ~vtkOFBShaderStorage();

  /**
   * Whether `window` offers shader storage buffers in fragment shaders (OpenGL 4.3 or
   * ARB_shader_storage_buffer_object, enough fragment storage blocks) and float bit casts
   * in shaders (OpenGL 3.3 or ARB_shader_bit_encoding). Makes the context current. `why`
   * says what is missing.
   */
  static bool IsSupported(vtkOpenGLRenderWindow* window, std::string& why);

  /// Window whose context holds the buffers (null when none).
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }
  void SetWindow(vtkOpenGLRenderWindow* window) { this->Window = window; }

  /**
   * Upload the structure (offsets, depths) and the selected arrays of every level.
   * With selection.Colors the samples carry the paint colours, else the scalars named by
   * selection.ScalarName.
   * Returns the number of samples uploaded, or -1 on failure (`error` says why).
   */
  vtkIdType UploadAll(const std::vector<vtkOFB*>& levels, const Selection& selection,
    std::string& error);

  /**
   * Upload the selected arrays of level `level` over the sample ranges `ranges`
   * (2 components: first, last) only. Returns the number of samples uploaded.
   */
  vtkIdType UploadRanges(
    const std::vector<vtkOFB*>& levels, int level, const Selection& selection,
    vtkIdTypeArray* ranges);

  /**
   * Sample `lut` at LUTSize equal steps over [range[0], range[1]] into the LUT buffer.
   */
  void UploadLookupTable(vtkScalarsToColors* lut, const double range[2]);

  /// Bind the allocated buffers to their binding points; Unbind puts 0 back there.
  void Bind();
  void Unbind();

  /// Connect the storage blocks of `program` to the binding points (once per program).
  void SetBlockBindings(vtkShaderProgram* program);

  /// Per-level layout for the shader's uniforms.
  int GetNumberOfLevels() const { return static_cast<int>(this->LevelSampleBase.size()); }
  const std::vector<int>& GetLevelCellBase() const { return this->LevelCellBase; }
  const std::vector<int>& GetLevelSampleBase() const { return this->LevelSampleBase; }
  const std::vector<int>& GetLevelDims() const { return this->LevelDims; }

  /// The most samples in one cell over the uploaded levels (their depth complexity).
  int GetMaximumCellSamples() const { return this->MaximumCellSamples; }

  /// Bytes of GPU memory held.
  size_t GetMemorySize() const;

  /// Free the buffers (needs the context current, or no context at all).
  void ReleaseGraphicsResources();

  /// Name of the shader storage block of a buffer, and its binding point.
  static const char* GetBlockName(int id);
  static unsigned int GetBindingPoint(int id);

  /// The array of `ofb` that an attribute (Colors, Scalars) or a buffer (Intensity, Normals)
  /// reads under `selection` (null if missing or unusable).
  static vtkDataArray* GetArray(vtkOFB* ofb, int id, const Selection& selection);

private:
  vtkOFBShaderStorage(const vtkOFBShaderStorage&) = delete;
  void operator=(const vtkOFBShaderStorage&) = delete;

  bool Allocate(int id, size_t bytes);
  void Upload(int id, size_t offset, size_t bytes, const void* data);
  void UploadArray(int id, vtkDataArray* array, vtkIdType first, vtkIdType last, vtkIdType base);
  void UploadSamples(vtkOFB* ofb, vtkDataArray* attribute, const Selection& selection,
    vtkIdType first, vtkIdType last, vtkIdType base);

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned int Handles[NumberOfBuffers];
  size_t Sizes[NumberOfBuffers];
  std::vector<int> LevelCellBase;   // 3 per level: first offsets entry of grid a
  std::vector<int> LevelSampleBase; // 1 per level
  std::vector<int> LevelDims;       // 3 per level
  int MaximumCellSamples = 0;
  std::vector<unsigned char> Scratch;
};

#endif
