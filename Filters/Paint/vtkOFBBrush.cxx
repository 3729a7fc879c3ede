#include "vtkOFBBrush.h"

#include "vtkOFB.h"
#include "vtkOFBBrushFunctions.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkOFBBrush);

//------------------------------------------------------------------------------
vtkOFBBrush::vtkOFBBrush()
  : Radius(1.0)
  , Strength(1.0)
  , Falloff(FALLOFF_SMOOTH)
  , BlendMode(BLEND_MIX)
  , Target(TARGET_COLOR)
  , SmearAmount(1.0)
  , BumpDepth(0.5)
  , NormalAware(false)
  , MaxNormalAngle(90.0)
  , PressureAffectsRadius(false)
  , PressureAffectsStrength(true)
{
  this->Color[0] = this->Color[1] = this->Color[2] = this->Color[3] = 1.0;
}

//------------------------------------------------------------------------------
vtkOFBBrush::~vtkOFBBrush() = default;

//------------------------------------------------------------------------------
void vtkOFBBrush::SetRadiusInCells(double cells, vtkOFB* ofb)
{
  if (!ofb || ofb->GetCellSize() <= 0.0)
  {
    vtkErrorMacro("SetRadiusInCells: no OFB or an empty one; the radius is unchanged.");
    return;
  }
  this->SetRadius(cells * ofb->GetCellSize());
}

//------------------------------------------------------------------------------
void vtkOFBBrush::SetColor(double r, double g, double b)
{
  this->SetColor(r, g, b, this->Color[3]);
}

//------------------------------------------------------------------------------
void vtkOFBBrush::SetOpacity(double a)
{
  this->SetColor(this->Color[0], this->Color[1], this->Color[2], a);
}

//------------------------------------------------------------------------------
void vtkOFBBrush::SetCustomFalloff(vtkPiecewiseFunction* f)
{
  if (this->CustomFalloff != f)
  {
    this->CustomFalloff = f;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPiecewiseFunction* vtkOFBBrush::GetCustomFalloff() const
{
  return this->CustomFalloff;
}

//------------------------------------------------------------------------------
double vtkOFBBrush::EvaluateFalloff(double normalizedDistance) const
{
  return vtkOFBBrush::EvaluateFalloff(this->Falloff, normalizedDistance, this->CustomFalloff);
}

//------------------------------------------------------------------------------
double vtkOFBBrush::EvaluateFalloff(int falloff, double x, vtkPiecewiseFunction* custom)
{
  if (falloff < 0 || falloff >= NUMBER_OF_FALLOFFS)
  {
    return 0.0; // not a falloff (an int outside the enumeration is no FalloffType)
  }
  return vtkofbbrush::Falloff(static_cast<FalloffType>(falloff),
    x,
    [custom](double at)
    { return custom ? std::min(1.0, std::max(0.0, custom->GetValue(at))) : 1.0; });
}

//------------------------------------------------------------------------------
void vtkOFBBrush::SetFalloff(int falloff)
{
  if (falloff < 0 || falloff >= NUMBER_OF_FALLOFFS)
  {
    vtkErrorMacro("SetFalloff: " << falloff << " is not a FalloffType; the falloff stays "
                                 << vtkOFBBrush::GetFalloffAsString(this->Falloff) << ".");
    return;
  }
  if (this->Falloff != falloff)
  {
    this->Falloff = falloff;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBBrush::SetBlendMode(int mode)
{
  if (mode < 0 || mode >= NUMBER_OF_BLEND_MODES)
  {
    vtkErrorMacro("SetBlendMode: " << mode << " is not a BlendModeType; the blend mode stays "
                                   << vtkOFBBrush::GetBlendModeAsString(this->BlendMode) << ".");
    return;
  }
  if (this->BlendMode != mode)
  {
    this->BlendMode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBBrush::SetTarget(int target)
{
  if (target < 0 || target >= NUMBER_OF_TARGETS)
  {
    vtkErrorMacro("SetTarget: " << target << " is not a TargetType; the target stays "
                                << vtkOFBBrush::GetTargetAsString(this->Target) << ".");
    return;
  }
  if (this->Target != target)
  {
    this->Target = target;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkOFBBrush::GetFalloffAsString(int falloff)
{
  if (falloff < 0 || falloff >= NUMBER_OF_FALLOFFS)
  {
    return "Unknown";
  }
  switch (static_cast<FalloffType>(falloff))
  {
    case FALLOFF_CONSTANT:
      return "Constant";
    case FALLOFF_LINEAR:
      return "Linear";
    case FALLOFF_SMOOTH:
      return "Smooth";
    case FALLOFF_SPHERE:
      return "Sphere";
    case FALLOFF_ROOT:
      return "Root";
    case FALLOFF_SHARP:
      return "Sharp";
    case FALLOFF_GAUSSIAN:
      return "Gaussian";
    case FALLOFF_CUSTOM:
      return "Custom";
    case NUMBER_OF_FALLOFFS:
      break;
  }
  return "Unknown";
}

//------------------------------------------------------------------------------
const char* vtkOFBBrush::GetBlendModeAsString(int mode)
{
  if (mode < 0 || mode >= NUMBER_OF_BLEND_MODES)
  {
    return "Unknown";
  }
  switch (static_cast<BlendModeType>(mode))
  {
    case BLEND_MIX:
      return "Mix";
    case BLEND_ADD:
      return "Add";
    case BLEND_SUBTRACT:
      return "Subtract";
    case BLEND_MULTIPLY:
      return "Multiply";
    case BLEND_LIGHTEN:
      return "Lighten";
    case BLEND_DARKEN:
      return "Darken";
    case BLEND_ERASE:
      return "Erase";
    case BLEND_ERASE_ALPHA:
      return "EraseAlpha";
    case NUMBER_OF_BLEND_MODES:
      break;
  }
  return "Unknown";
}

//------------------------------------------------------------------------------
const char* vtkOFBBrush::GetTargetAsString(int target)
{
  if (target < 0 || target >= NUMBER_OF_TARGETS)
  {
    return "Unknown";
  }
  switch (static_cast<TargetType>(target))
  {
    case TARGET_COLOR:
      return "Color";
    case TARGET_NORMAL:
      return "Normal";
    case TARGET_SMEAR:
      return "Smear";
    case NUMBER_OF_TARGETS:
      break;
  }
  return "Unknown";
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBBrush::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->CustomFalloff)
  {
    t = std::max(t, this->CustomFalloff->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
void vtkOFBBrush::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Color: (" << this->Color[0] << ", " << this->Color[1] << ", " << this->Color[2]
     << ", " << this->Color[3] << ")\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Falloff: " << vtkOFBBrush::GetFalloffAsString(this->Falloff) << "\n";
  os << indent << "CustomFalloff: " << this->CustomFalloff.GetPointer() << "\n";
  os << indent << "BlendMode: " << vtkOFBBrush::GetBlendModeAsString(this->BlendMode) << "\n";
  os << indent << "Target: " << vtkOFBBrush::GetTargetAsString(this->Target) << "\n";
  os << indent << "SmearAmount: " << this->SmearAmount << "\n";
  os << indent << "BumpDepth: " << this->BumpDepth << "\n";
  os << indent << "NormalAware: " << (this->NormalAware ? "On" : "Off") << "\n";
  os << indent << "MaxNormalAngle: " << this->MaxNormalAngle << "\n";
  os << indent << "PressureAffectsRadius: " << (this->PressureAffectsRadius ? "On" : "Off") << "\n";
  os << indent << "PressureAffectsStrength: " << (this->PressureAffectsStrength ? "On" : "Off")
     << "\n";
}
