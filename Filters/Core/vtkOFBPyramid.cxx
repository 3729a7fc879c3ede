#include "vtkOFBPyramid.h"
#include "vtkOFBPyramidResampler.h"
#include "vtkOFBRuns.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBSampler.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace
{
/// Scale the 3-component "Normals" sample array of `ofb` to unit length: samples
/// ids[0 .. count) where ids is given, else all.
void NormalizeSampleNormals(vtkOFB* ofb, const vtkIdType* ids = nullptr, vtkIdType count = 0)
{
  vtkDataArray* normals = ofb->GetSampleData()->GetArray(vtkOFB::NormalsArrayName());
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    return;
  }
  const vtkIdType n = ids ? count : ofb->GetNumberOfSamples();
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType i = ids ? ids[k] : k;
    double v[3];
    normals->GetTuple(i, v);
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0)
    {
      v[0] /= len;
      v[1] /= len;
      v[2] /= len;
      normals->SetTuple(i, v);
    }
  }
}

/// The filter radius of Resample (world units) for `radius` asked: at least the sqrt(3)
/// cells of the source within which a surface point always has a sample, so that every
/// target sample finds one.
double FilterRadiusOf(vtkOFB* source, double radius)
{
  return std::max(radius, std::sqrt(3.0) * source->GetCellSize());
}

/**
 * vtkOFBPyramid::Resample of the arrays in `names` (all where it is null); the facing
 * test's target normals are `reference` (3 floats a target sample) where given, else
 * the target's own; `fellBack` (one byte a target sample), where given, receives 1 for
 * the target samples with no source within the radius.
 */
bool ResampleArrays(vtkOFB* source,
  vtkOFB* target,
  double radius,
  const std::set<std::string>* names,
  const float* reference = nullptr,
  unsigned char* fellBack = nullptr)
{
  if (!source || !target || !(radius > 0.0) || source->GetNumberOfSamples() == 0)
  {
    return false;
  }
  vtkOFBPyramidResampler transfer(source, target, FilterRadiusOf(source, radius));
  transfer.SetTargetNormals(reference);
  transfer.FellBack = fellBack;
  transfer.CollectArrays(names);
  vtkSMPTools::For(0, target->GetNumberOfSamples(), transfer);
  transfer.ReplaceTargetArrays();
  if (!names || names->count(vtkOFB::NormalsArrayName()))
  {
    NormalizeSampleNormals(target);
  }
  return true;
}

/**
 * The target samples (sorted) whose Resample from `source` (with `radius`) may read one
 * of the source samples `changed`: those within the radius of one, and those that fell
 * back (`fellBack`, Resample's closest sample within 2 radius) with one within 2 radius.
 * The changed samples are gathered into cubes of half the radius first, and each cube
 * asks for the targets within the radius of any point of it (a superset: filtering a
 * target whose sources did not change gives its values again).
 */
std::vector<vtkIdType> AffectedTargets(vtkOFB* source,
  const std::vector<vtkIdType>& changed,
  vtkOFB* target,
  double radius,
  const unsigned char* fellBack)
{
  const double* origin = source->GetOrigin();
  const double side = 0.5 * radius;
  std::vector<vtkTypeUInt64> cubes;
  cubes.reserve(changed.size());
  std::vector<unsigned char> isChanged(static_cast<size_t>(source->GetNumberOfSamples()), 0);
  for (vtkIdType j : changed)
  {
    isChanged[j] = 1;
    double x[3];
    source->GetSamplePosition(j, x);
    vtkTypeUInt64 key = 0;
    for (int c = 0; c < 3; ++c)
    {
      const double q = std::max(0.0, std::floor((x[c] - origin[c]) / side));
      key = (key << 21) | (static_cast<vtkTypeUInt64>(std::min(q, 2097151.0)));
    }
    cubes.push_back(key);
  }
  std::sort(cubes.begin(), cubes.end());
  cubes.erase(std::unique(cubes.begin(), cubes.end()), cubes.end());
  const vtkIdType nt = target->GetNumberOfSamples();
  std::vector<std::atomic<unsigned char>> hit(static_cast<size_t>(nt)); // zeros
  const double reach = radius + 0.5 * std::sqrt(3.0) * side;
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(cubes.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        vtkTypeUInt64 key = cubes[k];
        double centre[3];
        for (int c = 2; c >= 0; --c)
        {
          centre[c] = origin[c] + (static_cast<double>(key & 2097151u) + 0.5) * side;
          key >>= 21;
        }
        // Threads may mark the same target (each writes the same value).
        target->ForEachSampleInSphere(
          centre, reach, [&](vtkIdType t, double) { hit[t].store(1, std::memory_order_relaxed); });
      }
    });
  std::vector<vtkIdType> ids;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    bool affected = hit[t].load(std::memory_order_relaxed) != 0;
    if (!affected && fellBack && fellBack[t])
    {
      double x[3];
      target->GetSamplePosition(t, x);
      source->ForEachSampleInSphere(
        x, 2.0 * radius, [&](vtkIdType j, double) { affected = affected || isChanged[j]; });
    }
    if (affected)
    {
      ids.push_back(t);
    }
  }
  return ids;
}

