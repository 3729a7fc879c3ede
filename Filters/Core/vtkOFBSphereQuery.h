/**
 * @class   vtkOFBSphereQuery
 * @brief   The sphere queries of a vtkOFB: rows of cells under a sphere, pipelined
 *
 * vtkOFBSphereQuery is the machinery behind vtkOFB::ForEachSampleInSphere and
 * vtkOFB::ForEachSampleInSpheres; use those. A sphere's candidates are, on each grid,
 * the rows of cells under its projection (a disc), each row only over the circle's
 * chord; a row's samples are consecutive in memory, so a row is one range of sample
 * ids. The rows are software-pipelined: a row's cell offsets and then its samples are
 * prefetched while earlier rows are visited.
 *
 * A query takes the frame and the raw arrays of its OFB once, as a locator takes its
 * data set, and lives for the duration of one call of vtkOFB's query methods: the OFB
 * must not be rebuilt while it is in use. Everything is inline (the visitors are
 * templates called for every sample): no allocation, no virtual call.
 *
 * Installed, not wrapped, because vtkOFB.h's templated queries need it; not part of
 * the user-facing API.
 *
 * @sa vtkOFB
 */

#ifndef vtkOFBSphereQuery_h
#define vtkOFBSphereQuery_h

#include "vtkOFB.h"         // for the frame and arrays read by the query
#include "vtkOFBPrefetch.h" // for VTKOFB_PREFETCH
#include "vtkType.h"        // for vtkIdType, vtkTypeUInt32

class vtkOFBSphereQuery
{
public:
  /// The frame and arrays of `ofb`, read once.
  explicit vtkOFBSphereQuery(const vtkOFB& ofb);

  /**
   * Call `f(id, squaredDistance)` for every sample within `radius` of `center`, and
   * `prefetch(first, last)` a row ahead (see vtkOFB::ForEachSampleInSphere).
   */
  template<typename Functor, typename Prefetch>
  void ForEachSampleInSphere(const double center[3],
    double radius,
    Functor& f,
    Prefetch& prefetch) const;

  /**
   * Spheres [0, n) set by `sphere(k, center, radius)`, `f(k, id, squaredDistance)`
   * for their samples (see vtkOFB::ForEachSampleInSpheres).
   */
  template<typename Sphere, typename Functor, typename Prefetch>
  void ForEachSampleInSpheres(vtkIdType n, Sphere& sphere, Functor& f, Prefetch& prefetch) const;

private:
  /// One row of cells [u0, u1] of a sphere query on grid `a`.
  struct Row
  {
    vtkIdType RowBase; // global id of cell u = 0 of the row
    vtkIdType U0, U1;
    vtkIdType First, Last; // the samples of cells [U0, U1] (set by FetchRow)
    double UCentre;        // the centre's u, world units relative to cell 0's centre
    double D;              // the centre's depth relative to the origin
    double DV2;            // squared distance of the row from the centre in v
    double DHigh;
    double R2;
    float DLow;
    int UAxis;
    // The OFB's arrays, taken once per sphere and grid (not per row).
    const vtkTypeUInt32* Offsets;
    const float* Depths;
    const vtkTypeUInt32* CellOf; // null without a cell index
  };

  /// The cells of grid `a` under a sphere's bounding box, and what its rows share.
  struct Grid
  {
    vtkIdType U0, U1, V0, V1, NU;
    double CU; // the centre's u in cell units
    double InverseCellSize;
    double CV; // the centre's v, world units
    int VAxis;
    Row Base;
  };

  /// False if the sphere's box misses grid `a`.
  bool BeginGrid(int a, const double center[3], double radius, Grid& grid) const;

  /// Row `iv` of the grid, only the cells under the circle's chord (its cell offsets
  /// prefetched); false if it misses.
  bool Chord(const Grid& grid, vtkIdType iv, Row& row) const;

  /// Read the row's sample range, prefetch its depths and cell indices, and hand its
  /// first samples (up to 512) to the caller's `prefetch(first, last)`.
  template<typename Prefetch>
  void FetchRow(Row& row, Prefetch& prefetch) const;

  ///@{
  /// Visit the samples of a fetched row: by a scan of them all, or cell by cell.
  template<typename Functor>
  void ForEachSampleInRow(const Row& row, Functor& f) const;
  template<typename Functor>
  void ForEachSampleInRowScan(const Row& row, Functor& f) const;
  template<typename Functor>
  void ForEachSampleInRowCells(const Row& row, Functor& f) const;
  ///@}

  /// Index of the first sample of [begin, end) whose depth is >= d.
  vtkIdType LowerBound(vtkIdType begin, vtkIdType end, float d) const;

  double Origin[3];
  double CellSize;
  vtkIdType Dimensions[3];
  vtkIdType CellBase[4];
  vtkIdType NumberOfSamples;
  const vtkTypeUInt32* Offsets;
  const float* Depths;
  const vtkTypeUInt32* CellOf; // null without a cell index
};

#include "vtkOFBSphereQuery.txx" // IWYU pragma: export

#endif
