#include "vtkOFBColoring.h"

#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkOFBColoring);
vtkCxxSetObjectMacro(vtkOFBColoring, LookupTable, vtkScalarsToColors);

//------------------------------------------------------------------------------
vtkOFBColoring::vtkOFBColoring()
  : ColorSource(COLOR_SOURCE_PAINT)
  , ScalarComponent(0)
  , LookupTable(nullptr)
  , ScalarRange{ 0.0, 1.0 }
  , UseLookupTableScalarRange(false)
  , IntensityArrayName("LIC")
  , IntensityModulation(false)
  , LICColorMode(COLOR_MODE_BLEND)
  , LICIntensity(1.0)
  , MapModeBias(0.0)
  , IntensityWeight(1.0)
  , EnhanceColorContrast(false)
  , LowColorContrastEnhancementFactor(0.0)
  , HighColorContrastEnhancementFactor(0.0)
{
}

//------------------------------------------------------------------------------
vtkOFBColoring::~vtkOFBColoring()
{
  this->SetLookupTable(nullptr);
}

//------------------------------------------------------------------------------
vtkScalarsToColors* vtkOFBColoring::GetLookupTable()
{
  if (!this->LookupTable)
  {
    vtkNew<vtkLookupTable> table;
    table->Build();
    this->SetLookupTable(table);
  }
  return this->LookupTable;
}

//------------------------------------------------------------------------------
vtkScalarsToColors* vtkOFBColoring::PrepareLookupTable(double range[2])
{
  vtkScalarsToColors* lut = this->GetLookupTable();
  if (this->UseLookupTableScalarRange)
  {
    std::copy(lut->GetRange(), lut->GetRange() + 2, range);
  }
  else
  {
    range[0] = this->ScalarRange[0];
    range[1] = this->ScalarRange[1];
    lut->SetRange(range);
  }
  return lut;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBColoring::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->LookupTable)
  {
    t = std::max(t, this->LookupTable->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
const char* vtkOFBColoring::GetColorSourceAsString(int source)
{
  switch (source)
  {
    case COLOR_SOURCE_PAINT:
      return "Paint";
    case COLOR_SOURCE_SCALARS:
      return "Scalars";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
const char* vtkOFBColoring::GetLICColorModeAsString(int mode)
{
  switch (mode)
  {
    case COLOR_MODE_BLEND:
      return "COLOR_MODE_BLEND";
    case COLOR_MODE_MAP:
      return "COLOR_MODE_MAP";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
void vtkOFBColoring::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ColorSource: " << GetColorSourceAsString(this->ColorSource) << "\n";
  os << indent
     << "ScalarArrayName: " << (this->ScalarArrayName.empty() ? "(none)" : this->ScalarArrayName)
     << "\n";
  os << indent << "ScalarComponent: " << this->ScalarComponent << "\n";
  os << indent << "LookupTable: " << this->LookupTable << "\n";
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1] << "\n";
  os << indent << "UseLookupTableScalarRange: " << (this->UseLookupTableScalarRange ? "On" : "Off")
     << "\n";
  os << indent << "IntensityArrayName: "
     << (this->IntensityArrayName.empty() ? "(none)" : this->IntensityArrayName) << "\n";
  os << indent << "IntensityModulation: " << (this->IntensityModulation ? "On" : "Off") << "\n";
  os << indent << "LICColorMode: " << GetLICColorModeAsString(this->LICColorMode) << "\n";
  os << indent << "LICIntensity: " << this->LICIntensity << "\n";
  os << indent << "MapModeBias: " << this->MapModeBias << "\n";
  os << indent << "IntensityWeight: " << this->IntensityWeight << "\n";
  os << indent << "EnhanceColorContrast: " << (this->EnhanceColorContrast ? "On" : "Off") << "\n";
  os << indent << "LowColorContrastEnhancementFactor: " << this->LowColorContrastEnhancementFactor
     << "\n";
  os << indent << "HighColorContrastEnhancementFactor: " << this->HighColorContrastEnhancementFactor
     << "\n";
}
