/**
 * @class   vtkOFBShaderStorage
 * @brief   The GPU side of vtkOFBPolyDataMapper: vtkOFB levels in shader storage (private)
 *
 * The helper object that owns the mapper's GPU state and its per-render upload state, as
 * vtkSurfaceLICInterface does for vtkSurfaceLICMapper; the mapper calls its named steps once
 * per render: SetContext (the window, checked once), UpdateLevels (the OFB and, when
 * mipmapped, its pyramid), UploadChanges (everything on a structure or selection change,
 * else the modified sample ranges), UpdateLookupTable, then Bind / SetUniforms / Unbind
 * around the draw.
 *
 * Owns the OpenGL shader storage buffer objects (SSBOs) that the lookup fragment shader
 * (shaders/vtkOFBLookupFS.glsl) reads: the cell offsets of every level, the samples (two
 * 32-bit words per sample: the depth, in cells of its level, and the colour attribute next
 * to it, either the paint colour as packed RGBA8 or a scalar as a float, so that one read
 * gives both and they share a cache line), and optional per-sample arrays (intensity as
 * a byte, normals as three floats, and of level 0 alone the direction of a vector field,
 * the flow a LIC follows, as three 10-bit signed components of its unit vector in a word).
 * Each buffer holds the levels one after the other.
 * Uploads are whole (structure change) or partial (glBufferSubData of modified sample
 * ranges). Buffers are bound to fixed binding points only around a draw and unbound
 * afterwards. All calls need the owning window's context current.
 */

#ifndef vtkOFBShaderStorage_h
#define vtkOFBShaderStorage_h

#include "vtkNew.h"          // for vtkNew
#include "vtkOFBPyramid.h"   // for Pyramid
#include "vtkSmartPointer.h" // for Pyramid
#include "vtkTimeStamp.h"    // for UploadTime
#include "vtkType.h"         // for vtkIdType
#include "vtkWeakPointer.h"  // for vtkWeakPointer

#include <string> // for Selection
#include <vector> // for levels

class vtkDataArray;
class vtkIdTypeArray;
class vtkOFB;
class vtkOpenGLRenderWindow;
class vtkPointData;
class vtkPolyData;
class vtkScalarsToColors;
class vtkShaderProgram;
class vtkWindow;

/**
 * Which sample arrays vtkOFBShaderStorage uploads. Empty names leave the buffer out.
 */
struct vtkOFBShaderStorageSelection
{
  bool Colors = true;        // the paint colours, else the scalars of ScalarName
  std::string ScalarName;    // colour attribute when not Colors
  int ScalarComponent = 0;   // -1: magnitude
  std::string IntensityName; // the Intensity buffer's array
  bool Normals = false;      // the Normals buffer
  std::string FlowName;      // the Flow buffer's array (3 components, level 0 only)
};

class vtkOFBShaderStorage
{
public:
  enum BufferId
  {
    BUFFER_OFFSETS = 0,
    BUFFER_SAMPLES,
    BUFFER_INTENSITY,
    BUFFER_NORMALS,
    BUFFER_FLOW,
    BUFFER_LUT,
    NUMBER_OF_BUFFERS
  };

  /// The colour attributes that GetArray resolves besides Intensity and Normals: one of them
  /// is the second word of every sample in the Samples buffer.
  enum AttributeId
  {
    ATTRIBUTE_COLORS = NUMBER_OF_BUFFERS,
    ATTRIBUTE_SCALARS
  };

  /// Bit masks of the per-sample buffers that hold attributes (UploadRanges).
  static constexpr unsigned int AllArrays = (1u << BUFFER_SAMPLES) | (1u << BUFFER_INTENSITY) |
    (1u << BUFFER_NORMALS) | (1u << BUFFER_FLOW);

  /// Most levels a storage holds (size of the shader's per-level uniform arrays).
  static constexpr int MaximumNumberOfLevels = 16;

  /// Entries of the lookup-table buffer.
  static constexpr int LUTSize = 1024;

  /// Which sample arrays to upload (vtkOFBShaderStorageSelection).
  using Selection = vtkOFBShaderStorageSelection;

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

  ///@{
  /**
   * The per-render steps of vtkOFBPolyDataMapper, in order.
   *
   * SetContext: use `window` (whether it is supported is checked once per window; `why`
   * says what it lacks); the buffers of another window are released in that window's
   * context first.
   *
   * UpdateLevels: level 0 is `ofb`; with `mipmapped` the coarser levels come from a
   * pyramid built on demand from `ofb` and `surface` (at most `maximumLevels` levels, the
   * coarsest with `minimumResolution` cells on its longest side). Returns false when the
   * pyramid could not be built (level 0 alone is used then).
   *
   * UploadChanges: upload every level on a structure or selection change; else, of level 0,
   * each selected array that is new or was Modified() since the last upload as a whole
   * (a re-convolved LIC array alone), then the sample ranges marked modified since
   * (vtkOFB::MarkSamplesModified) of the other arrays (and the pyramid's levels when
   * their attributes were filtered again). Returns the number of samples sent, -1 on failure
   * (`error` says why).
   *
   * UpdateLookupTable: sample `lut` over `range` into the LUT buffer when either changed.
   */
  bool SetContext(vtkOpenGLRenderWindow* window, std::string& why);
  bool UpdateLevels(vtkOFB* ofb,
    vtkPolyData* surface,
    bool mipmapped,
    int maximumLevels,
    int minimumResolution);
  vtkIdType UploadChanges(const Selection& selection, std::string& error);
  void UpdateLookupTable(vtkScalarsToColors* lut, const double range[2]);
  ///@}

