// CPU construction: samples on the surface, counts, fill rule, sorting, threads, meshes.
#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkReverseSense.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <vector>

#if defined(__linux__)
#include <sys/resource.h>
#endif

using namespace vtkofbtest;

namespace
{
/**
 * Expected number of samples of a sphere of radius r (in cells): each of the six
 * regions where one normal component dominates projects onto its grid as
 * {2x^2 + y^2 <= r^2, x^2 + 2y^2 <= r^2}; one sample per unit of projected area.
 */
double ExpectedSphereSamples(double r)
{
  const int steps = 200000;
  const double xmax = 1.0 / std::sqrt(2.0);
  double area = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const double x = -xmax + (i + 0.5) * (2.0 * xmax / steps);
    const double y = std::min(
      std::sqrt(std::max(0.0, 1.0 - 2.0 * x * x)), std::sqrt(std::max(0.0, (1.0 - x * x) / 2.0)));
    area += 2.0 * y * (2.0 * xmax / steps);
  }
  return 6.0 * area * r * r;
}

/// Random point on the surface, uniform by area.
struct SurfaceSampler
{
  explicit SurfaceSampler(vtkPolyData* mesh)
    : Mesh(mesh)
  {
    double total = 0.0;
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      double p[3][3];
      vtkIdType npts;
      const vtkIdType* ids;
      mesh->GetCellPoints(c, npts, ids);
      for (int k = 0; k < 3; ++k)
      {
        mesh->GetPoint(ids[k], p[k]);
      }
      double e1[3], e2[3], n[3];
      vtkMath::Subtract(p[1], p[0], e1);
      vtkMath::Subtract(p[2], p[0], e2);
      vtkMath::Cross(e1, e2, n);
      total += vtkMath::Norm(n);
      this->Cumulative.push_back(total);
    }
    this->Random->SetSeed(1234);
  }
  void Next(double x[3])
  {
    const double r = this->Uniform() * this->Cumulative.back();
    const vtkIdType c = std::lower_bound(this->Cumulative.begin(), this->Cumulative.end(), r) -
      this->Cumulative.begin();
    vtkIdType npts;
    const vtkIdType* ids;
    this->Mesh->GetCellPoints(c, npts, ids);
    double a = this->Uniform(), b = this->Uniform();
    if (a + b > 1.0)
    {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      this->Mesh->GetPoint(ids[k], p[k]);
    }
    for (int k = 0; k < 3; ++k)
    {
      x[k] = p[0][k] + a * (p[1][k] - p[0][k]) + b * (p[2][k] - p[0][k]);
    }
  }
  double Uniform()
  {
    this->Random->Next();
    return this->Random->GetValue();
  }
  vtkPolyData* Mesh;
  std::vector<double> Cumulative;
  vtkNew<vtkMinimalStandardRandomSequence> Random;
};

vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* mesh)
{
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputData(mesh);
  tri->PassVertsOff();
  tri->PassLinesOff();
  tri->Update();
  vtkSmartPointer<vtkPolyData> out = tri->GetOutput();
  return out;
}

void ExpectIdentical(vtkOFB* a, vtkOFB* b)
{
  ASSERT_EQ(a->GetNumberOfSamples(), b->GetNumberOfSamples());
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  EXPECT_EQ(0,
    std::memcmp(a->GetCellOffsets()->GetPointer(0),
      b->GetCellOffsets()->GetPointer(0),
      sizeof(vtkTypeUInt32) * (a->GetNumberOfCells() + 1)));
  EXPECT_EQ(0,
    std::memcmp(a->GetDepths()->GetPointer(0),
      b->GetDepths()->GetPointer(0),
      sizeof(float) * a->GetNumberOfSamples()));
  ASSERT_EQ(a->GetSampleData()->GetNumberOfArrays(), b->GetSampleData()->GetNumberOfArrays());
  for (int i = 0; i < a->GetSampleData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = a->GetSampleData()->GetArray(i);
    vtkDataArray* y = b->GetSampleData()->GetArray(x->GetName());
    ASSERT_NE(y, nullptr) << x->GetName();
    EXPECT_EQ(0,
      std::memcmp(
        x->GetVoidPointer(0), y->GetVoidPointer(0), x->GetDataSize() * x->GetDataTypeSize()))
      << x->GetName();
  }
}
}

