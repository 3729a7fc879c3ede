#include "vtkOFBTextureBaker.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOFB.h"
#include "vtkOFBFanTriangles.h"
#include "vtkOFBInputChecks.h"
#include "vtkOFBPyramidResampler.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <new>
#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBTextureBaker);

namespace
{
/// The covered texels: each one's surface point and the normal of its triangle.
struct Coverage
{
  int Width = 0;
  int Height = 0;
  std::vector<vtkTypeInt32> SlotOf; // per texel, -1 where no triangle covers it
  std::vector<vtkIdType> TexelOf;
  std::vector<double> Points;
  std::vector<float> Normals;

  void Reset(int w, int h)
  {
    this->Width = w;
    this->Height = h;
    this->SlotOf.assign(static_cast<size_t>(w) * h, -1);
  }

  /// Texels whose centres the triangle covers in UV space (uv in texture coordinates), or
  /// the texel under its centroid where it covers none.
  void AddTriangle(const glm::dvec2 uv[3], const glm::dvec3 x[3])
  {
    glm::dvec2 p[3];
    for (int k = 0; k < 3; ++k)
    {
      // Texel centres at integer coordinates.
      p[k] = glm::dvec2(uv[k].x * this->Width - 0.5, uv[k].y * this->Height - 0.5);
      if (!std::isfinite(p[k].x) || !std::isfinite(p[k].y))
      {
        return;
      }
    }
    const glm::dvec2 e1 = p[1] - p[0];
    const glm::dvec2 e2 = p[2] - p[0];
    const double area = e1.x * e2.y - e1.y * e2.x;
    const glm::dvec3 n = glm::cross(x[1] - x[0], x[2] - x[0]);
    const double length = glm::length(n);
    if (!(std::abs(area) > 1e-12) || !(length > 0.0) || !std::isfinite(length))
    {
      return;
    }
    const glm::vec3 normal(n / length);
    const double lowU = std::max(0.0, std::ceil(std::min({ p[0].x, p[1].x, p[2].x })));
    const double highU =
      std::min(this->Width - 1.0, std::floor(std::max({ p[0].x, p[1].x, p[2].x })));
    const double lowV = std::max(0.0, std::ceil(std::min({ p[0].y, p[1].y, p[2].y })));
    const double highV =
      std::min(this->Height - 1.0, std::floor(std::max({ p[0].y, p[1].y, p[2].y })));
    const double eps = -1e-9;
    bool any = false;
    for (double j = lowV; j <= highV; ++j)
    {
      for (double i = lowU; i <= highU; ++i)
      {
        const glm::dvec2 q = glm::dvec2(i, j) - p[0];
        const double w1 = (q.x * e2.y - q.y * e2.x) / area;
        const double w2 = (e1.x * q.y - e1.y * q.x) / area;
        const double w0 = 1.0 - w1 - w2;
        if (w0 < eps || w1 < eps || w2 < eps)
        {
          continue;
        }
        this->Set(static_cast<vtkIdType>(j) * this->Width + static_cast<vtkIdType>(i),
          w0 * x[0] + w1 * x[1] + w2 * x[2],
          normal);
        any = true;
      }
    }
    // A triangle too small to cover a texel centre (a sliver, a tiny chart) still gets the
    // texel under its centroid where no other triangle has it, so padding has a value to
    // spread and bilinear filtering inside it does not read the background.
    const glm::dvec2 c = glm::floor((p[0] + p[1] + p[2]) / 3.0 + 0.5);
    if (!any && c.x >= 0.0 && c.y >= 0.0 && c.x < this->Width && c.y < this->Height)
    {
      const vtkIdType texel =
        static_cast<vtkIdType>(c.y) * this->Width + static_cast<vtkIdType>(c.x);
      if (this->SlotOf[texel] < 0)
      {
        this->Set(texel, (x[0] + x[1] + x[2]) / 3.0, normal);
      }
    }
  }

