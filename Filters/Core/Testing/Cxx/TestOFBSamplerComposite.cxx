// Composite datasets as one OFB (vtkOFBMergeBlocks, vtkOFBSampler): block indices,
// array union and fill, bad blocks, and cell scalars as the samples' active scalars.
#include "vtkOFBTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

using namespace vtkofbtest;

namespace
{
/// A unit square of 4 x 4 quads at z = 0 with its corner at (x0, y0).
vtkSmartPointer<vtkPolyData> Tile(double x0, double y0)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(x0, y0, 0.0);
  plane->SetPoint1(x0 + 1.0, y0, 0.0);
  plane->SetPoint2(x0, y0 + 1.0, 0.0);
  plane->SetResolution(4, 4);
  plane->Update();
  auto tile = vtkSmartPointer<vtkPolyData>::New();
  tile->DeepCopy(plane->GetOutput());
  tile->GetPointData()->Initialize();
  return tile;
}

/// A cell array `name` of `type` with value v on every cell of `mesh` (and active scalars).
void AddCellValue(vtkPolyData* mesh, const char* name, int type, double v, bool active = false)
{
  auto array = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(type));
  array->SetName(name);
  array->SetNumberOfTuples(mesh->GetNumberOfCells());
  array->FillComponent(0, v);
  mesh->GetCellData()->AddArray(array);
  if (active)
  {
    mesh->GetCellData()->SetActiveScalars(name);
  }
}

/// Two tiles side by side, [0, 2] x [0, 1], as blocks 0 and 1 of a multi-block.
vtkSmartPointer<vtkMultiBlockDataSet> TwoTiles()
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetBlock(0, Tile(0.0, 0.0));
  blocks->SetBlock(1, Tile(1.0, 0.0));
  return blocks;
}

vtkSmartPointer<vtkOFB> Sample(vtkDataObject* input, int resolution, MessageObserver* messages)
{
  vtkNew<vtkOFBSampler> sampler;
  if (messages)
  {
    messages->Watch(sampler);
  }
  sampler->SetInputData(input);
  sampler->SetResolution(resolution);
  sampler->Update();
  vtkSmartPointer<vtkOFB> ofb = sampler->GetOutput();
  return ofb;
}

/// The block index of each sample, and whether it matches the tile under the sample.
void ExpectTileIndices(vtkOFB* ofb, int left, int right)
{
  auto* index = vtkIntArray::SafeDownCast(ofb->GetSampleData()->GetArray("BlockIndex"));
  ASSERT_NE(index, nullptr);
  vtkIdType bad = 0;
  std::set<int> seen;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const int v = index->GetValue(i);
    seen.insert(v);
    const bool onBorder = std::fabs(x[0] - 1.0) < 1e-9;
    bad += !onBorder && v != (x[0] < 1.0 ? left : right);
  }
  EXPECT_EQ(bad, 0) << "samples whose block index is not their tile's";
  EXPECT_EQ(seen, (std::set<int>{ left, right }));
}
}

TEST(SamplerComposite, MultiBlockIsOneOFBWithTheFlatBlockIndex)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(blocks, 64, messages);
  EXPECT_EQ(messages->Errors, "");
  ASSERT_GT(ofb->GetNumberOfSamples(), 500);
  // One frame over both tiles: [0, 2] is the longest side.
  double b[6];
  ofb->GetBounds(b);
  EXPECT_LT(b[0], 0.0);
  EXPECT_GT(b[1], 2.0);
  // Blocks 0 and 1 of the root are flat indices 1 and 2.
  ExpectTileIndices(ofb, 1, 2);
  // The same samples as the two tiles as one surface.
  vtkNew<vtkOFBMergeBlocks> merge;
  merge->SetInputData(blocks);
  merge->Update();
  EXPECT_EQ(merge->GetOutput()->GetNumberOfPoints(), 25 + 20); // the shared edge merged
  EXPECT_EQ(
    ofb->GetNumberOfSamples(), Sample(merge->GetOutput(), 64, nullptr)->GetNumberOfSamples());
}

