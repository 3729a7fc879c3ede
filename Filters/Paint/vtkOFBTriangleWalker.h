/**
 * @class   vtkOFBTriangleWalker
 * @brief   Moves points over a triangle surface along a tangent field
 *
 * Shared by the decal patch (OFB::Paint) and the particle advector (OFB::FlowPaths):
 * installed, not wrapped.
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
 * Vectors of a walk are 2-D, in an orthonormal frame of each triangle's plane: a
 * flat record per triangle (vtkOFBWalkerTriangle, one cache line) holds what a
 * walk reads, and each shared edge has its turn from one frame to the other
 * (vtkOFBWalkerTurn), all made once per input.
 *
 * Points at the same position are one point (a mesh may repeat its points per face, as
 * an OBJ with texture coordinates does): triangles that share an edge's positions are
 * neighbours, whatever the point ids. With a merge tolerance (Build's `mergeTolerance`),
 * points closer than it are one point too (pieces of a surface made apart, such as those
 * of vtkSphereSource, repeat their seam points a rounding error apart); each triangle
 * keeps its own corners' positions. Edges with one triangle (the boundary of an open
 * surface), edges shared by more than two triangles and edges of triangles of zero area
 * are boundaries: a walk that reaches one stops there.
 */

#ifndef vtkOFBTriangleWalker_h
#define vtkOFBTriangleWalker_h

#include "vtkOFBPaintModule.h" // for export macro
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

/**
 * One triangle as a walk reads it, in the triangle's own 2-D frame (an orthonormal
 * basis of its plane), in one cache line: the gradients of two barycentrics (the
 * third is minus their sum), the corner vectors projected into the plane and the
 * neighbours across the edges. Single precision: these are rates and directions
 * (relative error 6e-8); positions stay double barycentrics of double corners, so
 * a particle stays exactly on the surface. The turns across the edges are in a
 * separate array (vtkOFBWalkerTurn), read only when a walk crosses an edge.
 */
struct alignas(64) vtkOFBWalkerTriangle
{
  glm::vec2 Gradient[2]; ///< gradients of barycentrics 0 and 1 (1 / height, towards the corner)
  glm::vec2 Vector[3];   ///< the field at corner i, projected (world units)
  int Next[3];           ///< the neighbour across the edge opposite corner i; -1 boundary
  /// Per edge: bits 0-1 that edge's opposite corner in the neighbour, bits 2-3 where
  /// corner (i + 1) % 3 is in the neighbour, bit 4 the turn is a reflection.
  unsigned char Link[3];

  int Opposite(int i) const { return this->Link[i] & 3; }
  int NextA(int i) const { return (this->Link[i] >> 2) & 3; }
  bool Reflect(int i) const { return (this->Link[i] & 16) != 0; }

  /// The rates of change of the three barycentrics along `d`.
  glm::dvec3 Rates(const glm::dvec2& d) const
  {
    const double r0 = this->Gradient[0][0] * d[0] + this->Gradient[0][1] * d[1];
    const double r1 = this->Gradient[1][0] * d[0] + this->Gradient[1][1] * d[1];
    return glm::dvec3(r0, r1, -(r0 + r1));
  }
};

/**
 * The turns from a triangle's frame to each neighbour's across its edges (the
 * unfolding about the shared edge: a rotation by (cos, sin), or a reflection where
 * the neighbour's normal points the other way, see vtkOFBWalkerTriangle::Link).
 */
struct vtkOFBWalkerTurn
{
  glm::vec2 Turn[3];

  /// The turn across edge i (a reflection when `reflect`) applied to a vector.
  glm::dvec2 Apply(int i, bool reflect, const glm::dvec2& v) const
  {
    const glm::dvec2 cs(this->Turn[i]);
    const glm::dvec2 second = reflect ? glm::dvec2(cs[1], -cs[0]) : glm::dvec2(-cs[1], cs[0]);
    return v[0] * cs + v[1] * second;
  }
};

/**
 * Walks of several points at once (vtkOFBTriangleWalker::Walk of lanes), in
 * structure-of-arrays form: the lanes' triangles, barycentrics, displacements and
 * frames (the columns of Walk's `frame`: (Frame[0], Frame[1]) and (Frame[2],
 * Frame[3])), and how each walk ended.
 */
struct vtkOFBWalkLanes
{
  static constexpr int Size = 16;
  int Count = 0;
  vtkIdType Triangle[Size];
  double Bary[3][Size];
  double D[2][Size];
  double Frame[4][Size];
  int Result[Size];

