#include "vtkOFBBrush.h"

#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkOFBBrush);

//------------------------------------------------------------------------------
vtkOFBBrush::vtkOFBBrush()
  : Radius(1.0)
  , Strength(1.0)
  , Falloff(Smooth)
  , BlendMode(Mix)
  , Target(ColorTarget)
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
  if (!(x <= 1.0))
  {
    return 0.0; // outside the support, or NaN
  }
  x = std::max(x, 0.0);
  const double t = 1.0 - x;
  switch (falloff)
  {
    case Constant:
      return 1.0;
    case Linear:
      return t;
    case Smooth:
      return t * t * (3.0 - 2.0 * t);
    case Sphere:
      return std::sqrt(std::max(0.0, 1.0 - x * x));
    case Root:
      return std::sqrt(t);
    case Sharp:
      return t * t;
    case Gaussian:
      return std::exp(-4.5 * x * x);
    case Custom:
      return custom ? std::min(1.0, std::max(0.0, custom->GetValue(x))) : 1.0;
    default:
      return 0.0;
  }
}

//------------------------------------------------------------------------------
const char* vtkOFBBrush::GetFalloffAsString(int falloff)
{
  static const char* names[] = {
    "Constant", "Linear", "Smooth", "Sphere", "Root", "Sharp", "Gaussian", "Custom"
  };
  return falloff >= Constant && falloff <= Custom ? names[falloff] : "Unknown";
}

//------------------------------------------------------------------------------
const char* vtkOFBBrush::GetBlendModeAsString(int mode)
{
  static const char* names[] = {
    "Mix", "Add", "Subtract", "Multiply", "Lighten", "Darken", "Erase", "EraseAlpha"
  };
  return mode >= Mix && mode <= EraseAlpha ? names[mode] : "Unknown";
}

//------------------------------------------------------------------------------
const char* vtkOFBBrush::GetTargetAsString(int target)
{
  static const char* names[] = { "Color", "Normal", "Smear" };
  return target >= ColorTarget && target <= SmearTarget ? names[target] : "Unknown";
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
