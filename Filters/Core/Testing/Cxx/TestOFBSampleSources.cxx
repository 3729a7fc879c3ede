// Attribute-only re-sampling (vtkOFBSampler::StructureReuse): an update whose input
// has the geometry of the last build keeps its structure and gives the samples the
// same arrays as a full build; a changed geometry, resolution or setting is built.
#include "vtkOFBTestUtilities.h"
#include "vtkOFBTurningRotationSource.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

using namespace vtkofbtest;

namespace
{
/// The bunny with a point vector field, a point scalar and a cell array that depend on `t`.
vtkSmartPointer<vtkPolyData> WithArrays(vtkPolyData* mesh, double t, bool newPoints)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  if (newPoints)
  {
    // New arrays of the same content, as a reader gives at each time step.
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->DeepCopy(mesh->GetPoints());
    out->SetPoints(points);
  }
  out->GetPointData()->Initialize();
  out->GetCellData()->Initialize();
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("Velocity");
  vectors->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> scalar;
  scalar->SetName("Pressure");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    vectors->InsertNextTuple3(std::sin(20 * x[1] + t), std::cos(30 * x[2] - t), x[0] * t);
    scalar->InsertNextValue(std::cos(40 * x[0] + 3 * t));
  }
  vtkNew<vtkIntArray> cells;
  cells->SetName("Region");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    cells->InsertNextValue(static_cast<int>((c * 7 + static_cast<vtkIdType>(10 * t)) % 13));
  }
  out->GetPointData()->SetVectors(vectors);
  out->GetPointData()->AddArray(scalar);
  out->GetCellData()->AddArray(cells);
  return out;
}

/// A full build of `mesh` at `resolution` (no reuse).
vtkSmartPointer<vtkOFB> FullBuild(vtkPolyData* mesh, int resolution)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetStructureReuseToOff();
  sampler->SetResolution(resolution);
  sampler->SetInputData(mesh);
  sampler->Update();
  auto ofb = vtkSmartPointer<vtkOFB>::New();
  ofb->ShallowCopy(sampler->GetOutput());
  return ofb;
}

/// Every value of every sample array of `a` equals that of `b`, bit for bit (and the
/// structure too).
void ExpectSameSamples(vtkOFB* a, vtkOFB* b)
{
  ASSERT_EQ(a->GetNumberOfSamples(), b->GetNumberOfSamples());
  ASSERT_GT(a->GetNumberOfSamples(), 0);
  for (vtkIdType i = 0; i < a->GetNumberOfSamples(); ++i)
  {
    ASSERT_EQ(a->GetDepths()->GetValue(i), b->GetDepths()->GetValue(i));
  }
  vtkPointData* pa = a->GetSampleData();
  vtkPointData* pb = b->GetSampleData();
  ASSERT_EQ(pa->GetNumberOfArrays(), pb->GetNumberOfArrays());
  for (int k = 0; k < pb->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* expected = pb->GetArray(k);
    vtkDataArray* got = pa->GetArray(expected->GetName());
    ASSERT_NE(got, nullptr) << expected->GetName();
    ASSERT_EQ(got->GetNumberOfValues(), expected->GetNumberOfValues()) << expected->GetName();
    vtkIdType different = 0;
    for (vtkIdType v = 0; v < got->GetNumberOfValues(); ++v)
    {
      const double e = expected->GetComponent(v / expected->GetNumberOfComponents(),
        static_cast<int>(v % expected->GetNumberOfComponents()));
      const double g = got->GetComponent(
        v / got->GetNumberOfComponents(), static_cast<int>(v % got->GetNumberOfComponents()));
      different += std::memcmp(&e, &g, sizeof(double)) != 0 ? 1 : 0;
    }
    EXPECT_EQ(different, 0) << expected->GetName();
  }
  EXPECT_NE(pa->GetVectors(), nullptr);
  // The same arrays in the same roles (active scalars, vectors, texture coordinates).
  auto name = [](vtkDataArray* array)
  { return std::string(array && array->GetName() ? array->GetName() : "(none)"); };
  EXPECT_EQ(name(pa->GetScalars()), name(pb->GetScalars()));
  EXPECT_EQ(name(pa->GetVectors()), name(pb->GetVectors()));
  EXPECT_EQ(name(pa->GetTCoords()), name(pb->GetTCoords()));
}

