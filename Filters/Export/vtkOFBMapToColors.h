/**
 * @class   vtkOFBMapToColors
 * @brief   The colours vtkOFBPolyDataMapper shows, as an RGBA sample array of an OFB
 *
 * vtkOFBMapToColors computes at every sample the colour that vtkOFBPolyDataMapper
 * computes per fragment before lighting: a colour source (the paint, or a scalar
 * sample array through a lookup table) combined with a LIC (or any intensity array) as
 * VTK's surface LIC combines them. The result is an RGBA byte sample array that
 * everything taking paint takes: vtkOFBTextureBaker (with vtkOFBTextureAtlas, a LIC in
 * colour exported as an OBJ with its texture), vtkOFBProbeFilter (vertex colours),
 * vtkOFBWriter, vtkOFBToPolyData, or the mapper itself with its Paint source.
 *
 * The settings have the names, defaults and formulas of the mapper's (there:
 * vtkOFBPolyDataMapper::CopyColoringTo() sets them from a mapper, so that what is
 * exported is what is seen):
 * - ColorSource Paint (the "Colors" RGBA bytes; a sample with alpha 0 has RGB 0) or
 *   Scalars (ScalarArrayName, component ScalarComponent or its magnitude with -1,
 *   mapped through LookupTable over ScalarRange, or over the table's own range with
 *   UseLookupTableScalarRange; values outside the range are clamped to it);
 * - with IntensityModulation, the intensity L (IntensityArrayName, default "LIC",
 *   clamped to [0, 1]; the mapper keeps it as a byte, to 1/255):
 *   COLOR_MODE_BLEND: rgb' = rgb (1 - LICIntensity) + L LICIntensity;
 *   COLOR_MODE_MAP: rgb' = rgb mix(1, clamp(L + MapModeBias, 0, 1), IntensityWeight).
 * Alpha is the source's. With EnhanceColorContrast the lightness is then stretched, as
 * VTK's ENHANCE_CONTRAST_COLOR does. Channels are rounded to bytes (value 255, rounded).
 *
 * Output: a copy of the input OFB (its arrays shared, not copied) with the array
 * OutputArrayName (default "DisplayColors"; "Colors" replaces the paint in the copy) as
 * its active scalars. The input is untouched.
 *
 * Errors (an empty output): no input OFB, ColorSource Scalars without a numeric sample
 * array ScalarArrayName or with a ScalarComponent it lacks, Paint without RGBA byte
 * "Colors", IntensityModulation without a 1-component numeric IntensityArrayName, an
 * empty OutputArrayName, a ScalarRange that is not finite. A NaN scalar takes the
 * table's NaN colour, a NaN intensity counts as 0.
 *
 * @sa vtkOFBPolyDataMapper vtkOFBLIC vtkOFBTextureBaker vtkImageMapToColors
 */

#ifndef vtkOFBMapToColors_h
#define vtkOFBMapToColors_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBExportModule.h" // for export macro

#include <string> // for the array names

class vtkDataArray;
class vtkOFB;
class vtkScalarsToColors;