TEST(SamplerComposite, FlatIndicesFollowTheTreeWithEmptyNodes)
{
  // root 0 { 1: multi-block { 2: tile, 3: empty, 4: tile }, 5: tile }
  vtkNew<vtkMultiBlockDataSet> inner;
  inner->SetBlock(0, Tile(0.0, 0.0));
  inner->SetBlock(1, nullptr);
  inner->SetBlock(2, Tile(1.0, 0.0));
  vtkNew<vtkMultiBlockDataSet> root;
  root->SetBlock(0, inner);
  root->SetBlock(1, Tile(2.0, 0.0));
  std::map<unsigned int, vtkDataObject*> expected;
  auto iter = vtk::TakeSmartPointer(root->NewTreeIterator());
  iter->VisitOnlyLeavesOn();
  for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
  {
    expected[iter->GetCurrentFlatIndex()] = iter->GetCurrentDataObject();
  }
  EXPECT_EQ(expected.size(), 3u);
  vtkNew<vtkOFBMergeBlocks> merge;
  merge->SetInputData(root);
  merge->Update();
  auto* index = vtkIntArray::SafeDownCast(
    merge->GetOutput()->GetCellData()->GetArray(vtkOFBMergeBlocks::BlockIndexArrayName()));
  ASSERT_NE(index, nullptr);
  std::map<int, vtkIdType> cells;
  for (vtkIdType c = 0; c < index->GetNumberOfValues(); ++c)
  {
    ++cells[index->GetValue(c)];
  }
  ASSERT_EQ(cells.size(), 3u);
  for (const auto& entry : expected)
  {
    EXPECT_EQ(cells[static_cast<int>(entry.first)], 16) << "flat index " << entry.first;
  }
  EXPECT_EQ(cells.count(2) + cells.count(4) + cells.count(5), 3u);
}

TEST(SamplerComposite, PartitionedDataSetCollectionAndOtherDataSets)
{
  // An image block goes through its surface as any dataset does.
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 5, 1);
  image->SetSpacing(0.25, 0.25, 1.0);
  image->SetOrigin(1.0, 0.0, 0.0);
  vtkNew<vtkPartitionedDataSet> first;
  first->SetPartition(0, Tile(0.0, 0.0));
  vtkNew<vtkPartitionedDataSet> second;
  second->SetPartition(0, image);
  vtkNew<vtkPartitionedDataSetCollection> collection;
  collection->SetPartitionedDataSet(0, first);
  collection->SetPartitionedDataSet(1, second);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(collection, 64, messages);
  EXPECT_EQ(messages->Errors, "");
  // root 0 { 1: { 2: tile }, 3: { 4: image } }
  ExpectTileIndices(ofb, 2, 4);
}

TEST(SamplerComposite, ArraysMissingInABlockAreFilled)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  auto* left = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
  auto* right = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
  AddCellValue(left, "Pressure", VTK_DOUBLE, 5.0);
  AddCellValue(left, "Zone", VTK_INT, 7.0);
  AddCellValue(right, "Zone", VTK_FLOAT, 9.0); // converted to the first block's int
  vtkNew<vtkFloatArray> temperature;           // a point array of the right tile only
  temperature->SetName("Temperature");
  temperature->SetNumberOfTuples(right->GetNumberOfPoints());
  temperature->FillComponent(0, 300.0);
  right->GetPointData()->AddArray(temperature);

  vtkNew<vtkOFBMergeBlocks> merge;
  merge->SetInputData(blocks);
  merge->SetIntegerFillValue(-1.0);
  merge->Update();
  vtkPolyData* out = merge->GetOutput();
  auto* pressure = out->GetCellData()->GetArray("Pressure");
  auto* zone = out->GetCellData()->GetArray("Zone");
  auto* index = out->GetCellData()->GetArray("BlockIndex");
  ASSERT_TRUE(pressure && zone && index);
  EXPECT_EQ(zone->GetDataType(), VTK_INT);
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const bool isLeft = index->GetTuple1(c) == 1;
    EXPECT_EQ(zone->GetTuple1(c), isLeft ? 7.0 : 9.0);
    EXPECT_TRUE(isLeft ? pressure->GetTuple1(c) == 5.0 : std::isnan(pressure->GetTuple1(c)));
  }
  // The point array: 300 on the right tile's points, the shared edge included (the
  // left tile, first, lacks it), NaN on the others.
  auto* t = out->GetPointData()->GetArray("Temperature");
  ASSERT_NE(t, nullptr);
  vtkIdType nan = 0, set = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    nan += std::isnan(t->GetTuple1(p));
    set += t->GetTuple1(p) == 300.0;
  }
  EXPECT_EQ(nan, 20);
  EXPECT_EQ(set, 25);

  // Integer arrays missing in a block get IntegerFillValue (default 0).
  vtkSmartPointer<vtkMultiBlockDataSet> other = TwoTiles();
  AddCellValue(vtkPolyData::SafeDownCast(other->GetBlock(1)), "Zone", VTK_INT, 4.0);
  vtkSmartPointer<vtkOFB> ofb = Sample(other, 64, nullptr);
  auto* sampleZone = ofb->GetSampleData()->GetArray("Zone");
  auto* sampleIndex = ofb->GetSampleData()->GetArray("BlockIndex");
  ASSERT_TRUE(sampleZone && sampleIndex);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    ASSERT_EQ(sampleZone->GetTuple1(i), sampleIndex->GetTuple1(i) == 1 ? 0.0 : 4.0);
  }
}

