#include "vtkOFBPLICPyramid.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkMultiProcessController.h"
#include "vtkOFB.h"
#include "vtkOFBPLICExchange.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace
{
const char* const LICName = "LIC";

/// The ghost flags of `ofb` (null where it has none).
const unsigned char* GhostFlags(vtkOFB* ofb)
{
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    ofb->GetSampleData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  return ghosts && ghosts->GetNumberOfTuples() >= ofb->GetNumberOfSamples() ? ghosts->GetPointer(0)
                                                                            : nullptr;
}
}

vtkStandardNewMacro(vtkOFBPLICPyramid);
vtkCxxSetObjectMacro(vtkOFBPLICPyramid, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkOFBPLICPyramid::vtkOFBPLICPyramid()
  : Controller(nullptr)
  , ExchangeFilterSources(true)
  , Refilter(false)
  , LastFilterSentBytes(0)
  , LastFilterReceivedBytes(0)
  , LastRefilterTime(0.0)
  , LastRefilteredLevels(0)
  , Mean(0.5)
  , MeanTime(0)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOFBPLICPyramid::~vtkOFBPLICPyramid()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
bool vtkOFBPLICPyramid::NeedsRefilter()
{
  vtkOFB* input = this->GetInputOFB();
  if (!input || this->GetNumberOfLevels() < 2)
  {
    return false;
  }
  if (this->GetStructureTime() > this->RefilterTime.GetMTime())
  {
    return true;
  }
  vtkPointData* pd = input->GetSampleData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetName() && !this->IsComputedArray(array->GetName()) &&
      strcmp(array->GetName(), vtkDataSetAttributes::GhostArrayName()) != 0 &&
      array->GetMTime() > this->RefilterTime.GetMTime())
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkOFBPLICPyramid::BeginLevelLICs(int)
{
  this->LastFilterSentBytes = this->LastFilterReceivedBytes = 0;
  this->LastRefilterTime = 0.0;
  this->LastRefilteredLevels = 0;
  this->Refilter = false;
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return;
  }
  // One all-reduce: level 0's "LIC" over the owned samples (as the mapper's shader reads
  // it: clamped to [0, 1], NaN as 0), and whether a process must filter again.
  double local[3] = { 0.0, 0.0, this->NeedsRefilter() ? 1.0 : 0.0 };
  vtkOFB* input = this->GetInputOFB();
  vtkDataArray* lic = input ? input->GetSampleData()->GetArray(LICName) : nullptr;
  if (lic && lic->GetNumberOfTuples() >= input->GetNumberOfSamples())
  {
    const unsigned char* ghosts = GhostFlags(input);
    for (vtkIdType i = 0; i < input->GetNumberOfSamples(); ++i)
    {
      if (!ghosts || ghosts[i] == 0)
      {
        const double v = lic->GetComponent(i, 0);
        local[0] += v > 0.0 ? std::min(v, 1.0) : 0.0;
        local[1] += 1.0;
      }
    }
  }
  double global[3] = { 0.0, 0.0, 0.0 };
  controller->AllReduce(local, global, 3, vtkCommunicator::SUM_OP);
  this->Mean = global[1] > 0.0 ? global[0] / global[1] : 0.5;
  this->MeanArray = lic;
  this->MeanTime = lic ? lic->GetMTime() : 0;
  this->Refilter = this->ExchangeFilterSources && global[2] > 0.0;
}

//------------------------------------------------------------------------------
void vtkOFBPLICPyramid::PrepareLevelLIC(int k, vtkOFB* level)
{
  if (!this->Refilter)
  {
    return;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  // Level k - 1's arrays that level k filters (not the computed ones, nor the ghost flags).
  vtkOFB* finer = level ? this->GetLevel(k - 1) : nullptr;
  std::vector<std::string> names;
  vtkPointData* pd = finer ? finer->GetSampleData() : nullptr;
  for (int a = 0; pd && a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetName() && !this->IsComputedArray(array->GetName()) &&
      strcmp(array->GetName(), vtkDataSetAttributes::GhostArrayName()) != 0 &&
      array->GetNumberOfTuples() == finer->GetNumberOfSamples())
    {
      names.emplace_back(array->GetName());
    }
  }
  // The reach of the filtering, and a margin for level k's owned samples beyond the box of
  // level k - 1's (both sample the owned triangles).
  const double radius = level ? this->GetFilterReach(k) + 2.0 * level->GetCellSize() : 0.0;
  vtkOFBPLICExchange exchange;
  if (!exchange.Run(this->Controller, finer, names, radius))
  {
    vtkErrorMacro("Level " << k << " is filtered from this process's samples alone: "
                           << exchange.Problem << ".");
  }
  else if (level && exchange.Merged && exchange.Merged->GetNumberOfSamples() > 0)
  {
    const std::set<std::string> filtered(names.begin(), names.end());
    this->FilterLevel(k, exchange.Merged, &filtered);
    level->Modified();
    ++this->LastRefilteredLevels;
  }
  this->LastFilterSentBytes += exchange.SentBytes;
  this->LastFilterReceivedBytes += exchange.ReceivedBytes;
  this->LastRefilterTime += vtkTimerLog::GetUniversalTime() - start;
  this->RefilterTime.Modified();
}

//------------------------------------------------------------------------------
bool vtkOFBPLICPyramid::GetSharedMean(const std::string& name, double& mean)
{
  vtkOFB* input = this->GetInputOFB();
  vtkDataArray* lic = input ? input->GetSampleData()->GetArray(LICName) : nullptr;
  if (name != LICName || !lic || lic != this->MeanArray.Get() || lic->GetMTime() > this->MeanTime ||
    !this->Controller || this->Controller->GetNumberOfProcesses() <= 1)
  {
    return false;
  }
  mean = this->Mean;
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPLICPyramid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "ExchangeFilterSources: " << (this->ExchangeFilterSources ? "On" : "Off") << "\n";
  os << indent << "LastFilterSentBytes: " << this->LastFilterSentBytes << "\n";
  os << indent << "LastFilterReceivedBytes: " << this->LastFilterReceivedBytes << "\n";
  os << indent << "LastRefilterTime: " << this->LastRefilterTime << " s\n";
  os << indent << "LastRefilteredLevels: " << this->LastRefilteredLevels << "\n";
}
