// A composite surface (a sphere cut into four patches, a vtkMultiBlockDataSet) built into
// one OFB by both backends of vtkOFBBuilder and drawn by vtkOFBPolyDataMapper in one draw:
// the same picture as the uncut sphere, hidden blocks (vtkCompositeDataDisplayAttributes)
// not drawn and out of the bounds, and vtkCellPicker's block index. Opens render windows
// (run under xvfb-run).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellPicker.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBuilder.h"
#include "vtkOFBMapperTestHelpers.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBTestUtilities.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

namespace
{
using Pixel = std::array<int, 3>;

/// The patch of a point: 1..4 (its flat index) from the signs of x and y.
int Patch(const double x[3])
{
  return 1 + vtkofbtest::Quadrant(x);
}

/// `sphere` cut into four polydata blocks by the signs of x and y of its cell centres.
vtkSmartPointer<vtkMultiBlockDataSet> CutSphere(vtkPolyData* sphere)
{
  return vtkofbtest::CutIntoQuadrants(sphere);
}

vtkSmartPointer<vtkOFB> Build(vtkDataObject* input, int backend, vtkRenderWindow* window)
{
  vtkNew<vtkOFBBuilder> builder;
  builder->SetInputData(input);
  builder->SetResolution(128);
  builder->SetBackend(backend);
  builder->SetRenderWindow(window);
  builder->Update();
  EXPECT_EQ(builder->GetLastBackend(), backend);
  vtkSmartPointer<vtkOFB> ofb = builder->GetOutput();
  return ofb;
}

/// Colour of each block's samples: block 1 red, 2 green, 3 blue, 4 yellow.
void PaintByBlock(vtkOFB* ofb)
{
  auto* block = vtkIntArray::SafeDownCast(ofb->GetSampleData()->GetArray("BlockIndex"));
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  ASSERT_TRUE(block && colors);
  const unsigned char palette[5][4] = { { 0, 0, 0, 255 },
    { 255, 0, 0, 255 },
    { 0, 255, 0, 255 },
    { 0, 0, 255, 255 },
    { 255, 255, 0, 255 } };
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    colors->SetTypedTuple(i, palette[block->GetValue(i)]);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkOFBPolyDataMapper> Mapper;

  Scene(vtkDataObject* input, vtkOFB* ofb)
  {
    this->Mapper->SetInputDataObject(input);
    this->Mapper->SetOFB(ofb);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window->SetSize(120, 120);
    this->Window->AddRenderer(this->Renderer);
    // Looking down the z axis at the four patches.
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    this->Renderer->ResetCamera(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    camera->Zoom(1.5);
  }

  vtkSmartPointer<vtkImageData> Grab()
  {
    this->Window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkSmartPointer<vtkImageData> image = grab->GetOutput();
    return image;
  }
};

Pixel At(vtkImageData* image, int x, int y)
{
  const unsigned char* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
  return { p[0], p[1], p[2] };
}

/// Largest difference of a colour component between two images of the same size.
int LargestDifference(vtkImageData* a, vtkImageData* b)
{
  int worst = 0;
  const int* dims = a->GetDimensions();
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const Pixel p = At(a, x, y);
      const Pixel q = At(b, x, y);
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, std::abs(p[k] - q[k]));
      }
    }
  }
  return worst;
}
}

TEST(OFBCompositeMapper, BackendsAgreeOnACompositeInput)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  window->Render();
  if (!vtkOFBBuilder::IsSupported(window))
  {
    GTEST_SKIP() << "no OpenGL 4.3 context";
  }
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = CutSphere(vtkofbtest::MakeSphere(1.0, 48));
  vtkSmartPointer<vtkOFB> gl = Build(blocks, vtkOFBBuilder::BACKEND_OPENGL, window);
  vtkSmartPointer<vtkOFB> cpu = Build(blocks, vtkOFBBuilder::BACKEND_CPU, nullptr);
  ASSERT_DOUBLE_EQ(gl->GetCellSize(), cpu->GetCellSize());
  const double n = static_cast<double>(cpu->GetNumberOfSamples());
  ASSERT_GT(n, 10000);
  EXPECT_NEAR(static_cast<double>(gl->GetNumberOfSamples()), n, 1e-3 * n);
  // The same block index per sample: the same number of samples per block, within 0.1 %.
  std::map<int, double> counts[2];
  int k = 0;
  for (vtkOFB* ofb : { gl.Get(), cpu.Get() })
  {
    auto* block = vtkIntArray::SafeDownCast(ofb->GetSampleData()->GetArray("BlockIndex"));
    ASSERT_NE(block, nullptr);
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      counts[k][block->GetValue(i)] += 1.0;
    }
    ++k;
  }
  ASSERT_EQ(counts[1].size(), 4u);
  for (const auto& entry : counts[1])
  {
    EXPECT_NEAR(counts[0][entry.first], entry.second, 1e-3 * entry.second)
      << "block " << entry.first;
  }
}

