// vtkOFBMapToColors: the mapper's colouring (paint or scalars through a lookup table,
// combined with a LIC by blend or map) written per sample, against the formulas computed
// here in double precision; the input untouched; bad input.
#include "vtkOFBTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBColorSpace.h" // private header of the module: the HSL helpers
#include "vtkOFBColoring.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace vtkofbtest;

namespace
{
/// A painted sphere's OFB (some samples transparent) with a "LIC" of values spread over
/// [-0.2, 1.2] (some outside [0, 1], one NaN) and a 3-component "V".
vtkSmartPointer<vtkOFB> PaintedOFBWithLIC()
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 64), 48);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(0.5);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  for (int k = 0; k < 12; ++k)
  {
    // Every third dab erases the alpha (constant falloff: alpha 0 in its middle).
    unsigned char c[4];
    RandomColor(random, 255, c);
    painter->GetBrush()->SetColor(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    painter->GetBrush()->SetBlendMode(
      k % 3 == 0 ? vtkOFBBrush::BLEND_ERASE_ALPHA : vtkOFBBrush::BLEND_MIX);
    painter->GetBrush()->SetFalloffToConstant();
    double p[3];
    OnSphere(random->GetNextRangeValue(0, vtkMath::Pi()),
      random->GetNextRangeValue(0, 2 * vtkMath::Pi()),
      p);
    painter->Dab(p);
  }
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkFloatArray> lic;
  lic->SetName("LIC");
  lic->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> v;
  v->SetName("V");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    lic->SetValue(i, static_cast<float>(0.5 + 0.7 * x[0]));
    v->SetTuple3(i, x[0], 2.0 * x[1], 0.5);
  }
  lic->SetValue(n / 2, std::nanf(""));
  ofb->GetSampleData()->AddArray(lic);
  ofb->GetSampleData()->AddArray(v);
  return ofb;
}

/// The mapper's table rule: the colour of the nearest of 1024 values spread over range.
void TableColor(vtkScalarsToColors* lut, const double range[2], double s, double rgba[4])
{
  const double span = range[1] - range[0];
  double t = span != 0.0 ? (s - range[0]) / span : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  const double v = range[0] + span * std::floor(t * 1023.0 + 0.5) / 1023.0;
  lut->GetColor(v, rgba);
  rgba[3] = lut->GetOpacity(v);
}

/// Combine with the LIC l as VTK's surface LIC: blend or map.
void Combine(double rgba[4], double l, bool blend, double share, double bias, double weight)
{
  l = l > 0.0 ? std::min(l, 1.0) : 0.0; // clamped, NaN to 0
  for (int c = 0; c < 3; ++c)
  {
    rgba[c] = blend ? rgba[c] * (1.0 - share) + l * share
                    : rgba[c] * (1.0 + (std::min(1.0, std::max(0.0, l + bias)) - 1.0) * weight);
  }
}

/// The largest difference in levels between `colors` and `expected` over all samples.
template<typename F>
int LargestDifference(vtkUnsignedCharArray* colors, vtkIdType n, F expected)
{
  int worst = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double rgba[4];
    expected(i, rgba);
    for (int c = 0; c < 4; ++c)
    {
      const double want = std::min(1.0, std::max(0.0, rgba[c])) * 255.0;
      worst = std::max(
        worst, static_cast<int>(std::ceil(std::abs(colors->GetTypedComponent(i, c) - want) - 0.5)));
    }
  }
  return worst;
}

vtkOFB* MapColors(vtkOFBMapToColors* filter, vtkOFB* ofb)
{
  filter->SetInputData(ofb);
  filter->Update();
  return filter->GetOutput();
}
}