/// `mesh` with arrays of every kind the re-sampling has a loop for, depending on `t`.
vtkSmartPointer<vtkPolyData> WithEveryKind(vtkPolyData* mesh, double t)
{
  vtkSmartPointer<vtkPolyData> out = WithArrays(mesh, t, false);
  const vtkIdType n = out->GetNumberOfPoints();
  vtkNew<vtkUnsignedCharArray> colors; // input colours: the paint interpolated
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> temperature; // one float component
  temperature->SetName("Temperature");
  vtkNew<vtkFloatArray> flow; // two components
  flow->SetName("Flow2");
  flow->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> label; // integers, rounded
  label->SetName("Label");
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double s = std::sin(25 * x[0] + t), c = std::cos(17 * x[1] - 2 * t);
    colors->InsertNextTuple3(
      std::floor(127.5 + 127.5 * s), std::floor(127.5 + 127.5 * c), static_cast<double>(i % 256));
    temperature->InsertNextValue(static_cast<float>(300.0 + 50.0 * s * c));
    flow->InsertNextTuple2(s, c);
    label->InsertNextValue(static_cast<int>(1000 * s));
  }
  out->GetPointData()->SetScalars(colors);
  out->GetPointData()->AddArray(temperature);
  out->GetPointData()->AddArray(flow);
  out->GetPointData()->AddArray(label);
  vtkNew<vtkDoubleArray> cellScalars; // active cell scalars: the samples' active scalars
  cellScalars->SetName("CellValue");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    cellScalars->InsertNextValue(std::sin(0.01 * static_cast<double>(c) + t));
  }
  out->GetCellData()->SetScalars(cellScalars);
  return out;
}
}

TEST(OFBSampleSources, NewArraysOnTheSameGeometryAreResampled)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetStructureReuseToAlways();
  sampler->SetResolution(256);
  sampler->SetInputData(WithArrays(bunny, 0.0, true));
  sampler->Update();
  EXPECT_FALSE(sampler->GetLastUpdateResampled());
  const vtkMTimeType structure = sampler->GetOutput()->GetStructureMTime();

  for (int step = 1; step <= 3; ++step)
  {
    // New point arrays of the same content (content hash), then the same polydata
    // with its arrays changed in place (arrays and times).
    vtkSmartPointer<vtkPolyData> input = WithArrays(bunny, 0.5 * step, step != 3);
    sampler->SetInputData(input);
    sampler->Update();
    EXPECT_TRUE(sampler->GetLastUpdateResampled()) << "step " << step;
    EXPECT_EQ(sampler->GetOutput()->GetStructureMTime(), structure) << "step " << step;
    ExpectSameSamples(sampler->GetOutput(), FullBuild(input, 256));
  }
  // The same polydata, its vector field changed in place: the arrays and times of
  // the geometry are those of the last build.
  vtkDataArray* velocity = sampler->GetInputDataObject(0, 0)
    ? vtkPolyData::SafeDownCast(sampler->GetInputDataObject(0, 0))->GetPointData()->GetVectors()
    : nullptr;
  ASSERT_NE(velocity, nullptr);
  for (vtkIdType i = 0; i < velocity->GetNumberOfTuples(); ++i)
  {
    velocity->SetTuple3(i, 1.0, -2.0, 0.5);
  }
  velocity->Modified();
  sampler->Update();
  EXPECT_TRUE(sampler->GetLastUpdateResampled());
  ExpectSameSamples(sampler->GetOutput(),
    FullBuild(vtkPolyData::SafeDownCast(sampler->GetInputDataObject(0, 0)), 256));
}