  /// The texel's surface point and normal (the texel added where it was not covered).
  void Set(vtkIdType texel, const glm::dvec3& y, const glm::vec3& normal)
  {
    vtkTypeInt32& slot = this->SlotOf[texel];
    if (slot < 0)
    {
      slot = static_cast<vtkTypeInt32>(this->TexelOf.size()); // texels <= 2^28
      this->TexelOf.push_back(texel);
      this->Points.resize(this->Points.size() + 3);
      this->Normals.resize(this->Normals.size() + 3);
    }
    for (int c = 0; c < 3; ++c)
    {
      this->Points[3 * slot + c] = y[c];
      this->Normals[3 * slot + c] = normal[c];
    }
  }
};

/// Fill `passes` rings of empty texels around the filled ones with the mean of their
/// filled neighbours (8-neighbourhood; integer arrays rounded).
void Pad(vtkDataArray* image, std::vector<unsigned char>& filled, int w, int h, int passes)
{
  const int nc = image->GetNumberOfComponents();
  const bool integral = image->GetDataType() != VTK_FLOAT && image->GetDataType() != VTK_DOUBLE;
  std::vector<double> sum(nc), value(nc);
  for (int pass = 0; pass < passes; ++pass)
  {
    std::vector<vtkIdType> added;
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        const vtkIdType t = static_cast<vtkIdType>(j) * w + i;
        if (filled[t])
        {
          continue;
        }
        std::fill(sum.begin(), sum.end(), 0.0);
        int count = 0;
        for (int dj = -1; dj <= 1; ++dj)
        {
          for (int di = -1; di <= 1; ++di)
          {
            const int ni = i + di, nj = j + dj;
            const vtkIdType nt = static_cast<vtkIdType>(nj) * w + ni;
            if (ni < 0 || nj < 0 || ni >= w || nj >= h || filled[nt] != 1)
            {
              continue;
            }
            for (int c = 0; c < nc; ++c)
            {
              sum[c] += image->GetComponent(nt, c);
            }
            ++count;
          }
        }
        if (count == 0)
        {
          continue;
        }
        for (int c = 0; c < nc; ++c)
        {
          value[c] = integral ? std::floor(sum[c] / count + 0.5) : sum[c] / count;
          image->SetComponent(t, c, value[c]);
        }
        added.push_back(t);
      }
    }
    if (added.empty())
    {
      break;
    }
    for (vtkIdType t : added) // read from the next pass on
    {
      filled[t] = 1;
    }
  }
}
}

//------------------------------------------------------------------------------
vtkOFBTextureBaker::vtkOFBTextureBaker()
  : Radius(std::sqrt(3.0))
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOFBTextureBaker::~vtkOFBTextureBaker() = default;

