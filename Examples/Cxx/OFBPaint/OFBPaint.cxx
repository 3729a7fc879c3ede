// OFBPaint: paint a surface with the mouse through its Orthogonal Fragment Buffer.
//
// Usage: OFBPaint [data file] [--field NAME] [--block I|NAME[,...]] [--time T | --time-step N]
//                 [--resolution N] [--load paint.ofb]
//                 [--save paint.ofb] [--import-texture image.png] [--decal image.png]
//                 [--export painted.obj|.ply|.vtp] [--texture N]
//                 [--width W] [--height H] [--strokes strokes.txt --image out.png]
//                 [--play events.log]
//
// The data file is a mesh or a simulation result (.vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl,
// .obj, .ply; ofbExampleData.h). Without one it opens Testing/Data/stanford-bunny.obj of the
// source tree. With --field the painting starts from that point or cell array through a
// blue-to-red colour map (its magnitude for a vector). The surface
// is drawn by vtkOFBPolyDataMapper from an OFB built at --resolution (default 1024) and
// painted with vtkOFBPainterWidget: left-drag paints, the other buttons move the camera,
// 'h' shows the keys. With --strokes and --image it runs without a window on screen:
// it replays the stroke file (format in ofbPaintStrokes.h) and writes the picture.

#include "ofbPaintDecal.h"
#include "ofbPaintExport.h"
#include "ofbPaintStrokes.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBPainterRepresentation.h"
#include "vtkOFBPainterWidget.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkOFBReader.h"
#include "vtkOFBSampler.h"
#include "vtkOFBWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtksys/SystemTools.hxx"

#include "ofbExampleData.h"
#include "ofbExampleErrors.h"
#include "ofbExampleFiles.h"
#include "ofbExampleMesh.h"
#include "ofbExampleOptions.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using SystemTools = vtksys::SystemTools;

const char* const PaletteNames[9] = { "red",
  "orange",
  "yellow",
  "green",
  "cyan",
  "blue",
  "purple",
  "white",
  "black" };

using ErrorCounter = ofbexample::FirstError; // counts error events, keeps the first

/// The samples' colours from the sample array `name` (a point array interpolated, a cell
/// array per triangle; a vector's magnitude) through a blue-to-red map over its range.
bool PaintField(vtkOFB* ofb, const std::string& name)
{
  vtkDataArray* field = ofb->GetSampleData()->GetArray(name.c_str());
  auto* colors =
    vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray(vtkOFB::ColorsArrayName()));
  if (!field || !colors || colors->GetNumberOfComponents() != 4)
  {
    return false;
  }
  const int components = field->GetNumberOfComponents();
  std::vector<double> values(ofb->GetNumberOfSamples());
  double range[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double v = 0.0;
    for (int k = 0; k < components; ++k)
    {
      const double c = field->GetComponent(i, k);
      v += components == 1 ? c : c * c;
    }
    values[i] = components == 1 ? v : std::sqrt(v);
    if (std::isfinite(values[i]))
    {
      range[0] = std::min(range[0], values[i]);
      range[1] = std::max(range[1], values[i]);
    }
  }
  vtkNew<vtkLookupTable> table;
  table->SetHueRange(0.667, 0.0);
  table->SetTableRange(
    range[0] <= range[1] ? range[0] : 0.0, range[0] <= range[1] ? range[1] : 1.0);
  table->Build();
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    const unsigned char* rgba = table->MapValue(std::isfinite(values[i]) ? values[i] : range[0]);
    colors->SetTypedTuple(i, rgba);
  }
  ofb->MarkAllSamplesModified();
  ofb->Modified();
  return true;
}

