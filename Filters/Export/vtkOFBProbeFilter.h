/**
 * @class   vtkOFBProbeFilter
 * @brief   Transfer the sample arrays of a vtkOFB to the points of a surface
 *
 * vtkOFBProbeFilter gives every point of its input vtkPolyData (port 0) the values of
 * the sample arrays of a vtkOFB (port 1, `SetOFBConnection` / `SetOFBData`, as
 * vtkProbeFilter's source): the paint ("Colors", RGBA bytes), the LIC, painted normals,
 * any array. The output is the input surface with these arrays as point data, so a
 * painting or a LIC can be saved in any format that keeps point arrays (PLY with
 * vertex colours, VTP, OBJ through vtkOBJWriter) and opened where vtkOFB is not
 * installed. Detail finer than the surface's edges is lost: the values are those at
 * the points (use vtkOFBTextureBaker to keep it in a texture).
 *
 * Two lookups: `LOOKUP_NEAREST` (default), the value of the closest sample within
 * `Radius`, as vtkOFBPolyDataMapper's Nearest mode; and `LOOKUP_SMOOTH`, the mean of the
 * samples within `Radius` weighted by (1 - d^2/r^2)^2, as vtkOFBPyramid filters its
 * levels (integer arrays rounded). A point with no sample within `Radius` takes the
 * closest within twice `Radius`; a point with none there gets zeros and a 0 in the
 * `vtkValidPointMask` array (1 elsewhere; the name as vtkProbeFilter's, see
 * `ValidPointMaskArrayName`).
 *
 * With `NormalAware` (default on) and point normals on the input (the active
 * normals), samples whose normal faces away from the point's normal are skipped, so
 * that the two sides of a thin sheet keep their own values. Without point normals the
 * test is not made (add them with vtkPolyDataNormals).
 *
 * The OFB's arrays replace input point arrays of the same names and keep their
 * attribute roles (the OFB's active scalars, "Colors", become the output's, so a PLY
 * writer writes them as vertex colours). `PassPointArrays` (default on) keeps the
 * input's other point arrays; `AddArrayName` probes only the named arrays.
 *
 * Errors (an empty output): no OFB, an empty OFB, a Radius that is not positive and
 * finite, a named array that the OFB lacks.
 *
 * @sa vtkOFBToPolyData vtkOFBTextureBaker vtkProbeFilter
 */

#ifndef vtkOFBProbeFilter_h
#define vtkOFBProbeFilter_h

#include "vtkOFBExportModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for ArrayNames
#include <vector> // for ArrayNames

class vtkOFB;

class VTKOFBEXPORT_EXPORT vtkOFBProbeFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkOFBProbeFilter* New();
  vtkTypeMacro(vtkOFBProbeFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OFB to probe (input port 1).
   */
  void SetOFBConnection(vtkAlgorithmOutput* output);
  void SetOFBData(vtkOFB* ofb);
  vtkOFB* GetOFB();
  ///@}

  enum LookupModes
  {
    LOOKUP_NEAREST = 0,
    LOOKUP_SMOOTH = 1
  };

  ///@{
  /**
   * How a point's values are found: the closest sample (`LOOKUP_NEAREST`, default) or the
   * weighted mean of the samples within Radius (`LOOKUP_SMOOTH`).
   */
  vtkSetClampMacro(LookupMode, int, LOOKUP_NEAREST, LOOKUP_SMOOTH);
  vtkGetMacro(LookupMode, int);
  void SetLookupModeToNearest() { this->SetLookupMode(LOOKUP_NEAREST); }
  void SetLookupModeToSmooth() { this->SetLookupMode(LOOKUP_SMOOTH); }
  ///@}

  ///@{
  /**
   * Search radius in cells of the OFB (default sqrt(3), the paper's bound on the
   * distance from a surface point to its nearest sample). Must be positive and finite.
   */
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Skip samples facing away from the point's normal (default on; needs point normals).
   */
  vtkSetMacro(NormalAware, bool);
  vtkGetMacro(NormalAware, bool);
  vtkBooleanMacro(NormalAware, bool);
  ///@}

  ///@{
  /**
   * Keep the input's point arrays (default on); the OFB's arrays replace those of the
   * same names.
   */
  vtkSetMacro(PassPointArrays, bool);
  vtkGetMacro(PassPointArrays, bool);
  vtkBooleanMacro(PassPointArrays, bool);
  ///@}

  ///@{
  /**
   * Name of the array marking the points that found a sample (unsigned char, 1 or 0;
   * default "vtkValidPointMask"). An empty name leaves the array out.
   */
  vtkSetStdStringFromCharMacro(ValidPointMaskArrayName);
  vtkGetCharFromStdStringMacro(ValidPointMaskArrayName);
  ///@}

  ///@{
  /**
   * Probe only these sample arrays (none added: all of them).
   */
  void AddArrayName(const char* name);
  void ClearArrayNames();
  int GetNumberOfArrayNames() const { return static_cast<int>(this->ArrayNames.size()); }
  const char* GetArrayName(int i) const;
  ///@}

  /**
   * Number of points of the last update with no sample within twice Radius.
   */
  vtkGetMacro(NumberOfInvalidPoints, vtkIdType);

protected:
  vtkOFBProbeFilter();
  ~vtkOFBProbeFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int LookupMode = LOOKUP_NEAREST;
  double Radius;
  bool NormalAware = true;
  bool PassPointArrays = true;
  std::string ValidPointMaskArrayName = "vtkValidPointMask";
  std::vector<std::string> ArrayNames;
  vtkIdType NumberOfInvalidPoints = 0;

private:
  vtkOFBProbeFilter(const vtkOFBProbeFilter&) = delete;
  void operator=(const vtkOFBProbeFilter&) = delete;
};

#endif
