// OFBLIC: surface LIC of a mesh in a window. The LIC is computed once on the OFB's
// samples (vtkOFBLIC) and drawn by vtkOFBPolyDataMapper, so the streaks stay on the
// surface when the camera moves. The field is the tangential part of a rotation about a
// tilted axis through the centre of the mesh.
//
// Usage: OFBLIC [data file] [--field NAME] [--block I|NAME[,...]] [--time T | --time-step N]
//               [--resolution N] [--steps N] [--grain G]
//               [--image file.png [--keys K1,K2,...]] [--size S] [--export file.obj]
// The data file is a mesh or a simulation result (.vtp, .vtu, .vtm, .pvd, legacy .vtk,
// .stl, .obj, .ply; ofbExampleData.h): --field names its vector field (a point or a cell
// array of 3 components), --block its blocks and --time / --time-step its time step.
// Without --field the field is a rotation about a tilted axis (below). Without a file it
// reads Testing/Data/stanford-bunny.obj of the source tree. With
// --image it renders once off screen, writes the PNG and exits (no window); --keys
// K1,K2,... applies keys first, then one animation frame (a test of the keys); with
// --export as well it then exports what it drew. --export sets the file of key x
// (default <mesh name>_lic.obj): the LIC in the colours shown (vtkOFBMapToColors) as an
// OBJ with a texture (.obj; a mesh without texture coordinates gets a vtkOFBTextureAtlas),
// the same as glTF 2.0 (.gltf), a PLY with vertex colours (.ply) or a VTP (.vtp), as
// OFBPaint exports its paint.
//
// Keys: Up/Down steps +-5; Right/Left noise grain x2 / /2; m colour mode (the speed
// through a lookup table combined with the LIC in VTK surface LIC's map mode, then its
// blend mode with LICIntensity 0.8, then the grey LIC alone); n noise type; o oriented LIC;
// l enhanced LIC; d display lookup (InverseDistance, NearestMipmapped: antialiased where
// a pixel covers many cells, Nearest); space animation (the streaks flow: the LIC is
// recomputed with a new AnimationPhase on a repeating timer); c colour contrast (the
// final colour's lightness stretched, VTK's ENHANCE_CONTRAST_COLOR); x export. Mouse:
// VTK's trackball camera.

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBSampler.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include "ofbExampleData.h"
#include "ofbExampleErrors.h"
#include "ofbExampleFiles.h"
#include "ofbExampleOptions.h"
#include "ofbPaintExport.h" // OFBPaint's export, shared

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
/// The application: pipeline, window and the settings the keys change.
struct App
{
  vtkNew<vtkOFBSampler> Sampler;
  vtkNew<vtkOFBLIC> LIC;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkNew<vtkLookupTable> Table;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkTextActor> Text;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkOFBMapToColors> Colors;      // the colours shown, for export
  vtkNew<ofbexample::FirstError> Errors; // of the sampler, the LIC, the colours and the mapper
  vtkSmartPointer<vtkPolyData> Mesh;     // the surface drawn
  std::string ExportPath;                // key x
  std::string ExportMessage;             // what the last export said
  int ColorMode = 0;                     // 0 map, 1 blend, 2 LIC alone
  int Frame = 0;                         // animation frame, 0-9
  bool Animating = false;
  bool Deferred = false; // --keys: apply the settings, compute and draw once at the end

