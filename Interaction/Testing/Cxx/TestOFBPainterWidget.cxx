// vtkOFBPainterWidget: a recorded stroke over the bunny, the keys, pen lifts and bad set-ups.
#include "vtkOFBTestUtilities.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellPicker.h"
#include "vtkEvent.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkMath.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPainter.h"
#include "vtkOFBPainterRepresentation.h"
#include "vtkOFBPainterWidget.h"
#include "vtkOFBPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWidgetEventTranslator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace vtkofbtest;

namespace
{
const int WindowSize = 300;
const double RadiusInCells = 4.0;

// Counts the widget's events and copies the OFB's colours when a stroke ends.
struct EventLog
{
  int Start = 0;
  int Interaction = 0;
  int End = 0;
  int Modified = 0;
  vtkOFB* OFB = nullptr;
  vtkRenderWindowInteractor* Interactor = nullptr;
  bool Render = false; // whether frames are drawn outside strokes
  std::vector<unsigned char> ColorsAtEnd;
};

std::vector<unsigned char> CopyColors(vtkOFB* ofb)
{
  auto* colors = vtkUnsignedCharArray::SafeDownCast(ofb->GetSampleData()->GetArray("Colors"));
  return colors ? std::vector<unsigned char>(
                    colors->GetPointer(0), colors->GetPointer(0) + colors->GetNumberOfValues())
                : std::vector<unsigned char>();
}

void OnWidgetEvent(vtkObject*, unsigned long event, void* clientData, void*)
{
  auto* log = static_cast<EventLog*>(clientData);
  switch (event)
  {
    case vtkCommand::StartInteractionEvent:
      ++log->Start;
      log->Interactor->SetEnableRender(false);
      break;
    case vtkCommand::InteractionEvent:
      ++log->Interaction;
      break;
    case vtkCommand::EndInteractionEvent:
      ++log->End;
      log->ColorsAtEnd = CopyColors(log->OFB);
      log->Interactor->SetEnableRender(log->Render);
      break;
    default:
      ++log->Modified;
      break;
  }
}

// The bunny rendered through vtkOFBPolyDataMapper from its OFB, with an interactor and a
// painter widget enabled on it (brush radius RadiusInCells cells, palette colour 1).
struct PaintScene
{
  vtkSmartPointer<vtkPolyData> Bunny;
  vtkSmartPointer<vtkOFB> OFB;
  vtkNew<vtkOFBPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkOFBPainterWidget> Widget;
  vtkNew<vtkCallbackCommand> Callback;
  EventLog Log;

  // `render`: whether the widget's Render() calls draw (the tests of the keys and of the
  // stroke logic need no pictures, and llvmpipe frames are slow on a loaded machine). With
  // it, the frames during a stroke are skipped all the same: the frame after the stroke
  // uploads the samples it changed.
  bool Setup(bool render = false)
  {
    this->Bunny = ReadMesh("stanford-bunny.obj");
    if (!this->Bunny)
    {
      return false;
    }
    this->OFB = Build(this->Bunny, 512);
    this->Mapper->SetInputData(this->Bunny);
    this->Mapper->SetOFB(this->OFB);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(WindowSize, WindowSize);
    this->Window->AddRenderer(this->Renderer);
    this->Interactor->SetRenderWindow(this->Window);
    this->Renderer->ResetCamera();
    this->Window->Render();
    this->Interactor->SetEnableRender(render);
    this->Log.Render = render;

    vtkOFBPainterRepresentation* rep = this->Widget->GetPainterRepresentation();
    rep->SetOFB(this->OFB);
    rep->SetPaintedProp(this->Actor);
    rep->GetBrush()->SetRadiusInCells(RadiusInCells, this->OFB);
    this->Widget->SetInteractor(this->Interactor);
    this->Widget->On();

    this->Log.OFB = this->OFB;
    this->Log.Interactor = this->Interactor;
    this->Callback->SetCallback(OnWidgetEvent);
    this->Callback->SetClientData(&this->Log);
    for (unsigned long e : { vtkCommand::StartInteractionEvent,
           vtkCommand::InteractionEvent,
           vtkCommand::EndInteractionEvent,
           vtkCommand::WidgetModifiedEvent })
    {
      this->Widget->AddObserver(e, this->Callback);
    }
    return true;
  }

