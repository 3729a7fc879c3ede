/**
 * @class   vtkOFBTextureAtlas
 * @brief   A vtkOFB resampled into a texture atlas of one square tile per triangle
 *
 * vtkOFBTextureAtlas lays a surface's triangles out in a texture atlas without any
 * parametrization of the surface: every triangle gets a square tile of T x T texels of its
 * own (T a power of two, at least MinimumTileSize, chosen so that its edges have at least
 * TexelsPerCell texels per OFB cell), the vertex opposite its longest edge at the tile's
 * corner texel and the other two at the two adjacent corner texels (the longest edge on
 * the diagonal). Tiles are placed in Morton order, largest first, so that each tile and
 * each of its first log2(MinimumTileSize) mipmap levels stay apart from the others.
 *
 * Build() finds the sample that colours each texel, as vtkOFBPolyDataMapper's Nearest
 * lookup does: the texel's point on its triangle (texels past the diagonal take the
 * closest point of the diagonal), the closest sample in the cell under it in the grid most
 * aligned with the triangle's normal, then in the other two grids, then the closest sample
 * within sqrt(3) cells. The Gather methods then copy a sample array into texels, each
 * value multiplied by the texel's coverage (1 where a sample was found, 0 elsewhere), so
 * that a filtered value divided by the filtered coverage averages only covered texels.
 * Colours are premultiplied by their alpha for the same reason.
 *
 * The per-triangle map GetTriangleMaps() takes a point in OFB cells (x - origin) / cell
 * size to normalized atlas coordinates: u = dot(m[0..2], g) + m[3], v = dot(m[4..6], g)
 * + m[7], 8 floats a triangle, triangle i being the i-th polygon of the surface (the
 * order in which OpenGL numbers the primitives of VTK's polygon draw, gl_PrimitiveID).
 * vtkOFBPolyDataMapper's Atlas lookup mode reads the atlas through the GPU's texture
 * filtering (bilinear within a tile, trilinear across its mipmap levels).
 *
 * Input: polygons that are all triangles (triangulate first: vtkTriangleFilter), no
 * triangle strips. Build() returns false with an error message otherwise, or for an
 * empty OFB, or when even 1/8 texel a cell does not fit in MaximumTextureSize.
 *
 * @sa vtkOFBPolyDataMapper vtkOFBTextureBaker
 */

#ifndef vtkOFBTextureAtlas_h
#define vtkOFBTextureAtlas_h

#include "vtkOFBFiltersModule.h" // for export macro
#include "vtkObject.h"
#include "vtkWeakPointer.h" // for BuiltSurface

#include <string> // for GetErrorMessage
#include <vector> // for the layout

class vtkDataArray;
class vtkIdTypeArray;
class vtkOFB;
class vtkPolyData;
class vtkUnsignedCharArray;

class VTKOFBFILTERS_EXPORT vtkOFBTextureAtlas : public vtkObject
{
public:
  static vtkOFBTextureAtlas* New();
  vtkTypeMacro(vtkOFBTextureAtlas, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Texels per OFB cell along each triangle edge, at least (default 1; clamped to
   * [0.125, 8]). Build() halves it while the atlas does not fit MaximumTextureSize.
   */
  vtkSetClampMacro(TexelsPerCell, double, 0.125, 8.0);
  vtkGetMacro(TexelsPerCell, double);
  ///@}

  ///@{
  /**
   * Smallest tile side in texels, a power of two (default 4, clamped to [2, 64]): the
   * atlas keeps log2 of it mipmap levels apart per tile.
   */
  vtkSetClampMacro(MinimumTileSize, int, 2, 64);
  vtkGetMacro(MinimumTileSize, int);
  ///@}

  ///@{
  /**
   * Largest atlas side in texels (default 16384, OpenGL's GL_MAX_TEXTURE_SIZE on most
   * drivers; clamped to [64, 65536]).
   */
  vtkSetClampMacro(MaximumTextureSize, int, 64, 65536);
  vtkGetMacro(MaximumTextureSize, int);
  ///@}

  /**
   * Lay out the triangles of `surface` and find the sample of `ofb` that colours each
   * texel. Nothing is done when neither they nor the settings changed since the last
   * successful Build (returns true). Returns false (and the atlas is empty) on bad input;
   * GetErrorMessage() says why.
   */
  bool Build(vtkPolyData* surface, vtkOFB* ofb);

  /// Why the last Build() failed (empty after a success).
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

  ///@{
  /// Atlas size in texels (0 x 0 when empty), and the texels per cell actually used.
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }
  double GetEffectiveTexelsPerCell() const { return this->EffectiveTexelsPerCell; }
  ///@}