  /// Recompute what changed, update the text and draw.
  void Refresh()
  {
    if (this->Deferred)
    {
      return;
    }
    this->LIC->Update();
    // VTK surface LIC's colour modes: map multiplies the colour by the LIC plus
    // MapModeBias, blend mixes the LIC grey in by LICIntensity (1: the LIC alone).
    this->Mapper->GetColoring()->SetLICColorMode(
      this->ColorMode == 0 ? vtkOFBColoring::COLOR_MODE_MAP : vtkOFBColoring::COLOR_MODE_BLEND);
    this->Mapper->GetColoring()->SetMapModeBias(0.1);
    this->Mapper->GetColoring()->SetLICIntensity(this->ColorMode == 1 ? 0.8 : 1.0);
    static const char* noise[3] = { "uniform", "Gaussian", "Perlin" };
    std::ostringstream text;
    text << this->LIC->GetOutput()->GetNumberOfSamples() << " samples, LIC "
         << static_cast<int>(this->LIC->GetLastExecutionTime()) << " ms\n"
         << "steps " << this->LIC->GetNumberOfSteps() << " (Up/Down), grain "
         << this->LIC->GetNoiseGrainSize() << " cells (Right/Left)\n"
         << "m colour: "
         << (this->ColorMode == 0 ? "speed map LIC"
                                  : (this->ColorMode == 1 ? "speed blend LIC" : "LIC"))
         << ", n noise: " << noise[this->LIC->GetNoiseType()] << "\n"
         << "o oriented: " << (this->LIC->GetOrientedLIC() ? "on" : "off")
         << ", l enhanced: " << (this->LIC->GetEnhancedLIC() ? "on" : "off")
         << ", space animation: " << (this->Animating ? "on" : "off") << ", c colour contrast: "
         << (this->Mapper->GetColoring()->GetEnhanceColorContrast() ? "on" : "off") << "\n"
         << "d display: "
         << vtkOFBPolyDataMapper::GetLookupModeAsString(this->Mapper->GetLookupMode())
         << ", x export to " << this->ExportPath;
    if (this->Animating &&
      this->Mapper->GetLookupMode() == vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED)
    {
      // The first loop filters each phase's LIC down the pyramid (slow), the
      // next ones take the levels kept by the pyramid.
      text << " (slow on the first loop: d for Nearest)";
    }
    if (!this->ExportMessage.empty())
    {
      text << "\n" << this->ExportMessage;
    }
    this->Text->SetInput(text.str().c_str());
    this->Window->Render();
  }

  /// Apply a key; false if it is not one of ours.
  bool Key(const std::string& key)
  {
    vtkOFBLIC* lic = this->LIC;
    if (key == "Up" || key == "Down")
    {
      lic->SetNumberOfSteps(std::max(0, lic->GetNumberOfSteps() + (key == "Up" ? 5 : -5)));
    }
    else if (key == "Right" || key == "Left")
    {
      lic->SetNoiseGrainSize(lic->GetNoiseGrainSize() * (key == "Right" ? 2.0 : 0.5));
    }
    else if (key == "m")
    {
      this->ColorMode = (this->ColorMode + 1) % 3;
    }
    else if (key == "n")
    {
      lic->SetNoiseType((lic->GetNoiseType() + 1) % 3);
    }
    else if (key == "o")
    {
      lic->SetOrientedLIC(!lic->GetOrientedLIC());
      lic->SetImpulseNoiseProbability(lic->GetOrientedLIC() ? 0.15 : 1.0);
      lic->SetMinNoiseValue(lic->GetOrientedLIC() ? 0.5 : 0.0);
      lic->SetMaxNoiseValue(lic->GetOrientedLIC() ? 1.0 : 0.8);
    }
    else if (key == "l")
    {
      lic->SetEnhancedLIC(!lic->GetEnhancedLIC());
    }
    else if (key == "d")
    {
      static const int next[4] = { vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
        vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED,
        vtkOFBPolyDataMapper::LOOKUP_INVERSE_DISTANCE,
        vtkOFBPolyDataMapper::LOOKUP_NEAREST };
      this->Mapper->SetLookupMode(next[this->Mapper->GetLookupMode()]);
    }
    else if (key == "space")
    {
      this->Animating = !this->Animating;
      lic->SetAnimate(this->Animating);
    }
    else if (key == "c")
    {
      this->Mapper->GetColoring()->SetEnhanceColorContrast(
        !this->Mapper->GetColoring()->GetEnhanceColorContrast());
    }
    else if (key == "x")
    {
      this->Export();
    }
    else
    {
      return false;
    }
    this->Refresh();
    return true;
  }