  void Event(unsigned long event,
    int x,
    int y,
    char key = 0,
    const char* sym = nullptr,
    bool ctrl = false,
    bool shift = false)
  {
    this->Interactor->SetEventInformation(x, y, ctrl, shift, key, 0, sym);
    this->Interactor->InvokeEvent(event);
  }

  void Key(char key, const char* sym, bool ctrl = false, bool shift = false)
  {
    this->Event(vtkCommand::CharEvent, 150, 150, key, sym, ctrl, shift);
  }

  // The surface point under display position (x, y), as the widget picks it.
  bool Pick(int x, int y, double p[3])
  {
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(this->Widget->GetPainterRepresentation()->GetPickTolerance());
    picker->PickFromListOn();
    picker->AddPickList(this->Actor);
    if (!picker->Pick(x, y, 0.0, this->Renderer) || picker->GetCellId() < 0)
    {
      return false;
    }
    picker->GetPickPosition(p);
    return true;
  }
};

// The display positions of a recorded stream's events from the left button press up to
// (not including) the release: where the stroke went.
std::vector<std::array<int, 2>> StrokePositions(const std::string& path)
{
  std::ifstream in(path);
  std::vector<std::array<int, 2>> positions;
  std::string line;
  bool down = false;
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string event;
    std::array<int, 2> xy;
    if (!(words >> event >> xy[0] >> xy[1]) || event[0] == '#')
    {
      continue;
    }
    down =
      event == "LeftButtonPressEvent" ? true : (event == "LeftButtonReleaseEvent" ? false : down);
    if (down && (event == "LeftButtonPressEvent" || event == "MouseMoveEvent"))
    {
      positions.push_back(xy);
    }
  }
  return positions;
}

double DistanceToPolyline(const double x[3], const std::vector<std::array<double, 3>>& path)
{
  double best = VTK_DOUBLE_MAX;
  for (size_t k = 0; k < path.size(); ++k)
  {
    const double* a = path[k].data();
    const double* b = path[k + 1 < path.size() ? k + 1 : k].data();
    double ab[3], ax[3];
    vtkMath::Subtract(b, a, ab);
    vtkMath::Subtract(x, a, ax);
    const double len2 = vtkMath::Dot(ab, ab);
    const double t = len2 > 0.0 ? vtkMath::ClampValue(vtkMath::Dot(ax, ab) / len2, 0.0, 1.0) : 0.0;
    double c[3] = { a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2] };
    best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(x, c)));
  }
  return best;
}
}

