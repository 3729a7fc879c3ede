/**
 * @class   vtkOFBSurface
 * @brief   A triangle surface prepared for OFB construction (private)
 *
 * vtkOFBSampler::PrepareSurface fills it from a vtkPolyData: finite points,
 * non-degenerate triangles, unit point normals and the arrays to interpolate. The
 * CPU and OpenGL backends both sample from it.
 */

#ifndef vtkOFBSurface_h
#define vtkOFBSurface_h

#include "vtkDataArray.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <string>
#include <vector>

class vtkOFBSurface
{
public:
  /// Point coordinates, 3 per point.
  std::vector<double> Points;
  /// Point ids, 3 per triangle; only triangles of non-zero area.
  std::vector<vtkIdType> Triangles;
  /// Unit point normals, 3 per point (zero where a point has no area around it).
  std::vector<float> Normals;
  /// The tangent vector field, 3 components, or null.
  vtkSmartPointer<vtkDataArray> Vectors;
  /// The initial paint, 3 or 4 unsigned-char components, or null for DefaultColor.
  vtkSmartPointer<vtkUnsignedCharArray> Colors;
  /// Other point arrays to interpolate (array-of-structures layout).
  std::vector<vtkSmartPointer<vtkDataArray>> Arrays;
  /// TCoords array among Arrays, or -1.
  int TCoordsIndex = -1;
  unsigned char DefaultColor[4] = { 255, 255, 255, 255 };
  bool ProjectVectors = true;
  /// Bounds of the points used by the triangles.
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };

  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Triangles.size() / 3);
  }
};

#endif
