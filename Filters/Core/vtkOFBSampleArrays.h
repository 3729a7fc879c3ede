/**
 * @class   vtkOFBSampleArrays
 * @brief   The sample arrays of an OFB build (private)
 *
 * Colours, normals, the vector field and the other point arrays of a prepared
 * surface, allocated for n samples (uninitialized), reusing the spare arrays of
 * the output (vtkOFB::Recycle) that fit. Both backends fill them.
 */

#ifndef vtkOFBSampleArrays_h
#define vtkOFBSampleArrays_h

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBHugePages.h"
#include "vtkOFBSurface.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cstring>
#include <vector>

struct vtkOFBSampleArrays
{
  vtkSmartPointer<vtkUnsignedCharArray> Colors;
  vtkSmartPointer<vtkFloatArray> Normals;
  vtkSmartPointer<vtkFloatArray> Vectors;
  std::vector<vtkSmartPointer<vtkDataArray>> Others;

  vtkOFBSampleArrays(const vtkOFBSurface& surface, vtkIdType n, vtkOFB* ofb)
  {
    this->Colors = vtkUnsignedCharArray::SafeDownCast(
      NewArray(ofb, vtkOFB::ColorsArrayName(), VTK_UNSIGNED_CHAR, nullptr, 4, n));
    this->Normals = vtkFloatArray::SafeDownCast(
      NewArray(ofb, vtkOFB::NormalsArrayName(), VTK_FLOAT, nullptr, 3, n));
    if (surface.Vectors)
    {
      this->Vectors = vtkFloatArray::SafeDownCast(
        NewArray(ofb, surface.Vectors->GetName(), VTK_FLOAT, nullptr, 3, n));
    }
    for (const auto& in : surface.Arrays)
    {
      this->Others.push_back(
        NewArray(ofb, in->GetName(), in->GetDataType(), in, in->GetNumberOfComponents(), n));
    }
  }

  /**
   * n tuples of a spare array of `ofb` of this name and type (and of the class of
   * `like` when given), else of a new one.
   */
  static vtkSmartPointer<vtkDataArray> NewArray(vtkOFB* ofb,
    const char* name,
    int type,
    vtkDataArray* like,
    int components,
    vtkIdType n)
  {
    vtkSmartPointer<vtkDataArray> array = ofb->TakeSpareArray(name, type, components, n);
    if (array && (!like || std::strcmp(array->GetClassName(), like->GetClassName()) == 0))
    {
      return array;
    }
    array = vtk::TakeSmartPointer(like ? like->NewInstance() : vtkDataArray::CreateDataArray(type));
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(n);
    vtkofb::AdviseHugePages(array);
    return array;
  }

  /// Hand the arrays to the sample data (of the others, only those interpolated).
  void Attach(const vtkOFBSurface& surface,
    vtkPointData* sampleData,
    const std::vector<bool>& interpolated)
  {
    // The paint is the active scalars unless a cell array takes them (added first:
    // SetScalars would remove the array it replaces).
    if (surface.CellScalarsIndex >= 0 && interpolated[surface.CellScalarsIndex])
    {
      sampleData->AddArray(this->Colors);
    }
    else
    {
      sampleData->SetScalars(this->Colors);
    }
    sampleData->SetNormals(this->Normals);
    if (this->Vectors)
    {
      sampleData->SetVectors(this->Vectors);
    }
    for (size_t k = 0; k < this->Others.size(); ++k)
    {
      if (!interpolated[k])
      {
        continue;
      }
      if (static_cast<int>(k) == surface.TCoordsIndex)
      {
        sampleData->SetTCoords(this->Others[k]);
      }
      else if (static_cast<int>(k) == surface.CellVectorsIndex)
      {
        sampleData->SetVectors(this->Others[k]);
      }
      else if (static_cast<int>(k) == surface.CellScalarsIndex)
      {
        sampleData->SetScalars(this->Others[k]);
      }
      else
      {
        sampleData->AddArray(this->Others[k]);
      }
    }
  }
};

#endif
