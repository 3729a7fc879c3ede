/**
 * @class   vtkOFBPolyDataMapper
 * @brief   Render a surface with colours looked up per fragment in a vtkOFB
 *
 * vtkOFBPolyDataMapper is a vtkOpenGLPolyDataMapper that colours every fragment of its
 * input surface (port 0) from the samples of a vtkOFB (paper "Sample-based Surface
 * Coloring", sections 4.1-4.2), so that painted detail finer than the triangles shows:
 * the colour resolution is the OFB's, not the mesh's. The OFB is given with SetOFB or
 * connected to input port 1 with SetOFBConnection; it is normally built from the same
 * surface (vtkOFBSampler, vtkOFBBuilder).
 *
 * The vertex shader passes the model-coordinate position (in OFB cells) to the fragment
 * shader; the OFB lives in shader storage buffers (OpenGL 4.3). Lookup modes:
 * - Nearest (default): the closest sample in the cell under the point at depths within one
 *   cell (as vtkOFB::FindSample), in the grid most aligned with the triangle's geometric
 *   normal (computed per fragment from screen-space derivatives of the position: the normal
 *   vtkOFBSampler routes a triangle by, so the grid that holds its samples), else the next
 *   most aligned grid, else the last one, else the closest sample within
 *   InterpolationRadius in the 2x2 nearest cells of all three grids. The frame time
 *   against vtkPolyDataMapper with vertex colours is measured by
 *   Testing/Benchmarks/ofbMapperBenchmark (docs/performance.md, "Mapper history").
 * - InverseDistance: Shepard-weighted samples within sqrt(3) cells in the 3x3 cells
 *   around the point in all three grids.
 * - Mipmapped: InverseDistance on a pyramid of coarser OFBs (vtkOFBPyramid, built on
 *   demand from the input surface), the level chosen from the fragment's footprint in
 *   cells and blended between the two nearest levels.
 *
 * Colour sources: Paint (the OFB's "Colors" array) or Scalars (a named float sample
 * array mapped through the mapper's lookup table over its ScalarRange, or the table's own
 * range with UseLookupTableScalarRange). An intensity array (e.g. "LIC") can modulate
 * either. With UsePaintedNormals the OFB's "Normals" shade the surface. The colour
 * replaces the property's ambient and diffuse colours; its alpha multiplies the opacity.
 * Fragments with no sample nearby keep the property colour.
 *
 * Uploads are incremental: samples marked with vtkOFB::MarkSamplesModified after the last
 * upload are sent with glBufferSubData; a structure change (new OFB, reallocation) sends
 * everything. GetLastUploadedSampleCount() tells how many samples the last render sent.
 *
 * Without an OFB, with an empty one, or on a context without shader storage buffers, the
 * mapper renders like vtkOpenGLPolyDataMapper and warns once.
 *
 * A render is a short sequence of named steps (RenderPiece): UpdateOFBInput, CheckOFB,
 * PrepareContext, SelectArrays, CheckSurfaceInFrame, then the GPU-side steps of the private
 * helper vtkOFBShaderStorage (levels, uploads, lookup table), which owns every GPU resource
 * and what was uploaded; the shader code goes in through vtkOpenGLPolyDataMapper's
 * per-aspect hooks (ReplaceShaderColor, ReplaceShaderNormal, ReplaceShaderPositionVC).
 *
 * @sa vtkOFB vtkOFBSampler vtkOFBBuilder vtkOFBPyramid
 */

#ifndef vtkOFBPolyDataMapper_h
#define vtkOFBPolyDataMapper_h

#include "vtkOFBRenderingModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"

#include "vtkWeakPointer.h" // for WarnedOFB

#include <memory> // for std::unique_ptr
#include <set>    // for Warnings
#include <string> // for Warnings

class vtkAlgorithmOutput;
class vtkOFB;
class vtkOFBShaderStorage;
struct vtkOFBShaderStorageSelection;

