// OFBParticles: surface particles moving along a vector field on a mesh and painting
// its OFB (vtkOFBParticleAdvector), drawn by vtkOFBPolyDataMapper, animated.
//
// Usage: OFBParticles [data file] [--field rotation|height|mesh|NAME]
//                     [--block I|NAME[,...]] [--time T | --time-step N] [--particles N]
//                     [--resolution N] [--radius CELLS] [--lifetime STEPS]
//                     [--color constant|seeds|scalar|periodic] [--reveal]
//                     [--image out.png --steps N] [--width W] [--height H]
//                     [--view-up X Y Z]
//
// The data file is a mesh or a simulation result (.vtp, .vtu, .vtm, .pvd, legacy .vtk,
// .stl, .obj, .ply; ofbExampleData.h), with its blocks (--block) and time step (--time,
// --time-step). Without one it reads Testing/Data/horse.ply of the source tree. Fields:
// `rotation` (default) the tangential part of a rotation about an axis through the
// mesh's centre, `height` the surface gradient of the height along the view-up axis,
// `mesh` the file's active point vectors, any other NAME the file's point or cell array
// of 3 components of that name (a cell field holds on its cells' triangles). In the
// window: space pauses, r reseeds, c changes the colour mode, t toggles reveal mode (the surface
// starts dark and the particles uncover it, the paper's Fig. 2), q quits. `--image` runs headless:
// N steps, then writes a PNG.

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBParticleAdvector.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"

#include "ofbExampleData.h"
#include "ofbExampleErrors.h"
#include "ofbExampleFiles.h"
#include "ofbExampleOptions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
struct Options
{
  std::string Mesh = std::string(VTKOFB_DATA_DIR) + "/horse.ply";
  std::string Field = "rotation";
  ofbexample::DataOptions Data; // --block, --time, --time-step; Field when not built in
  std::string Color = "periodic";
  std::string Image;
  int Particles = 10000;
  int Resolution = 1024;
  int Steps = 200;
  int Lifetime = 0;
  int Width = 800;
  int Height = 600;
  double Radius = 2.5;
  double ViewUp[3] = { 0.0, 0.0, 1.0 }; // the horse's; the bunny's is y
  bool Reveal = false;
};

// The colour mode named `name`, or -1 for an unknown name.
int ColorMode(const std::string& name)
{
  if (name == "constant")
  {
    return vtkOFBParticleAdvector::COLOR_CONSTANT;
  }
  if (name == "seeds")
  {
    return vtkOFBParticleAdvector::COLOR_FROM_SEEDS;
  }
  if (name == "scalar")
  {
    return vtkOFBParticleAdvector::COLOR_BY_SCALAR;
  }
  return name == "periodic" ? vtkOFBParticleAdvector::COLOR_PERIODIC : -1;
}

bool Parse(int argc, char* argv[], Options& o)
{
  bool ok = true; // false once a value is not a number in its range
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--field" && more)
    {
      o.Field = argv[++i];
      ok = !o.Field.empty() && ok;
      const bool builtIn = o.Field == "rotation" || o.Field == "height" || o.Field == "mesh";
      o.Data.Field = builtIn ? std::string() : o.Field;
    }
    else if (a != "--field" && ofbexample::ParseDataOption(argc, argv, i, o.Data, ok))
    {
    }
    else if (a == "--color" && more)
    {
      o.Color = argv[++i];
      ok = ColorMode(o.Color) >= 0 && ok;
    }
    else if (a == "--image" && more)
    {
      o.Image = argv[++i];
    }
    else if (a == "--particles" && more)
    {
      ok = ofbexample::ParseInt(argv[++i], 1, 100000000, o.Particles) && ok;
    }
    else if (a == "--resolution" && more)
    {
      ok = ofbexample::ParseInt(argv[++i], 8, 16384, o.Resolution) && ok;
    }
    else if (a == "--steps" && more)
    {
      ok = ofbexample::ParseInt(argv[++i], 1, 1000000, o.Steps) && ok;
    }
    else if (a == "--lifetime" && more)
    {
      ok = ofbexample::ParseInt(argv[++i], 0, 1000000, o.Lifetime) && ok;
    }
    else if (a == "--radius" && more)
    {
      ok = ofbexample::ParseDouble(argv[++i], 0.01, 1000.0, o.Radius) && ok;
    }
    else if (a == "--width" && more)
    {
      ok = ofbexample::ParseInt(argv[++i], 64, 8192, o.Width) && ok;
    }
    else if (a == "--height" && more)
    {
      ok = ofbexample::ParseInt(argv[++i], 64, 8192, o.Height) && ok;
    }
    else if (a == "--view-up" && i + 3 < argc)
    {
      for (double& x : o.ViewUp)
      {
        ok = ofbexample::ParseDouble(argv[++i], -1e6, 1e6, x) && ok;
      }
      ok = ok && vtkMath::Norm(o.ViewUp) > 0.0;
    }
    else if (a == "--reveal")
    {
      o.Reveal = true;
    }
    else if (!a.empty() && a[0] != '-')
    {
      o.Mesh = a;
    }
    else
    {
      return false;
    }
  }
  return ok;
}

