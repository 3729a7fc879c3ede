/**
 * @class   vtkOFBParaViewProbe
 * @brief   vtkOFBProbeFilter whose output carries the OFB it probed
 *
 * The output is vtkOFBProbeFilter's (the mesh with the OFB's sample arrays on its
 * points) and, in its information (vtkDataObject::GetInformation()), the OFB itself
 * under the key OFB(). Algorithms downstream in the same process find the OFB there:
 * vtkOFBTexturedMeshWriter (ParaView's File > Save Data on this filter's output) bakes
 * it into a texture, a representation can colour the surface from it. The key is not
 * copied by ShallowCopy or DeepCopy: it reaches the algorithms that take this output
 * directly, not the outputs of filters in between.
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
   * The OFB that `data`'s information holds under OFB(), or null.
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
