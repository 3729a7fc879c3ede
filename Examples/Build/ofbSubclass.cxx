// ofbSubclass: subclasses of vtkOFB's algorithms built against the installed headers only
// (Examples/Build/CMakeLists.txt). Each overrides a protected virtual method and uses the
// protected API a subclass would use; if an installed header named or included a private
// header of vtkOFB, this program would not compile (private headers are not installed).
// It samples a sphere with a tangent vector field, computes its LIC and checks that every
// override ran. It opens no window, so it runs without a display.

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <iostream>
#include <vector>

namespace
{
/// A sampler that records which backend it chose and how long the build took.
class ofbRecordingSampler : public vtkOFBSampler
{
public:
  static ofbRecordingSampler* New();
  vtkTypeMacro(ofbRecordingSampler, vtkOFBSampler);

  int Selections = 0;
  bool UsedCPU = false;
  bool Timed = false;

protected:
  ofbRecordingSampler() = default;

  vtkOFBSamplerBackend* SelectBackend() override
  {
    ++this->Selections;
    return this->Superclass::SelectBackend();
  }

  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override
  {
    const int result = this->Superclass::RequestData(request, inputVector, outputVector);
    this->UsedCPU = this->GetLastBuildBackend() == this->GetCPUBackend();
    this->Timed = this->LastBuildTime >= 0.0 && this->Resolution > 0;
    return result;
  }
};
vtkStandardNewMacro(ofbRecordingSampler);

/// A LIC that checks its settings, field and kernel before the convolution, as a
/// subclass that adds its own checks or outputs would.
class ofbCheckedLIC : public vtkOFBLIC
{
public:
  static ofbCheckedLIC* New();
  vtkTypeMacro(ofbCheckedLIC, vtkOFBLIC);

  bool FieldFound = false;
  std::size_t KernelSize = 0;

protected:
  ofbCheckedLIC() = default;

  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override
  {
    vtkOFB* input = vtkOFB::GetData(inputVector[0]);
    if (!input || !this->CheckSettings())
    {
      return 0;
    }
    this->FieldFound = this->FindField(input) != nullptr;
    this->KernelSize = this->ComputeKernel(this->NumberOfSteps).size();
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
};
vtkStandardNewMacro(ofbCheckedLIC);

/// A mapper that records the input port information it was asked for.
class ofbRecordingMapper : public vtkOFBPolyDataMapper
{
public:
  static ofbRecordingMapper* New();
  vtkTypeMacro(ofbRecordingMapper, vtkOFBPolyDataMapper);

  int Filled = 0;

protected:
  ofbRecordingMapper() = default;

  int FillInputPortInformation(int port, vtkInformation* info) override
  {
    ++this->Filled;
    return this->Superclass::FillInputPortInformation(port, info);
  }
};
vtkStandardNewMacro(ofbRecordingMapper);
}

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->Update();
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(sphere->GetOutput());
  // A field around the z axis, tangent to the sphere.
  vtkNew<vtkFloatArray> field;
  field->SetName("Field");
  field->SetNumberOfComponents(3);
  field->SetNumberOfTuples(surface->GetNumberOfPoints());
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    field->SetTuple3(i, -p[1], p[0], 0.0);
  }
  surface->GetPointData()->SetVectors(field);

  vtkNew<ofbRecordingSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetResolution(48);
  sampler->Update();
  vtkOFB* ofb = sampler->GetOutput();
  if (ofb->GetNumberOfSamples() == 0 || sampler->Selections != 1 || !sampler->UsedCPU ||
    !sampler->Timed)
  {
    std::cerr << "ofbSubclass: the sampler subclass did not build through its overrides\n";
    return 1;
  }

  vtkNew<ofbCheckedLIC> lic;
  lic->SetInputData(ofb);
  lic->SetNumberOfSteps(5);
  lic->Update();
  vtkOFB* output = lic->GetOutput();
  vtkDataArray* values = output->GetSampleData()->GetArray("LIC");
  if (!lic->FieldFound || lic->KernelSize != 11 || !values ||
    values->GetNumberOfTuples() != ofb->GetNumberOfSamples())
  {
    std::cerr << "ofbSubclass: the LIC subclass did not convolve through its override\n";
    return 1;
  }

  vtkNew<ofbRecordingMapper> mapper;
  mapper->GetInputPortInformation(0);
  if (mapper->Filled != 1)
  {
    std::cerr << "ofbSubclass: the mapper subclass's FillInputPortInformation did not run\n";
    return 1;
  }

  std::cout << "ofbSubclass: " << ofb->GetNumberOfSamples()
            << " samples sampled and convolved by subclasses\n";
  return 0;
}
