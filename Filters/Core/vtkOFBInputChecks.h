// Installed helper header (not wrapped): the checks that the filters of every module
// make on a vtkPolyData input before they index into it. vtkPolyData enforces neither
// that its cells name existing points nor that its arrays have a tuple per point or
// cell; a reader of a hostile file (an OBJ with `f 1 2 99999`) or a hand-built
// vtkCellArray gives such data, and reading it is out of bounds. Each check returns
// false and sets `error` to a phrase naming the first problem; the filter prefixes the
// input it checked and gives an empty output.
#ifndef vtkOFBInputChecks_h
#define vtkOFBInputChecks_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkOFBArrayLength.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <sstream>
#include <string>

namespace vtkOFBInputChecksDetail
{
/**
 * The index of the first entry of `ids[0, n)` outside [0, points), or -1. The common
 * case (all valid) is one pass of a minimum and a maximum, which vectorizes; the
 * search for the first bad entry runs only when there is one.
 */
template<typename IdT>
vtkIdType FirstBadId(const IdT* ids, vtkIdType n, vtkIdType points)
{
  IdT lo = 0;
  IdT hi = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    lo = std::min(lo, ids[i]);
    hi = std::max(hi, ids[i]);
  }
  if (lo >= 0 && (n == 0 || static_cast<vtkIdType>(hi) < points))
  {
    return -1;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (ids[i] < 0 || static_cast<vtkIdType>(ids[i]) >= points)
    {
      return i;
    }
  }
  return -1;
}

/**
 * Check one cell array of `points` points, whose cells are named `kind` and whose first
 * cell has id `firstCell` in the dataset: offsets from 0 to the connectivity's size,
 * never decreasing, and every connectivity entry a point id in [0, points).
 */
template<typename ArrayT>
bool CheckCells(ArrayT* offsetsArray,
  ArrayT* connectivityArray,
  vtkIdType points,
  const char* kind,
  vtkIdType firstCell,
  std::string& error)
{
  using IdT = typename ArrayT::ValueType;
  const vtkIdType nOffsets = offsetsArray->GetNumberOfValues();
  const vtkIdType nIds = connectivityArray->GetNumberOfValues();
  const IdT* offsets = offsetsArray->GetPointer(0);
  const IdT* ids = connectivityArray->GetPointer(0);
  // The offsets (one more than the cells) delimit the cells in the connectivity: a
  // cell array built by hand (SetData) may have them wrong, and then every traversal
  // reads out of bounds.
  bool offsetsValid =
    nOffsets >= 1 && offsets[0] == 0 && static_cast<vtkIdType>(offsets[nOffsets - 1]) == nIds;
  for (vtkIdType c = 1; offsetsValid && c < nOffsets; ++c)
  {
    offsetsValid = offsets[c] >= offsets[c - 1];
  }
  if (!offsetsValid)
  {
    std::ostringstream os;
    os << "its " << kind << " cell array is inconsistent (offsets that do not run from 0 up to "
       << "the " << nIds << " connectivity entries)";
    error = os.str();
    return false;
  }
  const vtkIdType bad = FirstBadId(ids, nIds, points);
  if (bad < 0)
  {
    return true;
  }
  // The cell holding entry `bad`: the last whose offset is at most `bad`.
  const vtkIdType cell =
    static_cast<vtkIdType>(
      std::upper_bound(offsets, offsets + nOffsets, static_cast<IdT>(bad)) - offsets) -
    1;
  std::ostringstream os;
  os << kind << " " << cell << " (cell " << firstCell + cell << ") names point id "
     << static_cast<vtkIdType>(ids[bad]) << ", not in [0, " << points << ")";
  error = os.str();
  return false;
}
}

/**
 * Whether every cell of `data` (vertices, lines, polygons and strips) names only points
 * that exist, ids in [0, number of points), and its cell arrays are consistent. One
 * pass over each connectivity array. False with `error` set to, for example,
 * "polygon 3 (cell 3) names point id 99998, not in [0, 3)".
 */
inline bool vtkOFBCheckCellPointIds(vtkPolyData* data, std::string& error)
{
  if (!data)
  {
    error = "there is no input";
    return false;
  }
  const vtkIdType points = data->GetNumberOfPoints();
  struct Part
  {
    vtkCellArray* Cells;
    const char* Kind;
  };
  // In vtkPolyData's cell order, so that the cell ids in messages are the dataset's.
  const Part parts[4] = { { data->GetVerts(), "vertex" },
    { data->GetLines(), "line" },
    { data->GetPolys(), "polygon" },
    { data->GetStrips(), "strip" } };
  vtkIdType firstCell = 0;
  for (const Part& part : parts)
  {
    vtkCellArray* cells = part.Cells;
    if (!cells)
    {
      continue;
    }
    const bool valid = cells->IsStorage64Bit()
      ? vtkOFBInputChecksDetail::CheckCells(cells->GetOffsetsArray64(),
          cells->GetConnectivityArray64(),
          points,
          part.Kind,
          firstCell,
          error)
      : vtkOFBInputChecksDetail::CheckCells(cells->GetOffsetsArray32(),
          cells->GetConnectivityArray32(),
          points,
          part.Kind,
          firstCell,
          error);
    if (!valid)
    {
      return false;
    }
    firstCell += cells->GetNumberOfCells();
  }
  return true;
}

/**
 * Whether `array` has at least `needed` tuples (one per `what`: "points", "cells",
 * "stroke points"...) of at least `components` components. An absent array (null)
 * passes: callers that need one check for it first. False with `error` set to
 * "'Radius' has 2 tuples for 3 stroke points" (or the components wanted).
 */
inline bool vtkOFBCheckArrayLength(vtkAbstractArray* array,
  vtkIdType needed,
  const char* what,
  std::string& error,
  int components = 1)
{
  if (!array)
  {
    return true;
  }
  if (array->GetNumberOfTuples() < needed)
  {
    error = vtkOFBArrayLength(array, needed, what);
    return false;
  }
  if (array->GetNumberOfComponents() < components)
  {
    std::ostringstream os;
    os << "'" << (array->GetName() ? array->GetName() : "(unnamed)") << "' has "
       << array->GetNumberOfComponents() << " components, fewer than " << components;
    error = os.str();
    return false;
  }
  return true;
}

/**
 * Whether each point array of `data` has a tuple per point and each cell array a tuple
 * per cell: what a filter copying its input's attributes (vtkDataSetAttributes::CopyData)
 * reads. False with `error` naming the first short array.
 */
inline bool vtkOFBCheckAttributeArrays(vtkPolyData* data, std::string& error)
{
  vtkPointData* pd = data->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    if (!vtkOFBCheckArrayLength(
          pd->GetAbstractArray(i), data->GetNumberOfPoints(), "points", error))
    {
      error = "the point array " + error;
      return false;
    }
  }
  vtkCellData* cd = data->GetCellData();
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
  {
    if (!vtkOFBCheckArrayLength(cd->GetAbstractArray(i), data->GetNumberOfCells(), "cells", error))
    {
      error = "the cell array " + error;
      return false;
    }
  }
  return true;
}

#endif
