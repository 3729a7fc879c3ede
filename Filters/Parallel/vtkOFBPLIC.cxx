#include "vtkOFBPLIC.h"

#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLICReduction.h"
#include "vtkOFBPLICExchange.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkOFBPLIC);
vtkCxxSetObjectMacro(vtkOFBPLIC, Controller, vtkMultiProcessController);

namespace
{
/**
 * The statistics of every process, in a fixed sequence of collective calls: the
 * sequence that the settings give (per quantile stretch a range, then its histogram
 * unless the range is empty on every process; per contrast stretch a range). A process
 * whose vtkOFBLIC returned before a call (no samples, an error) makes the calls it
 * missed in Finish(), with nothing to contribute, so that every process makes the same
 * calls in the same order.
 */
class CollectiveStatistics : public vtkOFBLICReduction
{
public:
  enum Call
  {
    RANGE,
    COUNTS
  };

  CollectiveStatistics(vtkMultiProcessController* controller, bool enhanced, bool contrast)
    : Controller(controller)
  {
    for (int i = 0; enhanced && i < 2; ++i)
    {
      this->Calls.push_back(RANGE);
      this->Calls.push_back(COUNTS);
    }
    if (contrast)
    {
      this->Calls.push_back(RANGE);
    }
  }

  void Range(float& lo, float& hi) override
  {
    // A histogram that no process counts (the last range was empty everywhere).
    while (this->Next < this->Calls.size() && this->Calls[this->Next] == COUNTS)
    {
      ++this->Next;
    }
    ++this->Next;
    const float local[2] = { -lo, hi };
    float global[2];
    this->Controller->AllReduce(local, global, 2, vtkCommunicator::MAX_OP);
    lo = -global[0];
    hi = global[1];
    this->LastRangeCounted = hi > lo;
  }

  void Counts(vtkIdType* counts, int bins) override
  {
    ++this->Next;
    std::vector<long long> local(counts, counts + bins);
    std::vector<long long> global(bins);
    this->Controller->AllReduce(local.data(), global.data(), bins, vtkCommunicator::SUM_OP);
    std::copy(global.begin(), global.end(), counts);
  }

  /// The calls this process has not made, with an empty range and zero counts.
  void Finish()
  {
    while (this->Next < this->Calls.size())
    {
      if (this->Calls[this->Next] == RANGE)
      {
        float lo = std::numeric_limits<float>::max();
        float hi = std::numeric_limits<float>::lowest();
        this->Range(lo, hi);
      }
      else if (this->LastRangeCounted)
      {
        std::vector<vtkIdType> zeros(Bins, 0);
        this->Counts(zeros.data(), Bins);
      }
      else
      {
        ++this->Next;
      }
    }
  }

  /// The histogram size of vtkOFBLICStretchTails.
  static constexpr int Bins = 4096;

private:
  vtkMultiProcessController* Controller;
  std::vector<Call> Calls;
  std::size_t Next = 0;
  bool LastRangeCounted = false;
};
}

//------------------------------------------------------------------------------
vtkOFBPLIC::vtkOFBPLIC()
  : Controller(nullptr)
  , NumberOfGhostLevels(8)
  , GhostSamples(GHOST_SAMPLES_INPUT)
  , LevelGhostSamples(GHOST_SAMPLES_EXCHANGE)
  , ExchangeMargin(4.0)
  , LastSentSamples(0)
  , LastReceivedSamples(0)
  , LastSentBytes(0)
  , LastReceivedBytes(0)
  , LastExchangeTime(0.0)
  , Exchange(nullptr)
  , ExchangedNone(false)
  , ExchangedRadius(0.0)
  , ExchangedTime(0)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOFBPLIC::~vtkOFBPLIC()
{
  this->SetController(nullptr);
  delete this->Exchange;
}

//------------------------------------------------------------------------------
double vtkOFBPLIC::GetRequiredGhostDepth(double cellSize)
{
  const double steps =
    this->NumberOfSteps * (this->EnhancedLIC && this->NumberOfSteps > 0 ? 1.5 : 1.0);
  return (this->StepSize * steps + 3.0) * cellSize;
}

//------------------------------------------------------------------------------
int vtkOFBPLIC::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (!inInfo)
  {
    return 1;
  }
  const int downstream =
    outInfo ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) : 0;
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
    std::max(downstream, this->NumberOfGhostLevels));
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBPLIC::CopySettingsToLevel(vtkOFBLIC* level)
{
  vtkOFBPLIC* distributed = vtkOFBPLIC::SafeDownCast(level);
  if (distributed)
  {
    distributed->SetController(this->Controller);
    distributed->SetGhostSamples(this->LevelGhostSamples);
    distributed->SetLevelGhostSamples(this->LevelGhostSamples);
    distributed->SetExchangeMargin(this->ExchangeMargin);
  }
}