TEST(SamplerComposite, ArrayOfTheWrongLengthIsFilledWithAWarning)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  auto* left = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
  AddCellValue(left, "Pressure", VTK_DOUBLE, 5.0);
  auto* right = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
  vtkNew<vtkDoubleArray> shortArray; // 3 tuples for 16 cells
  shortArray->SetName("Pressure");
  shortArray->SetNumberOfTuples(3);
  shortArray->FillComponent(0, 1.0);
  right->GetCellData()->AddArray(shortArray);
  vtkNew<vtkDoubleArray> longPoints; // 99 tuples for 25 points
  longPoints->SetName("Long");
  longPoints->SetNumberOfTuples(99);
  longPoints->FillComponent(0, 1.0);
  right->GetPointData()->AddArray(longPoints);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(blocks, 64, messages);
  EXPECT_EQ(messages->Errors, "");
  EXPECT_NE(messages->Warnings.find("Block 2: the cell array 'Pressure' has 3 tuples for 16 cells"),
    std::string::npos)
    << messages->Warnings;
  EXPECT_NE(messages->Warnings.find("Block 2: the point array 'Long' has 99 tuples for 25 points"),
    std::string::npos)
    << messages->Warnings;
  auto* pressure = ofb->GetSampleData()->GetArray("Pressure");
  auto* index = ofb->GetSampleData()->GetArray("BlockIndex");
  ASSERT_TRUE(pressure && index);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    ASSERT_TRUE(index->GetTuple1(i) == 1 ? pressure->GetTuple1(i) == 5.0
                                         : std::isnan(pressure->GetTuple1(i)));
  }
}

TEST(SamplerComposite, BlockThatIsNotADataSetIsLeftOutWithAWarning)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  vtkNew<vtkTable> table;
  blocks->SetBlock(2, table);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(blocks, 64, messages);
  EXPECT_EQ(messages->Errors, "");
  EXPECT_NE(
    messages->Warnings.find("Block 3 is a vtkTable, not a dataset: left out."), std::string::npos)
    << messages->Warnings;
  ExpectTileIndices(ofb, 1, 2);
}

TEST(SamplerComposite, EmptyBlocksAreLeftOutAndAllEmptyIsAnError)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  blocks->SetBlock(2, nullptr);
  vtkNew<vtkPolyData> empty;
  blocks->SetBlock(3, empty);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(blocks, 64, messages);
  EXPECT_EQ(messages->Errors, "");
  EXPECT_EQ(messages->Warnings, "");
  ExpectTileIndices(ofb, 1, 2);

  vtkNew<vtkMultiBlockDataSet> none;
  none->SetBlock(0, empty);
  none->SetBlock(1, nullptr);
  messages->Clear();
  ofb = Sample(none, 64, messages);
  EXPECT_EQ(ofb->GetNumberOfSamples(), 0);
  EXPECT_NE(messages->Errors.find("The input has no dataset block with cells"), std::string::npos)
    << messages->Errors;
  vtkNew<vtkMultiBlockDataSet> nothing;
  messages->Clear();
  ofb = Sample(nothing, 64, messages);
  EXPECT_EQ(ofb->GetNumberOfSamples(), 0);
  EXPECT_NE(messages->Errors, "");
}

