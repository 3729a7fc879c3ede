#include "vtkOFBPainterRepresentation.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellPicker.h"
#include "vtkDataSet.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBBrushRing.h"
#include "vtkOFBPainter.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStaticCellLocator.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkOFBPainterRepresentation);

namespace
{
// The default palette: red, orange, yellow, green, cyan, blue, purple, white, black.
const double DefaultPalette[9][3] = { { 0.85, 0.10, 0.10 },
  { 1.00, 0.55, 0.05 },
  { 1.00, 0.88, 0.10 },
  { 0.15, 0.70, 0.20 },
  { 0.10, 0.75, 0.85 },
  { 0.10, 0.25, 0.90 },
  { 0.55, 0.20, 0.75 },
  { 1.00, 1.00, 1.00 },
  { 0.05, 0.05, 0.05 } };
// Cursor colours of the normal and smear targets.
const double NormalCursorColor[3] = { 0.55, 0.75, 1.0 };
const double SmearCursorColor[3] = { 1.0, 0.9, 0.2 };
}

//------------------------------------------------------------------------------
vtkOFBPainterRepresentation::vtkOFBPainterRepresentation()
  : Painter(nullptr)
  , PaintedProp(nullptr)
  , Picker(vtkCellPicker::New())
  , PickTolerance(0.0005)
  , MaximumJump(4.0)
  , StabilizerDistance(0.0)
  , CursorResolution(64)
  , CursorLift(0.05)
  , RadiusFactor(1.25)
  , StrengthStep(0.1)
  , PaletteIndex(0)
  , PenDown(false)
  , HasLastPoint(false)
  , PiecePainted(false)
  , StrokePieces(0)
  , StrokeSamplesChanged(0)
  , ConformCursor(true)
  , CursorPolyData(vtkPolyData::New())
  , PickLocator(vtkStaticCellLocator::New())
  , PickLocatorInstalled(false)
  , CursorMapper(vtkPolyDataMapper::New())
  , CursorActor(vtkActor::New())
  , CursorProperty(vtkProperty::New())
{
  this->InteractionState = OUTSIDE;
  for (const auto& rgb : DefaultPalette)
  {
    this->Palette.insert(this->Palette.end(), { rgb[0], rgb[1], rgb[2], 1.0 });
  }
  for (int i = 0; i < 3; ++i)
  {
    this->CursorPosition[i] = this->LastStrokePoint[i] = this->LastPickedPoint[i] = 0.0;
    this->CursorNormal[i] = i == 2 ? 1.0 : 0.0;
  }

  vtkOFBPainter* painter = vtkOFBPainter::New();
  vtkOFBBrush* brush = vtkOFBBrush::New();
  brush->SetColor(this->Palette[0], this->Palette[1], this->Palette[2]);
  painter->SetBrush(brush);
  brush->Delete();
  this->SetPainter(painter);
  painter->Delete();

  this->Picker->PickFromListOff();
  vtkNew<vtkPoints> points;
  this->CursorPolyData->SetPoints(points);
  this->CursorMapper->SetInputData(this->CursorPolyData);
  this->CursorActor->SetMapper(this->CursorMapper);
  this->CursorActor->PickableOff();
  this->CursorActor->VisibilityOff();
  this->CursorProperty->SetLineWidth(2.0);
  this->CursorProperty->SetLighting(false);
  this->CursorActor->SetProperty(this->CursorProperty);
}

