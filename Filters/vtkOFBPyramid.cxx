#include "vtkOFBPyramid.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOFB.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <vector>

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
  , LastInputOFB(nullptr)
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
bool vtkOFBPyramid::Update()
{
  if (!this->InputOFB || this->InputOFB->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("Update: no input OFB, or an empty one.");
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
      vtkErrorMacro("Update: no surface to sample the coarser levels from.");
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
        vtkErrorMacro("Update: level " << k << " could not be sampled.");
        this->Levels.clear();
        return false;
      }
      vtkSmartPointer<vtkOFB> level = vtkSmartPointer<vtkOFB>::New();
      level->DeepCopy(out);
      this->Levels.push_back(level);
    }
    this->StructureTime.Modified();
  }
  if (rebuild || this->InputOFB->GetMTime() > this->ArraysTime.GetMTime())
  {
    this->UpdateArrays();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPyramid::UpdateArrays()
{
  for (size_t k = 0; k < this->Levels.size(); ++k)
  {
    vtkOFB* finer = k == 0 ? this->InputOFB : this->Levels[k - 1].Get();
    vtkOFB* coarser = this->Levels[k];
    vtkOFBPyramid::Resample(finer, coarser, this->FilterRadius * coarser->GetCellSize());
  }
  this->ArraysTime.Modified();
}

//------------------------------------------------------------------------------
bool vtkOFBPyramid::Resample(vtkOFB* source, vtkOFB* target, double radius)
{
  if (!source || !target || !(radius > 0.0) || source->GetNumberOfSamples() == 0)
  {
    return false;
  }
  // Search at least the sqrt(3) cells of the source within which a surface point always
  // has a sample, so that every target sample finds one.
  radius = std::max(radius, std::sqrt(3.0) * source->GetCellSize());
  vtkPointData* spd = source->GetSampleData();
  vtkPointData* tpd = target->GetSampleData();
  const vtkIdType nt = target->GetNumberOfSamples();
  vtkDataArray* sNormals = spd->GetNormals() ? spd->GetNormals() : spd->GetArray("Normals");
  vtkDataArray* tNormals = tpd->GetNormals() ? tpd->GetNormals() : tpd->GetArray("Normals");
  if (sNormals && sNormals->GetNumberOfComponents() != 3)
  {
    sNormals = nullptr;
  }
  if (tNormals && (tNormals->GetNumberOfComponents() != 3 || tNormals->GetNumberOfTuples() != nt))
  {
    tNormals = nullptr;
  }
  // Keep a copy of the target normals: the source's normals replace them below.
  std::vector<float> targetNormals;
  if (tNormals && sNormals)
  {
    targetNormals.resize(static_cast<size_t>(3 * nt));
    for (vtkIdType i = 0; i < nt; ++i)
    {
      double n[3];
      tNormals->GetTuple(i, n);
      for (int c = 0; c < 3; ++c)
      {
        targetNormals[3 * i + c] = static_cast<float>(n[c]);
      }
    }
  }
  // The arrays to transfer, and their new target arrays.
  std::vector<vtkDataArray*> from;
  std::vector<vtkSmartPointer<vtkDataArray>> to;
  int totalComponents = 0;
  for (int a = 0; a < spd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = spd->GetArray(a);
    if (!array || !array->GetName() || array->GetNumberOfTuples() != source->GetNumberOfSamples())
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> out;
    out.TakeReference(array->NewInstance());
    out->SetName(array->GetName());
    out->SetNumberOfComponents(array->GetNumberOfComponents());
    out->SetNumberOfTuples(nt);
    out->Fill(0.0);
    from.push_back(array);
    to.push_back(out);
    totalComponents += array->GetNumberOfComponents();
  }
  const double r = radius;
  vtkSMPTools::For(0, nt, [&](vtkIdType begin, vtkIdType end) {
    std::vector<double> sum(static_cast<size_t>(totalComponents));
    for (vtkIdType i = begin; i < end; ++i)
    {
      double x[3];
      target->GetSamplePosition(i, x);
      const float* tn = targetNormals.empty() ? nullptr : &targetNormals[3 * i];
      std::fill(sum.begin(), sum.end(), 0.0);
      double wsum = 0.0;
      vtkIdType closest = -1;
      double closestD2 = 4.0 * r * r;
      auto accumulate = [&](vtkIdType j, double w) {
        int offset = 0;
        for (size_t k = 0; k < from.size(); ++k)
        {
          const int nc = from[k]->GetNumberOfComponents();
          for (int c = 0; c < nc; ++c)
          {
            sum[offset + c] += w * from[k]->GetComponent(j, c);
          }
          offset += nc;
        }
        wsum += w;
      };
      auto facing = [&](vtkIdType j) {
        if (!tn)
        {
          return true;
        }
        double sn[3];
        sNormals->GetTuple(j, sn);
        return sn[0] * tn[0] + sn[1] * tn[1] + sn[2] * tn[2] >= 0.0;
      };
      source->ForEachSampleInSphere(x, 2.0 * r, [&](vtkIdType j, double d2) {
        if (!facing(j))
        {
          return;
        }
        if (d2 < closestD2)
        {
          closestD2 = d2;
          closest = j;
        }
        if (d2 < r * r)
        {
          const double q = 1.0 - d2 / (r * r);
          accumulate(j, q * q);
        }
      });
      if (wsum <= 0.0 && closest >= 0)
      {
        accumulate(closest, 1.0);
      }
      if (wsum <= 0.0)
      {
        continue;
      }
      int offset = 0;
      for (size_t k = 0; k < from.size(); ++k)
      {
        const int nc = from[k]->GetNumberOfComponents();
        const bool integral =
          from[k]->GetDataType() != VTK_FLOAT && from[k]->GetDataType() != VTK_DOUBLE;
        for (int c = 0; c < nc; ++c)
        {
          double v = sum[offset + c] / wsum;
          if (integral)
          {
            v = std::floor(v + 0.5);
          }
          to[k]->SetComponent(i, c, v);
        }
        offset += nc;
      }
    }
  });
  // Replace the target arrays, keeping the attribute roles of the source.
  for (size_t k = 0; k < to.size(); ++k)
  {
    tpd->RemoveArray(to[k]->GetName());
    tpd->AddArray(to[k]);
  }
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
  {
    vtkAbstractArray* active = spd->GetAbstractAttribute(attribute);
    if (active && active->GetName() && tpd->GetArray(active->GetName()))
    {
      tpd->SetActiveAttribute(active->GetName(), attribute);
    }
  }
  // Renormalise transferred normals.
  vtkDataArray* normals = tpd->GetArray("Normals");
  if (normals && normals->GetNumberOfComponents() == 3)
  {
    for (vtkIdType i = 0; i < nt; ++i)
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
  return true;
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
