/**
 * @class   vtkOFBViewResolution
 * @brief   The OFB resolution and LIC noise grain that a renderer's view needs
 *
 * vtkOFBViewResolution computes, for the current camera of a vtkRenderer and a surface,
 * the vtkOFBSampler Resolution that gives about CellsPerPixel OFB cells per pixel on the
 * visible part of the surface, and the vtkOFBLIC NoiseGrainSize (in cells of that
 * resolution) that makes the noise grain NoiseGrainPixels pixels wide there: for a user
 * who zooms in and wants the OFB (and its LIC) computed again with detail at the new
 * scale.
 *
 * The pixel size at a point is the world length that one pixel covers at the point's
 * depth (perspective: 2 d tan(ViewAngle / 2) / height at the view depth d; parallel:
 * 2 ParallelScale / height). The points are the surface's points (or a 9 x 9 x 9 lattice of
 * the bounds) that lie in the view frustum; the pixel size used is the FootprintQuantile
 * quantile of theirs (default 0.5, the median: half of the visible points have finer
 * pixels). The cell size is that pixel size / CellsPerPixel, and the Resolution the
 * sampler's: the longest side of the surface's bounds in cells, plus the two padding
 * cells, clamped to [MinimumResolution, MaximumResolution]. NoiseGrainSize is
 * NoiseGrainPixels pixels in cells of the clamped resolution, at least 1.
 *
 * Points are taken in world coordinates (an actor's transform is not applied). Compute
 * returns false, with an error, without a renderer with a camera and a size, without
 * points, or when no point is in the view (the results are then 0).
 *
 * @sa vtkOFBSampler vtkOFBLIC vtkOFBPolyDataMapper
 */

#ifndef vtkOFBViewResolution_h
#define vtkOFBViewResolution_h

#include "vtkOFBRenderingModule.h" // for export macro
#include "vtkObject.h"

class vtkDataSet;
class vtkRenderer;

class VTKOFBRENDERING_EXPORT vtkOFBViewResolution : public vtkObject
{
public:
  static vtkOFBViewResolution* New();
  vtkTypeMacro(vtkOFBViewResolution, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * OFB cells per pixel wanted on the visible surface (default 1; 0.01..100).
   */
  vtkSetClampMacro(CellsPerPixel, double, 0.01, 100.0);
  vtkGetMacro(CellsPerPixel, double);
  ///@}

  ///@{
  /**
   * Width of the LIC noise grain on the screen, in pixels (default 2; 0.1..1000).
   */
  vtkSetClampMacro(NoiseGrainPixels, double, 0.1, 1000.0);
  vtkGetMacro(NoiseGrainPixels, double);
  ///@}

  ///@{
  /**
   * Quantile of the visible points' pixel sizes that sets the cell size (default 0.5;
   * 0 the finest pixel, 1 the coarsest).
   */
  vtkSetClampMacro(FootprintQuantile, double, 0.0, 1.0);
  vtkGetMacro(FootprintQuantile, double);
  ///@}

  ///@{
  /**
   * Bounds of the Resolution (defaults 16 and 4096: an OFB's memory grows with the square
   * of its resolution, about 1 GB for a closed surface at 4096).
   */
  vtkSetClampMacro(MinimumResolution, int, 3, 65536);
  vtkGetMacro(MinimumResolution, int);
  vtkSetClampMacro(MaximumResolution, int, 3, 65536);
  vtkGetMacro(MaximumResolution, int);
  ///@}

  ///@{
  /**
   * Compute the results for the active camera of `renderer` and the points of `surface`
   * (any vtkDataSet), or a lattice of `bounds` (xmin, xmax, ymin, ymax, zmin, zmax).
   * Returns false with an error on bad input or when nothing is in view.
   */
  bool Compute(vtkRenderer* renderer, vtkDataSet* surface);
  bool Compute(vtkRenderer* renderer, const double bounds[6]);
  ///@}

  ///@{
  /**
   * Results of the last Compute: the sampler's Resolution, the LIC's NoiseGrainSize in
   * cells, the cell size (world units), the pixel size used (world units), and the number
   * of points found in the view. 0 before a successful Compute.
   */
  vtkGetMacro(Resolution, int);
  vtkGetMacro(NoiseGrainSize, double);
  vtkGetMacro(CellSize, double);
  vtkGetMacro(PixelSize, double);
  vtkGetMacro(NumberOfVisiblePoints, vtkIdType);
  ///@}

protected:
  vtkOFBViewResolution();
  ~vtkOFBViewResolution() override;

  /// The shared part of Compute: `points` (3 doubles each) of a box whose longest side is
  /// `longest`.
  bool ComputeFromPoints(vtkRenderer* renderer,
    const double* points,
    vtkIdType count,
    double longest);
  void ResetResults();

  double CellsPerPixel;
  double NoiseGrainPixels;
  double FootprintQuantile;
  int MinimumResolution;
  int MaximumResolution;

  int Resolution;
  double NoiseGrainSize;
  double CellSize;
  double PixelSize;
  vtkIdType NumberOfVisiblePoints;

private:
  vtkOFBViewResolution(const vtkOFBViewResolution&) = delete;
  void operator=(const vtkOFBViewResolution&) = delete;
};

#endif
