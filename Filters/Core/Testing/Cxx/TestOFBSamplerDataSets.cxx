// Any vtkDataSet as the sampler's input (through its outer surface), and cell arrays
// as sample arrays: a sample takes its triangle's input cell's value.
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace vtkofbtest;

namespace
{
/// Quads of the plane: 4 x 4 over [-1, 1]^2 at z = 0; cell i covers column i % 4, row i / 4.
constexpr int PlaneResolution = 4;

/// The value of cell c of the plane's scalar "CellValue", distinct per cell.
double CellValue(vtkIdType c)
{
  return 10.0 + 3.0 * static_cast<double>(c);
}

/// The cell vector "CellVectors" of cell c of the plane (in the plane, distinct per cell).
void CellVector(vtkIdType c, double v[3])
{
  v[0] = 1.0 + static_cast<double>(c % PlaneResolution);
  v[1] = -2.0 + static_cast<double>(c / PlaneResolution);
  v[2] = 0.0;
}

/**
 * A plane of quads with a cell scalar "CellValue" (active cell scalars) and a cell
 * vector "CellVectors" (active cell vectors), and no point arrays but the plane's own.
 */
vtkSmartPointer<vtkPolyData> MakeCellDataPlane()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(PlaneResolution, PlaneResolution);
  plane->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(plane->GetOutput());
  mesh->GetPointData()->Initialize();
  vtkNew<vtkDoubleArray> values;
  values->SetName("CellValue");
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("CellVectors");
  vectors->SetNumberOfComponents(3);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    double v[3];
    CellVector(c, v);
    values->InsertNextValue(CellValue(c));
    vectors->InsertNextTuple(v);
  }
  mesh->GetCellData()->SetScalars(values);
  mesh->GetCellData()->SetVectors(vectors);
  return mesh;
}

/**
 * The plane's cells whose square contains x (within a hundredth of a cell, so
 * that a sample on a shared edge belongs to both).
 */
std::vector<vtkIdType> CellsAt(const double x[3])
{
  std::vector<vtkIdType> cells;
  const double size = 2.0 / PlaneResolution;
  const double eps = 0.01 * size;
  for (vtkIdType c = 0; c < PlaneResolution * PlaneResolution; ++c)
  {
    const double x0 = -1.0 + size * static_cast<double>(c % PlaneResolution);
    const double y0 = -1.0 + size * static_cast<double>(c / PlaneResolution);
    if (x[0] >= x0 - eps && x[0] <= x0 + size + eps && x[1] >= y0 - eps && x[1] <= y0 + size + eps)
    {
      cells.push_back(c);
    }
  }
  return cells;
}

/// Check that every sample of `ofb` has the cell scalar and vector of a cell containing it.
void ExpectCellValuesAtSamples(vtkOFB* ofb)
{
  vtkPointData* sd = ofb->GetSampleData();
  vtkDataArray* values = sd->GetArray("CellValue");
  vtkDataArray* vectors = sd->GetArray("CellVectors");
  ASSERT_NE(values, nullptr);
  ASSERT_NE(vectors, nullptr);
  EXPECT_EQ(sd->GetVectors(), vectors); // the cell data's active vectors
  EXPECT_EQ(values->GetDataType(), VTK_DOUBLE);
  ASSERT_GT(ofb->GetNumberOfSamples(), 1000);
  vtkIdType bad = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3], v[3];
    ofb->GetSamplePosition(i, x);
    vectors->GetTuple(i, v);
    bool found = false;
    for (const vtkIdType c : CellsAt(x))
    {
      double expected[3];
      CellVector(c, expected);
      found = found ||
        (values->GetTuple1(i) == CellValue(c) && std::fabs(v[0] - expected[0]) < 1e-5 &&
          std::fabs(v[1] - expected[1]) < 1e-5 && std::fabs(v[2]) < 1e-5);
    }
    bad += found ? 0 : 1;
  }
  EXPECT_EQ(bad, 0) << "samples whose values are not those of a cell containing them";
}