void Usage(const char* argv0)
{
  std::cerr
    << "Usage: " << argv0
    << " [data file] [--field NAME] [--block I|NAME[,...]] [--time T | --time-step N]\n"
       "       [--resolution N] [--load paint.ofb] [--save paint.ofb]\n"
       "       [--import-texture IMAGE] [--decal IMAGE] [--export FILE] [--texture N]\n"
       "       [--width W] [--height H]\n"
       "       [--strokes strokes.txt --image out.png]\n"
       "Paint the surface (default stanford-bunny.obj) with the mouse; 'h' lists the keys.\n"
       "  data file        .vtp .vtu .vtm .pvd .vtk .stl .obj .ply, by content or extension\n"
       "  --field NAME     start from this point or cell array in colour (blue to red)\n"
       "  --block LIST     the blocks to show: flat indices or names, comma-separated\n"
       "  --time T         the time step closest to T; --time-step N the Nth (from 0)\n"
       "  --resolution N   OFB cells along the longest side (default 1024)\n"
       "  --load FILE      start from a painted OFB saved before (key 's')\n"
       "  --save FILE      where 's' saves and 'l' loads (default <mesh name>.ofb); the\n"
       "                   headless mode saves the painted OFB there when given\n"
       "  --import-texture IMAGE  start from the mesh's texture (PNG, JPEG, ...) projected\n"
       "                   into the OFB through its texture coordinates\n"
       "  --decal IMAGE    what 'k' stamps at the cursor, 4 brush radii wide, upright on\n"
       "                   screen (default: a badge with an arrow)\n"
       "  --export FILE    where 'x' exports the painting (default <mesh name>_painted.obj:\n"
       "                   the paint baked into the mesh's texture, or for a mesh without\n"
       "                   texture coordinates into an atlas of charts on the OFB's grids;\n"
       "                   or a .gltf: the same textured mesh as glTF 2.0; or a .ply:\n"
       "                   vertex colours; or a .vtp); the headless mode exports\n"
       "                   there when given\n"
       "  --texture N      texels a side of the exported texture (default 2048; the most\n"
       "                   for an atlas, which takes a texel a cell where that fits, else\n"
       "                   about the most that fits)\n"
       "  --strokes FILE   replay a stroke file without a window on screen (format in\n"
       "                   Examples/Cxx/OFBPaint/ofbPaintStrokes.h), with --image OUT.png\n"
       "  --play FILE      play recorded mouse and key events (vtkInteractorEventRecorder's\n"
       "                   format) in the window, then exit: a scripted session\n";
}

// The application: the surface, its OFB, the window and the painter widget.
class PaintApp
{
public:
  bool Setup(const std::map<std::string, std::string>& options,
    const std::string& meshPath,
    bool headless);
  int RunInteractive(const std::string& play);
  int RunHeadless(const std::string& strokes, const std::string& image);

private:
  bool BuildOFB(int resolution);
  std::string FieldName; // --field: the painting starts from it
  bool LoadOFB(const std::string& path);
  bool SaveOFB(const std::string& path);
  bool Screenshot(const std::string& path);
  void UseOFB(vtkOFB* ofb);
  void ResetView(double azimuth, double elevation, double zoom);
  bool PickPixel(double x, double y, double p[3]);
  void UpdateTexts(const std::string& message);
  static void OnKey(vtkObject*, unsigned long, void* clientData, void*);
  static void OnWidget(vtkObject*, unsigned long event, void* clientData, void*);

  std::string MeshPath;
  std::string SavePath;
  std::string ExportPath;
  int TextureSize = 2048;
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkOFB> OFB;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkOFBPainterWidget> Widget;
  vtkNew<vtkTextActor> Help;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkCallbackCommand> KeyCallback;
  vtkNew<vtkCallbackCommand> WidgetCallback;
  int Screenshots = 0;
  bool SaveRequested = false;   // --save given: the headless mode saves the painted OFB
  bool ExportRequested = false; // --export given: the headless mode exports the painting
  ofbpaint::DecalStamper Decals;

public:
  /// Stamp the decal centred at surface point p; the samples changed or -1.
  long long StampDecal(const double p[3], std::string& message);
};

bool PaintApp::BuildOFB(int resolution)
{
  vtkNew<vtkOFBSampler> sampler;
  vtkNew<ErrorCounter> errors;
  sampler->AddObserver(vtkCommand::ErrorEvent, errors);
  sampler->SetInputData(this->Surface);
  sampler->SetResolution(resolution);
  sampler->Update();
  vtkOFB* ofb = sampler->GetOutput();
  if (errors->Count > 0 || !ofb || ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "OFBPaint: building the OFB at resolution " << resolution << " failed"
              << (errors->Text.empty() ? "" : ": " + errors->Text) << "\n";
    return false;
  }
  if (!this->FieldName.empty() && !PaintField(ofb, this->FieldName))
  {
    std::cerr << "OFBPaint: the OFB has no sample array '" << this->FieldName << "'\n";
    return false;
  }
  this->UseOFB(ofb);
  std::cout << "OFB: " << ofb->GetNumberOfSamples() << " samples at resolution " << resolution
            << " (cell size " << ofb->GetCellSize() << ")\n";
  return true;
}

