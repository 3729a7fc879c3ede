// Private header of vtkOFBLIC: the noise that the LIC convolves, a function of the
// 3-D position (so samples of different grids at the same surface point read the same
// value, and no seam shows where the grids meet) and of a seed.
#ifndef vtkOFBLICNoise_h
#define vtkOFBLICNoise_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

/**
 * Settings of the generated noise, in the units of vtkOFBLIC's knobs (see there).
 * `Grain` is the edge of a noise lattice cell in world units (NoiseGrainSize cells).
 */
struct vtkOFBLICNoiseSettings
{
  int Type = 1; // vtkOFBLIC::NOISE_TYPE_UNIFORM, _GAUSSIAN, _PERLIN
  double Grain = 1.0;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double MinValue = 0.0;
  double MaxValue = 0.8;
  int Levels = 256;
  double ImpulseProbability = 1.0;
  double ImpulseBackground = 0.0;
  std::uint64_t Seed = 1;
};

/**
 * Solid noise on a 3-D lattice of cells of edge `Grain`:
 * - uniform or Gaussian white noise: one value per lattice cell, from a hash of the
 *   cell's integer coordinates and the seed (no table, no state: thread-safe and the
 *   same for any order of evaluation);
 * - Perlin noise: the sum of four octaves of gradient noise with periods of 2, 4, 8
 *   and 16 lattice cells, gradients from the same hash.
 * The value in [0, 1] is then quantized to `Levels` levels, mapped to
 * [MinValue, MaxValue], and replaced by ImpulseBackground in lattice cells whose
 * impulse draw is at or above ImpulseProbability (impulse noise), as VTK's
 * vtkSurfaceLICInterface generates its noise texture.
 */
class vtkOFBLICNoise
{
public:
  explicit vtkOFBLICNoise(const vtkOFBLICNoiseSettings& s)
    : S(s)
    , Origin(s.Origin[0], s.Origin[1], s.Origin[2])
    , InvGrain(1.0 / s.Grain)
  {
    if (s.Type == 1 && s.Levels > 1 && s.Levels <= MaxTabulatedLevels)
    {
      this->TabulateGaussian();
    }
  }

  /// The noise value at world position x.
  float Evaluate(const glm::dvec3& x) const
  {
    const glm::dvec3 g = (x - this->Origin) * this->InvGrain;
    const glm::dvec3 f = glm::floor(g);
    const std::int64_t ix = Cell(f.x);
    const std::int64_t iy = Cell(f.y);
    const std::int64_t iz = Cell(f.z);
    double u;
    switch (this->S.Type)
    {
      case 0:
        u = this->Uniform(ix, iy, iz, 1);
        break;
      case 2:
        u = this->Perlin(g);
        break;
      default:
        u = this->Thresholds.empty() ? this->Gaussian(ix, iy, iz) : this->Uniform(ix, iy, iz, 1);
        break;
    }
    if (this->S.ImpulseProbability < 1.0 &&
      this->Uniform(ix, iy, iz, 3) >= this->S.ImpulseProbability)
    {
      return static_cast<float>(this->S.ImpulseBackground);
    }
    if (!this->Thresholds.empty())
    {
      return static_cast<float>(this->FinishLevel(this->GaussianLevel(u)));
    }
    return static_cast<float>(this->Finish(u));
  }

  /// A lattice coordinate as an integer, clamped in double to +-2^62 (NaN to 0) first: a
  /// far origin or position has no int64 cell.
  static std::int64_t Cell(double v)
  {
    constexpr double limit = 4611686018427387904.0; // 2^62
    return static_cast<std::int64_t>(
      v > -limit ? (v < limit ? v : limit) : (v <= -limit ? -limit : 0.0));
  }

  /// A 64-bit hash of a lattice cell, the seed and a stream number (splitmix64 rounds).
  static std::uint64_t Hash(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t seed)
  {
    std::uint64_t h = seed * 0x9E3779B97F4A7C15ull;
    const std::uint64_t keys[3] = {
      static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(z)
    };
    for (const std::uint64_t k : keys)
    {
      h ^= k + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
      h ^= h >> 30;
      h *= 0xBF58476D1CE4E5B9ull;
      h ^= h >> 27;
      h *= 0x94D049BB133111EBull;
      h ^= h >> 31;
    }
    return h;
  }

private:
  /// Uniform in [0, 1) from stream `stream` of the cell.
  double Uniform(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t stream) const
  {
    const std::uint64_t h = Hash(x, y, z, this->S.Seed * 4 + stream);
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
  }

  /// Gaussian (Box-Muller) with mean 0.5 and standard deviation 1/6, clamped to [0, 1].
  double Gaussian(std::int64_t x, std::int64_t y, std::int64_t z) const
  {
    const double u1 = 1.0 - this->Uniform(x, y, z, 1); // (0, 1]
    const double u2 = this->Uniform(x, y, z, 2);
    const double n = std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    return std::min(1.0, std::max(0.0, 0.5 + n / 6.0));
  }