vtkSmartPointer<vtkOFB> Sample(vtkDataObject* input, int resolution, vtkOFBSampler* sampler)
{
  sampler->SetInputData(input);
  sampler->SetResolution(resolution);
  sampler->Update();
  auto ofb = vtkSmartPointer<vtkOFB>::New();
  ofb->ShallowCopy(sampler->GetOutput());
  return ofb;
}

vtkSmartPointer<vtkOFB> Sample(vtkDataObject* input, int resolution)
{
  vtkNew<vtkOFBSampler> sampler;
  return Sample(input, resolution, sampler);
}

/// A box of nx x ny x nz voxels over [0, nx] x [0, ny] x [0, nz] as vtkImageData,
/// with a point array "PointX" (x) and a cell array "CellId".
vtkSmartPointer<vtkImageData> MakeImageBox(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx + 1, ny + 1, nz + 1);
  vtkNew<vtkFloatArray> px;
  px->SetName("PointX");
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    px->InsertNextValue(static_cast<float>(image->GetPoint(p)[0]));
  }
  vtkNew<vtkIntArray> ids;
  ids->SetName("CellId");
  for (vtkIdType c = 0; c < image->GetNumberOfCells(); ++c)
  {
    ids->InsertNextValue(static_cast<int>(c));
  }
  image->GetPointData()->AddArray(px);
  image->GetCellData()->AddArray(ids);
  return image;
}

/// The same box as a vtkUnstructuredGrid of hexahedra, built by hand.
vtkSmartPointer<vtkUnstructuredGrid> MakeHexBox(vtkImageData* image)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    points->InsertNextPoint(image->GetPoint(p));
  }
  grid->SetPoints(points);
  grid->Allocate(image->GetNumberOfCells());
  int dims[3];
  image->GetDimensions(dims);
  const auto id = [&](int i, int j, int k)
  { return static_cast<vtkIdType>(i + dims[0] * (j + dims[1] * k)); };
  for (int k = 0; k + 1 < dims[2]; ++k)
  {
    for (int j = 0; j + 1 < dims[1]; ++j)
    {
      for (int i = 0; i + 1 < dims[0]; ++i)
      {
        const vtkIdType hex[8] = { id(i, j, k),
          id(i + 1, j, k),
          id(i + 1, j + 1, k),
          id(i, j + 1, k),
          id(i, j, k + 1),
          id(i + 1, j, k + 1),
          id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
    }
  }
  grid->GetPointData()->ShallowCopy(image->GetPointData());
  grid->GetCellData()->ShallowCopy(image->GetCellData());
  return grid;
}

vtkSmartPointer<vtkPolyData> ExtractSurface(vtkDataSet* input)
{
  vtkNew<vtkDataSetSurfaceFilter> extract;
  extract->SetInputData(input);
  extract->Update();
  vtkSmartPointer<vtkPolyData> surface = extract->GetOutput();
  return surface;
}
}

//------------------------------------------------------------------------------
TEST(SamplerDataSets, UnstructuredGridIsSampledThroughItsSurface)
{
  vtkSmartPointer<vtkImageData> image = MakeImageBox(3, 2, 2);
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeHexBox(image);
  vtkNew<MessageObserver> messages;
  vtkNew<vtkOFBSampler> sampler;
  messages->Watch(sampler);
  vtkSmartPointer<vtkOFB> ofb = Sample(grid, 64, sampler);
  EXPECT_EQ(messages->Errors, "");
  vtkSmartPointer<vtkOFB> reference = Sample(ExtractSurface(grid), 64);
  ASSERT_GT(ofb->GetNumberOfSamples(), 1000);
  EXPECT_EQ(ofb->GetNumberOfSamples(), reference->GetNumberOfSamples());
  for (const char* name : { "PointX", "CellId" })
  {
    vtkDataArray* a = ofb->GetSampleData()->GetArray(name);
    vtkDataArray* b = reference->GetSampleData()->GetArray(name);
    ASSERT_NE(a, nullptr) << name;
    ASSERT_NE(b, nullptr) << name;
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      ASSERT_EQ(a->GetTuple1(i), b->GetTuple1(i)) << name << ", sample " << i;
    }
  }
  // The cell id of each sample is one of a hexahedron touching it.
  vtkDataArray* cellIds = ofb->GetSampleData()->GetArray("CellId");
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const vtkIdType c = static_cast<vtkIdType>(cellIds->GetTuple1(i));
    double bounds[6];
    grid->GetCellBounds(c, bounds);
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_GE(x[k], bounds[2 * k] - 0.05) << "sample " << i;
      ASSERT_LE(x[k], bounds[2 * k + 1] + 0.05) << "sample " << i;
    }
  }
}

