#include "vtkOFBToPolyData.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkOFBArrayLength.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

vtkStandardNewMacro(vtkOFBToPolyData);

//------------------------------------------------------------------------------
vtkOFBToPolyData::vtkOFBToPolyData()
  : GenerateVertices(true)
  , GenerateGridAxis(true)
  , GenerateCellIds(false)
{
}

//------------------------------------------------------------------------------
vtkOFBToPolyData::~vtkOFBToPolyData() = default;

//------------------------------------------------------------------------------
int vtkOFBToPolyData::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBToPolyData::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkOFB* ofb = vtkOFB::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  if (!ofb)
  {
    vtkErrorMacro("The input is not a vtkOFB.");
    return 1;
  }
  const vtkIdType n = ofb->GetNumberOfSamples();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  double* x = static_cast<double*>(points->GetVoidPointer(0));
  vtkSMPTools::For(0,
    n,
    16384,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        ofb->GetSamplePosition(i, x + 3 * i);
      }
    });
  output->SetPoints(points);
  this->UpdateProgress(0.5);

  if (this->GenerateVertices)
  {
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfValues(n + 1);
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    connectivity->SetNumberOfValues(n);
    vtkIdType* o = offsets->GetPointer(0);
    vtkIdType* c = connectivity->GetPointer(0);
    vtkSMPTools::For(0,
      n + 1,
      65536,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          o[i] = i;
          if (i < n)
          {
            c[i] = i;
          }
        }
      });
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    verts->SetData(offsets, connectivity);
    output->SetVerts(verts);
  }

  output->GetPointData()->ShallowCopy(ofb->GetSampleData());
  // A sample array of another length than the samples would be a point array that
  // readers of the point cloud index past its end: left out, with a warning.
  vtkPointData* pd = output->GetPointData();
  for (int k = pd->GetNumberOfArrays() - 1; k >= 0; --k)
  {
    vtkAbstractArray* array = pd->GetAbstractArray(k);
    if (array && array->GetNumberOfTuples() != n)
    {
      vtkWarningMacro(
        "The sample array " << vtkOFBArrayLength(array, n, "samples") << ": left out.");
      pd->RemoveArray(k);
    }
  }
  if (this->GenerateGridAxis)
  {
    auto axis = vtkSmartPointer<vtkUnsignedCharArray>::New();
    axis->SetName("GridAxis");
    axis->SetNumberOfValues(n);
    for (int a = 0; a < 3; ++a)
    {
      const vtkIdType b = ofb->GetGridFirstSample(a);
      const vtkIdType e = ofb->GetGridFirstSample(a + 1);
      for (vtkIdType i = b; i < e; ++i)
      {
        axis->SetValue(i, static_cast<unsigned char>(a));
      }
    }
    output->GetPointData()->AddArray(axis);
  }
  if (this->GenerateCellIds)
  {
    output->GetPointData()->AddArray(ofb->GetCellIndex());
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBToPolyData::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GenerateVertices: " << (this->GenerateVertices ? "On" : "Off") << "\n";
  os << indent << "GenerateGridAxis: " << (this->GenerateGridAxis ? "On" : "Off") << "\n";
  os << indent << "GenerateCellIds: " << (this->GenerateCellIds ? "On" : "Off") << "\n";
}
