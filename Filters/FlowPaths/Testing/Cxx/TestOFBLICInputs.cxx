// GoogleTest units of vtkOFBLIC's input handling: bad input and settings, far origins and
// huge values, and a cell vector field of the sampled surface.
#include "vtkOFBLICTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICTracer.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTriangleFilter.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>

using namespace vtkofbtest;

//------------------------------------------------------------------------------
TEST(LIC, BadInput)
{
  vtkNew<MessageObserver> messages;
  vtkNew<vtkOFBLIC> lic;
  messages->Watch(lic);
  // No vectors.
  vtkSmartPointer<vtkOFB> plain = Build(MakeSquare(), 64);
  ASSERT_GT(plain->GetNumberOfSamples(), 0);
  lic->SetInputData(plain);
  lic->Update();
  EXPECT_NE(messages->Errors.find("No vector field"), std::string::npos) << messages->Errors;
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0);

  // A field without 3 components.
  messages->Clear();
  vtkNew<vtkFloatArray> scalar;
  scalar->SetName("Speed");
  scalar->SetNumberOfTuples(plain->GetNumberOfSamples());
  scalar->FillValue(1.0f);
  plain->GetSampleData()->AddArray(scalar);
  lic->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Speed");
  lic->Update();
  EXPECT_NE(messages->Errors.find("components"), std::string::npos) << messages->Errors;
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0);

  // A field with fewer tuples than samples (reading it would run past its end).
  messages->Clear();
  vtkNew<vtkFloatArray> shortField;
  shortField->SetName("Short");
  shortField->SetNumberOfComponents(3);
  shortField->SetNumberOfTuples(plain->GetNumberOfSamples() / 2);
  shortField->FillValue(1.0f);
  plain->GetSampleData()->AddArray(shortField);
  lic->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Short");
  lic->Update();
  EXPECT_NE(messages->Errors.find("'Short' has"), std::string::npos) << messages->Errors;
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0);
  lic->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);

  // NaN vectors: masked, the rest convolved.
  messages->Clear();
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 64, UniformField(dir));
  vtkDataArray* vectors = ofb->GetSampleData()->GetVectors();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); i += 3)
  {
    vectors->SetTuple3(i, nan, 0.0, 0.0);
  }
  lic->SetInputData(ofb);
  lic->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  EXPECT_EQ(lic->GetNumberOfMaskedSamples(), (ofb->GetNumberOfSamples() + 2) / 3);
  const float* values = LICValues(lic->GetOutput());
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    ASSERT_TRUE(values[i] >= 0.0f && values[i] <= 1.0f);
  }

  // All-zero field: all masked, a warning.
  messages->Clear();
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    vectors->SetTuple3(i, 0.0, 0.0, 0.0);
  }
  vectors->Modified();
  ofb->Modified();
  lic->Update();
  EXPECT_NE(messages->Warnings.find("masked at every sample"), std::string::npos);
  EXPECT_EQ(lic->GetNumberOfMaskedSamples(), ofb->GetNumberOfSamples());
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), ofb->GetNumberOfSamples());

  // Contrast enhancement: a mode that is not VTK's, a factor outside [0, 1] or NaN.
  for (int k = 0; k < 3; ++k)
  {
    messages->Clear();
    lic->SetEnhanceContrast(k == 0 ? 2 : vtkOFBLIC::ENHANCE_CONTRAST_LIC);
    lic->SetLowLICContrastEnhancementFactor(k == 1 ? std::nan("") : 0.0);
    lic->SetHighLICContrastEnhancementFactor(k == 2 ? 1.5 : 0.0);
    lic->Update();
    EXPECT_NE(messages->Errors.find("EnhanceContrast"), std::string::npos) << k;
    EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0) << k;
  }
  lic->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_OFF);
  lic->SetHighLICContrastEnhancementFactor(0.0);

  // Zero and negative step sizes.
  for (double step : { 0.0, -1.0, std::numeric_limits<double>::infinity() })
  {
    messages->Clear();
    lic->SetStepSize(step);
    lic->Update();
    EXPECT_NE(messages->Errors.find("StepSize"), std::string::npos) << step;
    EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0);
  }
  lic->SetStepSize(1.0);

  // Empty OFB: an empty output with empty arrays, no error.
  messages->Clear();
  vtkNew<vtkOFB> empty;
  lic->SetInputData(empty);
  lic->Update();
  EXPECT_TRUE(messages->Errors.empty()) << messages->Errors;
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0);
  ASSERT_NE(lic->GetOutput()->GetSampleData()->GetArray("LIC"), nullptr);

  // A noise array that does not exist.
  messages->Clear();
  lic->SetInputData(plain);
  lic->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Speed");
  lic->SetNoiseArrayName("Nothing");
  vtkSmartPointer<vtkOFB> field = BuildWithField(MakeSquare(), 64, UniformField(dir));
  lic->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
  lic->SetInputData(field);
  lic->Update();
  EXPECT_NE(messages->Errors.find("noise array"), std::string::npos) << messages->Errors;
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0);
}