// A built-in field (the advector projects it into the tangent planes).
bool MakeField(vtkPolyData* mesh, const std::string& kind, const double up[3])
{
  if (kind == "mesh")
  {
    return mesh->GetPointData()->GetVectors() != nullptr;
  }
  double c[3];
  mesh->GetCenter(c);
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  field->SetNumberOfComponents(3);
  field->SetNumberOfTuples(mesh->GetNumberOfPoints());
  const double w[3] = { 0.2, 1.0, 0.1 };
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3], r[3], v[3] = { up[0], up[1], up[2] }; // height: its gradient
    mesh->GetPoint(i, x);
    if (kind == "rotation")
    {
      for (int k = 0; k < 3; ++k)
      {
        r[k] = x[k] - c[k];
      }
      vtkMath::Cross(w, r, v);
    }
    field->SetTuple(i, v);
  }
  mesh->GetPointData()->SetVectors(field);
  return kind == "rotation" || kind == "height";
}

// The OFB's paint back to its start: white, or dark and transparent for reveal.
void ResetPaint(vtkOFB* ofb, bool reveal)
{
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  if (!colors)
  {
    return;
  }
  const unsigned char base[4] = { 235, 235, 235, 255 };
  const unsigned char hidden[4] = { 40, 40, 48, 0 };
  for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); ++i)
  {
    colors->SetTypedTuple(i, reveal ? hidden : base);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
}

/// The application: the mesh, its OFB (painted in place), the particles and the window;
/// every filter's errors counted in Errors (one makes the run fail).
struct App
{
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkNew<ofbexample::FirstError> Errors;
  vtkNew<vtkOFB> OFB;
  vtkNew<vtkOFBParticleAdvector> Advector;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTextActor> Text;
  bool Paused = false;
  bool Reveal = false;
  int Mode = 3;
  void Status()
  {
    std::string s = std::string("colour: ") +
      vtkOFBParticleAdvector::GetColorModeAsString(this->Mode) + (this->Reveal ? ", reveal" : "") +
      (this->Paused ? ", paused" : "") +
      "   [space] pause  [r] reseed  [c] colour  [t] reveal  [q] quit";
    this->Text->SetInput(s.c_str());
  }
};

void OnTimer(vtkObject*, unsigned long, void* data, void*)
{
  App* app = static_cast<App*>(data);
  if (!app->Paused)
  {
    app->Advector->Step();
    app->Window->Render();
  }
}

void OnKey(vtkObject* caller, unsigned long, void* data, void*)
{
  App* app = static_cast<App*>(data);
  const std::string key = static_cast<vtkRenderWindowInteractor*>(caller)->GetKeySym();
  if (key == "space")
  {
    app->Paused = !app->Paused;
  }
  else if (key == "r")
  {
    app->Advector->SetRandomSeed(app->Advector->GetRandomSeed() + 1);
  }
  else if (key == "c")
  {
    app->Mode = (app->Mode + 1) % 4;
    app->Advector->SetColorMode(app->Mode);
  }
  else if (key == "t")
  {
    app->Reveal = !app->Reveal;
    ResetPaint(app->OFB, app->Reveal);
    app->Advector->Reset();
  }
  app->Status();
  app->Window->Render();
}

void Usage()
{
  std::cerr << "Usage: OFBParticles [data file] [--field rotation|height|mesh|NAME] "
               "[--block I|NAME[,...]] [--time T | --time-step N] [--particles N] [--resolution "
               "N] [--radius CELLS] [--lifetime STEPS] "
               "[--color constant|seeds|scalar|periodic] [--reveal] [--image out.png "
               "--steps N] [--width W] [--height H] [--view-up X Y Z]\n"
               "  N: particles 1-1e8, resolution 8-16384, steps 1-1e6, lifetime 0-1e6;\n"
               "  CELLS 0.01-1000; W and H 64-8192; the view-up not zero\n";
}

/// The surface of o.Mesh with its field as the active vectors and a "Height" point array
/// along the view-up (for the scalar colour mode); null after a message.
vtkSmartPointer<vtkPolyData> ReadMesh(const Options& o)
{
  ofbexample::DataSurface data;
  if (!ofbexample::ReadDataReported("OFBParticles", o.Mesh, o.Data, true, false, data))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = data.Surface;
  if (data.Field)
  {
    // A cell field holds on its cells' triangles (the advector reads the active cell
    // vectors where there are no active point vectors).
    ofbexample::SetFieldAsVectors(data);
  }
  else if (!MakeField(mesh, o.Field, o.ViewUp))
  {
    std::cerr << "OFBParticles: '" << o.Mesh
              << "' has no active point vectors for --field mesh; its arrays: "
              << ofbexample::DescribeArrays(mesh) << "\n";
    return nullptr;
  }
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    height->InsertNextValue(vtkMath::Dot(mesh->GetPoint(i), o.ViewUp));
  }
  mesh->GetPointData()->AddArray(height);
  return mesh;
}

