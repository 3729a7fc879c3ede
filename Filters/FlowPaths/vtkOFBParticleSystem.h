/**
 * @class   vtkOFBParticleSystem
 * @brief   The particles of vtkOFBParticleAdvector: seeds, steps, colours, trails (private)
 *
 * Particles live on a vtkOFBTriangleWalker. Seeds are surface points; particle
 * `id = seed * ChainLength + k` is the k-th particle of its seed's chain, released
 * at step k * ChainSpacing. `Advance()` makes one step of every particle in
 * parallel (vtkSMPTools; each particle reads and writes only its own state and
 * draws random numbers from its own stream, so the result does not depend on the
 * number of threads).
 */

#ifndef vtkOFBParticleSystem_h
#define vtkOFBParticleSystem_h

#include "vtkOFBParticleStepper.h"
#include "vtkOFBTriangleWalker.h"

#include <cstdint>
#include <vector>

class vtkOFBParticleSystem
{
public:
  enum State : unsigned char
  {
    WAITING = 0, ///< a chain member not released yet
    MOVING = 1,
    STOPPED = 2
  };

  struct Particle
  {
    vtkOFBSurfacePoint Point;
    glm::dvec3 Position{ 0.0 };
    glm::dvec3 Previous{ 0.0 };
    double SubStep = 0.0;
    vtkIdType Seed = 0;
    int Age = 0;
    int Generation = 0;
    int Chain = 0;
    State Status = WAITING;
    bool Painted = false; ///< moved during the last step: paints a footprint
    float Color[4] = { 1.f, 1.f, 1.f, 1.f };
  };

  /// Colouring of the particles at a step.
  struct Coloring
  {
    int Mode = 0; // vtkOFBParticleAdvector::ColorModes
    float Constant[3] = { 1.f, 0.f, 0.f };
    int Period = 60;
    /// ByScalar: the surface array (component 0), its range and a colour table.
    vtkDataArray* Scalars = nullptr;
    double Range[2] = { 0.0, 1.0 };
    std::vector<float> Table; // RGB, evenly over Range
  };

  /// Settings of the motion (any change restarts the particles).
  struct Settings
  {
    int ChainLength = 1;
    int ChainSpacing = 1;
    int Lifetime = 0;
    int TrailLength = 16;
    unsigned int RandomSeed = 0;
    bool RandomSeeds = true; ///< reseed at random points (else at the seed point)
  };

  const vtkOFBTriangleWalker* Walker = nullptr;
  vtkOFBParticleStepper Stepper;
  Settings Setup;

  /// Seed points and their colours (RGBA in [0, 1]).
  std::vector<vtkOFBSurfacePoint> Seeds;
  std::vector<float> SeedColors;

  std::vector<Particle> Particles;
  /// Per particle, 0 where another process advances it (null: every particle here).
  const unsigned char* Active = nullptr;
  std::vector<glm::dvec3> Trails; // TrailLength per particle, a ring
  std::vector<int> TrailCount;
  std::vector<int> TrailHead;
  vtkIdType CurrentStep = 0;

  /// `n` random seeds drawn area-uniformly from the streams of seeds 0..n-1.
  void MakeRandomSeeds(vtkIdType n);

  /// Particles at their seeds (chains waiting), step 0.
  void Start();

  /**
   * `numSteps` steps of every particle (each batch of the stepper's MaximumBatch
   * particles makes all of them in a row); colours from `coloring` at each new
   * step. Footprints and `Painted` are those of the last step.
   */
  void Advance(const Coloring& coloring, vtkIdType numSteps = 1);

  /// The field at a particle (its tangent plane, world units, with the direction).
  glm::dvec3 Velocity(const Particle& p) const;

  /// Positions of particle i's trail, oldest first.
  int GetTrail(vtkIdType i, glm::dvec3* out) const;

  /// The footprint weight of a chain member: 1 - k / ChainLength.
  double ChainWeight(int k) const { return 1.0 - static_cast<double>(k) / this->Setup.ChainLength; }

  /// The periodic colour (red, blue, green) at `step` for `period` steps.
  static void PeriodicColor(vtkIdType step, int period, float rgb[3]);

  /// A uniform number in [0, 1) of draw `k` of stream (seed, particle, generation).
  static double Random(unsigned int seed, vtkIdType particle, int generation, int k);

  /// Add `x` to the end of particle i's trail.
  void PushTrail(vtkIdType i, const glm::dvec3& x);

private:
  void Reseed(vtkIdType i, Particle& p);
  void Release(vtkIdType i, Particle& p);
  /// One step (`step` to `step + 1`) of particles begin..end-1 (at most a batch).
  void AdvanceBatch(vtkIdType begin, vtkIdType end, vtkIdType step, const Coloring& coloring);
  /// The colour of `p` at `step` (steps since the seeds).
  void ColorParticle(const Coloring& coloring, vtkIdType step, Particle& p) const;
};

#endif