//------------------------------------------------------------------------------
void vtkOFBTextureBaker::SetOFBConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkOFBTextureBaker::SetOFBData(vtkOFB* ofb)
{
  this->SetInputDataInternal(1, ofb);
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBTextureBaker::FindSourceArray(vtkOFB* ofb) const
{
  vtkPointData* spd = ofb->GetSampleData();
  vtkDataArray* source = this->ArrayName.empty()
    ? (spd->GetScalars() ? spd->GetScalars() : spd->GetArray(vtkOFB::ColorsArrayName()))
    : spd->GetArray(this->ArrayName.c_str());
  return source && source->GetName() && source->GetNumberOfTuples() == ofb->GetNumberOfSamples()
    ? source
    : nullptr;
}

//------------------------------------------------------------------------------
int vtkOFBTextureBaker::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBTextureBaker::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  // The scalars' type and components, for downstream imaging filters: those of the
  // array in the OFB where it is there already (SetOFBData, an updated pipeline),
  // else what the default array, the paint, has (RGBA bytes), or one float.
  vtkOFB* ofb = vtkOFB::GetData(inputVector[1]);
  vtkDataArray* source = ofb ? this->FindSourceArray(ofb) : nullptr;
  if (source)
  {
    vtkDataObject::SetPointDataActiveScalarInfo(info,
      this->OutputScalarType == VTK_FLOAT ? VTK_FLOAT : source->GetDataType(),
      source->GetNumberOfComponents());
  }
  else if (this->ArrayName.empty() || this->ArrayName == vtkOFB::ColorsArrayName())
  {
    vtkDataObject::SetPointDataActiveScalarInfo(
      info, this->OutputScalarType == VTK_FLOAT ? VTK_FLOAT : VTK_UNSIGNED_CHAR, 4);
  }
  else
  {
    vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
  }
  const int w = std::max(1, std::min(this->TextureSize[0], 16384));
  const int h = std::max(1, std::min(this->TextureSize[1], 16384));
  const int extent[6] = { 0, w - 1, 0, h - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkOFBTextureBaker::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* mesh = vtkPolyData::GetData(inputVector[0]);
  vtkOFB* ofb = vtkOFB::GetData(inputVector[1]);
  vtkImageData* image = vtkImageData::GetData(outputVector);
  image->Initialize();
  this->NumberOfBakedTexels = 0;
  const int w = this->TextureSize[0];
  const int h = this->TextureSize[1];
  vtkDataArray* tcoords = mesh ? mesh->GetPointData()->GetTCoords() : nullptr;
  if (!mesh || !ofb || ofb->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("No mesh, or no OFB to bake or an empty one (SetOFBConnection).");
    return 1;
  }
  std::string error;
  if (!vtkOFBCheckCellPointIds(mesh, error))
  {
    vtkErrorMacro("The mesh (input port 0) is invalid: " << error << ".");
    return 1;
  }
  if (!tcoords || tcoords->GetNumberOfComponents() < 2 ||
    tcoords->GetNumberOfTuples() != mesh->GetNumberOfPoints())
  {
    vtkErrorMacro("The mesh has no texture coordinates (2 components, one pair a point).");
    return 1;
  }
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
  {
    vtkErrorMacro("TextureSize " << w << " x " << h << " is outside [1, 16384].");
    return 1;
  }
  if (!(this->Radius > 0.0) || !std::isfinite(this->Radius))
  {
    vtkErrorMacro("Radius " << this->Radius << " is not positive and finite.");
    return 1;
  }
  if (this->OutputScalarType != VTK_VOID && this->OutputScalarType != VTK_FLOAT)
  {
    vtkErrorMacro("OutputScalarType " << this->OutputScalarType
                                      << " is neither VTK_VOID (the array's type) nor VTK_FLOAT.");
    return 1;
  }
  vtkDataArray* source = this->FindSourceArray(ofb);
  if (!source)
  {
    vtkErrorMacro("The OFB has no sample array '"
      << (this->ArrayName.empty() ? vtkOFB::ColorsArrayName() : this->ArrayName.c_str())
      << "' to bake.");
    return 1;
  }
  // Checked before anything is allocated: an allocation of many GiB may succeed and
  // then exhaust the memory page by page instead of failing.
  const vtkIdType bytes = vtkOFBTextureBaker::EstimateBakeBytes(
    w, h, source->GetNumberOfComponents() * source->GetDataTypeSize());
  if (bytes / (vtkIdType(1) << 20) >= this->MemoryLimit)
  {
    vtkErrorMacro("Baking a " << w << " x " << h << " texture would take about " << (bytes >> 20)
                              << " MiB, more than MemoryLimit (" << this->MemoryLimit
                              << " MiB): refused. Raise MemoryLimit or bake a smaller texture.");
    return 1;
  }
  if (mesh->GetNumberOfStrips() > 0 || mesh->GetNumberOfLines() > 0)
  {
    vtkWarningMacro("Strips and lines are not baked: apply vtkTriangleFilter first.");
  }

  // A texture too large for the memory gives an error, not an exception out of VTK.
  try
  {
    this->Bake(mesh, ofb, source, tcoords, image, outputVector->GetInformationObject(0));
  }
  catch (const std::bad_alloc&)
  {
    image->Initialize();
    vtkErrorMacro("Not enough memory to bake a " << w << " x " << h << " texture.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBTextureBaker::Bake(vtkPolyData* mesh,
  vtkOFB* ofb,
  vtkDataArray* source,
  vtkDataArray* tcoords,
  vtkImageData* image,
  vtkInformation* outInfo)
{
  const int w = this->TextureSize[0];
  const int h = this->TextureSize[1];
  // The texels covered by the triangles (fans of the polygons), in cell order.
  Coverage cover;
  cover.Reset(w, h);
  const vtkIdType total = mesh->GetNumberOfPolys();
  vtkOFBForEachFanTriangle(mesh,
    [&](vtkIdType cell, const vtkIdType corner[3], const glm::dvec3 x[3])
    {
      glm::dvec2 uv[3];
      for (int c = 0; c < 3; ++c)
      {
        uv[c] =
          glm::dvec2(tcoords->GetComponent(corner[c], 0), tcoords->GetComponent(corner[c], 1));
      }
      cover.AddTriangle(uv, x);
      if ((cell & 4095) == 0)
      {
        this->UpdateProgress(0.3 * cell / std::max<vtkIdType>(total, 1));
      }
    });

  // Their values, looked up in the OFB.
  const vtkIdType n = static_cast<vtkIdType>(cover.TexelOf.size());
  vtkOFBPyramidResampler transfer(ofb, cover.Points.data(), n, this->Radius * ofb->GetCellSize());
  transfer.Nearest = this->LookupMode == 0;
  const std::set<std::string> names = { source->GetName() };
  transfer.CollectArrays(&names);
  transfer.SetTargetNormals(this->NormalAware ? cover.Normals.data() : nullptr);
  std::vector<unsigned char> found(static_cast<size_t>(n), 0);
  transfer.Found = found.data();
  vtkSMPTools::For(0, n, 4096, transfer);
  this->UpdateProgress(0.8);

  // The image.
  image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  const vtkIdType texels = static_cast<vtkIdType>(w) * h;
  vtkSmartPointer<vtkDataArray> values = vtk::TakeSmartPointer(source->NewInstance());
  values->SetName(source->GetName());
  values->SetNumberOfComponents(source->GetNumberOfComponents());
  values->SetNumberOfTuples(texels);
  values->Fill(0.0);
  auto mask = vtkSmartPointer<vtkUnsignedCharArray>::New();
  mask->SetName("vtkValidPointMask");
  mask->SetNumberOfValues(texels);
  mask->Fill(0);
  std::vector<unsigned char> filled(static_cast<size_t>(texels), 0);
  vtkDataArray* baked = transfer.GetTargetArrays().front();
  for (vtkIdType k = 0; k < n; ++k)
  {
    if (found[k])
    {
      values->SetTuple(cover.TexelOf[k], k, baked);
      mask->SetValue(cover.TexelOf[k], 1);
      filled[cover.TexelOf[k]] = 1;
      ++this->NumberOfBakedTexels;
    }
  }
  if (this->NumberOfBakedTexels == 0)
  {
    vtkWarningMacro("No texel was baked: are the texture coordinates in [0, 1] and the mesh "
                    "the OFB's surface?");
  }
  Pad(values, filled, w, h, this->Padding);
  if (this->OutputScalarType == VTK_FLOAT && values->GetDataType() != VTK_FLOAT)
  {
    auto floats = vtkSmartPointer<vtkFloatArray>::New();
    floats->DeepCopy(values); // converted, not scaled
    floats->SetName(source->GetName());
    values = floats;
  }
  image->GetPointData()->SetScalars(values);
  image->GetPointData()->AddArray(mask);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, values->GetDataType(), values->GetNumberOfComponents());
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBTextureBaker::EstimateBakeBytes(int width, int height, int bytesPerTuple)
{
  // Per texel, at most: its slot (4), and when covered its texel id (8), surface
  // point (24), normal (12) and found flag (1); the image's mask (1) and fill flags
  // (1); the looked-up values and the image's values (a tuple each).
  const vtkIdType perTexel =
    4 + 8 + 24 + 12 + 1 + 1 + 1 + 2 * vtkIdType(std::max(0, bytesPerTuple));
  return static_cast<vtkIdType>(std::max(0, width)) * std::max(0, height) * perTexel;
}

//------------------------------------------------------------------------------
void vtkOFBTextureBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TextureSize: " << this->TextureSize[0] << " x " << this->TextureSize[1] << "\n";
  os << indent << "ArrayName: " << (this->ArrayName.empty() ? "(active scalars)" : this->ArrayName)
     << "\n";
  os << indent << "OutputScalarType: "
     << (this->OutputScalarType == VTK_VOID ? "SameAsArray"
                                            : vtkImageScalarTypeNameMacro(this->OutputScalarType))
     << "\n";
  os << indent << "LookupMode: " << (this->LookupMode == 0 ? "Nearest" : "Smooth") << "\n";
  os << indent << "Radius: " << this->Radius << " cells\n";
  os << indent << "NormalAware: " << (this->NormalAware ? "On" : "Off") << "\n";
  os << indent << "Padding: " << this->Padding << " texels\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "NumberOfBakedTexels: " << this->NumberOfBakedTexels << "\n";
}