TEST(OFBSampleSources, EveryKindOfArrayIsResampledBitForBit)
{
  // Input colours, float, two-component, integer and cell arrays, active cell
  // scalars, and vectors projected or not: each as a full build gives it.
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  for (const bool project : { true, false })
  {
    vtkNew<vtkOFBSampler> sampler;
    sampler->SetStructureReuseToAlways();
    sampler->SetProjectVectors(project);
    sampler->SetResolution(200);
    sampler->SetInputData(WithEveryKind(bunny, 0.0));
    sampler->Update();
    for (int step = 1; step <= 2; ++step)
    {
      vtkSmartPointer<vtkPolyData> input = WithEveryKind(bunny, 0.7 * step);
      sampler->SetInputData(input);
      sampler->Update();
      EXPECT_TRUE(sampler->GetLastUpdateResampled());
      vtkNew<vtkOFBSampler> full;
      full->SetStructureReuseToOff();
      full->SetProjectVectors(project);
      full->SetResolution(200);
      full->SetInputData(input);
      full->Update();
      ExpectSameSamples(sampler->GetOutput(), full->GetOutput());
      // The paint comes from the input colours (not the uniform default colour).
      double range[2];
      sampler->GetOutput()
        ->GetSampleData()
        ->GetArray(vtkOFB::ColorsArrayName())
        ->GetRange(range, 0);
      EXPECT_GT(range[1] - range[0], 100.0);
    }
  }
}

TEST(OFBSampleSources, ChangedGeometryOrSettingIsBuilt)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetStructureReuseToAlways();
  sampler->SetResolution(128);
  sampler->SetInputData(WithArrays(bunny, 0.0, true));
  sampler->Update();

  // One point moved (new arrays, same size): a full build.
  vtkSmartPointer<vtkPolyData> moved = WithArrays(bunny, 1.0, true);
  double x[3];
  moved->GetPoint(10, x);
  x[0] += 1e-3;
  moved->GetPoints()->SetPoint(10, x);
  sampler->SetInputData(moved);
  sampler->Update();
  EXPECT_FALSE(sampler->GetLastUpdateResampled());
  ExpectSameSamples(sampler->GetOutput(), FullBuild(moved, 128));

  // The same geometry again: re-sampled; another resolution: built.
  sampler->SetInputData(WithArrays(moved, 2.0, true));
  sampler->Update();
  EXPECT_TRUE(sampler->GetLastUpdateResampled());
  sampler->SetResolution(130);
  sampler->Update();
  EXPECT_FALSE(sampler->GetLastUpdateResampled());

  // Off: never re-sampled.
  sampler->SetStructureReuseToOff();
  sampler->SetInputData(WithArrays(moved, 3.0, true));
  sampler->Update();
  EXPECT_FALSE(sampler->GetLastUpdateResampled());
}

TEST(OFBSampleSources, TimeSeriesReuseTheStructure)
{
  // The default (STRUCTURE_REUSE_TIME_SERIES): a time-aware input is re-sampled from
  // its second step on; data set directly (no time steps) is always built.
  vtkNew<TurningRotationSource> source;
  source->Mesh = MakeSphere(1.0, 48);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetResolution(128);
  sampler->SetInputConnection(source->GetOutputPort());
  sampler->UpdateTimeStep(0.0);
  EXPECT_FALSE(sampler->GetLastUpdateResampled());
  const vtkMTimeType structure = sampler->GetOutput()->GetStructureMTime();
  sampler->UpdateTimeStep(0.5);
  EXPECT_TRUE(sampler->GetLastUpdateResampled());
  EXPECT_EQ(sampler->GetOutput()->GetStructureMTime(), structure);
  EXPECT_DOUBLE_EQ(
    sampler->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), 0.5);

  vtkNew<vtkOFBSampler> direct;
  direct->SetResolution(128);
  direct->SetInputData(WithArrays(source->Mesh, 0.0, false));
  direct->Update();
  direct->SetInputData(WithArrays(source->Mesh, 1.0, false));
  direct->Update();
  EXPECT_FALSE(direct->GetLastUpdateResampled());
}
