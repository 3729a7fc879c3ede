// vtkOFBInputChecks.h: cells naming points that do not exist (past the end, negative) in
// every kind of cell and both storages, inconsistent cell arrays, short arrays; and the
// sampler, which refuses such a surface with the helper's message.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkOFBInputChecks.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <gtest/gtest.h>

#include <string>

using namespace vtkofbtest;

namespace
{
/// Four points, a vertex, a line, a triangle and a strip, all valid.
vtkSmartPointer<vtkPolyData> EveryKind(bool storage64)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(1, 1, 0);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  auto cells = [&](vtkIdType n)
  {
    auto a = vtkSmartPointer<vtkCellArray>::New();
    if (storage64)
    {
      a->Use64BitStorage();
    }
    else
    {
      a->Use32BitStorage();
    }
    a->InsertNextCell(n, ids);
    return a;
  };
  data->SetVerts(cells(1));
  data->SetLines(cells(2));
  data->SetPolys(cells(3));
  data->SetStrips(cells(4));
  return data;
}

std::string CheckIds(vtkPolyData* data)
{
  std::string error;
  const bool valid = vtkOFBCheckCellPointIds(data, error);
  EXPECT_EQ(valid, error.empty());
  return error;
}
}

//------------------------------------------------------------------------------
TEST(InputChecks, ValidCellsPass)
{
  for (bool storage64 : { false, true })
  {
    EXPECT_EQ(CheckIds(EveryKind(storage64)), "");
  }
  EXPECT_EQ(CheckIds(vtkNew<vtkPolyData>()), "");
  std::string error;
  EXPECT_FALSE(vtkOFBCheckCellPointIds(nullptr, error));
}

//------------------------------------------------------------------------------
TEST(InputChecks, FirstBadIdIsNamedWithItsCell)
{
  for (bool storage64 : { false, true })
  {
    // The vertex is cell 0, the line 1, the triangle 2, the strip 3.
    vtkSmartPointer<vtkPolyData> data = EveryKind(storage64);
    data->GetPolys()->ReplaceCellAtId(0, { 0, 1, 4 });
    EXPECT_EQ(CheckIds(data), "polygon 0 (cell 2) names point id 4, not in [0, 4)");
    data->GetLines()->ReplaceCellAtId(0, { -1, 1 });
    EXPECT_EQ(CheckIds(data), "line 0 (cell 1) names point id -1, not in [0, 4)");
    data = EveryKind(storage64);
    vtkNew<vtkCellArray> strips;
    strips->InsertNextCell({ 0, 1, 2 });
    strips->InsertNextCell({ 0, 1, 2, 99999 });
    data->SetStrips(strips);
    EXPECT_EQ(CheckIds(data), "strip 1 (cell 4) names point id 99999, not in [0, 4)");
    data = EveryKind(storage64);
    data->GetVerts()->ReplaceCellAtId(0, { 4 });
    EXPECT_EQ(CheckIds(data), "vertex 0 (cell 0) names point id 4, not in [0, 4)");
  }
  // No points: any id is bad.
  vtkSmartPointer<vtkPolyData> data = EveryKind(true);
  data->SetPoints(vtkNew<vtkPoints>());
  EXPECT_EQ(CheckIds(data), "vertex 0 (cell 0) names point id 0, not in [0, 0)");
}

//------------------------------------------------------------------------------
TEST(InputChecks, InconsistentOffsetsAreRefused)
{
  // Offsets built by hand: decreasing, or not ending at the connectivity's size.
  vtkSmartPointer<vtkPolyData> data = EveryKind(true);
  for (const std::vector<vtkTypeInt64>& offsets : { std::vector<vtkTypeInt64>{ 0, 3, 2, 6 },
         std::vector<vtkTypeInt64>{ 0, 3, 7 },
         std::vector<vtkTypeInt64>{ 1, 3, 6 } })
  {
    vtkNew<vtkTypeInt64Array> o;
    for (vtkTypeInt64 v : offsets)
    {
      o->InsertNextValue(v);
    }
    vtkNew<vtkTypeInt64Array> c;
    for (vtkTypeInt64 v : { 0, 1, 2, 0, 2, 3 })
    {
      c->InsertNextValue(v);
    }
    vtkNew<vtkCellArray> polys;
    polys->SetData(o, c);
    data->SetPolys(polys);
    const std::string error = CheckIds(data);
    EXPECT_NE(error.find("polygon cell array is inconsistent"), std::string::npos) << error;
  }
}

//------------------------------------------------------------------------------
TEST(InputChecks, ArrayLengths)
{
  vtkNew<vtkFloatArray> a;
  a->SetName("Radius");
  a->SetNumberOfComponents(1);
  a->SetNumberOfTuples(2);
  std::string error;
  EXPECT_TRUE(vtkOFBCheckArrayLength(nullptr, 5, "points", error)); // absent: fine
  EXPECT_TRUE(vtkOFBCheckArrayLength(a, 2, "points", error));
  EXPECT_FALSE(vtkOFBCheckArrayLength(a, 3, "stroke points", error));
  EXPECT_EQ(error, "'Radius' has 2 tuples for 3 stroke points");
  EXPECT_FALSE(vtkOFBCheckArrayLength(a, 2, "points", error, 3));
  EXPECT_EQ(error, "'Radius' has 1 components, fewer than 3");

  vtkSmartPointer<vtkPolyData> data = EveryKind(true);
  EXPECT_TRUE(vtkOFBCheckAttributeArrays(data, error));
  vtkNew<vtkFloatArray> cellArray;
  cellArray->SetName("PerCell");
  cellArray->SetNumberOfTuples(3); // 4 cells
  data->GetCellData()->AddArray(cellArray);
  EXPECT_FALSE(vtkOFBCheckAttributeArrays(data, error));
  EXPECT_EQ(error, "the cell array 'PerCell' has 3 tuples for 4 cells");
  data->GetPointData()->AddArray(a);
  EXPECT_FALSE(vtkOFBCheckAttributeArrays(data, error));
  EXPECT_EQ(error, "the point array 'Radius' has 2 tuples for 4 points");
}

//------------------------------------------------------------------------------
TEST(InputChecks, SamplerRefusesBadIdsWithTheHelpersMessage)
{
  vtkSmartPointer<vtkPolyData> plane = MakeTexturedPlane(4);
  for (vtkIdType badId : { vtkIdType(25), vtkIdType(99999), vtkIdType(-1) })
  {
    vtkNew<vtkOFBSampler> sampler;
    vtkNew<MessageObserver> o;
    o->Watch(sampler);
    sampler->SetInputData(WithBadPointId(plane, badId));
    sampler->SetResolution(32);
    sampler->Update();
    EXPECT_NE(o->Errors.find("The input surface is invalid: polygon 16 (cell 16) names point id " +
                std::to_string(badId) + ", not in [0, 25)"),
      std::string::npos)
      << o->Errors;
    EXPECT_EQ(sampler->GetOutput()->GetNumberOfSamples(), 0);
  }
}
