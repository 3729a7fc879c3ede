#include "vtkOFBPyramid.h"

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
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace
{
/// The 3-component sample normals of `pd` (the active ones, else "Normals"), or null.
vtkDataArray* SampleNormals(vtkPointData* pd)
{
  vtkDataArray* normals = pd->GetNormals() ? pd->GetNormals() : pd->GetArray("Normals");
  return normals && normals->GetNumberOfComponents() == 3 ? normals : nullptr;
}

/**
 * The distance-weighted transfer of vtkOFBPyramid::Resample: the arrays to
 * transfer and their new target arrays, and the filter of one target sample
 * (a functor for vtkSMPTools::For over the target samples).
 */
class ResampleFunctor
{
public:
  ResampleFunctor(vtkOFB* source, vtkOFB* target, double radius)
    : Source(source)
    , Target(target)
    , Radius(radius)
  {
  }

  /**
   * The arrays of the source to transfer (named, one tuple per sample; only those in
   * `names` unless it is null), each with a new target array of zeros (`fill`: else
   * left uninitialized, WriteInPlace replaces it).
   */
  void CollectArrays(const std::set<std::string>* names, bool fill = true)
  {
    vtkPointData* spd = this->Source->GetSampleData();
    const vtkIdType nt = this->Target->GetNumberOfSamples();
    for (int a = 0; a < spd->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = spd->GetArray(a);
      if (!array || !array->GetName() ||
        array->GetNumberOfTuples() != this->Source->GetNumberOfSamples() ||
        (names && !names->count(array->GetName())))
      {
        continue;
      }
      vtkSmartPointer<vtkDataArray> out;
      out.TakeReference(array->NewInstance());
      out->SetName(array->GetName());
      out->SetNumberOfComponents(array->GetNumberOfComponents());
      out->SetNumberOfTuples(fill ? nt : 0);
      if (fill)
      {
        out->Fill(0.0);
      }
      this->From.push_back(array);
      auto* floats = vtkFloatArray::FastDownCast(array);
      auto* bytes = vtkUnsignedCharArray::FastDownCast(array);
      this->FromFloats.push_back(floats ? floats->GetPointer(0) : nullptr);
      this->FromBytes.push_back(bytes ? bytes->GetPointer(0) : nullptr);
      this->To.push_back(out);
      this->TotalComponents += array->GetNumberOfComponents();
    }
  }

  /**
   * The normals of the target, to which source samples must not face away: `reference`
   * (3 floats a target sample) where given, else a copy of the target's normals (the
   * transfer replaces them by the source's); none when either OFB has no normals.
   */
  void SetTargetNormals(const float* reference)
  {
    this->SourceNormals = SampleNormals(this->Source->GetSampleData());
    auto* floats = vtkFloatArray::FastDownCast(this->SourceNormals);
    this->SourceNormalValues = floats ? floats->GetPointer(0) : nullptr;
    this->TargetNormalValues = nullptr;
    if (!this->SourceNormals)
    {
      return;
    }
    if (reference)
    {
      this->TargetNormalValues = reference;
      return;
    }
    vtkDataArray* targetNormals = SampleNormals(this->Target->GetSampleData());
    if (!targetNormals || targetNormals->GetNumberOfTuples() != this->Target->GetNumberOfSamples())
    {
      return;
    }
    const vtkIdType nt = this->Target->GetNumberOfSamples();
    this->TargetNormals.resize(static_cast<size_t>(3 * nt));
    for (vtkIdType i = 0; i < nt; ++i)
    {
      double n[3];
      targetNormals->GetTuple(i, n);
      for (int c = 0; c < 3; ++c)
      {
        this->TargetNormals[3 * i + c] = static_cast<float>(n[c]);
      }
    }
    this->TargetNormalValues = this->TargetNormals.data();
  }

  /**
   * Write into the target's own arrays of the same names instead of new ones (a
   * transfer to some target samples only, FilterSome); false, with nothing set, where
   * the target lacks one of them or its size or components differ.
   */
  bool WriteInPlace()
  {
    std::vector<vtkSmartPointer<vtkDataArray>> own;
    vtkPointData* tpd = this->Target->GetSampleData();
    for (const auto& to : this->To)
    {
      vtkDataArray* array = tpd->GetArray(to->GetName());
      if (!array || array->GetDataType() != to->GetDataType() ||
        array->GetNumberOfComponents() != to->GetNumberOfComponents() ||
        array->GetNumberOfTuples() != this->Target->GetNumberOfSamples())
      {
        return false;
      }
      own.emplace_back(array);
    }
    this->To = own;
    return true;
  }

  /// Filter the target samples ids[begin, end).
  void FilterSome(const vtkIdType* ids, vtkIdType begin, vtkIdType end) const
  {
    std::vector<double> sum(static_cast<size_t>(this->TotalComponents));
    for (vtkIdType k = begin; k < end; ++k)
    {
      std::fill(sum.begin(), sum.end(), 0.0);
      const double weights = this->Gather(ids[k], sum);
      if (weights > 0.0)
      {
        this->Write(ids[k], sum, weights);
      }
    }
  }

  /// Filter target samples [begin, end).
  void operator()(vtkIdType begin, vtkIdType end) const
  {
    std::vector<double> sum(static_cast<size_t>(this->TotalComponents));
    for (vtkIdType i = begin; i < end; ++i)
    {
      std::fill(sum.begin(), sum.end(), 0.0);
      const double weights = this->Gather(i, sum);
      if (weights > 0.0)
      {
        this->Write(i, sum, weights);
      }
    }
  }

  /// Replace the target's arrays by the transferred ones, with the source's attribute roles.
  void ReplaceTargetArrays() const
  {
    vtkPointData* spd = this->Source->GetSampleData();
    vtkPointData* tpd = this->Target->GetSampleData();
    for (const auto& to : this->To)
    {
      tpd->RemoveArray(to->GetName());
      tpd->AddArray(to);
    }
    for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
    {
      vtkAbstractArray* active = spd->GetAbstractAttribute(attribute);
      if (active && active->GetName() && tpd->GetArray(active->GetName()))
      {
        tpd->SetActiveAttribute(active->GetName(), attribute);
      }
    }
  }

private:
  /**
   * The weighted sums of the source samples within Radius of target sample i
   * that face its way into `sum`, and their total weight; the closest such
   * sample within 2 Radius, with weight 1, when none is within Radius.
   */
  double Gather(vtkIdType i, std::vector<double>& sum) const
  {
    const double r = this->Radius;
    double x[3];
    this->Target->GetSamplePosition(i, x);
    const float* tn = this->TargetNormalValues ? this->TargetNormalValues + 3 * i : nullptr;
    double weights = 0.0;
    this->Source->ForEachSampleInSphere(x,
      r,
      [&](vtkIdType j, double d2)
      {
        if (d2 < r * r && this->Faces(j, tn))
        {
          const double q = 1.0 - d2 / (r * r);
          this->Accumulate(j, q * q, sum);
          weights += q * q;
        }
      });
    if (weights > 0.0)
    {
      return weights;
    }
    // None within r (rare): the closest within 2 r, searched only then (a sphere of
    // 2 r holds four times the candidates).
    vtkIdType closest = -1;
    double closestD2 = 4.0 * r * r;
    this->Source->ForEachSampleInSphere(x,
      2.0 * r,
      [&](vtkIdType j, double d2)
      {
        if (d2 < closestD2 && this->Faces(j, tn))
        {
          closestD2 = d2;
          closest = j;
        }
      });
    if (closest >= 0)
    {
      this->Accumulate(closest, 1.0, sum);
      weights = 1.0;
    }
    return weights;
  }

  /// Whether source sample j does not face away from the target normal tn (if any).
  bool Faces(vtkIdType j, const float* tn) const
  {
    if (!tn)
    {
      return true;
    }
    double sn[3];
    if (this->SourceNormalValues)
    {
      const float* n = this->SourceNormalValues + 3 * j;
      sn[0] = n[0];
      sn[1] = n[1];
      sn[2] = n[2];
    }
    else
    {
      this->SourceNormals->GetTuple(j, sn);
    }
    return sn[0] * tn[0] + sn[1] * tn[1] + sn[2] * tn[2] >= 0.0;
  }

  /// out[c] += w * v[c] for the nc components of one tuple.
  template<typename T>
  static void AddTuple(const T* v, int nc, double w, double* out)
  {
    for (int c = 0; c < nc; ++c)
    {
      out[c] += w * v[c];
    }
  }

  /// Add weight w times every component of source sample j to `sum`.
  void Accumulate(vtkIdType j, double w, std::vector<double>& sum) const
  {
    int offset = 0;
    for (size_t k = 0; k < this->From.size(); ++k)
    {
      const int nc = this->From[k]->GetNumberOfComponents();
      double* out = sum.data() + offset;
      // Float and byte arrays (the LIC, normals, colours) read directly, the others
      // through the virtual accessor.
      if (this->FromFloats[k])
      {
        AddTuple(this->FromFloats[k] + nc * j, nc, w, out);
      }
      else if (this->FromBytes[k])
      {
        AddTuple(this->FromBytes[k] + nc * j, nc, w, out);
      }
      else
      {
        for (int c = 0; c < nc; ++c)
        {
          out[c] += w * this->From[k]->GetComponent(j, c);
        }
      }
      offset += nc;
    }
  }

  /// Target sample i's values: the sums over their weight, integers rounded.
  void Write(vtkIdType i, const std::vector<double>& sum, double weights) const
  {
    int offset = 0;
    for (size_t k = 0; k < this->From.size(); ++k)
    {
      const int nc = this->From[k]->GetNumberOfComponents();
      const bool integral =
        this->From[k]->GetDataType() != VTK_FLOAT && this->From[k]->GetDataType() != VTK_DOUBLE;
      for (int c = 0; c < nc; ++c)
      {
        double v = sum[offset + c] / weights;
        if (integral)
        {
          v = std::floor(v + 0.5);
        }
        this->To[k]->SetComponent(i, c, v);
      }
      offset += nc;
    }
  }

  vtkOFB* Source;
  vtkOFB* Target;
  const double Radius;
  std::vector<vtkDataArray*> From;
  std::vector<const float*> FromFloats;        // From[k]'s values if float, else null
  std::vector<const unsigned char*> FromBytes; // From[k]'s values if unsigned char
  std::vector<vtkSmartPointer<vtkDataArray>> To;
  int TotalComponents = 0;
  vtkDataArray* SourceNormals = nullptr;
  const float* SourceNormalValues = nullptr; // SourceNormals' values if float
  std::vector<float> TargetNormals;          // a copy, where no reference is given
  const float* TargetNormalValues = nullptr; // the facing test's target normals, or null
};

/// Scale the 3-component "Normals" sample array of `ofb` to unit length: samples
/// ids[0 .. count) where ids is given, else all.
void NormalizeSampleNormals(vtkOFB* ofb, const vtkIdType* ids = nullptr, vtkIdType count = 0)
{
  vtkDataArray* normals = ofb->GetSampleData()->GetArray("Normals");
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
 * the target's own.
 */
bool ResampleArrays(vtkOFB* source,
  vtkOFB* target,
  double radius,
  const std::set<std::string>* names,
  const float* reference = nullptr)
{
  if (!source || !target || !(radius > 0.0) || source->GetNumberOfSamples() == 0)
  {
    return false;
  }
  ResampleFunctor transfer(source, target, FilterRadiusOf(source, radius));
  transfer.SetTargetNormals(reference);
  transfer.CollectArrays(names);
  vtkSMPTools::For(0, target->GetNumberOfSamples(), transfer);
  transfer.ReplaceTargetArrays();
  if (!names || names->count("Normals"))
  {
    NormalizeSampleNormals(target);
  }
  return true;
}

/**
 * The target samples (sorted) whose Resample from `source` may read one of the source
 * samples `changed`: those within 2 `radius` of one (the fallback's reach). The changed
 * samples are gathered into cubes of side `radius` first, and each cube asks for the
 * targets within 2 radius of any point of it (a superset: filtering a target whose
 * sources did not change gives its values again).
 */
std::vector<vtkIdType> AffectedTargets(vtkOFB* source,
  const std::vector<vtkIdType>& changed,
  vtkOFB* target,
  double radius)
{
  const double* origin = source->GetOrigin();
  std::vector<vtkTypeUInt64> cubes;
  cubes.reserve(changed.size());
  for (vtkIdType j : changed)
  {
    double x[3];
    source->GetSamplePosition(j, x);
    vtkTypeUInt64 key = 0;
    for (int c = 0; c < 3; ++c)
    {
      const double q = std::max(0.0, std::floor((x[c] - origin[c]) / radius));
      key = (key << 21) | (static_cast<vtkTypeUInt64>(std::min(q, 2097151.0)));
    }
    cubes.push_back(key);
  }
  std::sort(cubes.begin(), cubes.end());
  cubes.erase(std::unique(cubes.begin(), cubes.end()), cubes.end());
  std::vector<unsigned char> hit(static_cast<size_t>(target->GetNumberOfSamples()), 0);
  const double reach = 2.0 * radius + 0.5 * std::sqrt(3.0) * radius;
  for (vtkTypeUInt64 key : cubes)
  {
    double centre[3];
    for (int c = 2; c >= 0; --c)
    {
      centre[c] = origin[c] + (static_cast<double>(key & 2097151u) + 0.5) * radius;
      key >>= 21;
    }
    target->ForEachSampleInSphere(centre, reach, [&](vtkIdType t, double) { hit[t] = 1; });
  }
  std::vector<vtkIdType> ids;
  for (size_t t = 0; t < hit.size(); ++t)
  {
    if (hit[t])
    {
      ids.push_back(static_cast<vtkIdType>(t));
    }
  }
  return ids;
}

/**
 * Resample of every array of `source` to the target samples `ids` alone, in place (the
 * other target samples keep their values), their normals scaled to unit length; the
 * facing test's target normals are `reference` where given. False (nothing changed)
 * where the target lacks an array of the source or one differs in type or size.
 */
bool ResampleSome(vtkOFB* source,
  vtkOFB* target,
  double radius,
  const std::vector<vtkIdType>& ids,
  const float* reference)
{
  ResampleFunctor transfer(source, target, radius);
  transfer.SetTargetNormals(reference);
  transfer.CollectArrays(nullptr, false);
  if (!transfer.WriteInPlace())
  {
    return false;
  }
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(ids.size()),
    [&](vtkIdType begin, vtkIdType end) { transfer.FilterSome(ids.data(), begin, end); });
  NormalizeSampleNormals(target, ids.data(), static_cast<vtkIdType>(ids.size()));
  return true;
}

/// Levels 1.. (`levels`) filtered from level 0 (`input`) one after the other: the arrays
/// in `names`, all where it is null. `radius` in cells of each coarser level; the facing
/// test's normals of level k + 1 are references[k] where it is not empty.
void FilterLevels(vtkOFB* input,
  const std::vector<vtkSmartPointer<vtkOFB>>& levels,
  double radius,
  const std::set<std::string>* names,
  const std::vector<std::vector<float>>& references)
{
  for (size_t k = 0; k < levels.size(); ++k)
  {
    vtkOFB* finer = k == 0 ? input : levels[k - 1].Get();
    const float* reference =
      k < references.size() && !references[k].empty() ? references[k].data() : nullptr;
    ResampleArrays(finer, levels[k], radius * levels[k]->GetCellSize(), names, reference);
  }
}

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
    size_t out = 0;
    for (size_t r = 1; r < runs.size(); ++r)
    {
      if (runs[r].first - runs[out].second <= gap)
      {
        runs[out].second = runs[r].second;
      }
      else
      {
        runs[++out] = runs[r];
      }
    }
    runs.resize(out + 1);
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

//------------------------------------------------------------------------------
vtkOFBPyramid::vtkOFBPyramid()
  : InputOFB(nullptr)
  , Surface(nullptr)
  , MaximumNumberOfLevels(8)
  , MinimumResolution(8)
  , FilterRadius(1.5)
{
}

//------------------------------------------------------------------------------
vtkOFBPyramid::~vtkOFBPyramid()
{
  this->SetInputOFB(nullptr);
  this->SetSurface(nullptr);
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
    (this->Surface && this->Surface->GetMTime() > this->StructureTime.GetMTime());
  if (rebuild)
  {
    this->Levels.clear();
    this->ReferenceNormals.clear();
    this->LastInputOFB = this->InputOFB;
    this->StructureTime.Modified();
    if (this->MaximumNumberOfLevels > 1 && !this->Surface)
    {
      vtkErrorMacro("UpdateLevels: no surface to sample the coarser levels from.");
      return false;
    }
    const vtkIdType* dims = this->InputOFB->GetDimensions();
    // The sampler pads the frame by one cell on each side: halve the unpadded cells so
    // that the cell size doubles from level to level.
    const int finest = static_cast<int>(std::max({ dims[0], dims[1], dims[2] })) - 2;
    vtkNew<vtkOFBSampler> sampler;
    sampler->SetInputData(this->Surface);
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
        this->ReferenceNormals.clear();
        return false;
      }
      vtkSmartPointer<vtkOFB> level = vtkSmartPointer<vtkOFB>::New();
      level->DeepCopy(out);
      this->Levels.push_back(level);
      // The sampler's normals: the facing test's reference at every filtering (the
      // level's "Normals" become the filtered ones), so that a filtering does not depend
      // on the ones before.
      this->ReferenceNormals.emplace_back();
      auto* normals = vtkFloatArray::FastDownCast(SampleNormals(level->GetSampleData()));
      if (normals)
      {
        this->ReferenceNormals.back().assign(
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
  FilterLevels(this->InputOFB, this->Levels, this->FilterRadius, nullptr, this->ReferenceNormals);
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
  FilterLevels(this->InputOFB, this->Levels, this->FilterRadius, &changed, this->ReferenceNormals);
  this->ArraysTime.Modified();
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::FilterChangedSamples()
{
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
  if (changed.empty() || this->ReferenceNormals.size() != this->Levels.size())
  {
    return false;
  }
  // Level by level, the targets that may read a changed sample are filtered again, and
  // they are the changed samples of the next level.
  for (size_t k = 0; k < this->Levels.size() && !changed.empty(); ++k)
  {
    vtkOFB* finer = k == 0 ? this->InputOFB : this->Levels[k - 1].Get();
    vtkOFB* level = this->Levels[k];
    const double radius = FilterRadiusOf(finer, this->FilterRadius * level->GetCellSize());
    std::vector<vtkIdType> targets = AffectedTargets(finer, changed, level, radius);
    const float* reference =
      this->ReferenceNormals[k].empty() ? nullptr : this->ReferenceNormals[k].data();
    if (!ResampleSome(finer, level, radius, targets, reference))
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
  os << indent << "MaximumNumberOfLevels: " << this->MaximumNumberOfLevels << "\n";
  os << indent << "MinimumResolution: " << this->MinimumResolution << "\n";
  os << indent << "FilterRadius: " << this->FilterRadius << " cells\n";
  os << indent << "NumberOfLevels: " << this->GetNumberOfLevels() << "\n";
}