/**
 * Resample of the arrays `names` (all where null) of `source` to the target samples `ids`
 * alone, in place (the
 * other target samples keep their values), their normals scaled to unit length; the
 * facing test's target normals are `reference` where given, `fellBack` as in
 * ResampleArrays. False (nothing changed) where the target lacks an array of the source
 * or one differs in type or size.
 */
bool ResampleSome(vtkOFB* source,
  vtkOFB* target,
  double radius,
  const std::vector<vtkIdType>& ids,
  const float* reference,
  unsigned char* fellBack,
  const std::set<std::string>* names)
{
  vtkOFBPyramidResampler transfer(source, target, radius);
  transfer.SetTargetNormals(reference);
  transfer.FellBack = fellBack;
  transfer.CollectArrays(names, false);
  if (!transfer.WriteInPlace())
  {
    return false;
  }
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(ids.size()),
    [&](vtkIdType begin, vtkIdType end) { transfer.Filter(ids.data(), begin, end); });
  NormalizeSampleNormals(target, ids.data(), static_cast<vtkIdType>(ids.size()));
  return true;
}

/// Levels 1.. (`levels`) filtered from level 0 (`input`) one after the other: the arrays
/// in `names`, all where it is null. `radius` in cells of each coarser level; the facing
/// test's target normals and the fallback record of level k + 1 are references[k] and
/// fellBacks[k] (see ResampleArrays).
void FilterLevels(vtkOFB* input,
  const std::vector<vtkSmartPointer<vtkOFB>>& levels,
  double radius,
  const std::set<std::string>* names,
  const std::vector<const float*>& references,
  const std::vector<unsigned char*>& fellBacks)
{
  for (size_t k = 0; k < levels.size(); ++k)
  {
    vtkOFB* finer = k == 0 ? input : levels[k - 1].Get();
    ResampleArrays(
      finer, levels[k], radius * levels[k]->GetCellSize(), names, references[k], fellBacks[k]);
  }
}

/// A 64-bit hash of an array's values, bytes and layout (null: 0).
vtkTypeUInt64 HashValues(vtkDataArray* array)
{
  if (!array)
  {
    return 0;
  }
  const size_t bytes = static_cast<size_t>(array->GetDataSize()) * array->GetDataTypeSize();
  const auto* data = static_cast<const unsigned char*>(array->GetVoidPointer(0));
  vtkTypeUInt64 h = 0x9E3779B97F4A7C15ull ^ (bytes * 31 + array->GetDataType());
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8)
  {
    vtkTypeUInt64 w;
    std::memcpy(&w, data + i, 8);
    h = (h ^ w) * 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  }
  for (; i < bytes; ++i)
  {
    h = (h ^ data[i]) * 0x94D049BB133111EBull;
  }
  return h ^ (h >> 29);
}

/**
 * The sampler of the coarser levels: the box their frames are computed from is the one
 * level 0's frame was computed from. That is the surface's bounds where they give level
 * 0's frame (an OFB sampled from this surface); otherwise (a piece of a distributed
 * surface sampled on the whole surface's frame, vtkOFBPSampler) the box is recovered from
 * level 0's origin, dimensions and cell size, so that every piece's levels have the same
 * frames when their level 0 has.
 */
class vtkOFBPyramidLevelSampler : public vtkOFBSampler
{
public:
  static vtkOFBPyramidLevelSampler* New();
  vtkTypeMacro(vtkOFBPyramidLevelSampler, vtkOFBSampler);

  vtkOFB* Finest = nullptr;

