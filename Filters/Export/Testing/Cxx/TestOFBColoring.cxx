// vtkOFBColoring: its defaults, clamps and names; one object shared by a
// vtkOFBPolyDataMapper and a vtkOFBMapToColors drives both (a setting changed once
// re-executes the filter and is a change of the mapper; both print it); SetColoring(nullptr)
// is refused with an error and changes nothing.
#include "vtkOFBTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkOFBColoring.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using namespace vtkofbtest;

namespace
{
/// A sphere's OFB, painted orange, with a "LIC" that varies from sample to sample.
vtkSmartPointer<vtkOFB> OFBWithLIC()
{
  vtkSmartPointer<vtkOFB> ofb = Build(MakeSphere(1.0, 32), 24);
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkUnsignedCharArray> paint;
  paint->SetName("Colors");
  paint->SetNumberOfComponents(4);
  paint->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const unsigned char rgba[4] = { 200, 120, 40, 255 };
    paint->SetTypedTuple(i, rgba);
  }
  ofb->GetSampleData()->AddArray(paint);
  vtkNew<vtkFloatArray> lic;
  lic->SetName("LIC");
  lic->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    lic->SetValue(i, static_cast<float>(i % 7) / 6.0f);
  }
  ofb->GetSampleData()->AddArray(lic);
  return ofb;
}

std::string Printed(vtkObject* object)
{
  std::ostringstream os;
  object->Print(os);
  return os.str();
}

/// The RGBA bytes of the filter's output array, copied.
std::vector<unsigned char> Output(vtkOFBMapToColors* filter)
{
  filter->Update();
  auto* colors = vtkUnsignedCharArray::SafeDownCast(
    filter->GetOutput()->GetSampleData()->GetArray(filter->GetOutputArrayName()));
  if (!colors)
  {
    return {};
  }
  const unsigned char* p = colors->GetPointer(0);
  return std::vector<unsigned char>(p, p + 4 * colors->GetNumberOfTuples());
}
}

