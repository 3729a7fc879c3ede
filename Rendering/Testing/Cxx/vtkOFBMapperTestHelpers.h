// Helpers of the vtkOFBPolyDataMapper tests: painting patterns into OFB colours, and
// image tests comparing two lookup modes side by side.
#ifndef vtkOFBMapperTestHelpers_h
#define vtkOFBMapperTestHelpers_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBRegressionTestImage.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <functional>
#include <iostream>

namespace vtkofbtest
{
/// The RGBA "Colors" sample array of an OFB (null if missing).
inline vtkUnsignedCharArray* GetColors(vtkOFB* ofb)
{
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  return (colors && colors->GetNumberOfComponents() == 4) ? colors : nullptr;
}

/// Set every sample's colour from its position; marks all samples modified.
inline void Paint(vtkOFB* ofb,
  const std::function<void(const double x[3], unsigned char rgba[4])>& f)
{
  vtkUnsignedCharArray* colors = GetColors(ofb);
  if (!colors)
  {
    return;
  }
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    unsigned char rgba[4] = { 255, 255, 255, 255 };
    f(x, rgba);
    colors->SetTypedTuple(i, rgba);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
}

/// Set the colour of every sample within `radius` of `center` to `rgba` (candidates from
/// vtkOFB::ForEachSampleInSphere, as a brush finds them); marks them modified and calls
/// Modified() once. Returns the number of samples set.
inline vtkIdType PaintSphere(vtkOFB* ofb,
  const double center[3],
  double radius,
  const unsigned char rgba[4])
{
  vtkUnsignedCharArray* colors = GetColors(ofb);
  if (!colors)
  {
    return 0;
  }
  vtkIdType count = 0;
  ofb->ForEachSampleInSphere(center,
    radius,
    [&](vtkIdType id, double)
    {
      colors->SetTypedTuple(id, rgba);
      ofb->MarkSamplesModified(id, id + 1);
      ++count;
    });
  ofb->Modified();
  return count;
}

/// A 3-D checker of cubes of edge `size` (world units), colours a and b.
inline void PaintChecker(vtkOFB* ofb,
  double size,
  const unsigned char a[4],
  const unsigned char b[4])
{
  Paint(ofb,
    [&](const double x[3], unsigned char rgba[4])
    {
      const long k = static_cast<long>(
        std::floor(x[0] / size) + std::floor(x[1] / size) + std::floor(x[2] / size));
      const unsigned char* c = (k % 2 == 0) ? a : b;
      for (int i = 0; i < 4; ++i)
      {
        rgba[i] = c[i];
      }
    });
}

/**
 * Compare the rendered window with the test's baseline image (interactive with -I).
 * Returns the test's exit code (0 on success).
 */
inline int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* renWin)
{
  int retVal = vtkRegressionTestImage(renWin);
  if (retVal == vtkRegressionTester::DO_INTERACTOR)
  {
    vtkNew<vtkRenderWindowInteractor> iren;
    iren->SetRenderWindow(renWin);
    iren->Start();
  }
  return !retVal;
}

/**
 * Compare the rendered window with the test's baseline image by vtkOFBImageComparison
 * (interactive with -I): the texture (the high-passed luminance) and the low-passed
 * colour inside the surface, VTK's image difference outside it. For images whose
 * surface carries a LIC, which VTK's image difference alone does not see. The
 * background of the window's first renderer tells the surface from the background.
 * Returns the test's exit code (0 on success).
 */
inline int CompareLICWithBaseline(int argc, char* argv[], vtkRenderWindow* renWin)
{
  const int retVal = vtkOFBRegressionTestImage(renWin);
  if (retVal == vtkOFBImageComparison::DO_INTERACTOR)
  {
    vtkNew<vtkRenderWindowInteractor> iren;
    iren->SetRenderWindow(renWin);
    iren->Start();
  }
  return retVal == vtkOFBImageComparison::FAILED ? 1 : 0;
}

/**
 * Render `window`, then compare it with the test's baseline (CompareLICWithBaseline where
 * `lic`, else CompareWithBaseline); 1 (after a message) where `mapper` did not colour from
 * the OFB.
 */
inline int RenderAndCompare(int argc,
  char* argv[],
  vtkRenderWindow* window,
  vtkOFBPolyDataMapper* mapper,
  bool lic = false)
{
  window->Render();
  if (!mapper->GetLastRenderUsedOFB())
  {
    std::cerr << "The mapper did not colour from the OFB." << std::endl;
    return 1;
  }
  return lic ? CompareLICWithBaseline(argc, argv, window)
             : CompareWithBaseline(argc, argv, window);
}

/**
 * Render `surface` coloured by `ofb` with lookup mode `left` in the left half of a
 * 400x200 window and `right` in the right half, camera zoomed by `zoom`, and
 * compare with the test's baseline. Returns the test's exit code (0 on success).
 */
inline int CompareLookupModes(int argc,
  char* argv[],
  vtkPolyData* surface,
  vtkOFB* ofb,
  int left,
  int right,
  const double background[3],
  double zoom)
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(400, 200);
  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkOFBPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->SetOFB(ofb);
    mapper->SetLookupMode(v == 0 ? left : right);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * v, 0.0, 0.5 * (v + 1), 1.0);
    renderer->AddActor(actor);
    renderer->SetBackground(background[0], background[1], background[2]);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Zoom(zoom);
    renWin->AddRenderer(renderer);
  }
  renWin->Render();
  return CompareWithBaseline(argc, argv, renWin);
}
}

#endif
