/**
 * @class   vtkOFBColoring
 * @brief   The colouring settings of an OFB's samples, shared by display and export
 *
 * vtkOFBColoring holds how a sample of a vtkOFB gets its colour before lighting, as
 * vtkSurfaceLICInterface holds the settings that VTK's LIC mappers share. Both
 * vtkOFBPolyDataMapper (per fragment, on the GPU) and vtkOFBMapToColors (per sample, as
 * an RGBA byte array for export) read their colouring from one (GetColoring(), created
 * by default). Shared, `mapToColors->SetColoring(mapper->GetColoring())`, the export
 * writes exactly the colours that are shown, and a change made once is seen by both:
 * the mapper and the filter include the colouring's modification time in their own.
 *
 * The colour of a sample:
 * - ColorSource COLOR_SOURCE_PAINT (the "Colors" RGBA bytes; a sample with alpha 0 has
 *   RGB 0) or COLOR_SOURCE_SCALARS (ScalarArrayName, component ScalarComponent or its
 *   magnitude with -1, mapped through LookupTable over ScalarRange, or over the table's
 *   own range with UseLookupTableScalarRange; values outside the range are clamped to it);
 * - with IntensityModulation, the intensity L (IntensityArrayName, default "LIC", clamped
 *   to [0, 1]; the mapper keeps it as a byte, to 1/255) combined as VTK's surface LIC
 *   combines its LIC with the scalar colours (c: the source's colour, alpha kept):
 *   COLOR_MODE_BLEND: c' = c (1 - LICIntensity) + L LICIntensity;
 *   COLOR_MODE_MAP: c' = c mix(1, clamp(L + MapModeBias, 0, 1), IntensityWeight).
 * - with EnhanceColorContrast, the HSL lightness is then stretched, as VTK's
 *   ENHANCE_CONTRAST_COLOR does.
 *
 * Only settings live here; the arrays are looked up, and errors reported, by whoever
 * colours with them.
 *
 * @sa vtkOFBPolyDataMapper vtkOFBMapToColors vtkOFBLIC vtkSurfaceLICInterface
 */

#ifndef vtkOFBColoring_h
#define vtkOFBColoring_h

#include "vtkOFBExportModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for the array names

class vtkScalarsToColors;