TEST(PainterWidget, RecordedStrokePaintsAlongThePathAndUndoRestores)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup(true));
  const std::vector<unsigned char> before = CopyColors(scene.OFB);
  ASSERT_FALSE(before.empty());

  // The surface points of the recorded path, picked as the widget picks them.
  const std::string stream = std::string(VTKOFB_INTERACTION_DATA_DIR) + "/PainterWidgetStroke.log";
  std::vector<std::array<double, 3>> path;
  for (const auto& xy : StrokePositions(stream))
  {
    std::array<double, 3> p;
    ASSERT_TRUE(scene.Pick(xy[0], xy[1], p.data()))
      << "the recorded stroke stays on the bunny at (" << xy[0] << ", " << xy[1] << ")";
    path.push_back(p);
  }
  ASSERT_GE(path.size(), 10u);

  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(scene.Interactor);
  recorder->SetFileName(stream.c_str());
  recorder->Play();

  // One stroke: one Start/End pair, an InteractionEvent per dragged move.
  EXPECT_EQ(scene.Log.Start, 1);
  EXPECT_EQ(scene.Log.End, 1);
  EXPECT_GE(scene.Log.Interaction, static_cast<int>(path.size()));
  EXPECT_EQ(scene.Widget->GetNumberOfStrokes(), 1);

  // The paint at the stroke's end: changed along the path, nowhere farther than the radius
  // from the dabs, which follow the surface between the picked points (within a radius of
  // the chords between them: the bunny's surface bumps between picks).
  const std::vector<unsigned char>& painted = scene.Log.ColorsAtEnd;
  ASSERT_EQ(painted.size(), before.size());
  const double radius = scene.Widget->GetPainterRepresentation()->GetBrush()->GetRadius();
  const double tolerance = 1e-6 * radius;
  std::vector<std::array<double, 3>> dabs;
  vtkPoints* centres = scene.Widget->GetPainterRepresentation()->GetPainter()->GetStrokeDabs();
  for (vtkIdType i = 0; i < centres->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> q;
    centres->GetPoint(i, q.data());
    EXPECT_LT(DistanceToPolyline(q.data(), path), radius) << "dab " << i << " left the path";
    dabs.push_back(q);
  }
  ASSERT_GE(dabs.size(), path.size());
  vtkIdType changed = 0, outside = 0;
  double farthest = 0.0;
  const vtkIdType n = scene.OFB->GetNumberOfSamples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (std::equal(before.begin() + 4 * i, before.begin() + 4 * i + 4, painted.begin() + 4 * i))
    {
      continue;
    }
    ++changed;
    double x[3];
    scene.OFB->GetSamplePosition(i, x);
    const double d = DistanceToPolyline(x, dabs);
    farthest = std::max(farthest, d);
    outside += d > radius + tolerance;
  }
  EXPECT_GT(changed, 0);
  EXPECT_EQ(outside, 0) << "farthest changed sample at " << farthest / radius << " radii";
  for (const auto& p : path)
  {
    const vtkIdType id = scene.OFB->FindClosestSample(p.data());
    ASSERT_GE(id, 0);
    EXPECT_FALSE(
      std::equal(before.begin() + 4 * id, before.begin() + 4 * id + 4, painted.begin() + 4 * id))
      << "the sample under the path at (" << p[0] << ", " << p[1] << ", " << p[2]
      << ") kept its colour";
  }

  // The stream ends with the undo key: every colour is back, bit for bit, and the frame
  // after it uploaded the restored samples only.
  EXPECT_EQ(CopyColors(scene.OFB), before);
  EXPECT_EQ(scene.Log.Modified, 1);
  EXPECT_TRUE(scene.Mapper->GetLastRenderUsedOFB());
  EXPECT_GE(scene.Mapper->GetLastUploadedSampleCount(), changed);
  EXPECT_LT(scene.Mapper->GetLastUploadedSampleCount(), n / 4);
}