void PaintApp::UseOFB(vtkOFB* ofb)
{
  this->OFB = ofb;
  this->Mapper->SetOFB(ofb);
  this->Widget->GetPainterRepresentation()->SetOFB(ofb);
  // Mirror painting (key m) reflects across the planes through the centre of the mesh's
  // box: the plane of symmetry of a model built symmetric about its middle.
  double bounds[6];
  this->Surface->GetBounds(bounds);
  this->Widget->GetPainterRepresentation()->GetPainter()->SetMirrorOrigin(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
}

bool PaintApp::LoadOFB(const std::string& path)
{
  vtkNew<vtkOFBReader> reader;
  vtkNew<ErrorCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkOFB* ofb = reader->GetOutput();
  if (errors->Count > 0 || !ofb || ofb->GetNumberOfSamples() == 0)
  {
    std::cerr << "OFBPaint: cannot load '" << path << "'"
              << (errors->Text.empty() ? "" : ": " + errors->Text) << "\n";
    return false;
  }
  // An OFB of another surface would colour this one with unrelated paint: its frame is the
  // surface's bounds padded by a cell and rounded up to whole cells.
  const double* b = this->Surface->GetBounds();
  const double* origin = ofb->GetOrigin();
  const vtkIdType* dims = ofb->GetDimensions();
  const double s = ofb->GetCellSize();
  for (int a = 0; a < 3; ++a)
  {
    const double high = origin[a] + dims[a] * s;
    if (b[2 * a] < origin[a] || b[2 * a + 1] > high || b[2 * a] - origin[a] > 2.0 * s ||
      high - b[2 * a + 1] > 3.0 * s)
    {
      std::cerr << "OFBPaint: '" << path << "' was not built from this surface\n";
      return false;
    }
  }
  vtkSmartPointer<vtkOFB> copy = ofb; // keep it past the reader
  this->UseOFB(copy);
  std::cout << "Loaded " << path << " (" << ofb->GetNumberOfSamples() << " samples)\n";
  return true;
}

bool PaintApp::SaveOFB(const std::string& path)
{
  vtkNew<vtkOFBWriter> writer;
  vtkNew<ErrorCounter> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(this->OFB);
  writer->SetFileName(path.c_str());
  const bool ok = writer->Write() == 1 && errors->Count == 0;
  if (!ok)
  {
    std::cerr << "OFBPaint: cannot save '" << path << "'"
              << (errors->Text.empty() ? "" : ": " + errors->Text) << "\n";
  }
  return ok;
}

bool PaintApp::Screenshot(const std::string& path)
{
  // The window as it shows (hide the help with 'h' first for the picture alone).
  std::string message;
  const bool ok = ofbexample::WriteWindowPNG(this->Window, path, message);
  if (!ok)
  {
    std::cerr << "OFBPaint: " << message << "\n";
  }
  return ok;
}

// The default view looks at the front of the model (the bunny's face: y up, head toward
// -x), turned by `azimuth` and `elevation` degrees and zoomed by `zoom`.
void PaintApp::ResetView(double azimuth, double elevation, double zoom)
{
  double center[3];
  this->Surface->GetCenter(center);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0], center[1], center[2] + 1.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Azimuth(-35.0 + azimuth);
  camera->Elevation(10.0 + elevation);
  camera->OrthogonalizeViewUp();
  this->Renderer->ResetCamera();
  camera->Zoom(1.2 * zoom);
  this->Window->Render();
}

bool PaintApp::PickPixel(double x, double y, double p[3])
{
  // The widget's picker, with its cell locator on the surface.
  const int height = this->Window->GetSize()[1];
  vtkOFBPainterRepresentation* rep = this->Widget->GetPainterRepresentation();
  if (rep->ComputeInteractionState(static_cast<int>(x), static_cast<int>(height - 1 - y)) !=
    vtkOFBPainterRepresentation::ON_SURFACE)
  {
    return false;
  }
  rep->GetCursorPosition(p);
  return true;
}
}

