#include "vtkOFBMapToColors.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkOFB.h"
#include "vtkOFBColorSpace.h"
#include "vtkOFBColoring.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkOFBMapToColors);

namespace
{
// Entries of the sampled lookup table: vtkOFBPolyDataMapper's (vtkOFBShaderStorage), so
// that a sample gets the colour the mapper's nearest entry gives it.
constexpr int TableSize = 1024;

/// One value a tuple of an array (a component, or the magnitude with component -1) as
/// floats, for the per-sample loop.
struct ToFloats
{
  template<typename ArrayT>
  void operator()(ArrayT* array, int component, std::vector<float>& out) const
  {
    const auto tuples = vtk::DataArrayTupleRange(array);
    const int nc = array->GetNumberOfComponents();
    float* dst = out.data();
    vtkSMPTools::For(0,
      array->GetNumberOfTuples(),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const auto tuple = tuples[i];
          if (component >= 0 || nc == 1)
          {
            dst[i] = static_cast<float>(tuple[std::max(component, 0)]);
            continue;
          }
          double sum = 0.0;
          for (int c = 0; c < nc; ++c)
          {
            const double v = tuple[c];
            sum += v * v;
          }
          dst[i] = static_cast<float>(std::sqrt(sum));
        }
      });
  }
};

std::vector<float> Floats(vtkDataArray* array, int component)
{
  std::vector<float> out(static_cast<size_t>(array->GetNumberOfTuples()));
  ToFloats worker;
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker, component, out))
  {
    worker(array, component, out);
  }
  return out;
}

/// The lookup table sampled at TableSize equal steps over the scalar range, as the mapper
/// uploads it, and how a scalar finds its entry.
struct SampledTable
{
  std::vector<glm::vec4> Entries;
  glm::vec4 NaN{ 0.0f };
  double Low = 0.0;
  double Scale = 0.0; // 1 / (high - low), 0 for an empty range: the first entry

  void Sample(vtkScalarsToColors* lut, const double range[2])
  {
    this->Entries.resize(TableSize);
    this->Low = range[0];
    this->Scale = range[1] != range[0] ? 1.0 / (range[1] - range[0]) : 0.0;
    for (int i = 0; i < TableSize; ++i)
    {
      const double v = range[0] + (range[1] - range[0]) * i / (TableSize - 1.0);
      double rgb[3];
      lut->GetColor(v, rgb);
      this->Entries[i] = glm::vec4(rgb[0], rgb[1], rgb[2], lut->GetOpacity(v));
    }
    double rgb[3];
    lut->GetColor(vtkMath::Nan(), rgb);
    this->NaN = glm::vec4(rgb[0], rgb[1], rgb[2], lut->GetOpacity(vtkMath::Nan()));
  }

  glm::vec4 Color(float scalar) const
  {
    if (std::isnan(scalar))
    {
      return this->NaN;
    }
    const double s = std::min(1.0, std::max(0.0, (scalar - this->Low) * this->Scale));
    return this->Entries[std::min(static_cast<int>(s * (TableSize - 1) + 0.5), TableSize - 1)];
  }
};

/// The colour of sample i before lighting: the source's, combined with the intensity.
struct SampleColor
{
  const unsigned char* Paint = nullptr; // RGBA bytes, or null: the scalars
  const SampledTable* Table = nullptr;
  const float* Scalars = nullptr;
  const float* Intensity = nullptr; // null without modulation
  bool Blend = true;
  float Share = 0.8f;
  float Bias = 0.0f;
  float Weight = 1.0f;

  glm::vec4 operator()(vtkIdType i) const
  {
    glm::vec4 c;
    if (this->Paint)
    {
      const unsigned char* p = this->Paint + 4 * i;
      c = glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
      c = c.a > 0.0f ? c : glm::vec4(0.0f);
    }
    else
    {
      c = this->Table->Color(this->Scalars[i]);
    }
    if (this->Intensity)
    {
      // Clamped to [0, 1] (NaN to 0), as the mapper stores it.
      const float v = this->Intensity[i];
      const float l = v > 0.0f ? std::min(v, 1.0f) : 0.0f;
      const glm::vec3 rgb(c);
      c = glm::vec4(this->Blend
          ? glm::mix(rgb, glm::vec3(l), this->Share)
          : rgb * glm::mix(1.0f, glm::clamp(l + this->Bias, 0.0f, 1.0f), this->Weight),
        c.a);
    }
    return c;
  }
};