namespace
{
/// A short stroke on the bunny: onto (150, 150), press, drag to (160, 152), release; the
/// colours it left in `painted`.
void PaintShortStroke(PaintScene& scene, std::vector<unsigned char>& painted)
{
  scene.Event(vtkCommand::MouseMoveEvent, 150, 150);
  ASSERT_EQ(scene.Widget->GetPainterRepresentation()->GetInteractionState(),
    vtkOFBPainterRepresentation::ON_SURFACE);
  scene.Event(vtkCommand::LeftButtonPressEvent, 150, 150);
  scene.Event(vtkCommand::MouseMoveEvent, 160, 152);
  scene.Event(vtkCommand::LeftButtonReleaseEvent, 160, 152);
  painted = CopyColors(scene.OFB);
}

/// + and - scale the radius, which stays between a quarter of a cell and the OFB's diagonal.
void CheckRadiusKeys(PaintScene& scene)
{
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  vtkOFBBrush* brush = rep->GetBrush();
  const double r0 = brush->GetRadius();

  scene.Key('+', "plus");
  EXPECT_NEAR(brush->GetRadius(), r0 * 1.25, 1e-12 * r0);
  scene.Key('-', "minus");
  scene.Key('-', "minus");
  EXPECT_NEAR(brush->GetRadius(), r0 / 1.25, 1e-12 * r0);
  // Pressed on, the radius stops at a quarter of a cell and at the OFB's diagonal (it
  // reached 0 and infinity before, where no key brought it back).
  vtkOFB* ofb = rep->GetPainter()->GetOFB();
  for (int i = 0; i < 4000; ++i)
  {
    rep->ScaleRadius(-1);
  }
  EXPECT_DOUBLE_EQ(brush->GetRadius(), 0.25 * ofb->GetCellSize());
  for (int i = 0; i < 4000; ++i)
  {
    rep->ScaleRadius(1);
  }
  const double largest = brush->GetRadius();
  EXPECT_TRUE(std::isfinite(largest) && largest > ofb->GetCellSize() * ofb->GetDimensions()[0])
    << largest;
  brush->SetRadius(r0);
}

/// [ and ] the strength, f the falloff, t the target, b the blend mode.
void CheckBrushKeys(PaintScene& scene)
{
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  vtkOFBBrush* brush = rep->GetBrush();
  brush->SetStrength(0.5);
  scene.Key(']', "bracketright");
  EXPECT_NEAR(brush->GetStrength(), 0.6, 1e-12);
  for (int i = 0; i < 12; ++i)
  {
    scene.Key('[', "bracketleft");
  }
  EXPECT_EQ(brush->GetStrength(), 0.0);
  brush->SetStrength(1.0);

  // Falloffs cycle through the seven curves, skipping Custom.
  brush->SetFalloff(vtkOFBBrush::FALLOFF_CONSTANT);
  std::vector<int> falloffs;
  for (int i = 0; i < 7; ++i)
  {
    scene.Key('f', "f");
    falloffs.push_back(brush->GetFalloff());
  }
  EXPECT_EQ(falloffs,
    (std::vector<int>{ vtkOFBBrush::FALLOFF_LINEAR,
      vtkOFBBrush::FALLOFF_SMOOTH,
      vtkOFBBrush::FALLOFF_SPHERE,
      vtkOFBBrush::FALLOFF_ROOT,
      vtkOFBBrush::FALLOFF_SHARP,
      vtkOFBBrush::FALLOFF_GAUSSIAN,
      vtkOFBBrush::FALLOFF_CONSTANT }));

  scene.Key('t', "t");
  EXPECT_EQ(brush->GetTarget(), vtkOFBBrush::TARGET_NORMAL);
  scene.Key('t', "t");
  EXPECT_EQ(brush->GetTarget(), vtkOFBBrush::TARGET_SMEAR);
  scene.Key('t', "t");
  EXPECT_EQ(brush->GetTarget(), vtkOFBBrush::TARGET_COLOR);

  scene.Key('b', "b");
  EXPECT_EQ(brush->GetBlendMode(), vtkOFBBrush::BLEND_ADD);
  brush->SetBlendMode(vtkOFBBrush::BLEND_MIX);
}

/// m cycles the mirror plane; the cursor shows the reflection.
void CheckMirrorKeys(PaintScene& scene)
{
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  // Mirror: none, x, y, z, none (one axis at a time).
  vtkOFBPainter* painter = rep->GetPainter();
  ASSERT_NE(painter, nullptr);
  std::vector<int> mirrors;
  for (int i = 0; i < 4; ++i)
  {
    scene.Key('m', "m");
    mirrors.push_back((painter->GetMirrorX() ? 1 : 0) | (painter->GetMirrorY() ? 2 : 0) |
      (painter->GetMirrorZ() ? 4 : 0));
  }
  EXPECT_EQ(mirrors, (std::vector<int>{ 1, 2, 4, 0 }));
  // The cursor shows a ring and a tick for the dab and one of each for its reflection.
  scene.Event(vtkCommand::MouseMoveEvent, 150, 150);
  ASSERT_EQ(rep->GetInteractionState(), vtkOFBPainterRepresentation::ON_SURFACE);
  EXPECT_EQ(rep->GetCursorPolyData()->GetNumberOfLines(), 2);
  painter->SetMirrorOrigin(0.01, 0.0, 0.0);
  scene.Key('m', "m");
  ASSERT_TRUE(painter->GetMirrorX());
  vtkPolyData* cursor = rep->GetCursorPolyData();
  ASSERT_EQ(cursor->GetNumberOfLines(), 4);
  // The second tick starts at the reflection of the cursor's position across x = 0.01.
  vtkIdType count;
  const vtkIdType* ids;
  cursor->GetLines()->GetCellAtId(3, count, ids);
  double tick[3];
  cursor->GetPoint(ids[0], tick);
  const double* at = rep->GetCursorPosition();
  EXPECT_NEAR(tick[0], 0.02 - at[0], 1e-6); // points stored as floats
  EXPECT_NEAR(tick[1], at[1], 1e-6);
  EXPECT_NEAR(tick[2], at[2], 1e-6);
  scene.Key('m', "m");
  scene.Key('m', "m");
  scene.Key('m', "m");
  ASSERT_FALSE(painter->GetMirrorX() || painter->GetMirrorY() || painter->GetMirrorZ());
}

/// Digits choose a palette colour, c the next one.
void CheckPaletteKeys(PaintScene& scene)
{
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  vtkOFBBrush* brush = rep->GetBrush();
  double rgba[4];
  scene.Key('6', "6");
  ASSERT_TRUE(rep->GetPaletteColor(5, rgba));
  EXPECT_EQ(rep->GetPaletteIndex(), 5);
  for (int c = 0; c < 4; ++c)
  {
    EXPECT_EQ(brush->GetColor()[c], rgba[c]);
  }
  scene.Key('c', "c");
  EXPECT_EQ(rep->GetPaletteIndex(), 6);
  // Nine colours: 'c' comes back to the first after the ninth, index 9 is not one, and
  // setting colour 11 makes twelve (the count was of doubles, four a colour: 'c' walked
  // past the palette's end and SetPaletteColor wrote past it).
  EXPECT_EQ(rep->GetNumberOfPaletteColors(), 9);
  EXPECT_FALSE(rep->GetPaletteColor(9, rgba));
  for (int i = 0; i < 3; ++i)
  {
    scene.Key('c', "c");
  }
  EXPECT_EQ(rep->GetPaletteIndex(), 0);
  rep->SetPaletteColor(11, 0.2, 0.4, 0.6);
  EXPECT_EQ(rep->GetNumberOfPaletteColors(), 12);
  ASSERT_TRUE(rep->GetPaletteColor(11, rgba));
  EXPECT_DOUBLE_EQ(rgba[2], 0.6);
  ASSERT_TRUE(rep->GetPaletteColor(10, rgba));
  EXPECT_DOUBLE_EQ(rgba[0], 1.0); // new entries opaque white
  rep->SetNumberOfPaletteColors(9);
}

/// Keys left to the style, undo and redo, and no key with the shortcuts off.
void CheckUndoKeysAndShortcutsOff(PaintScene& scene)
{
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  vtkOFBBrush* brush = rep->GetBrush();
  const int modifiedBefore = scene.Log.Modified;
  scene.Key('r', "r"); // not a painting key: left to the interactor style
  EXPECT_EQ(scene.Log.Modified, modifiedBefore);

  // Undo with Ctrl+Z (X11's control character 26), redo with Shift+U and Ctrl+Y.
  const std::vector<unsigned char> before = CopyColors(scene.OFB);
  std::vector<unsigned char> painted;
  ASSERT_NO_FATAL_FAILURE(PaintShortStroke(scene, painted));
  ASSERT_NE(painted, before);
  scene.Key(26, "z", true);
  EXPECT_EQ(CopyColors(scene.OFB), before);
  scene.Key('U', "U", false, true);
  EXPECT_EQ(CopyColors(scene.OFB), painted);
  scene.Key('u', "u");
  EXPECT_EQ(CopyColors(scene.OFB), before);
  scene.Key(25, "y", true);
  EXPECT_EQ(CopyColors(scene.OFB), painted);

  // With the shortcuts off the keys do nothing.
  scene.Widget->KeyboardShortcutsOff();
  const double r1 = brush->GetRadius();
  scene.Key('+', "plus");
  EXPECT_EQ(brush->GetRadius(), r1);
}
}

