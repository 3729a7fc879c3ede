/**
 * @class   vtkOFBParticleExchange
 * @brief   The collective calls vtkOFBParticleAdvector makes on a distributed surface
 *
 * Set by a distributed subclass (vtkOFBPParticleAdvector) for the time of its
 * RequestData. With one, each process advances the particles that are on its own
 * (non-ghost) triangles, sends their states to every process after each step (so every
 * process paints every footprint into its own samples, in particle order), and hands a
 * particle whose step ended on a ghost triangle to the process that owns the triangle
 * (found by the particle's position). Every method is a collective call.
 *
 * @sa vtkOFBParticleAdvector vtkOFBPParticleAdvector
 */

#ifndef vtkOFBParticleExchange_h
#define vtkOFBParticleExchange_h

#include <vector> // for the buffers

class vtkOFBParticleExchange
{
public:
  virtual ~vtkOFBParticleExchange() = default;

  /// This process's index, from 0.
  virtual int GetRank() = 0;

  /// Every process's `local` values, concatenated in the order of the processes.
  virtual void AllGather(const std::vector<double>& local, std::vector<double>& all) = 0;

  /// The element-wise minimum over every process, in place (the same length everywhere).
  virtual void AllReduceMinimum(std::vector<double>& values) = 0;

  /// The maximum of `value` over every process.
  virtual double AllReduceMaximum(double value) = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkOFBParticleExchange.h