  /// Lane `j` starts at `p` with displacement `d` and the identity frame.
  void Set(int j, const vtkOFBSurfacePoint& p, double dx, double dy)
  {
    this->Triangle[j] = p.Triangle;
    for (int i = 0; i < 3; ++i)
    {
      this->Bary[i][j] = p.Bary[i];
    }
    this->D[0][j] = dx;
    this->D[1][j] = dy;
    this->Frame[0][j] = 1.0;
    this->Frame[1][j] = 0.0;
    this->Frame[2][j] = 0.0;
    this->Frame[3][j] = 1.0;
  }

  /// Where lane `j` ended.
  void Get(int j, vtkOFBSurfacePoint& p) const
  {
    p.Triangle = this->Triangle[j];
    p.Bary = glm::dvec3(this->Bary[0][j], this->Bary[1][j], this->Bary[2][j]);
  }
};

class VTKOFBPAINT_EXPORT vtkOFBTriangleWalker
{
public:
  /// How a walk ended.
  enum WalkResult
  {
    WALK_INSIDE = 0,   ///< the whole displacement was travelled
    WALK_BOUNDARY = 1, ///< stopped on a boundary edge
    WALK_STUCK = 2     ///< too many edge crossings for one displacement (stopped where it was)
  };

  /**
   * Take the triangles of `surface` (every polygon must be a triangle: run
   * vtkTriangleFilter first; `polygonCells`, if given, names the cell each of its
   * polygons came from, see SetCellVectors) and its point `vectors` (3 components, or null for a
   * zero field, else at least a tuple a point). Returns false with `error` set when a
   * cell names a point that does not exist, the vectors are short, or there is no
   * triangle of non-zero area. Triangles of zero area are left out; the others keep
   * their order. Points closer than `mergeTolerance` (world units; default 0: only
   * points at exactly the same position) are one point for the triangles' adjacency.
   */
  bool Build(vtkPolyData* surface,
    vtkDataArray* vectors,
    std::string& error,
    const vtkIdType* polygonCells = nullptr,
    double mergeTolerance = 0.0);

  /**
   * Replace the field by cell vectors `vectors` (3 doubles per cell of the
   * polygonCells given to Build, world units): each triangle carries its cell's
   * vector at its three corners, projected into its plane (a cell value holds on its
   * triangles); and the largest speed.
   */
  void SetCellVectors(const double* vectors);

  /**
   * Replace the field, on the same surface, by the point vectors `vectors` (3
   * doubles a point, world units, as many points as the surface Build took): each
   * triangle's corner vectors projected into its plane, and the largest speed.
   * For a field that changes in time on a fixed surface (no rebuild).
   */
  void SetPointVectors(const double* vectors);