//------------------------------------------------------------------------------
TEST(MapToColors, PaintBlendedWithTheLICEqualsTheFormula)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedOFBWithLIC();
  auto* paint = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  ASSERT_NE(paint, nullptr);
  vtkNew<vtkUnsignedCharArray> before;
  before->DeepCopy(paint);
  vtkNew<vtkOFBMapToColors> filter;
  filter->GetColoring()->IntensityModulationOn();
  filter->GetColoring()->SetLICIntensity(0.6);
  vtkOFB* out = MapColors(filter, ofb);
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_EQ(out->GetNumberOfSamples(), n);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(out->GetSampleData()->GetScalars());
  ASSERT_NE(colors, nullptr);
  EXPECT_STREQ(colors->GetName(), "DisplayColors");
  EXPECT_EQ(colors->GetNumberOfComponents(), 4);
  const auto* lic = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("LIC"));
  vtkIdType transparent = 0;
  const int worst = LargestDifference(colors,
    n,
    [&](vtkIdType i, double rgba[4])
    {
      for (int c = 0; c < 4; ++c)
      {
        rgba[c] = paint->GetTypedComponent(i, c) / 255.0;
      }
      if (rgba[3] == 0.0)
      {
        ++transparent;
        rgba[0] = rgba[1] = rgba[2] = 0.0;
      }
      Combine(rgba, lic->GetValue(i), true, 0.6, 0.0, 1.0);
    });
  EXPECT_LE(worst, 1);
  EXPECT_GT(transparent, 0);
  // The input untouched; the output shares the paint and the LIC.
  EXPECT_EQ(ofb->GetSampleData()->GetArray("DisplayColors"), nullptr);
  for (vtkIdType i = 0; i < 4 * n; ++i)
  {
    ASSERT_EQ(paint->GetValue(i), before->GetValue(i));
  }
  EXPECT_EQ(out->GetSampleData()->GetArray("Colors"), paint);
  EXPECT_EQ(out->GetSampleData()->GetArray("LIC"), ofb->GetSampleData()->GetArray("LIC"));

  // Without modulation, the paint itself (transparent samples black).
  filter->GetColoring()->IntensityModulationOff();
  filter->SetOutputArrayName("Colors");
  out = MapColors(filter, ofb);
  colors = vtkUnsignedCharArray::SafeDownCast(out->GetSampleData()->GetArray("Colors"));
  ASSERT_NE(colors, paint);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool clear = paint->GetTypedComponent(i, 3) == 0;
    for (int c = 0; c < 4; ++c)
    {
      ASSERT_EQ(colors->GetTypedComponent(i, c), clear ? 0 : paint->GetTypedComponent(i, c));
    }
  }
}

//------------------------------------------------------------------------------
TEST(MapToColors, ScalarsMappedAndMultipliedByTheLICEqualTheFormula)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedOFBWithLIC();
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->SetAlphaRange(0.5, 1.0);
  lut->Build();
  vtkNew<vtkOFBMapToColors> filter;
  filter->GetColoring()->SetColorSourceToScalars();
  filter->GetColoring()->SetScalarArrayName("V");
  filter->GetColoring()->SetLookupTable(lut);
  filter->GetColoring()->IntensityModulationOn();
  filter->GetColoring()->SetLICColorModeToMap();
  filter->GetColoring()->SetMapModeBias(-0.2);
  filter->GetColoring()->SetIntensityWeight(0.7);
  auto* v = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("V"));
  const auto* lic = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("LIC"));
  // The magnitude over [0, 2], then component 1 over the table's own range [-1, 1.5].
  for (int component : { -1, 1 })
  {
    filter->GetColoring()->SetScalarComponent(component);
    if (component == 1)
    {
      lut->SetRange(-1.0, 1.5);
      filter->GetColoring()->UseLookupTableScalarRangeOn();
    }
    else
    {
      filter->GetColoring()->SetScalarRange(0.0, 2.0);
    }
    auto* colors =
      vtkUnsignedCharArray::SafeDownCast(MapColors(filter, ofb)->GetSampleData()->GetScalars());
    ASSERT_NE(colors, nullptr);
    const double range[2] = { component == 1 ? -1.0 : 0.0, component == 1 ? 1.5 : 2.0 };
    std::set<int> reds;
    const int worst = LargestDifference(colors,
      n,
      [&](vtkIdType i, double rgba[4])
      {
        double t[3];
        v->GetTuple(i, t);
        TableColor(lut, range, component < 0 ? vtkMath::Norm(t) : t[1], rgba);
        Combine(rgba, lic->GetValue(i), false, 0.0, -0.2, 0.7);
      });
    EXPECT_LE(worst, 1) << "component " << component;
    for (vtkIdType i = 0; i < n; ++i)
    {
      reds.insert(colors->GetTypedComponent(i, 0));
    }
    EXPECT_GT(reds.size(), 50u) << "the table's colours spread over the samples";
  }
  EXPECT_DOUBLE_EQ(lut->GetRange()[0], -1.0);
}