//------------------------------------------------------------------------------
TEST(Coloring, DefaultsClampsAndNames)
{
  vtkNew<vtkOFBColoring> coloring;
  EXPECT_EQ(coloring->GetColorSource(), vtkOFBColoring::COLOR_SOURCE_PAINT);
  EXPECT_STREQ(coloring->GetScalarArrayName(), "");
  EXPECT_EQ(coloring->GetScalarComponent(), 0);
  EXPECT_EQ(coloring->GetScalarRange()[0], 0.0);
  EXPECT_EQ(coloring->GetScalarRange()[1], 1.0);
  EXPECT_FALSE(coloring->GetUseLookupTableScalarRange());
  EXPECT_STREQ(coloring->GetIntensityArrayName(), "LIC");
  EXPECT_FALSE(coloring->GetIntensityModulation());
  EXPECT_EQ(coloring->GetLICColorMode(), vtkOFBColoring::COLOR_MODE_BLEND);
  EXPECT_DOUBLE_EQ(coloring->GetLICIntensity(), 1.0);
  EXPECT_DOUBLE_EQ(coloring->GetMapModeBias(), 0.0);
  EXPECT_DOUBLE_EQ(coloring->GetIntensityWeight(), 1.0);
  EXPECT_FALSE(coloring->GetEnhanceColorContrast());
  EXPECT_DOUBLE_EQ(coloring->GetLowColorContrastEnhancementFactor(), 0.0);
  EXPECT_DOUBLE_EQ(coloring->GetHighColorContrastEnhancementFactor(), 0.0);
  EXPECT_NE(coloring->GetLookupTable(), nullptr) << "a default table on demand";

  coloring->SetColorSourceToScalars();
  EXPECT_EQ(coloring->GetColorSource(), vtkOFBColoring::COLOR_SOURCE_SCALARS);
  coloring->SetColorSource(9);
  EXPECT_EQ(coloring->GetColorSource(), vtkOFBColoring::COLOR_SOURCE_SCALARS);
  coloring->SetScalarComponent(-5);
  EXPECT_EQ(coloring->GetScalarComponent(), -1);
  coloring->SetLICColorModeToMap();
  EXPECT_EQ(coloring->GetLICColorMode(), vtkOFBColoring::COLOR_MODE_MAP);
  coloring->SetLICIntensity(-1.0);
  EXPECT_DOUBLE_EQ(coloring->GetLICIntensity(), 0.0);
  coloring->SetMapModeBias(3.0);
  EXPECT_DOUBLE_EQ(coloring->GetMapModeBias(), 1.0);
  coloring->SetIntensityWeight(2.0);
  EXPECT_DOUBLE_EQ(coloring->GetIntensityWeight(), 1.0);
  coloring->SetLowColorContrastEnhancementFactor(1.5);
  EXPECT_DOUBLE_EQ(coloring->GetLowColorContrastEnhancementFactor(), 1.0);
  coloring->SetHighColorContrastEnhancementFactor(-0.5);
  EXPECT_DOUBLE_EQ(coloring->GetHighColorContrastEnhancementFactor(), 0.0);
  EXPECT_STREQ(vtkOFBColoring::GetColorSourceAsString(1), "Scalars");
  EXPECT_STREQ(vtkOFBColoring::GetLICColorModeAsString(0), "COLOR_MODE_BLEND");

  const std::string printed = Printed(coloring);
  for (const char* setting : { "ColorSource: Scalars",
         "ScalarArrayName",
         "ScalarComponent: -1",
         "LookupTable",
         "ScalarRange: 0 1",
         "UseLookupTableScalarRange: Off",
         "IntensityArrayName: LIC",
         "IntensityModulation: Off",
         "LICColorMode: COLOR_MODE_MAP",
         "LICIntensity: 0",
         "MapModeBias: 1",
         "IntensityWeight: 1",
         "EnhanceColorContrast: Off",
         "LowColorContrastEnhancementFactor: 1",
         "HighColorContrastEnhancementFactor: 0" })
  {
    EXPECT_NE(printed.find(setting), std::string::npos) << setting << " in\n" << printed;
  }
}

//------------------------------------------------------------------------------
TEST(Coloring, MTimeIncludesTheLookupTable)
{
  vtkNew<vtkOFBColoring> coloring;
  vtkNew<vtkLookupTable> lut;
  coloring->SetLookupTable(lut);
  EXPECT_EQ(coloring->GetLookupTable(), lut.Get());
  const vtkMTimeType before = coloring->GetMTime();
  lut->SetHueRange(0.2, 0.3);
  EXPECT_GT(coloring->GetMTime(), before);
  // PrepareLookupTable: ScalarRange set on the table, or the table's own range.
  coloring->SetScalarRange(-2.0, 3.0);
  double range[2];
  EXPECT_EQ(coloring->PrepareLookupTable(range), lut.Get());
  EXPECT_EQ(range[0], -2.0);
  EXPECT_EQ(range[1], 3.0);
  EXPECT_EQ(lut->GetRange()[1], 3.0);
  lut->SetRange(5.0, 6.0);
  coloring->UseLookupTableScalarRangeOn();
  coloring->PrepareLookupTable(range);
  EXPECT_EQ(range[0], 5.0);
  EXPECT_EQ(range[1], 6.0);
}