  /// Write the LIC in the colours shown to ExportPath; false (and the reason in
  /// ExportMessage, printed) where it could not.
  bool Export()
  {
    this->LIC->Update();
    this->Colors->SetInputConnection(this->LIC->GetOutputPort());
    this->Colors->SetColoring(this->Mapper->GetColoring());
    this->Colors->SetOutputArrayName("Colors"); // what the export takes as the paint
    this->Colors->Update();
    if (this->Errors->Count > 0)
    {
      this->ExportMessage = "cannot export '" + this->ExportPath + "'" + this->Errors->Suffix();
      std::cerr << "OFBLIC: " << this->ExportMessage << "\n";
      return false;
    }
    const bool ok = ofbpaint::ExportPainting(
      this->Mesh, this->Colors->GetOutput(), this->ExportPath, 4096, this->ExportMessage);
    (ok ? std::cout : std::cerr) << "OFBLIC: " << this->ExportMessage << "\n";
    return ok;
  }

  /// One animation frame: move the streaks a tenth of a period along the flow. The phases
  /// repeat exactly (k / 10), so that a mipmapped display filters each one once (the
  /// pyramid's filter cache).
  void Tick()
  {
    if (this->Animating)
    {
      this->Frame = (this->Frame + 1) % 10;
      this->LIC->SetAnimationPhase(this->Frame / 10.0);
      this->Refresh();
    }
  }
};

/// Trackball camera with the application's keys (which VTK's own keys would shadow).
class KeyStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static KeyStyle* New();
  vtkTypeMacro(KeyStyle, vtkInteractorStyleTrackballCamera);
  App* Application = nullptr;

  void OnKeyPress() override
  {
    const char* sym = this->Interactor->GetKeySym();
    if (!sym || !this->Application->Key(sym))
    {
      this->Superclass::OnKeyPress();
    }
  }
  void OnChar() override
  {
    const std::string keys = "mnoldcx ";
    if (keys.find(this->Interactor->GetKeyCode()) == std::string::npos)
    {
      this->Superclass::OnChar();
    }
  }
};
vtkStandardNewMacro(KeyStyle);

/// The field (rotation about a tilted axis through the centre) and its speed (its range in
/// `range`).
void AddField(vtkPolyData* mesh, double range[2])
{
  double b[6];
  mesh->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  double a[3] = { 0.4, 1.0, 0.3 };
  vtkMath::Normalize(a);
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> speed;
  speed->SetName("Speed");
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    const double* x = mesh->GetPoint(p);
    const double r[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
    double v[3];
    vtkMath::Cross(a, r, v);
    flow->InsertNextTuple(v);
    speed->InsertNextValue(static_cast<float>(vtkMath::Norm(v)));
  }
  mesh->GetPointData()->SetVectors(flow);
  mesh->GetPointData()->AddArray(speed);
  speed->GetRange(range);
}

int WriteImage(App& app, const std::string& path)
{
  app.Refresh();
  if (app.Errors->Count > 0 || !app.Mapper->GetLastRenderUsedOFB() ||
    !app.LIC->GetOutput()->GetSampleData()->GetArray("LIC"))
  {
    std::cerr << "OFBLIC: the LIC was not drawn" << app.Errors->Suffix() << "\n";
    return 1;
  }
  std::string message;
  if (!ofbexample::WriteWindowPNG(app.Window, path, message))
  {
    std::cerr << "OFBLIC: " << message << "\n";
    return 1;
  }
  std::cout << "wrote " << path << "\n";
  return 0;
}