TEST(OFBCompositeMapper, DrawsTheBlocksAsTheUncutSurface)
{
  vtkSmartPointer<vtkPolyData> sphere = vtkofbtest::MakeSphere(1.0, 48);
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = CutSphere(sphere);
  vtkSmartPointer<vtkOFB> ofb = Build(blocks, vtkOFBBuilder::BACKEND_CPU, nullptr);
  PaintByBlock(ofb);
  Scene composite(blocks, ofb);
  vtkSmartPointer<vtkImageData> a = composite.Grab();
  EXPECT_TRUE(composite.Mapper->GetLastRenderUsedOFB());
  // The same OFB on the uncut sphere: the same picture, patch borders included.
  Scene whole(sphere, ofb);
  vtkSmartPointer<vtkImageData> b = whole.Grab();
  EXPECT_LE(LargestDifference(a, b), 8);
  // Each quadrant of the picture shows its block's colour.
  const Pixel q1 = At(a, 35, 35), q2 = At(a, 85, 35), q3 = At(a, 35, 85), q4 = At(a, 85, 85);
  EXPECT_TRUE(q1[0] > 100 && q1[1] < 40 && q1[2] < 40) << q1[0] << " " << q1[1] << " " << q1[2];
  EXPECT_TRUE(q2[1] > 100 && q2[0] < 40 && q2[2] < 40) << q2[0] << " " << q2[1] << " " << q2[2];
  EXPECT_TRUE(q3[2] > 100 && q3[0] < 40 && q3[1] < 40) << q3[0] << " " << q3[1] << " " << q3[2];
  EXPECT_TRUE(q4[0] > 100 && q4[1] > 100 && q4[2] < 40) << q4[0] << " " << q4[1] << " " << q4[2];
  // The bounds are the sphere's.
  const double* bounds = composite.Actor->GetBounds();
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(bounds[i], i % 2 ? 1.0 : -1.0, 1e-3) << i;
  }
}

TEST(OFBCompositeMapper, HiddenBlocksAreNotDrawnAndLeaveTheBounds)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = CutSphere(vtkofbtest::MakeSphere(1.0, 48));
  vtkSmartPointer<vtkOFB> ofb = Build(blocks, vtkOFBBuilder::BACKEND_CPU, nullptr);
  PaintByBlock(ofb);
  Scene scene(blocks, ofb);
  vtkSmartPointer<vtkImageData> all = scene.Grab();
  for (const Pixel& p : { At(all, 35, 35), At(all, 85, 35), At(all, 35, 85), At(all, 85, 85) })
  {
    EXPECT_GT(p[0] + p[1] + p[2], 200); // every patch drawn
  }
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockVisibility(blocks->GetBlock(0), false); // flat index 1: x < 0, y < 0
  scene.Mapper->SetCompositeDataDisplayAttributes(attributes);
  EXPECT_EQ(scene.Mapper->GetCompositeDataDisplayAttributes(), attributes.Get());
  vtkSmartPointer<vtkImageData> hidden = scene.Grab();
  EXPECT_EQ(At(hidden, 35, 35), (Pixel{ 0, 0, 0 })); // the background through the hole
  EXPECT_EQ(At(hidden, 85, 35), At(all, 85, 35));
  EXPECT_EQ(At(hidden, 35, 85), At(all, 35, 85));
  EXPECT_EQ(At(hidden, 85, 85), At(all, 85, 85));
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  auto* index = vtkIntArray::SafeDownCast(
    scene.Mapper->GetRenderedSurface()->GetCellData()->GetArray("BlockIndex"));
  ASSERT_NE(index, nullptr);
  double range[2];
  index->GetRange(range);
  EXPECT_EQ(range[0], 2.0);

  // Hiding both blocks of x < 0 moves the bounds' minimum x to 0; the root hidden hides all.
  attributes->SetBlockVisibility(blocks->GetBlock(2), false);
  double bounds[6];
  scene.Actor->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], 0.0, 0.05);
  EXPECT_NEAR(bounds[1], 1.0, 1e-3);
  attributes->RemoveBlockVisibilities();
  attributes->SetBlockVisibility(blocks, false);
  vtkSmartPointer<vtkImageData> none = scene.Grab();
  EXPECT_EQ(At(none, 85, 85), (Pixel{ 0, 0, 0 }));
  // A block's own visibility wins over its parent's.
  attributes->SetBlockVisibility(blocks->GetBlock(3), true);
  vtkSmartPointer<vtkImageData> one = scene.Grab();
  EXPECT_EQ(At(one, 85, 85), At(all, 85, 85));
  EXPECT_EQ(At(one, 35, 85), (Pixel{ 0, 0, 0 }));
}

