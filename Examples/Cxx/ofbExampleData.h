/**
 * @file   ofbExampleData.h
 * @brief  The one way the example applications open data: meshes and simulation results
 *
 * OFBPaint, OFBLIC, OFBParticles and OFBDemo read their input through ReadDataSurface:
 *
 * - The format is chosen by the file's content, else by its extension: a VTK XML file
 *   (`<VTKFile type="...">`: .vtp, .vtu, .vti, .vts, .vtr, .vtm, read by
 *   vtkXMLGenericDataObjectReader), a ParaView data collection (.pvd, `type="Collection"`:
 *   its DataSet entries, each a time step and a part), a legacy VTK file ("# vtk DataFile",
 *   vtkGenericDataObjectReader), PLY ("ply"), STL (binary by its size, or "solid") and OBJ.
 *   Meshes (OBJ, PLY, STL) go through the checks of ReadMeshChecked (ofbExampleMesh.h).
 * - Blocks (`--block LIST`): of a multiblock file (.vtm, a legacy multiblock) or the parts
 *   of a .pvd step, by flat index (vtkDataObjectTreeIterator's, counted over the leaves
 *   and their parents as vtkCompositeDataSet does) or by name; default all.
 * - Time (`--time T`: the step whose time is closest to T; `--time-step N`: the Nth, from
 *   0): of a .pvd, or of a reader that reports time steps. A value outside the file's
 *   range, or a time asked of a file without time steps, is an error naming the range.
 * - The chosen blocks of a composite file become one surface through vtkOFBMergeBlocks,
 *   as vtkOFBSampler merges a composite input into one OFB: a cell array "BlockIndex"
 *   holding each block's flat index (a sample array in the OFB), the points shared by
 *   blocks merged, the union of the blocks' arrays. A single data set gives its polygons
 *   or its outer surface.
 * - The field (`--field NAME`): a point or a cell array of that name (point first). A
 *   file without it is an error that lists the arrays the file has (vectors first).
 *
 * Every failure is a message ("cannot read 'PATH': ...") and a null result, never a crash.
 */
#ifndef ofbExampleData_h
#define ofbExampleData_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDataArray;
class vtkPolyData;

namespace ofbexample
{
/// The data options of the applications (--field, --block, --time, --time-step).
struct DataOptions
{
  std::string Field;  ///< the array to use; "" for the application's default
  std::string Blocks; ///< comma-separated flat indices or names; "" for all
  bool HasTime = false;
  double Time = 0.0; ///< with HasTime: the step whose time is closest
  int TimeStep = -1; ///< >= 0: the step by its index
};

/// The usage line of the data options.
const char* DataOptionsUsage();

/**
 * If argv[i] is a data option, read it (and its value, advancing i) into `options` and
 * return true; `ok` becomes false when its value is missing or not a number.
 */
bool ParseDataOption(int argc, char* argv[], int& i, DataOptions& options, bool& ok);

/// The surface read, and where its field is.
struct DataSurface
{
  vtkSmartPointer<vtkPolyData> Surface;
  vtkDataArray* Field = nullptr; ///< options.Field's array in the surface, or null
  bool FieldOnCells = false;     ///< whether Field is a cell array
  std::string Summary;           ///< what was read: format, blocks, time step
};

/**
 * The data at `path` as one surface (polygons; see the file comment), with options'
 * blocks, time step and field; false with `message` the reason. With `vectors`, the field
 * must have 3 components.
 */
bool ReadDataSurface(const std::string& path,
  const DataOptions& options,
  bool vectors,
  DataSurface& data,
  std::string& message);

/// As ReadDataSurface, then triangles (lines and vertices dropped) with point normals.
bool ReadDataTriangles(const std::string& path,
  const DataOptions& options,
  bool vectors,
  DataSurface& data,
  std::string& message);

/**
 * ReadDataSurface (with `triangles`, ReadDataTriangles) as the applications report it:
 * "read PATH: SUMMARY" on the standard output, or false after "APPLICATION: REASON" on
 * the standard error.
 */
bool ReadDataReported(const char* application,
  const std::string& path,
  const DataOptions& options,
  bool vectors,
  bool triangles,
  DataSurface& data);

/// The arrays of `surface` for a message: "point vectors: A, B; cell vectors: C; other
/// point arrays: D; other cell arrays: E" (or "no point or cell arrays").
std::string DescribeArrays(vtkPolyData* surface);

/// Make data.Field (3 components) the surface's active vectors where it lives (points or
/// cells; the other's active vectors unset, so vtkOFBSampler and vtkOFBParticleAdvector
/// take it).
void SetFieldAsVectors(DataSurface& data);

/// SetFieldAsVectors, and the field's magnitude added beside it as "Speed"; `range` the
/// magnitude's range.
void UseFieldAsVectors(DataSurface& data, double range[2]);
}

#endif