  /// The frame (origin, cell size, dimensions) that `b` gives at `resolution`, as
  /// vtkOFBSampler::ComputeFrame computes it.
  static void FrameOf(const double b[6],
    int resolution,
    double origin[3],
    double& cellSize,
    vtkIdType dims[3])
  {
    const double longest = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
    cellSize = longest / (resolution - 2);
    for (int a = 0; a < 3; ++a)
    {
      const double cells = std::ceil((b[2 * a + 1] - b[2 * a]) / cellSize - 1e-9);
      dims[a] = std::max<vtkIdType>(1, static_cast<vtkIdType>(cells)) + 2;
      origin[a] = 0.5 * (b[2 * a] + b[2 * a + 1]) - 0.5 * dims[a] * cellSize;
    }
  }

protected:
  vtkOFBPyramidLevelSampler() = default;
  ~vtkOFBPyramidLevelSampler() override = default;

  void GetFrameBounds(const double surfaceBounds[6], double bounds[6]) override
  {
    std::copy(surfaceBounds, surfaceBounds + 6, bounds);
    if (!this->Finest || !(this->Finest->GetCellSize() > 0.0))
    {
      return;
    }
    const vtkIdType* d0 = this->Finest->GetDimensions();
    const double* o0 = this->Finest->GetOrigin();
    const double h0 = this->Finest->GetCellSize();
    const vtkIdType finest = std::max({ d0[0], d0[1], d0[2] }) - 2;
    double origin[3];
    double h = 0.0;
    vtkIdType dims[3];
    FrameOf(surfaceBounds, static_cast<int>(finest) + 2, origin, h, dims);
    bool same = std::abs(h - h0) <= 1e-9 * h0;
    for (int a = 0; a < 3 && same; ++a)
    {
      same = dims[a] == d0[a] && std::abs(origin[a] - o0[a]) <= 1e-6 * h0;
    }
    if (same)
    {
      return;
    }
    // Level 0's box: its frame less the padding cell on each side, the longest side
    // `finest` cells long.
    for (int a = 0; a < 3; ++a)
    {
      const double centre = o0[a] + 0.5 * static_cast<double>(d0[a]) * h0;
      const double half = 0.5 * static_cast<double>(d0[a] == finest + 2 ? finest : d0[a] - 2) * h0;
      bounds[2 * a] = centre - half;
      bounds[2 * a + 1] = centre + half;
    }
  }

private:
  vtkOFBPyramidLevelSampler(const vtkOFBPyramidLevelSampler&) = delete;
  void operator=(const vtkOFBPyramidLevelSampler&) = delete;
};
vtkStandardNewMacro(vtkOFBPyramidLevelSampler);

/// Mark the sorted samples `ids` of `ofb` modified, as at most 128 ranges (runs joined
/// across their smallest gaps first), and the OFB Modified().
void MarkRuns(vtkOFB* ofb, const std::vector<vtkIdType>& ids)
{
  std::vector<std::pair<vtkIdType, vtkIdType>> runs;
  for (vtkIdType i : ids)
  {
    if (!runs.empty() && runs.back().second == i)
    {
      ++runs.back().second;
    }
    else
    {
      runs.emplace_back(i, i + 1);
    }
  }
  for (vtkIdType gap = 64; runs.size() > 128; gap *= 2)
  {
    vtkOFBJoinRuns(runs, gap);
  }
  for (const auto& run : runs)
  {
    ofb->MarkSamplesModified(run.first, run.second);
  }
  ofb->Modified();
}
}

vtkStandardNewMacro(vtkOFBPyramid);
vtkCxxSetObjectMacro(vtkOFBPyramid, InputOFB, vtkOFB);
vtkCxxSetObjectMacro(vtkOFBPyramid, Surface, vtkPolyData);
vtkCxxSetObjectMacro(vtkOFBPyramid, LevelSurface, vtkPolyData);

//------------------------------------------------------------------------------
vtkOFBPyramid::vtkOFBPyramid()
  : InputOFB(nullptr)
  , Surface(nullptr)
  , LevelSurface(nullptr)
  , MaximumNumberOfLevels(8)
  , MinimumResolution(8)
  , FilterRadius(1.5)
  , FilterCacheSize(128)
  , NumberOfFilterCacheHits(0)
{
}

//------------------------------------------------------------------------------
vtkOFBPyramid::~vtkOFBPyramid()
{
  this->SetInputOFB(nullptr);
  this->SetSurface(nullptr);
  this->SetLevelSurface(nullptr);
}

