#include "vtkOFBLICPyramid.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace
{
// The arrays that vtkOFBLIC writes.
const char* const LICArrayNames[] = { "LIC", "LICMask" };
}

vtkStandardNewMacro(vtkOFBLICPyramid);
vtkCxxSetObjectMacro(vtkOFBLICPyramid, LIC, vtkOFBLIC);

//------------------------------------------------------------------------------
vtkOFBLICPyramid::vtkOFBLICPyramid()
  : LIC(nullptr)
  , DeferLevelLICs(false)
  , LevelLICsPending(false)
  , NumberOfLevelLICComputations(0)
  , LastLevelLICTime(0.0)
{
}

//------------------------------------------------------------------------------
vtkOFBLICPyramid::~vtkOFBLICPyramid()
{
  this->SetLIC(nullptr);
}

//------------------------------------------------------------------------------
bool vtkOFBLICPyramid::IsComputedArray(const std::string& name) const
{
  return this->LIC && (name == LICArrayNames[0] || name == LICArrayNames[1]);
}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::CopySettings(vtkOFBLIC* from, vtkOFBLIC* to)
{
  to->SetNumberOfSteps(from->GetNumberOfSteps());
  to->SetStepSize(from->GetStepSize());
  to->SetNormalizeVectors(from->GetNormalizeVectors());
  to->SetFieldInterpolation(from->GetFieldInterpolation());
  to->SetKernelType(from->GetKernelType());
  to->SetOrientedLIC(from->GetOrientedLIC());
  to->SetAnimate(from->GetAnimate());
  to->SetAnimationPhase(from->GetAnimationPhase());
  to->SetNoiseType(from->GetNoiseType());
  to->SetNoiseGrainSize(from->GetNoiseGrainSize());
  to->SetMinNoiseValue(from->GetMinNoiseValue());
  to->SetMaxNoiseValue(from->GetMaxNoiseValue());
  to->SetNumberOfNoiseLevels(from->GetNumberOfNoiseLevels());
  to->SetImpulseNoiseProbability(from->GetImpulseNoiseProbability());
  to->SetImpulseNoiseBackgroundValue(from->GetImpulseNoiseBackgroundValue());
  to->SetNoiseGeneratorSeed(from->GetNoiseGeneratorSeed());
  to->SetNoiseArrayName(from->GetNoiseArrayName());
  to->SetEnhancedLIC(from->GetEnhancedLIC());
  to->SetEnhanceContrast(from->GetEnhanceContrast());
  to->SetLowLICContrastEnhancementFactor(from->GetLowLICContrastEnhancementFactor());
  to->SetHighLICContrastEnhancementFactor(from->GetHighLICContrastEnhancementFactor());
  to->SetMaskThreshold(from->GetMaskThreshold());
  to->SetMaskOnSurface(from->GetMaskOnSurface());
  to->SetMaskColor(from->GetMaskColor());
  to->SetMaskIntensity(from->GetMaskIntensity());
  to->SetCacheStreamlines(from->GetCacheStreamlines());
  // The field: the same array (by name) where one was chosen, else the active vectors.
  vtkInformation* info = from->GetInformation();
  if (info->Has(vtkAlgorithm::INPUT_ARRAYS_TO_PROCESS()))
  {
    to->SetInputArrayToProcess(0, from->GetInputArrayInformation(0));
  }
}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::ComputeLevelArrays(const std::set<std::string>* names)
{
  if (!this->LIC || (names && !names->count(LICArrayNames[0])))
  {
    return;
  }
  vtkOFB* input = this->GetInputOFB();
  if (!input || !input->GetSampleData()->GetArray(LICArrayNames[0]))
  {
    return;
  }
  if (this->DeferLevelLICs)
  {
    this->LevelLICsPending = true;
    return;
  }
  this->RunLevelLICs(this->GetNumberOfLevels());
}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::ComputeLevelLICs(int numberOfLevels)
{
  this->RunLevelLICs(numberOfLevels < 0 ? this->GetNumberOfLevels() : numberOfLevels);
  // Outside the arrays' update: the levels' arrays changed now (all of them, for a
  // renderer that uploads what changed).
  this->ArraysTime.Modified();
  this->AllArraysTime.Modified();
}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::RunLevelLICs(int levels)
{
  this->LevelLICsPending = false;
  if (!this->LIC)
  {
    return;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  const int own = this->GetNumberOfLevels();
  vtkOFB* input = this->GetInputOFB();
  // Where level 0 has no LIC (nor samples) this process only takes part.
  const bool computed = input && input->GetSampleData()->GetArray(LICArrayNames[0]);
  this->LevelLICs.resize(static_cast<size_t>(std::max(levels - 1, 0)));
  vtkNew<vtkOFB> empty;
  this->BeginLevelLICs(levels);
  for (int k = 1; k < levels; ++k)
  {
    vtkOFB* level = computed && k < own ? this->GetLevel(k) : nullptr;
    this->PrepareLevelLIC(k, level);
    vtkSmartPointer<vtkOFBLIC>& lic = this->LevelLICs[k - 1];
    if (!lic || strcmp(lic->GetClassName(), this->LIC->GetClassName()) != 0)
    {
      // The LIC's class: a distributed LIC gives distributed levels.
      lic.TakeReference(this->LIC->NewInstance());
    }
    CopySettings(this->LIC, lic);
    this->LIC->CopySettingsToLevel(lic);
    lic->SetInputData(level ? level : empty.Get());
    lic->Update();
    if (!level)
    {
      continue;
    }
    vtkOFB* out = lic->GetOutput();
    for (const char* name : LICArrayNames)
    {
      vtkDataArray* array = out ? out->GetSampleData()->GetArray(name) : nullptr;
      if (array && array->GetNumberOfTuples() == level->GetNumberOfSamples())
      {
        // The level's own LIC replaces the one filtered from the finer level.
        level->GetSampleData()->RemoveArray(name);
        level->GetSampleData()->AddArray(array);
      }
      else
      {
        vtkWarningMacro("The LIC of level " << k << " could not be computed: it keeps the LIC "
                                            << "filtered from level " << k - 1 << ".");
        break;
      }
    }
    level->Modified();
  }
  ++this->NumberOfLevelLICComputations;
  this->LastLevelLICTime = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::BeginLevelLICs(int) {}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::PrepareLevelLIC(int, vtkOFB*) {}

//------------------------------------------------------------------------------
vtkOFBLIC* vtkOFBLICPyramid::GetLevelLIC(int k) const
{
  return k >= 1 && k <= static_cast<int>(this->LevelLICs.size()) ? this->LevelLICs[k - 1].Get()
                                                                 : nullptr;
}

//------------------------------------------------------------------------------
void vtkOFBLICPyramid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LIC: " << this->LIC << "\n";
  os << indent << "DeferLevelLICs: " << (this->DeferLevelLICs ? "On" : "Off") << "\n";
  os << indent << "LevelLICsPending: " << (this->LevelLICsPending ? "yes" : "no") << "\n";
  os << indent << "NumberOfLevelLICComputations: " << this->NumberOfLevelLICComputations << "\n";
  os << indent << "LastLevelLICTime: " << this->LastLevelLICTime << " s\n";
}
