// Private header of vtkOFBPyramid and vtkOFBProbeFilter: the distance-weighted transfer
// of sample arrays from an OFB to the samples of another (vtkOFBPyramid::Resample and the
// filtering of the pyramid's levels) or to points (the probe).
#ifndef vtkOFBPyramidResampler_h
#define vtkOFBPyramidResampler_h

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

/// The 3-component sample normals of `pd` (the active ones, else "Normals"), or null.
inline vtkDataArray* vtkOFBSampleNormals(vtkPointData* pd)
{
  vtkDataArray* normals =
    pd->GetNormals() ? pd->GetNormals() : pd->GetArray(vtkOFB::NormalsArrayName());
  return normals && normals->GetNumberOfComponents() == 3 ? normals : nullptr;
}

/**
 * The distance-weighted transfer of vtkOFBPyramid::Resample: the arrays to
 * transfer and their target arrays (new ones, or the target's own for a transfer to
 * some target samples), and the filter of target samples (a functor for
 * vtkSMPTools::For over the target samples). The targets are the samples of an OFB
 * or points (`points`, 3 doubles a point).
 */
class vtkOFBPyramidResampler
{
public:
  vtkOFBPyramidResampler(vtkOFB* source, vtkOFB* target, double radius)
    : Source(source)
    , Target(target)
    , NumberOfTargets(target->GetNumberOfSamples())
    , Radius(radius)
  {
  }
  vtkOFBPyramidResampler(vtkOFB* source, const double* points, vtkIdType n, double radius)
    : Source(source)
    , Points(points)
    , NumberOfTargets(n)
    , Radius(radius)
  {
  }

  /// Take the closest source sample within the radius instead of the weighted mean.
  bool Nearest = false;

  /// The new target arrays.
  const std::vector<vtkSmartPointer<vtkDataArray>>& GetTargetArrays() const { return this->To; }

  /**
   * The arrays of the source to transfer (named, one tuple per sample; only those in
   * `names` unless it is null), each with a new target array of zeros (`fill`: else
   * left uninitialized, WriteInPlace replaces it).
   */
  void CollectArrays(const std::set<std::string>* names, bool fill = true)
  {
    vtkPointData* spd = this->Source->GetSampleData();
    const vtkIdType nt = this->NumberOfTargets;
    for (int a = 0; a < spd->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = spd->GetArray(a);
      // The ghost flags of a piece's level are its own sampler's (from the ghost cells of
      // the surface it samples, as level 0's), not filtered: the owned samples of the
      // pieces' levels then are those of one process's levels.
      if (!array || !array->GetName() ||
        array->GetNumberOfTuples() != this->Source->GetNumberOfSamples() ||
        (names && !names->count(array->GetName())) ||
        !strcmp(array->GetName(), vtkDataSetAttributes::GhostArrayName()))
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
    this->SourceNormals = vtkOFBSampleNormals(this->Source->GetSampleData());
    auto* floats = vtkFloatArray::FastDownCast(this->SourceNormals);
    this->SourceNormalValues = floats ? floats->GetPointer(0) : nullptr;
    this->TargetNormalValues = nullptr;
    if (!this->SourceNormals)
    {
      return;
    }
    if (reference || !this->Target)
    {
      this->TargetNormalValues = reference;
      return;
    }
    vtkDataArray* targetNormals = vtkOFBSampleNormals(this->Target->GetSampleData());
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
   * transfer to some target samples only, Filter with ids); false, with nothing set, where
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

  /// Filter the target samples ids[begin, end), or [begin, end) without ids; where
  /// FellBack is set, record in it which ones found no source within the radius.
  void Filter(const vtkIdType* ids, vtkIdType begin, vtkIdType end) const
  {
    std::vector<double> sum(static_cast<size_t>(this->TotalComponents));
    for (vtkIdType k = begin; k < end; ++k)
    {
      const vtkIdType i = ids ? ids[k] : k;
      std::fill(sum.begin(), sum.end(), 0.0);
      bool fellBack;
      const double weights = this->Gather(i, sum, fellBack);
      if (weights > 0.0)
      {
        this->Write(i, sum, weights);
      }
      if (this->FellBack)
      {
        this->FellBack[i] = fellBack ? 1 : 0;
      }
      if (this->Found)
      {
        this->Found[i] = weights > 0.0 ? 1 : 0;
      }
    }
  }

  void operator()(vtkIdType begin, vtkIdType end) const { this->Filter(nullptr, begin, end); }

  /// Where to record which target samples fell back (one byte each), or null.
  unsigned char* FellBack = nullptr;
  /// Where to record which targets found a source sample (one byte each), or null.
  unsigned char* Found = nullptr;

  /// Replace the target's arrays (or `tpd`'s) by the transferred ones, with the source's
  /// attribute roles.
  void ReplaceTargetArrays(vtkPointData* tpd = nullptr) const
  {
    vtkPointData* spd = this->Source->GetSampleData();
    tpd = tpd ? tpd : this->Target->GetSampleData();
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
  double Gather(vtkIdType i, std::vector<double>& sum, bool& fellBack) const
  {
    fellBack = false;
    const double r = this->Radius;
    double x[3];
    if (this->Target)
    {
      this->Target->GetSamplePosition(i, x);
    }
    else
    {
      std::copy(this->Points + 3 * i, this->Points + 3 * i + 3, x);
    }
    const float* tn = this->TargetNormalValues ? this->TargetNormalValues + 3 * i : nullptr;
    double weights = 0.0;
    if (this->Nearest)
    {
      return this->GatherClosest(x, tn, r, sum, fellBack) ? 1.0 : 0.0;
    }
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
    fellBack = true;
    bool dummy;
    return this->GatherClosest(x, tn, 2.0 * r, sum, dummy) ? 1.0 : 0.0;
  }

  /// Add the closest source sample within r of x that faces tn's way (the smallest id
  /// among equally close ones) to `sum` with weight 1; false if there is none.
  /// `farther`: it lies beyond Radius.
  bool GatherClosest(const double x[3],
    const float* tn,
    double r,
    std::vector<double>& sum,
    bool& farther) const
  {
    vtkIdType closest = -1;
    double closestD2 = r * r;
    this->Source->ForEachSampleInSphere(x,
      r,
      [&](vtkIdType j, double d2)
      {
        if ((d2 < closestD2 || (d2 == closestD2 && j < closest)) && this->Faces(j, tn))
        {
          closestD2 = d2;
          closest = j;
        }
      });
    if (closest < 0)
    {
      return false;
    }
    farther = closestD2 > this->Radius * this->Radius;
    this->Accumulate(closest, 1.0, sum);
    return true;
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
  vtkOFB* Target = nullptr;
  const double* Points = nullptr; // the targets when there is no target OFB
  const vtkIdType NumberOfTargets;
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

#endif
