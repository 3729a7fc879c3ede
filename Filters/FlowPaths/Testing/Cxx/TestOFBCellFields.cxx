// Cell fields of the mesh downstream of the sampler, with no extra step: vtkOFBLIC,
// vtkOFBMapToColors and vtkOFBParticleAdvector given the mesh's cell array by name (with a
// cell association), and NaN in a cell field.
#include "vtkOFBLICTestHelpers.h"
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vtkofbtest;

namespace
{
const double ZAxis[3] = { 0.0, 0.0, 1.0 };

/**
 * The sphere with only cell fields: "Wind" (the rotation about z at the cell centre, not
 * active) and "Pressure" (z of the cell centre); `nanCells` cells (every 97th) hold NaN.
 */
vtkSmartPointer<vtkPolyData> CellFieldSphere(bool nanCells)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 48);
  vtkNew<vtkDoubleArray> wind;
  wind->SetName("Wind");
  wind->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("Pressure");
  const VectorField rotation = RotationField(ZAxis);
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    double centre[3];
    CellCentre(sphere, c, centre);
    double v[3];
    rotation(centre, v);
    if (nanCells && c % 97 == 0)
    {
      v[0] = v[1] = v[2] = vtkMath::Nan();
    }
    wind->InsertNextTuple(v);
    pressure->InsertNextValue(nanCells && c % 97 == 0 ? vtkMath::Nan() : centre[2]);
  }
  sphere->GetCellData()->AddArray(wind);
  sphere->GetCellData()->AddArray(pressure);
  return sphere;
}

vtkSmartPointer<vtkOFB> Sample(vtkPolyData* mesh)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetResolution(96);
  sampler->Update();
  vtkSmartPointer<vtkOFB> ofb = sampler->GetOutput();
  return ofb;
}

vtkSmartPointer<vtkOFB> RunLIC(vtkOFB* ofb, MessageObserver* messages)
{
  vtkNew<vtkOFBLIC> lic;
  messages->Watch(lic);
  lic->SetInputData(ofb);
  // The mesh's cell array, by name, with a cell association.
  lic->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Wind");
  lic->Update();
  vtkSmartPointer<vtkOFB> out = vtkSmartPointer<vtkOFB>::New();
  out->ShallowCopy(lic->GetOutput());
  return out;
}
}

TEST(CellFields, LICTakesTheSampleArrayOfTheMeshsCellArray)
{
  vtkSmartPointer<vtkOFB> ofb = Sample(CellFieldSphere(false));
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> out = RunLIC(ofb, messages);
  EXPECT_EQ(messages->Errors, "");
  auto* lic = vtkFloatArray::SafeDownCast(out->GetSampleData()->GetArray("LIC"));
  ASSERT_NE(lic, nullptr);
  ASSERT_EQ(lic->GetNumberOfTuples(), ofb->GetNumberOfSamples());
  // Streaks along the rotation: the LIC correlates more along than across.
  const StreakMeasure s = SphereStreaks(out, lic->GetPointer(0), ZAxis, false);
  EXPECT_GT(s.Along, s.Across + 0.2) << s.Along << " " << s.Across;
}

