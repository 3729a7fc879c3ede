/**
 * @class   vtkOFBTextureAtlas
 * @brief   Texture coordinates for a surface that has none: one square tile per triangle
 *
 * vtkOFBTextureAtlas gives a surface without a parametrization the texture coordinates
 * that vtkOFBTextureBaker needs, so that what an OFB holds (the paint, a LIC) can be
 * exported at the OFB's resolution as a textured mesh (OBJ with a PNG, glTF, vtkTexture)
 * for any mesh, not only for meshes made with UVs.
 *
 * Every triangle gets a square tile of its own: S x S texels, S a multiple of
 * MinimumTileSize chosen so that each edge has at least TexelsPerCell texels per cell of
 * the OFB (input port 1, read for its cell size only). The vertex opposite the longest
 * edge goes to the centre of the tile's corner texel, the other two to the centres of the
 * two adjacent corner texels (the longest edge on the diagonal), so that bilinear
 * filtering inside a triangle never reads another tile. Tiles are packed in rows, largest
 * first, into an atlas about as wide as high.
 *
 * Output: the triangles with their points repeated per triangle (point data copied, cell
 * data passed; point normals computed from the triangles where the input has none, so
 * that the repeated points still shade smoothly) and 2-component float texture coordinates
 * "AtlasTCoords" (the active TCoords), and a field-data array "AtlasSize" (width, height in
 * texels): set it as vtkOFBTextureBaker's TextureSize. GetAtlasSize() gives it too after an update.
 *
 * Errors (an empty output): no OFB or an empty one, a surface without polygons or with
 * polygons that are not triangles, or with triangle strips (apply vtkTriangleFilter
 * first), an atlas that does not fit MaximumTextureSize even at 1/8 texel a cell (the
 * density is halved until it fits, with a warning).
 *
 * @sa vtkOFBTextureBaker vtkOBJWriter
 */

#ifndef vtkOFBTextureAtlas_h
#define vtkOFBTextureAtlas_h

#include "vtkOFBFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkOFB;

class VTKOFBFILTERS_EXPORT vtkOFBTextureAtlas : public vtkPolyDataAlgorithm
{
public:
  static vtkOFBTextureAtlas* New();
  vtkTypeMacro(vtkOFBTextureAtlas, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OFB whose cell size sets the density (input port 1).
   */
  void SetSourceConnection(vtkAlgorithmOutput* output);
  void SetSourceData(vtkOFB* ofb);
  ///@}

  ///@{
  /**
   * Texels per OFB cell along every triangle edge, at least (default 1; clamped to
   * [0.125, 8]).
   */
  vtkSetClampMacro(TexelsPerCell, double, 0.125, 8.0);
  vtkGetMacro(TexelsPerCell, double);
  ///@}

  ///@{
  /**
   * Tile sides are multiples of this many texels (default 4, clamped to [2, 64]): the
   * smallest tile, and the alignment that keeps log2 of it mipmap levels within a tile.
   */
  vtkSetClampMacro(MinimumTileSize, int, 2, 64);
  vtkGetMacro(MinimumTileSize, int);
  ///@}

  ///@{
  /**
   * Largest atlas side in texels (default 16384, vtkOFBTextureBaker's and most OpenGL
   * drivers' limit; clamped to [16, 65536]).
   */
  vtkSetClampMacro(MaximumTextureSize, int, 16, 65536);
  vtkGetMacro(MaximumTextureSize, int);
  ///@}

  ///@{
  /**
   * After an update: the atlas's width and height in texels (0 0 after an error), and the
   * texels per cell used (TexelsPerCell, or less where the atlas had to shrink).
   */
  vtkGetVector2Macro(AtlasSize, int);
  vtkGetMacro(EffectiveTexelsPerCell, double);
  ///@}

protected:
  vtkOFBTextureAtlas();
  ~vtkOFBTextureAtlas() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /// Tile sides and places at `density` texels a cell; false when they do not fit.
  bool LayOut(const double* extents, vtkIdType n, double density, int* side, int* origin);

  /// The triangles with repeated points and texture coordinates (`ids`: 3 input points a
  /// triangle; `corner`: the one opposite its longest edge; tile sides and origins).
  void MakeOutput(vtkPolyData* input,
    const vtkIdType* ids,
    const int* corner,
    const int* side,
    const int* origin,
    vtkPolyData* output);

  double TexelsPerCell;
  int MinimumTileSize;
  int MaximumTextureSize;
  int AtlasSize[2];
  double EffectiveTexelsPerCell;

private:
  vtkOFBTextureAtlas(const vtkOFBTextureAtlas&) = delete;
  void operator=(const vtkOFBTextureAtlas&) = delete;
};

#endif
