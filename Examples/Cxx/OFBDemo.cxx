// OFBDemo: build the Orthogonal Fragment Buffer of a mesh, print its statistics and render
// it into a PNG: left, the samples as a point cloud coloured by grid; right, the surface
// drawn by vtkOFBPolyDataMapper from an OFB paint of grid colours and stripes a few cells
// wide (finer than the triangles).
//
// Usage: OFBDemo [mesh or data file: .obj .ply .stl .vtp .vtu .vtm .pvd .vtk] [--resolution N]
// [--backend auto|cpu|opengl]
//                [--lookup nearest|idw|mipmap|nearestmipmap] [--output file.png] [--width W]
//                [--height H]
//
// Without a mesh it reads Testing/Data/stanford-bunny.obj of the source tree.

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBuilder.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBToPolyData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtksys/SystemTools.hxx"

#include "ofbExampleData.h"
#include "ofbExampleErrors.h"
#include "ofbExampleFiles.h"
#include "ofbExampleOptions.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

namespace
{
using SystemTools = vtksys::SystemTools;

// Grid colours (X red, Y green, Z blue) of both views.
const unsigned char GridColors[3][3] = { { 217, 38, 38 }, { 38, 166, 38 }, { 38, 77, 230 } };
// The paint's stripes: StripeWidth dark cells every StripePeriod cells along y.
const double StripePeriod = 8.0;
const double StripeWidth = 2.0;
const int TimedRenders = 5;

using ErrorCounter = ofbexample::FirstError; // counts error events, keeps the first

void Usage(const char* argv0)
{
  std::cerr << "Usage: " << argv0
            << " [mesh.obj|mesh.ply] [--resolution N] [--backend auto|cpu|opengl]\n"
               "       [--lookup nearest|idw|mipmap|nearestmipmap] [--output file.png] [--width W] "
               "[--height H]\n"
               "Builds the OFB of the mesh (default stanford-bunny.obj, resolution 1024), prints\n"
               "its statistics and renders into a PNG (default ofb-demo.png, 1600 x 800) its\n"
               "samples coloured by grid (X red, Y green, Z blue) and the surface drawn by\n"
               "vtkOFBPolyDataMapper (lookup nearest by default) from an OFB paint of the grid\n"
               "colours with fine stripes.\n";
}

// Signed volume enclosed by the polygons (fan-triangulated): negative when the faces wind
// clockwise seen from outside, i.e. the mesh is inside out.
double SignedVolume(vtkPolyData* mesh)
{
  double volume = 0.0;
  vtkNew<vtkIdList> ids;
  double p0[3], p1[3], p2[3], c[3];
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      mesh->GetPoint(ids->GetId(0), p0);
      mesh->GetPoint(ids->GetId(k), p1);
      mesh->GetPoint(ids->GetId(k + 1), p2);
      vtkMath::Cross(p1, p2, c);
      volume += vtkMath::Dot(p0, c) / 6.0;
    }
  }
  return volume;
}

vtkSmartPointer<vtkTextActor> MakeCaption(const std::string& text)
{
  auto caption = vtkSmartPointer<vtkTextActor>::New();
  caption->SetInput(text.c_str());
  caption->GetTextProperty()->SetFontSize(18);
  caption->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  caption->SetPosition(12, 12); // viewport coordinates
  return caption;
}

// The command line, with its defaults.
struct Options
{
  std::string MeshPath;
  std::string OutputPath = "ofb-demo.png";
  std::string Backend = "auto";
  std::string Lookup = "nearest";
  int Resolution = 1024;
  int Width = 1600;
  int Height = 800;
};