namespace
{
/// The painter's mirror axes as letters ("x", "xz"), or "none".
std::string MirrorName(vtkOFBPainter* painter)
{
  std::string axes;
  axes += painter->GetMirrorX() ? "x" : "";
  axes += painter->GetMirrorY() ? "y" : "";
  axes += painter->GetMirrorZ() ? "z" : "";
  return axes.empty() ? "none" : axes;
}

void PaintApp::UpdateTexts(const std::string& message)
{
  vtkOFBPainterRepresentation* rep = this->Widget->GetPainterRepresentation();
  std::ostringstream help;
  help << "Left-drag on the surface: paint    other buttons: camera\n"
          "+ / -  brush radius      ] / [  strength\n"
          "f  falloff    t  target (colour, normal, smear)    b  blend mode    m  mirror\n"
          "g  stroke stabilizer (the brush trails the cursor by 0, 1, 2 or 4 radii)\n"
          "1-9  colour:";
  for (int i = 0; i < 9; ++i)
  {
    help << " " << i + 1 << " " << PaletteNames[i];
  }
  help << "\nc  next colour    u or Ctrl+Z  undo    U or Ctrl+Y  redo\n"
          "s  save "
       << SystemTools::GetFilenameName(this->SavePath) << "    l  load it    x  export "
       << SystemTools::GetFilenameName(this->ExportPath)
       << "\np  screenshot (PNG)    d  display: Nearest / NearestMipmapped (the mean of "
          "detail finer than a pixel)\nr  reset the view    h  hide this help    q  quit";
  this->Help->SetInput(help.str().c_str());
  // The brush in two lines: size, strength and colour; falloff, target and blend mode.
  vtkOFBBrush* brush = rep->GetBrush();
  const double* c = brush->GetColor();
  double named[4];
  const bool isPalette =
    rep->GetPaletteColor(rep->GetPaletteIndex(), named) && std::equal(named, named + 4, c);
  std::ostringstream line;
  line << std::setprecision(3) << "radius " << brush->GetRadius() / this->OFB->GetCellSize()
       << " cells   strength " << brush->GetStrength() << "   colour ";
  if (isPalette && rep->GetPaletteIndex() < 9)
  {
    line << rep->GetPaletteIndex() + 1 << " " << PaletteNames[rep->GetPaletteIndex()];
  }
  else
  {
    line << std::setprecision(2) << c[0] << " " << c[1] << " " << c[2] << " " << c[3];
  }
  line << "\nfalloff " << vtkOFBBrush::GetFalloffAsString(brush->GetFalloff()) << "   target "
       << vtkOFBBrush::GetTargetAsString(brush->GetTarget()) << "   blend "
       << vtkOFBBrush::GetBlendModeAsString(brush->GetBlendMode()) << "   mirror "
       << MirrorName(rep->GetPainter()) << "   stabilizer " << rep->GetStabilizerDistance()
       << " r   display "
       << vtkOFBPolyDataMapper::GetLookupModeAsString(this->Mapper->GetLookupMode());
  const std::string status = line.str() + (message.empty() ? "" : "\n" + message);
  this->Status->SetInput(status.c_str());
}

void PaintApp::OnWidget(vtkObject*, unsigned long event, void* clientData, void*)
{
  auto* self = static_cast<PaintApp*>(clientData);
  vtkOFBPainterRepresentation* rep = self->Widget->GetPainterRepresentation();
  std::string message;
  if (event == vtkCommand::EndInteractionEvent)
  {
    message = "stroke: " + std::to_string(rep->GetStrokeSamplesChanged()) + " samples painted";
  }
  self->UpdateTexts(message);
}

void PaintApp::OnKey(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* self = static_cast<PaintApp*>(clientData);
  if (self->Widget->IsPainting() || self->Interactor->GetControlKey())
  {
    return;
  }
  std::string message;
  switch (self->Interactor->GetKeyCode())
  {
    case 'h':
      self->Help->SetVisibility(!self->Help->GetVisibility());
      break;
    case 's':
      message = self->SaveOFB(self->SavePath) ? "saved " + self->SavePath
                                              : "could not save " + self->SavePath;
      break;
    case 'l':
      message = self->LoadOFB(self->SavePath) ? "loaded " + self->SavePath
                                              : "could not load " + self->SavePath;
      break;
    case 'p':
    {
      std::ostringstream name;
      name << "ofbpaint-" << std::setw(3) << std::setfill('0') << self->Screenshots++ << ".png";
      message =
        self->Screenshot(name.str()) ? "wrote " + name.str() : "could not write " + name.str();
      break;
    }
    case 'k':
    {
      vtkOFBPainterRepresentation* rep = self->Widget->GetPainterRepresentation();
      const int* xy = self->Interactor->GetEventPosition();
      double p[3];
      if (rep->ComputeInteractionState(xy[0], xy[1]) != vtkOFBPainterRepresentation::ON_SURFACE)
      {
        message = "move the mouse onto the surface to stamp the decal";
        break;
      }
      rep->GetCursorPosition(p);
      const long long changed = self->StampDecal(p, message);
      message = changed < 0 ? message : "decal: " + std::to_string(changed) + " samples";
      break;
    }
    case 'x':
      ofbpaint::ExportPainting(
        self->Surface, self->OFB, self->ExportPath, self->TextureSize, message);
      break;
    case 'r':
      self->ResetView(0.0, 0.0, 1.0);
      break;
    case 'g':
    {
      // The stroke stabilizer ("lazy mouse"): the brush trails the cursor by 0, 1, 2 or 4
      // brush radii.
      vtkOFBPainterRepresentation* rep = self->Widget->GetPainterRepresentation();
      const double d = rep->GetStabilizerDistance();
      rep->SetStabilizerDistance(d < 1.0 ? 1.0 : (d < 2.0 ? 2.0 : (d < 4.0 ? 4.0 : 0.0)));
      break;
    }
    case 'd':
      // NearestMipmapped filters the OFB's pyramid; a stroke then filters again only the
      // samples of each level near the paint (vtkOFBPyramid), so painting stays fluid.
      self->Mapper->SetLookupMode(
        self->Mapper->GetLookupMode() == vtkOFBPolyDataMapper::LOOKUP_NEAREST
          ? vtkOFBPolyDataMapper::LOOKUP_NEAREST_MIPMAPPED
          : vtkOFBPolyDataMapper::LOOKUP_NEAREST);
      break;
    default:
      return; // the widget's keys and the interactor style's
  }
  self->KeyCallback->SetAbortFlag(1);
  self->UpdateTexts(message);
  self->Window->Render();
}

bool PaintApp::Setup(const std::map<std::string, std::string>& options,
  const std::string& meshPath,
  bool headless)
{
  this->MeshPath = meshPath;
  ofbexample::DataOptions dataOptions;
  dataOptions.Field = options.at("--field");
  dataOptions.Blocks = options.at("--block");
  dataOptions.HasTime = !options.at("--time").empty();
  if ((dataOptions.HasTime &&
        !ofbexample::ParseDouble(options.at("--time"), -1e300, 1e300, dataOptions.Time)) ||
    (!options.at("--time-step").empty() &&
      !ofbexample::ParseInt(options.at("--time-step"), 0, 1000000000, dataOptions.TimeStep)))
  {
    std::cerr << "OFBPaint: --time must be a number and --time-step a step index from 0\n";
    return false;
  }
  ofbexample::DataSurface data;
  if (!ofbexample::ReadDataReported("OFBPaint", meshPath, dataOptions, false, true, data))
  {
    return false;
  }
  this->Surface = data.Surface;
  this->FieldName = dataOptions.Field;
  int resolution = 0, width = 0, height = 0;
  if (!ofbexample::ParseInt(options.at("--resolution"), 8, 8192, resolution) ||
    !ofbexample::ParseInt(options.at("--width"), 64, 8192, width) ||
    !ofbexample::ParseInt(options.at("--height"), 64, 8192, height) ||
    !ofbexample::ParseInt(options.at("--texture"), 1, 16384, this->TextureSize))
  {
    std::cerr << "OFBPaint: --resolution must be in [8, 8192], --width and --height in "
                 "[64, 8192], --texture in [1, 16384]\n";
    return false;
  }
  this->ExportRequested = !options.at("--export").empty();
  this->ExportPath = this->ExportRequested ? options.at("--export")
                                           : ofbpaint::DefaultExportPath(meshPath, "painted");
  this->SaveRequested = !options.at("--save").empty();
  this->SavePath = options.at("--save").empty()
    ? SystemTools::GetFilenameWithoutLastExtension(meshPath) + ".ofb"
    : options.at("--save");

  this->Mapper->SetInputData(this->Surface);
  this->Mapper->UsePaintedNormalsOn(); // the normal target's bumps show in the shading
  this->Actor->SetMapper(this->Mapper);
  this->Actor->GetProperty()->SetAmbient(0.2);
  this->Actor->GetProperty()->SetDiffuse(0.8);
  this->Actor->GetProperty()->SetSpecular(0.15);
  this->Renderer->AddActor(this->Actor);
  this->Renderer->GradientBackgroundOn();
  this->Renderer->SetBackground(0.42, 0.45, 0.5);
  this->Renderer->SetBackground2(0.82, 0.84, 0.88);
  this->Window->AddRenderer(this->Renderer);
  this->Window->SetSize(width, height);
  this->Window->SetWindowName("OFBPaint");
  this->Window->SetOffScreenRendering(headless);
  this->Interactor->SetRenderWindow(this->Window);

  vtkOFBPainterRepresentation* rep = this->Widget->GetPainterRepresentation();
  rep->SetPaintedProp(this->Actor);
  rep->SetRenderer(this->Renderer); // for the headless mode's picks (On() sets it too)
  this->Widget->SetInteractor(this->Interactor);

  const std::string& load = options.at("--load");
  if (!(load.empty() ? this->BuildOFB(resolution) : this->LoadOFB(load)))
  {
    return false;
  }
  if (!options.at("--decal").empty())
  {
    std::string message;
    if (!this->Decals.LoadImage(options.at("--decal"), message))
    {
      std::cerr << "OFBPaint: " << message << "\n";
      return false;
    }
  }
  if (!options.at("--import-texture").empty())
  {
    std::string message;
    vtkSmartPointer<vtkOFB> textured =
      ofbpaint::ImportTexture(this->Surface, this->OFB, options.at("--import-texture"), message);
    if (!textured)
    {
      std::cerr << "OFBPaint: " << message << "\n";
      return false;
    }
    this->UseOFB(textured);
    std::cout << message << "\n";
  }
  // A brush of 1.5 % of the surface's diagonal, whatever the OFB's resolution.
  rep->GetBrush()->SetRadius(0.015 * this->Surface->GetLength());
  this->ResetView(0.0, 0.0, 1.0);
  return true;
}

int PaintApp::RunInteractive(const std::string& play)
{
  for (vtkTextActor* text : { this->Help.Get(), this->Status.Get() })
  {
    text->GetTextProperty()->SetFontSize(15);
    text->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    text->GetTextProperty()->SetShadow(1);
    text->GetTextProperty()->SetBackgroundColor(0.1, 0.1, 0.12);
    text->GetTextProperty()->SetBackgroundOpacity(0.35);
    this->Renderer->AddViewProp(text);
  }
  this->Help->GetTextProperty()->SetVerticalJustificationToTop();
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->SetPosition(0.01, 0.985);
  this->Status->SetPosition(10, 10);

  this->KeyCallback->SetCallback(PaintApp::OnKey);
  this->KeyCallback->SetClientData(this);
  this->Interactor->AddObserver(vtkCommand::CharEvent, this->KeyCallback, 1.0);
  this->WidgetCallback->SetCallback(PaintApp::OnWidget);
  this->WidgetCallback->SetClientData(this);
  for (unsigned long e : { vtkCommand::EndInteractionEvent, vtkCommand::WidgetModifiedEvent })
  {
    this->Widget->AddObserver(e, this->WidgetCallback);
  }
  this->UpdateTexts("");
  this->Widget->On();
  this->Interactor->Initialize();
  this->Window->Render();
  if (!play.empty())
  {
    // A scripted session: the recorded events, then exit.
    vtkNew<ErrorCounter> errors;
    vtkNew<vtkInteractorEventRecorder> recorder;
    recorder->AddObserver(vtkCommand::ErrorEvent, errors);
    recorder->SetInteractor(this->Interactor);
    recorder->SetFileName(play.c_str());
    recorder->Play();
    if (errors->Count > 0)
    {
      std::cerr << "OFBPaint: cannot play '" << play << "': " << errors->Text << "\n";
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  }
  this->Interactor->Start();
  return EXIT_SUCCESS;
}

long long PaintApp::StampDecal(const double p[3], std::string& message)
{
  // Upright on screen: the decal's right along the camera's (direction x up).
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  double d[3], up[3], right[3];
  camera->GetDirectionOfProjection(d);
  camera->GetViewUp(up);
  vtkMath::Cross(d, up, right);
  vtkOFBPainterRepresentation* rep = this->Widget->GetPainterRepresentation();
  const double size = 4.0 * rep->GetBrush()->GetRadius();
  return this->Decals.Stamp(this->Surface, rep->GetPainter(), p, right, size, message);
}

int PaintApp::RunHeadless(const std::string& strokes, const std::string& image)
{
  ofbpaint::StrokeStatistics statistics;
  std::string error;
  const bool ok = ofbpaint::ReplayStrokes(
    strokes,
    this->Widget->GetPainterRepresentation()->GetPainter(),
    [this](double x, double y, double p[3]) { return this->PickPixel(x, y, p); },
    [this](double azimuth, double elevation, double zoom)
    { this->ResetView(azimuth, elevation, zoom); },
    statistics,
    error,
    [this](const double p[3], std::string& message) { return this->StampDecal(p, message); });
  if (!ok)
  {
    std::cerr << "OFBPaint: " << error << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "Replayed " << strokes << ": " << statistics.Strokes << " strokes, "
            << statistics.Points << " points (" << statistics.SkippedPoints
            << " pixel points off the surface skipped), " << statistics.SamplesChanged
            << " samples changed\n";
  this->Window->Render();
  if (!this->Screenshot(image))
  {
    return EXIT_FAILURE;
  }
  std::cout << "Wrote " << image << "\n";
  if (this->SaveRequested && !this->SaveOFB(this->SavePath))
  {
    return EXIT_FAILURE;
  }
  if (this->ExportRequested)
  {
    std::string message;
    const bool exported = ofbpaint::ExportPainting(
      this->Surface, this->OFB, this->ExportPath, this->TextureSize, message);
    (exported ? std::cout : std::cerr) << (exported ? "" : "OFBPaint: ") << message << "\n";
    return exported ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  std::map<std::string, std::string> options = { { "--resolution", "1024" },
    { "--load", "" },
    { "--save", "" },
    { "--export", "" },
    { "--import-texture", "" },
    { "--decal", "" },
    { "--texture", "2048" },
    { "--width", "1200" },
    { "--height", "900" },
    { "--strokes", "" },
    { "--image", "" },
    { "--play", "" },
    { "--field", "" },
    { "--block", "" },
    { "--time", "" },
    { "--time-step", "" } };
  std::string meshPath;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      Usage(argv[0]);
      return EXIT_SUCCESS;
    }
    if (options.count(arg) && i + 1 < argc)
    {
      options[arg] = argv[++i];
    }
    else if (!arg.empty() && arg[0] != '-' && meshPath.empty())
    {
      meshPath = arg;
    }
    else
    {
      std::cerr << "OFBPaint: unexpected argument '" << arg << "'\n";
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }
  const bool headless = !options["--strokes"].empty() || !options["--image"].empty();
  if (headless && (options["--strokes"].empty() || options["--image"].empty()))
  {
    std::cerr << "OFBPaint: --strokes and --image go together\n";
    return EXIT_FAILURE;
  }
  meshPath = meshPath.empty() ? VTKOFB_DATA_DIR "/stanford-bunny.obj" : meshPath;
  PaintApp app;
  if (!app.Setup(options, meshPath, headless))
  {
    return EXIT_FAILURE;
  }
  return headless ? app.RunHeadless(options["--strokes"], options["--image"])
                  : app.RunInteractive(options["--play"]);
}
