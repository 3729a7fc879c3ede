/**
 * @file   vtkOFBPaintWaves.h
 * @brief  Private: the order in which vtkOFBPaintKernel paints a call's dabs
 *
 * Dabs are grouped into waves: a dab goes one wave after the last earlier dab whose
 * sphere (or smear source sphere) it overlaps, so the dabs of a wave touch disjoint
 * samples and may run in parallel, and painting wave after wave gives the result of
 * painting the dabs one after the other. Within a wave the dabs are in Morton order
 * of their centres, so that consecutive dabs read neighbouring rows of the grids.
 */

#ifndef vtkOFBPaintWaves_h
#define vtkOFBPaintWaves_h

#include "vtkType.h"

#include <glm/vec3.hpp>

#include <utility>
#include <vector>

struct vtkOFBDab;

class vtkOFBPaintWaves
{
public:
  /**
   * Group and order `dabs`; with `smear`, a dab's sphere also covers its smear
   * source (the previous position).
   */
  void Compute(const std::vector<vtkOFBDab>& dabs, bool smear);

  /// The dabs by wave, then in Morton order.
  const std::vector<int>& GetOrder() const { return this->Order; }

  /// The first position in GetOrder() of each wave, and the end.
  const std::vector<int>& GetWaveStarts() const { return this->WaveStarts; }

private:
  void Sort(int numberOfWaves, const glm::dvec3& low, double maxReach);
  void SortKeys(int begin, int end);

  // Kept from call to call.
  std::vector<int> Order;
  std::vector<int> WaveStarts;
  std::vector<glm::dvec3> Centre;
  std::vector<double> Reach;
  std::vector<size_t> BucketOf;
  std::vector<int> BucketStart;
  std::vector<int> Fill;
  std::vector<int> Members;
  std::vector<int> Wave;
  std::vector<std::pair<vtkTypeUInt64, int>> Key; // Morton code, dab
  std::vector<std::pair<vtkTypeUInt64, int>> KeyScratch;
  std::vector<int> DigitCount;
};

#endif
