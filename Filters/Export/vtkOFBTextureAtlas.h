/**
 * @class   vtkOFBTextureAtlas
 * @brief   Texture coordinates for a surface that has none, on the OFB's own grids
 *
 * vtkOFBTextureAtlas gives a surface without a parametrization the texture coordinates
 * that vtkOFBTextureBaker needs, so that what an OFB holds (the paint, a LIC) can be
 * exported at the OFB's resolution as a textured mesh (OBJ with a PNG, glTF, vtkTexture)
 * for any mesh, not only for meshes made with UVs. The OFB (input port 1) gives the frame
 * and the cell size.
 *
 * Layout Charts (the default): the surface is cut into charts, pieces whose triangles all
 * face one of the six axis directions most (the largest component of the triangle's
 * normal), grown over shared edges (an edge is shared where its points lie at one place,
 * whatever their ids: a mesh split at its seams is welded for this); each chart is projected along
 * its axis onto the OFB's grid of that axis, the grid the OFB samples such a surface best on. At
 * one texel a cell (TexelsPerCell 1) a texel is a cell of that grid and its centre lies on the
 * cell's centre, so the surface point of a texel is where the OFB took that cell's sample: the bake
 * reads the samples themselves, not a resampling. A chart stops growing where a triangle would
 * cover a texel centre it already covers (the surface folding over itself along the axis); that
 * triangle starts or joins another chart. Charts are mirrored so that each is seen from outside,
 * and at least `ChartPadding` texels lie between a chart and the next (vtkOFBTextureBaker's
 * Padding fills them): charts are dropped, tallest first, onto the skyline of the atlas's
 * columns by their outlines (per column the rows their triangles touch, grown by the padding),
 * each where it comes to rest lowest, so that outlines interlock where rectangles would leave
 * gaps, in an atlas about as wide as high. Points are repeated only where charts meet.
 *
 * Layout Triangles: every triangle gets a square tile of its own, S x S texels, S a
 * multiple of MinimumTileSize chosen so that each edge has at least TexelsPerCell texels
 * per cell. The vertex opposite the longest edge goes to the centre of the tile's corner
 * texel, the other two to the centres of the two adjacent corner texels (the longest edge
 * on the diagonal), so that bilinear filtering inside a triangle never reads another tile.
 * Tiles are packed in rows, largest first. About 4 to 5 times the texels of the charts at the
 * same density (half of each tile is empty, small triangles get the smallest tile), and a
 * texel's point is not a sample's.
 *
 * Output: the triangles in input order (cell data passed; point data copied to the points,
 * which are repeated where a point's triangles lie in different charts or, for Triangles,
 * per triangle; point normals computed from the triangles where the input has none, so
 * that repeated points still shade smoothly), 2-component float texture coordinates
 * "AtlasTCoords" (the active TCoords), and a field-data array "AtlasSize" (width, height in
 * texels): set it as vtkOFBTextureBaker's TextureSize. GetAtlasSize() gives it too after an
 * update.
 *
 * Errors (an empty output): no OFB or an empty one, a surface without polygons or with
 * polygons that are not triangles, or with triangle strips (apply vtkTriangleFilter
 * first), an atlas that does not fit MaximumTextureSize even at 1/8 texel a cell. Below
 * that, an atlas too large at TexelsPerCell gets a lower density, with a warning: for
 * Charts about the largest that fits (EffectiveTexelsPerCell), for Triangles the density
 * halved until it fits.
 *
 * @sa vtkOFBTextureBaker vtkOBJWriter
 */

#ifndef vtkOFBTextureAtlas_h
#define vtkOFBTextureAtlas_h

#include "vtkOFBExportModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for WithNormals

class vtkOFB;

class VTKOFBEXPORT_EXPORT vtkOFBTextureAtlas : public vtkPolyDataAlgorithm
{
public:
  static vtkOFBTextureAtlas* New();
  vtkTypeMacro(vtkOFBTextureAtlas, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OFB whose cell size sets the density (input port 1).
   */
  void SetOFBConnection(vtkAlgorithmOutput* output);
  void SetOFBData(vtkOFB* ofb);
  ///@}

  enum LayoutType
  {
    CHARTS = 0,
    TRIANGLES = 1
  };

  ///@{
  /**
   * Charts projected on the OFB's grids (CHARTS, the default) or a square tile per
   * triangle (TRIANGLES).
   */
  vtkSetClampMacro(Layout, int, CHARTS, TRIANGLES);
  vtkGetMacro(Layout, int);
  void SetLayoutToCharts() { this->SetLayout(CHARTS); }
  void SetLayoutToTriangles() { this->SetLayout(TRIANGLES); }
  ///@}

  ///@{
  /**
   * Texels per OFB cell (default 1; clamped to [0.125, 8]): along the grid for Charts
   * (1 puts the texel centres on the cell centres), along every triangle edge at least for
   * Triangles.
   */
  vtkSetClampMacro(TexelsPerCell, double, 0.125, 8.0);
  vtkGetMacro(TexelsPerCell, double);
  ///@}

  ///@{
  /**
   * Charts only: texels between a chart and the edge of its rectangle (default 2, clamped
   * to [1, 32]); two charts' texels are at least twice that apart.
   */
  vtkSetClampMacro(ChartPadding, int, 1, 32);
  vtkGetMacro(ChartPadding, int);
  ///@}

  ///@{
  /**
   * Triangles only: tile sides are multiples of this many texels (default 4, clamped to
   * [2, 64]): the smallest tile, and the alignment that keeps log2 of it mipmap levels
   * within a tile.
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

  /**
   * After an update: the number of charts (Charts), or of triangles (Triangles); 0 after
   * an error.
   */
  vtkGetMacro(NumberOfCharts, int);

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

  /// The Charts layout and its output; false when the atlas does not fit.
  bool MakeCharts(vtkPolyData* input, vtkOFB* ofb, const vtkIdType* ids, vtkPolyData* output);

  /// A warning where the density had to be lowered to fit.
  void WarnOfDensity();

  /// The input with point normals (computed where it has none).
  static vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* input);

  int Layout;
  double TexelsPerCell;
  int ChartPadding;
  int MinimumTileSize;
  int MaximumTextureSize;
  int AtlasSize[2];
  double EffectiveTexelsPerCell;
  int NumberOfCharts;

private:
  vtkOFBTextureAtlas(const vtkOFBTextureAtlas&) = delete;
  void operator=(const vtkOFBTextureAtlas&) = delete;
};

#endif