class VTKOFBEXPORT_EXPORT vtkOFBMapToColors : public vtkOFBAlgorithm
{
public:
  static vtkOFBMapToColors* New();
  vtkTypeMacro(vtkOFBMapToColors, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ColorSources
  {
    Paint = 0,
    Scalars = 1
  };

  enum LICColorModes
  {
    COLOR_MODE_BLEND = 0,
    COLOR_MODE_MAP = 1
  };

  ///@{
  /**
   * Where colours come from: Paint (default, the "Colors" sample array, RGBA bytes) or
   * Scalars (ScalarArrayName through the lookup table).
   */
  vtkSetClampMacro(ColorSource, int, Paint, Scalars);
  vtkGetMacro(ColorSource, int);
  void SetColorSourceToPaint() { this->SetColorSource(Paint); }
  void SetColorSourceToScalars() { this->SetColorSource(Scalars); }
  ///@}

  ///@{
  /**
   * The sample array mapped through the lookup table with ColorSource Scalars (default
   * empty), and its component (default 0; -1 uses the magnitude).
   */
  vtkSetStdStringFromCharMacro(ScalarArrayName);
  vtkGetCharFromStdStringMacro(ScalarArrayName);
  vtkSetClampMacro(ScalarComponent, int, -1, 63);
  vtkGetMacro(ScalarComponent, int);
  ///@}

  ///@{
  /**
   * The lookup table (default none: a vtkLookupTable with VTK's defaults, made at the
   * first update), and the scalar range it maps (default 0 to 1, as vtkMapper's), or the
   * table's own range with UseLookupTableScalarRange (default off; off sets the table's
   * range, as vtkMapper does).
   */
  void SetLookupTable(vtkScalarsToColors* lut);
  vtkScalarsToColors* GetLookupTable();
  vtkSetVector2Macro(ScalarRange, double);
  vtkGetVector2Macro(ScalarRange, double);
  vtkSetMacro(UseLookupTableScalarRange, bool);
  vtkGetMacro(UseLookupTableScalarRange, bool);
  vtkBooleanMacro(UseLookupTableScalarRange, bool);
  ///@}

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
   * How the intensity combines with the colour (vtkSurfaceLICInterface's ColorMode):
   * COLOR_MODE_BLEND (default) or COLOR_MODE_MAP; formulas in the class documentation.
   */
  vtkSetClampMacro(LICColorMode, int, COLOR_MODE_BLEND, COLOR_MODE_MAP);
  vtkGetMacro(LICColorMode, int);
  void SetLICColorModeToBlend() { this->SetLICColorMode(COLOR_MODE_BLEND); }
  void SetLICColorModeToMap() { this->SetLICColorMode(COLOR_MODE_MAP); }
  ///@}

  ///@{
  /**
   * COLOR_MODE_BLEND: the intensity's share, in [0, 1] (default 0.8). COLOR_MODE_MAP:
   * MapModeBias added to the intensity, in [-1, 1] (default 0), and IntensityWeight the
   * strength of the multiplication, in [0, 1] (default 1).
   */
  vtkSetClampMacro(LICIntensity, double, 0.0, 1.0);
  vtkGetMacro(LICIntensity, double);
  vtkSetClampMacro(MapModeBias, double, -1.0, 1.0);
  vtkGetMacro(MapModeBias, double);
  vtkSetClampMacro(IntensityWeight, double, 0.0, 1.0);
  vtkGetMacro(IntensityWeight, double);
  ///@}

  ///@{
  /**
   * VTK surface LIC's contrast enhancement of the final colour (its EnhanceContrast
   * modes ENHANCE_CONTRAST_COLOR and _BOTH; default off): the HSL lightness L of every
   * colour (after the intensity) is stretched, L' = clamp((L - m) / (M - m), 0, 1), with
   * m = min + Low (max - min) and M = max - High (max - min) over the samples' colours with
   * alpha above 0; hue and saturation are kept. The factors are in [0, 1] (default 0);
   * where M <= m nothing is stretched.
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
   * After an update with EnhanceColorContrast: the smallest and largest lightness of the
   * colours before the stretch, what the mapper stretches by (0 0 without the stretch or
   * without samples of alpha above 0: not computed).
   */
  vtkGetVector2Macro(LightnessRange, double);

  /**
   * The lightness range that an update with EnhanceColorContrast would find for `input`
   * (the smallest and largest HSL lightness of the colours with alpha above 0, before the
   * stretch), computed without writing any output or colour array: what
   * vtkOFBPolyDataMapper stretches by. False, with 0 0, where there is no such colour or
   * the input lacks the arrays the settings name (an error then).
   */
  bool ComputeLightnessRange(vtkOFB* input, double range[2]);

  ///@{
  /**
   * Name of the RGBA byte array written (default "DisplayColors"); it becomes the
   * output's active scalars.
   */
  vtkSetStdStringFromCharMacro(OutputArrayName);
  vtkGetCharFromStdStringMacro(OutputArrayName);
  ///@}

  /**
   * Also the lookup table's modification time.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkOFBMapToColors();
  ~vtkOFBMapToColors() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /// The source colour array (Colors or the scalars) and the intensity (or null), checked;
  /// false with an error.
  bool FindArrays(vtkOFB* input, vtkDataArray*& source, vtkDataArray*& intensity);

  /// The per-sample colouring of the settings (the sampled table, the values as floats).
  struct Coloring;
  void Prepare(vtkDataArray* source, vtkDataArray* intensity, Coloring& coloring);

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
  std::string OutputArrayName;
  double LightnessRange[2];

private:
  vtkOFBMapToColors(const vtkOFBMapToColors&) = delete;
  void operator=(const vtkOFBMapToColors&) = delete;
};

#endif
