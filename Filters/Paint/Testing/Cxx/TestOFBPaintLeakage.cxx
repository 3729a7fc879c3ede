// Colour leakage of the volume brush (paper Fig. 5) with and without NormalAware:
// the share of a far sheet's samples inside the brush sphere that get painted.
#include "vtkOFBTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBDecalPatch.h"
#include "vtkOFBPainter.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace vtkofbtest;

namespace
{
vtkUnsignedCharArray* Colors(vtkOFB* ofb)
{
  return vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
}

/// A thin slab: two 2 x 2 sheets 0.05 apart facing away from each other (top +z at 0.025).
vtkSmartPointer<vtkPolyData> ThinSlab()
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2.0);
  cube->SetYLength(2.0);
  cube->SetZLength(0.05);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  triangles->Update();
  vtkSmartPointer<vtkPolyData> out = triangles->GetOutput();
  return out;
}

/// Two 2 x 2 sheets at z = 0 and z = -0.05, both facing +z.
vtkSmartPointer<vtkPolyData> SheetsFacingTheSameWay()
{
  vtkNew<vtkAppendPolyData> sheets;
  for (double z : { 0.0, -0.05 })
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-1, -1, z);
    plane->SetPoint1(1, -1, z);
    plane->SetPoint2(-1, 1, z);
    sheets->AddInputConnection(plane->GetOutputPort());
  }
  sheets->Update();
  vtkSmartPointer<vtkPolyData> out = sheets->GetOutput();
  return out;
}

/// A copy of `base` with one red dab of radius `r` at `c` (linear falloff; with
/// `normalAware`, samples whose normal is over 60 degrees from the dab's are left).
vtkSmartPointer<vtkOFB> DabRed(vtkOFB* base, double r, const double c[3], bool normalAware)
{
  auto ofb = vtkSmartPointer<vtkOFB>::New();
  ofb->DeepCopy(base);
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  painter->GetBrush()->SetRadius(r);
  painter->GetBrush()->SetColor(1, 0, 0);
  painter->GetBrush()->SetFalloffToLinear();
  painter->GetBrush()->SetNormalAware(normalAware);
  painter->GetBrush()->SetMaxNormalAngle(60.0);
  painter->Dab(c);
  return ofb;
}
}

//------------------------------------------------------------------------------
TEST(Painter, NormalAwareLimitsLeakageThroughAThinWall)
{
  // A thin slab: two parallel sheets (top +z, bottom -z) closer than the radius,
  // the paper's colour leakage (Fig. 5).
  vtkSmartPointer<vtkOFB> base = Build(ThinSlab(), 256);
  const double r = 0.1; // two sheet distances
  const double c[3] = { 0.1, 0.05, 0.025 };
  double share[2];
  for (int aware = 0; aware < 2; ++aware)
  {
    vtkSmartPointer<vtkOFB> ofb = DabRed(base, r, c, aware == 1);
    vtkIdType far = 0, farPainted = 0, near = 0, nearPainted = 0;
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      if (vtkMath::Distance2BetweenPoints(x, c) >= r * r || std::abs(x[0]) > 0.99 ||
        std::abs(x[1]) > 0.99)
      {
        continue; // outside the brush, or on the slab's rim
      }
      const bool painted = Colors(ofb)->GetValue(4 * i + 1) < 255;
      if (x[2] < 0.0)
      {
        ++far;
        farPainted += painted;
      }
      else
      {
        ++near;
        nearPainted += painted;
      }
    }
    ASSERT_GT(far, 100);
    share[aware] = double(farPainted) / far;
    EXPECT_GT(double(nearPainted) / near, 0.95);
    std::cout << "[ leakage ] slab 0.05 thick, brush radius 0.1: NormalAware "
              << (aware ? "on " : "off") << ": " << farPainted << " of " << far
              << " far-sheet samples inside the brush painted (" << 100.0 * share[aware]
              << " %), near sheet " << 100.0 * nearPainted / near << " %\n";
  }
  EXPECT_GT(share[0], 0.9);
  EXPECT_EQ(share[1], 0.0);
}