//------------------------------------------------------------------------------
int vtkOFBPyramid::GetNumberOfLevels() const
{
  return this->InputOFB ? 1 + static_cast<int>(this->Levels.size()) : 0;
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBPyramid::GetLevel(int k) const
{
  if (k == 0)
  {
    return this->InputOFB;
  }
  if (!this->InputOFB || k < 0 || k > static_cast<int>(this->Levels.size()))
  {
    return nullptr;
  }
  return this->Levels[k - 1];
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::UpdateLevels()
{
  if (!this->InputOFB || this->InputOFB->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("UpdateLevels: no input OFB, or an empty one.");
    this->Levels.clear();
    return false;
  }
  const bool rebuild = this->InputOFB != this->LastInputOFB ||
    this->InputOFB->GetStructureMTime() > this->StructureTime.GetMTime() ||
    this->GetMTime() > this->StructureTime.GetMTime() ||
    (this->Surface && this->Surface->GetMTime() > this->StructureTime.GetMTime()) ||
    (this->LevelSurface && this->LevelSurface->GetMTime() > this->StructureTime.GetMTime());
  if (rebuild)
  {
    this->Levels.clear();
    this->States.clear();
    this->LastInputOFB = this->InputOFB;
    this->StructureTime.Modified();
    vtkPolyData* surface = this->LevelSurface ? this->LevelSurface : this->Surface;
    if (this->MaximumNumberOfLevels > 1 && !surface)
    {
      vtkErrorMacro("UpdateLevels: no surface to sample the coarser levels from.");
      return false;
    }
    const vtkIdType* dims = this->InputOFB->GetDimensions();
    // The sampler pads the frame by one cell on each side: halve the unpadded cells so
    // that the cell size doubles from level to level.
    const int finest = static_cast<int>(std::max({ dims[0], dims[1], dims[2] })) - 2;
    vtkNew<vtkOFBPyramidLevelSampler> sampler;
    sampler->Finest = this->InputOFB;
    sampler->SetInputData(surface);
    sampler->UseInputColorsOff();
    sampler->PassPointArraysOff();
    for (int k = 1; k < this->MaximumNumberOfLevels; ++k)
    {
      const int resolution = (finest >> k) + 2;
      if ((finest >> k) < 1 || resolution < this->MinimumResolution)
      {
        break;
      }
      sampler->SetResolution(resolution);
      sampler->Update();
      vtkOFB* out = sampler->GetOutput();
      if (!out || out->GetNumberOfSamples() == 0)
      {
        vtkErrorMacro("UpdateLevels: level " << k << " could not be sampled.");
        this->Levels.clear();
        this->States.clear();
        return false;
      }
      vtkSmartPointer<vtkOFB> level = vtkSmartPointer<vtkOFB>::New();
      level->DeepCopy(out);
      this->Levels.push_back(level);
      // The sampler's normals: the facing test's reference at every filtering (the
      // level's "Normals" become the filtered ones), so that a filtering does not depend
      // on the ones before.
      this->States.emplace_back();
      LevelState& state = this->States.back();
      state.FellBack.assign(static_cast<size_t>(level->GetNumberOfSamples()), 0);
      auto* normals = vtkFloatArray::FastDownCast(vtkOFBSampleNormals(level->GetSampleData()));
      if (normals)
      {
        state.ReferenceNormals.assign(
          normals->GetPointer(0), normals->GetPointer(0) + 3 * level->GetNumberOfSamples());
      }
    }
    this->StructureTime.Modified();
  }
  if (rebuild)
  {
    this->UpdateArrays();
  }
  else if (this->InputOFB->GetMTime() > this->ArraysTime.GetMTime())
  {
    this->UpdateModifiedArrays();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::UpdateArrays()
{
  this->FilterCache.clear();
  this->FilterAllLevels(nullptr);
  // Kept as well: an animation's first phase comes back after the others.
  if (this->FilterCacheSize > 0 && this->InputOFB)
  {
    std::vector<std::pair<std::string, vtkTypeUInt64>> hashes;
    vtkPointData* pd = this->InputOFB->GetSampleData();
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = pd->GetArray(a);
      if (array && array->GetName() &&
        array->GetNumberOfTuples() == this->InputOFB->GetNumberOfSamples())
      {
        hashes.emplace_back(array->GetName(), HashValues(array));
      }
    }
    this->CacheLevels(hashes);
  }
  this->AllArraysTime.Modified();
  this->ArraysTime.Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::UpdateModifiedArrays()
{
  if (!this->InputOFB || this->Levels.empty())
  {
    this->ArraysTime.Modified();
    return;
  }
  // The named sample arrays of level 0 modified (or new) since the last computation.
  // All of them where level 1 lacks one of their names, or where none is newer although
  // the OFB is (values changed in place without the array's Modified()).
  vtkPointData* pd = this->InputOFB->GetSampleData();
  vtkPointData* coarse = this->Levels[0]->GetSampleData();
  std::set<std::string> changed;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || !array->GetName() ||
      array->GetNumberOfTuples() != this->InputOFB->GetNumberOfSamples())
    {
      continue;
    }
    if (!coarse->GetArray(array->GetName()))
    {
      this->UpdateArrays();
      return;
    }
    if (array->GetMTime() > this->ArraysTime.GetMTime())
    {
      changed.insert(array->GetName());
    }
  }
  if (changed.empty())
  {
    if (!this->FilterChangedSamples())
    {
      this->UpdateArrays();
    }
    return;
  }
  std::vector<std::pair<std::string, vtkTypeUInt64>> hashes;
  this->TakeCachedLevels(changed, hashes);
  if (!changed.empty())
  {
    this->FilterAllLevels(&changed);
  }
  this->CacheLevels(hashes);
  this->ArraysTime.Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::TakeCachedLevels(std::set<std::string>& names,
  std::vector<std::pair<std::string, vtkTypeUInt64>>& hashes)
{
  if (this->FilterCacheSize <= 0)
  {
    this->FilterCache.clear();
    return;
  }
  vtkPointData* pd = this->InputOFB->GetSampleData();
  for (auto it = names.begin(); it != names.end();)
  {
    const vtkTypeUInt64 hash = HashValues(pd->GetArray(it->c_str()));
    hashes.emplace_back(*it, hash);
    auto hit = std::find_if(this->FilterCache.begin(),
      this->FilterCache.end(),
      [&](const CachedFiltering& c)
      {
        return c.Hash == hash && c.Name == *it && c.Structure == this->StructureTime.GetMTime() &&
          c.Levels.size() == this->Levels.size();
      });
    if (hit == this->FilterCache.end())
    {
      ++it;
      continue;
    }
    // The kept arrays replace the levels' (new objects to a renderer: uploaded whole).
    for (size_t k = 0; k < this->Levels.size(); ++k)
    {
      this->Levels[k]->GetSampleData()->AddArray(hit->Levels[k]);
      this->Levels[k]->Modified();
    }
    std::rotate(hit, hit + 1, this->FilterCache.end()); // most recently used last
    ++this->NumberOfFilterCacheHits;
    it = names.erase(it);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::CacheLevels(const std::vector<std::pair<std::string, vtkTypeUInt64>>& hashes)
{
  const size_t budget = static_cast<size_t>(this->FilterCacheSize) * 1048576;
  for (const auto& named : hashes)
  {
    const bool kept = std::any_of(this->FilterCache.begin(),
      this->FilterCache.end(),
      [&](const CachedFiltering& c) { return c.Hash == named.second && c.Name == named.first; });
    if (kept || budget == 0)
    {
      continue;
    }
    CachedFiltering entry{ named.second, named.first, this->StructureTime.GetMTime(), {}, 0 };
    for (const auto& level : this->Levels)
    {
      vtkDataArray* array = level->GetSampleData()->GetArray(named.first.c_str());
      if (!array)
      {
        entry.Levels.clear();
        break;
      }
      entry.Levels.emplace_back(array);
      entry.Bytes += static_cast<size_t>(array->GetDataSize()) * array->GetDataTypeSize();
    }
    if (!entry.Levels.empty() && entry.Bytes <= budget)
    {
      this->FilterCache.push_back(std::move(entry));
    }
  }
  // The least recently used go first.
  size_t total = 0;
  for (const CachedFiltering& c : this->FilterCache)
  {
    total += c.Bytes;
  }
  while (total > budget && !this->FilterCache.empty())
  {
    total -= this->FilterCache.front().Bytes;
    this->FilterCache.erase(this->FilterCache.begin());
  }
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::FilterAllLevels(const std::set<std::string>* names)
{
  std::vector<const float*> references;
  std::vector<unsigned char*> fellBacks;
  for (LevelState& state : this->States)
  {
    references.push_back(state.ReferenceNormals.empty() ? nullptr : state.ReferenceNormals.data());
    fellBacks.push_back(state.FellBack.data());
  }
  references.resize(this->Levels.size(), nullptr);
  fellBacks.resize(this->Levels.size(), nullptr);
  FilterLevels(this->InputOFB, this->Levels, this->FilterRadius, names, references, fellBacks);
  this->ComputeLevelArrays(names);
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::FilterLevel(int k, vtkOFB* source, const std::set<std::string>* names)
{
  vtkOFB* level = k >= 1 ? this->GetLevel(k) : nullptr;
  if (!level || !source || static_cast<size_t>(k) > this->States.size())
  {
    return false;
  }
  LevelState& state = this->States[k - 1];
  return ResampleArrays(source,
    level,
    this->FilterRadius * level->GetCellSize(),
    names,
    state.ReferenceNormals.empty() ? nullptr : state.ReferenceNormals.data(),
    state.FellBack.data());
}

//------------------------------------------------------------------------------
double vtkOFBPyramid::GetFilterReach(int k) const
{
  vtkOFB* level = k >= 1 ? this->GetLevel(k) : nullptr;
  vtkOFB* finer = level ? this->GetLevel(k - 1) : nullptr;
  return finer ? 2.0 * FilterRadiusOf(finer, this->FilterRadius * level->GetCellSize()) : 0.0;
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::GetSharedMean(const std::string&, double&)
{
  return false;
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::ComputeLevelArrays(const std::set<std::string>*) {}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::IsComputedArray(const std::string&) const
{
  return false;
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::FilterChangedSamples()
{
  // The levels' arrays are written in place: kept ones could no longer match their hash.
  this->FilterCache.clear();
  // Level 0's samples marked modified since the last computation (painting marks what
  // it changed); none, or more than a quarter of them, and everything is filtered.
  vtkNew<vtkIdTypeArray> ranges;
  this->InputOFB->GetSampleRangesModifiedSince(this->ArraysTime.GetMTime(), ranges);
  std::vector<vtkIdType> changed;
  const vtkIdType limit = this->InputOFB->GetNumberOfSamples() / 4;
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    const vtkIdType first = ranges->GetTypedComponent(r, 0);
    const vtkIdType last = ranges->GetTypedComponent(r, 1);
    if (static_cast<vtkIdType>(changed.size()) + (last - first) > limit)
    {
      return false;
    }
    for (vtkIdType i = first; i < last; ++i)
    {
      changed.push_back(i);
    }
  }
  if (changed.empty() || this->States.size() != this->Levels.size())
  {
    return false;
  }
  // The arrays filtered, not computed per level (ComputeLevelArrays).
  std::set<std::string> filtered;
  vtkPointData* pd = this->InputOFB->GetSampleData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetName() && !this->IsComputedArray(array->GetName()))
    {
      filtered.insert(array->GetName());
    }
  }
  // Level by level, the targets that may read a changed sample are filtered again, and
  // they are the changed samples of the next level.
  for (size_t k = 0; k < this->Levels.size() && !changed.empty(); ++k)
  {
    vtkOFB* finer = k == 0 ? this->InputOFB : this->Levels[k - 1].Get();
    vtkOFB* level = this->Levels[k];
    const double radius = FilterRadiusOf(finer, this->FilterRadius * level->GetCellSize());
    LevelState& state = this->States[k];
    std::vector<vtkIdType> targets =
      AffectedTargets(finer, changed, level, radius, state.FellBack.data());
    const float* reference =
      state.ReferenceNormals.empty() ? nullptr : state.ReferenceNormals.data();
    if (!ResampleSome(finer, level, radius, targets, reference, state.FellBack.data(), &filtered))
    {
      return false;
    }
    MarkRuns(level, targets);
    changed.swap(targets);
  }
  this->ArraysTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::Resample(vtkOFB* source, vtkOFB* target, double radius)
{
  return ResampleArrays(source, target, radius, nullptr);
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputOFB: " << this->InputOFB << "\n";
  os << indent << "Surface: " << this->Surface << "\n";
  os << indent << "LevelSurface: " << this->LevelSurface << "\n";
  os << indent << "MaximumNumberOfLevels: " << this->MaximumNumberOfLevels << "\n";
  os << indent << "MinimumResolution: " << this->MinimumResolution << "\n";
  os << indent << "FilterRadius: " << this->FilterRadius << " cells\n";
  os << indent << "FilterCacheSize: " << this->FilterCacheSize << " MiB ("
     << this->FilterCache.size() << " arrays kept, " << this->NumberOfFilterCacheHits << " hits)\n";
  os << indent << "NumberOfLevels: " << this->GetNumberOfLevels() << "\n";
}