TEST(SamplerComposite, BlockWithABadPointIdIsAnError)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  blocks->SetBlock(1, WithBadPointId(vtkPolyData::SafeDownCast(blocks->GetBlock(1)), 99999));
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(blocks, 64, messages);
  EXPECT_EQ(ofb->GetNumberOfSamples(), 0);
  EXPECT_NE(messages->Errors.find("Block 2 is invalid"), std::string::npos) << messages->Errors;
}

TEST(SamplerComposite, ActiveCellScalarsBecomeTheSamplesActiveScalars)
{
  vtkSmartPointer<vtkPolyData> tile = Tile(0.0, 0.0);
  AddCellValue(tile, "Pressure", VTK_DOUBLE, 2.5, true);
  vtkSmartPointer<vtkOFB> ofb = Sample(tile, 32, nullptr);
  vtkPointData* sd = ofb->GetSampleData();
  ASSERT_NE(sd->GetScalars(), nullptr);
  EXPECT_STREQ(sd->GetScalars()->GetName(), "Pressure");
  // The paint stays, by name.
  auto* colors = vtkUnsignedCharArray::SafeDownCast(sd->GetArray("Colors"));
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->GetNumberOfTuples(), ofb->GetNumberOfSamples());

  // With active point scalars, the paint stays the active scalars.
  vtkNew<vtkFloatArray> pointScalars;
  pointScalars->SetName("Height");
  pointScalars->SetNumberOfTuples(tile->GetNumberOfPoints());
  pointScalars->FillComponent(0, 1.0);
  tile->GetPointData()->SetScalars(pointScalars);
  ofb = Sample(tile, 32, nullptr);
  ASSERT_NE(ofb->GetSampleData()->GetScalars(), nullptr);
  EXPECT_STREQ(ofb->GetSampleData()->GetScalars()->GetName(), "Colors");
  EXPECT_NE(ofb->GetSampleData()->GetArray("Pressure"), nullptr);

  // Cell colours (RGB bytes) as the active cell scalars leave the paint active.
  vtkSmartPointer<vtkPolyData> coloured = Tile(0.0, 0.0);
  vtkNew<vtkUnsignedCharArray> cellColors;
  cellColors->SetName("FaceColors");
  cellColors->SetNumberOfComponents(3);
  cellColors->SetNumberOfTuples(coloured->GetNumberOfCells());
  cellColors->FillComponent(0, 200.0);
  coloured->GetCellData()->SetScalars(cellColors);
  ofb = Sample(coloured, 32, nullptr);
  ASSERT_NE(ofb->GetSampleData()->GetScalars(), nullptr);
  EXPECT_STREQ(ofb->GetSampleData()->GetScalars()->GetName(), "Colors");
  EXPECT_NE(ofb->GetSampleData()->GetArray("FaceColors"), nullptr);

  // Through a composite input as well.
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  AddCellValue(vtkPolyData::SafeDownCast(blocks->GetBlock(0)), "Pressure", VTK_DOUBLE, 1.0, true);
  ofb = Sample(blocks, 32, nullptr);
  ASSERT_NE(ofb->GetSampleData()->GetScalars(), nullptr);
  EXPECT_STREQ(ofb->GetSampleData()->GetScalars()->GetName(), "Pressure");
}

