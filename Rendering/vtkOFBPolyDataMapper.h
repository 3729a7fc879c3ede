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
 * - Nearest: the closest sample in the cell under the point at depths within one
 *   cell (as vtkOFB::FindSample), in the grid most aligned with the triangle's geometric
 *   normal (computed per fragment from screen-space derivatives of the position: the normal
 *   vtkOFBSampler routes a triangle by, so the grid that holds its samples), else the next
 *   most aligned grid, else the last one, else the closest sample within
 *   InterpolationRadius in the 2x2 nearest cells of all three grids. The cheapest mode;
 *   Testing/Benchmarks/ofbMapperBenchmark compares every mode's frame time with
 *   vtkPolyDataMapper's (docs/benchmarks.md).
 * - InverseDistance: Shepard-weighted samples within sqrt(3) cells in the 3x3 cells
 *   around the point in all three grids.
 * - Mipmapped: InverseDistance on a pyramid of coarser OFBs (vtkOFBPyramid, built on
 *   demand from the input surface), the level chosen from the fragment's footprint in
 *   cells and blended between the two nearest levels.
 * - NearestMipmapped: Nearest on the same pyramid, in the one level whose cells are
 *   nearest to the fragment's footprint (round(log2(cells per pixel) + MipmapBias), as
 *   GL_NEAREST_MIPMAP_NEAREST for a texture): detail finer than a pixel (a LIC or paint of
 *   a high-resolution OFB seen whole) shows its filtered mean instead of aliasing, and the
 *   lookup reads a level about as fine as the screen, which keeps it in the cache (the
 *   lookup to use for a fine OFB seen whole). Where the footprint is under 1.41 cells
 *   (close-ups) it reads level 0 as Nearest does. The pyramid's arrays are filtered
 *   again whenever the OFB's arrays change: a modified array alone (an animated LIC costs
 *   its filtering down the pyramid), or, for values changed in place and marked with
 *   vtkOFB::MarkSamplesModified (painting), only the coarse samples that read them, and
 *   only those are uploaded (vtkOFBPyramid::UpdateModifiedArrays).
 *
 * - Smooth: interpolation along the surface where a level-0 cell covers a pixel or more,
 *   and the two pyramid levels around the footprint blended where cells are smaller than
 *   pixels (the blend of Mipmapped, so no line where the level changes). In each level and
 *   each of the three grids, the samples of the 2x2 cells nearest to the point are weighted
 *   by the tents of their in-plane offsets (bilinear where the surface lies in one grid's
 *   region) and by their agreement with the fragment's tangent plane (full within half a
 *   cell of it, none from one cell: the other side of a thin sheet does not bleed through).
 *   The weights are continuous, so the colour is continuous across cell borders and grid
 *   changes: close-ups show no cell blocks. Close up, a LIC is also averaged along its flow
 *   (FlowAlignedFiltering), which removes the beads that bilinear interpolation makes of
 *   streaks at an angle to the grid. The lookup to use for a LIC (with a
 *   vtkOFBLICPyramid from OFB::FlowPaths as the pyramid, SetPyramid, streaks stay at every
 *   zoom instead of fading to grey). Where the pyramid computes the intensity on every
 *   level (vtkOFBPyramid::IsComputedArray), the levels are independent textures, whose
 *   plain mix would lose contrast half-way between levels (a band of weaker streaks); the
 *   blended intensity is then m + (mix - m) / sqrt((1 - t)^2 + t^2), with m the mean of
 *   level 0's intensity (over every process's owned samples where the pyramid gives it:
 *   vtkOFBPyramid::GetSharedMean) and t the blend weight, which keeps the variance of the
 *   mix.
 * - Automatic (default): Smooth where the colouring modulates by an intensity array that
 *   the OFB has (a LIC: no cell blocks close up), else Nearest (paint: the cheapest, and
 *   crisp brush edges). It builds the pyramid only when it resolves to Smooth. With
 *   AutomaticLevelLIC (default on), an OFB connected straight from a vtkOFBLIC gets a
 *   vtkOFBLICPyramid of it, so a LIC keeps its streaks from far without any setting.
 *
 * The colouring is a vtkOFBColoring (GetColoring(), one made by default), the object
 * vtkOFBMapToColors reads too: share it, `mapToColors->SetColoring(mapper->GetColoring())`,
 * and the export holds what is shown. Colour sources: paint (the OFB's "Colors" array) or
 * scalars (a named float sample array mapped through the colouring's lookup table over
 * its ScalarRange, or the table's own range with UseLookupTableScalarRange; vtkMapper's
 * own LookupTable and ScalarRange play no part in the OFB colours). A LIC array
 * (IntensityArrayName, e.g. vtkOFBLIC's "LIC", values L in [0, 1]) combines with either,
 * per fragment, as in VTK's surface LIC (c: the colour of the source, alpha kept):
 * - COLOR_MODE_BLEND (default): c' = L * LICIntensity + c * (1 - LICIntensity); with
 *   LICIntensity 1 the LIC shows alone.
 * - COLOR_MODE_MAP: c' = c * mix(1, clamp(L + MapModeBias, 0, 1), IntensityWeight); with
 *   IntensityWeight 1 (default) VTK 9.1's shader formula (it multiplies the RGB colour).
 * The combined colour is then lit as the surface colour (VTK's image-space LIC combines
 * with the lit colour; with lighting off, or ambient 1 and diffuse 0, both agree).
 * An array that is new or Modified() since the last render (a re-convolution with another
 * AnimationPhase) is uploaded alone, whole; vtkOFB::MarkSamplesModified ranges upload
 * the selected arrays over those ranges.
 *
 * A change of the colouring (shared or not) is a change of the mapper (GetMTime includes
 * it): the next render uses it.
 *
 * Settings of vtkSurfaceLICInterface and where they are here (vtkOFBColoring: the
 * mapper's GetColoring()):
 * | vtkSurfaceLICInterface            | vtkOFB                                             |
 * |-----------------------------------|----------------------------------------------------|
 * | Enable                            | IntensityModulation (vtkOFBColoring)               |
 * | ColorMode (COLOR_MODE_BLEND/MAP)  | LICColorMode (COLOR_MODE_BLEND/MAP), same formulas |
 * | LICIntensity (0.8)                | LICIntensity (0.8), same meaning                   |
 * | MapModeBias (0)                   | MapModeBias (0), same meaning                      |
 * | (none)                            | IntensityWeight (1): strength of MAP               |
 * | scalar colouring of the mapper    | ColorSource Scalars + lookup table, or Paint       |
 * | NumberOfSteps, StepSize           | vtkOFBLIC (StepSize in cells, not pixels)          |
 * | NormalizeVectors                  | vtkOFBLIC                                          |
 * | EnhancedLIC, EnhanceContrast (LIC)| vtkOFBLIC                                          |
 * | Low/HighLICContrastEnhancement... | vtkOFBLIC                                          |
 * | MaskOnSurface, MaskThreshold,     | vtkOFBLIC (masking is computed with the LIC)       |
 * |   MaskColor, MaskIntensity        |                                                    |
 * | noise (GenerateNoiseTexture, ...) | vtkOFBLIC                                          |
 * | EnhanceContrast COLOR/BOTH,       | EnhanceColorContrast (vtkOFBColoring), same names  |
 * |   Low/HighColorContrastEnh...     |   and formula; the range over the OFB's samples    |
 * | AntiAlias                         | not needed: the LIC lives on the surface; the      |
 * |                                   |   InverseDistance and mipmapped lookups filter it  |
 * | CompositeStrategy                 | not applicable (no image-space compositing)        |
 *
 * With UsePaintedNormals the OFB's "Normals" shade the surface. The colour replaces the
 * property's ambient and diffuse colours; its alpha multiplies the opacity. Fragments with
 * no sample nearby keep the property colour.
 *
 * Translucency: where the OFB's colours have alpha below 255 (or the lookup table is not
 * opaque), HasTranslucentPolygonalGeometry() says so and the surface renders in the
 * translucent pass with the sample alpha, sorted with the renderer's other actors by
 * VTK's depth peeling (vtkRenderer::SetUseDepthPeeling). An OFB whose colours start
 * transparent (alpha 0) is thus revealed where paint lands (paper Fig. 2). Filtered
 * lookups average colours premultiplied by their alpha, so that transparent samples do
 * not darken their painted neighbours.
 *
 * Uploads are incremental: samples marked with vtkOFB::MarkSamplesModified after the last
 * upload are sent with glBufferSubData; a structure change (new OFB, reallocation) sends
 * everything. GetLastUploadedSampleCount() tells how many samples the last render sent.
 *
 * Without an OFB, with an empty one, or on a context without shader storage buffers, the
 * mapper renders like vtkOpenGLPolyDataMapper and warns once.
 *
 * Port 0 also takes a composite dataset (a vtkMultiBlockDataSet of wall patches): its
 * blocks are drawn as one surface in one draw, coloured from one OFB built from the same
 * input, with per-block visibility (SetCompositeDataDisplayAttributes); see
 * GetRenderedSurface().
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

#include "vtkSmartPointer.h" // for CompositeSurface, AutoPyramid
#include "vtkWeakPointer.h"  // for WarnedOFB

#include <memory> // for std::unique_ptr
#include <set>    // for Warnings
#include <string> // for Warnings

class vtkAlgorithmOutput;
class vtkCompositeDataDisplayAttributes;
class vtkDataArray;
class vtkOFB;
class vtkOFBColoring;
class vtkOFBCompositeSurface;
class vtkOFBPyramid;
class vtkPolyData;

class VTKOFBRENDERING_EXPORT vtkOFBPolyDataMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkOFBPolyDataMapper* New();
  vtkTypeMacro(vtkOFBPolyDataMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Lookup modes (see the class description). NUMBER_OF_LOOKUP_MODES counts them.
  enum LookupModes
  {
    LOOKUP_NEAREST = 0,
    LOOKUP_INVERSE_DISTANCE,
    LOOKUP_MIPMAPPED,
    LOOKUP_NEAREST_MIPMAPPED,
    LOOKUP_SMOOTH,
    LOOKUP_AUTOMATIC,
    NUMBER_OF_LOOKUP_MODES
  };

  ///@{
  /**
   * The OFB that colours the surface: set directly (input port 1's data; SetOFBData is
   * the same as SetOFB, named as the filters that take an OFB on a second port) or
   * through a pipeline connection to input port 1. Default none.
   */
  void SetOFB(vtkOFB* ofb);
  void SetOFBData(vtkOFB* ofb) { this->SetOFB(ofb); }
  vtkOFB* GetOFB();
  void SetOFBConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /**
   * How a fragment's colour is read from the OFB, a LookupModes value: LOOKUP_NEAREST,
   * LOOKUP_INVERSE_DISTANCE, LOOKUP_MIPMAPPED, LOOKUP_NEAREST_MIPMAPPED, LOOKUP_SMOOTH or
   * LOOKUP_AUTOMATIC (default: LOOKUP_SMOOTH where the colouring shows an intensity array
   * of the OFB, a LIC, else LOOKUP_NEAREST; GetResolvedLookupMode says which the last
   * render used).
   * Another value is an error and leaves the mode unchanged. The mode reaches the
   * fragment shader as OFB_LOOKUP_MODE, one of the defines OFB_LOOKUP_NEAREST, ...
   * (the enumerators' names with OFB_ for LOOKUP_), which the shader tells apart.
   */
  void SetLookupMode(int mode);
  vtkGetMacro(LookupMode, int);
  void SetLookupModeToNearest() { this->SetLookupMode(LOOKUP_NEAREST); }
  void SetLookupModeToInverseDistance() { this->SetLookupMode(LOOKUP_INVERSE_DISTANCE); }
  void SetLookupModeToMipmapped() { this->SetLookupMode(LOOKUP_MIPMAPPED); }
  void SetLookupModeToNearestMipmapped() { this->SetLookupMode(LOOKUP_NEAREST_MIPMAPPED); }
  void SetLookupModeToSmooth() { this->SetLookupMode(LOOKUP_SMOOTH); }
  void SetLookupModeToAutomatic() { this->SetLookupMode(LOOKUP_AUTOMATIC); }
  vtkGetMacro(ResolvedLookupMode, int);
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
   * Mipmapped and NearestMipmapped modes: number added to the level computed from the
   * footprint (log2 of the cells a pixel covers); positive values blur, negative sharpen.
   * Default 0.
   */
  vtkSetMacro(MipmapBias, double);
  vtkGetMacro(MipmapBias, double);
  ///@}

  ///@{
  /**
   * Mipmapped and NearestMipmapped modes: most pyramid levels, level 0 included (1..16,
   * default 8), and the coarsest resolution in cells on the longest side (default 8).
   */
  vtkSetClampMacro(MaximumNumberOfMipmapLevels, int, 1, 16);
  vtkGetMacro(MaximumNumberOfMipmapLevels, int);
  vtkSetClampMacro(MinimumMipmapResolution, int, 3, 65536);
  vtkGetMacro(MinimumMipmapResolution, int);
  ///@}

  ///@{
  /**
   * The pyramid of coarser levels that the mipmapped lookups read (Mipmapped,
   * NearestMipmapped, Smooth). Default: a vtkOFBPyramid of the mapper's own, whose levels
   * filter level 0's arrays down. A subclass may compute arrays per level instead: a
   * vtkOFBLICPyramid (OFB::FlowPaths) computes the LIC on every level, with the noise grain
   * and the steps in that level's cells, so that a LIC seen from far shows streaks. The
   * mapper sets its input OFB, surface, MaximumNumberOfLevels and MinimumResolution at
   * every render. Null restores a pyramid of the mapper's own.
   */
  void SetPyramid(vtkOFBPyramid* pyramid);
  vtkOFBPyramid* GetPyramid();
  ///@}

  ///@{
  /**
   * With LOOKUP_AUTOMATIC resolved to Smooth, no pyramid set with SetPyramid and the OFB
   * connected straight from a vtkOFBLIC (SetOFBConnection), use a vtkOFBLICPyramid of that
   * LIC: the default display of a LIC pipeline keeps its streaks from far. It costs a LIC
   * on the coarser levels (about half of level 0's) whenever the LIC changes. Default on.
   */
  vtkSetMacro(AutomaticLevelLIC, bool);
  vtkGetMacro(AutomaticLevelLIC, bool);
  vtkBooleanMacro(AutomaticLevelLIC, bool);
  ///@}

  ///@{
  /**
   * Flow-aligned filter of a LIC shown close up (LOOKUP_SMOOTH, or Automatic resolved to
   * it, with an intensity). The bilinear interpolation of the Smooth lookup, applied to
   * streaks one cell wide that run at an angle to the grid, peaks at each cell centre on
   * the streak and dips between them: where a cell covers several pixels, the streaks
   * show as chains of beads (a period of 1.41 cells on a diagonal), and streaks near an
   * axis as stair steps (1 / sin of the angle). With FlowAlignedFiltering on (default),
   * the intensity is averaged along the flow, with weights 1/4, 1/2, 1/4 at -h, 0 and +h
   * cells, h being half that period, which the average cancels (0.71 on a diagonal, 1 at
   * 30 degrees), at most MaximumFlowFilterOffset (default 2 cells, reached below 14.5
   * degrees). The direction is that of the vector field the LIC follows, interpolated like
   * the intensity and projected onto the fragment's tangent plane. The filter leaves the
   * intensity across the streaks as it is, and fades out where the neighbouring directions
   * disagree (about a critical point). It acts where a level-0 cell covers about a pixel or
   * more (in full from 1.4 pixels a cell, none below 0.7); where no cell of the surface
   * can cover 0.7 pixels (the footprint at its bounds' point nearest to the camera), the
   * shader without the filter is used, so that far views cost nothing more. Close up, it
   * costs two more Smooth lookups a fragment.
   *
   * The field: the sample array FlowArrayName of the OFB when set (default empty), else
   * the field of the vtkOFBLIC that the OFB comes from (connected with SetOFBConnection,
   * or the LIC of a vtkOFBLICPyramid given with SetPyramid), else the OFB's active
   * vectors. Without a 3-component array of that name, no filter. The mapper uploads its
   * directions, 4 bytes a level-0 sample.
   */
  vtkSetMacro(FlowAlignedFiltering, bool);
  vtkGetMacro(FlowAlignedFiltering, bool);
  vtkBooleanMacro(FlowAlignedFiltering, bool);
  vtkSetClampMacro(MaximumFlowFilterOffset, double, 0.0, 4.0);
  vtkGetMacro(MaximumFlowFilterOffset, double);
  vtkSetStdStringFromCharMacro(FlowArrayName);
  vtkGetCharFromStdStringMacro(FlowArrayName);
  /// The field array of the last render's filter ("" when it had none; from far, where no
  /// cell covers 0.7 pixels, it is not run).
  const char* GetResolvedFlowArrayName() { return this->ResolvedFlowArrayName.c_str(); }
  ///@}

  ///@{
  /**
   * The colouring of the OFB's samples (default: a vtkOFBColoring of its own): colour
   * source, lookup table and scalar range, intensity (LIC) and how it combines, colour
   * contrast. Shareable with vtkOFBMapToColors and other mappers; a change to it is seen
   * at the next render. The LIC is held on the GPU as a byte a sample (clamped to [0, 1],
   * NaN as 0, to 1/255: finer than the 8-bit colours it ends in). The colour contrast's
   * lightness range is computed on the CPU (vtkOFBMapToColors) when the OFB or the
   * colouring changes. Null is refused with an error (the colouring stays as it was).
   */
  void SetColoring(vtkOFBColoring* coloring);
  vtkGetObjectMacro(Coloring, vtkOFBColoring);
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

  ///@{
  /**
   * Per-block visibility of a composite input, as vtkCompositePolyDataMapper2 takes it
   * (SetBlockVisibility; a block without its own visibility has its parent's). Default
   * none: every block is visible. Hidden blocks are not drawn and leave the bounds; the OFB
   * (built from all blocks) is unchanged.
   */
  void SetCompositeDataDisplayAttributes(vtkCompositeDataDisplayAttributes* attributes);
  vtkCompositeDataDisplayAttributes* GetCompositeDataDisplayAttributes();
  ///@}

  /**
   * The surface drawn: the input vtkPolyData, or for a composite input (a
   * vtkMultiBlockDataSet, vtkPartitionedDataSetCollection, ... of datasets) its visible
   * blocks merged into one vtkPolyData by vtkOFBMergeBlocks, with the cell array
   * "BlockIndex", the surface whose OFB vtkOFBSampler builds from the same input. A
   * composite input is drawn in one draw, coloured from one OFB.
   */
  vtkPolyData* GetRenderedSurface();

  /**
   * Also the colouring's modification time (which includes its lookup table's).
   */
  vtkMTimeType GetMTime() override;

  /**
   * Samples uploaded to the GPU by the last render of the piece (0 when nothing changed).
   * With depth peeling a frame renders a translucent piece once per peel and only the
   * first uploads: count a frame's uploads with GetUploadedBytes() instead.
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

  /**
   * Whether the surface has translucent parts: an OFB colour (paint) with alpha below
   * 255, or a colouring lookup table that is not opaque (scalars). Without a usable OFB, the
   * superclass's answer. Updates input port 1; the scan of the colours' alpha runs only
   * when they changed (modified sample ranges, a new array or structure) and stops at the
   * first translucent sample.
   */
  bool HasTranslucentPolygonalGeometry() override;

  /**
   * Bytes uploaded to the GPU since the mapper was created (OFB samples, attributes and
   * lookup table): the difference over a render says what that render sent.
   */
  vtkIdType GetUploadedBytes();

protected:
  // Types of the implementation (vtkOFBShaderStorage, private): the GPU state and what
  // was uploaded, and which sample arrays a render uploads.
  class vtkStorage;
  struct vtkSelection;

  vtkOFBPolyDataMapper();
  ~vtkOFBPolyDataMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  ///@{
  /**
   * Composite input (vtkOFBPolyDataMapperComposite.cxx): RenderSurface draws
   * GetRenderedSurface() as vtkOpenGLPolyDataMapper::RenderPiece draws its input;
   * ComputeBounds gives the visible blocks' bounds.
   */
  void RenderSurface(vtkRenderer* ren, vtkActor* act);
  void ComputeBounds() override;
  ///@}

  ///@{
  /**
   * vtkOpenGLPolyDataMapper's per-aspect shader hooks: the position in OFB cells
   * (PositionVC), the lookup and the colour it gives (Color), the painted normals (Normal).
   */
  void ReplaceShaderPositionVC(std::map<vtkShader::Type, vtkShader*> shaders,
    vtkRenderer* ren,
    vtkActor* act) override;
  void ReplaceShaderColor(std::map<vtkShader::Type, vtkShader*> shaders,
    vtkRenderer* ren,
    vtkActor* act) override;
  void ReplaceShaderNormal(std::map<vtkShader::Type, vtkShader*> shaders,
    vtkRenderer* ren,
    vtkActor* act) override;
  void ReplaceShaderLight(std::map<vtkShader::Type, vtkShader*> shaders,
    vtkRenderer* ren,
    vtkActor* act) override;
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
   * levels and what changed of them), UploadLookupTable (scalars source only);
   * UpdateShaderKey notes a change of the shader's variant.
   */
  bool PrepareOFB(vtkRenderer* ren);
  vtkOFB* UpdateOFBInput();
  bool CheckOFB(vtkOFB* ofb);
  bool PrepareContext(vtkRenderer* ren);
  bool SelectArrays(vtkOFB* ofb, vtkSelection& selection);
  void CheckSurfaceInFrame(vtkOFB* ofb);
  bool UploadOFB(vtkOFB* ofb, const vtkSelection& selection);
  void UploadLookupTable();
  /// The lightness range of the OFB's colours (the colouring's EnhanceColorContrast), computed
  /// again when they may have changed.
  void UpdateLightnessRange(vtkOFB* ofb);
  void UpdateShaderKey();
  void UpdateOFBProducer();
  /// The mode this render uses: LookupMode, or Automatic's choice.
  void ResolveLookupMode();
  /// The pyramid of Automatic (AutomaticLevelLIC): a vtkOFBLICPyramid of the OFB's
  /// producer where it is a vtkOFBLIC, else the storage's own.
  void UpdateAutomaticPyramid();
  /// The field of the flow-aligned filter (FlowAlignedFiltering): its array name in
  /// selection.FlowName, empty where the filter is off or there is no field.
  void SelectFlow(vtkOFB* ofb, vtkSelection& selection);
  /// Whether a level-0 cell of the surface may cover 0.7 pixels or more somewhere in the
  /// view (the footprint at the point of its bounds nearest to the camera): the shader
  /// with the flow-aligned filter is used then, the one without it otherwise, so that far
  /// views do not run its code.
  bool FlowFilterInView(vtkRenderer* ren, vtkActor* act);
  /// Whether the pyramid computes the intensity on every level (LevelIntensity), and the
  /// mean of level 0's intensity (IntensityMean), computed again when the array changes.
  void UpdateLevelIntensity(vtkOFB* ofb);
  ///@}

  /**
   * Whether the "Colors" sample array of `ofb` holds an alpha below 255 (cached, see
   * HasTranslucentPolygonalGeometry).
   */
  bool HasTranslucentColors(vtkOFB* ofb);

  /**
   * Set "ofbNormalMatrix" (model to view normals) on `program`.
   */
  void SetNormalMatrix(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act);

  /**
   * Warn once per distinct message, until the OFB or a setting changes.
   */
  void WarnOnce(const std::string& message);

  int LookupMode;
  int ResolvedLookupMode;
  bool AutomaticLevelLIC;
  bool UserPyramid;                           // a pyramid was given with SetPyramid
  vtkSmartPointer<vtkOFBPyramid> AutoPyramid; // AutomaticLevelLIC's vtkOFBLICPyramid
  double InterpolationRadius;
  double MipmapBias;
  int MaximumNumberOfMipmapLevels;
  int MinimumMipmapResolution;
  vtkOFBColoring* Coloring;
  double LightnessRange[2];   // of the colours shown, before the stretch
  vtkTimeStamp LightnessTime; // when it was computed
  bool UsePaintedNormals;
  bool FlowAlignedFiltering;
  double MaximumFlowFilterOffset;
  std::string FlowArrayName;
  std::string ResolvedFlowArrayName;

  vtkIdType LastUploadedSampleCount;
  bool LastRenderUsedOFB;

  // Resolved per render: what the shader needs.
  bool OFBActive;
  bool SourceScalars;
  bool UseIntensity;
  bool UseNormals;
  bool DeepCells;
  bool LevelIntensity;
  bool UseFlow;    // the flow buffer is uploaded
  bool FlowInView; // the shader filters along the flow
  double IntensityMean;
  vtkWeakPointer<vtkDataArray> MeanArray; // the array IntensityMean is of, and when
  vtkMTimeType MeanTime;
  std::string ShaderKey;
  vtkTimeStamp ShaderKeyTime;

  // The GPU state and what was uploaded.
  std::unique_ptr<vtkStorage> Storage;

  // HasTranslucentColors's cache: the OFB and colour array scanned, when, the answer, and
  // where the last translucent sample was found.
  vtkWeakPointer<vtkOFB> AlphaOFB;
  vtkWeakPointer<vtkDataArray> AlphaColors;
  vtkTimeStamp AlphaTime;
  bool AlphaTranslucent;
  vtkIdType AlphaHint;

  std::set<std::string> Warnings;
  vtkSmartPointer<vtkOFBCompositeSurface> CompositeSurface;
  vtkWeakPointer<vtkOFB> WarnedOFB;
  vtkMTimeType WarnedMTime;

private:
  vtkOFBPolyDataMapper(const vtkOFBPolyDataMapper&) = delete;
  void operator=(const vtkOFBPolyDataMapper&) = delete;
};

#endif