TEST(PainterWidget, KeysChangeTheBrushAndAreTakenFromTheStyle)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup());
  ASSERT_NO_FATAL_FAILURE(CheckRadiusKeys(scene));
  ASSERT_NO_FATAL_FAILURE(CheckBrushKeys(scene));
  ASSERT_NO_FATAL_FAILURE(CheckMirrorKeys(scene));
  ASSERT_NO_FATAL_FAILURE(CheckPaletteKeys(scene));
  ASSERT_NO_FATAL_FAILURE(CheckUndoKeysAndShortcutsOff(scene));
}

TEST(PainterWidget, OneKeyReboundThroughTheEventTranslator)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup());
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  vtkOFBBrush* brush = rep->GetBrush();

  // Undo moves from `u` to `z`; `u` is dropped and goes to the interactor style.
  vtkWidgetEventTranslator* keys = scene.Widget->GetEventTranslator();
  EXPECT_EQ(
    keys->RemoveTranslation(vtkCommand::CharEvent, vtkEvent::AnyModifier, 'u', 0, nullptr), 1);
  keys->SetTranslation(
    vtkCommand::CharEvent, vtkEvent::AnyModifier, 'z', 0, nullptr, vtkOFBPainterWidget::UNDO);

  const std::vector<unsigned char> before = CopyColors(scene.OFB);
  std::vector<unsigned char> painted;
  ASSERT_NO_FATAL_FAILURE(PaintShortStroke(scene, painted));
  ASSERT_NE(painted, before);

  const int modifiedBefore = scene.Log.Modified;
  scene.Key('u', "u");
  EXPECT_EQ(CopyColors(scene.OFB), painted) << "the dropped key still undoes";
  EXPECT_EQ(scene.Log.Modified, modifiedBefore);
  scene.Key('z', "z");
  EXPECT_EQ(CopyColors(scene.OFB), before) << "the new key does not undo";
  EXPECT_EQ(scene.Log.Modified, modifiedBefore + 1);

  // The other keys are as they were: redo with Shift+U and Ctrl+Y, undo with Ctrl+Z,
  // the brush keys.
  scene.Key('U', "U", false, true);
  EXPECT_EQ(CopyColors(scene.OFB), painted);
  scene.Key(26, "z", true);
  EXPECT_EQ(CopyColors(scene.OFB), before);
  scene.Key(25, "y", true);
  EXPECT_EQ(CopyColors(scene.OFB), painted);
  const double r0 = brush->GetRadius();
  scene.Key('+', "plus");
  EXPECT_NEAR(brush->GetRadius(), r0 * 1.25, 1e-12 * r0);
  brush->SetStrength(0.5);
  scene.Key('[', "bracketleft");
  EXPECT_NEAR(brush->GetStrength(), 0.4, 1e-12);
}