TEST(CellFields, MapToColorsColoursByTheMeshsCellArray)
{
  vtkSmartPointer<vtkOFB> ofb = Sample(CellFieldSphere(true));
  vtkNew<vtkLookupTable> lut;
  lut->SetNanColor(1.0, 0.0, 1.0, 1.0);
  lut->Build();
  vtkNew<vtkOFBMapToColors> colors;
  colors->SetInputData(ofb);
  colors->GetColoring()->SetColorSourceToScalars();
  colors->GetColoring()->SetScalarArrayName("Pressure");
  colors->GetColoring()->SetScalarRange(-1.0, 1.0);
  colors->GetColoring()->SetLookupTable(lut);
  vtkNew<MessageObserver> messages;
  messages->Watch(colors);
  colors->Update();
  EXPECT_EQ(messages->Errors, "");
  auto* rgba = vtkUnsignedCharArray::SafeDownCast(
    colors->GetOutput()->GetSampleData()->GetArray(colors->GetOutputArrayName()));
  vtkDataArray* pressure = ofb->GetSampleData()->GetArray("Pressure");
  ASSERT_TRUE(rgba && pressure);
  // NaN cells show the NaN colour, and only they.
  vtkIdType nan = 0, wrong = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const bool isNaN = std::isnan(pressure->GetTuple1(i));
    const bool magenta = rgba->GetValue(4 * i) == 255 && rgba->GetValue(4 * i + 1) == 0 &&
      rgba->GetValue(4 * i + 2) == 255;
    nan += isNaN;
    wrong += isNaN != magenta;
  }
  EXPECT_GT(nan, 0);
  EXPECT_EQ(wrong, 0);
}

TEST(CellFields, NaNInACellVectorFieldIsMaskedByTheLICAndRefusedByParticles)
{
  vtkSmartPointer<vtkPolyData> sphere = CellFieldSphere(true);
  vtkSmartPointer<vtkOFB> ofb = Sample(sphere);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> out = RunLIC(ofb, messages);
  EXPECT_EQ(messages->Errors, "");
  auto* lic = vtkFloatArray::SafeDownCast(out->GetSampleData()->GetArray("LIC"));
  auto* mask = out->GetSampleData()->GetArray("LICMask");
  vtkDataArray* wind = ofb->GetSampleData()->GetArray("Wind");
  ASSERT_TRUE(lic && mask && wind);
  vtkIdType nan = 0, unmasked = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfSamples(); ++i)
  {
    ASSERT_TRUE(std::isfinite(lic->GetValue(i))) << "sample " << i;
    if (std::isnan(wind->GetComponent(i, 0)))
    {
      ++nan;
      unmasked += mask->GetTuple1(i) == 0.0;
    }
  }
  EXPECT_GT(nan, 0);
  EXPECT_EQ(unmasked, 0);

  // The advector reads the field on the mesh (cells averaged to points): a clear error.
  vtkNew<vtkOFBParticleAdvector> advector;
  messages->Clear();
  messages->Watch(advector);
  advector->SetInputData(sphere);
  advector->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Wind");
  advector->SetNumberOfParticles(10);
  advector->Update();
  EXPECT_NE(messages->Errors.find("non-finite"), std::string::npos) << messages->Errors;
  EXPECT_EQ(advector->GetParticles()->GetNumberOfPoints(), 0);
}

TEST(CellFields, ParticlesTakeTheMeshsCellArrayByName)
{
  vtkSmartPointer<vtkPolyData> sphere = CellFieldSphere(false);
  vtkNew<vtkOFBParticleAdvector> advector;
  vtkNew<MessageObserver> messages;
  messages->Watch(advector);
  advector->SetInputData(sphere);
  advector->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Wind");
  advector->SetNumberOfParticles(20);
  advector->SetStepsPerUpdate(50);
  advector->Update();
  vtkNew<vtkPoints> start;
  start->DeepCopy(advector->GetParticles()->GetPoints());
  advector->Step();
  EXPECT_EQ(messages->Errors, "");
  vtkPoints* points = advector->GetParticles()->GetPoints();
  ASSERT_NE(points, nullptr);
  ASSERT_EQ(points->GetNumberOfPoints(), 20);
  // They moved along the rotation about z: their heights stay, their longitudes change.
  const double cell = advector->GetCellSize();
  int moved = 0;
  for (vtkIdType i = 0; i < 20; ++i)
  {
    double a[3], b[3];
    start->GetPoint(i, a);
    points->GetPoint(i, b);
    EXPECT_NEAR(a[2], b[2], 0.5 * cell) << "particle " << i;
    moved += std::sqrt(vtkMath::Distance2BetweenPoints(a, b)) > 2.0 * cell;
  }
  EXPECT_GE(moved, 15);
}