//------------------------------------------------------------------------------
TEST(MapToColors, ColorContrastStretchesTheLightnessAndKeepsTheHue)
{
  // The HSL helpers: the same lightness gives the colour back; another keeps the hue's
  // pattern (channel - min) / (max - min) and reaches that lightness.
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(9);
  for (int k = 0; k < 1000; ++k)
  {
    glm::vec3 c;
    for (int j = 0; j < 3; ++j)
    {
      c[j] = static_cast<float>(random->GetNextRangeValue(0.05, 0.95));
    }
    const glm::vec3 same = vtkOFBWithLightness(c, vtkOFBLightness(c));
    ASSERT_LT(glm::length(same - c), 1e-5f);
    const float l = static_cast<float>(random->GetNextRangeValue(0.1, 0.9));
    const glm::vec3 d = vtkOFBWithLightness(c, l);
    ASSERT_NEAR(vtkOFBLightness(d), l, 1e-5f);
    const float cl = std::min({ c.r, c.g, c.b }), ch = std::max({ c.r, c.g, c.b });
    const float dl = std::min({ d.r, d.g, d.b }), dh = std::max({ d.r, d.g, d.b });
    for (int j = 0; j < 3; ++j)
    {
      ASSERT_NEAR((c[j] - cl) / (ch - cl), (d[j] - dl) / (dh - dl), 1e-3f);
    }
  }

  vtkSmartPointer<vtkOFB> ofb = PaintedOFBWithLIC();
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkOFBMapToColors> filter;
  filter->GetColoring()->IntensityModulationOn();
  filter->GetColoring()->SetLICIntensity(0.5);
  filter->SetOutputArrayName("Plain");
  vtkNew<vtkUnsignedCharArray> plain;
  plain->DeepCopy(MapColors(filter, ofb)->GetSampleData()->GetArray("Plain"));
  EXPECT_EQ(filter->GetLightnessRange()[1], 0.0) << "not computed without the stretch";
  filter->GetColoring()->EnhanceColorContrastOn();
  filter->GetColoring()->SetLowColorContrastEnhancementFactor(0.1);
  filter->GetColoring()->SetHighColorContrastEnhancementFactor(0.2);
  filter->SetOutputArrayName("Stretched");
  auto* stretched = vtkUnsignedCharArray::SafeDownCast(
    MapColors(filter, ofb)->GetSampleData()->GetArray("Stretched"));
  ASSERT_NE(stretched, nullptr);
  double range[2];
  filter->GetLightnessRange(range);
  EXPECT_LT(range[0], range[1]);
  // The range alone (what the mapper asks for): the same numbers, with the stretch off
  // too, and no array written to the input.
  const int arrays = ofb->GetSampleData()->GetNumberOfArrays();
  filter->GetColoring()->EnhanceColorContrastOff();
  double alone[2] = { -1.0, -1.0 };
  EXPECT_TRUE(filter->ComputeLightnessRange(ofb, alone));
  EXPECT_EQ(alone[0], range[0]);
  EXPECT_EQ(alone[1], range[1]);
  EXPECT_EQ(ofb->GetSampleData()->GetNumberOfArrays(), arrays);
  filter->GetColoring()->EnhanceColorContrastOn();
  const double m = range[0] + 0.1 * (range[1] - range[0]);
  const double M = range[1] - 0.2 * (range[1] - range[0]);
  ASSERT_GT(M - m, 0.1);
  double low = 1.0, high = 0.0, worst = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    glm::vec3 a, b;
    for (int c = 0; c < 3; ++c)
    {
      a[c] = plain->GetTypedComponent(i, c) / 255.0f;
      b[c] = stretched->GetTypedComponent(i, c) / 255.0f;
    }
    if (plain->GetTypedComponent(i, 3) == 0)
    {
      continue;
    }
    low = std::min(low, static_cast<double>(vtkOFBLightness(a)));
    high = std::max(high, static_cast<double>(vtkOFBLightness(a)));
    const double want = std::min(1.0, std::max(0.0, (vtkOFBLightness(a) - m) / (M - m)));
    worst = std::max(worst, std::abs(vtkOFBLightness(b) - want));
  }
  // The range is that of the unrounded colours; the stretch of rounded ones is compared.
  EXPECT_NEAR(low, range[0], 1.0 / 255.0);
  EXPECT_NEAR(high, range[1], 1.0 / 255.0);
  EXPECT_LE(worst, 2.0 / 255.0 / (M - m));
}