//------------------------------------------------------------------------------
TEST(Sampler, SphereSamplesLieOnTheMeshAndMatchTheExpectedCount)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 256);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(sphere);
  locator->BuildLocator();
  for (int resolution : { 64, 128, 256, 512 })
  {
    vtkSmartPointer<vtkOFB> ofb = Build(sphere, resolution);
    const double s = ofb->GetCellSize();
    const double expected = ExpectedSphereSamples(1.0 / s);
    const double n = static_cast<double>(ofb->GetNumberOfSamples());
    std::cout << "resolution " << resolution << ": " << n << " samples, expected " << expected
              << " (" << 100.0 * (n - expected) / expected << " %)\n";
    EXPECT_NEAR(n, expected, 0.02 * expected) << "resolution " << resolution;
    // Every sample on the mesh, within 1e-3 cell of its nearest triangle.
    if (resolution > 256)
    {
      continue; // the count is enough at the finest level; distances are checked below
    }
    double worst = 0.0;
    vtkNew<vtkGenericCell> cell;
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3], closest[3], d2;
      vtkIdType cellId;
      int subId;
      ofb->GetSamplePosition(i, x);
      locator->FindClosestPoint(x, closest, cell, cellId, subId, d2);
      worst = std::max(worst, std::sqrt(d2) / s);
    }
    std::cout << "  farthest sample from the mesh: " << worst << " cells\n";
    EXPECT_LT(worst, 1e-3) << "resolution " << resolution;
  }
}

//------------------------------------------------------------------------------
TEST(Sampler, FillRuleGivesNoHoleAndNoDuplicateOnSharedEdges)
{
  // A plane whose diagonals pass exactly through cell centres: each of the
  // (R-2)^2 centres inside is covered exactly once.
  const int m = 6; // cells per quad
  const int quads = 10;
  const int resolution = m * quads + 2;
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.25);
  plane->SetPoint1(1.0, 0.0, 0.25);
  plane->SetPoint2(0.0, 1.0, 0.25);
  plane->SetResolution(quads, quads);
  plane->Update();
  vtkSmartPointer<vtkPolyData> mesh = Triangulated(plane->GetOutput());
  vtkSmartPointer<vtkOFB> ofb = Build(mesh, resolution);
  EXPECT_EQ(ofb->GetNumberOfSamples(), static_cast<vtkIdType>(m * quads) * (m * quads));
  EXPECT_EQ(ofb->GetNumberOfSamples(2), ofb->GetNumberOfSamples());
  EXPECT_EQ(ofb->GetDepthComplexity(), 1);
}

//------------------------------------------------------------------------------
TEST(Sampler, CellsAreDepthSortedWithoutDuplicatedSurfacePoints)
{
  for (const char* name : { "sphere", "stanford-bunny.obj" })
  {
    vtkSmartPointer<vtkPolyData> mesh =
      std::strcmp(name, "sphere") ? ReadMesh(name) : MakeSphere(1.0, 128);
    ASSERT_NE(mesh, nullptr) << name;
    vtkSmartPointer<vtkOFB> ofb = Build(mesh, 256);
    const vtkTypeUInt32* offsets = ofb->GetCellOffsets()->GetPointer(0);
    const float* depth = ofb->GetDepths()->GetPointer(0);
    const double s = ofb->GetCellSize();
    vtkIdType unsorted = 0, duplicates = 0;
    for (vtkIdType c = 0; c < ofb->GetNumberOfCells(); ++c)
    {
      for (vtkTypeUInt32 i = offsets[c] + 1; i < offsets[c + 1]; ++i)
      {
        unsorted += depth[i] < depth[i - 1];
        // Two samples of one ray within 1e-3 cell are one surface point taken twice.
        duplicates += (depth[i] - depth[i - 1]) < 1e-3 * s;
      }
    }
    EXPECT_EQ(unsorted, 0) << name;
    EXPECT_EQ(duplicates, 0) << name;
    EXPECT_GE(ofb->GetDepthComplexity(), 2) << name;
  }
}