/// The smallest and largest HSL lightness of the samples' colours with alpha above 0
/// (x > y where there are none).
glm::vec2 FindLightnessRange(const SampleColor& color, vtkIdType n)
{
  vtkSMPThreadLocal<glm::vec2> ranges(glm::vec2(1.0f, 0.0f));
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      glm::vec2& r = ranges.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        const glm::vec4 c = color(i);
        if (c.a > 0.0f)
        {
          const float l = vtkOFBLightness(glm::vec3(c));
          r = r.x > r.y ? glm::vec2(l) : glm::vec2(std::min(r.x, l), std::max(r.y, l));
        }
      }
    });
  glm::vec2 range(1.0f, 0.0f);
  for (const glm::vec2& r : ranges)
  {
    if (r.x <= r.y)
    {
      range = range.x > range.y ? r : glm::vec2(std::min(range.x, r.x), std::max(range.y, r.y));
    }
  }
  return range;
}

unsigned char ToByte(float v)
{
  return static_cast<unsigned char>(std::min(1.0f, std::max(0.0f, v)) * 255.0f + 0.5f);
}
}

//------------------------------------------------------------------------------
vtkOFBMapToColors::vtkOFBMapToColors()
  : Coloring(vtkOFBColoring::New())
  , OutputArrayName("DisplayColors")
  , LightnessRange{ 0.0, 0.0 }
{
}

//------------------------------------------------------------------------------
vtkOFBMapToColors::~vtkOFBMapToColors()
{
  this->Coloring->Delete();
}

//------------------------------------------------------------------------------
void vtkOFBMapToColors::SetColoring(vtkOFBColoring* coloring)
{
  if (!coloring)
  {
    vtkErrorMacro("SetColoring(nullptr) is refused: the filter keeps its colouring.");
    return;
  }
  if (coloring == this->Coloring)
  {
    return;
  }
  coloring->Register(this);
  this->Coloring->UnRegister(this);
  this->Coloring = coloring;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBMapToColors::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Coloring->GetMTime());
}