/// The application's pipeline: sampler -> LIC -> mapper coloured by speed and modulated by
/// the LIC, in a window of `size` pixels; every filter's errors counted in app.Errors.
void BuildPipeline(App& app, vtkPolyData* mesh, int resolution, int steps, double grain, int size)
{
  app.Sampler->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  app.LIC->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  app.Colors->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  app.Mapper->AddObserver(vtkCommand::ErrorEvent, app.Errors);
  app.Sampler->SetInputData(mesh);
  app.Sampler->SetResolution(resolution);
  app.LIC->SetInputConnection(app.Sampler->GetOutputPort());
  app.LIC->SetNumberOfSteps(steps);
  app.LIC->SetNoiseGrainSize(grain);
  app.LIC->SetEnhanceContrast(vtkOFBLIC::ENHANCE_CONTRAST_LIC);
  app.Table->SetHueRange(0.667, 0.0);
  app.Table->Build();
  app.Mapper->SetInputData(mesh);
  app.Mapper->SetOFBConnection(app.LIC->GetOutputPort());
  app.Mapper->SetLookupModeToInverseDistance();
  app.Mapper->GetColoring()->SetIntensityArrayName("LIC");
  app.Mapper->GetColoring()->IntensityModulationOn();
  app.Mapper->GetColoring()->SetColorSourceToScalars();
  app.Mapper->GetColoring()->SetLookupTable(app.Table);
  app.Mapper->GetColoring()->SetScalarArrayName("Speed");
  app.Mapper->GetColoring()->SetLowColorContrastEnhancementFactor(0.05);
  app.Mapper->GetColoring()->SetHighColorContrastEnhancementFactor(0.05);
  app.Actor->SetMapper(app.Mapper);
  app.Text->GetTextProperty()->SetFontSize(12);
  app.Text->SetPosition(10, 10);
  app.Renderer->AddActor(app.Actor);
  app.Renderer->AddViewProp(app.Text);
  app.Renderer->SetBackground(0.1, 0.1, 0.15);
  app.Window->AddRenderer(app.Renderer);
  app.Window->SetSize(size, size);
  app.Window->SetWindowName("OFBLIC: surface LIC on the OFB");
}

/// The command line, with its defaults.
struct Options
{
  std::string MeshPath = std::string(VTKOFB_DATA_DIR) + "/stanford-bunny.obj";
  std::string Image;
  std::string Keys;
  std::string ExportPath;
  int Resolution = 512;
  int Steps = 20;
  int Size = 800;
  double Grain = 1.0;
  ofbexample::DataOptions Data;
};

/// Parse the command line into `o`: -1 to go on, or the exit status (after the usage or a
/// message).
int ParseOptions(int argc, char* argv[], Options& o)
{
  bool ok = true; // false once a value is not a number in its range
  for (int i = 1; i < argc && ok; ++i)
  {
    const std::string arg = argv[i];
    const bool value = i + 1 < argc;
    if (arg == "--resolution" && value)
    {
      ok = ofbexample::ParseInt(argv[++i], 8, 16384, o.Resolution);
    }
    else if (arg == "--steps" && value)
    {
      ok = ofbexample::ParseInt(argv[++i], 0, 1000, o.Steps);
    }
    else if (arg == "--grain" && value)
    {
      ok = ofbexample::ParseDouble(argv[++i], 0.01, 100.0, o.Grain);
    }
    else if (arg == "--image" && value)
    {
      o.Image = argv[++i];
    }
    else if (arg == "--keys" && value)
    {
      o.Keys = argv[++i];
    }
    else if (arg == "--export" && value)
    {
      o.ExportPath = argv[++i];
    }
    else if (arg == "--size" && value)
    {
      ok = ofbexample::ParseInt(argv[++i], 64, 8192, o.Size);
    }
    else if (ofbexample::ParseDataOption(argc, argv, i, o.Data, ok))
    {
    }
    else if (!arg.empty() && arg[0] != '-')
    {
      o.MeshPath = arg;
    }
    else
    {
      ok = false;
    }
    if (!ok)
    {
      std::cerr << "Usage: " << argv[0] << " [data file] " << ofbexample::DataOptionsUsage()
                << " [--resolution N] [--steps N] [--grain G]"
                   " [--image file.png [--keys K1,K2,...]] [--size S] [--export file.obj]\n"
                   "  data: .vtp .vtu .vtm .pvd .vtk .stl .obj .ply; --field a vector array\n"
                   "  resolution 8-16384, steps 0-1000, grain 0.01-100 cells, size 64-8192\n";
      return arg == "--help" ? 0 : 1;
    }
  }
  // The OBJ writer names the texture after the OBJ: it would replace the image.
  const std::string::size_type dot = o.ExportPath.rfind('.');
  if (!o.Image.empty() && dot != std::string::npos && o.ExportPath.substr(dot) == ".obj" &&
    o.ExportPath.substr(0, dot) + ".png" == o.Image)
  {
    std::cerr << "OFBLIC: --export " << o.ExportPath << " would write its texture over --image "
              << o.Image << ": give them different names.\n";
    return 1;
  }
  return -1;
}