//------------------------------------------------------------------------------
// Two coincident copies of a plane, the second (blue, later triangle ids) wound the
// other way: it faces against the z grid's axis and is set up first, so its
// fragments arrive first in each cell. Samples of equal depth must still come in
// triangle order (as the OpenGL backend orders them): red, then blue, in every cell,
// with and without another point array interpolated after the sort.
TEST(Sampler, EqualDepthsComeInTriangleOrder)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(7, 5);
  plane->Update();
  vtkPolyData* quads = plane->GetOutput();
  const vtkIdType nPoints = quads->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> tris;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  colors->SetName("Colors");
  vtkNew<vtkFloatArray> label;
  label->SetName("Label");
  for (int copy = 0; copy < 2; ++copy)
  {
    for (vtkIdType i = 0; i < nPoints; ++i)
    {
      points->InsertNextPoint(quads->GetPoint(i));
      const unsigned char rgb[3] = {
        static_cast<unsigned char>(copy ? 0 : 255), 0, static_cast<unsigned char>(copy ? 255 : 0)
      };
      colors->InsertNextTypedTuple(rgb);
      label->InsertNextValue(static_cast<float>(copy + 1));
    }
  }
  for (int copy = 0; copy < 2; ++copy)
  {
    for (vtkIdType c = 0; c < quads->GetNumberOfCells(); ++c)
    {
      vtkIdType n;
      const vtkIdType* q;
      quads->GetCellPoints(c, n, q);
      const vtkIdType base = copy * nPoints;
      const vtkIdType a[3] = { base + q[0], base + q[1], base + q[2] };
      const vtkIdType b[3] = { base + q[0], base + q[2], base + q[3] };
      const vtkIdType ra[3] = { a[0], a[2], a[1] };
      const vtkIdType rb[3] = { b[0], b[2], b[1] };
      tris->InsertNextCell(3, copy ? ra : a);
      tris->InsertNextCell(3, copy ? rb : b);
    }
  }
  for (const bool withLabel : { false, true })
  {
    vtkNew<vtkPolyData> mesh;
    mesh->SetPoints(points);
    mesh->SetPolys(tris);
    mesh->GetPointData()->SetScalars(colors);
    if (withLabel)
    {
      mesh->GetPointData()->AddArray(label);
    }
    vtkSmartPointer<vtkOFB> ofb = Build(mesh, 32);
    const vtkTypeUInt32* offsets = ofb->GetCellOffsets()->GetPointer(0);
    auto* rgba = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetScalars());
    vtkDataArray* labels = ofb->GetSampleData()->GetArray("Label");
    ASSERT_NE(rgba, nullptr);
    ASSERT_EQ(labels != nullptr, withLabel);
    vtkIdType pairs = 0, wrong = 0;
    for (vtkIdType c = 0; c < ofb->GetNumberOfCells(); ++c)
    {
      const vtkTypeUInt32 first = offsets[c];
      if (offsets[c + 1] == first)
      {
        continue;
      }
      ASSERT_EQ(offsets[c + 1] - first, 2u) << "cell " << c;
      ++pairs;
      wrong += rgba->GetValue(4 * first) != 255 || rgba->GetValue(4 * first + 6) != 255;
      if (labels)
      {
        wrong += labels->GetComponent(first, 0) != 1.0 || labels->GetComponent(first + 1, 0) != 2.0;
      }
    }
    EXPECT_GT(pairs, 500) << "withLabel " << withLabel;
    EXPECT_EQ(wrong, 0) << "withLabel " << withLabel;
  }
}