//------------------------------------------------------------------------------
TEST(LIC, FarOriginsAndHugeValuesAreDefined)
{
  // One sample per cell of a 2 x 2 x 2 frame far from the origin (or at the ends of
  // float depths), with huge and non-finite vectors: no undefined conversion (the
  // sanitizer build runs this clean), and a LIC value that is finite or masked.
  for (double origin : { 1e308, -1e308, 0.0 })
  {
    for (float depth : { 0.5f, 3e38f, -3e38f })
    {
      vtkNew<vtkOFB> ofb;
      const double o[3] = { origin, -origin, origin };
      const vtkIdType dims[3] = { 2, 2, 2 };
      ASSERT_TRUE(ofb->SetFrame(o, 1.0, dims));
      const vtkIdType cells = ofb->GetNumberOfCells();
      for (vtkIdType c = 0; c <= cells; ++c)
      {
        ofb->GetCellOffsets()->SetValue(c, static_cast<vtkTypeUInt32>(c));
      }
      ASSERT_TRUE(ofb->AllocateSamples(cells));
      vtkNew<vtkFloatArray> vectors;
      vectors->SetName("V");
      vectors->SetNumberOfComponents(3);
      vectors->SetNumberOfTuples(cells);
      for (vtkIdType i = 0; i < cells; ++i)
      {
        ofb->GetDepths()->SetValue(i, depth);
        const float big = (i % 3 == 0) ? 3e38f : (i % 3 == 1 ? 1.0f : NAN);
        vectors->SetTuple3(i, big, -big, 1.0);
      }
      ofb->BuildCellIndex();
      ofb->GetSampleData()->SetVectors(vectors);
      vtkNew<vtkOFBLIC> lic;
      lic->SetInputData(ofb);
      lic->Update();
      vtkOFB* out = lic->GetOutput();
      for (int a = 0; a < out->GetSampleData()->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* array = out->GetSampleData()->GetArray(a);
        if (array == vectors.Get() || array->GetDataType() != VTK_FLOAT)
        {
          continue;
        }
        for (vtkIdType v = 0; v < array->GetNumberOfValues(); ++v)
        {
          EXPECT_TRUE(std::isfinite(array->GetComponent(v / array->GetNumberOfComponents(),
            static_cast<int>(v % array->GetNumberOfComponents()))))
            << array->GetName() << " origin " << origin << " depth " << depth;
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
TEST(LIC, CellVectorFieldOfTheSampledSurfaceIsFound)
{
  // The square's triangles carry the field as active cell vectors, no point vectors:
  // the sampler makes them the samples' active vectors, which vtkOFBLIC finds.
  vtkSmartPointer<vtkPolyData> mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(MakeSquare());
  mesh->GetPointData()->Initialize();
  vtkNew<vtkFloatArray> flow;
  flow->SetName("CellFlow");
  flow->SetNumberOfComponents(3);
  const double axis[3] = { 0.0, 0.0, 1.0 };
  const VectorField rotation = RotationField(axis);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    double bounds[6], centre[3], v[3];
    mesh->GetCellBounds(c, bounds);
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    }
    rotation(centre, v);
    flow->InsertNextTuple(v);
  }
  mesh->GetCellData()->SetVectors(flow);
  vtkSmartPointer<vtkOFB> ofb = Build(mesh, 256);
  ASSERT_GT(ofb->GetNumberOfSamples(), 50000);
  ASSERT_NE(ofb->GetSampleData()->GetVectors(), nullptr);
  EXPECT_STREQ(ofb->GetSampleData()->GetVectors()->GetName(), "CellFlow");

  vtkNew<vtkOFBLIC> lic;
  vtkNew<MessageObserver> messages;
  messages->Watch(lic);
  vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
  EXPECT_EQ(messages->Errors.find("No vector field"), std::string::npos) << messages->Errors;
  EXPECT_EQ(messages->Errors, "");
  ASSERT_EQ(out->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  const float* values = LICValues(out);
  ASSERT_NE(values, nullptr);
  const auto range = std::minmax_element(values, values + out->GetNumberOfSamples());
  EXPECT_LT(*range.first + 0.1f, *range.second) << "the LIC is constant";
}
