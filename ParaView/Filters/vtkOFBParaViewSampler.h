/**
 * @class   vtkOFBParaViewSampler
 * @brief   vtkOFBBuilder whose vector field may be "none", for ParaView's array menus
 *
 * ParaView's array list sets the vector field with SetInputArrayToProcess, and sets the
 * name "None" (or an empty name) when the input has no vector array or the user chose
 * none. vtkOFBBuilder takes a name it cannot find as an error; this subclass takes
 * "None" and the empty name as "no vector field" (the samples get no active vectors),
 * and passes every other choice on unchanged.
 *
 * @sa vtkOFBBuilder vtkOFBSampler
 */

#ifndef vtkOFBParaViewSampler_h
#define vtkOFBParaViewSampler_h

#include "vtkOFBBuilder.h"
#include "vtkOFBParaViewModule.h" // for export macro

class VTKOFBPARAVIEW_EXPORT vtkOFBParaViewSampler : public vtkOFBBuilder
{
public:
  static vtkOFBParaViewSampler* New();
  vtkTypeMacro(vtkOFBParaViewSampler, vtkOFBBuilder);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  using Superclass::SetInputArrayToProcess;
  /**
   * As vtkAlgorithm's, except that the name "None" or an empty name removes the choice
   * of array `idx` (no vector field).
   */
  void SetInputArrayToProcess(int idx,
    int port,
    int connection,
    int fieldAssociation,
    const char* name) override;

protected:
  vtkOFBParaViewSampler();
  ~vtkOFBParaViewSampler() override;

private:
  vtkOFBParaViewSampler(const vtkOFBParaViewSampler&) = delete;
  void operator=(const vtkOFBParaViewSampler&) = delete;
};

#endif