//------------------------------------------------------------------------------
// The CPU backend sets up the triangles that enter a closed surface first (by its
// winding, from the sign of the volume it encloses), so that the fragments of a
// cell mostly arrive in depth order. The horse is wound inwards: it and its copy
// wound outwards must give the same samples in the same order, depth sorted (the
// normals to rounding: a triangle's barycentrics are stepped in float along a
// span, from other vertices, 5e-5 apart on the horse's thinnest triangles).
TEST(Sampler, WindingDoesNotChangeTheSamples)
{
  vtkSmartPointer<vtkPolyData> horse = ReadMesh("horse.ply");
  ASSERT_NE(horse, nullptr);
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(horse);
  reverse->ReverseCellsOn();
  reverse->ReverseNormalsOff();
  reverse->Update();
  vtkSmartPointer<vtkOFB> inwards = Build(horse, 256);
  vtkSmartPointer<vtkOFB> outwards = Build(reverse->GetOutput(), 256);
  ASSERT_GT(inwards->GetNumberOfSamples(), 50000);
  EXPECT_GE(inwards->GetDepthComplexity(), 4);
  ASSERT_EQ(inwards->GetNumberOfSamples(), outwards->GetNumberOfSamples());
  const vtkIdType n = inwards->GetNumberOfSamples();
  EXPECT_EQ(0,
    std::memcmp(inwards->GetCellOffsets()->GetPointer(0),
      outwards->GetCellOffsets()->GetPointer(0),
      sizeof(vtkTypeUInt32) * (inwards->GetNumberOfCells() + 1)));
  EXPECT_EQ(0,
    std::memcmp(inwards->GetDepths()->GetPointer(0),
      outwards->GetDepths()->GetPointer(0),
      sizeof(float) * static_cast<size_t>(n)));
  vtkDataArray* n1 = inwards->GetSampleData()->GetNormals();
  vtkDataArray* n2 = outwards->GetSampleData()->GetNormals();
  ASSERT_TRUE(n1 && n2);
  vtkIdType different = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      different += std::fabs(n1->GetComponent(i, k) - n2->GetComponent(i, k)) > 1e-3;
    }
  }
  EXPECT_EQ(different, 0);
  const vtkTypeUInt32* offsets = inwards->GetCellOffsets()->GetPointer(0);
  const float* depth = inwards->GetDepths()->GetPointer(0);
  vtkIdType unsorted = 0;
  for (vtkIdType c = 0; c < inwards->GetNumberOfCells(); ++c)
  {
    for (vtkTypeUInt32 i = offsets[c] + 1; i < offsets[c + 1]; ++i)
    {
      unsorted += depth[i] < depth[i - 1];
    }
  }
  EXPECT_EQ(unsorted, 0);
}

//------------------------------------------------------------------------------
TEST(Sampler, IdenticalOutputWithOneAndTwoThreads)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkSMPTools::Initialize(1);
  vtkSmartPointer<vtkOFB> one = Build(bunny, 512);
  vtkSMPTools::Initialize(2);
  vtkSmartPointer<vtkOFB> two = Build(bunny, 512);
  ASSERT_GT(one->GetNumberOfSamples(), 0);
  ExpectIdentical(one, two);
  const std::string backend = vtkSMPTools::GetBackend();
  if (vtkSMPTools::SetBackend("STDThread"))
  {
    vtkSMPTools::Initialize(2);
    vtkSmartPointer<vtkOFB> std2 = Build(bunny, 512);
    ExpectIdentical(one, std2);
    vtkSMPTools::SetBackend(backend.c_str());
  }
  vtkSMPTools::Initialize(0);
}