TEST(PainterWidget, StrokeLeavingTheSurfaceIsOneUndoStep)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup());
  const std::vector<unsigned char> before = CopyColors(scene.OFB);
  // On the bunny, off it (the window's corner), back on it: the pen lifts over the gap.
  scene.Event(vtkCommand::MouseMoveEvent, 140, 150);
  scene.Event(vtkCommand::LeftButtonPressEvent, 140, 150);
  scene.Event(vtkCommand::MouseMoveEvent, 145, 150);
  scene.Event(vtkCommand::MouseMoveEvent, 3, 3);
  scene.Event(vtkCommand::MouseMoveEvent, 165, 155);
  scene.Event(vtkCommand::MouseMoveEvent, 170, 155);
  scene.Event(vtkCommand::LeftButtonReleaseEvent, 170, 155);
  EXPECT_EQ(scene.Log.Start, 1);
  EXPECT_EQ(scene.Log.End, 1);
  const std::vector<unsigned char> painted = CopyColors(scene.OFB);
  ASSERT_NE(painted, before);

  // Nothing painted between the two pieces: the sample half-way stays unpainted.
  double a[3], b[3], mid[3];
  ASSERT_TRUE(scene.Pick(145, 150, a));
  ASSERT_TRUE(scene.Pick(165, 155, b));
  const double radius = scene.Widget->GetPainterRepresentation()->GetBrush()->GetRadius();
  if (std::sqrt(vtkMath::Distance2BetweenPoints(a, b)) > 3.0 * radius)
  {
    for (int i = 0; i < 3; ++i)
    {
      mid[i] = 0.5 * (a[i] + b[i]);
    }
    scene.OFB->ForEachSampleInSphere(mid,
      0.4 * radius,
      [&](vtkIdType id, double)
      {
        EXPECT_TRUE(std::equal(
          before.begin() + 4 * id, before.begin() + 4 * id + 4, painted.begin() + 4 * id))
          << "sample " << id << " between the pieces was painted";
      });
  }

  EXPECT_GT(scene.Widget->GetPainterRepresentation()->Undo(), 0);
  EXPECT_EQ(CopyColors(scene.OFB), before);
  EXPECT_GT(scene.Widget->GetPainterRepresentation()->Redo(), 0);
  EXPECT_EQ(CopyColors(scene.OFB), painted);
}