  /// The triangles of the walker (the same points, only its triangles) for a locator.
  vtkPolyData* GetTriangles() const { return this->Triangles; }

  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Corners.size() / 3);
  }

  /// What a walk reads of triangle `t` (for the batched stages of the stepper).
  const vtkOFBWalkerTriangle& GetRecord(vtkIdType t) const { return this->Records[t]; }

  /// The largest length of a point vector.
  double GetMaximumSpeed() const { return this->MaximumSpeed; }

  /// The total area of the triangles.
  double GetArea() const { return this->Area.empty() ? 0.0 : this->Area.back(); }

  /// Point id of corner `i` (0..2) of triangle `t`.
  vtkIdType GetCorner(vtkIdType t, int i) const { return this->Corners[3 * t + i]; }

  /// The smallest id of the points that are one point of the surface with point `i`.
  vtkIdType GetPointKey(vtkIdType i) const { return this->Canonical[i]; }

  /// Unit normal of triangle `t`.
  const glm::dvec3& GetNormal(vtkIdType t) const { return this->Normals[t]; }

  /// World position of a surface point.
  glm::dvec3 Position(const vtkOFBSurfacePoint& p) const
  {
    const glm::dvec3* c = &this->CornerPoints[3 * p.Triangle];
    return p.Bary[0] * c[0] + p.Bary[1] * c[1] + p.Bary[2] * c[2];
  }

  /// The field at a surface point in its triangle's 2-D frame (world units).
  glm::dvec2 Field2(const vtkOFBSurfacePoint& p) const
  {
    const vtkOFBWalkerTriangle& t = this->Records[p.Triangle];
    return p.Bary[0] * glm::dvec2(t.Vector[0]) + p.Bary[1] * glm::dvec2(t.Vector[1]) +
      p.Bary[2] * glm::dvec2(t.Vector[2]);
  }

  /// The field at a surface point, projected into its triangle's plane (world units).
  glm::dvec3 Field(const vtkOFBSurfacePoint& p) const
  {
    return this->To3D(p.Triangle, this->Field2(p));
  }

  /// A vector of triangle `t`'s 2-D frame in world coordinates.
  glm::dvec3 To3D(vtkIdType t, const glm::dvec2& v) const
  {
    return v[0] * this->Axes[2 * t] + v[1] * this->Axes[2 * t + 1];
  }

  /**
   * Ask the processor to fetch what a step of a particle in triangle `t` reads
   * (its record and corners), ahead of the step: the particles of a step are
   * spread over the surface, so these are rarely in the cache otherwise.
   */
  void Prefetch(vtkIdType t) const
  {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(&this->Records[t]);
#endif
    this->PrefetchCorners(t);
  }

  /// Fetch ahead the corner positions of `t` (for `Position`).
  void PrefetchCorners(vtkIdType t) const
  {
#if defined(__GNUC__) || defined(__clang__)
    const char* c = reinterpret_cast<const char*>(&this->CornerPoints[3 * t]);
    __builtin_prefetch(c);
    __builtin_prefetch(c + 64);
#else
    (void)t;
#endif
  }

  /// Fetch ahead what a walk reads of the neighbours of `t` (where it may go next).
  void PrefetchNeighbors(vtkIdType t) const
  {
#if defined(__GNUC__) || defined(__clang__)
    const vtkOFBWalkerTriangle& r = this->Records[t];
    for (int i = 0; i < 3; ++i)
    {
      if (r.Next[i] >= 0)
      {
        __builtin_prefetch(&this->Records[r.Next[i]]);
      }
    }
    __builtin_prefetch(&this->Turns[t]);
#else
    (void)t;
#endif
  }

  /// Barycentric interpolation of a point array's component at a surface point.
  double Interpolate(vtkDataArray* array, int component, const vtkOFBSurfacePoint& p) const;

  /**
   * Move `p` by `d` when the path stays inside p's triangle (the common case of a
   * short step) and return true, as `Walk` would; otherwise leave `p` as it is and
   * return false. Inline, so that a step that crosses no edge makes no call.
   */
  bool WalkInside(vtkOFBSurfacePoint& p, const glm::dvec2& d) const
  {
    const glm::dvec3 db = this->Records[p.Triangle].Rates(d);
    // The same test as Walk's for the first edge met before the end of d.
    for (int i = 0; i < 3; ++i)
    {
      if (db[i] < 0.0 && p.Bary[i] < -db[i])
      {
        return false;
      }
    }
    p.Bary = glm::max(p.Bary + db, glm::dvec3(0.0));
    return true;
  }

  /**
   * Move `p` by `d` (a vector of p's triangle's 2-D frame, world units). When
   * `frame` is given it is multiplied from the left by every turn the walk makes,
   * so that `frame` maps vectors of the start frame to the end frame.
   */
  WalkResult Walk(vtkOFBSurfacePoint& p, glm::dvec2 d, glm::dmat2* frame) const;

  /**
   * The walks of `lanes.Count` lanes, each as `Walk` (the same results bit for
   * bit; the frames only when `withFrame`), interleaved: each round makes one edge
   * crossing of every lane still walking, so the processor overlaps the dependent
   * loads and divisions of different walks instead of waiting on one at a time.
   */
  void Walk(vtkOFBWalkLanes& lanes, bool withFrame) const;

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
  /// One round of Walk's loop for lane `j`; true when its walk ended.
  bool CrossLane(vtkOFBWalkLanes& lanes, int j, bool withFrame) const;
  void BuildGeometry();
  void BuildAdjacency(double mergeTolerance);
  /// Joins the canonical ids of points closer than `tolerance` (the smallest id names each).
  void MergeClosePoints(double tolerance);
  /// Edge `edge` of `t` is shared with edge `opposite` of `next`.
  void Link(vtkIdType t, int edge, vtkIdType next, int opposite);

  vtkSmartPointer<vtkPolyData> Triangles;
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Vectors;
  std::vector<vtkIdType> Corners;   // 3 point ids per triangle
  std::vector<vtkIdType> Cells;     // per triangle, its cell (Build's polygonCells)
  std::vector<vtkIdType> Canonical; // per point, the smallest id at its position (adjacency)
  std::vector<vtkOFBWalkerTriangle> Records; // what a walk reads
  std::vector<vtkOFBWalkerTurn> Turns;       // the turns across the edges
  std::vector<glm::dvec2> Gradients;         // 3 per triangle, double, while building
  std::vector<glm::dvec3> CornerPoints;      // 3 per triangle: its corners' positions
  std::vector<glm::dvec3> Normals;           // unit normal per triangle
  std::vector<glm::dvec3> Axes;              // 2 per triangle: the 2-D frame in world space
  std::vector<double> Area;                  // running sum of triangle areas
  double MaximumSpeed = 0.0;
};

#endif
