#include "vtkOFBParaViewSampler.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkOFBPSampler.h"
#include "vtkOFBParaViewArrayChoice.h"
#include "vtkObjectFactory.h"

namespace
{
// vtkOFBPSampler whose RequestData the ParaView sampler calls with its own pipeline
// information (same inputs, same output).
class vtkOFBParaViewPieceSampler : public vtkOFBPSampler
{
public:
  static vtkOFBParaViewPieceSampler* New();
  vtkTypeMacro(vtkOFBParaViewPieceSampler, vtkOFBPSampler);
  int Sample(vtkInformation* request, vtkInformationVector** in, vtkInformationVector* out)
  {
    return this->RequestData(request, in, out);
  }

protected:
  vtkOFBParaViewPieceSampler() = default;
  ~vtkOFBParaViewPieceSampler() override = default;

private:
  vtkOFBParaViewPieceSampler(const vtkOFBParaViewPieceSampler&) = delete;
  void operator=(const vtkOFBParaViewPieceSampler&) = delete;
};
vtkStandardNewMacro(vtkOFBParaViewPieceSampler);
}

vtkStandardNewMacro(vtkOFBParaViewSampler);

//------------------------------------------------------------------------------
vtkOFBParaViewSampler::vtkOFBParaViewSampler() = default;

//------------------------------------------------------------------------------
vtkOFBParaViewSampler::~vtkOFBParaViewSampler() = default;

//------------------------------------------------------------------------------
void vtkOFBParaViewSampler::SetInputArrayToProcess(int idx,
  int port,
  int connection,
  int fieldAssociation,
  const char* name)
{
  if (!vtkofbparaview::ChooseNoArray(this, idx, name))
  {
    this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
  }
}

//------------------------------------------------------------------------------
int vtkOFBParaViewSampler::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  if (!this->Pieces)
  {
    this->Pieces = vtkSmartPointer<vtkOFBParaViewPieceSampler>::New();
  }
  auto* pieces = static_cast<vtkOFBParaViewPieceSampler*>(this->Pieces.Get());
  pieces->SetController(controller);
  pieces->SetResolution(this->Resolution);
  pieces->SetMemoryLimit(this->MemoryLimit);
  pieces->SetDefaultColor(this->DefaultColor);
  pieces->SetUseInputColors(this->UseInputColors);
  pieces->SetPassPointArrays(this->PassPointArrays);
  pieces->SetPassCellArrays(this->PassCellArrays);
  pieces->SetArrayPrecedence(this->ArrayPrecedence);
  pieces->SetProjectVectors(this->ProjectVectors);
  pieces->SetStructureReuse(this->StructureReuse);
  // The vector field chosen (or none).
  vtkInformation* own = this->GetInformation();
  vtkInformation* theirs = pieces->GetInformation();
  if (own->Has(vtkAlgorithm::INPUT_ARRAYS_TO_PROCESS()))
  {
    theirs->CopyEntry(own, vtkAlgorithm::INPUT_ARRAYS_TO_PROCESS(), 1);
  }
  else
  {
    theirs->Remove(vtkAlgorithm::INPUT_ARRAYS_TO_PROCESS());
  }
  return pieces->Sample(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkOFBParaViewSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
