/**
 * @class   vtkOFBTriangleWalker
 * @brief   Moves points over a triangle surface along a tangent field (private)
 *
 * vtkOFBParticleAdvector keeps every particle as a triangle and barycentric
 * coordinates, so its position is always a convex combination of the corners of
 * one triangle: it lies exactly on the surface. A displacement is a vector in the
 * plane of the particle's triangle. `Walk` moves along it in barycentric
 * coordinates (the gradients of the barycentrics give their rate of change); where
 * the path leaves the triangle it stops on the edge, continues in the neighbour
 * across that edge and turns the rest of the displacement about the shared edge
 * into the neighbour's plane (the unfolding of the two triangles into one plane,
 * read backwards). The composed turns, `Frame`, carry vectors of the start
 * triangle's plane to the end triangle's, so a Runge-Kutta scheme can bring the
 * slopes it samples elsewhere back into the plane where it started.
 *
 * Edges with one triangle (the boundary of an open surface), edges shared by more
 * than two triangles and edges of triangles of zero area are boundaries: a walk
 * that reaches one stops there.
 */

#ifndef vtkOFBTriangleWalker_h
#define vtkOFBTriangleWalker_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

class vtkDataArray;

/// A point on the surface: a triangle of the walker and barycentric coordinates.
struct vtkOFBSurfacePoint
{
  vtkIdType Triangle = -1;
  glm::dvec3 Bary{ 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 };
};

class vtkOFBTriangleWalker
{
public:
  /// How a walk ended.
  enum WalkResult
  {
    Inside = 0,   ///< the whole displacement was travelled
    Boundary = 1, ///< stopped on a boundary edge
    Stuck = 2     ///< too many edge crossings for one displacement (stopped where it was)
  };

  /**
   * Take the triangles of `surface` (every polygon must be a triangle: run
   * vtkTriangleFilter first) and its point `vectors` (3 components, or null for a
   * zero field). Returns false with `error` set when there is no triangle of
   * non-zero area. Triangles of zero area are left out; the others keep their
   * order.
   */
  bool Build(vtkPolyData* surface, vtkDataArray* vectors, std::string& error);

  /// The triangles of the walker (the same points, only its triangles) for a locator.
  vtkPolyData* GetTriangles() const { return this->Triangles; }

  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Corners.size() / 3);
  }

  /// The largest length of a point vector.
  double GetMaximumSpeed() const { return this->MaximumSpeed; }

  /// The total area of the triangles.
  double GetArea() const { return this->Area.empty() ? 0.0 : this->Area.back(); }

  /// Point id of corner `i` (0..2) of triangle `t`.
  vtkIdType GetCorner(vtkIdType t, int i) const { return this->Corners[3 * t + i]; }

  /// Unit normal of triangle `t`.
  const glm::dvec3& GetNormal(vtkIdType t) const { return this->Normals[t]; }

  /// World position of a surface point.
  glm::dvec3 Position(const vtkOFBSurfacePoint& p) const
  {
    const vtkIdType* c = &this->Corners[3 * p.Triangle];
    return p.Bary[0] * this->Points[c[0]] + p.Bary[1] * this->Points[c[1]] +
      p.Bary[2] * this->Points[c[2]];
  }

  /// The field at a surface point, projected into its triangle's plane (world units).
  glm::dvec3 Field(const vtkOFBSurfacePoint& p) const
  {
    const vtkIdType* c = &this->Corners[3 * p.Triangle];
    const glm::dvec3 v = p.Bary[0] * this->Vectors[c[0]] + p.Bary[1] * this->Vectors[c[1]] +
      p.Bary[2] * this->Vectors[c[2]];
    const glm::dvec3& n = this->Normals[p.Triangle];
    return v - glm::dot(v, n) * n;
  }

  /// Barycentric interpolation of a point array's component at a surface point.
  double Interpolate(vtkDataArray* array, int component, const vtkOFBSurfacePoint& p) const;

  /**
   * Move `p` by `d` (a vector in the plane of p's triangle, world units). When
   * `frame` is given it is multiplied from the left by every turn the walk makes,
   * so that `frame` maps vectors of the start plane to the end plane.
   */
  WalkResult Walk(vtkOFBSurfacePoint& p, glm::dvec3 d, glm::dmat3* frame) const;

  /**
   * The surface point of triangle `t` closest to `x` (barycentrics of the
   * projection of x on the plane, clamped to the triangle).
   */
  vtkOFBSurfacePoint Locate(vtkIdType t, const double x[3]) const;

  /**
   * An area-uniform surface point from three numbers uniform in [0, 1).
   */
  vtkOFBSurfacePoint Sample(double u0, double u1, double u2) const;

private:
  void BuildGeometry();
  void BuildAdjacency();

  vtkSmartPointer<vtkPolyData> Triangles;
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Vectors;
  std::vector<vtkIdType> Corners;          // 3 point ids per triangle
  std::vector<vtkIdType> Neighbors;        // across the edge opposite corner i; -1 boundary
  std::vector<signed char> NeighborCorner; // that edge's opposite corner in the neighbour
  std::vector<glm::dvec3> Normals;         // unit normal per triangle
  std::vector<glm::dvec3> Gradients;       // 3 per triangle: gradients of the barycentrics
  std::vector<glm::dvec3> EdgeOut;         // 3 per triangle: unit in-plane normal out of edge i
  std::vector<double> Area;                // running sum of triangle areas
  double MaximumSpeed = 0.0;
};

#endif