//------------------------------------------------------------------------------
TEST(Sampler, RebuildReusesTheMemoryOfArraysNobodyElseHolds)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(bunny);
  sampler->SetResolution(256);
  sampler->Update();
  vtkOFB* output = sampler->GetOutput();
  ASSERT_GT(output->GetNumberOfSamples(), 0);
  vtkNew<vtkOFB> reference;
  reference->DeepCopy(output);
  const void* depths = output->GetDepths()->GetVoidPointer(0);
  const void* normals = output->GetSampleData()->GetNormals()->GetVoidPointer(0);

  // A rebuild writes over the same memory and gives the same OFB.
  sampler->Modified();
  sampler->Update();
  EXPECT_EQ(output->GetDepths()->GetVoidPointer(0), depths);
  EXPECT_EQ(output->GetSampleData()->GetNormals()->GetVoidPointer(0), normals);
  EXPECT_EQ(output->GetNumberOfSpareArrays(), 0);
  ExpectIdentical(reference, output);

  // Arrays another OFB shares are left alone.
  vtkNew<vtkOFB> held;
  held->ShallowCopy(output);
  sampler->SetResolution(200);
  sampler->Update();
  EXPECT_NE(output->GetDepths()->GetVoidPointer(0), held->GetDepths()->GetVoidPointer(0));
  ExpectIdentical(reference, held);
  ExpectIdentical(Build(bunny, 200), output);

  // Smaller and larger rebuilds over recycled memory equal fresh builds.
  for (const int resolution : { 128, 300 })
  {
    sampler->SetResolution(resolution);
    sampler->Update();
    EXPECT_EQ(output->GetNumberOfSpareArrays(), 0);
    ExpectIdentical(Build(bunny, resolution), output);
  }
  // Without the kept build buffers, the same OFB again.
  sampler->ReleaseBuffers();
  sampler->SetResolution(256);
  sampler->Update();
  ExpectIdentical(reference, output);

  // A rebuild of a surface with vectors and colours after one without them.
  vtkNew<vtkPolyData> painted;
  painted->DeepCopy(bunny);
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("Flow");
  vectors->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("Colors");
  rgb->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < painted->GetNumberOfPoints(); ++i)
  {
    double x[3];
    painted->GetPoint(i, x);
    vectors->InsertNextTuple3(-x[1], x[0], 0.5);
    rgb->InsertNextTuple3(i % 256, (3 * i) % 256, 128);
  }
  painted->GetPointData()->SetVectors(vectors);
  painted->GetPointData()->SetScalars(rgb);
  sampler->SetInputData(painted);
  sampler->Update();
  ASSERT_NE(output->GetSampleData()->GetArray("Flow"), nullptr);
  ExpectIdentical(Build(painted, 256), output);
  sampler->SetInputData(bunny);

  // A failed rebuild leaves an empty OFB holding no spare memory.
  sampler->SetResolution(0);
  vtkNew<MessageObserver> errors;
  sampler->AddObserver(vtkCommand::ErrorEvent, errors);
  sampler->Update();
  EXPECT_EQ(output->GetNumberOfSamples(), 0);
  EXPECT_EQ(output->GetNumberOfSpareArrays(), 0);

  // Recycle keeps only unshared arrays; Initialize frees them.
  vtkNew<vtkOFB> copy;
  copy->DeepCopy(reference);
  vtkSmartPointer<vtkDataArray> kept = copy->GetSampleData()->GetNormals();
  copy->Recycle();
  EXPECT_EQ(copy->GetNumberOfSamples(), 0);
  // Offsets, depths, cell index, colours and the OBJ reader's cell array "GroupIds".
  ASSERT_NE(reference->GetSampleData()->GetArray("GroupIds"), nullptr);
  EXPECT_EQ(copy->GetNumberOfSpareArrays(), 5);
  EXPECT_EQ(copy->TakeSpareArray("Normals", VTK_FLOAT, 3, 1), nullptr);
  EXPECT_EQ(copy->TakeSpareArray(nullptr, VTK_FLOAT, 1, 1), nullptr);
  EXPECT_EQ(copy->TakeSpareArray("Depths", VTK_DOUBLE, 1, 1), nullptr);
  EXPECT_EQ(copy->TakeSpareArray("Depths", VTK_FLOAT, 3, 1), nullptr);
  EXPECT_EQ(
    copy->TakeSpareArray("Depths", VTK_FLOAT, 1, reference->GetNumberOfSamples() + 1), nullptr);
  vtkSmartPointer<vtkDataArray> depthsBack =
    copy->TakeSpareArray("Depths", VTK_FLOAT, 1, reference->GetNumberOfSamples() / 2);
  ASSERT_NE(depthsBack, nullptr);
  EXPECT_EQ(depthsBack->GetNumberOfTuples(), reference->GetNumberOfSamples() / 2);
  copy->Initialize();
  EXPECT_EQ(copy->GetNumberOfSpareArrays(), 0);
}