//------------------------------------------------------------------------------
TEST(Coloring, SharedByAMapperAndMapToColorsDrivesBoth)
{
  vtkSmartPointer<vtkOFB> ofb = OFBWithLIC();
  vtkNew<vtkOFBPolyDataMapper> mapper;
  vtkNew<vtkOFBMapToColors> filter;
  filter->SetInputData(ofb);
  filter->SetColoring(mapper->GetColoring());
  ASSERT_EQ(filter->GetColoring(), mapper->GetColoring());
  vtkOFBColoring* shared = mapper->GetColoring();
  shared->IntensityModulationOn();
  const std::vector<unsigned char> first = Output(filter);
  ASSERT_EQ(first.size(), static_cast<size_t>(4 * ofb->GetNumberOfSamples()));
  EXPECT_EQ(Output(filter), first) << "nothing changed: the same colours";

  // One change, through either holder, reaches both.
  const vtkMTimeType mapperTime = mapper->GetMTime();
  const vtkMTimeType filterTime = filter->GetMTime();
  filter->GetColoring()->SetLICIntensity(0.3);
  EXPECT_DOUBLE_EQ(mapper->GetColoring()->GetLICIntensity(), 0.3);
  EXPECT_GT(mapper->GetMTime(), mapperTime) << "the mapper renders anew";
  EXPECT_GT(filter->GetMTime(), filterTime);
  const std::vector<unsigned char> second = Output(filter);
  ASSERT_EQ(second.size(), first.size());
  EXPECT_NE(second, first) << "the filter re-executed with the new setting";
  EXPECT_NE(Printed(mapper).find("LICIntensity: 0.3"), std::string::npos);
  EXPECT_NE(Printed(filter).find("LICIntensity: 0.3"), std::string::npos);

  // A change of the shared lookup table too.
  shared->SetColorSourceToScalars();
  shared->SetScalarArrayName("LIC");
  const std::vector<unsigned char> third = Output(filter);
  const vtkMTimeType beforeTable = mapper->GetMTime();
  vtkLookupTable* table = vtkLookupTable::SafeDownCast(shared->GetLookupTable());
  ASSERT_NE(table, nullptr);
  table->SetHueRange(0.3, 0.3);
  table->ForceBuild();
  EXPECT_GT(mapper->GetMTime(), beforeTable);
  EXPECT_NE(Output(filter), third);

  // Another colouring for the filter alone: the mapper keeps the shared one.
  vtkNew<vtkOFBColoring> own;
  filter->SetColoring(own);
  EXPECT_EQ(mapper->GetColoring(), shared);
  EXPECT_EQ(filter->GetColoring(), own.Get());
  EXPECT_NE(Output(filter), third) << "paint, no intensity: the default colouring";
}

//------------------------------------------------------------------------------
TEST(Coloring, SetColoringNullIsRefusedWithAnError)
{
  vtkSmartPointer<vtkOFB> ofb = OFBWithLIC();
  vtkNew<vtkOFBPolyDataMapper> mapper;
  vtkNew<vtkOFBMapToColors> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(mapper);
  messages->Watch(filter);
  vtkOFBColoring* mapperColoring = mapper->GetColoring();
  vtkOFBColoring* filterColoring = filter->GetColoring();
  ASSERT_NE(mapperColoring, nullptr);
  ASSERT_NE(filterColoring, nullptr);
  EXPECT_NE(mapperColoring, filterColoring) << "each made its own";
  const vtkMTimeType mapperTime = mapper->GetMTime();

  mapper->SetColoring(nullptr);
  EXPECT_NE(messages->Errors.find("SetColoring(nullptr) is refused"), std::string::npos);
  EXPECT_EQ(mapper->GetColoring(), mapperColoring);
  EXPECT_EQ(mapper->GetMTime(), mapperTime);
  messages->Clear();
  filter->SetColoring(nullptr);
  EXPECT_NE(messages->Errors.find("SetColoring(nullptr) is refused"), std::string::npos);
  EXPECT_EQ(filter->GetColoring(), filterColoring);

  // Both still work.
  messages->Clear();
  filter->SetInputData(ofb);
  EXPECT_EQ(Output(filter).size(), static_cast<size_t>(4 * ofb->GetNumberOfSamples()));
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  EXPECT_NE(Printed(mapper).find("ColorSource: Paint"), std::string::npos);
}
