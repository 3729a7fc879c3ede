/**
 * @class   vtkOFBShaderStorage
 * @brief   Shader storage buffers holding vtkOFB levels for vtkOFBPolyDataMapper (private)
 *
 * Owns the OpenGL shader storage buffer objects (SSBOs) that the lookup fragment shader
 * (shaders/vtkOFBLookupFS.glsl) reads: cell offsets and depths of every level (the
 * structure), and per-sample arrays (paint colours as packed RGBA8, scalars, intensity and
 * normals as floats), each buffer holding the levels one after the other. Uploads
 * are whole (structure change) or partial (glBufferSubData of modified sample ranges of
 * level 0). Buffers are bound to fixed binding points only around a draw and unbound
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
    Depths,
    Colors,
    Scalars,
    Intensity,
    Normals,
    LUT,
    NumberOfBuffers
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
   * ARB_shader_storage_buffer_object, enough fragment storage blocks). Makes the context
   * current. `why` says what is missing.
   */
  static bool IsSupported(vtkOpenGLRenderWindow* window, std::string& why);

  /// Window whose context holds the buffers (null when none).
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }
  void SetWindow(vtkOpenGLRenderWindow* window) { this->Window = window; }

  /**
   * Upload the structure (offsets, depths) and the selected arrays of every level.
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

  /// Bytes of GPU memory held.
  size_t GetMemorySize() const;

  /// Free the buffers (needs the context current, or no context at all).
  void ReleaseGraphicsResources();

  /// Name of the shader storage block of a buffer, and its binding point.
  static const char* GetBlockName(int id);
  static unsigned int GetBindingPoint(int id);

  /// The array of `ofb` that a buffer reads under `selection` (null if missing or unusable).
  static vtkDataArray* GetArray(vtkOFB* ofb, int id, const Selection& selection);

private:
  vtkOFBShaderStorage(const vtkOFBShaderStorage&) = delete;
  void operator=(const vtkOFBShaderStorage&) = delete;

  bool Allocate(int id, size_t bytes);
  void Upload(int id, size_t offset, size_t bytes, const void* data);
  void UploadArray(int id, vtkDataArray* array, const Selection& selection, vtkIdType first,
    vtkIdType last, vtkIdType base);

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned int Handles[NumberOfBuffers];
  size_t Sizes[NumberOfBuffers];
  std::vector<int> LevelCellBase;   // 3 per level: first offsets entry of grid a
  std::vector<int> LevelSampleBase; // 1 per level
  std::vector<int> LevelDims;       // 3 per level
  std::vector<unsigned char> Scratch;
};

#endif