  /// Mipmap levels that stay within each tile (log2 of the smallest tile used).
  int GetNumberOfTileLevels() const { return this->TileLevels; }

  /// Triangles laid out.
  vtkIdType GetNumberOfTriangles() const { return static_cast<vtkIdType>(this->Maps.size() / 8); }

  /// 8 floats a triangle: the map from OFB cells to normalized atlas coordinates.
  const float* GetTriangleMaps() const { return this->Maps.data(); }

  /// The sample of each texel, row by row (-1 where none), Width * Height entries.
  const vtkTypeInt32* GetTexelSamples() const { return this->Samples.data(); }

  /// Texels with a sample.
  vtkIdType GetNumberOfCoveredTexels() const { return this->CoveredTexels; }

  ///@{
  /**
   * Fill `out` (Width * Height texels, row by row) from a sample array, each value
   * multiplied by the texel's coverage:
   * - GatherCoverage: 255 where the texel has a sample, else 0 (one byte a texel);
   * - GatherColors: RGBA bytes premultiplied by alpha (3-component colours get alpha 255;
   *   4 bytes a texel);
   * - GatherScalars: component `component` of `array` (-1: the magnitude) as floats;
   * - GatherIntensity: values clamped to [0, 1] as 16-bit unsigned normalized integers;
   * - GatherNormals: unit vectors as 8-bit signed normalized integers, 4 a texel (the
   *   fourth 0).
   * With `ranges` (two components: first and last sample, as
   * vtkOFB::GetSampleRangesModifiedSince gives them, sorted) only the texels whose sample
   * lies in one of them are written; `rows` then receives the first and last row written
   * (first > last when none). Returns false when the array is too short or of the wrong
   * shape.
   */
  void GatherCoverage(unsigned char* out) const;
  bool GatherColors(vtkDataArray* colors,
    unsigned char* out,
    vtkIdTypeArray* ranges = nullptr,
    int rows[2] = nullptr) const;
  bool GatherScalars(vtkDataArray* array,
    int component,
    float* out,
    vtkIdTypeArray* ranges = nullptr,
    int rows[2] = nullptr) const;
  bool GatherIntensity(vtkDataArray* array,
    unsigned short* out,
    vtkIdTypeArray* ranges = nullptr,
    int rows[2] = nullptr) const;
  bool GatherNormals(vtkDataArray* normals,
    signed char* out,
    vtkIdTypeArray* ranges = nullptr,
    int rows[2] = nullptr) const;
  ///@}

  /// Forget the layout (the next Build() starts again).
  void Initialize();

protected:
  vtkOFBTextureAtlas();
  ~vtkOFBTextureAtlas() override;

  /// Build's steps: the tile sizes for a density, their places, the maps and samples.
  bool CheckInput(vtkPolyData* surface, vtkOFB* ofb);
  bool LayOut(vtkPolyData* surface, vtkOFB* ofb);
  void FindTexelSamples(vtkPolyData* surface, vtkOFB* ofb);

  /// Samples of the OFB built from (arrays must be as long); VTK_ID_MAX without a layout,
  /// so that no array passes.
  vtkIdType GetNumberOfSamplesBuilt() const;

  /// Calls `write(texel, sample)` for every texel (of `ranges` only, if given) in
  /// parallel; returns the rows touched in `rows`.
  template<typename Writer>
  void ForEachTexel(vtkIdTypeArray* ranges, int rows[2], const Writer& write) const;

  double TexelsPerCell;
  int MinimumTileSize;
  int MaximumTextureSize;

  int Width;
  int Height;
  double EffectiveTexelsPerCell;
  int TileLevels;
  vtkIdType CoveredTexels;
  std::vector<float> Maps;
  std::vector<int> TileSize;   // per triangle
  std::vector<int> TileOrigin; // per triangle: x, y
  std::vector<vtkTypeInt32> Samples;
  std::string ErrorMessage;

  // What the layout was built from.
  vtkWeakPointer<vtkPolyData> BuiltSurface;
  vtkWeakPointer<vtkOFB> BuiltOFB;
  vtkMTimeType BuiltSurfaceTime;
  vtkMTimeType BuiltStructureTime;
  vtkMTimeType BuiltSettingsTime;

private:
  vtkOFBTextureAtlas(const vtkOFBTextureAtlas&) = delete;
  void operator=(const vtkOFBTextureAtlas&) = delete;
};

#endif
