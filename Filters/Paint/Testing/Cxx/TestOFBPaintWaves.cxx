// vtkOFBPainter::Dabs with thousands of separate dabs in one call (particle footprints):
// most of them fall in the first wave, which the painter orders along a Morton curve
// (a radix sort above 256 dabs) before painting it in parallel. Whatever the order, every
// dab must be painted exactly once: the colours equal those of the same dabs one by one.
#include "vtkOFBTestUtilities.h"

#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vtkofbtest;

//------------------------------------------------------------------------------
TEST(PaintWaves, ThousandsOfSeparateDabsEqualDabsOneByOne)
{
  // 4000 dabs of 1.5 cells on a sphere of about 256 cells' radius: about one in eight
  // overlaps an earlier one, so the first wave holds thousands.
  vtkSmartPointer<vtkPolyData> sphere = MakeSphere(1.0, 96);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  vtkNew<vtkPolyData> dabs;
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(4);
  for (int i = 0; i < 4000; ++i)
  {
    const double theta = random->GetNextRangeValue(0.0, 2.0 * vtkMath::Pi());
    double p[3];
    OnSphere(theta, std::acos(random->GetNextRangeValue(-1.0, 1.0)), p);
    points->InsertNextPoint(p);
    unsigned char c[4];
    RandomColor(random, 255, c);
    color->InsertNextTypedTuple(c);
  }
  dabs->SetPoints(points);
  dabs->GetPointData()->AddArray(color);

  std::vector<std::vector<unsigned char>> results;
  for (int threads : { 1, 2, 0 })
  {
    vtkSmartPointer<vtkOFB> ofb = Build(sphere, 512);
    ASSERT_GT(ofb->GetNumberOfSamples(), 500000);
    vtkNew<vtkOFBPainter> painter;
    painter->SetOFB(ofb);
    painter->GetBrush()->SetRadius(1.5 * ofb->GetCellSize());
    painter->GetBrush()->SetStrength(0.7);
    vtkIdType changed = 0;
    if (threads > 0)
    {
      vtkSMPTools::LocalScope(
        vtkSMPTools::Config{ threads }, [&]() { changed = painter->Dabs(dabs); });
    }
    else
    {
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        const unsigned char* c = color->GetPointer(4 * i);
        painter->GetBrush()->SetColor(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, 1.0);
        changed += painter->Dab(points->GetPoint(i));
      }
    }
    // Each dab changes a few samples: 4000 dabs, well over 4000 changes.
    EXPECT_GT(changed, 4000);
    auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
    ASSERT_NE(colors, nullptr);
    results.emplace_back(
      colors->GetPointer(0), colors->GetPointer(0) + 4 * colors->GetNumberOfTuples());
  }
  EXPECT_TRUE(results[0] == results[1]) << "1 and 2 threads differ";
  EXPECT_TRUE(results[0] == results[2]) << "one call differs from the dabs one by one";
}
