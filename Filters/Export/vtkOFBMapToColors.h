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
 * The colouring is a vtkOFBColoring (GetColoring(), one made by default): the colour
 * source (paint, or scalars through a lookup table), the intensity and how it combines
 * (VTK surface LIC's blend and map), the colour contrast; the formulas are in its
 * documentation. Give the filter a mapper's, `SetColoring(mapper->GetColoring())`, and
 * what is exported is what is seen; a change to the shared object re-executes the filter
 * (GetMTime includes the colouring's).
 *
 * Alpha is the source's. Channels are rounded to bytes (value 255, rounded).
 *
 * Output: a copy of the input OFB (its arrays shared, not copied) with the array
 * OutputArrayName (default "DisplayColors"; "Colors" replaces the paint in the copy) as
 * its active scalars. The input is untouched.
 *
 * Errors (an empty output): no input OFB, no colouring, COLOR_SOURCE_SCALARS without a
 * numeric sample array ScalarArrayName or with a ScalarComponent it lacks,
 * COLOR_SOURCE_PAINT without RGBA byte "Colors", IntensityModulation without a 1-component numeric
 * IntensityArrayName, an empty OutputArrayName, a ScalarRange that is not finite. A NaN scalar
 * takes the table's NaN colour, a NaN intensity counts as 0.
 *
 * @sa vtkOFBColoring vtkOFBPolyDataMapper vtkOFBLIC vtkOFBTextureBaker vtkImageMapToColors
 */

#ifndef vtkOFBMapToColors_h
#define vtkOFBMapToColors_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBExportModule.h" // for export macro

#include <string> // for the array names

class vtkDataArray;
class vtkOFB;
class vtkOFBColoring;

class VTKOFBEXPORT_EXPORT vtkOFBMapToColors : public vtkOFBAlgorithm
{
public:
  static vtkOFBMapToColors* New();
  vtkTypeMacro(vtkOFBMapToColors, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The colouring settings (default: a vtkOFBColoring of its own). Set a mapper's to
   * export what it shows; the object is shared, not copied. Null is refused with an
   * error (the colouring stays as it was).
   */
  void SetColoring(vtkOFBColoring* coloring);
  vtkGetObjectMacro(Coloring, vtkOFBColoring);
  ///@}

  /**
   * After an update with the colouring's EnhanceColorContrast: the smallest and largest lightness
   * of the colours before the stretch, what the mapper stretches by (0 0 without the stretch or
   * without samples of alpha above 0: not computed).
   */
  vtkGetVector2Macro(LightnessRange, double);

  /**
   * The lightness range that an update with the colouring's EnhanceColorContrast would find for
   * `input` (the smallest and largest HSL lightness of the colours with alpha above 0, before the
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
   * Also the colouring's modification time (which includes its lookup table's).
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
  struct SampleColoring;
  void Prepare(vtkDataArray* source, vtkDataArray* intensity, SampleColoring& coloring);

  vtkOFBColoring* Coloring;
  std::string OutputArrayName;
  double LightnessRange[2];

private:
  vtkOFBMapToColors(const vtkOFBMapToColors&) = delete;
  void operator=(const vtkOFBMapToColors&) = delete;
};

#endif
