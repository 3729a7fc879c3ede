#include "vtkOFBSamplePicker.h"

#include "vtkCell.h"
#include "vtkCellPicker.h"
#include "vtkDataSet.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolygon.h"
#include "vtkRenderer.h"
#include "vtkTriangle.h"

#include <algorithm>

vtkStandardNewMacro(vtkOFBSamplePicker);
vtkCxxSetObjectMacro(vtkOFBSamplePicker, OFB, vtkOFB);

//------------------------------------------------------------------------------
vtkOFBSamplePicker::vtkOFBSamplePicker()
  : OFB(nullptr)
  , Picker(vtkCellPicker::New())
  , Tolerance(0.001)
  , SampleId(-1)
{
  this->PickPosition[0] = this->PickPosition[1] = this->PickPosition[2] = 0.0;
  this->PickNormal[0] = this->PickNormal[1] = 0.0;
  this->PickNormal[2] = 1.0;
}

//------------------------------------------------------------------------------
vtkOFBSamplePicker::~vtkOFBSamplePicker()
{
  this->SetOFB(nullptr);
  this->Picker->Delete();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBSamplePicker::Pick(double x, double y, vtkRenderer* renderer)
{
  this->SampleId = -1;
  if (!renderer)
  {
    vtkErrorMacro("Pick: no renderer given.");
    return -1;
  }
  if (!this->OFB)
  {
    vtkErrorMacro("Pick: no OFB set.");
    return -1;
  }
  this->Picker->SetTolerance(this->Tolerance);
  if (!this->Picker->Pick(x, y, 0.0, renderer) || this->Picker->GetCellId() < 0)
  {
    return -1;
  }
  this->Picker->GetPickPosition(this->PickPosition);
  this->Picker->GetPickNormal(this->PickNormal);
  // The OFB holds a triangle's samples in the grid of its face normal; the pick normal
  // may be interpolated from point normals and point to another grid.
  double faceNormal[3];
  const double* normal = this->GetFaceNormal(faceNormal) ? faceNormal : this->PickNormal;
  this->SampleId = this->OFB->FindSample(this->PickPosition, normal);
  if (this->SampleId < 0)
  {
    this->SampleId = this->OFB->FindClosestSample(this->PickPosition);
  }
  return this->SampleId;
}

//------------------------------------------------------------------------------
bool vtkOFBSamplePicker::GetFaceNormal(double normal[3])
{
  vtkDataSet* data = this->Picker->GetDataSet();
  vtkCell* cell = data ? data->GetCell(this->Picker->GetCellId()) : nullptr;
  if (!cell || cell->GetNumberOfPoints() < 3)
  {
    return false;
  }
  vtkPoints* points = cell->GetPoints();
  if (cell->GetCellType() == VTK_TRIANGLE_STRIP)
  {
    // The triangle of the strip that was hit.
    const vtkIdType first =
      std::min<vtkIdType>(this->Picker->GetSubId(), points->GetNumberOfPoints() - 3);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(std::max<vtkIdType>(first, 0) + k, p[k]);
    }
    vtkTriangle::ComputeNormal(p[0], p[1], p[2], normal);
  }
  else
  {
    vtkPolygon::ComputeNormal(points, normal);
  }
  return normal[0] != 0.0 || normal[1] != 0.0 || normal[2] != 0.0;
}

//------------------------------------------------------------------------------
void vtkOFBSamplePicker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OFB: " << this->OFB << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "PickPosition: (" << this->PickPosition[0] << ", " << this->PickPosition[1]
     << ", " << this->PickPosition[2] << ")\n";
  os << indent << "PickNormal: (" << this->PickNormal[0] << ", " << this->PickNormal[1] << ", "
     << this->PickNormal[2] << ")\n";
  os << indent << "SampleId: " << this->SampleId << "\n";
}
