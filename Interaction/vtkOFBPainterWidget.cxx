#include "vtkOFBPainterWidget.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkEvent.h"
#include "vtkOFBPainterRepresentation.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkWidgetCallbackMapper.h"
#include "vtkWidgetEvent.h"

vtkStandardNewMacro(vtkOFBPainterWidget);

//------------------------------------------------------------------------------
vtkOFBPainterWidget::vtkOFBPainterWidget()
  : WidgetState(START)
  , KeyboardShortcuts(true)
  , NumberOfStrokes(0)
{
  // 'i' would toggle the widget and is not among the painting keys.
  this->KeyPressActivationOff();
  this->ManagesCursor = 1;
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonPressEvent,
    vtkWidgetEvent::Select,
    this,
    vtkOFBPainterWidget::SelectAction);
  this->CallbackMapper->SetCallbackMethod(
    vtkCommand::MouseMoveEvent, vtkWidgetEvent::Move, this, vtkOFBPainterWidget::MoveAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonReleaseEvent,
    vtkWidgetEvent::EndSelect,
    this,
    vtkOFBPainterWidget::EndSelectAction);
  this->MapKeys();
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::MapKey(char key,
  int modifier,
  unsigned long widgetEvent,
  KeyCallback action)
{
  this->CallbackMapper->SetCallbackMethod(
    vtkCommand::CharEvent, modifier, key, 0, nullptr, widgetEvent, this, action);
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::MapKeys()
{
  // The plain keys match with any modifier: `+`, `_` and `U` are typed with Shift on
  // many layouts.
  const int any = vtkEvent::AnyModifier;
  this->MapKey('+', any, GROW_BRUSH, vtkOFBPainterWidget::GrowBrushAction);
  this->MapKey('=', any, GROW_BRUSH, vtkOFBPainterWidget::GrowBrushAction);
  this->MapKey('-', any, SHRINK_BRUSH, vtkOFBPainterWidget::ShrinkBrushAction);
  this->MapKey('_', any, SHRINK_BRUSH, vtkOFBPainterWidget::ShrinkBrushAction);
  this->MapKey(']', any, INCREASE_STRENGTH, vtkOFBPainterWidget::IncreaseStrengthAction);
  this->MapKey('[', any, DECREASE_STRENGTH, vtkOFBPainterWidget::DecreaseStrengthAction);
  this->MapKey('f', any, NEXT_FALLOFF, vtkOFBPainterWidget::NextFalloffAction);
  this->MapKey('t', any, NEXT_TARGET, vtkOFBPainterWidget::NextTargetAction);
  this->MapKey('b', any, NEXT_BLEND_MODE, vtkOFBPainterWidget::NextBlendModeAction);
  this->MapKey('m', any, NEXT_MIRROR, vtkOFBPainterWidget::NextMirrorAction);
  this->MapKey('c', any, NEXT_PALETTE_COLOR, vtkOFBPainterWidget::NextPaletteColorAction);
  for (char key = '1'; key <= '9'; ++key)
  {
    this->MapKey(key, any, SELECT_PALETTE_COLOR, vtkOFBPainterWidget::SelectPaletteColorAction);
  }
  this->MapKey('u', any, UNDO, vtkOFBPainterWidget::UndoAction);
  this->MapKey('U', any, REDO, vtkOFBPainterWidget::RedoAction);
  // Control keys: X11 and Windows give the control character (Ctrl+Z is 26, Ctrl+Y 25),
  // other systems the letter.
  const int ctrl = vtkEvent::ControlModifier;
  const int ctrlShift = vtkEvent::ControlModifier | vtkEvent::ShiftModifier;
  for (char z : { '\x1a', 'z', 'Z' })
  {
    this->MapKey(z, ctrl, UNDO, vtkOFBPainterWidget::UndoAction);
    this->MapKey(z, ctrlShift, REDO, vtkOFBPainterWidget::RedoAction);
  }
  for (char y : { '\x19', 'y', 'Y' })
  {
    this->MapKey(y, ctrl, REDO, vtkOFBPainterWidget::RedoAction);
    this->MapKey(y, ctrlShift, REDO, vtkOFBPainterWidget::RedoAction);
  }
}

//------------------------------------------------------------------------------
vtkOFBPainterWidget::~vtkOFBPainterWidget() = default;

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::SetRepresentation(vtkOFBPainterRepresentation* rep)
{
  this->SetWidgetRepresentation(rep);
}

//------------------------------------------------------------------------------
vtkOFBPainterRepresentation* vtkOFBPainterWidget::GetPainterRepresentation()
{
  return vtkOFBPainterRepresentation::SafeDownCast(this->GetRepresentation());
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::CreateDefaultRepresentation()
{
  if (!this->WidgetRep)
  {
    this->WidgetRep = vtkOFBPainterRepresentation::New();
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::SelectAction(vtkAbstractWidget* w)
{
  vtkOFBPainterWidget* self = static_cast<vtkOFBPainterWidget*>(w);
  auto* rep = vtkOFBPainterRepresentation::SafeDownCast(self->WidgetRep);
  if (!rep || self->WidgetState == PAINTING)
  {
    return;
  }
  const int X = self->Interactor->GetEventPosition()[0];
  const int Y = self->Interactor->GetEventPosition()[1];
  if (rep->ComputeInteractionState(X, Y) != vtkOFBPainterRepresentation::ON_SURFACE)
  {
    return; // off the surface: the interactor style has the event
  }
  if (!rep->CanPaint())
  {
    return;
  }
  self->WidgetState = PAINTING;
  self->GrabFocus(self->EventCallbackCommand);
  self->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
  double eventPos[2] = { static_cast<double>(X), static_cast<double>(Y) };
  rep->StartWidgetInteraction(eventPos);
  self->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
  self->EventCallbackCommand->SetAbortFlag(1);
  self->Render();
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::MoveAction(vtkAbstractWidget* w)
{
  vtkOFBPainterWidget* self = static_cast<vtkOFBPainterWidget*>(w);
  auto* rep = vtkOFBPainterRepresentation::SafeDownCast(self->WidgetRep);
  if (!rep)
  {
    return;
  }
  const int X = self->Interactor->GetEventPosition()[0];
  const int Y = self->Interactor->GetEventPosition()[1];
  if (self->WidgetState == START)
  {
    // Hovering: move the cursor; the interactor style still gets the event (a drag that
    // started off the surface rotates the camera).
    const int before = rep->GetInteractionState();
    const int state = rep->ComputeInteractionState(X, Y);
    self->SetCursor(state);
    if (state == vtkOFBPainterRepresentation::ON_SURFACE ||
      before == vtkOFBPainterRepresentation::ON_SURFACE)
    {
      self->Render();
    }
    return;
  }
  double eventPos[2] = { static_cast<double>(X), static_cast<double>(Y) };
  rep->WidgetInteraction(eventPos);
  self->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
  self->EventCallbackCommand->SetAbortFlag(1);
  self->Render();
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::EndSelectAction(vtkAbstractWidget* w)
{
  vtkOFBPainterWidget* self = static_cast<vtkOFBPainterWidget*>(w);
  auto* rep = vtkOFBPainterRepresentation::SafeDownCast(self->WidgetRep);
  if (!rep || self->WidgetState != PAINTING)
  {
    return;
  }
  double eventPos[2] = { static_cast<double>(self->Interactor->GetEventPosition()[0]),
    static_cast<double>(self->Interactor->GetEventPosition()[1]) };
  rep->EndWidgetInteraction(eventPos);
  self->WidgetState = START;
  ++self->NumberOfStrokes;
  self->ReleaseFocus();
  self->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
  self->EventCallbackCommand->SetAbortFlag(1);
  // Show the cursor again where the mouse is.
  rep->ComputeInteractionState(static_cast<int>(eventPos[0]), static_cast<int>(eventPos[1]));
  self->Render();
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::ApplyKey(vtkAbstractWidget* w, KeyFunction apply)
{
  vtkOFBPainterWidget* self = static_cast<vtkOFBPainterWidget*>(w);
  auto* rep = vtkOFBPainterRepresentation::SafeDownCast(self->WidgetRep);
  if (!rep || !self->KeyboardShortcuts || !self->Interactor)
  {
    return;
  }
  if (apply(rep, self->Interactor->GetKeyCode()))
  {
    self->EventCallbackCommand->SetAbortFlag(1);
    self->InvokeEvent(vtkCommand::WidgetModifiedEvent, nullptr);
    self->Render();
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::GrowBrushAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->ScaleRadius(1);
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::ShrinkBrushAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->ScaleRadius(-1);
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::IncreaseStrengthAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->AddStrength(1);
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::DecreaseStrengthAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->AddStrength(-1);
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::NextFalloffAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->NextFalloff();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::NextTargetAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->NextTarget();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::NextBlendModeAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->NextBlendMode();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::NextMirrorAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->NextMirror();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::NextPaletteColorAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->NextPaletteColor();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::SelectPaletteColorAction(vtkAbstractWidget* w)
{
  // The digit typed picks the colour: '1' the first.
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char key)
    { return key >= '1' && key <= '9' && rep->SelectPaletteColor(key - '1'); });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::UndoAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->Undo();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::RedoAction(vtkAbstractWidget* w)
{
  ApplyKey(w,
    [](vtkOFBPainterRepresentation* rep, char)
    {
      rep->Redo();
      return true;
    });
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::SetCursor(int state)
{
  if (this->ManagesCursor)
  {
    this->RequestCursorShape(
      state == vtkOFBPainterRepresentation::ON_SURFACE ? VTK_CURSOR_CROSSHAIR : VTK_CURSOR_DEFAULT);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KeyboardShortcuts: " << (this->KeyboardShortcuts ? "On" : "Off") << "\n";
  os << indent << "WidgetState: " << (this->WidgetState == PAINTING ? "Painting" : "Start") << "\n";
  os << indent << "NumberOfStrokes: " << this->NumberOfStrokes << "\n";
}
