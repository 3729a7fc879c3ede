#include "vtkOFBPainterWidget.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkOFBPainterRepresentation.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkWidgetCallbackMapper.h"
#include "vtkWidgetEvent.h"

#include <cctype>
#include <cstring>

vtkStandardNewMacro(vtkOFBPainterWidget);

//------------------------------------------------------------------------------
vtkOFBPainterWidget::vtkOFBPainterWidget()
  : WidgetState(Start)
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
  // Every character goes to KeyAction, which takes the painting keys and leaves the rest.
  this->CallbackMapper->SetCallbackMethod(
    vtkCommand::CharEvent, vtkWidgetEvent::ModifyEvent, this, vtkOFBPainterWidget::KeyAction);
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
  if (!rep || self->WidgetState == Painting)
  {
    return;
  }
  const int X = self->Interactor->GetEventPosition()[0];
  const int Y = self->Interactor->GetEventPosition()[1];
  if (rep->ComputeInteractionState(X, Y) != vtkOFBPainterRepresentation::OnSurface)
  {
    return; // off the surface: the interactor style has the event
  }
  if (!rep->CanPaint())
  {
    return;
  }
  self->WidgetState = Painting;
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
  if (self->WidgetState == Start)
  {
    // Hovering: move the cursor; the interactor style still gets the event (a drag that
    // started off the surface rotates the camera).
    const int before = rep->GetInteractionState();
    const int state = rep->ComputeInteractionState(X, Y);
    self->SetCursor(state);
    if (state == vtkOFBPainterRepresentation::OnSurface ||
      before == vtkOFBPainterRepresentation::OnSurface)
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
  if (!rep || self->WidgetState != Painting)
  {
    return;
  }
  double eventPos[2] = { static_cast<double>(self->Interactor->GetEventPosition()[0]),
    static_cast<double>(self->Interactor->GetEventPosition()[1]) };
  rep->EndWidgetInteraction(eventPos);
  self->WidgetState = Start;
  ++self->NumberOfStrokes;
  self->ReleaseFocus();
  self->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
  self->EventCallbackCommand->SetAbortFlag(1);
  // Show the cursor again where the mouse is.
  rep->ComputeInteractionState(static_cast<int>(eventPos[0]), static_cast<int>(eventPos[1]));
  self->Render();
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::KeyAction(vtkAbstractWidget* w)
{
  vtkOFBPainterWidget* self = static_cast<vtkOFBPainterWidget*>(w);
  auto* rep = vtkOFBPainterRepresentation::SafeDownCast(self->WidgetRep);
  if (!rep || !self->KeyboardShortcuts || !self->Interactor)
  {
    return;
  }
  if (self->HandleKey(rep))
  {
    self->EventCallbackCommand->SetAbortFlag(1);
    self->InvokeEvent(vtkCommand::WidgetModifiedEvent, nullptr);
    self->Render();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBPainterWidget::HandleKey(vtkOFBPainterRepresentation* rep)
{
  vtkRenderWindowInteractor* iren = this->Interactor;
  const char code = iren->GetKeyCode();
  const char* sym = iren->GetKeySym();
  const bool ctrl = iren->GetControlKey() != 0;
  const bool shift = iren->GetShiftKey() != 0;
  // With Control held, X11 gives the control character (Ctrl+Z is 26); the key symbol
  // still names the letter.
  char letter = code;
  if (ctrl && code >= 1 && code <= 26)
  {
    letter = static_cast<char>('a' + code - 1);
  }
  else if (ctrl && sym && std::strlen(sym) == 1)
  {
    letter = static_cast<char>(std::tolower(static_cast<unsigned char>(sym[0])));
  }
  if (ctrl)
  {
    if ((letter == 'z' || letter == 'Z') && !shift)
    {
      rep->Undo();
      return true;
    }
    if (letter == 'y' || letter == 'Y' || letter == 'z' || letter == 'Z')
    {
      rep->Redo();
      return true;
    }
    return false;
  }
  switch (code)
  {
    case '+':
    case '=':
      rep->ScaleRadius(1);
      return true;
    case '-':
    case '_':
      rep->ScaleRadius(-1);
      return true;
    case ']':
      rep->AddStrength(1);
      return true;
    case '[':
      rep->AddStrength(-1);
      return true;
    case 'f':
      rep->NextFalloff();
      return true;
    case 't':
      rep->NextTarget();
      return true;
    case 'b':
      rep->NextBlendMode();
      return true;
    case 'm':
      rep->NextMirror();
      return true;
    case 'c':
      rep->NextPaletteColor();
      return true;
    case 'u':
      rep->Undo();
      return true;
    case 'U':
      rep->Redo();
      return true;
    default:
      break;
  }
  if (code >= '1' && code <= '9')
  {
    return rep->SelectPaletteColor(code - '1');
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::SetCursor(int state)
{
  if (this->ManagesCursor)
  {
    this->RequestCursorShape(
      state == vtkOFBPainterRepresentation::OnSurface ? VTK_CURSOR_CROSSHAIR : VTK_CURSOR_DEFAULT);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainterWidget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KeyboardShortcuts: " << (this->KeyboardShortcuts ? "On" : "Off") << "\n";
  os << indent << "WidgetState: " << (this->WidgetState == Painting ? "Painting" : "Start") << "\n";
  os << indent << "NumberOfStrokes: " << this->NumberOfStrokes << "\n";
}