//------------------------------------------------------------------------------
TEST(MapToColors, BadInputGivesAnErrorAndAnEmptyOutput)
{
  vtkSmartPointer<vtkOFB> ofb = PaintedOFBWithLIC();
  vtkNew<vtkOFBMapToColors> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  auto expectError = [&](const char* words)
  {
    messages->Clear();
    EXPECT_EQ(MapColors(filter, ofb)->GetNumberOfSamples(), 0) << words;
    EXPECT_NE(messages->Errors.find(words), std::string::npos) << messages->Errors;
  };
  filter->GetColoring()->SetColorSourceToScalars();
  filter->GetColoring()->SetScalarArrayName("nothing");
  expectError("no numeric sample array \"nothing\"");
  filter->GetColoring()->SetScalarArrayName("LIC");
  filter->GetColoring()->SetScalarComponent(2);
  expectError("with a component 2");
  filter->GetColoring()->SetScalarComponent(0);
  filter->GetColoring()->SetScalarRange(0.0, HUGE_VAL);
  expectError("is not finite");
  filter->GetColoring()->SetScalarRange(0.0, 1.0);
  filter->GetColoring()->IntensityModulationOn();
  filter->GetColoring()->SetIntensityArrayName("V");
  expectError("1-component");
  filter->GetColoring()->SetIntensityArrayName("LIC");
  filter->SetOutputArrayName("");
  expectError("OutputArrayName is empty");
  filter->SetOutputArrayName("Out");
  // A scalar range of zero width: every sample takes the table's first colour.
  filter->GetColoring()->SetScalarRange(0.5, 0.5);
  filter->GetColoring()->IntensityModulationOff();
  messages->Clear();
  vtkOFB* out = MapColors(filter, ofb);
  EXPECT_EQ(out->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  EXPECT_TRUE(messages->Errors.empty());
  auto* colors = vtkUnsignedCharArray::SafeDownCast(out->GetSampleData()->GetArray("Out"));
  ASSERT_NE(colors, nullptr);
  double first[3];
  filter->GetColoring()->GetLookupTable()->GetColor(0.5, first);
  EXPECT_EQ(colors->GetTypedComponent(7, 2), static_cast<int>(first[2] * 255.0 + 0.5));
  // A NaN scalar (the LIC's sample n / 2) takes the table's NaN colour.
  double nanColor[3];
  filter->GetColoring()->GetLookupTable()->GetColor(vtkMath::Nan(), nanColor);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(colors->GetTypedComponent(ofb->GetNumberOfSamples() / 2, c),
      static_cast<int>(nanColor[c] * 255.0 + 0.5));
  }
  // Paint without colours.
  ofb->GetSampleData()->RemoveArray("Colors");
  filter->GetColoring()->SetColorSourceToPaint();
  expectError("no \"Colors\" array of RGBA bytes");
  messages->Clear();
  double range[2] = { -1.0, -1.0 };
  EXPECT_FALSE(filter->ComputeLightnessRange(ofb, range));
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], 0.0);
  EXPECT_NE(messages->Errors.find("no \"Colors\" array of RGBA bytes"), std::string::npos);
  messages->Clear();
  EXPECT_FALSE(filter->ComputeLightnessRange(nullptr, range));
  EXPECT_NE(messages->Errors.find("No input OFB"), std::string::npos);
  // An empty OFB (no arrays either): an error and an empty output, no crash.
  vtkNew<vtkOFB> empty;
  filter->GetColoring()->SetColorSourceToScalars();
  messages->Clear();
  filter->SetInputData(empty);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfSamples(), 0);
  EXPECT_NE(messages->Errors.find("no numeric sample array"), std::string::npos);
}
