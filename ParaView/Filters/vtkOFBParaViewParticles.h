/**
 * @class   vtkOFBParaViewParticles
 * @brief   vtkOFBParticleAdvector with time steps that ParaView's animation steps through
 *
 * On a steady field vtkOFBParticleAdvector counts time in steps from the seeds and
 * reports an open time range ([0, VTK_INT_MAX]) with no time steps. ParaView's
 * animation scene takes the time steps of its sources, so this subclass reports
 * NumberOfTimeSteps of them, 0, 1, ..., NumberOfTimeSteps - 1 (the time range
 * [0, NumberOfTimeSteps - 1]): the animation toolbar's play, next and last frame step the
 * particles (time t is step floor(t) from the seeds). On an unsteady field (a surface
 * with TIME_STEPS) the input's time steps are reported, as vtkOFBParticleAdvector does.
 *
 * Settings that ParaView's array menus give: the vector field through
 * SetInputArrayToProcess, where the name "None" or an empty name means the surface's
 * active vectors.
 *
 * Under MPI it is vtkOFBPParticleAdvector: each process advances the particles on its
 * piece of the surface and hands those that leave it to the process that owns where they
 * go. The seeds (port 2) are asked for whole on every process (piece 0 of 1), as
 * vtkOFBPParticleAdvector needs the same seeds everywhere. With one process, or no
 * controller, it is vtkOFBParticleAdvector.
 *
 * @sa vtkOFBParticleAdvector vtkOFBPParticleAdvector
 */

#ifndef vtkOFBParaViewParticles_h
#define vtkOFBParaViewParticles_h

#include "vtkOFBPParticleAdvector.h"
#include "vtkOFBParaViewModule.h" // for export macro

class VTKOFBPARAVIEW_EXPORT vtkOFBParaViewParticles : public vtkOFBPParticleAdvector
{
public:
  static vtkOFBParaViewParticles* New();
  vtkTypeMacro(vtkOFBParaViewParticles, vtkOFBPParticleAdvector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The time steps reported on a steady field: 0 to NumberOfTimeSteps - 1, in particle
   * steps (>= 1; default 100).
   */
  vtkSetClampMacro(NumberOfTimeSteps, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  using Superclass::SetInputArrayToProcess;
  /**
   * As vtkAlgorithm's, except that the name "None" or an empty name removes the choice
   * of array `idx` (the active vectors are used).
   */
  void SetInputArrayToProcess(int idx,
    int port,
    int connection,
    int fieldAssociation,
    const char* name) override;

protected:
  vtkOFBParaViewParticles();
  ~vtkOFBParaViewParticles() override;

  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;
  int RequestUpdateExtent(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

  int NumberOfTimeSteps;

private:
  vtkOFBParaViewParticles(const vtkOFBParaViewParticles&) = delete;
  void operator=(const vtkOFBParaViewParticles&) = delete;
};

#endif