//------------------------------------------------------------------------------
vtkOFBPainterRepresentation::~vtkOFBPainterRepresentation()
{
  this->SetPainter(nullptr);
  this->SetPaintedProp(nullptr);
  this->Picker->Delete();
  this->CursorPolyData->Delete();
  this->PickLocator->Delete();
  this->CursorMapper->Delete();
  this->CursorActor->Delete();
  this->CursorProperty->Delete();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::SetPainter(vtkOFBPainter* painter)
{
  if (painter == this->Painter)
  {
    return;
  }
  if (this->PenDown && this->Painter)
  {
    this->Painter->EndStroke();
  }
  this->PenDown = false;
  this->UndoPieces.clear();
  this->RedoPieces.clear();
  vtkOFBPainter* old = this->Painter;
  this->Painter = painter;
  if (painter)
  {
    painter->Register(this);
  }
  if (old)
  {
    old->UnRegister(this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::SetOFB(vtkOFB* ofb)
{
  if (!this->Painter)
  {
    vtkErrorMacro("SetOFB: no painter set.");
    return;
  }
  if (ofb != this->Painter->GetOFB())
  {
    // The painter ends its stroke and drops its history on a new OFB.
    this->PenDown = false;
    this->UndoPieces.clear();
    this->RedoPieces.clear();
    this->Painter->SetOFB(ofb);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBPainterRepresentation::GetOFB()
{
  return this->Painter ? this->Painter->GetOFB() : nullptr;
}

//------------------------------------------------------------------------------
vtkOFBBrush* vtkOFBPainterRepresentation::GetBrush()
{
  return this->Painter ? this->Painter->GetBrush() : nullptr;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::SetPaintedProp(vtkProp* prop)
{
  if (prop == this->PaintedProp)
  {
    return;
  }
  if (this->PaintedProp)
  {
    this->PaintedProp->UnRegister(this);
  }
  this->PaintedProp = prop;
  this->Picker->InitializePickList();
  if (prop)
  {
    prop->Register(this);
    this->Picker->AddPickList(prop);
  }
  this->Picker->SetPickFromList(prop != nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::SetPaletteColor(int index, double r, double g, double b, double a)
{
  if (index < 0 || index >= 1024)
  {
    vtkErrorMacro("SetPaletteColor: index " << index << " is outside [0, 1023].");
    return;
  }
  if (index >= this->GetNumberOfPaletteColors())
  {
    this->SetNumberOfPaletteColors(index + 1);
  }
  const double rgba[4] = { r, g, b, a };
  for (int c = 0; c < 4; ++c)
  {
    this->Palette[4 * index + c] = vtkMath::ClampValue(rgba[c], 0.0, 1.0);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::SetNumberOfPaletteColors(int n)
{
  n = std::max(0, std::min(n, 1024));
  this->Palette.resize(4 * static_cast<size_t>(n), 1.0); // new entries opaque white
  this->PaletteIndex = std::min(this->PaletteIndex, std::max(0, n - 1));
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkOFBPainterRepresentation::GetPaletteColor(int index, double rgba[4]) const
{
  if (index < 0 || index >= this->GetNumberOfPaletteColors())
  {
    return false;
  }
  std::copy_n(this->Palette.data() + 4 * index, 4, rgba);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::ScaleRadius(int steps)
{
  if (vtkOFBBrush* brush = this->GetBrush())
  {
    // Kept between a quarter of a cell (a smaller dab paints one sample at most) and the
    // OFB's diagonal (a larger one paints them all): pressed on, the keys reached 0 or
    // infinity, which no key brought back.
    double r = brush->GetRadius() * std::pow(this->RadiusFactor, steps);
    vtkOFB* ofb = this->Painter->GetOFB();
    if (ofb && ofb->GetCellSize() > 0.0)
    {
      const vtkIdType* d = ofb->GetDimensions();
      const double cell = ofb->GetCellSize();
      const double diagonal =
        cell * std::sqrt(static_cast<double>(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      r = std::min(std::max(r, 0.25 * cell), diagonal);
    }
    if (std::isfinite(r) && r > 0.0)
    {
      brush->SetRadius(r);
    }
    this->BuildRepresentation();
    return;
  }
  vtkErrorMacro("ScaleRadius: no painter or no brush set.");
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::AddStrength(int steps)
{
  if (vtkOFBBrush* brush = this->GetBrush())
  {
    // Rounded to the step so that repeated presses land on 0 and 1 exactly.
    const double s = brush->GetStrength() + steps * this->StrengthStep;
    brush->SetStrength(std::round(s / this->StrengthStep) * this->StrengthStep);
    return;
  }
  vtkErrorMacro("AddStrength: no painter or no brush set.");
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::NextFalloff()
{
  if (vtkOFBBrush* brush = this->GetBrush())
  {
    // The falloffs in their order, Custom (a curve set in code) left out.
    int next = (brush->GetFalloff() + 1) % vtkOFBBrush::NUMBER_OF_FALLOFFS;
    if (next == vtkOFBBrush::FALLOFF_CUSTOM)
    {
      next = (next + 1) % vtkOFBBrush::NUMBER_OF_FALLOFFS;
    }
    brush->SetFalloff(next);
    return;
  }
  vtkErrorMacro("NextFalloff: no painter or no brush set.");
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::NextTarget()
{
  if (vtkOFBBrush* brush = this->GetBrush())
  {
    brush->SetTarget((brush->GetTarget() + 1) % vtkOFBBrush::NUMBER_OF_TARGETS);
    this->BuildRepresentation();
    return;
  }
  vtkErrorMacro("NextTarget: no painter or no brush set.");
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::NextMirror()
{
  vtkOFBPainter* painter = this->GetPainter();
  if (!painter)
  {
    vtkErrorMacro("NextMirror: no painter set.");
    return;
  }
  // none -> x -> y -> z -> none; from a combination set elsewhere, back to none.
  const bool x = painter->GetMirrorX(), y = painter->GetMirrorY(), z = painter->GetMirrorZ();
  const int count = (x ? 1 : 0) + (y ? 1 : 0) + (z ? 1 : 0);
  painter->SetMirrorX(count == 0);
  painter->SetMirrorY(count == 1 && x);
  painter->SetMirrorZ(count == 1 && y);
  this->BuildRepresentation(); // the cursor's rings at the reflections
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::NextBlendMode()
{
  if (vtkOFBBrush* brush = this->GetBrush())
  {
    brush->SetBlendMode((brush->GetBlendMode() + 1) % vtkOFBBrush::NUMBER_OF_BLEND_MODES);
    return;
  }
  vtkErrorMacro("NextBlendMode: no painter or no brush set.");
}

//------------------------------------------------------------------------------
bool vtkOFBPainterRepresentation::SelectPaletteColor(int index)
{
  vtkOFBBrush* brush = this->GetBrush();
  if (!brush)
  {
    vtkErrorMacro("SelectPaletteColor: no painter or no brush set.");
    return false;
  }
  double rgba[4];
  if (!this->GetPaletteColor(index, rgba))
  {
    return false;
  }
  this->PaletteIndex = index;
  brush->SetColor(rgba);
  this->BuildRepresentation();
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::NextPaletteColor()
{
  const int n = this->GetNumberOfPaletteColors();
  if (n > 0)
  {
    this->SelectPaletteColor((this->PaletteIndex + 1) % n);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainterRepresentation::Undo()
{
  return this->StepHistory(true);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainterRepresentation::Redo()
{
  return this->StepHistory(false);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainterRepresentation::StepHistory(bool undo)
{
  if (!this->Painter)
  {
    vtkErrorMacro(<< (undo ? "Undo" : "Redo") << ": no painter set.");
    return 0;
  }
  if (this->PenDown)
  {
    return 0;
  }
  // A widget stroke is one or more painter steps (see ContinueStroke); a step painted
  // through the painter directly counts as one.
  std::vector<int>& from = undo ? this->UndoPieces : this->RedoPieces;
  std::vector<int>& to = undo ? this->RedoPieces : this->UndoPieces;
  const int pieces = from.empty() ? 1 : from.back();
  if (!from.empty())
  {
    from.pop_back();
  }
  vtkIdType changed = 0;
  int done = 0;
  for (; done < pieces && (undo ? this->Painter->CanUndo() : this->Painter->CanRedo()); ++done)
  {
    changed += undo ? this->Painter->Undo() : this->Painter->Redo();
  }
  if (done > 0)
  {
    to.push_back(done);
  }
  return changed;
}

//------------------------------------------------------------------------------
std::string vtkOFBPainterRepresentation::GetBrushDescription()
{
  vtkOFBBrush* brush = this->GetBrush();
  if (!brush)
  {
    return "no brush";
  }
  const double* rgba = brush->GetColor();
  std::ostringstream os;
  os << std::setprecision(3) << "radius " << brush->GetRadius();
  vtkOFB* ofb = this->GetOFB();
  if (ofb && ofb->GetCellSize() > 0.0)
  {
    os << " (" << std::setprecision(3) << brush->GetRadius() / ofb->GetCellSize() << " cells)";
  }
  os << std::setprecision(2) << ", strength " << brush->GetStrength() << ", colour (" << rgba[0]
     << " " << rgba[1] << " " << rgba[2] << " " << rgba[3] << "), "
     << vtkOFBBrush::GetFalloffAsString(brush->GetFalloff()) << " falloff, target "
     << vtkOFBBrush::GetTargetAsString(brush->GetTarget()) << ", blend "
     << vtkOFBBrush::GetBlendModeAsString(brush->GetBlendMode());
  return os.str();
}

//------------------------------------------------------------------------------
bool vtkOFBPainterRepresentation::CanPaint()
{
  if (!this->Painter)
  {
    vtkErrorMacro("Cannot paint: no painter set (SetPainter).");
    return false;
  }
  if (!this->Painter->GetOFB())
  {
    vtkErrorMacro("Cannot paint: the painter has no OFB (SetOFB).");
    return false;
  }
  if (!this->Painter->GetBrush())
  {
    vtkErrorMacro("Cannot paint: the painter has no brush (vtkOFBPainter::SetBrush).");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBPainterRepresentation::PickSurface(double x, double y)
{
  // Before the window's first render the renderer has no aspect yet (VTK leaves it
  // uninitialised, and a pick would read it): nothing is under the mouse then.
  vtkRenderWindow* window = this->Renderer ? this->Renderer->GetRenderWindow() : nullptr;
  if (!window || window->GetNeverRendered())
  {
    return false;
  }
  this->UpdatePickLocator();
  this->Picker->SetTolerance(this->PickTolerance);
  if (!this->Picker->Pick(x, y, 0.0, this->Renderer) || this->Picker->GetCellId() < 0)
  {
    return false;
  }
  this->Picker->GetPickPosition(this->CursorPosition);
  this->Picker->GetPickNormal(this->CursorNormal);
  if (vtkMath::Normalize(this->CursorNormal) == 0.0)
  {
    this->CursorNormal[0] = this->CursorNormal[1] = 0.0;
    this->CursorNormal[2] = 1.0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::UpdatePickLocator()
{
  // A cell locator on the painted actor's surface: vtkCellPicker otherwise intersects the
  // ray with every cell, and the widget picks at every mouse move.
  vtkActor* actor = vtkActor::SafeDownCast(this->PaintedProp);
  vtkDataSet* surface =
    actor && actor->GetMapper() ? actor->GetMapper()->GetInputAsDataSet() : nullptr;
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    if (this->PickLocatorInstalled)
    {
      this->Picker->RemoveAllLocators();
      this->PickLocatorInstalled = false;
    }
    return;
  }
  if (surface != this->PickLocator->GetDataSet() ||
    surface->GetMTime() > this->PickLocator->GetMTime() || !this->PickLocatorInstalled)
  {
    this->PickLocator->SetDataSet(surface);
    this->PickLocator->BuildLocator();
    this->PickLocator->Modified();
    this->Picker->RemoveAllLocators();
    this->Picker->AddLocator(this->PickLocator);
    this->PickLocatorInstalled = true;
  }
}

//------------------------------------------------------------------------------
int vtkOFBPainterRepresentation::ComputeInteractionState(int X, int Y, int vtkNotUsed(modify))
{
  const bool hit = this->PickSurface(X, Y);
  if (this->InteractionState != PAINTING)
  {
    this->InteractionState = hit ? ON_SURFACE : OUTSIDE;
  }
  this->BuildRepresentation();
  return hit ? ON_SURFACE : OUTSIDE;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::StartWidgetInteraction(double eventPos[2])
{
  this->StartEventPosition[0] = eventPos[0];
  this->StartEventPosition[1] = eventPos[1];
  this->StartEventPosition[2] = 0.0;
  this->StrokeSamplesChanged = 0;
  if (!this->CanPaint())
  {
    return;
  }
  const bool hit = this->PickSurface(eventPos[0], eventPos[1]);
  this->Painter->BeginStroke();
  this->PenDown = true;
  this->HasLastPoint = false;
  this->PiecePainted = false;
  this->StrokePieces = 1;
  this->InteractionState = PAINTING;
  this->ContinueStroke(hit);
  this->BuildRepresentation();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::WidgetInteraction(double eventPos[2])
{
  const bool hit = this->PickSurface(eventPos[0], eventPos[1]);
  if (this->PenDown)
  {
    this->ContinueStroke(hit);
  }
  this->BuildRepresentation();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::ContinueStroke(bool hit)
{
  if (!hit)
  {
    this->HasLastPoint = false; // lift the pen over the gap
    return;
  }
  vtkOFBBrush* brush = this->Painter->GetBrush();
  const double radius = brush ? brush->GetRadius() : 0.0;
  const double jump = this->MaximumJump * radius;
  if (this->HasLastPoint &&
    vtkMath::Distance2BetweenPoints(this->LastPickedPoint, this->CursorPosition) > jump * jump)
  {
    this->HasLastPoint = false;
  }
  std::copy_n(this->CursorPosition, 3, this->LastPickedPoint);
  // With the stabilizer the brush trails the cursor by a string of that length.
  double target[3] = { this->CursorPosition[0], this->CursorPosition[1], this->CursorPosition[2] };
  const double string = this->StabilizerDistance * radius;
  if (this->HasLastPoint && string > 0.0)
  {
    const double d =
      std::sqrt(vtkMath::Distance2BetweenPoints(this->LastStrokePoint, this->CursorPosition));
    if (d <= string)
    {
      return; // the string is slack: nothing to paint
    }
    const double t = (d - string) / d;
    for (int i = 0; i < 3; ++i)
    {
      target[i] =
        this->LastStrokePoint[i] + t * (this->CursorPosition[i] - this->LastStrokePoint[i]);
    }
  }
  if (!this->HasLastPoint && this->PiecePainted)
  {
    // The painter has no "move without painting": a new piece is a new painter stroke,
    // counted so that Undo() takes back the whole widget stroke.
    this->Painter->EndStroke();
    this->Painter->BeginStroke();
    ++this->StrokePieces;
  }
  // The first StrokeTo of a painter stroke places a dab at the point; the next ones dab
  // along the segment from the previous point.
  this->StrokeSamplesChanged += this->Painter->StrokeTo(target);
  this->PiecePainted = true;
  std::copy_n(target, 3, this->LastStrokePoint);
  this->HasLastPoint = true;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::EndWidgetInteraction(double vtkNotUsed(eventPos)[2])
{
  if (this->PenDown && this->Painter)
  {
    this->Painter->EndStroke();
    this->UndoPieces.push_back(this->StrokePieces);
    this->RedoPieces.clear();
  }
  this->PenDown = false;
  this->HasLastPoint = false;
  this->InteractionState = OUTSIDE;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::UpdateCursorColor()
{
  vtkOFBBrush* brush = this->GetBrush();
  const int target = brush ? brush->GetTarget() : vtkOFBBrush::TARGET_COLOR;
  const double* color = target == vtkOFBBrush::TARGET_NORMAL
    ? NormalCursorColor
    : (target == vtkOFBBrush::TARGET_SMEAR ? SmearCursorColor
                                           : (brush ? brush->GetColor() : nullptr));
  if (color)
  {
    this->CursorProperty->SetColor(color[0], color[1], color[2]);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::BuildRepresentation()
{
  vtkOFBBrush* brush = this->GetBrush();
  const bool visible = brush && this->InteractionState != OUTSIDE;
  this->CursorActor->SetVisibility(visible);
  if (!visible)
  {
    return;
  }
  this->BuildCursorGeometry(brush->GetRadius());
  this->UpdateCursorColor();
  this->BuildTime.Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::BuildCursorGeometry(double r)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkOFB* conform = this->ConformCursor ? this->GetOFB() : nullptr;
  const double lift = this->CursorLift * r + (conform ? 0.5 * conform->GetCellSize() : 0.0);
  vtkOFBAddBrushRing(conform,
    this->CursorPosition,
    this->CursorNormal,
    r,
    this->CursorResolution,
    lift,
    points,
    lines);
  // The reflections the painter paints too, each with its ring.
  if (vtkOFBPainter* painter = this->GetPainter())
  {
    double centres[21];
    int axes[7];
    const int count = painter->GetMirrorReflections(this->CursorPosition, centres, axes);
    for (int k = 0; k < count; ++k)
    {
      double n[3];
      for (int a = 0; a < 3; ++a)
      {
        n[a] = (axes[k] & (1 << a)) ? -this->CursorNormal[a] : this->CursorNormal[a];
      }
      vtkOFBAddBrushRing(
        conform, centres + 3 * k, n, r, this->CursorResolution, lift, points, lines);
    }
  }
  this->CursorPolyData->SetPoints(points);
  this->CursorPolyData->SetLines(lines);
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::PlaceWidget(double vtkNotUsed(bounds)[6])
{
  // The cursor follows the mouse; there is nothing to place.
  this->Placed = 1;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::GetActors(vtkPropCollection* pc)
{
  this->CursorActor->GetActors(pc);
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::ReleaseGraphicsResources(vtkWindow* w)
{
  this->CursorActor->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
int vtkOFBPainterRepresentation::RenderOpaqueGeometry(vtkViewport* viewport)
{
  return this->CursorActor->GetVisibility() ? this->CursorActor->RenderOpaqueGeometry(viewport) : 0;
}

//------------------------------------------------------------------------------
int vtkOFBPainterRepresentation::RenderTranslucentPolygonalGeometry(vtkViewport* viewport)
{
  return this->CursorActor->GetVisibility()
    ? this->CursorActor->RenderTranslucentPolygonalGeometry(viewport)
    : 0;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkOFBPainterRepresentation::HasTranslucentPolygonalGeometry()
{
  return this->CursorActor->GetVisibility() ? this->CursorActor->HasTranslucentPolygonalGeometry()
                                            : 0;
}

//------------------------------------------------------------------------------
double* vtkOFBPainterRepresentation::GetBounds()
{
  return this->CursorActor->GetVisibility() ? this->CursorActor->GetBounds() : nullptr;
}

//------------------------------------------------------------------------------
void vtkOFBPainterRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Painter: " << this->Painter << "\n";
  os << indent << "OFB: " << this->GetOFB() << "\n";
  os << indent << "PaintedProp: " << this->PaintedProp << "\n";
  os << indent << "PickTolerance: " << this->PickTolerance << "\n";
  os << indent << "MaximumJump: " << this->MaximumJump << "\n";
  os << indent << "StabilizerDistance: " << this->StabilizerDistance << "\n";
  os << indent << "CursorResolution: " << this->CursorResolution << "\n";
  os << indent << "CursorLift: " << this->CursorLift << "\n";
  os << indent << "ConformCursor: " << (this->ConformCursor ? "On" : "Off") << "\n";
  os << indent << "CursorProperty: " << this->CursorProperty << "\n";
  os << indent << "RadiusFactor: " << this->RadiusFactor << "\n";
  os << indent << "StrengthStep: " << this->StrengthStep << "\n";
  os << indent << "NumberOfPaletteColors: " << this->GetNumberOfPaletteColors() << "\n";
  for (int i = 0; i < this->GetNumberOfPaletteColors(); ++i)
  {
    const double* c = this->Palette.data() + 4 * i;
    os << indent.GetNextIndent() << "PaletteColor " << i << ": (" << c[0] << ", " << c[1] << ", "
       << c[2] << ", " << c[3] << ")\n";
  }
  os << indent << "PaletteIndex: " << this->PaletteIndex << "\n";
  os << indent << "CursorPosition: (" << this->CursorPosition[0] << ", " << this->CursorPosition[1]
     << ", " << this->CursorPosition[2] << ")\n";
  os << indent << "CursorNormal: (" << this->CursorNormal[0] << ", " << this->CursorNormal[1]
     << ", " << this->CursorNormal[2] << ")\n";
  os << indent << "StrokeSamplesChanged: " << this->StrokeSamplesChanged << "\n";
}
