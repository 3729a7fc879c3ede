/**
 * @class   vtkOFBParaViewProbe
 * @brief   vtkOFBProbeFilter whose output carries the OFB it probed
 *
 * The output is vtkOFBProbeFilter's (the mesh with the OFB's sample arrays on its
 * points), and GetOFB() finds the OFB probed from that output or from any shallow copy
 * of it, in the same process: vtkOFBTexturedMeshWriter (ParaView's File > Save Data on
 * this filter's output) bakes it into a texture, a representation can colour the
 * surface from it. ParaView hands a filter's output to the algorithms downstream as a
 * shallow copy (its post filter), which keeps the arrays and drops the information
 * keys, so the OFB is found in two ways: the output's information holds it under the
 * key OFB(), and the output's "vtkValidPointMask" array (shared by shallow copies) is
 * registered with it, weakly (an OFB or array deleted is forgotten). A deep copy or a
 * filter that makes new arrays loses it.
 *
 * @sa vtkOFBProbeFilter vtkOFBTexturedMeshWriter
 */

#ifndef vtkOFBParaViewProbe_h
#define vtkOFBParaViewProbe_h

#include "vtkOFBParaViewModule.h" // for export macro
#include "vtkOFBProbeFilter.h"

class vtkDataObject;
class vtkInformationDataObjectKey;
class vtkOFB;

class VTKOFBPARAVIEW_EXPORT vtkOFBParaViewProbe : public vtkOFBProbeFilter
{
public:
  static vtkOFBParaViewProbe* New();
  vtkTypeMacro(vtkOFBParaViewProbe, vtkOFBProbeFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The key under which the output's information holds the OFB probed.
   */
  static vtkInformationDataObjectKey* OFB();

  /**
   * The OFB probed into `data` or into the output that `data` is a shallow copy of:
   * the one its information holds under OFB(), else the one registered with its
   * "vtkValidPointMask" point array; null if none.
   */
  static vtkOFB* GetOFB(vtkDataObject* data);

protected:
  vtkOFBParaViewProbe();
  ~vtkOFBParaViewProbe() override;

  int RequestData(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

private:
  vtkOFBParaViewProbe(const vtkOFBParaViewProbe&) = delete;
  void operator=(const vtkOFBParaViewProbe&) = delete;
};

#endif
