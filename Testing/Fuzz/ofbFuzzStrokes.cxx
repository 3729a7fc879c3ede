// Fuzz target: the stroke files of OFBPaint (Examples/Cxx/OFBPaint/ofbPaintStrokes.cxx),
// replayed on a small painted sphere. Pixel points map to points of the sphere, `view`
// lines are accepted and decals stamp nothing, so that every command of the format runs
// without a window. A replay may refuse a line; it must not crash.
#include "ofbFuzzFile.h"
#include "ofbPaintStrokes.h"

#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBSampler.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace
{
/// The OFB of a unit sphere at a low resolution, built once.
vtkOFB* BaseOFB()
{
  static vtkSmartPointer<vtkOFB> base;
  if (!base)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(12);
    sphere->SetPhiResolution(8);
    vtkNew<vtkOFBSampler> sampler;
    sampler->SetInputConnection(sphere->GetOutputPort());
    sampler->SetResolution(16);
    sampler->Update();
    base = sampler->GetOutput();
    if (base->GetNumberOfSamples() == 0)
    {
      std::fprintf(stderr, "ofbFuzzStrokes: cannot build the sphere's OFB\n");
      std::abort();
    }
  }
  return base;
}

/// The point of the unit sphere at pixel (x, y) of a 480 x 400 view; none off the image.
bool Pick(double x, double y, double point[3])
{
  if (!(x >= 0.0 && x < 480.0 && y >= 0.0 && y < 400.0))
  {
    return false;
  }
  const double theta = x / 480.0 * 2.0 * M_PI;
  const double phi = y / 400.0 * M_PI;
  point[0] = 0.5 * std::sin(phi) * std::cos(theta);
  point[1] = 0.5 * std::sin(phi) * std::sin(theta);
  point[2] = 0.5 * std::cos(phi);
  return true;
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkObject::GlobalWarningDisplayOff();
  const std::string& path = ofbFuzzWriteInput("ofb-fuzz-strokes", ".txt", data, size);

  // A fresh copy and painter each time: one input's brush and paint do not leak into
  // the next one's run.
  vtkNew<vtkOFB> ofb;
  ofb->DeepCopy(BaseOFB());
  vtkNew<vtkOFBPainter> painter;
  painter->SetOFB(ofb);
  vtkNew<vtkOFBBrush> brush;
  painter->SetBrush(brush);
  ofbpaint::StrokeStatistics statistics;
  std::string error;
  ofbpaint::ReplayStrokes(
    path,
    painter,
    Pick,
    [](double, double, double) {},
    statistics,
    error,
    [](const double*, std::string&) -> long long { return 0; });
  return 0;
}
