/**
 * @class   vtkOFBTextureProjector
 * @brief   Write the UV texture of a mesh into the colours of a vtkOFB
 *
 * vtkOFBTextureProjector is the way back of vtkOFBTextureBaker: it gives each sample of
 * an OFB the colour of a textured mesh at the sample, so that an existing texture
 * (a scanned colour map, a texture painted elsewhere, a decal on a small patch with its
 * own texture coordinates) becomes the OFB's paint, to be painted over with
 * vtkOFBPainter and baked or probed back out.
 *
 * Input port 0: the OFB. Port 1: the mesh (`SetMeshConnection` / `SetMeshData`; a
 * vtkPolyData of polygons with 2-component texture coordinates, the active TCoords).
 * Port 2: the texture (`SetTextureConnection` / `SetTextureData`; a 2-D vtkImageData of
 * unsigned char, unsigned short or float scalars: grey, grey and alpha, RGB or RGBA; row
 * 0 at v = 0, as vtkOFBImageReader gives it). Texels are fractions of their type's range:
 * bytes / 255, 16-bit values / 65535 (a 16-bit image keeps the precision of its 16 bits
 * until the colour is rounded to a byte), floats clamped to [0, 1]. Output: a copy of the OFB
 * (arrays shared) whose "Colors" (RGBA bytes, made white and opaque where the OFB has none) are a
 * new array.
 *
 * Each sample takes the point closest to it on the mesh's triangles within
 * `MaximumDistance` cells (default 2; only triangles it does not face away from, where
 * the OFB has "Normals"; the smallest triangle id among equally close ones) and the
 * texture at that point's texture coordinates (bilinear with `InterpolateTexture`,
 * default on, else the nearest texel; wrapped with `RepeatTexture`, default on, else
 * clamped to the edge). The texel is laid over the sample's colour with the texel's
 * alpha times `Opacity` (default 1): an opaque texture replaces the colours, a
 * transparent part leaves them. Samples with no triangle within reach keep theirs.
 *
 * Errors (an empty output): no OFB or an empty one, no mesh or one without texture
 * coordinates, no texture or one that is not unsigned char, unsigned short or float with 1 to 4
 * components, a
 * MaximumDistance that is not positive and finite.
 *
 * @sa vtkOFBTextureBaker vtkOFBProbeFilter vtkOFBPainter
 */

#ifndef vtkOFBTextureProjector_h
#define vtkOFBTextureProjector_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBPaintModule.h" // for export macro

class vtkImageData;
class vtkPolyData;

class VTKOFBPAINT_EXPORT vtkOFBTextureProjector : public vtkOFBAlgorithm
{
public:
  static vtkOFBTextureProjector* New();
  vtkTypeMacro(vtkOFBTextureProjector, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The textured mesh (input port 1) and its texture (input port 2).
   */
  void SetMeshConnection(vtkAlgorithmOutput* output);
  void SetMeshData(vtkPolyData* mesh);
  void SetTextureConnection(vtkAlgorithmOutput* output);
  void SetTextureData(vtkImageData* image);
  ///@}

  ///@{
  /**
   * How far from the mesh a sample may be and still take its colour, in cells of the
   * OFB (default 2).
   */
  vtkSetMacro(MaximumDistance, double);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * Bilinear texture lookup (default on), else the nearest texel.
   */
  vtkSetMacro(InterpolateTexture, bool);
  vtkGetMacro(InterpolateTexture, bool);
  vtkBooleanMacro(InterpolateTexture, bool);
  ///@}

  ///@{
  /**
   * Texture coordinates outside [0, 1] wrap around (default on), else clamp to the edge.
   */
  vtkSetMacro(RepeatTexture, bool);
  vtkGetMacro(RepeatTexture, bool);
  vtkBooleanMacro(RepeatTexture, bool);
  ///@}

  ///@{
  /**
   * Factor on the texels' alpha when they are laid over the colours (0 to 1, default 1).
   */
  vtkSetClampMacro(Opacity, double, 0.0, 1.0);
  vtkGetMacro(Opacity, double);
  ///@}

  /**
   * Number of samples the last update gave a texel to (those within reach of the mesh).
   */
  vtkGetMacro(NumberOfProjectedSamples, vtkIdType);

protected:
  vtkOFBTextureProjector();
  ~vtkOFBTextureProjector() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double MaximumDistance = 2.0;
  bool InterpolateTexture = true;
  bool RepeatTexture = true;
  double Opacity = 1.0;
  vtkIdType NumberOfProjectedSamples = 0;

private:
  vtkOFBTextureProjector(const vtkOFBTextureProjector&) = delete;
  void operator=(const vtkOFBTextureProjector&) = delete;
};

#endif