//------------------------------------------------------------------------------
TEST(SamplerDataSets, ImageDataIsSampledThroughItsSurface)
{
  vtkSmartPointer<vtkImageData> image = MakeImageBox(3, 2, 2);
  vtkNew<MessageObserver> messages;
  vtkNew<vtkOFBSampler> sampler;
  messages->Watch(sampler);
  vtkSmartPointer<vtkOFB> ofb = Sample(image, 64, sampler);
  EXPECT_EQ(messages->Errors, "");
  EXPECT_EQ(ofb->GetNumberOfSamples(), Sample(ExtractSurface(image), 64)->GetNumberOfSamples());
  EXPECT_GT(ofb->GetNumberOfSamples(), 1000);
  EXPECT_NE(ofb->GetSampleData()->GetArray("CellId"), nullptr);
  EXPECT_GT(sampler->EstimateMemory(image), 0.0);
}

//------------------------------------------------------------------------------
TEST(SamplerDataSets, QuadsCellArraysGiveEachSampleItsCellsValue)
{
  vtkSmartPointer<vtkPolyData> mesh = MakeCellDataPlane();
  ExpectCellValuesAtSamples(Sample(mesh, 128));
  // The same through the all-triangles path (no triangulation by the sampler).
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(mesh);
  triangulate->Update();
  ExpectCellValuesAtSamples(Sample(triangulate->GetOutput(), 128));
}

//------------------------------------------------------------------------------
TEST(SamplerDataSets, PassCellArraysOffLeavesThemOut)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->PassCellArraysOff();
  vtkSmartPointer<vtkOFB> ofb = Sample(MakeCellDataPlane(), 64, sampler);
  EXPECT_GT(ofb->GetNumberOfSamples(), 0);
  EXPECT_EQ(ofb->GetSampleData()->GetArray("CellValue"), nullptr);
  EXPECT_EQ(ofb->GetSampleData()->GetVectors(), nullptr);
}

//------------------------------------------------------------------------------
TEST(SamplerDataSets, ArrayPrecedenceChoosesPointOrCellArrayOfTheSameName)
{
  vtkSmartPointer<vtkPolyData> mesh = MakeCellDataPlane();
  // A point array "CellValue" too: 1000 plus x, in [999, 1001].
  vtkNew<vtkFloatArray> pointValues;
  pointValues->SetName("CellValue");
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    pointValues->InsertNextValue(static_cast<float>(1000.0 + mesh->GetPoint(p)[0]));
  }
  mesh->GetPointData()->AddArray(pointValues);

  vtkNew<vtkOFBSampler> sampler;
  EXPECT_EQ(sampler->GetArrayPrecedence(), vtkOFBSampler::POINT_ARRAYS_FIRST);
  vtkSmartPointer<vtkOFB> ofb = Sample(mesh, 64, sampler);
  vtkDataArray* values = ofb->GetSampleData()->GetArray("CellValue");
  ASSERT_NE(values, nullptr);
  EXPECT_EQ(values->GetDataType(), VTK_FLOAT);
  double range[2];
  values->GetRange(range);
  EXPECT_GE(range[0], 999.0 - 1e-3);
  EXPECT_LE(range[1], 1001.0 + 1e-3);

  sampler->SetArrayPrecedenceToCellArraysFirst();
  ofb = Sample(mesh, 64, sampler);
  values = ofb->GetSampleData()->GetArray("CellValue");
  ASSERT_NE(values, nullptr);
  EXPECT_EQ(values->GetDataType(), VTK_DOUBLE);
  values->GetRange(range);
  EXPECT_EQ(range[0], CellValue(0));
  EXPECT_EQ(range[1], CellValue(PlaneResolution * PlaneResolution - 1));
}
