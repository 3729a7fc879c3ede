#include "vtkOFBPyramid.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
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
   * `names` unless it is null), each with a new target array of zeros.
   */
  void CollectArrays(const std::set<std::string>* names)
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
      out->SetNumberOfTuples(nt);
      out->Fill(0.0);
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
   * A copy of the target's normals, to which source samples must not face away
   * (the transfer replaces the target's normals by the source's); none when
   * either OFB has no normals.
   */
  void CopyTargetNormals()
  {
    this->SourceNormals = SampleNormals(this->Source->GetSampleData());
    auto* floats = vtkFloatArray::FastDownCast(this->SourceNormals);
    this->SourceNormalValues = floats ? floats->GetPointer(0) : nullptr;
    vtkDataArray* targetNormals = SampleNormals(this->Target->GetSampleData());
    if (!targetNormals || !this->SourceNormals ||
      targetNormals->GetNumberOfTuples() != this->Target->GetNumberOfSamples())
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
    const float* tn = this->TargetNormals.empty() ? nullptr : &this->TargetNormals[3 * i];
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
  std::vector<float> TargetNormals;
};

/// Scale the 3-component "Normals" sample array of `ofb` to unit length.
void NormalizeSampleNormals(vtkOFB* ofb)
{
  vtkDataArray* normals = ofb->GetSampleData()->GetArray("Normals");
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    return;
  }
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double n[3];
    normals->GetTuple(i, n);
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0.0)
    {
      n[0] /= len;
      n[1] /= len;
      n[2] /= len;
      normals->SetTuple(i, n);
    }
  }
}

/// vtkOFBPyramid::Resample of the arrays in `names` (all where it is null).
bool ResampleArrays(vtkOFB* source,
  vtkOFB* target,
  double radius,
  const std::set<std::string>* names)
{
  if (!source || !target || !(radius > 0.0) || source->GetNumberOfSamples() == 0)
  {
    return false;
  }
  // Search at least the sqrt(3) cells of the source within which a surface point always
  // has a sample, so that every target sample finds one.
  radius = std::max(radius, std::sqrt(3.0) * source->GetCellSize());
  ResampleFunctor transfer(source, target, radius);
  transfer.CopyTargetNormals();
  transfer.CollectArrays(names);
  vtkSMPTools::For(0, target->GetNumberOfSamples(), transfer);
  transfer.ReplaceTargetArrays();
  if (!names || names->count("Normals"))
  {
    NormalizeSampleNormals(target);
  }
  return true;
}

/// Levels 1.. (`levels`) filtered from level 0 (`input`) one after the other: the arrays
/// in `names`, all where it is null. `radius` in cells of each coarser level.
void FilterLevels(vtkOFB* input,
  const std::vector<vtkSmartPointer<vtkOFB>>& levels,
  double radius,
  const std::set<std::string>* names)
{
  for (size_t k = 0; k < levels.size(); ++k)
  {
    vtkOFB* finer = k == 0 ? input : levels[k - 1].Get();
    ResampleArrays(finer, levels[k], radius * levels[k]->GetCellSize(), names);
  }
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
        return false;
      }
      vtkSmartPointer<vtkOFB> level = vtkSmartPointer<vtkOFB>::New();
      level->DeepCopy(out);
      this->Levels.push_back(level);
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
  FilterLevels(this->InputOFB, this->Levels, this->FilterRadius, nullptr);
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
    this->UpdateArrays();
    return;
  }
  FilterLevels(this->InputOFB, this->Levels, this->FilterRadius, &changed);
  this->ArraysTime.Modified();
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
