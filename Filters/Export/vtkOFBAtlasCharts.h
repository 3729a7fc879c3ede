// Private header of vtkOFBTextureAtlas: the charts layout. A chart is a piece of the
// surface whose triangles all face one of the six axis directions most (the normal's
// largest component), projected along that axis onto the OFB's grid: a texel is a cell of
// that grid, its centre on the cell's centre (at one texel a cell), so a texel's surface
// point is where the OFB took that cell's sample. Charts grow over shared edges (points
// welded by position, so that a mesh split at its seams still has neighbours) and stop
// where a triangle would cover a texel centre of the chart twice (the surface folding over
// itself along the axis). Charts are dropped, tallest first, onto the skyline of the
// atlas's columns by their outlines grown by `padding` (see Pack).
#ifndef vtkOFBAtlasCharts_h
#define vtkOFBAtlasCharts_h

#include "vtkType.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

class vtkOFBAtlasCharts
{
public:
  /**
   * What does not depend on the density, once for the triangles that Build then lays out:
   * each triangle's axis direction and its neighbours across edges. The ids index `x`
   * unchecked: vtkOFBTextureAtlas refuses a surface whose cells name points that do not
   * exist (vtkOFBCheckCellPointIds) before it gets here.
   */
  void Prepare(const double* x, const vtkIdType* ids, vtkIdType n);

  /**
   * Lay out (after Prepare with the same arguments) the `n` triangles `ids` (3 point ids a
   * triangle) of the points `x` (3 doubles a point, world units) in the frame of an OFB (`origin`,
   * `cellSize`), at `density` texels a cell, each chart `padding` texels from the next. False when
   * the atlas would need a side over `maximumSize` texels: Width and Height are then the size it
   * would need (0 where even that is out of reach), and the layout is not to be used.
   */
  bool Build(const double* x,
    const vtkIdType* ids,
    vtkIdType n,
    const double origin[3],
    double cellSize,
    double density,
    int padding,
    int maximumSize);

  /// The atlas's texel coordinates of point `p` (world units) in chart `c`: texel (i, j)
  /// has its centre at (i + 0.5, j + 0.5). A point that is not finite gets the chart's
  /// first texel.
  glm::dvec2 TexelCoordinates(const double p[3], int c) const;

  std::vector<int> ChartOf; // per triangle
  int Width = 0;
  int Height = 0;

  int GetNumberOfCharts() const { return static_cast<int>(this->Axis.size()); }

private:
  /// `p` (world units) projected along the axis of direction `k` (2 a, + 1 where the
  /// normal points to -a), in texels, texel centres at integers; u mirrored for -a, so
  /// that every chart is seen from outside and keeps the triangles' orientation.
  glm::dvec2 Project(const glm::dvec3& p, int k) const;
  void Classify(const double* x, const vtkIdType* ids, vtkIdType n);
  /// Per point id (up to the largest used) the id of the first used point, by id, at the
  /// same position; -1 for a point no triangle uses.
  static std::vector<vtkIdType> WeldPoints(const double* x, const vtkIdType* ids, vtkIdType n);
  void FindNeighbours(const double* x, const vtkIdType* ids, vtkIdType n);
  bool Grow(const double* x, const vtkIdType* ids, vtkIdType n);
  void AdoptDegenerate(vtkIdType n);
  bool Pack(const double* x, const vtkIdType* ids, vtkIdType n, int padding, int maximumSize);
  /// Per column of each chart's rectangle (chart c's columns from First[c]), the rows its
  /// triangles touch grown by `padding`: [Bottom, Top), Bottom >= Top for none.
  struct Outlines
  {
    std::vector<int> First;
    std::vector<int> Bottom;
    std::vector<int> Top;
  };
  Outlines Outline(const double* x,
    const vtkIdType* ids,
    vtkIdType n,
    int padding,
    const std::vector<glm::dvec2>& low,
    const std::vector<glm::ivec2>& size) const;
  /// Width, Height and Shift from the outlines dropped onto a skyline (0 x 0 if too large).
  void Drop(const Outlines& outlines,
    const std::vector<glm::dvec2>& low,
    const std::vector<glm::ivec2>& size,
    int padding);

  glm::dvec3 Origin{ 0.0 };
  double Scale = 1.0;                    // texels a world unit
  double HalfCell = 0.5;                 // half a cell, in texels
  std::vector<signed char> Direction;    // per triangle: 2 a (+ 1 for -a), -1 degenerate
  std::vector<vtkIdType> NeighbourStart; // per triangle + 1, into Neighbours
  std::vector<vtkIdType> Neighbours;     // triangles sharing an edge
  std::vector<signed char> Axis;         // per chart: its direction
  std::vector<glm::dvec2> Shift;         // per chart: atlas texel = projection + shift
  std::vector<glm::dvec2> Low;           // per chart: its first texel, projected
};

#endif