// Parse the command line into `options`. Returns -1 to go on, or the exit status (after
// the usage or a message).
int ParseOptions(int argc, char* argv[], Options& options)
{
  // Options with a value, by long name, with their defaults; the short names.
  std::map<std::string, std::string> values = { { "--resolution", "1024" },
    { "--backend", "auto" },
    { "--lookup", "nearest" },
    { "--output", "ofb-demo.png" },
    { "--width", "1600" },
    { "--height", "800" } };
  const std::map<std::string, std::string> shortNames = {
    { "-r", "--resolution" }, { "-b", "--backend" }, { "-l", "--lookup" }, { "-o", "--output" }
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = shortNames.count(argv[i]) ? shortNames.at(argv[i]) : argv[i];
    if (arg == "-h" || arg == "--help")
    {
      Usage(argv[0]);
      return EXIT_SUCCESS;
    }
    else if (values.count(arg) && i + 1 < argc)
    {
      values[arg] = argv[++i];
    }
    else if (!arg.empty() && arg[0] != '-' && options.MeshPath.empty())
    {
      options.MeshPath = arg;
    }
    else
    {
      std::cerr << "OFBDemo: unexpected argument '" << argv[i] << "'\n";
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }
  if (options.MeshPath.empty())
  {
    options.MeshPath = VTKOFB_DATA_DIR "/stanford-bunny.obj";
  }
  options.OutputPath = values["--output"];
  options.Backend = SystemTools::LowerCase(values["--backend"]);
  options.Lookup = SystemTools::LowerCase(values["--lookup"]);
  const std::string& backend = options.Backend;
  const std::string& lookup = options.Lookup;
  const std::pair<bool, std::string> checks[] = { // each value valid, or the message
    { ofbexample::ParseInt(values["--resolution"], -2147483647, 2147483647, options.Resolution),
      "bad resolution '" + values["--resolution"] + "'" },
    { backend == "auto" || backend == "cpu" || backend == "opengl",
      "unknown backend '" + values["--backend"] + "' (auto, cpu or opengl)" },
    { lookup == "nearest" || lookup == "idw" || lookup == "mipmap" || lookup == "nearestmipmap",
      "unknown lookup '" + values["--lookup"] + "' (nearest, idw, mipmap or nearestmipmap)" },
    { ofbexample::ParseInt(values["--width"], 16, 8192, options.Width),
      "bad width '" + values["--width"] + "'" },
    { ofbexample::ParseInt(values["--height"], 16, 8192, options.Height),
      "bad height '" + values["--height"] + "'" }
  };
  for (const auto& check : checks)
  {
    if (!check.first)
    {
      std::cerr << "OFBDemo: " << check.second << "\n";
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }
  const std::string outputDir =
    SystemTools::GetFilenamePath(SystemTools::CollapseFullPath(options.OutputPath));
  if (!SystemTools::FileIsDirectory(outputDir))
  {
    std::cerr << "OFBDemo: cannot write '" << options.OutputPath << "': no directory '" << outputDir
              << "'\n";
    return EXIT_FAILURE;
  }
  return -1;
}

// Build the OFB of `mesh` with `builder`; false after a message.
bool BuildOFB(vtkPolyData* mesh, const Options& options, vtkOFBBuilder* builder)
{
  vtkNew<ErrorCounter> buildErrors;
  builder->AddObserver(vtkCommand::ErrorEvent, buildErrors);
  builder->SetInputData(mesh);
  builder->SetResolution(options.Resolution);
  builder->SetBackend(options.Backend == "cpu"
      ? vtkOFBBuilder::BACKEND_CPU
      : (options.Backend == "opengl" ? vtkOFBBuilder::BACKEND_OPENGL
                                     : vtkOFBBuilder::BACKEND_AUTO));
  builder->Update();
  vtkOFB* ofb = builder->GetOutput();
  if (buildErrors->Count > 0 || !ofb || ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "OFBDemo: building the OFB at resolution " << options.Resolution << " failed"
              << buildErrors->Suffix() << "\n";
    return false;
  }
  return true;
}

// Print the frame, the samples and depth complexity of each grid, memory and build time.
void PrintStatistics(vtkOFBBuilder* builder, int resolution)
{
  vtkOFB* ofb = builder->GetOutput();
  const double ms = builder->GetLastBuildTime();
  const vtkIdType n = ofb->GetNumberOfSamples();
  const vtkIdType* dims = ofb->GetDimensions();
  const char* axes[3] = { "X", "Y", "Z" };
  std::cout << std::fixed << "Resolution:        " << resolution << " (frame " << dims[0] << " x "
            << dims[1] << " x " << dims[2] << " cells, cell size " << std::setprecision(6)
            << ofb->GetCellSize() << ")\n"
            << "Backend:           " << vtkOFBBuilder::GetBackendAsString(builder->GetLastBackend())
            << "\n"
            << "Samples:           " << n << "\n";
  for (int a = 0; a < 3; ++a)
  {
    vtkIdType nu, nv;
    ofb->GetGridDimensions(a, nu, nv);
    std::cout << "  grid " << axes[a] << " (" << nu << " x " << nv << "): " << std::setw(10)
              << ofb->GetNumberOfSamples(a) << " samples, depth complexity "
              << ofb->GetDepthComplexity(a) << "\n";
  }
  std::cout << "Depth complexity:  " << ofb->GetDepthComplexity() << "\n"
            << std::setprecision(2) << "Bytes per sample:  " << ofb->GetBytesPerSample() << "\n"
            << "Memory:            " << ofb->GetActualMemorySize() / 1024.0 << " MB\n"
            << "Build time:        " << ms << " ms\n";
  if (ms > 0.0)
  {
    std::cout << "Throughput:        " << std::setprecision(1) << (n / (ms * 1e-3)) / 1e6
              << " million samples/s\n";
  }
  else
  {
    std::cout << "Throughput:        n/a (build time below the timer's resolution)\n";
  }
}

// Write the OFB's paint: each sample in the colour of its grid, darkened in stripes
// StripeWidth cells wide every StripePeriod cells along y, much finer than the triangles.
// Returns the samples as a point cloud coloured by grid alone, or null after a message.
vtkSmartPointer<vtkPolyData> PaintGridColors(vtkOFBBuilder* builder)
{
  vtkOFB* ofb = builder->GetOutput();
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkOFBToPolyData> toPoints;
  toPoints->SetInputConnection(builder->GetOutputPort());
  toPoints->Update();
  vtkSmartPointer<vtkPolyData> cloud = toPoints->GetOutput(); // point i is sample i
  auto* paint = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  if (!paint || paint->GetNumberOfComponents() != 4 || cloud->GetNumberOfPoints() != n)
  {
    std::cerr << "OFBDemo: the OFB has no RGBA Colors sample array or no point cloud\n";
    return nullptr;
  }
  vtkNew<vtkUnsignedCharArray> gridColors;
  gridColors->SetName("GridColors");
  gridColors->SetNumberOfComponents(3);
  gridColors->SetNumberOfTuples(n);
  const double* origin = ofb->GetOrigin();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const double stripe = std::fmod((x[1] - origin[1]) / ofb->GetCellSize(), StripePeriod);
    const unsigned char* rgb = GridColors[ofb->GetSampleAxis(i)];
    gridColors->SetTypedTuple(i, rgb);
    for (int c = 0; c < 3; ++c)
    {
      paint->SetTypedComponent(i, c, stripe < StripeWidth ? rgb[c] / 4 : rgb[c]);
    }
    paint->SetTypedComponent(i, 3, 255);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
  cloud->GetPointData()->SetScalars(gridColors);
  return cloud;
}

// Points are lit with the sample normals; an inside-out mesh (horse.ply, for one) would
// render dark, so turn its normals around for the picture only. (The surface needs no
// such care: two-sided lighting turns its normals toward the camera.)
void FlipNormalsOfInsideOutMesh(vtkPolyData* mesh, vtkPolyData* cloud)
{
  vtkDataArray* normals = cloud->GetPointData()->GetNormals();
  if (!normals || SignedVolume(mesh) >= 0.0)
  {
    return;
  }
  std::cout << "Note:              the mesh is inside out (negative volume); its normals are "
               "flipped for display\n";
  vtkSmartPointer<vtkDataArray> flipped = vtk::TakeSmartPointer(normals->NewInstance());
  flipped->DeepCopy(normals);
  for (vtkIdType v = 0; v < flipped->GetNumberOfValues(); ++v)
  {
    flipped->SetVariantValue(v, -flipped->GetVariantValue(v).ToDouble());
  }
  cloud->GetPointData()->SetNormals(flipped);
}

// The picture: left, the point cloud; right, the surface coloured per fragment from the
// paint; two viewports with one camera, captions below.
struct Scene
{
  vtkNew<vtkActor> CloudActor;
  vtkNew<vtkActor> SurfaceActor;
  vtkNew<vtkOFBPolyDataMapper> SurfaceMapper;
  vtkNew<vtkRenderer> Left;
  vtkNew<vtkRenderer> Right;
  vtkNew<vtkRenderWindow> Window;

  void Build(vtkPolyData* mesh, vtkPolyData* cloud, vtkOFB* ofb, const Options& options)
  {
    vtkNew<vtkPolyDataMapper> cloudMapper;
    cloudMapper->SetInputData(cloud);
    this->CloudActor->SetMapper(cloudMapper);
    this->CloudActor->GetProperty()->SetPointSize(1.5);
    this->SurfaceMapper->SetInputData(mesh);
    this->SurfaceMapper->SetOFB(ofb);
    const std::map<std::string, int> modes = { { "idw",
                                                 vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE },
      { "mipmap", vtkOFBPolyDataMapper::LOOKUP_MIPMAPPED },
      { "nearestmipmap", vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED } };
    const auto mode = modes.find(options.Lookup);
    this->SurfaceMapper->SetLookupMode(
      mode != modes.end() ? mode->second : vtkOFBPolyDataMapper::LOOKUP_NEAREST);
    this->SurfaceActor->SetMapper(this->SurfaceMapper);
    for (vtkActor* actor : { this->CloudActor.Get(), this->SurfaceActor.Get() })
    {
      actor->GetProperty()->SetAmbient(0.25);
      actor->GetProperty()->SetDiffuse(0.75);
    }
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(options.Width, options.Height);
    this->Left->SetViewport(0.0, 0.0, 0.5, 1.0);
    this->Right->SetViewport(0.5, 0.0, 1.0, 1.0);
    this->Left->AddActor(this->CloudActor);
    this->Left->AddViewProp(MakeCaption(SystemTools::GetFilenameName(options.MeshPath) + ": " +
      std::to_string(ofb->GetNumberOfSamples()) + " OFB samples at resolution " +
      std::to_string(options.Resolution) + "\nsamples of grid X red, grid Y green, grid Z blue"));
    this->Right->AddActor(this->SurfaceActor);
    this->Right->AddViewProp(MakeCaption("surface by vtkOFBPolyDataMapper (" + options.Lookup +
      " lookup): OFB paint of\ngrid colours, dark stripes " + std::to_string(int(StripeWidth)) +
      " cells wide every " + std::to_string(int(StripePeriod)) + " cells"));
    this->Right->SetActiveCamera(this->Left->GetActiveCamera());
    for (vtkRenderer* renderer : { this->Left.Get(), this->Right.Get() })
    {
      renderer->SetBackground(0.88, 0.88, 0.88);
      this->Window->AddRenderer(renderer);
    }
  }

  // Look at the front of the model: in the bunny's scan frame y is up and the head points
  // to -x, so start on +z and turn 35 degrees toward -x, a little above.
  void AimCamera(vtkPolyData* mesh)
  {
    double center[3];
    mesh->GetCenter(center);
    vtkCamera* camera = this->Left->GetActiveCamera();
    camera->SetFocalPoint(center);
    camera->SetPosition(center[0], center[1], center[2] + 1.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->Azimuth(-35.0);
    camera->Elevation(10.0);
    camera->OrthogonalizeViewUp();
    this->Left->ResetCamera();
    camera->Zoom(1.2);
  }

  // Print the frame time of the mapper alone: the point cloud hidden, the GPU waited for.
  void TimeMapper(const Options& options)
  {
    this->CloudActor->VisibilityOff();
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < TimedRenders; ++k)
    {
      this->Window->Render();
      this->Window->WaitForCompletion();
    }
    const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
    this->CloudActor->VisibilityOn();
    this->Window->Render();
    std::cout << "Mapper lookup:     "
              << vtkOFBPolyDataMapper::GetLookupModeAsString(this->SurfaceMapper->GetLookupMode())
              << "\n"
              << "Mapper frame time: " << std::setprecision(1) << elapsed.count() / TimedRenders
              << " ms (surface only, average of " << TimedRenders << " renders at "
              << options.Width / 2 << " x " << options.Height << ")\n";
  }
};

// Write the window into the PNG `path` (staged and renamed into place); false after a
// message.
bool WritePicture(vtkRenderWindow* window, const Options& options)
{
  const std::string& path = options.OutputPath;
  std::string message;
  if (!ofbexample::WriteWindowPNG(window, path, message))
  {
    std::cerr << "OFBDemo: " << message << "\n";
    return false;
  }
  std::cout << "Wrote " << SystemTools::CollapseFullPath(path) << " (" << options.Width << " x "
            << options.Height << ")\n";
  return true;
}
}

int main(int argc, char* argv[])
{
  Options options;
  const int status = ParseOptions(argc, argv, options);
  if (status >= 0)
  {
    return status;
  }

  // 1. Read the mesh.
  std::string readError;
  ofbexample::DataSurface data;
  if (!ofbexample::ReadDataSurface(options.MeshPath, {}, false, data, readError))
  {
    std::cerr << "OFBDemo: " << readError << "\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkPolyData> mesh = data.Surface;
  std::cout << "Mesh:              " << options.MeshPath << "\n"
            << "                   " << mesh->GetNumberOfPoints() << " points, "
            << mesh->GetNumberOfPolys() << " polygons\n";

  // 2. Build its OFB and print its statistics.
  vtkNew<vtkOFBBuilder> builder;
  if (!BuildOFB(mesh, options, builder))
  {
    return EXIT_FAILURE;
  }
  PrintStatistics(builder, options.Resolution);

  // 3. Paint it, and make the point cloud.
  vtkSmartPointer<vtkPolyData> cloud = PaintGridColors(builder);
  if (!cloud)
  {
    return EXIT_FAILURE;
  }
  FlipNormalsOfInsideOutMesh(mesh, cloud);

  // 4. Render both views, time the mapper, write the picture.
  Scene scene;
  scene.Build(mesh, cloud, builder->GetOutput(), options);
  scene.AimCamera(mesh);
  scene.Window->Render();
  if (!scene.SurfaceMapper->GetLastRenderUsedOFB())
  {
    std::cout << "Note:              the mapper could not colour from the OFB (see the "
                 "warning); the surface shows the plain property colour\n";
  }
  scene.TimeMapper(options);
  return WritePicture(scene.Window, options) ? EXIT_SUCCESS : EXIT_FAILURE;
}
