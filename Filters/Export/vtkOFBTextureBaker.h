/**
 * @class   vtkOFBTextureBaker
 * @brief   Bake a sample array of a vtkOFB into the UV texture of a mesh
 *
 * vtkOFBTextureBaker writes what an OFB holds (the paint, a LIC, any sample array)
 * into a texture image of a mesh that has texture coordinates, so that a painting
 * made with vtkOFB keeps its detail finer than the triangles in any renderer or file
 * format that takes a textured mesh (OBJ with a PNG, glTF, vtkTexture).
 *
 * Input port 0: the mesh (vtkPolyData with 2-component texture coordinates, the active
 * TCoords, one pair a point; polygons are split into fans, strips and lines are
 * ignored with a warning: apply vtkTriangleFilter first). Input port 1: the OFB
 * (`SetOFBConnection` / `SetOFBData`). Output: a vtkImageData of `TextureSize`
 * texels (origin 0, spacing 1; texel (i, j) is texture coordinate ((i + 0.5) / W,
 * (j + 0.5) / H), row 0 at v = 0, as vtkTexture and vtkOFBImageWriter take it) with the
 * baked array (same name and components as the OFB's, the active scalars; its type, or
 * float with OutputScalarTypeToFloat) and
 * a `vtkValidPointMask` array (1 where a triangle covers the texel centre and a sample
 * was found, 0 elsewhere). A triangle too small in UV space to cover any texel centre
 * covers the texel under its centroid instead (where no other triangle covers it), so
 * that slivers and tiny UV islands get a value and padding around it.
 *
 * Each covered texel's surface point (barycentric in its triangle, the last triangle
 * in cell order where triangles overlap in UV space) is looked up in the OFB as
 * vtkOFBProbeFilter does (`LookupMode` Nearest or Smooth, `Radius` in cells, with
 * `NormalAware` the triangle's normal as the facing reference). `Padding` texels
 * around the covered ones (default 4) are filled with the mean of their filled
 * neighbours, so that bilinear filtering and mipmaps do not bleed the background
 * into the edges of UV islands.
 *
 * Errors (an empty image): no OFB or an empty one, a mesh without texture
 * coordinates, a TextureSize outside [1, 16384] or one whose bake would take more
 * than MemoryLimit, a Radius that is not positive and finite, an array the OFB lacks.
 *
 * A float bake (the OFB's LIC and other float arrays as they are, or any array with
 * OutputScalarTypeToFloat) written by vtkOFBImageWriter to an OpenEXR file keeps every
 * value bit for bit (32-bit float); the paint (RGBA bytes) goes to a PNG.
 *
 * @sa vtkOFBProbeFilter vtkTexture vtkOFBImageWriter
 */

#ifndef vtkOFBTextureBaker_h
#define vtkOFBTextureBaker_h

#include "vtkImageAlgorithm.h"
#include "vtkOFBExportModule.h" // for export macro

#include <string> // for ArrayName

class vtkDataArray;
class vtkImageData;
class vtkPolyData;
class vtkOFB;