//------------------------------------------------------------------------------
int vtkOFBPLIC::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->LastSentSamples = this->LastReceivedSamples = 0;
  this->LastSentBytes = this->LastReceivedBytes = 0;
  this->LastExchangeTime = 0.0;
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  vtkOFB* output = vtkOFB::GetData(outputVector);
  if (this->GhostSamples == GHOST_SAMPLES_INPUT || !output)
  {
    return this->RequestCollective(request, inputVector, outputVector);
  }
  return this->RequestExchanged(request, vtkOFB::GetData(inputVector[0]), output);
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkOFBPLIC::ReadArrayNames(vtkOFB* input)
{
  std::vector<std::string> names;
  if (!input || input->GetNumberOfSamples() == 0)
  {
    return names;
  }
  vtkDataArray* normals = nullptr;
  vtkDataArray* vectors = this->FindFieldAndNormals(input, normals);
  // An array without a name is not exchanged (the exchange then fails, with an error).
  for (vtkDataArray* array : { vectors, normals })
  {
    names.emplace_back(array && array->GetName() ? array->GetName() : "");
  }
  if (this->NoiseArrayName && *this->NoiseArrayName)
  {
    names.emplace_back(this->NoiseArrayName);
  }
  return names;
}

//------------------------------------------------------------------------------
bool vtkOFBPLIC::CanReuseExchange(vtkOFB* input,
  const std::vector<std::string>& names,
  double radius)
{
  if (!this->Exchange || !this->Exchange->Merged || !this->Exchange->Problem.empty())
  {
    return false;
  }
  // A process without samples sends and receives nothing: any such input will do.
  const bool none = !input || input->GetNumberOfSamples() == 0;
  if (none || this->ExchangedNone)
  {
    return none && this->ExchangedNone;
  }
  if (input != this->ExchangedInput.Get() || names != this->ExchangedNames ||
    radius != this->ExchangedRadius)
  {
    return false;
  }
  if (input->GetStructureMTime() > this->ExchangedTime)
  {
    return false;
  }
  std::vector<std::string> read = names;
  read.emplace_back(vtkDataSetAttributes::GhostArrayName());
  for (const std::string& name : read)
  {
    vtkDataArray* array = input->GetSampleData()->GetArray(name.c_str());
    if (array && array->GetMTime() > this->ExchangedTime)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkOFBPLIC::RequestExchanged(vtkInformation* request, vtkOFB* input, vtkOFB* output)
{
  const double start = vtkTimerLog::GetUniversalTime();
  const double cell = input ? input->GetCellSize() : 0.0;
  const double radius = this->GhostSamples == GHOST_SAMPLES_GATHER
    ? -1.0
    : this->GetRequiredGhostDepth(cell) + this->ExchangeMargin * cell;
  const std::vector<std::string> names = this->ReadArrayNames(input);
  const int reuse = this->CanReuseExchange(input, names, radius) ? 1 : 0;
  int everywhere = 0;
  this->Controller->AllReduce(&reuse, &everywhere, 1, vtkCommunicator::MIN_OP);
  bool exchanged = everywhere != 0;
  if (!everywhere)
  {
    delete this->Exchange;
    this->Exchange = new vtkOFBPLICExchange;
    exchanged = this->Exchange->Run(this->Controller, input, names, radius);
    if (!exchanged)
    {
      vtkErrorMacro(
        "Cannot exchange the samples that the LIC reads: " << this->Exchange->Problem << ".");
    }
    this->LastSentSamples = this->Exchange->SentSamples;
    this->LastReceivedSamples = this->Exchange->ReceivedSamples;
    this->LastSentBytes = this->Exchange->SentBytes;
    this->LastReceivedBytes = this->Exchange->ReceivedBytes;
    this->ExchangedInput = exchanged ? input : nullptr;
    this->ExchangedNone = !input || input->GetNumberOfSamples() == 0;
    this->ExchangedNames = names;
    this->ExchangedRadius = radius;
    vtkTimeStamp now;
    now.Modified();
    this->ExchangedTime = now.GetMTime();
  }
  this->LastExchangeTime = vtkTimerLog::GetUniversalTime() - start;
  vtkOFBPLICExchange& exchange = *this->Exchange;

  // The LIC of the merged samples (on every process: its collective calls), as the input.
  vtkNew<vtkOFB> empty;
  vtkOFB* merged = exchanged && exchange.Merged ? exchange.Merged.Get() : empty.Get();
  vtkNew<vtkInformation> inInfo;
  inInfo->Set(vtkDataObject::DATA_OBJECT(), merged);
  vtkNew<vtkInformationVector> inVector;
  inVector->Append(inInfo);
  vtkInformationVector* inputs[1] = { inVector };
  vtkNew<vtkOFB> result;
  vtkNew<vtkInformation> outInfo;
  outInfo->Set(vtkDataObject::DATA_OBJECT(), result);
  vtkNew<vtkInformationVector> outVector;
  outVector->Append(outInfo);
  const int status = this->RequestCollective(request, inputs, outVector);

  auto* lic = vtkFloatArray::SafeDownCast(result->GetSampleData()->GetArray("LIC"));
  auto* mask = vtkUnsignedCharArray::SafeDownCast(result->GetSampleData()->GetArray("LICMask"));
  if (!exchanged || !input || !lic || !mask ||
    lic->GetNumberOfTuples() != merged->GetNumberOfSamples() ||
    mask->GetNumberOfTuples() != merged->GetNumberOfSamples())
  {
    output->Initialize();
    return status;
  }
  // Each input sample's value: its own, or (a ghost sample) its owner's.
  const vtkIdType n = input->GetNumberOfSamples();
  vtkNew<vtkFloatArray> licOut;
  licOut->SetName("LIC");
  licOut->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> maskOut;
  maskOut->SetName("LICMask");
  maskOut->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType m = exchange.InputToMerged[i];
    licOut->SetValue(i, m >= 0 ? lic->GetValue(m) : 0.5f);
    maskOut->SetValue(i, m >= 0 ? mask->GetValue(m) : 0);
  }
  output->ShallowCopy(input);
  output->GetSampleData()->AddArray(licOut);
  output->GetSampleData()->AddArray(maskOut);
  return status;
}

//------------------------------------------------------------------------------
int vtkOFBPLIC::RequestCollective(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = this->Controller;
  const bool enhanced = this->EnhancedLIC && this->NumberOfSteps > 0;
  const bool contrast =
    this->EnhanceContrast == ENHANCE_CONTRAST_LIC || this->EnhanceContrast == ENHANCE_CONTRAST_BOTH;
  CollectiveStatistics reduction(controller, enhanced, contrast);
  vtkOFB* input = vtkOFB::GetData(inputVector[0]);
  if (input)
  {
    // Ghost samples are read, not counted: their owner counts them.
    auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
      input->GetSampleData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
    if (ghosts && ghosts->GetNumberOfComponents() == 1 &&
      ghosts->GetNumberOfTuples() == input->GetNumberOfSamples())
    {
      reduction.Excluded = ghosts->GetPointer(0);
    }
  }
  if (!this->NormalizeVectors)
  {
    // The field's scale: the largest tangential magnitude of every process's samples.
    const double local = input ? this->LargestFieldMagnitude(input) : 0.0;
    double global = 0.0;
    controller->AllReduce(&local, &global, 1, vtkCommunicator::MAX_OP);
    this->FieldScale = global;
  }
  this->Reduction = &reduction;
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->Reduction = nullptr;
  reduction.Finish();
  return result;
}

//------------------------------------------------------------------------------
double vtkOFBPLIC::LargestFieldMagnitude(vtkOFB* input)
{
  // As vtkOFBLIC packs its samples: the field less its component along the normal (as a
  // float, as the tracer reads it), samples that it masks left out.
  const vtkIdType n = input->GetNumberOfSamples();
  vtkPointData* pd = input->GetSampleData();
  vtkDataArray* normals =
    pd->GetNormals() ? pd->GetNormals() : pd->GetArray(vtkOFB::NormalsArrayName());
  // The field as vtkOFBLIC::FindField chooses it (which reports a bad one).
  vtkInformation* info = this->GetInputArrayInformation(0);
  vtkDataArray* vectors = nullptr;
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    vectors = pd->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  }
  else if (info && info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    vectors = pd->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
  }
  if (!normals || !vectors || normals->GetNumberOfComponents() != 3 ||
    vectors->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() < n ||
    vectors->GetNumberOfTuples() < n)
  {
    return 0.0;
  }
  const bool unit = vtkFloatArray::SafeDownCast(normals) != nullptr;
  double largest = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double nrm[3], v[3];
    normals->GetTuple(i, nrm);
    vectors->GetTuple(i, v);
    const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    for (int c = 0; c < 3; ++c)
    {
      const double d = unit ? nrm[c] : (len > 0.0 && std::isfinite(len) ? nrm[c] / len : 0.0);
      nrm[c] = static_cast<double>(static_cast<float>(d));
    }
    const double dot = v[0] * nrm[0] + v[1] * nrm[1] + v[2] * nrm[2];
    double t[3];
    for (int c = 0; c < 3; ++c)
    {
      t[c] = v[c] - dot * nrm[c];
    }
    const double mag = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    const double test =
      this->MaskOnSurface ? mag : std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (mag > 0.0 && std::isfinite(mag) && std::isfinite(test) && test >= this->MaskThreshold)
    {
      largest = std::max(largest, mag);
    }
  }
  return largest;
}

//------------------------------------------------------------------------------
void vtkOFBPLIC::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfGhostLevels: " << this->NumberOfGhostLevels << "\n";
  os << indent << "GhostSamples: " << this->GhostSamples << "\n";
  os << indent << "LevelGhostSamples: " << this->LevelGhostSamples << "\n";
  os << indent << "ExchangeMargin: " << this->ExchangeMargin << " cells\n";
}