//------------------------------------------------------------------------------
TEST(Sampler, ClosestSampleWithinSqrt3CellsOfRandomSurfacePoints)
{
  for (const char* name : { "sphere", "stanford-bunny.obj" })
  {
    vtkSmartPointer<vtkPolyData> mesh =
      std::strcmp(name, "sphere") ? Triangulated(ReadMesh(name)) : MakeSphere(1.0, 128);
    ASSERT_NE(mesh, nullptr);
    vtkSmartPointer<vtkOFB> ofb = Build(mesh, 512);
    const double bound = std::sqrt(3.0) * ofb->GetCellSize();
    SurfaceSampler points(mesh);
    int misses = 0;
    double worst = 0.0;
    for (int i = 0; i < 10000; ++i)
    {
      double x[3], y[3];
      points.Next(x);
      const vtkIdType id = ofb->FindClosestSample(x);
      if (id < 0 || !ofb->GetSamplePosition(id, y))
      {
        ++misses;
        continue;
      }
      worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(x, y)));
    }
    std::cout << name << ": farthest closest sample " << worst / ofb->GetCellSize() << " cells, "
              << misses << " misses\n";
    EXPECT_EQ(misses, 0) << name;
    EXPECT_LE(worst, bound) << name;
  }
}

//------------------------------------------------------------------------------
TEST(Sampler, AttributesAreInterpolatedAndVectorsTangent)
{
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 64);
  const vtkIdType np = sphere->GetNumberOfPoints();
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("Wind");
  vectors->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double x[3];
    sphere->GetPoint(i, x);
    vectors->InsertNextTuple3(1.0, 0.5, 0.25); // constant: not tangent anywhere
    height->InsertNextValue(x[2]);
    colors->InsertNextTuple3(x[0] > 0 ? 255 : 0, 10, 20);
  }
  sphere->GetPointData()->AddArray(vectors);
  sphere->GetPointData()->AddArray(height);
  sphere->GetPointData()->SetScalars(colors);

  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(sphere);
  sampler->SetResolution(128);
  sampler->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Wind");
  sampler->Update();
  vtkOFB* ofb = sampler->GetOutput();
  vtkPointData* sd = ofb->GetSampleData();
  vtkFloatArray* normals = vtkFloatArray::SafeDownCast(sd->GetNormals());
  vtkFloatArray* wind = vtkFloatArray::SafeDownCast(sd->GetArray("Wind"));
  vtkDataArray* h = sd->GetArray("Height");
  vtkUnsignedCharArray* c = vtkUnsignedCharArray::SafeDownCast(sd->GetScalars());
  ASSERT_NE(normals, nullptr);
  ASSERT_NE(wind, nullptr);
  ASSERT_NE(h, nullptr);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(sd->GetVectors(), wind);
  EXPECT_EQ(h->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(c->GetNumberOfComponents(), 4);
  double worstTangent = 0.0, worstNormal = 0.0, worstHeight = 0.0;
  int wrongColor = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3], n[3], v[3];
    ofb->GetSamplePosition(i, x);
    normals->GetTuple(i, n);
    wind->GetTuple(i, v);
    worstTangent = std::max(worstTangent, std::fabs(vtkMath::Dot(n, v)));
    const double r = vtkMath::Norm(x);
    worstNormal = std::max(worstNormal, 1.0 - vtkMath::Dot(n, x) / r);
    worstHeight = std::max(worstHeight, std::fabs(h->GetTuple1(i) - x[2]));
    if (std::fabs(x[0]) > 0.1)
    {
      wrongColor += c->GetValue(4 * i) != (x[0] > 0 ? 255 : 0) || c->GetValue(4 * i + 1) != 10 ||
        c->GetValue(4 * i + 3) != 255;
    }
  }
  EXPECT_LT(worstTangent, 1e-5);
  EXPECT_LT(worstNormal, 1e-3);
  EXPECT_LT(worstHeight, 1e-3);
  EXPECT_EQ(wrongColor, 0);
}

