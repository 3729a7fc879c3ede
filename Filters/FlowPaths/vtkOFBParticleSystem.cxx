#include "vtkOFBParticleSystem.h"

#include "vtkDataArray.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

namespace
{
// SplitMix64's finalizer: a well-mixed 64-bit hash.
inline std::uint64_t Mix(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}
}

//------------------------------------------------------------------------------
double vtkOFBParticleSystem::Random(unsigned int seed, vtkIdType particle, int generation, int k)
{
  std::uint64_t h = Mix(static_cast<std::uint64_t>(seed));
  h = Mix(h ^ static_cast<std::uint64_t>(particle));
  h = Mix(h ^ static_cast<std::uint64_t>(generation));
  h = Mix(h ^ static_cast<std::uint64_t>(k));
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::PeriodicColor(vtkIdType step, int period, float rgb[3])
{
  static const float palette[3][3] = { { 1.f, 0.f, 0.f }, { 0.f, 0.f, 1.f }, { 0.f, 1.f, 0.f } };
  const double phase = 3.0 * static_cast<double>(step % period) / period;
  const int from = std::min(2, static_cast<int>(phase));
  const int to = (from + 1) % 3;
  const float f = static_cast<float>(phase - from);
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = (1.f - f) * palette[from][c] + f * palette[to][c];
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::MakeRandomSeeds(vtkIdType n)
{
  this->Seeds.resize(n);
  this->SeedColors.assign(4 * n, 1.f);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const unsigned int seed = this->Setup.RandomSeed;
    this->Seeds[i] =
      this->Walker->Sample(Random(seed, i, -1, 0), Random(seed, i, -1, 1), Random(seed, i, -1, 2));
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::Start()
{
  const int chain = this->Setup.ChainLength;
  const vtkIdType n = static_cast<vtkIdType>(this->Seeds.size()) * chain;
  this->Particles.assign(n, Particle());
  const int length = this->Setup.TrailLength;
  this->Trails.assign(n * length, glm::dvec3(0.0));
  this->TrailCount.assign(n, 0);
  this->TrailHead.assign(n, 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    Particle& p = this->Particles[i];
    p.Seed = i / chain;
    p.Chain = static_cast<int>(i % chain);
    p.Status = WAITING;
    std::copy_n(&this->SeedColors[4 * p.Seed], 4, p.Color);
    if (p.Chain == 0)
    {
      this->Release(i, p);
    }
  }
  this->CurrentStep = 0;
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::PushTrail(vtkIdType i, const glm::dvec3& x)
{
  const int length = this->Setup.TrailLength;
  int& head = this->TrailHead[i];
  this->Trails[i * length + head] = x;
  head = head + 1 == length ? 0 : head + 1;
  this->TrailCount[i] = std::min(length, this->TrailCount[i] + 1);
}

//------------------------------------------------------------------------------
int vtkOFBParticleSystem::GetTrail(vtkIdType i, glm::dvec3* out) const
{
  const int length = this->Setup.TrailLength;
  const int count = this->TrailCount[i];
  const int first = (this->TrailHead[i] - count + length) % length;
  for (int k = 0; k < count; ++k)
  {
    out[k] = this->Trails[i * length + (first + k) % length];
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::Release(vtkIdType i, Particle& p)
{
  p.Point = this->Seeds[p.Seed];
  p.Position = this->Walker->Position(p.Point);
  p.Previous = p.Position;
  p.Age = 0;
  p.SubStep = 0.0;
  p.Status = MOVING;
  this->TrailCount[i] = 0;
  this->TrailHead[i] = 0;
  this->PushTrail(i, p.Position);
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::Reseed(vtkIdType i, Particle& p)
{
  ++p.Generation;
  if (this->Setup.RandomSeeds && this->Setup.ChainLength == 1)
  {
    const unsigned int seed = this->Setup.RandomSeed;
    p.Point = this->Walker->Sample(Random(seed, i, p.Generation, 0),
      Random(seed, i, p.Generation, 1),
      Random(seed, i, p.Generation, 2));
    p.Position = this->Walker->Position(p.Point);
    p.Previous = p.Position;
    p.Age = 0;
    p.SubStep = 0.0;
    p.Status = MOVING;
    this->TrailCount[i] = 0;
    this->TrailHead[i] = 0;
    this->PushTrail(i, p.Position);
  }
  else
  {
    this->Release(i, p);
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::ColorParticle(const Coloring& coloring,
  vtkIdType step,
  Particle& p) const
{
  switch (coloring.Mode)
  {
    case 0: // constant
      std::copy_n(coloring.Constant, 3, p.Color);
      break;
    case 1: // from seeds
      std::copy_n(&this->SeedColors[4 * p.Seed], 3, p.Color);
      break;
    case 2: // by scalar
    {
      if (!coloring.Scalars || coloring.Table.empty())
      {
        break;
      }
      const double v = this->Walker->Interpolate(coloring.Scalars, 0, p.Point);
      const int n = static_cast<int>(coloring.Table.size() / 3);
      const double width = coloring.Range[1] - coloring.Range[0];
      const double t = width > 0.0 ? (v - coloring.Range[0]) / width : 0.0;
      // Clamped before it becomes an integer: a NaN or a value far out of the range
      // overflows the conversion (undefined; on x86 the first colour, not the last).
      const double tc = std::isfinite(t) ? std::min(std::max(t, 0.0), 1.0) : 0.0;
      const int k = std::min(n - 1, static_cast<int>(tc * n));
      std::copy_n(&coloring.Table[3 * k], 3, p.Color);
      break;
    }
    case 3: // periodic
    default:
      PeriodicColor(step, coloring.Period, p.Color);
      break;
  }
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::Advance(const Coloring& coloring, vtkIdType numSteps)
{
  const vtkIdType first = this->CurrentStep;
  this->CurrentStep += numSteps;
  constexpr vtkIdType batch = vtkOFBParticleStepper::MaximumBatch;
  // Ranges of at least a batch: the stepper's batches cost about the same for a
  // few particles as for a full batch.
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(this->Particles.size()),
    batch,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; i += batch)
      {
        const vtkIdType last = std::min(end, i + batch);
        const vtkIdType ahead = std::min(end - last, batch);
        for (vtkIdType k = last; k < last + ahead; ++k)
        {
          if (this->Particles[k].Point.Triangle >= 0)
          {
            this->Walker->Prefetch(this->Particles[k].Point.Triangle);
          }
        }
        // All the steps of a batch of particles in a row: their triangles stay in
        // the cache.
        for (vtkIdType step = first; step < first + numSteps; ++step)
        {
          this->AdvanceBatch(i, last, step, coloring);
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkOFBParticleSystem::AdvanceBatch(vtkIdType begin,
  vtkIdType end,
  vtkIdType step,
  const Coloring& coloring)
{
  vtkOFBSurfacePoint* points[vtkOFBParticleStepper::MaximumBatch];
  double* subSteps[vtkOFBParticleStepper::MaximumBatch];
  vtkIdType moving[vtkOFBParticleStepper::MaximumBatch];
  vtkOFBParticleStepper::Result results[vtkOFBParticleStepper::MaximumBatch];
  int n = 0;
  const int lifetime = this->Setup.Lifetime;
  for (vtkIdType i = begin; i < end; ++i)
  {
    // Where the stages of the step may go: fetched for all the batch at once.
    if (this->Particles[i].Status == MOVING && (!this->Active || this->Active[i]))
    {
      this->Walker->PrefetchNeighbors(this->Particles[i].Point.Triangle);
    }
  }
  for (vtkIdType i = begin; i < end; ++i)
  {
    Particle& p = this->Particles[i];
    p.Painted = false;
    if (this->Active && !this->Active[i])
    {
      continue; // another process advances it
    }
    if (p.Status == WAITING)
    {
      // Released at its seed when the step count reaches its release step.
      if (step + 1 >= static_cast<vtkIdType>(p.Chain) * this->Setup.ChainSpacing)
      {
        this->Release(i, p);
        p.Painted = true;
      }
      continue;
    }
    if (lifetime > 0 && (p.Age >= lifetime || p.Status == STOPPED))
    {
      this->Reseed(i, p);
    }
    ++p.Age;
    if (p.Status == MOVING)
    {
      p.Previous = p.Position;
      points[n] = &p.Point;
      subSteps[n] = &p.SubStep;
      moving[n] = i;
      ++n;
    }
  }
  this->Stepper.Advance(n, points, subSteps, results);
  for (int j = 0; j < n; ++j)
  {
    const vtkIdType i = moving[j];
    Particle& p = this->Particles[i];
    p.Position = this->Walker->Position(p.Point);
    p.Painted = results[j] != vtkOFBParticleStepper::STOPPED_AT_ZERO;
    if (results[j] != vtkOFBParticleStepper::MOVED)
    {
      p.Status = STOPPED;
    }
    if (p.Painted)
    {
      this->PushTrail(i, p.Position);
    }
  }
  for (vtkIdType i = begin; i < end; ++i)
  {
    Particle& p = this->Particles[i];
    if (p.Status != WAITING && (!this->Active || this->Active[i]))
    {
      this->ColorParticle(coloring, step + 1, p);
    }
  }
}

//------------------------------------------------------------------------------
glm::dvec3 vtkOFBParticleSystem::Velocity(const Particle& p) const
{
  return this->Stepper.Sign * this->Walker->Field(p.Point);
}