  ///@{
  /**
   * The pyramid that UpdateLevels builds the coarser levels with (a vtkOFBPyramid of its
   * own by default; null restores one). SetPyramid returns whether it changed.
   */
  bool SetPyramid(vtkOFBPyramid* pyramid);
  vtkOFBPyramid* GetPyramid() const { return this->Pyramid; }
  ///@}

  /// The OFB whose samples the buffers hold (null when none).
  vtkOFB* GetUploadedOFB() const { return this->UploadedOFB; }

  /**
   * Set the uniforms that describe the uploaded levels (and, with `scalars`, the lookup
   * table's range) on `program`, and connect its storage blocks to the binding points.
   */
  void SetUniforms(vtkShaderProgram* program, bool scalars);

  /**
   * Upload the structure (offsets, depths) and the selected arrays of every level.
   * With selection.Colors the samples carry the paint colours, else the scalars named by
   * selection.ScalarName.
   * Returns the number of samples uploaded, or -1 on failure (`error` says why).
   */
  vtkIdType UploadAll(const std::vector<vtkOFB*>& levels,
    const Selection& selection,
    std::string& error);

  /**
   * Upload the selected arrays of level `level` over the sample ranges `ranges`
   * (2 components: first, last) only. Returns the number of samples uploaded.
   */
  vtkIdType UploadRanges(const std::vector<vtkOFB*>& levels,
    int level,
    const Selection& selection,
    vtkIdTypeArray* ranges,
    unsigned int buffers = AllArrays);

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

  /// Bytes sent to the GPU since the storage was created.
  size_t GetUploadedBytes() const { return this->UploadedBytes; }

  /**
   * Free the buffers in their window's context and forget what was uploaded, when
   * `window` is that window or null.
   */
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Name of the shader storage block of a buffer, and its binding point.
  static const char* GetBlockName(int id);
  static unsigned int GetBindingPoint(int id);

  /// The array of `ofb` that an attribute (Colors, Scalars) or a buffer (Intensity, Normals)
  /// reads under `selection` (null if missing or unusable, shorter than the samples included).
  static vtkDataArray* GetArray(vtkOFB* ofb, int id, const Selection& selection);

private:
  /// GetArray's choice among the sample arrays `pd`, before the length check.
  static vtkDataArray* FindArray(vtkPointData* pd, int id, const Selection& selection);

  vtkOFBShaderStorage(const vtkOFBShaderStorage&) = delete;
  void operator=(const vtkOFBShaderStorage&) = delete;

  /// Deletes the buffers in Window's context (which must be current); without a Window
  /// (gone, and its context with it) only forgets their names.
  void FreeBuffers();
  void ForgetUploads();
  vtkIdType UploadCoarseLevels(const Selection& selection, unsigned int whole);
  unsigned int UploadChangedArrays(const Selection& selection, vtkIdType& count);
  void RecordArrays(const Selection& selection);
  bool Allocate(int id, size_t bytes);
  void Upload(int id, size_t offset, size_t bytes, const void* data);
  void UploadArray(int id, vtkDataArray* array, vtkIdType first, vtkIdType last, vtkIdType base);
  void UploadIntensity(vtkDataArray* array, vtkIdType first, vtkIdType last, vtkIdType base);
  void UploadFlow(vtkDataArray* array, vtkIdType first, vtkIdType last);
  void UploadSamples(vtkOFB* ofb,
    vtkDataArray* attribute,
    const Selection& selection,
    vtkIdType first,
    vtkIdType last,
    vtkIdType base);

  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkWeakPointer<vtkOpenGLRenderWindow> CheckedWindow;
  bool CheckedWindowSupported = false;
  std::string CheckedWindowReason;

  // The levels of this render, and what the buffers hold.
  vtkSmartPointer<vtkOFBPyramid> Pyramid;
  bool OwnPyramid = true; // Pyramid is the storage's own
  std::vector<vtkOFB*> Levels;
  vtkNew<vtkIdTypeArray> Ranges;
  vtkTimeStamp UploadTime;
  std::string UploadKey;
  vtkWeakPointer<vtkOFB> UploadedOFB;
  vtkMTimeType UploadedPyramidTime = 0;
  vtkWeakPointer<vtkScalarsToColors> UploadedLUT; // another table (a colouring swapped) uploads
  vtkMTimeType UploadedLUTTime = 0;
  double UploadedLUTRange[2] = { 0.0, 0.0 };
  size_t UploadedBytes = 0;
  vtkWeakPointer<vtkDataArray> UploadedArrays[NUMBER_OF_BUFFERS]; // level 0's, per buffer

  unsigned int Handles[NUMBER_OF_BUFFERS];
  size_t Sizes[NUMBER_OF_BUFFERS];
  std::vector<int> LevelCellBase;   // 3 per level: first offsets entry of grid a
  std::vector<int> LevelSampleBase; // 1 per level
  std::vector<int> LevelDims;       // 3 per level
  int MaximumCellSamples = 0;
  std::vector<unsigned char> Scratch;
};

#endif