TEST(PainterWidget, StabilizerTrailsTheCursor)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup());
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  const double radius = rep->GetBrush()->GetRadius();
  const double string = 3.0 * radius;
  rep->SetStabilizerDistance(3.0);
  const std::vector<unsigned char> before = CopyColors(scene.OFB);
  scene.Event(vtkCommand::MouseMoveEvent, 150, 150);
  ASSERT_EQ(rep->GetInteractionState(), vtkOFBPainterRepresentation::ON_SURFACE);
  scene.Event(vtkCommand::LeftButtonPressEvent, 150, 150);
  const vtkIdType first = rep->GetStrokeSamplesChanged();
  EXPECT_GT(first, 0) << "the press paints its dab";
  double start[3];
  rep->GetCursorPosition(start);
  // While the cursor stays within the string's length of that dab, nothing more.
  int x = 151;
  for (; x < 230; ++x)
  {
    scene.Event(vtkCommand::MouseMoveEvent, x, 150);
    if (vtkMath::Distance2BetweenPoints(rep->GetCursorPosition(), start) > string * string)
    {
      break;
    }
    EXPECT_EQ(rep->GetStrokeSamplesChanged(), first) << "slack string, x = " << x;
  }
  ASSERT_LT(x, 230) << "the cursor never left the string's reach";
  // Farther on, the brush follows a string's length behind the cursor: every dab of the
  // stroke lies about that far or farther from the cursor, the last one about that far.
  for (int k = 1; k <= 10; ++k)
  {
    scene.Event(vtkCommand::MouseMoveEvent, x + 2 * k, 150);
  }
  EXPECT_GT(rep->GetStrokeSamplesChanged(), first);
  const double* cursor = rep->GetCursorPosition();
  vtkPoints* dabs = rep->GetPainter()->GetStrokeDabs();
  ASSERT_GT(dabs->GetNumberOfPoints(), 1);
  double nearest = VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i < dabs->GetNumberOfPoints(); ++i)
  {
    nearest =
      std::min(nearest, std::sqrt(vtkMath::Distance2BetweenPoints(dabs->GetPoint(i), cursor)));
  }
  EXPECT_GT(nearest, 0.9 * string);
  EXPECT_LT(nearest, string + 0.5 * radius);
  scene.Event(vtkCommand::LeftButtonReleaseEvent, x + 20, 150);
  EXPECT_GT(rep->Undo(), 0);
  EXPECT_EQ(CopyColors(scene.OFB), before);
}

TEST(PainterWidget, PressOffTheSurfaceIsLeftToTheStyle)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup());
  const std::vector<unsigned char> before = CopyColors(scene.OFB);
  scene.Event(vtkCommand::MouseMoveEvent, 3, 3);
  EXPECT_EQ(scene.Widget->GetPainterRepresentation()->GetInteractionState(),
    vtkOFBPainterRepresentation::OUTSIDE);
  scene.Event(vtkCommand::LeftButtonPressEvent, 3, 3);
  scene.Event(vtkCommand::MouseMoveEvent, 150, 150);
  scene.Event(vtkCommand::LeftButtonReleaseEvent, 150, 150);
  EXPECT_EQ(scene.Log.Start, 0);
  EXPECT_EQ(CopyColors(scene.OFB), before);
}

TEST(PainterWidget, ClearErrorsWithoutOFBOrPainter)
{
  PaintScene scene;
  ASSERT_TRUE(scene.Setup());
  vtkOFBPainterRepresentation* rep = scene.Widget->GetPainterRepresentation();
  MessageObserver* observer = MessageObserver::New();
  observer->Watch(rep);

  rep->SetOFB(nullptr);
  scene.Event(vtkCommand::MouseMoveEvent, 150, 150);
  scene.Event(vtkCommand::LeftButtonPressEvent, 150, 150);
  scene.Event(vtkCommand::LeftButtonReleaseEvent, 150, 150);
  EXPECT_NE(observer->Errors.find("no OFB"), std::string::npos) << observer->Errors;
  EXPECT_EQ(scene.Log.Start, 0);

  observer->Clear();
  rep->SetPainter(nullptr);
  EXPECT_EQ(rep->GetBrush(), nullptr);
  scene.Event(vtkCommand::LeftButtonPressEvent, 150, 150);
  scene.Event(vtkCommand::LeftButtonReleaseEvent, 150, 150);
  EXPECT_NE(observer->Errors.find("no painter"), std::string::npos) << observer->Errors;
  observer->Clear();
  scene.Key('+', "plus");
  scene.Key('u', "u");
  EXPECT_NE(observer->Errors.find("no painter"), std::string::npos);
  observer->Clear();
  scene.Key('m', "m");
  EXPECT_NE(observer->Errors.find("NextMirror: no painter"), std::string::npos);
  EXPECT_EQ(scene.Log.Start, 0);

  std::ostringstream os;
  rep->Print(os);
  scene.Widget->Print(os);
  EXPECT_NE(os.str().find("RadiusFactor: 1.25"), std::string::npos);
  EXPECT_NE(os.str().find("KeyboardShortcuts: On"), std::string::npos);
  observer->Delete();
}