class VTKOFBRENDERING_EXPORT vtkOFBPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkOFBPolyDataMapper* New();
  vtkTypeMacro(vtkOFBPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum LookupModes
  {
    Nearest = 0,
    InverseDistance = 1,
    Mipmapped = 2
  };

  enum ColorSources
  {
    Paint = 0,
    Scalars = 1
  };

  ///@{
  /**
   * The OFB that colours the surface: set directly (input port 1's data) or through a
   * pipeline connection to input port 1. Default none.
   */
  void SetOFB(vtkOFB* ofb);
  vtkOFB* GetOFB();
  void SetOFBConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /**
   * How a fragment's colour is read from the OFB: Nearest (default), InverseDistance or
   * Mipmapped.
   */
  vtkSetClampMacro(LookupMode, int, Nearest, Mipmapped);
  vtkGetMacro(LookupMode, int);
  void SetLookupModeToNearest() { this->SetLookupMode(Nearest); }
  void SetLookupModeToInverseDistance() { this->SetLookupMode(InverseDistance); }
  void SetLookupModeToMipmapped() { this->SetLookupMode(Mipmapped); }
  static const char* GetLookupModeAsString(int mode);
  ///@}

  ///@{
  /**
   * Radius of the inverse-distance lookup, in OFB cells (default sqrt(3) = 1.732, the
   * paper's bound; clamped to [0.5, 1.5 * sqrt(2)] since only the 3x3 cells around the
   * point are searched).
   */
  vtkSetClampMacro(InterpolationRadius, double, 0.5, 2.1213);
  vtkGetMacro(InterpolationRadius, double);
  ///@}

  ///@{
  /**
   * Mipmapped mode: number added to the level computed from the footprint (log2 of the
   * cells a pixel covers); positive values blur, negative sharpen. Default 0.
   */
  vtkSetMacro(MipmapBias, double);
  vtkGetMacro(MipmapBias, double);
  ///@}

  ///@{
  /**
   * Mipmapped mode: most pyramid levels, level 0 included (1..16, default 8), and the
   * coarsest resolution in cells on the longest side (default 8).
   */
  vtkSetClampMacro(MaximumNumberOfMipmapLevels, int, 1, 16);
  vtkGetMacro(MaximumNumberOfMipmapLevels, int);
  vtkSetClampMacro(MinimumMipmapResolution, int, 3, 65536);
  vtkGetMacro(MinimumMipmapResolution, int);
  ///@}

  ///@{
  /**
   * Where colours come from: Paint (default, the "Colors" sample array, RGBA bytes) or
   * Scalars (ScalarArrayName through the lookup table).
   */
  vtkSetClampMacro(ColorSource, int, Paint, Scalars);
  vtkGetMacro(ColorSource, int);
  void SetColorSourceToPaint() { this->SetColorSource(Paint); }
  void SetColorSourceToScalars() { this->SetColorSource(Scalars); }
  static const char* GetColorSourceAsString(int source);
  ///@}

  ///@{
  /**
   * Sample array mapped through the lookup table when ColorSource is Scalars (default
   * none), and its component (default 0; -1 uses the magnitude).
   */
  vtkSetStringMacro(ScalarArrayName);
  vtkGetStringMacro(ScalarArrayName);
  vtkSetClampMacro(ScalarComponent, int, -1, 63);
  vtkGetMacro(ScalarComponent, int);
  ///@}

  ///@{
  /**
   * Float sample array (e.g. "LIC", values in [0, 1]) whose value multiplies the colour
   * when IntensityModulation is on (default off, no array). The colour is scaled by
   * mix(1, intensity, IntensityWeight); IntensityWeight is in [0, 1], default 1.
   */
  vtkSetStringMacro(IntensityArrayName);
  vtkGetStringMacro(IntensityArrayName);
  vtkSetMacro(IntensityModulation, bool);
  vtkGetMacro(IntensityModulation, bool);
  vtkBooleanMacro(IntensityModulation, bool);
  vtkSetClampMacro(IntensityWeight, double, 0.0, 1.0);
  vtkGetMacro(IntensityWeight, double);
  ///@}

  ///@{
  /**
   * Shade with the OFB's "Normals" sample array instead of the surface normals (default
   * off). Needs lighting on the actor.
   */
  vtkSetMacro(UsePaintedNormals, bool);
  vtkGetMacro(UsePaintedNormals, bool);
  vtkBooleanMacro(UsePaintedNormals, bool);
  ///@}

  /**
   * Samples uploaded to the GPU by the last render (0 when nothing changed).
   */
  vtkGetMacro(LastUploadedSampleCount, vtkIdType);

  /**
   * Whether the last render coloured from the OFB (false: plain rendering).
   */
  vtkGetMacro(LastRenderUsedOFB, bool);

  /**
   * Bytes of GPU memory that the OFB buffers take.
   */
  vtkIdType GetGPUMemorySize();

  /**
   * Release the OFB buffers and the superclass's resources.
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * Render a piece: prepare and upload the OFB, then draw with the lookup shader.
   */
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

protected:
  vtkOFBPolyDataMapper();
  ~vtkOFBPolyDataMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  ///@{
  /**
   * vtkOpenGLPolyDataMapper's per-aspect shader hooks: the position in OFB cells
   * (PositionVC), the lookup and the colour it gives (Color), the painted normals (Normal).
   */
  void ReplaceShaderPositionVC(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderColor(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  ///@}
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  ///@{
  /**
   * The steps of a render. PrepareOFB runs them in order and returns whether this render
   * colours from the OFB: UpdateOFBInput (update input port 1, return its OFB),
   * CheckOFB (present, not empty), PrepareContext (the window offers what the lookup
   * needs), SelectArrays (which sample arrays the shader reads, with fallbacks),
   * CheckSurfaceInFrame (warn when the surface leaves the OFB's frame), UploadOFB (the
   * levels and what changed of them), UploadLookupTable (Scalars source only);
   * UpdateShaderKey notes a change of the shader's variant.
   */
  bool PrepareOFB(vtkRenderer* ren);
  vtkOFB* UpdateOFBInput();
  bool CheckOFB(vtkOFB* ofb);
  bool PrepareContext(vtkRenderer* ren);
  bool SelectArrays(vtkOFB* ofb, vtkOFBShaderStorageSelection& selection);
  void CheckSurfaceInFrame(vtkOFB* ofb);
  bool UploadOFB(vtkOFB* ofb, const vtkOFBShaderStorageSelection& selection);
  void UploadLookupTable();
  void UpdateShaderKey();
  ///@}

  /**
   * Set "ofbNormalMatrix" (model to view normals) on `program`.
   */
  void SetNormalMatrix(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act);

  /**
   * Warn once per distinct message, until the OFB or a setting changes.
   */
  void WarnOnce(const std::string& message);

  int LookupMode;
  double InterpolationRadius;
  double MipmapBias;
  int MaximumNumberOfMipmapLevels;
  int MinimumMipmapResolution;
  int ColorSource;
  char* ScalarArrayName;
  int ScalarComponent;
  char* IntensityArrayName;
  bool IntensityModulation;
  double IntensityWeight;
  bool UsePaintedNormals;

  vtkIdType LastUploadedSampleCount;
  bool LastRenderUsedOFB;

  // Resolved per render: what the shader needs.
  bool OFBActive;
  bool SourceScalars;
  bool UseIntensity;
  bool UseNormals;
  bool DeepCells;
  std::string ShaderKey;
  vtkTimeStamp ShaderKeyTime;

  // The GPU state and what was uploaded.
  std::unique_ptr<vtkOFBShaderStorage> Storage;

  std::set<std::string> Warnings;
  vtkWeakPointer<vtkOFB> WarnedOFB;
  vtkMTimeType WarnedMTime;

private:
  vtkOFBPolyDataMapper(const vtkOFBPolyDataMapper&) = delete;
  void operator=(const vtkOFBPolyDataMapper&) = delete;
};

#endif
