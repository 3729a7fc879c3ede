// ofbDemo: build the Orthogonal Fragment Buffer of a mesh, print its statistics and render
// it into a PNG: left, the samples as a point cloud coloured by grid; right, the surface
// drawn by vtkOFBPolyDataMapper from an OFB paint of grid colours and stripes a few cells
// wide (finer than the triangles).
//
// Usage: ofbDemo [mesh.obj|mesh.ply] [--resolution N] [--backend auto|cpu|opengl]
//                [--lookup nearest|idw|mipmap] [--output file.png] [--width W] [--height H]
//
// Without a mesh it reads Testing/Data/stanford-bunny.obj of the source tree.

#include "vtkAbstractPolyDataReader.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOFB.h"
#include "vtkOFBBuilder.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBToPolyData.h"
#include "vtkPLYReader.h"
#include "vtkPNGWriter.h"
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
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
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

// Counts the error events of the objects it observes and keeps the last message, so that
// a failed read, build or write is reported even when the pipeline itself does not fail.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    // VTK's text is "ERROR: In <file>, line <n>\n<class> (<address>): <message>\n".
    std::string text = data ? static_cast<const char*>(data) : "";
    const std::string::size_type start = text.find("): ");
    text = start == std::string::npos ? text : text.substr(start + 3);
    this->Last = text.substr(0, text.find_last_not_of(" \n") + 1);
  }
  std::string Suffix() const { return this->Last.empty() ? std::string() : ": " + this->Last; }
  int Count = 0;
  std::string Last;
};

void Usage(const char* argv0)
{
  std::cerr << "Usage: " << argv0
            << " [mesh.obj|mesh.ply] [--resolution N] [--backend auto|cpu|opengl]\n"
               "       [--lookup nearest|idw|mipmap] [--output file.png] [--width W] "
               "[--height H]\n"
               "Builds the OFB of the mesh (default stanford-bunny.obj, resolution 1024), prints\n"
               "its statistics and renders into a PNG (default ofb-demo.png, 1600 x 800) its\n"
               "samples coloured by grid (X red, Y green, Z blue) and the surface drawn by\n"
               "vtkOFBPolyDataMapper (lookup nearest by default) from an OFB paint of the grid\n"
               "colours with fine stripes.\n";
}

bool ParseInt(const std::string& text, int low, int high, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  const bool ok = !text.empty() && !*end && v >= low && v <= high;
  value = ok ? static_cast<int>(v) : value;
  return ok;
}

// VTK 9.1's PLY reader crashes on a truncated file: check that the header is complete and
// that the body is at least as long as its elements need (binary files; lists counted with
// their smallest possible length) or has a line per element (ASCII files).
bool CheckPLY(const std::string& path, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    error = "not a PLY file";
    return false;
  }
  // clang-format off
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "uchar", 1 }, { "int8", 1 },
    { "uint8", 1 }, { "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 }, { "int", 4 },
    { "uint", 4 }, { "int32", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
    { "double", 8 }, { "float64", 8 } };
  // clang-format on
  bool ascii = false, complete = false;
  long long elements = 0, count = 0, minBytes = 0;
  while (!complete && std::getline(in, line))
  {
    line.erase(line.find_last_not_of('\r') + 1);
    std::istringstream words(line);
    std::string key, a, b, c;
    words >> key >> a;
    bool bad = false;
    if (key == "format")
    {
      ascii = a == "ascii";
    }
    else if (key == "element")
    {
      bad = !(words >> count) || count < 0;
      elements += bad ? 0 : count;
    }
    else if (key == "property")
    {
      // A list is sized by its count type b, and needs a valid item type c.
      const std::string type = a == "list" && (words >> b >> c) && sizes.count(c) ? b : a;
      bad = !sizes.count(type);
      minBytes += bad ? 0 : count * sizes.at(type);
    }
    if (bad)
    {
      error = "bad " + key + " line '" + line + "'";
      return false;
    }
    complete = key == "end_header";
  }
  if (!complete)
  {
    error = "the PLY header has no end_header";
    return false;
  }
  long long lines = 0;
  while (ascii && lines < elements && std::getline(in, line))
  {
    lines += line.find_first_not_of(" \t\r") != std::string::npos;
  }
  const std::streamoff body = in.tellg();
  in.seekg(0, std::ios::end);
  if (ascii ? lines < elements : in.tellg() - body < minBytes)
  {
    error = "the file is truncated";
    return false;
  }
  return true;
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

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error)
{
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path));
  vtkSmartPointer<vtkAbstractPolyDataReader> reader;
  if (!SystemTools::FileExists(path, true))
  {
    error = "no such file";
  }
  else if (ext == ".ply")
  {
    reader = CheckPLY(path, error) ? vtkSmartPointer<vtkPLYReader>::New() : nullptr;
  }
  else if (ext == ".obj")
  {
    reader = vtkSmartPointer<vtkOBJReader>::New();
  }
  else
  {
    error = "unsupported extension '" + ext + "' (use .obj or .ply)";
  }
  if (!reader)
  {
    return nullptr;
  }
  vtkNew<ErrorCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
  error = errors->Count > 0
    ? (errors->Last.empty() ? "the reader failed" : errors->Last)
    : (!mesh || mesh->GetNumberOfPolys() == 0 ? "no polygons in the file" : "");
  return error.empty() ? mesh : nullptr;
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
}

