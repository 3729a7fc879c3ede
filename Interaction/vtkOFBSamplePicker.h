/**
 * @class   vtkOFBSamplePicker
 * @brief   The OFB sample under a display position
 *
 * vtkOFBSamplePicker picks the surface under a display position with a
 * vtkCellPicker, then looks up the OFB sample at the picked point with
 * vtkOFB::FindSample in the grid most aligned with the picked cell's face normal:
 * the grid that holds that triangle's samples. The sample found lies in the cell of
 * that grid under the picked point (within half a cell of it across the grid) and
 * within a cell of it in depth. Where there is none (the ray through that cell's
 * centre meets another triangle), it falls back to vtkOFB::FindClosestSample. It is
 * the picking half of the painter widget.
 *
 * Pick() returns the sample id, or -1 when nothing is hit, no OFB is set or no
 * sample lies within sqrt(3) cells of the hit point.
 */

#ifndef vtkOFBSamplePicker_h
#define vtkOFBSamplePicker_h

#include "vtkOFBInteractionModule.h" // for export macro
#include "vtkObject.h"

class vtkCellPicker;
class vtkOFB;
class vtkRenderer;

class VTKOFBINTERACTION_EXPORT vtkOFBSamplePicker : public vtkObject
{
public:
  static vtkOFBSamplePicker* New();
  vtkTypeMacro(vtkOFBSamplePicker, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OFB whose samples are picked (default none).
   */
  void SetOFB(vtkOFB* ofb);
  vtkGetObjectMacro(OFB, vtkOFB);
  ///@}

  ///@{
  /**
   * Tolerance of the cell picker, as a fraction of the window diagonal (default 0.001).
   */
  vtkSetClampMacro(Tolerance, double, 0.0, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  /**
   * Pick at display position (x, y) in `renderer`; returns the sample id or -1.
   */
  vtkIdType Pick(double x, double y, vtkRenderer* renderer);

  ///@{
  /**
   * World position and normal of the last surface hit.
   */
  vtkGetVector3Macro(PickPosition, double);
  vtkGetVector3Macro(PickNormal, double);
  ///@}

  /**
   * Sample of the last pick, or -1.
   */
  vtkGetMacro(SampleId, vtkIdType);

protected:
  vtkOFBSamplePicker();
  ~vtkOFBSamplePicker() override;

  /**
   * The geometric normal of the picked cell (of its picked triangle in a strip), not
   * normalized; false when there is none.
   */
  bool GetFaceNormal(double normal[3]);

  vtkOFB* OFB;
  vtkCellPicker* Picker;
  double Tolerance;
  double PickPosition[3];
  double PickNormal[3];
  vtkIdType SampleId;

private:
  vtkOFBSamplePicker(const vtkOFBSamplePicker&) = delete;
  void operator=(const vtkOFBSamplePicker&) = delete;
};

#endif
