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
 * Under MPI (pvbatch or pvserver on several processes, each with its piece of the
 * surface), the pieces are sampled by vtkOFBPSampler with the same settings: one frame
 * for the whole surface (an all-reduce of the pieces' bounds), ghost cells sampled and
 * flagged in the sample array "vtkGhostType". There the CPU builds the samples whatever
 * the Backend. With one process, or no controller, it is vtkOFBBuilder.
 *
 * @sa vtkOFBBuilder vtkOFBSampler vtkOFBPSampler
 */

#ifndef vtkOFBParaViewSampler_h
#define vtkOFBParaViewSampler_h

#include "vtkOFBBuilder.h"
#include "vtkOFBParaViewModule.h" // for export macro
#include "vtkSmartPointer.h"      // for Pieces

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

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The distributed sampler that samples this process's piece under MPI.
  vtkSmartPointer<vtkAlgorithm> Pieces;

private:
  vtkOFBParaViewSampler(const vtkOFBParaViewSampler&) = delete;
  void operator=(const vtkOFBParaViewSampler&) = delete;
};

#endif
