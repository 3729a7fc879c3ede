#include "vtkOFBSamplePicker.h"

#include "vtkCellPicker.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

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
  this->SampleId = this->OFB->FindSample(this->PickPosition, this->PickNormal);
  if (this->SampleId < 0)
  {
    this->SampleId = this->OFB->FindClosestSample(this->PickPosition);
  }
  return this->SampleId;
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
