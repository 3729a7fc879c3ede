// Installed helper of vtkOFBTextureBaker and vtkOFBTextureProjector: the triangles of a
// mesh's polygons, each polygon split into a fan from its first point.
#ifndef vtkOFBFanTriangles_h
#define vtkOFBFanTriangles_h

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <glm/vec3.hpp>

/**
 * Call `f(vtkIdType cell, const vtkIdType corner[3], const glm::dvec3 x[3])` for each
 * triangle of the fans of `mesh`'s polygons, in cell order: the polygon's id, the
 * triangle's point ids and their positions. The point ids are read unchecked: callers
 * refuse a mesh whose cells name points that do not exist first (vtkOFBCheckCellPointIds,
 * vtkOFBInputChecks.h).
 */
template<typename Functor>
void vtkOFBForEachFanTriangle(vtkPolyData* mesh, Functor&& f)
{
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  vtkIdType cell = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cell)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    cells->GetCurrentCell(npts, ids);
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      const vtkIdType corner[3] = { ids[0], ids[k], ids[k + 1] };
      glm::dvec3 x[3];
      for (int c = 0; c < 3; ++c)
      {
        double p[3];
        mesh->GetPoint(corner[c], p);
        x[c] = glm::dvec3(p[0], p[1], p[2]);
      }
      f(cell, corner, x);
    }
  }
}

#endif
