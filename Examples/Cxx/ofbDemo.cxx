// ofbDemo: build the Orthogonal Fragment Buffer of a mesh, print its statistics and
// render its samples as a point cloud coloured by grid into a PNG.
//
// Usage: ofbDemo [mesh.obj|mesh.ply] [--resolution N] [--backend auto|cpu|opengl]
//                [--output file.png] [--width W] [--height H]
//
// Without a mesh it reads Testing/Data/stanford-bunny.obj of the source tree.

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkIdList.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOFB.h"
#include "vtkOFBBuilder.h"
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
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#ifndef VTKOFB_DEFAULT_MESH
#define VTKOFB_DEFAULT_MESH "stanford-bunny.obj"
#endif

namespace
{
// Counts the error events of the objects it observes, so that a failed read or
// build is reported even when the pipeline itself does not fail.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    if (data)
    {
      // VTK's text is "ERROR: In <file>, line <n>\n<class> (<address>): <message>\n":
      // keep the message.
      std::string text = static_cast<const char*>(data);
      const std::string::size_type start = text.find("): ");
      if (start != std::string::npos)
      {
        text = text.substr(start + 3);
      }
      const std::string::size_type end = text.find_last_not_of(" \n");
      this->Last = end == std::string::npos ? std::string() : text.substr(0, end + 1);
    }
  }
  int Count = 0;
  std::string Last;
};

void Usage(const char* argv0)
{
  std::cerr << "Usage: " << argv0
            << " [mesh.obj|mesh.ply] [--resolution N] [--backend auto|cpu|opengl]\n"
               "       [--output file.png] [--width W] [--height H]\n"
               "Builds the OFB of the mesh (default " VTKOFB_DEFAULT_MESH
               ", resolution 1024), prints its statistics\n"
               "and renders its samples coloured by grid (X red, Y green, Z blue) into a PNG\n"
               "(default ofb-demo.png).\n";
}

bool ParseInt(const char* text, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (!text[0] || *end || v < -2147483647L || v > 2147483647L)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

// VTK 9.1's PLY reader crashes on a truncated file: check that the header is
// complete and that the body is at least as long as its elements need (binary
// files; lists counted with their smallest possible length) or has a line per
// element (ASCII files).
bool CheckPLY(const std::string& path, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    error = "not a PLY file";
    return false;
  }
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "uchar", 1 }, { "int8", 1 },
    { "uint8", 1 }, { "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 }, { "int", 4 },
    { "uint", 4 }, { "int32", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
    { "double", 8 }, { "float64", 8 } };
  bool ascii = false, complete = false;
  long long elements = 0, count = 0, minBytes = 0;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string key, a, b, c;
    words >> key;
    if (key == "format")
    {
      words >> a;
      ascii = a == "ascii";
    }
    else if (key == "element")
    {
      words >> a >> count;
      if (!words || count < 0)
      {
        error = "bad element line '" + line + "'";
        return false;
      }
      elements += count;
    }
    else if (key == "property")
    {
      words >> a;
      if (a == "list")
      {
        words >> b >> c;
        if (!sizes.count(b) || !sizes.count(c))
        {
          error = "bad property line '" + line + "'";
          return false;
        }
        minBytes += count * sizes.at(b);
      }
      else if (sizes.count(a))
      {
        minBytes += count * sizes.at(a);
      }
      else
      {
        error = "bad property line '" + line + "'";
        return false;
      }
    }
    else if (key == "end_header")
    {
      complete = true;
      break;
    }
  }
  if (!complete)
  {
    error = "the PLY header has no end_header";
    return false;
  }
  if (ascii)
  {
    long long lines = 0;
    while (lines < elements && std::getline(in, line))
    {
      lines += line.find_first_not_of(" \t\r") != std::string::npos;
    }
    if (lines < elements)
    {
      error = "the file is truncated";
      return false;
    }
    return true;
  }
  const std::streamoff body = in.tellg();
  in.seekg(0, std::ios::end);
  if (in.tellg() - body < minBytes)
  {
    error = "the file is truncated";
    return false;
  }
  return true;
}

// Signed volume enclosed by the polygons (fan-triangulated): negative when the
// faces wind clockwise seen from outside, i.e. the mesh is inside out.
double SignedVolume(vtkPolyData* mesh)
{
  double volume = 0.0;
  vtkCellArray* polys = mesh->GetPolys();
  vtkNew<vtkIdList> ids;
  double p0[3], p1[3], p2[3], c[3];
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    if (ids->GetNumberOfIds() < 3)
    {
      continue;
    }
    mesh->GetPoint(ids->GetId(0), p0);
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
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
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    error = "no such file";
    return nullptr;
  }
  const std::string ext = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  vtkNew<ErrorCounter> errors;
  vtkSmartPointer<vtkPolyData> mesh;
  if (ext == ".ply")
  {
    if (!CheckPLY(path, error))
    {
      return nullptr;
    }
    vtkNew<vtkPLYReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  else if (ext == ".obj")
  {
    vtkNew<vtkOBJReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    reader->Update();
    mesh = reader->GetOutput();
  }
  else
  {
    error = "unsupported extension '" + ext + "' (use .obj or .ply)";
    return nullptr;
  }
  if (errors->Count > 0)
  {
    error = errors->Last.empty() ? "the reader failed" : errors->Last;
    return nullptr;
  }
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    error = "no polygons in the file";
    return nullptr;
  }
  return mesh;
}
}