TEST(SamplerComposite, NaNInACellFieldIsNaNInItsSamples)
{
  vtkSmartPointer<vtkPolyData> tile = Tile(0.0, 0.0);
  vtkNew<vtkDoubleArray> values;
  values->SetName("Pressure");
  values->SetNumberOfTuples(tile->GetNumberOfCells());
  for (vtkIdType c = 0; c < tile->GetNumberOfCells(); ++c)
  {
    values->SetValue(c, c == 5 ? vtkMath::Nan() : 1.0);
  }
  tile->GetCellData()->AddArray(values);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(tile, 32, messages);
  EXPECT_EQ(messages->Errors, "");
  auto* pressure = ofb->GetSampleData()->GetArray("Pressure");
  ASSERT_NE(pressure, nullptr);
  vtkIdType nan = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const double v = pressure->GetTuple1(i);
    nan += std::isnan(v);
    ASSERT_TRUE(std::isnan(v) || v == 1.0);
  }
  // Cell 5 covers a sixteenth of the tile.
  EXPECT_GT(nan, ofb->GetNumberOfSamples() / 32);
  EXPECT_LT(nan, ofb->GetNumberOfSamples() / 8);
}

TEST(SamplerComposite, NormalsOfSomeBlocksOnlyAreNotTheNormals)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = TwoTiles();
  auto* left = vtkPolyData::SafeDownCast(blocks->GetBlock(0));
  vtkNew<vtkFloatArray> normals; // pointing down: not what the sampler would compute
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(left->GetNumberOfPoints());
  normals->FillComponent(0, 0.0);
  normals->FillComponent(1, 0.0);
  normals->FillComponent(2, -1.0);
  left->GetPointData()->SetNormals(normals);
  vtkNew<vtkOFBMergeBlocks> merge;
  merge->SetInputData(blocks);
  merge->Update();
  EXPECT_EQ(merge->GetOutput()->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(merge->GetOutput()->GetPointData()->GetArray("Normals"), nullptr);
  // The samples' normals are computed (+z for the plane), none zero or NaN.
  vtkSmartPointer<vtkOFB> ofb = Sample(blocks, 64, nullptr);
  vtkDataArray* sn = ofb->GetSampleData()->GetNormals();
  ASSERT_NE(sn, nullptr);
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    ASSERT_NEAR(std::fabs(sn->GetComponent(i, 2)), 1.0, 1e-6) << "sample " << i;
  }
  // With normals on every block, they are the normals.
  auto* right = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
  vtkNew<vtkFloatArray> rightNormals;
  rightNormals->DeepCopy(normals);
  rightNormals->SetNumberOfTuples(right->GetNumberOfPoints());
  right->GetPointData()->SetNormals(rightNormals);
  merge->SetInputData(nullptr);
  merge->SetInputData(blocks);
  merge->Update();
  EXPECT_NE(merge->GetOutput()->GetPointData()->GetNormals(), nullptr);
}

TEST(SamplerComposite, PolyDataArrayOfTheWrongLengthIsLeftOutWithAWarning)
{
  vtkSmartPointer<vtkPolyData> tile = Tile(0.0, 0.0);
  AddCellValue(tile, "Good", VTK_DOUBLE, 4.0);
  vtkNew<vtkDoubleArray> shortCells; // 3 tuples for 16 cells
  shortCells->SetName("Short");
  shortCells->SetNumberOfTuples(3);
  shortCells->FillComponent(0, 1.0);
  tile->GetCellData()->AddArray(shortCells);
  vtkNew<vtkDoubleArray> longPoints; // 99 tuples for 25 points
  longPoints->SetName("Long");
  longPoints->SetNumberOfTuples(99);
  longPoints->FillComponent(0, 1.0);
  tile->GetPointData()->AddArray(longPoints);
  vtkNew<MessageObserver> messages;
  vtkSmartPointer<vtkOFB> ofb = Sample(tile, 32, messages);
  EXPECT_EQ(messages->Errors, "");
  EXPECT_NE(messages->Warnings.find("The cell array 'Short' has 3 tuples for 16 cells: left out."),
    std::string::npos)
    << messages->Warnings;
  EXPECT_NE(
    messages->Warnings.find("The point array 'Long' has 99 tuples for 25 points: left out."),
    std::string::npos)
    << messages->Warnings;
  EXPECT_GT(ofb->GetNumberOfSamples(), 0);
  EXPECT_EQ(ofb->GetSampleData()->GetArray("Short"), nullptr);
  EXPECT_EQ(ofb->GetSampleData()->GetArray("Long"), nullptr);
  EXPECT_NE(ofb->GetSampleData()->GetArray("Good"), nullptr);
}
