/**
 * @class   vtkOFBDecalPatch
 * @brief   A surface-aligned patch with texture coordinates: where a decal lies on a surface
 *
 * vtkOFBDecalPatch makes the paper's surface-aligned brush (section 5, Fig. 12): a grid
 * of points traced over the input surface from `Center` along `Direction`, so that a
 * picture laid on it follows the surface as a sticker would, instead of being projected
 * through it. The output is that grid as triangles with texture coordinates (u across
 * `Width`, v across `Height`, both from 0 to 1) and point normals (the surface's
 * triangle normals): with vtkOFBTextureProjector it writes an image into an OFB's
 * colours on the patch only (set the projector's RepeatTexture off, so that the samples
 * along the decal's edges take its edge texels, and a MaximumDistance of about a cell:
 * enough for the samples between the patch's flat triangles and the curved surface, not
 * so much that an opaque rim spreads far around it).
 *
 * The centre is moved onto the surface (its closest point). The central row is traced
 * from it both ways along the direction (projected into the tangent plane), the
 * direction carried across the triangles it crosses (the unfolding of the triangles
 * into one plane); from each point of the row a column is traced both ways along the
 * perpendicular of the carried direction (the paper's tangent correction). Distances
 * are along the surface: `Width` and `Height` in world units. A trace that reaches
 * the boundary of an open surface stops there (the rest of its points on the boundary).
 *
 * Input: a vtkPolyData of polygons (triangulated here; points repeated per face, as an OBJ
 * with texture coordinates has them, are joined by position). Errors (an empty
 * output): no polygon of non-zero area, a Center that is not finite, a Width or Height
 * that is not positive and finite, a Direction of zero length or along the surface
 * normal at the centre.
 *
 * @sa vtkOFBTextureProjector vtkOFBPainter
 */

#ifndef vtkOFBDecalPatch_h
#define vtkOFBDecalPatch_h

#include "vtkOFBPaintModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for the cached surface

class VTKOFBPAINT_EXPORT vtkOFBDecalPatch : public vtkPolyDataAlgorithm
{
public:
  static vtkOFBDecalPatch* New();
  vtkTypeMacro(vtkOFBDecalPatch, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Where the decal's centre is (moved onto the surface; default the origin).
   */
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  ///@}

  ///@{
  /**
   * The decal's u direction (its "right"; default +x), projected into the tangent plane.
   */
  vtkSetVector3Macro(Direction, double);
  vtkGetVector3Macro(Direction, double);
  ///@}

  ///@{
  /**
   * Size along the surface in world units (default 1 x 1).
   */
  vtkSetMacro(Width, double);
  vtkGetMacro(Width, double);
  vtkSetMacro(Height, double);
  vtkGetMacro(Height, double);
  ///@}

  ///@{
  /**
   * Quads of the grid across the width and the height (default 32 x 32, each in [1, 1024]).
   */
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  ///@}

protected:
  vtkOFBDecalPatch();
  ~vtkOFBDecalPatch() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// False with an error where the settings cannot make a decal.
  bool CheckSettings();

  double Center[3] = { 0.0, 0.0, 0.0 };
  double Direction[3] = { 1.0, 0.0, 0.0 };
  double Width = 1.0;
  double Height = 1.0;
  int Resolution[2] = { 32, 32 };

private:
  vtkOFBDecalPatch(const vtkOFBDecalPatch&) = delete;
  void operator=(const vtkOFBDecalPatch&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals; // the walker and locator of the last surface
};

#endif