int main(int argc, char* argv[])
{
  std::string meshPath = std::string(VTKOFB_DATA_DIR) + "/" + VTKOFB_DEFAULT_MESH;
  std::string outputPath = "ofb-demo.png";
  std::string backend = "auto";
  int resolution = 1024;
  int width = 1024;
  int height = 768;
  bool haveMesh = false;

  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "-h" || arg == "--help")
    {
      Usage(argv[0]);
      return EXIT_SUCCESS;
    }
    else if ((arg == "-r" || arg == "--resolution") && hasValue)
    {
      if (!ParseInt(argv[++i], resolution))
      {
        std::cerr << "ofbDemo: bad resolution '" << argv[i] << "'\n";
        return EXIT_FAILURE;
      }
    }
    else if ((arg == "-o" || arg == "--output") && hasValue)
    {
      outputPath = argv[++i];
    }
    else if ((arg == "-b" || arg == "--backend") && hasValue)
    {
      backend = vtksys::SystemTools::LowerCase(argv[++i]);
      if (backend != "auto" && backend != "cpu" && backend != "opengl")
      {
        std::cerr << "ofbDemo: unknown backend '" << argv[i] << "' (auto, cpu or opengl)\n";
        return EXIT_FAILURE;
      }
    }
    else if (arg == "--width" && hasValue)
    {
      if (!ParseInt(argv[++i], width) || width < 16 || width > 8192)
      {
        std::cerr << "ofbDemo: bad width '" << argv[i] << "'\n";
        return EXIT_FAILURE;
      }
    }
    else if (arg == "--height" && hasValue)
    {
      if (!ParseInt(argv[++i], height) || height < 16 || height > 8192)
      {
        std::cerr << "ofbDemo: bad height '" << argv[i] << "'\n";
        return EXIT_FAILURE;
      }
    }
    else if (!arg.empty() && arg[0] != '-' && !haveMesh)
    {
      meshPath = arg;
      haveMesh = true;
    }
    else
    {
      std::cerr << "ofbDemo: unexpected argument '" << arg << "'\n";
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }

  // 1. Read the mesh.
  std::string readError;
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(meshPath, readError);
  if (!mesh)
  {
    std::cerr << "ofbDemo: cannot read mesh '" << meshPath << "': " << readError << "\n";
    return EXIT_FAILURE;
  }
  double bounds[6];
  mesh->GetBounds(bounds);
  std::cout << "Mesh:              " << meshPath << "\n"
            << "                   " << mesh->GetNumberOfPoints() << " points, "
            << mesh->GetNumberOfPolys() << " polygons\n";

  // 2. Build its OFB.
  vtkNew<vtkOFBBuilder> builder;
  vtkNew<ErrorCounter> buildErrors;
  builder->AddObserver(vtkCommand::ErrorEvent, buildErrors);
  builder->SetInputData(mesh);
  builder->SetResolution(resolution);
  if (backend == "cpu")
  {
    builder->SetBackendToCPU();
  }
  else if (backend == "opengl")
  {
    builder->SetBackendToOpenGL();
  }
  builder->Update();
  vtkOFB* ofb = builder->GetOutput();
  if (buildErrors->Count > 0 || !ofb || ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "ofbDemo: building the OFB at resolution " << resolution << " failed"
              << (buildErrors->Last.empty() ? std::string() : ": " + buildErrors->Last) << "\n";
    return EXIT_FAILURE;
  }

  // 3. Statistics.
  const double ms = builder->GetLastBuildTime();
  const vtkIdType n = ofb->GetNumberOfSamples();
  const vtkIdType* dims = ofb->GetDimensions();
  const double megabytes = ofb->GetActualMemorySize() / 1024.0;
  const char* axes[3] = { "X", "Y", "Z" };
  std::cout << std::fixed;
  std::cout << "Resolution:        " << resolution << " (frame " << dims[0] << " x " << dims[1]
            << " x " << dims[2] << " cells, cell size " << std::setprecision(6)
            << ofb->GetCellSize() << ")\n";
  std::cout << "Backend:           "
            << vtkOFBBuilder::GetBackendAsString(builder->GetLastBackend()) << "\n";
  std::cout << "Samples:           " << n << "\n";
  for (int a = 0; a < 3; ++a)
  {
    vtkIdType nu, nv;
    ofb->GetGridDimensions(a, nu, nv);
    std::cout << "  grid " << axes[a] << " (" << nu << " x " << nv << "): " << std::setw(10)
              << ofb->GetNumberOfSamples(a) << " samples, depth complexity "
              << ofb->GetDepthComplexity(a) << "\n";
  }
  std::cout << "Depth complexity:  " << ofb->GetDepthComplexity() << "\n";
  std::cout << std::setprecision(2);
  std::cout << "Bytes per sample:  " << ofb->GetBytesPerSample() << "\n";
  std::cout << "Memory:            " << megabytes << " MB\n";
  std::cout << "Build time:        " << ms << " ms\n";
  if (ms > 0.0)
  {
    std::cout << "Throughput:        " << std::setprecision(1) << (n / (ms * 1e-3)) / 1e6
              << " million samples/s\n";
  }
  else
  {
    std::cout << "Throughput:        n/a (build time below the timer's resolution)\n";
  }

  // 4. Render the samples as a point cloud coloured by grid.
  vtkNew<vtkOFBToPolyData> toPoints;
  toPoints->SetInputConnection(builder->GetOutputPort());
  toPoints->GenerateGridAxisOn();
  toPoints->GenerateVerticesOn();
  toPoints->Update();
  vtkPolyData* cloud = toPoints->GetOutput();
  if (!cloud->GetPointData()->GetArray("GridAxis") || cloud->GetNumberOfPoints() != n)
  {
    std::cerr << "ofbDemo: the point cloud of the OFB has no GridAxis array\n";
    return EXIT_FAILURE;
  }
  // Points are lit with the sample normals; an inside-out mesh (horse.ply, for
  // one) would render dark, so turn its normals around for the picture only.
  vtkDataArray* normals = cloud->GetPointData()->GetNormals();
  if (normals && SignedVolume(mesh) < 0.0)
  {
    std::cout << "Note:              the mesh is inside out (negative volume); its normals are "
                 "flipped for display\n";
    vtkSmartPointer<vtkDataArray> flipped = vtk::TakeSmartPointer(normals->NewInstance());
    flipped->DeepCopy(normals);
    for (vtkIdType i = 0; i < flipped->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        flipped->SetComponent(i, c, -flipped->GetComponent(i, c));
      }
    }
    cloud->GetPointData()->SetNormals(flipped);
  }

  vtkNew<vtkLookupTable> gridColors;
  gridColors->SetNumberOfTableValues(3);
  gridColors->SetTableRange(0.0, 2.0);
  gridColors->SetTableValue(0, 0.85, 0.15, 0.15, 1.0); // X: red
  gridColors->SetTableValue(1, 0.15, 0.65, 0.15, 1.0); // Y: green
  gridColors->SetTableValue(2, 0.15, 0.30, 0.90, 1.0); // Z: blue
  gridColors->Build();

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(cloud);
  mapper->SetLookupTable(gridColors);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("GridAxis");
  mapper->SetColorModeToMapScalars(); // GridAxis is unsigned char: map it, do not use it as a colour
  mapper->SetScalarRange(0.0, 2.0);
  mapper->ScalarVisibilityOn();

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetPointSize(1.5);
  actor->GetProperty()->SetAmbient(0.25);
  actor->GetProperty()->SetDiffuse(0.75);

  std::ostringstream caption;
  caption << vtksys::SystemTools::GetFilenameName(meshPath) << ": " << n
          << " OFB samples at resolution " << resolution
          << "\nsamples of grid X red, grid Y green, grid Z blue";
  vtkNew<vtkTextActor> text;
  text->SetInput(caption.str().c_str());
  text->GetTextProperty()->SetFontSize(18);
  text->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  text->SetDisplayPosition(12, 12);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddViewProp(text);
  renderer->SetBackground(0.88, 0.88, 0.88);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(renderer);

  // Look at the front of the model: in the bunny's scan frame y is up and the
  // head points to -x, so start on +z and turn 35 degrees toward -x, a little above.
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0], center[1], center[2] + 1.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Azimuth(-35.0);
  camera->Elevation(10.0);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  camera->Zoom(1.2);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();

  const std::string outputDir =
    vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(outputPath));
  if (!vtksys::SystemTools::FileIsDirectory(outputDir))
  {
    std::cerr << "ofbDemo: cannot write '" << outputPath << "': no directory '" << outputDir
              << "'\n";
    return EXIT_FAILURE;
  }
  vtkNew<ErrorCounter> writeErrors;
  vtkNew<vtkPNGWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, writeErrors);
  writer->SetFileName(outputPath.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writeErrors->Count > 0 || !vtksys::SystemTools::FileExists(outputPath, true))
  {
    std::cerr << "ofbDemo: cannot write '" << outputPath << "'"
              << (writeErrors->Last.empty() ? std::string() : ": " + writeErrors->Last) << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Wrote " << vtksys::SystemTools::CollapseFullPath(outputPath) << " (" << width
            << " x " << height << ")\n";
  return EXIT_SUCCESS;
}
