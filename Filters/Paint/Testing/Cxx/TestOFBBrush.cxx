// Tests of vtkOFBBrush's settings: the enumerators it accepts.
#include "vtkOFBTestUtilities.h"

#include "vtkNew.h"
#include "vtkOFBBrush.h"

#include <gtest/gtest.h>

#include <string>

using namespace vtkofbtest;

//------------------------------------------------------------------------------
// A value that is no enumerator is refused with an error, and the setting stays.
TEST(Brush, UnknownEnumeratorsAreErrors)
{
  vtkNew<vtkOFBBrush> brush;
  vtkNew<MessageObserver> messages;
  messages->Watch(brush);
  brush->SetFalloffToGaussian();
  brush->SetBlendModeToDarken();
  brush->SetTargetToSmear();
  const vtkMTimeType before = brush->GetMTime();
  for (int bad : { -1, static_cast<int>(vtkOFBBrush::NUMBER_OF_FALLOFFS), 99 })
  {
    messages->Clear();
    brush->SetFalloff(bad);
    EXPECT_NE(messages->Errors.find("not a FalloffType"), std::string::npos) << bad;
    EXPECT_EQ(brush->GetFalloff(), vtkOFBBrush::FALLOFF_GAUSSIAN);
  }
  for (int bad : { -1, static_cast<int>(vtkOFBBrush::NUMBER_OF_BLEND_MODES), 99 })
  {
    messages->Clear();
    brush->SetBlendMode(bad);
    EXPECT_NE(messages->Errors.find("not a BlendModeType"), std::string::npos) << bad;
    EXPECT_EQ(brush->GetBlendMode(), vtkOFBBrush::BLEND_DARKEN);
  }
  for (int bad : { -1, static_cast<int>(vtkOFBBrush::NUMBER_OF_TARGETS), 99 })
  {
    messages->Clear();
    brush->SetTarget(bad);
    EXPECT_NE(messages->Errors.find("not a TargetType"), std::string::npos) << bad;
    EXPECT_EQ(brush->GetTarget(), vtkOFBBrush::TARGET_SMEAR);
  }
  EXPECT_EQ(brush->GetMTime(), before);
  EXPECT_STREQ(vtkOFBBrush::GetFalloffAsString(99), "Unknown");
  EXPECT_STREQ(vtkOFBBrush::GetBlendModeAsString(-1), "Unknown");
  EXPECT_STREQ(vtkOFBBrush::GetTargetAsString(vtkOFBBrush::NUMBER_OF_TARGETS), "Unknown");
  EXPECT_EQ(vtkOFBBrush::EvaluateFalloff(99, 0.5), 0.0);
  messages->Clear();
  brush->SetFalloff(vtkOFBBrush::FALLOFF_ROOT);
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  EXPECT_EQ(brush->GetFalloff(), vtkOFBBrush::FALLOFF_ROOT);
}
