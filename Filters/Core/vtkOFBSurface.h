/**
 * @class   vtkOFBSurface
 * @brief   A triangle surface prepared for OFB construction (for backends)
 *
 * vtkOFBSampler fills it from its input vtkPolyData and hands it to the backend
 * that builds the OFB (vtkOFBSamplerBackend): finite points, triangles of
 * non-zero area, unit point normals and the point arrays to interpolate into the
 * samples. Backends only read it.
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
  /// Other point arrays to interpolate (array-of-structures layout).
  std::vector<vtkSmartPointer<vtkDataArray>> Arrays;
  /// TCoords array among Arrays, or -1.
  int TCoordsIndex = -1;
  /// Paint of the samples when Colors is null, RGBA.
  unsigned char DefaultColor[4] = { 255, 255, 255, 255 };
  /// Whether the vector field is projected into the tangent plane of each sample.
  bool ProjectVectors = true;
  /// Bounds of the points used by the triangles.
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Points.size() / 3); }

  vtkIdType GetNumberOfTriangles() const
  {
    return static_cast<vtkIdType>(this->Triangles.size() / 3);
  }
};

#endif