class VTKOFBEXPORT_EXPORT vtkOFBColoring : public vtkObject
{
public:
  static vtkOFBColoring* New();
  vtkTypeMacro(vtkOFBColoring, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Where colours come from.
  enum ColorSources
  {
    COLOR_SOURCE_PAINT = 0,
    COLOR_SOURCE_SCALARS = 1
  };

  /// How the intensity combines with the colour, as vtkSurfaceLICInterface's ColorMode.
  enum LICColorModes
  {
    COLOR_MODE_BLEND = 0,
    COLOR_MODE_MAP = 1
  };

  ///@{
  /**
   * Where colours come from: COLOR_SOURCE_PAINT (default, the "Colors" sample array,
   * RGBA bytes) or COLOR_SOURCE_SCALARS (ScalarArrayName through the lookup table).
   */
  vtkSetClampMacro(ColorSource, int, COLOR_SOURCE_PAINT, COLOR_SOURCE_SCALARS);
  vtkGetMacro(ColorSource, int);
  void SetColorSourceToPaint() { this->SetColorSource(COLOR_SOURCE_PAINT); }
  void SetColorSourceToScalars() { this->SetColorSource(COLOR_SOURCE_SCALARS); }
  static const char* GetColorSourceAsString(int source);
  ///@}

  ///@{
  /**
   * The sample array mapped through the lookup table with COLOR_SOURCE_SCALARS (default
   * empty: none), and its component (default 0; -1 uses the magnitude; clamped to
   * [-1, 63]).
   */
  vtkSetStdStringFromCharMacro(ScalarArrayName);
  vtkGetCharFromStdStringMacro(ScalarArrayName);
  vtkSetClampMacro(ScalarComponent, int, -1, 63);
  vtkGetMacro(ScalarComponent, int);
  ///@}

  ///@{
  /**
   * The lookup table, reference counted (default none: GetLookupTable() makes a
   * vtkLookupTable with VTK's defaults, as vtkMapper does).
   */
  void SetLookupTable(vtkScalarsToColors* lut);
  vtkScalarsToColors* GetLookupTable();
  ///@}

  ///@{
  /**
   * The scalar range the lookup table maps, in the scalars' units (default 0 to 1, as
   * vtkMapper's), or the table's own range with UseLookupTableScalarRange (default off;
   * off sets the table's range when colouring, as vtkMapper does).
   */
  vtkSetVector2Macro(ScalarRange, double);
  vtkGetVector2Macro(ScalarRange, double);
  vtkSetMacro(UseLookupTableScalarRange, bool);
  vtkGetMacro(UseLookupTableScalarRange, bool);
  vtkBooleanMacro(UseLookupTableScalarRange, bool);
  ///@}

  /**
   * The lookup table ready to colour with, and the range it maps in `range`: the table's
   * own with UseLookupTableScalarRange, else ScalarRange, which is then set on the table
   * (as vtkMapper does).
   */
  vtkScalarsToColors* PrepareLookupTable(double range[2]);

  ///@{
  /**
   * The intensity (a LIC) combined with the colour when IntensityModulation is on
   * (default off): a 1-component sample array, values in [0, 1] (default "LIC", what
   * vtkOFBLIC writes).
   */
  vtkSetStdStringFromCharMacro(IntensityArrayName);
  vtkGetCharFromStdStringMacro(IntensityArrayName);
  vtkSetMacro(IntensityModulation, bool);
  vtkGetMacro(IntensityModulation, bool);
  vtkBooleanMacro(IntensityModulation, bool);
  ///@}

  ///@{
  /**
   * How the intensity combines with the colour (vtkSurfaceLICInterface's ColorMode;
   * vtkMapper has a ColorMode of its own): COLOR_MODE_BLEND (default) mixes the intensity
   * grey with the colour by LICIntensity, COLOR_MODE_MAP multiplies the colour by the
   * intensity plus MapModeBias. Formulas in the class documentation.
   */
  vtkSetClampMacro(LICColorMode, int, COLOR_MODE_BLEND, COLOR_MODE_MAP);
  vtkGetMacro(LICColorMode, int);
  void SetLICColorModeToBlend() { this->SetLICColorMode(COLOR_MODE_BLEND); }
  void SetLICColorModeToMap() { this->SetLICColorMode(COLOR_MODE_MAP); }
  static const char* GetLICColorModeAsString(int mode);
  ///@}

  ///@{
  /**
   * COLOR_MODE_BLEND: the intensity's share of the result, in [0, 1] (default 1: the LIC
   * alone at full contrast; VTK's default is 0.8): 0 shows the colour alone. Lower it, or
   * use COLOR_MODE_MAP, to see a colour under the LIC. Without EnhanceColorContrast the
   * mapper mixes the LIC into the lit colour, unlit, as VTK does.
   */
  vtkSetClampMacro(LICIntensity, double, 0.0, 1.0);
  vtkGetMacro(LICIntensity, double);
  ///@}

  ///@{
  /**
   * COLOR_MODE_MAP: added to the intensity before it multiplies the colour, in [-1, 1]
   * (default 0, as VTK's); positive values brighten, negative darken.
   */
  vtkSetClampMacro(MapModeBias, double, -1.0, 1.0);
  vtkGetMacro(MapModeBias, double);
  ///@}

  ///@{
  /**
   * COLOR_MODE_MAP: strength of the multiplication, in [0, 1] (default 1, VTK's formula):
   * the factor is mix(1, clamp(L + MapModeBias, 0, 1), IntensityWeight).
   */
  vtkSetClampMacro(IntensityWeight, double, 0.0, 1.0);
  vtkGetMacro(IntensityWeight, double);
  ///@}

  ///@{
  /**
   * VTK surface LIC's contrast enhancement of the final colour (its EnhanceContrast modes
   * ENHANCE_CONTRAST_COLOR and _BOTH; default off): the HSL lightness L of every colour
   * (after the intensity) is stretched, L' = clamp((L - m) / (M - m), 0, 1), with
   * m = min + Low (max - min) and M = max - High (max - min), min and max over the colours
   * of the OFB's samples with alpha above 0 (VTK takes them over the screen's fragments,
   * which change with the view: here they stay put); hue and saturation are kept. The
   * factors are in [0, 1] (default 0); where M <= m nothing is stretched.
   */
  vtkSetMacro(EnhanceColorContrast, bool);
  vtkGetMacro(EnhanceColorContrast, bool);
  vtkBooleanMacro(EnhanceColorContrast, bool);
  vtkSetClampMacro(LowColorContrastEnhancementFactor, double, 0.0, 1.0);
  vtkGetMacro(LowColorContrastEnhancementFactor, double);
  vtkSetClampMacro(HighColorContrastEnhancementFactor, double, 0.0, 1.0);
  vtkGetMacro(HighColorContrastEnhancementFactor, double);
  ///@}

  /**
   * Also the lookup table's modification time.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkOFBColoring();
  ~vtkOFBColoring() override;

  int ColorSource;
  std::string ScalarArrayName;
  int ScalarComponent;
  vtkScalarsToColors* LookupTable;
  double ScalarRange[2];
  bool UseLookupTableScalarRange;
  std::string IntensityArrayName;
  bool IntensityModulation;
  int LICColorMode;
  double LICIntensity;
  double MapModeBias;
  double IntensityWeight;
  bool EnhanceColorContrast;
  double LowColorContrastEnhancementFactor;
  double HighColorContrastEnhancementFactor;

private:
  vtkOFBColoring(const vtkOFBColoring&) = delete;
  void operator=(const vtkOFBColoring&) = delete;
};

#endif