class VTKOFBEXPORT_EXPORT vtkOFBTextureBaker : public vtkImageAlgorithm
{
public:
  static vtkOFBTextureBaker* New();
  vtkTypeMacro(vtkOFBTextureBaker, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OFB to bake (input port 1).
   */
  void SetOFBConnection(vtkAlgorithmOutput* output);
  void SetOFBData(vtkOFB* ofb);
  ///@}

  ///@{
  /**
   * Width and height of the texture in texels (default 1024 x 1024; each in [1, 16384]).
   */
  vtkSetVector2Macro(TextureSize, int);
  vtkGetVector2Macro(TextureSize, int);
  ///@}

  ///@{
  /**
   * The sample array to bake (default empty: the OFB's active scalars, which are the
   * paint unless the sampled mesh had active cell scalars, or the paint when there
   * are no active scalars; see docs/inputs.md).
   */
  vtkSetStdStringFromCharMacro(ArrayName);
  vtkGetCharFromStdStringMacro(ArrayName);
  ///@}

  ///@{
  /**
   * The type of the baked texels: VTK_VOID (default) keeps the array's type (RGBA bytes
   * for the paint, float for the LIC), VTK_FLOAT converts the values to 32-bit float
   * (not scaled: bytes stay 0 to 255), for an OpenEXR texture of a double or integer
   * array. Other types are refused with an error.
   */
  vtkSetMacro(OutputScalarType, int);
  vtkGetMacro(OutputScalarType, int);
  void SetOutputScalarTypeToSameAsArray() { this->SetOutputScalarType(VTK_VOID); }
  void SetOutputScalarTypeToFloat() { this->SetOutputScalarType(VTK_FLOAT); }
  ///@}

  ///@{
  /**
   * The lookup (vtkOFBProbeFilter::LOOKUP_NEAREST, default, or vtkOFBProbeFilter::LOOKUP_SMOOTH)
   * and its radius in cells of the OFB (default sqrt(3)).
   */
  vtkSetClampMacro(LookupMode, int, 0, 1);
  vtkGetMacro(LookupMode, int);
  void SetLookupModeToNearest() { this->SetLookupMode(0); }
  void SetLookupModeToSmooth() { this->SetLookupMode(1); }
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Skip samples facing away from the triangle (default on).
   */
  vtkSetMacro(NormalAware, bool);
  vtkGetMacro(NormalAware, bool);
  vtkBooleanMacro(NormalAware, bool);
  ///@}

  ///@{
  /**
   * Texels filled around the covered ones (default 4, at most 64).
   */
  vtkSetClampMacro(Padding, int, 0, 64);
  vtkGetMacro(Padding, int);
  ///@}

  ///@{
  /**
   * Most memory a bake may take, in MiB (default 4096; at least 1). The baker
   * estimates its working memory before allocating anything, at most 51 bytes a texel
   * besides two tuples of the baked array (for RGBA bytes: 59 bytes a texel, so a
   * 4096 x 4096 texture needs up to 0.9 GiB and 16384 x 16384 up to 15 GiB), and
   * refuses a TextureSize whose estimate exceeds the limit with an error naming it.
   */
  vtkSetClampMacro(MemoryLimit, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MemoryLimit, vtkIdType);
  ///@}

  /**
   * The working memory, in bytes, that baking a `width` x `height` texture of a sample
   * array of `bytesPerTuple` bytes a tuple takes at most (see MemoryLimit).
   */
  static vtkIdType EstimateBakeBytes(int width, int height, int bytesPerTuple);

  /**
   * Number of texels the last update covered with a triangle and found a sample for.
   */
  vtkGetMacro(NumberOfBakedTexels, vtkIdType);

protected:
  vtkOFBTextureBaker();
  ~vtkOFBTextureBaker() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Bake `source` into `image` (RequestData's work once its input is checked).
  void Bake(vtkPolyData* mesh,
    vtkOFB* ofb,
    vtkDataArray* source,
    vtkDataArray* tcoords,
    vtkImageData* image,
    vtkInformation* outInfo);
  /// The sample array to bake (ArrayName, or the active scalars, or "Colors"), or null.
  vtkDataArray* FindSourceArray(vtkOFB* ofb) const;

  int TextureSize[2] = { 1024, 1024 };
  std::string ArrayName;
  int OutputScalarType = VTK_VOID;
  int LookupMode = 0;
  double Radius;
  bool NormalAware = true;
  int Padding = 4;
  vtkIdType MemoryLimit = 4096;
  vtkIdType NumberOfBakedTexels = 0;

private:
  vtkOFBTextureBaker(const vtkOFBTextureBaker&) = delete;
  void operator=(const vtkOFBTextureBaker&) = delete;
};

#endif
