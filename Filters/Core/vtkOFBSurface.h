/**
 * @class   vtkOFBSurface
 * @brief   A triangle surface prepared for OFB construction (for backends)
 *
 * vtkOFBSampler fills it from its input vtkPolyData and hands it to the backend
 * that builds the OFB (vtkOFBSamplerBackend): finite points, triangles of
 * non-zero area, unit point normals, the point arrays to interpolate into the
 * samples and the cell arrays whose values the samples take from the input cell
 * of their triangle. Backends only read it.
 *
 * Not for applications: the header is installed (not wrapped) so that backends
 * in other modules (the OpenGL one of vtkOFBBuilder) can read the surface.
 *
 * @sa vtkOFBSamplerBackend vtkOFBSampler
 */

#ifndef vtkOFBSurface_h
#define vtkOFBSurface_h

#include "vtkDataArray.h"         // for Arrays
#include "vtkSmartPointer.h"      // for members
#include "vtkUnsignedCharArray.h" // for Colors

#include <vector> // for members

class vtkOFBSurface
{
public:
  /// Point coordinates, 3 per point.
  std::vector<double> Points;
  /// Point ids, 3 per triangle; only triangles of non-zero area.
  std::vector<vtkIdType> Triangles;
  /// Unit point normals, 3 per point (zero where a point has no area around it).
  std::vector<float> Normals;
  /// The tangent vector field (a vtkFloatArray, 3 components), or null.
  vtkSmartPointer<vtkDataArray> Vectors;
  /// The initial paint, 3 or 4 unsigned-char components, or null for DefaultColor.
  vtkSmartPointer<vtkUnsignedCharArray> Colors;
  /**
   * Other arrays of the samples (array-of-structures layout): point arrays, to
   * interpolate, and cell arrays (ArraysPerCell), copied from the cell of each
   * sample's triangle.
   */
  std::vector<vtkSmartPointer<vtkDataArray>> Arrays;
  /// Whether Arrays[k] is a cell array (one tuple per input cell); empty: none is.
  std::vector<bool> ArraysPerCell;
  /// The input cell id of each triangle; filled only when Arrays has cell arrays.
  std::vector<vtkIdType> TriangleCells;
  /// TCoords array among Arrays, or -1.
  int TCoordsIndex = -1;
  /// The cell array among Arrays that becomes the samples' active vectors, or -1.
  int CellVectorsIndex = -1;
  /// The cell array among Arrays that becomes the samples' active scalars, or -1.
  int CellScalarsIndex = -1;
  /// Paint of the samples when Colors is null, RGBA.
  unsigned char DefaultColor[4] = { 255, 255, 255, 255 };
  /// Whether the vector field is projected into the tangent plane of each sample.
  bool ProjectVectors = true;
  /// Bounds of the points used by the triangles.
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Points.size() / 3); }

  /// The input cell id per triangle to read Arrays[k] through, or null for a point array.
  const vtkIdType* GetArrayCells(size_t k) const
  {
    return k < this->ArraysPerCell.size() && this->ArraysPerCell[k] ? this->TriangleCells.data()
                                                                    : nullptr;
  }

  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Triangles.size() / 3);
  }
};

#endif