  /// Gradient noise of one octave at lattice position p (period 1), in about [-1, 1].
  double Gradient(const glm::dvec3& p, std::uint64_t octave) const
  {
    const glm::dvec3 f = glm::floor(p);
    const glm::dvec3 t = p - f;
    const glm::dvec3 w = t * t * t * (t * (t * 6.0 - 15.0) + 10.0); // quintic fade
    double corners[8];
    for (int c = 0; c < 8; ++c)
    {
      const glm::dvec3 o((c & 1) ? 1.0 : 0.0, (c & 2) ? 1.0 : 0.0, (c & 4) ? 1.0 : 0.0);
      const glm::dvec3 q = f + o;
      const std::uint64_t h = Hash(Cell(q.x), Cell(q.y), Cell(q.z), this->S.Seed * 16 + 8 + octave);
      // One of the 12 edge directions of a cube (improved Perlin noise).
      static const double g[12][3] = { { 1, 1, 0 },
        { -1, 1, 0 },
        { 1, -1, 0 },
        { -1, -1, 0 },
        { 1, 0, 1 },
        { -1, 0, 1 },
        { 1, 0, -1 },
        { -1, 0, -1 },
        { 0, 1, 1 },
        { 0, -1, 1 },
        { 0, 1, -1 },
        { 0, -1, -1 } };
      const double* gv = g[(h >> 32) % 12];
      const glm::dvec3 d = t - o;
      corners[c] = gv[0] * d.x + gv[1] * d.y + gv[2] * d.z;
    }
    const double x00 = corners[0] + w.x * (corners[1] - corners[0]);
    const double x10 = corners[2] + w.x * (corners[3] - corners[2]);
    const double x01 = corners[4] + w.x * (corners[5] - corners[4]);
    const double x11 = corners[6] + w.x * (corners[7] - corners[6]);
    const double y0 = x00 + w.y * (x10 - x00);
    const double y1 = x01 + w.y * (x11 - x01);
    return y0 + w.z * (y1 - y0);
  }

  /// Four octaves of gradient noise at g (lattice units), mapped to [0, 1].
  double Perlin(const glm::dvec3& g) const
  {
    double sum = 0.0;
    double period = 2.0;
    for (std::uint64_t octave = 0; octave < 4; ++octave, period *= 2.0)
    {
      sum += this->Gradient(g / period, octave);
    }
    return std::min(1.0, std::max(0.0, 0.5 + 0.35 * sum));
  }

  /// Quantize to Levels levels and map to [MinValue, MaxValue].
  double Finish(double u) const
  {
    const int levels = this->S.Levels;
    if (levels <= 1)
    {
      return this->S.MaxValue;
    }
    return this->FinishLevel(std::min<int>(levels - 1, static_cast<int>(std::floor(u * levels))));
  }

  /// Level j of Levels mapped to [MinValue, MaxValue].
  double FinishLevel(int j) const
  {
    const double q = static_cast<double>(j) / (this->S.Levels - 1);
    return this->S.MinValue + q * (this->S.MaxValue - this->S.MinValue);
  }

  /**
   * Gaussian noise quantized to Levels levels, drawn from one uniform u by inverting
   * its distribution: the level of Gaussian() followed by Finish() is at least k with
   * probability 1 - Phi(6 (k / Levels - 1/2)), so the level is the number of
   * thresholds Phi(6 (k / Levels - 1/2)), k = 1 ... Levels - 1, at or below u. The
   * same distribution as Box-Muller's, for one hash and no logarithm or cosine.
   */
  void TabulateGaussian()
  {
    const int levels = this->S.Levels;
    this->Thresholds.resize(levels - 1);
    for (int k = 1; k < levels; ++k)
    {
      const double x = 6.0 * (static_cast<double>(k) / levels - 0.5);
      this->Thresholds[k - 1] = 0.5 * std::erfc(-x / std::sqrt(2.0));
    }
    // Buckets of u: the thresholds below each bucket's start.
    this->Buckets.resize(NumberOfBuckets + 1);
    for (int b = 0, j = 0; b <= NumberOfBuckets; ++b)
    {
      const double start = static_cast<double>(b) / NumberOfBuckets;
      while (j < levels - 1 && this->Thresholds[j] < start)
      {
        ++j;
      }
      this->Buckets[b] = j;
    }
  }

  int GaussianLevel(double u) const
  {
    int j = this->Buckets[static_cast<int>(u * NumberOfBuckets)];
    const int last = static_cast<int>(this->Thresholds.size());
    while (j < last && this->Thresholds[j] <= u)
    {
      ++j;
    }
    return j;
  }

  static constexpr int MaxTabulatedLevels = 1 << 16;
  static constexpr int NumberOfBuckets = 4096;

  vtkOFBLICNoiseSettings S;
  glm::dvec3 Origin;
  double InvGrain;
  std::vector<double> Thresholds; // Gaussian levels (TabulateGaussian), else empty
  std::vector<int> Buckets;
};

#endif