//------------------------------------------------------------------------------
TEST(Painter, NormalAwareCannotSeparateSheetsFacingTheSameWay)
{
  // Two parallel sheets 0.05 apart facing the same way (+z), brush radius 0.1:
  // the normals agree, so the normal-aware brush leaks as the plain one does; only
  // a surface-aligned brush tells them apart (SurfaceAlignedDecalDoesNotLeak below).
  vtkSmartPointer<vtkOFB> base = Build(SheetsFacingTheSameWay(), 256);
  const double r = 0.1;
  const double c[3] = { 0.1, 0.05, 0.0 };
  for (int aware = 0; aware < 2; ++aware)
  {
    vtkSmartPointer<vtkOFB> ofb = DabRed(base, r, c, aware == 1);
    vtkIdType far = 0, farPainted = 0;
    for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
    {
      double x[3];
      ofb->GetSamplePosition(i, x);
      if (vtkMath::Distance2BetweenPoints(x, c) < r * r && x[2] < -0.025)
      {
        ++far;
        farPainted += Colors(ofb)->GetValue(4 * i + 1) < 255;
      }
    }
    ASSERT_GT(far, 100);
    std::cout << "[ leakage ] sheets 0.05 apart facing the same way, brush radius 0.1: "
              << "NormalAware " << (aware ? "on " : "off") << ": " << farPainted << " of " << far
              << " far-sheet samples inside the brush painted (" << 100.0 * farPainted / far
              << " %)\n";
    EXPECT_GT(double(farPainted) / far, 0.9);
  }
}

//------------------------------------------------------------------------------
TEST(Painter, SurfaceAlignedDecalDoesNotLeak)
{
  // The surface-aligned brush (vtkOFBDecalPatch + vtkOFBTextureProjector) on the two
  // configurations above: a 0.2 x 0.2 decal (the volume brush's diameter) centred on the
  // near sheet paints the near sheet under it and nothing of the far one, whichever way
  // the far sheet faces.
  vtkNew<vtkImageData> red;
  red->SetDimensions(1, 1, 1);
  red->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  const unsigned char opaqueRed[4] = { 255, 0, 0, 255 };
  vtkUnsignedCharArray::SafeDownCast(red->GetPointData()->GetScalars())
    ->SetTypedTuple(0, opaqueRed);
  for (int sameWay = 0; sameWay < 2; ++sameWay)
  {
    vtkSmartPointer<vtkPolyData> surface = sameWay ? SheetsFacingTheSameWay() : ThinSlab();
    const double top = sameWay ? 0.0 : 0.025;
    vtkSmartPointer<vtkOFB> ofb = Build(surface, 256);
    const double c[3] = { 0.1, 0.05, top };
    vtkNew<vtkOFBDecalPatch> decal;
    decal->SetInputData(surface);
    decal->SetCenter(c[0], c[1], c[2] + 0.001);
    decal->SetWidth(0.2);
    decal->SetHeight(0.2);
    vtkNew<vtkOFBTextureProjector> projector;
    projector->SetInputData(ofb);
    projector->SetMeshConnection(decal->GetOutputPort());
    projector->SetTextureData(red);
    projector->SetMaximumDistance(1.0);
    projector->Update();
    vtkOFB* out = projector->GetOutput();
    vtkIdType far = 0, farPainted = 0, near = 0, nearPainted = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfSamples(); ++i)
    {
      double x[3];
      out->GetSamplePosition(i, x);
      if (std::abs(x[0] - c[0]) > 0.09 || std::abs(x[1] - c[1]) > 0.09)
      {
        continue; // outside the decal's square, or at its rim
      }
      const bool painted = Colors(out)->GetValue(4 * i + 1) < 255;
      const bool isNear = std::abs(x[2] - top) < 1e-6;
      near += isNear;
      nearPainted += isNear && painted;
      far += !isNear;
      farPainted += !isNear && painted;
    }
    ASSERT_GT(far, 100);
    std::cout << "[ leakage ] " << (sameWay ? "sheets facing the same way" : "a thin slab")
              << ", decal 0.2 x 0.2: " << farPainted << " of " << far
              << " far-sheet samples under it painted, near sheet " << nearPainted << " of " << near
              << "\n";
    EXPECT_EQ(nearPainted, near);
    EXPECT_EQ(farPainted, 0);
  }
}