//------------------------------------------------------------------------------
TEST(Sampler, RealMeshesBuild)
{
  for (const char* name :
    { "stanford-bunny.obj", "horse.ply", "fandisk.obj", "rocker-arm.obj", "teapot.obj" })
  {
    vtkSmartPointer<vtkPolyData> mesh = ReadMesh(name);
    ASSERT_NE(mesh, nullptr) << name;
    vtkNew<vtkOFBSampler> sampler;
    sampler->SetInputData(mesh);
    sampler->SetResolution(1024);
    sampler->Update();
    vtkOFB* ofb = sampler->GetOutput();
    std::cout << name << ": " << mesh->GetNumberOfPolys() << " polygons, "
              << ofb->GetNumberOfSamples() << " samples (X " << ofb->GetNumberOfSamples(0) << ", Y "
              << ofb->GetNumberOfSamples(1) << ", Z " << ofb->GetNumberOfSamples(2)
              << "), depth complexity " << ofb->GetDepthComplexity(0) << " "
              << ofb->GetDepthComplexity(1) << " " << ofb->GetDepthComplexity(2) << ", "
              << ofb->GetBytesPerSample() << " bytes/sample, " << sampler->GetLastBuildTime()
              << " ms\n";
    EXPECT_GT(ofb->GetNumberOfSamples(0), 0) << name;
    EXPECT_GT(ofb->GetNumberOfSamples(1), 0) << name;
    EXPECT_GT(ofb->GetNumberOfSamples(2), 0) << name;
    EXPECT_EQ(ofb->GetNumberOfSamples(),
      ofb->GetNumberOfSamples(0) + ofb->GetNumberOfSamples(1) + ofb->GetNumberOfSamples(2));
    EXPECT_GE(ofb->GetDepthComplexity(), 2) << name;
    EXPECT_EQ(ofb->GetSampleData()->GetNumberOfTuples(), ofb->GetNumberOfSamples()) << name;
    // Every sample inside the frame and with a unit normal.
    double bounds[6];
    ofb->GetBounds(bounds);
    int bad = 0;
    vtkDataArray* normals = ofb->GetSampleData()->GetNormals();
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); i += 7)
    {
      double x[3], n[3];
      ofb->GetSamplePosition(i, x);
      normals->GetTuple(i, n);
      for (int a = 0; a < 3; ++a)
      {
        bad += x[a] < bounds[2 * a] || x[a] > bounds[2 * a + 1];
      }
      bad += std::fabs(vtkMath::Norm(n) - 1.0) > 1e-4;
    }
    EXPECT_EQ(bad, 0) << name;
  }
}

//------------------------------------------------------------------------------
namespace
{
/// Peak resident memory of this process in bytes (0 where unknown).
double PeakResidentBytes()
{
#if defined(__linux__)
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss); // KiB on Linux
#else
  return 0.0;
#endif
}
}

TEST(Sampler, MemoryLimitCountsTheSurfaceCopyAndPerTriangleBuffers)
{
  // About 200k triangles: their setup alone takes over 30 MB, a few MiB their grids.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 320);
  const double triangles = static_cast<double>(sphere->GetNumberOfPolys());
  ASSERT_GT(triangles, 190000.0);
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(sphere);
  sampler->SetResolution(64);
  sampler->SetMemoryLimit(4); // MiB: above the grids, below the per-triangle need
  vtkNew<MessageObserver> messages;
  messages->Watch(sampler);
  const double before = PeakResidentBytes();
  sampler->Update();
  const double grown = PeakResidentBytes() - before;
  EXPECT_NE(messages->Errors.find("memory limit"), std::string::npos) << messages->Errors;
  EXPECT_EQ(sampler->GetOutput()->GetNumberOfSamples(), 0);
  EXPECT_EQ(sampler->GetOutput()->GetNumberOfCells(), 0);
  // The check came before the copy of the surface and the triangle setups (a
  // build that allocated them would have touched over 30 MB).
  EXPECT_LT(grown, 8.0 * 1048576.0) << "bytes allocated before the memory check";
  // The estimate counts those buffers: over 150 bytes a triangle, over the limit.
  const double estimate = sampler->EstimateMemory(sphere);
  EXPECT_GT(estimate, 150.0 * triangles);
  EXPECT_GT(estimate, 4.0 * 1048576.0);
  // The same surface within a limit above its need builds.
  sampler->SetMemoryLimit(static_cast<vtkIdType>(estimate / 1048576.0) + 8);
  messages->Clear();
  sampler->Update();
  EXPECT_EQ(messages->Errors, "");
  EXPECT_GT(sampler->GetOutput()->GetNumberOfSamples(), 0);
}
