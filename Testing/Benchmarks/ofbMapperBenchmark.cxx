// ofbMapperBenchmark: frame time of vtkOFBPolyDataMapper (Nearest, InverseDistance,
// Mipmapped) against VTK's own poly data mapper with vertex colours, on the same mesh
// (the Stanford bunny by default) in the same window, printed as ratios.
// Not a test: run it by hand, under xvfb-run on a headless machine:
//   xvfb-run -a -s "-screen 0 1280x1024x24" ofbMapperBenchmark [options]
// Options: --mesh FILE (.obj/.ply), --resolution N (OFB cells, default 1024),
// --frames N (timed frames per mapper, default 30), --width W --height H (1280x1024).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOFB.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
// The same colour for a vertex and for a sample: bands of the position.
void ColorAt(const double x[3], const double bounds[6], unsigned char rgba[4])
{
  double t[3];
  for (int i = 0; i < 3; ++i)
  {
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    t[i] = extent > 0.0 ? (x[i] - bounds[2 * i]) / extent : 0.0;
  }
  rgba[0] = static_cast<unsigned char>(127.5 + 127.5 * std::sin(12.0 * t[0]));
  rgba[1] = static_cast<unsigned char>(127.5 + 127.5 * std::sin(12.0 * t[1] + 1.0));
  rgba[2] = static_cast<unsigned char>(127.5 + 127.5 * std::sin(12.0 * t[2] + 2.0));
  rgba[3] = 255;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".ply")
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  else
  {
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    return nullptr;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

// Milliseconds per frame of `frames` renders (after warm-up) while the camera turns.
double TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, int frames)
{
  vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  for (int i = 0; i < 3; ++i)
  {
    window->Render();
  }
  if (gl)
  {
    gl->WaitForCompletion();
  }
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i)
  {
    renderer->GetActiveCamera()->Azimuth(360.0 / frames);
    window->Render();
    if (gl)
    {
      gl->WaitForCompletion();
    }
  }
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(stop - start).count() / frames;
}
}

int main(int argc, char* argv[])
{
  std::string mesh = std::string(VTKOFB_BENCHMARK_DATA_DIR) + "/stanford-bunny.obj";
  int resolution = 1024;
  int frames = 30;
  int width = 1280;
  int height = 1024;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--mesh" && hasValue)
    {
      mesh = argv[++i];
    }
    else if (arg == "--resolution" && hasValue)
    {
      resolution = std::atoi(argv[++i]);
    }
    else if (arg == "--frames" && hasValue)
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--width" && hasValue)
    {
      width = std::atoi(argv[++i]);
    }
    else if (arg == "--height" && hasValue)
    {
      height = std::atoi(argv[++i]);
    }
    else
    {
      std::cout << "usage: ofbMapperBenchmark [--mesh FILE] [--resolution N] [--frames N] "
                   "[--width W] [--height H]\n";
      return arg == "--help" ? 0 : 1;
    }
  }

  vtkSmartPointer<vtkPolyData> surface = ReadMesh(mesh);
  if (!surface)
  {
    std::cerr << "Cannot read a surface from " << mesh << "\n";
    return 1;
  }
  double bounds[6];
  surface->GetBounds(bounds);

  // Vertex colours for the peer.
  vtkSmartPointer<vtkPolyData> colored = vtkSmartPointer<vtkPolyData>::New();
  colored->ShallowCopy(surface);
  vtkNew<vtkUnsignedCharArray> vertexColors;
  vertexColors->SetName("Colors");
  vertexColors->SetNumberOfComponents(4);
  vertexColors->SetNumberOfTuples(surface->GetNumberOfPoints());
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    unsigned char rgba[4];
    ColorAt(surface->GetPoint(i), bounds, rgba);
    vertexColors->SetTypedTuple(i, rgba);
  }
  colored->GetPointData()->SetScalars(vertexColors);

  // The OFB, with the same colours per sample.
  vtkNew<vtkOFBSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetResolution(resolution);
  sampler->Update();
  vtkOFB* ofb = sampler->GetOutput();
  if (ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "The OFB build failed.\n";
    return 1;
  }
  auto* sampleColors =
    vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    unsigned char rgba[4];
    ColorAt(x, bounds, rgba);
    sampleColors->SetTypedTuple(i, rgba);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.2, 0.25);
  window->AddRenderer(renderer);
  vtkNew<vtkActor> actor;
  renderer->AddActor(actor);

  vtkNew<vtkPolyDataMapper> peer;
  peer->SetInputData(colored);
  actor->SetMapper(peer);
  renderer->ResetCamera();
  window->Render();
  const std::string renderer_name =
    window->ReportCapabilities() ? window->ReportCapabilities() : "";
  const double peerMs = TimeFrames(window, renderer, frames);

  std::cout << "ofbMapperBenchmark: " << mesh << "\n"
            << "  triangles " << surface->GetNumberOfPolys() << ", OFB resolution "
            << resolution << ", samples " << ofb->GetNumberOfSamples() << ", window " << width
            << "x" << height << ", " << frames << " frames per mapper\n";
  const std::string::size_type at = renderer_name.find("OpenGL renderer string:");
  if (at != std::string::npos)
  {
    std::cout << "  " << renderer_name.substr(at, renderer_name.find('\n', at) - at) << "\n";
  }
  std::cout << std::fixed << std::setprecision(2);
  std::cout << "  vtkPolyDataMapper, vertex colours        " << std::setw(8) << peerMs
            << " ms/frame\n";

  const int modes[3] = { vtkOFBPolyDataMapper::Nearest, vtkOFBPolyDataMapper::InverseDistance,
    vtkOFBPolyDataMapper::Mipmapped };
  double nearestRatio = 0.0;
  for (int mode : modes)
  {
    vtkNew<vtkOFBPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->SetOFB(ofb);
    mapper->SetLookupMode(mode);
    actor->SetMapper(mapper);
    window->Render();
    if (!mapper->GetLastRenderUsedOFB())
    {
      std::cerr << "vtkOFBPolyDataMapper could not use the OFB on this context.\n";
      return 1;
    }
    const double ms = TimeFrames(window, renderer, frames);
    const double ratio = ms / peerMs;
    if (mode == vtkOFBPolyDataMapper::Nearest)
    {
      nearestRatio = ratio;
    }
    std::cout << "  vtkOFBPolyDataMapper, " << std::left << std::setw(18)
              << vtkOFBPolyDataMapper::GetLookupModeAsString(mode) << std::right << std::setw(8)
              << ms << " ms/frame, ratio " << ratio << "\n";
    mapper->ReleaseGraphicsResources(window);
  }
  std::cout << "  goal: Nearest at most 2x the vertex-colour mapper: "
            << (nearestRatio <= 2.0 ? "met" : "NOT met") << " (" << nearestRatio << "x)\n";
  return 0;
}
