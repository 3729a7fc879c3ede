#include "vtkOFBProbeFilter.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBPyramidResampler.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

vtkStandardNewMacro(vtkOFBProbeFilter);

//------------------------------------------------------------------------------
vtkOFBProbeFilter::vtkOFBProbeFilter()
  : Radius(std::sqrt(3.0))
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOFBProbeFilter::~vtkOFBProbeFilter() = default;

//------------------------------------------------------------------------------
void vtkOFBProbeFilter::SetOFBConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkOFBProbeFilter::SetOFBData(vtkOFB* ofb)
{
  this->SetInputDataInternal(1, ofb);
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBProbeFilter::GetOFB()
{
  return this->GetNumberOfInputConnections(1) > 0
    ? vtkOFB::SafeDownCast(this->GetExecutive()->GetInputData(1, 0))
    : nullptr;
}

//------------------------------------------------------------------------------
void vtkOFBProbeFilter::AddArrayName(const char* name)
{
  if (name)
  {
    this->ArrayNames.emplace_back(name);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBProbeFilter::ClearArrayNames()
{
  if (!this->ArrayNames.empty())
  {
    this->ArrayNames.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkOFBProbeFilter::GetArrayName(int i) const
{
  return i >= 0 && i < this->GetNumberOfArrayNames() ? this->ArrayNames[i].c_str() : nullptr;
}

//------------------------------------------------------------------------------
int vtkOFBProbeFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBProbeFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkOFB* ofb = vtkOFB::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->NumberOfInvalidPoints = 0;
  if (!input)
  {
    vtkErrorMacro("The input is not a vtkPolyData.");
    return 1;
  }
  // The output shares the input's cells: cells naming points that do not exist would
  // reach whatever reads it.
  std::string error;
  if (!vtkOFBCheckCellPointIds(input, error))
  {
    vtkErrorMacro("The surface (input port 0) is invalid: " << error << ".");
    return 1;
  }
  if (!ofb || ofb->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("No OFB to probe, or an empty one: connect one to port 1 (SetOFBConnection).");
    return 1;
  }
  if (!(this->Radius > 0.0) || !std::isfinite(this->Radius))
  {
    vtkErrorMacro("Radius " << this->Radius << " is not positive and finite.");
    return 1;
  }
  std::set<std::string> names(this->ArrayNames.begin(), this->ArrayNames.end());
  for (const std::string& name : names)
  {
    vtkDataArray* array = ofb->GetSampleData()->GetArray(name.c_str());
    if (!array || array->GetNumberOfTuples() != ofb->GetNumberOfSamples())
    {
      vtkErrorMacro("The OFB has no sample array '" << name << "' (one tuple per sample).");
      return 1;
    }
  }

  // The points as doubles, and their normals as floats for the facing test.
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<double> x(static_cast<size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, x.data() + 3 * i);
  }
  std::vector<float> normals;
  vtkDataArray* pointNormals = input->GetPointData()->GetNormals();
  if (this->NormalAware && pointNormals && pointNormals->GetNumberOfComponents() == 3 &&
    pointNormals->GetNumberOfTuples() == n)
  {
    normals.resize(static_cast<size_t>(3 * n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      double v[3];
      pointNormals->GetTuple(i, v);
      std::copy(v, v + 3, normals.begin() + 3 * i);
    }
  }

  vtkOFBPyramidResampler transfer(ofb, x.data(), n, this->Radius * ofb->GetCellSize());
  transfer.Nearest = this->LookupMode == LOOKUP_NEAREST;
  transfer.CollectArrays(names.empty() ? nullptr : &names);
  transfer.SetTargetNormals(normals.empty() ? nullptr : normals.data());
  auto mask = vtkSmartPointer<vtkUnsignedCharArray>::New();
  mask->SetNumberOfValues(n);
  transfer.Found = mask->GetPointer(0);
  const vtkIdType chunk = 4096;
  for (vtkIdType first = 0; first < n && !this->AbortExecute; first += 16 * chunk)
  {
    vtkSMPTools::For(first, std::min(n, first + 16 * chunk), chunk, transfer);
    this->UpdateProgress(static_cast<double>(std::min(n, first + 16 * chunk)) / n);
  }
  if (this->AbortExecute)
  {
    output->Initialize();
    return 1;
  }

  output->CopyStructure(input);
  if (this->PassPointArrays)
  {
    output->GetPointData()->PassData(input->GetPointData());
  }
  output->GetCellData()->PassData(input->GetCellData());
  transfer.ReplaceTargetArrays(output->GetPointData());
  for (vtkIdType i = 0; i < n; ++i)
  {
    this->NumberOfInvalidPoints += mask->GetValue(i) ? 0 : 1;
  }
  if (!this->ValidPointMaskArrayName.empty())
  {
    mask->SetName(this->ValidPointMaskArrayName.c_str());
    output->GetPointData()->AddArray(mask);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBProbeFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LookupMode: " << (this->LookupMode == LOOKUP_NEAREST ? "Nearest" : "Smooth")
     << "\n";
  os << indent << "Radius: " << this->Radius << " cells\n";
  os << indent << "NormalAware: " << (this->NormalAware ? "On" : "Off") << "\n";
  os << indent << "PassPointArrays: " << (this->PassPointArrays ? "On" : "Off") << "\n";
  os << indent << "ValidPointMaskArrayName: " << this->ValidPointMaskArrayName << "\n";
  os << indent << "ArrayNames:";
  for (const std::string& name : this->ArrayNames)
  {
    os << " " << name;
  }
  os << (this->ArrayNames.empty() ? " (all)\n" : "\n");
  os << indent << "NumberOfInvalidPoints: " << this->NumberOfInvalidPoints << "\n";
}