TEST(OFBCompositeMapper, DisplayAttributesSetAgainKeepTheSurface)
{
  // A view that sets the same block visibilities again before every render (as ParaView's
  // does) keeps the merged surface, and so the OFB and its levels built from it; a
  // visibility that changes gives a new surface.
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = CutSphere(vtkofbtest::MakeSphere(1.0, 24));
  vtkSmartPointer<vtkOFB> ofb = Build(blocks, vtkOFBBuilder::BACKEND_CPU, nullptr);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->SetOFB(ofb);
  mapper->SetCompositeDataDisplayAttributes(attributes);
  attributes->SetBlockVisibility(blocks->GetBlock(0), true);
  // Held, so that a new surface cannot take the old one's address.
  vtkSmartPointer<vtkPolyData> first = mapper->GetRenderedSurface();
  ASSERT_NE(first, nullptr);
  const vtkIdType cells = first->GetNumberOfCells();
  attributes->RemoveBlockVisibilities();
  attributes->SetBlockVisibility(blocks->GetBlock(0), true); // the same, set again
  EXPECT_EQ(mapper->GetRenderedSurface(), first);
  attributes->SetBlockVisibility(blocks->GetBlock(0), false);
  vtkSmartPointer<vtkPolyData> second = mapper->GetRenderedSurface();
  EXPECT_NE(second, first);
  EXPECT_LT(second->GetNumberOfCells(), cells);
}

TEST(OFBCompositeMapper, CellPickerGivesTheBlockIndex)
{
  vtkSmartPointer<vtkMultiBlockDataSet> blocks = CutSphere(vtkofbtest::MakeSphere(1.0, 48));
  vtkSmartPointer<vtkOFB> ofb = Build(blocks, vtkOFBBuilder::BACKEND_CPU, nullptr);
  Scene scene(blocks, ofb);
  scene.Grab();
  vtkNew<vtkCellPicker> picker;
  const int xy[4][2] = { { 35, 35 }, { 85, 35 }, { 35, 85 }, { 85, 85 } };
  for (int q = 0; q < 4; ++q)
  {
    ASSERT_TRUE(picker->Pick(xy[q][0], xy[q][1], 0.0, scene.Renderer)) << q;
    EXPECT_EQ(picker->GetActor(), scene.Actor.Get());
    EXPECT_EQ(picker->GetFlatBlockIndex(), q + 1);
    double p[3];
    picker->GetPickPosition(p);
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 0.01);
    EXPECT_GT(p[2], 0.0);
    EXPECT_EQ(Patch(p), q + 1);
  }
}

TEST(OFBCompositeMapper, BlocksWithoutCellsGiveAnEmptySurfaceWithoutError)
{
  // A ParaView client that lets the server render holds the composite structure with empty
  // blocks (and a process of a distributed surface may): nothing to draw, no error.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, vtkNew<vtkPolyData>());
  vtkNew<vtkOFBPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  vtkNew<vtkofbtest::MessageObserver> messages;
  vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::ErrorEvent, messages);
  vtkPolyData* surface = mapper->GetRenderedSurface();
  vtkOutputWindow::GetInstance()->RemoveObserver(messages);
  ASSERT_NE(surface, nullptr);
  EXPECT_EQ(surface->GetNumberOfCells(), 0);
  EXPECT_EQ(messages->Errors, "");
}