/// The OFB of app.Mesh in app.OFB, its paint reset, and the advector on it; false after
/// a message.
bool BuildParticles(App& app, const Options& o)
{
  vtkNew<vtkOFBSampler> sampler;
  sampler->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  sampler->SetInputData(app.Mesh);
  sampler->SetResolution(o.Resolution);
  sampler->Update();
  if (app.Errors->Count > 0 || sampler->GetOutput()->GetNumberOfSamples() == 0)
  {
    std::cerr << "OFBParticles: the OFB of " << o.Mesh << " could not be built"
              << app.Errors->Suffix() << "\n";
    return false;
  }
  app.OFB->ShallowCopy(sampler->GetOutput());
  ResetPaint(app.OFB, o.Reveal);
  vtkOFBParticleAdvector* advector = app.Advector;
  advector->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  advector->SetInputData(app.Mesh);
  advector->SetOFB(app.OFB);
  advector->SetNumberOfParticles(o.Particles);
  advector->SetFootprintRadius(o.Radius);
  advector->SetLifetime(o.Lifetime);
  advector->SetColorMode(ColorMode(o.Color));
  advector->SetScalarArrayName("Height");
  advector->SetColorPeriod(90);
  return true;
}

/// The mapper drawing app.Mesh from the OFB, in a window of o.Width x o.Height looking at
/// a side of the view-up axis.
void BuildScene(App& app, const Options& o)
{
  app.Mapper->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  app.Mapper->SetInputData(app.Mesh);
  app.Mapper->SetOFB(app.OFB);
  vtkNew<vtkActor> actor;
  actor->SetMapper(app.Mapper);
  actor->GetProperty()->SetSpecular(0.2);
  app.Renderer->AddActor(actor);
  app.Renderer->SetBackground(0.1, 0.12, 0.16);
  app.Renderer->SetBackground2(0.32, 0.34, 0.4);
  app.Renderer->GradientBackgroundOn();
  app.Window->SetSize(o.Width, o.Height);
  app.Window->AddRenderer(app.Renderer);
  // Look from a side of the view-up axis, then fit the mesh.
  vtkCamera* camera = app.Renderer->GetActiveCamera();
  double center[3], side[3];
  app.Mesh->GetCenter(center);
  const double other[3] = {
    0.0, std::abs(o.ViewUp[1]) > 0.9 ? 0.0 : 1.0, std::abs(o.ViewUp[1]) > 0.9 ? 1.0 : 0.0
  };
  vtkMath::Cross(o.ViewUp, other, side);
  vtkMath::Normalize(side);
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + side[0], center[1] + side[1], center[2] + side[2]);
  camera->SetViewUp(o.ViewUp);
  app.Renderer->ResetCamera();
  camera->Azimuth(30);
  camera->Elevation(15);
  camera->Zoom(1.3);
}

/// Headless: o.Steps steps, then the window as the PNG o.Image; the exit status.
int WriteImage(App& app, const Options& o)
{
  app.Window->SetOffScreenRendering(1);
  app.Advector->SetStepsPerUpdate(std::max(1, o.Steps));
  app.Advector->Step();
  app.Window->Render();
  if (app.Errors->Count > 0 || !app.Mapper->GetLastRenderUsedOFB())
  {
    std::cerr << "OFBParticles: the particles were not drawn" << app.Errors->Suffix() << "\n";
    return 1;
  }
  std::string message; // the front buffer: the frame drawn after the steps
  if (!ofbexample::WriteWindowPNG(app.Window, o.Image, message, true))
  {
    std::cerr << "OFBParticles: " << message << "\n";
    return 1;
  }
  std::cout << "Wrote " << o.Image << " after " << app.Advector->GetCurrentStep() << " steps of "
            << app.Advector->GetParticles()->GetNumberOfPoints() << " particles on "
            << app.Mesh->GetNumberOfPolys() << " triangles (" << app.OFB->GetNumberOfSamples()
            << " samples)\n";
  return 0;
}

/// The animation in a window, with the keys, until q.
void Interact(App& app, const Options& o)
{
  app.Text->GetTextProperty()->SetFontSize(14);
  app.Text->SetPosition(10, 10);
  app.Renderer->AddActor2D(app.Text);
  app.Reveal = o.Reveal;
  app.Mode = app.Advector->GetColorMode();
  app.Status();
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(app.Window);
  interactor->Initialize();
  vtkNew<vtkCallbackCommand> timer;
  timer->SetCallback(OnTimer);
  timer->SetClientData(&app);
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetCallback(OnKey);
  keys->SetClientData(&app);
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  interactor->CreateRepeatingTimer(30);
  app.Window->Render();
  interactor->Start();
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    Usage();
    return 1;
  }
  App app;
  app.Mesh = ReadMesh(o);
  if (!app.Mesh || !BuildParticles(app, o))
  {
    return 1;
  }
  BuildScene(app, o);
  if (!o.Image.empty())
  {
    return WriteImage(app, o);
  }
  Interact(app, o);
  return 0;
}