/// The surface of o.MeshPath with its field (the file's, or AddField's) as the active
/// vectors and its speed; null after a message.
vtkSmartPointer<vtkPolyData> ReadMesh(const Options& o, double speedRange[2])
{
  ofbexample::DataSurface data;
  if (!ofbexample::ReadDataReported("OFBLIC", o.MeshPath, o.Data, true, false, data))
  {
    return nullptr;
  }
  if (data.Field)
  {
    ofbexample::UseFieldAsVectors(data, speedRange);
  }
  else
  {
    AddField(data.Surface, speedRange);
  }
  return data.Surface;
}

/// Headless: the keys of o.Keys, one animation frame, the PNG o.Image, then the export
/// when asked for; the exit status.
int RunHeadless(App& app, const Options& o)
{
  app.Window->SetOffScreenRendering(1);
  app.Deferred = true;
  std::istringstream list(o.Keys);
  for (std::string key; std::getline(list, key, ',');)
  {
    if (!app.Key(key))
    {
      std::cerr << "OFBLIC: unknown key '" << key << "'\n";
      return 1;
    }
  }
  app.Tick();
  app.Deferred = false;
  const int written = WriteImage(app, o.Image);
  return written != 0 || o.ExportPath.empty() || app.Export() ? written : 1;
}

/// The window with the keys (KeyStyle) and the animation timer, until it closes.
void Interact(App& app)
{
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<KeyStyle> style;
  style->Application = &app;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(app.Window);
  interactor->Initialize();
  vtkNew<vtkCallbackCommand> timer;
  timer->SetClientData(&app);
  timer->SetCallback(
    [](vtkObject*, unsigned long, void* client, void*) { static_cast<App*>(client)->Tick(); });
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  interactor->CreateRepeatingTimer(40);
  app.Refresh();
  interactor->Start();
}
}

int main(int argc, char* argv[])
{
  Options o;
  const int status = ParseOptions(argc, argv, o);
  if (status >= 0)
  {
    return status;
  }
  double speedRange[2];
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(o, speedRange);
  if (!mesh)
  {
    return 1;
  }
  App app;
  app.Mesh = mesh;
  app.ExportPath =
    !o.ExportPath.empty() ? o.ExportPath : ofbpaint::DefaultExportPath(o.MeshPath, "lic");
  BuildPipeline(app, mesh, o.Resolution, o.Steps, o.Grain, o.Size);
  app.Mapper->GetColoring()->SetScalarRange(speedRange);
  app.LIC->Update();
  if (app.Errors->Count > 0 || app.LIC->GetOutput()->GetNumberOfSamples() == 0)
  {
    std::cerr << "OFBLIC: no LIC of " << o.MeshPath << " (its OFB could not be built)"
              << app.Errors->Suffix() << "\n";
    return 1;
  }
  app.Renderer->ResetCamera();
  app.Renderer->GetActiveCamera()->Dolly(1.3);
  app.Renderer->ResetCameraClippingRange();
  if (!o.Image.empty())
  {
    return RunHeadless(app, o);
  }
  Interact(app);
  return 0;
}
