/**
 * @class   vtkOFBPParticleAdvector
 * @brief   vtkOFBParticleAdvector on a surface distributed over processes: particles handed off
 *
 * Each process holds a piece of the surface (port 0) with ghost cells (it asks for
 * NumberOfGhostLevels levels, and more when they do not cover one step: StepSize cells,
 * and the stages of the integrator within it) and paints its piece of the OFB (port 1,
 * from vtkOFBPSampler). Points a rounding error apart are one point of the surface, so
 * the seams of pieces made apart join. The seeds (port 2) are the same on every
 * process: each seed goes to the process whose own (non-ghost) triangle is closest to
 * it. Each process advances the particles it owns; after every step the states of all
 * particles are sent to every process (an all-gather of 23 doubles a particle), so that
 * every process paints every footprint into its own samples in particle order, and a
 * particle whose step ended on a ghost triangle goes to the process that owns that
 * triangle, found by the particle's position (two all-reduces over the particles that
 * left). No particle is lost or duplicated: one not claimed stays where it was. Each
 * process outputs the particles (port 1) and trails (port 2) it owns; together they are
 * one process's.
 *
 * Limits: seeds are required and Lifetime must be 0 (random seeds and reseeds are drawn
 * from each piece's own triangles): otherwise an error on every process. The field's
 * scale with NormalizeVectors off is the largest speed of every process. The cell size
 * (the unit of StepSize) is the OFB's: give the OFB of vtkOFBPSampler, whose frame is
 * common. A process with an empty piece makes the same collective calls with nothing to
 * contribute and outputs no particles. With an unsteady surface (pathlines) each
 * process plans its time steps from its own piece's speeds (not equal to one
 * process), and an empty piece is an error on every process. With no controller, or a
 * single process, it is vtkOFBParticleAdvector.
 *
 * @sa vtkOFBParticleAdvector vtkOFBParticleExchange vtkOFBPSampler
 */

#ifndef vtkOFBPParticleAdvector_h
#define vtkOFBPParticleAdvector_h

#include "vtkOFBParallelModule.h" // for export macro
#include "vtkOFBParticleAdvector.h"

class vtkMultiProcessController;

class VTKOFBPARALLEL_EXPORT vtkOFBPParticleAdvector : public vtkOFBParticleAdvector
{
public:
  static vtkOFBPParticleAdvector* New();
  vtkTypeMacro(vtkOFBPParticleAdvector, vtkOFBParticleAdvector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes that share the surface (default: the global controller at
   * construction). Null or a single process: no communication.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * Ghost levels asked of the surface (port 0), at least (default 2). When a piece's
   * ghost cells end less than a step from its own triangles (a walk of a step could
   * reach their end), every process asks for twice as many levels and executes again,
   * up to 64 levels (GetRequiredGhostLevels).
   */
  vtkSetClampMacro(NumberOfGhostLevels, int, 0, 1024);
  vtkGetMacro(NumberOfGhostLevels, int);
  ///@}

  /**
   * The ghost levels that the steps needed, found by the updates so far (0 when
   * NumberOfGhostLevels was enough; never lowered).
   */
  int GetRequiredGhostLevels() const { return this->RequiredGhostLevels; }

  /**
   * The particles handed from one process to another during the last update (the same
   * number on every process).
   */
  vtkIdType GetNumberOfHandOffs() const { return this->NumberOfHandOffs; }

protected:
  vtkOFBPParticleAdvector();
  ~vtkOFBPParticleAdvector() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkMultiProcessController* Controller;
  int NumberOfGhostLevels;

private:
  vtkOFBPParticleAdvector(const vtkOFBPParticleAdvector&) = delete;
  void operator=(const vtkOFBPParticleAdvector&) = delete;
};

#endif