int main(int argc, char* argv[])
{
  // Options with a value, by long name, with their defaults; the short names.
  std::map<std::string, std::string> options = { { "--resolution", "1024" },
    { "--backend", "auto" },
    { "--lookup", "nearest" },
    { "--output", "ofb-demo.png" },
    { "--width", "1600" },
    { "--height", "800" } };
  const std::map<std::string, std::string> shortNames = {
    { "-r", "--resolution" }, { "-b", "--backend" }, { "-l", "--lookup" }, { "-o", "--output" }
  };
  std::string meshPath;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = shortNames.count(argv[i]) ? shortNames.at(argv[i]) : argv[i];
    if (arg == "-h" || arg == "--help")
    {
      Usage(argv[0]);
      return EXIT_SUCCESS;
    }
    else if (options.count(arg) && i + 1 < argc)
    {
      options[arg] = argv[++i];
    }
    else if (!arg.empty() && arg[0] != '-' && meshPath.empty())
    {
      meshPath = arg;
    }
    else
    {
      std::cerr << "ofbDemo: unexpected argument '" << argv[i] << "'\n";
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }
  meshPath = meshPath.empty() ? VTKOFB_DATA_DIR "/stanford-bunny.obj" : meshPath;
  const std::string outputPath = options["--output"];
  const std::string backend = SystemTools::LowerCase(options["--backend"]);
  const std::string lookup = SystemTools::LowerCase(options["--lookup"]);
  int resolution = 0, width = 0, height = 0;
  const std::pair<bool, std::string> checks[] = { // each value valid, or the message
    { ParseInt(options["--resolution"], -2147483647, 2147483647, resolution),
      "bad resolution '" + options["--resolution"] + "'" },
    { backend == "auto" || backend == "cpu" || backend == "opengl",
      "unknown backend '" + options["--backend"] + "' (auto, cpu or opengl)" },
    { lookup == "nearest" || lookup == "idw" || lookup == "mipmap",
      "unknown lookup '" + options["--lookup"] + "' (nearest, idw or mipmap)" },
    { ParseInt(options["--width"], 16, 8192, width), "bad width '" + options["--width"] + "'" },
    { ParseInt(options["--height"], 16, 8192, height), "bad height '" + options["--height"] + "'" }
  };
  for (const auto& check : checks)
  {
    if (!check.first)
    {
      std::cerr << "ofbDemo: " << check.second << "\n";
      return EXIT_FAILURE;
    }
  }
  const std::string outputDir =
    SystemTools::GetFilenamePath(SystemTools::CollapseFullPath(outputPath));
  if (!SystemTools::FileIsDirectory(outputDir))
  {
    std::cerr << "ofbDemo: cannot write '" << outputPath << "': no directory '" << outputDir
              << "'\n";
    return EXIT_FAILURE;
  }

  // 1. Read the mesh.
  std::string readError;
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(meshPath, readError);
  if (!mesh)
  {
    std::cerr << "ofbDemo: cannot read mesh '" << meshPath << "': " << readError << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Mesh:              " << meshPath << "\n"
            << "                   " << mesh->GetNumberOfPoints() << " points, "
            << mesh->GetNumberOfPolys() << " polygons\n";

  // 2. Build its OFB.
  vtkNew<vtkOFBBuilder> builder;
  vtkNew<ErrorCounter> buildErrors;
  builder->AddObserver(vtkCommand::ErrorEvent, buildErrors);
  builder->SetInputData(mesh);
  builder->SetResolution(resolution);
  builder->SetBackend(backend == "cpu"
      ? vtkOFBBuilder::CPU
      : (backend == "opengl" ? vtkOFBBuilder::OpenGL : vtkOFBBuilder::Auto));
  builder->Update();
  vtkOFB* ofb = builder->GetOutput();
  if (buildErrors->Count > 0 || !ofb || ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "ofbDemo: building the OFB at resolution " << resolution << " failed"
              << buildErrors->Suffix() << "\n";
    return EXIT_FAILURE;
  }

  // 3. Statistics.
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

  // 4. The OFB's paint: each sample in the colour of its grid, darkened in stripes
  // StripeWidth cells wide every StripePeriod cells along y, much finer than the triangles.
  // The point cloud gets the grid colours alone.
  vtkNew<vtkOFBToPolyData> toPoints;
  toPoints->SetInputConnection(builder->GetOutputPort());
  toPoints->Update();
  vtkPolyData* cloud = toPoints->GetOutput(); // point i is sample i
  auto* paint = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  if (!paint || paint->GetNumberOfComponents() != 4 || cloud->GetNumberOfPoints() != n)
  {
    std::cerr << "ofbDemo: the OFB has no RGBA Colors sample array or no point cloud\n";
    return EXIT_FAILURE;
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

  // Points are lit with the sample normals; an inside-out mesh (horse.ply, for one) would
  // render dark, so turn its normals around for the picture only. (The surface needs no
  // such care: two-sided lighting turns its normals toward the camera.)
  vtkDataArray* normals = cloud->GetPointData()->GetNormals();
  if (normals && SignedVolume(mesh) < 0.0)
  {
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

  // 5. Left, the point cloud; right, the surface coloured per fragment from the paint.
  vtkNew<vtkPolyDataMapper> cloudMapper;
  cloudMapper->SetInputData(cloud);
  vtkNew<vtkActor> cloudActor;
  cloudActor->SetMapper(cloudMapper);
  cloudActor->GetProperty()->SetPointSize(1.5);
  vtkNew<vtkOFBPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputData(mesh);
  surfaceMapper->SetOFB(ofb);
  surfaceMapper->SetLookupMode(lookup == "idw"
      ? vtkOFBPolyDataMapper::InverseDistance
      : (lookup == "mipmap" ? vtkOFBPolyDataMapper::Mipmapped : vtkOFBPolyDataMapper::Nearest));
  vtkNew<vtkActor> surfaceActor;
  surfaceActor->SetMapper(surfaceMapper);
  for (vtkActor* actor : { cloudActor.Get(), surfaceActor.Get() })
  {
    actor->GetProperty()->SetAmbient(0.25);
    actor->GetProperty()->SetDiffuse(0.75);
  }

  // 6. Two viewports with one camera, captions below.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  left->AddActor(cloudActor);
  left->AddViewProp(MakeCaption(SystemTools::GetFilenameName(meshPath) + ": " + std::to_string(n) +
    " OFB samples at resolution " + std::to_string(resolution) +
    "\nsamples of grid X red, grid Y green, grid Z blue"));
  right->AddActor(surfaceActor);
  right->AddViewProp(MakeCaption("surface by vtkOFBPolyDataMapper (" + lookup +
    " lookup): OFB paint of\ngrid colours, dark stripes " + std::to_string(int(StripeWidth)) +
    " cells wide every " + std::to_string(int(StripePeriod)) + " cells"));
  right->SetActiveCamera(left->GetActiveCamera());
  for (vtkRenderer* renderer : { left.Get(), right.Get() })
  {
    renderer->SetBackground(0.88, 0.88, 0.88);
    window->AddRenderer(renderer);
  }

  // Look at the front of the model: in the bunny's scan frame y is up and the head points
  // to -x, so start on +z and turn 35 degrees toward -x, a little above.
  double center[3];
  mesh->GetCenter(center);
  vtkCamera* camera = left->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0], center[1], center[2] + 1.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Azimuth(-35.0);
  camera->Elevation(10.0);
  camera->OrthogonalizeViewUp();
  left->ResetCamera();
  camera->Zoom(1.2);
  window->Render();
  if (!surfaceMapper->GetLastRenderUsedOFB())
  {
    std::cout << "Note:              the mapper could not colour from the OFB (see the "
                 "warning); the surface shows the plain property colour\n";
  }

  // Frame time of the mapper alone: the point cloud hidden, the GPU waited for.
  cloudActor->VisibilityOff();
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < TimedRenders; ++k)
  {
    window->Render();
    window->WaitForCompletion();
  }
  const std::chrono::duration<double, std::milli> elapsed =
    std::chrono::steady_clock::now() - start;
  cloudActor->VisibilityOn();
  window->Render();
  std::cout << "Mapper lookup:     "
            << vtkOFBPolyDataMapper::GetLookupModeAsString(surfaceMapper->GetLookupMode()) << "\n"
            << "Mapper frame time: " << std::setprecision(1) << elapsed.count() / TimedRenders
            << " ms (surface only, average of " << TimedRenders << " renders at " << width / 2
            << " x " << height << ")\n";

  // 7. Write the picture.
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<ErrorCounter> writeErrors;
  vtkNew<vtkPNGWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, writeErrors);
  writer->SetFileName(outputPath.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writeErrors->Count > 0 || !SystemTools::FileExists(outputPath, true))
  {
    std::cerr << "ofbDemo: cannot write '" << outputPath << "'" << writeErrors->Suffix() << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Wrote " << SystemTools::CollapseFullPath(outputPath) << " (" << width << " x "
            << height << ")\n";
  return EXIT_SUCCESS;
}