//------------------------------------------------------------------------------
int vtkOFBMapToColors::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOFBMapToColors::FindArrays(vtkOFB* input, vtkDataArray*& source, vtkDataArray*& intensity)
{
  vtkPointData* pd = input->GetSampleData();
  const vtkIdType n = input->GetNumberOfSamples();
  vtkOFBColoring* settings = this->Coloring;
  source = nullptr;
  intensity = nullptr;
  if (settings->GetColorSource() == vtkOFBColoring::COLOR_SOURCE_PAINT)
  {
    source = vtkUnsignedCharArray::SafeDownCast(pd->GetAbstractArray(vtkOFB::ColorsArrayName()));
    if (!source || source->GetNumberOfComponents() != 4 || source->GetNumberOfTuples() != n)
    {
      vtkErrorMacro("ColorSource Paint: the OFB has no \"Colors\" array of RGBA bytes, one a "
                    "sample.");
      return false;
    }
  }
  else
  {
    source = vtkArrayDownCast<vtkDataArray>(pd->GetAbstractArray(settings->GetScalarArrayName()));
    if (!source || source->GetNumberOfTuples() != n ||
      settings->GetScalarComponent() >= source->GetNumberOfComponents())
    {
      vtkErrorMacro("ColorSource Scalars: no numeric sample array \""
        << settings->GetScalarArrayName() << "\" with a component "
        << settings->GetScalarComponent() << ", one tuple a sample.");
      return false;
    }
    const double* range = settings->GetScalarRange();
    if (!std::isfinite(range[0]) || !std::isfinite(range[1]))
    {
      vtkErrorMacro("ScalarRange " << range[0] << " " << range[1] << " is not finite.");
      return false;
    }
  }
  if (settings->GetIntensityModulation())
  {
    intensity =
      vtkArrayDownCast<vtkDataArray>(pd->GetAbstractArray(settings->GetIntensityArrayName()));
    if (!intensity || intensity->GetNumberOfComponents() != 1 ||
      intensity->GetNumberOfTuples() != n)
    {
      vtkErrorMacro("IntensityModulation: no numeric 1-component sample array \""
        << settings->GetIntensityArrayName() << "\", one value a sample.");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
struct vtkOFBMapToColors::SampleColoring
{
  SampledTable Table;
  std::vector<float> Scalars;
  std::vector<float> Intensity;
  SampleColor Color;
};

//------------------------------------------------------------------------------
void vtkOFBMapToColors::Prepare(vtkDataArray* source,
  vtkDataArray* intensityArray,
  SampleColoring& c)
{
  vtkOFBColoring* settings = this->Coloring;
  const bool paint = settings->GetColorSource() == vtkOFBColoring::COLOR_SOURCE_PAINT;
  // The scalar range: the table's own, or set on the table, as vtkMapper does.
  if (!paint)
  {
    double range[2];
    vtkScalarsToColors* lut = settings->PrepareLookupTable(range);
    c.Table.Sample(lut, range);
  }
  this->UpdateProgress(0.2);
  if (!paint)
  {
    c.Scalars = Floats(source, settings->GetScalarComponent());
  }
  if (intensityArray)
  {
    c.Intensity = Floats(intensityArray, 0);
  }
  this->UpdateProgress(0.4);

  SampleColor& color = c.Color;
  color.Paint = paint ? vtkUnsignedCharArray::SafeDownCast(source)->GetPointer(0) : nullptr;
  color.Table = &c.Table;
  color.Scalars = c.Scalars.empty() ? nullptr : c.Scalars.data();
  color.Intensity = c.Intensity.empty() ? nullptr : c.Intensity.data();
  color.Blend = settings->GetLICColorMode() == vtkOFBColoring::COLOR_MODE_BLEND;
  color.Share = static_cast<float>(settings->GetLICIntensity());
  color.Bias = static_cast<float>(settings->GetMapModeBias());
  color.Weight = static_cast<float>(settings->GetIntensityWeight());
}

//------------------------------------------------------------------------------
bool vtkOFBMapToColors::ComputeLightnessRange(vtkOFB* input, double range[2])
{
  range[0] = range[1] = 0.0;
  vtkDataArray* source;
  vtkDataArray* intensityArray;
  if (!input)
  {
    vtkErrorMacro("No input OFB.");
    return false;
  }
  if (!this->FindArrays(input, source, intensityArray))
  {
    return false;
  }
  SampleColoring coloring;
  this->Prepare(source, intensityArray, coloring);
  const glm::vec2 found = FindLightnessRange(coloring.Color, input->GetNumberOfSamples());
  this->UpdateProgress(1.0);
  if (found[0] > found[1])
  {
    return false;
  }
  range[0] = found[0];
  range[1] = found[1];
  return true;
}

//------------------------------------------------------------------------------
int vtkOFBMapToColors::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkOFB* input = vtkOFB::GetData(inputVector[0]);
  vtkOFB* output = vtkOFB::GetData(outputVector);
  output->Initialize();
  vtkDataArray* source;
  vtkDataArray* intensityArray;
  if (!input)
  {
    vtkErrorMacro("No input OFB.");
    return 1;
  }
  if (this->OutputArrayName.empty())
  {
    vtkErrorMacro("OutputArrayName is empty.");
    return 1;
  }
  if (!this->FindArrays(input, source, intensityArray))
  {
    return 1;
  }
  const vtkIdType n = input->GetNumberOfSamples();
  SampleColoring coloring;
  this->Prepare(source, intensityArray, coloring);
  const SampleColor& color = coloring.Color;

  // With the stretch: the lightness range of the colours shown (alpha above 0), a pass of
  // its own before the one that writes them.
  this->LightnessRange[0] = this->LightnessRange[1] = 0.0;
  const bool enhance = this->Coloring->GetEnhanceColorContrast();
  const glm::vec2 range = enhance ? FindLightnessRange(color, n) : glm::vec2(1.0f, 0.0f);
  if (range[0] <= range[1])
  {
    this->LightnessRange[0] = range[0];
    this->LightnessRange[1] = range[1];
  }
  const double span = this->LightnessRange[1] - this->LightnessRange[0];
  const float low = static_cast<float>(
    this->LightnessRange[0] + this->Coloring->GetLowColorContrastEnhancementFactor() * span);
  const float high = static_cast<float>(
    this->LightnessRange[1] - this->Coloring->GetHighColorContrastEnhancementFactor() * span);
  const bool stretch = enhance && high > low;
  this->UpdateProgress(0.6);

  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName(this->OutputArrayName.c_str());
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(n);
  unsigned char* out = colors->GetPointer(0);
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        glm::vec4 c = color(i);
        if (stretch)
        {
          const glm::vec3 rgb(c);
          c = glm::vec4(vtkOFBWithLightness(
                          rgb, glm::clamp((vtkOFBLightness(rgb) - low) / (high - low), 0.0f, 1.0f)),
            c.a);
        }
        for (int k = 0; k < 4; ++k)
        {
          out[4 * i + k] = ToByte(c[k]);
        }
      }
    });
  this->UpdateProgress(0.9);

  output->ShallowCopy(input);
  vtkPointData* pd = output->GetSampleData();
  // AddArray replaces an array of the same name; SetScalars would replace the active one.
  pd->AddArray(colors);
  pd->SetActiveScalars(this->OutputArrayName.c_str());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBMapToColors::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Coloring:\n";
  this->Coloring->PrintSelf(os, indent.GetNextIndent());
  os << indent << "OutputArrayName: " << this->OutputArrayName << "\n";
  os << indent << "LightnessRange: " << this->LightnessRange[0] << " " << this->LightnessRange[1]
     << "\n";
}
