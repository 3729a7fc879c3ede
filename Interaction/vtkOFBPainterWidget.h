/**
 * @class   vtkOFBPainterWidget
 * @brief   Paint a surface's OFB with the mouse: brush cursor, strokes, keys, undo
 *
 * vtkOFBPainterWidget paints into a vtkOFB with a vtkOFBPainter as a person paints in a
 * texture-paint program. Its representation (vtkOFBPainterRepresentation) shows the brush
 * as a ring on the surface under the mouse, aligned with the surface and of the brush's
 * radius. Render the surface with a vtkOFBPolyDataMapper on the same OFB: it uploads only
 * the samples each stroke changed.
 *
 * Mouse:
 * - Move: the cursor follows the surface (hidden off the surface).
 * - Left button down on the surface, drag, release: one stroke, dabs spaced along the
 *   path at the painter's Spacing (one undo step). Left button down off the surface is
 *   left to the interactor style (rotating the camera, say), as are the other buttons.
 *
 * Keys (with KeyboardShortcuts on, the default; these keys are taken from the interactor
 * style while the widget is enabled):
 * - `+` or `=`: brush radius times the representation's RadiusFactor (1.25);
 *   `-` or `_`: divided by it (between a quarter of a cell and the OFB's diagonal).
 * - `]`: strength up by the representation's StrengthStep (0.1); `[`: down.
 * - `f`: next falloff (constant, linear, smooth, sphere, root, sharp, Gaussian).
 * - `t`: next target (colour, normal, smear).
 * - `b`: next blend mode (mix, add, subtract, multiply, lighten, darken, erase, erase
 *   alpha).
 * - `m`: next mirror (none, x, y, z: the painter's MirrorX/Y/Z about its MirrorOrigin).
 * - `1` to `9`: palette colour 1 to 9; `c`: next palette colour.
 * - `u` or Ctrl+Z: undo the last stroke; `U` (Shift+U), Ctrl+Y or Ctrl+Shift+Z: redo.
 * Other keys go to the interactor style (`r` resets the camera, `q` quits, ...). The
 * widget is switched with On() and Off(): KeyPressActivation is off, so `i` is not taken.
 *
 * Each key is a translation in the widget's vtkWidgetEventTranslator from a CharEvent
 * (key code and modifiers) to one of this class's widget events (GROW_BRUSH, UNDO, ...),
 * which the vtkWidgetCallbackMapper maps to its action, as vtkSphereWidget2 maps its
 * events. An application rebinds or drops one key through GetEventTranslator():
 * @code
 * vtkWidgetEventTranslator* keys = widget->GetEventTranslator();
 * // Drop `u` (undo stays on Ctrl+Z); the key goes to the interactor style again.
 * keys->RemoveTranslation(vtkCommand::CharEvent, vtkEvent::AnyModifier, 'u', 0, nullptr);
 * // Undo on `z`.
 * keys->SetTranslation(vtkCommand::CharEvent, vtkEvent::AnyModifier, 'z', 0, nullptr,
 *   vtkOFBPainterWidget::UNDO);
 * @endcode
 * The plain keys are bound with vtkEvent::AnyModifier (a key typed with Shift matches);
 * Ctrl+Z is bound with vtkEvent::ControlModifier to the control character 26 (X11,
 * Windows) and to `z`/`Z` (other systems), Ctrl+Y likewise to 25 and `y`/`Y`.
 * RemoveTranslation with a key code removes only that key's bindings.
 *
 * Events: StartInteractionEvent when a stroke starts (before its first dab),
 * InteractionEvent after each move of a stroke, EndInteractionEvent when it ends: one
 * Start/End pair per stroke. A key that changes the brush or undoes/redoes a stroke
 * invokes WidgetModifiedEvent (an application updates its status text there).
 *
 * @sa vtkOFBPainterRepresentation vtkOFBPainter vtkOFBBrush vtkOFBPolyDataMapper
 */

#ifndef vtkOFBPainterWidget_h
#define vtkOFBPainterWidget_h

#include "vtkAbstractWidget.h"
#include "vtkOFBInteractionModule.h" // for export macro

class vtkOFBPainterRepresentation;

class VTKOFBINTERACTION_EXPORT vtkOFBPainterWidget : public vtkAbstractWidget
{
public:
  static vtkOFBPainterWidget* New();
  vtkTypeMacro(vtkOFBPainterWidget, vtkAbstractWidget);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The representation (created on demand by CreateDefaultRepresentation).
   */
  void SetRepresentation(vtkOFBPainterRepresentation* rep);
  vtkOFBPainterRepresentation* GetPainterRepresentation();
  void CreateDefaultRepresentation() override;
  ///@}

  ///@{
  /**
   * Whether the widget answers the keys listed in the class description (default on).
   */
  vtkSetMacro(KeyboardShortcuts, bool);
  vtkGetMacro(KeyboardShortcuts, bool);
  vtkBooleanMacro(KeyboardShortcuts, bool);
  ///@}

  /**
   * The widget events the keys translate to (see the class description), numbered
   * after vtkWidgetEvent's own.
   */
  enum KeyEvents
  {
    GROW_BRUSH = 1000,
    SHRINK_BRUSH,
    INCREASE_STRENGTH,
    DECREASE_STRENGTH,
    NEXT_FALLOFF,
    NEXT_TARGET,
    NEXT_BLEND_MODE,
    NEXT_MIRROR,
    NEXT_PALETTE_COLOR,
    SELECT_PALETTE_COLOR, ///< the palette colour of the digit typed (`1` the first)
    UNDO,
    REDO
  };

  /**
   * Whether a stroke is being painted.
   */
  bool IsPainting() const { return this->WidgetState == PAINTING; }

  /**
   * Number of strokes painted since the widget was created.
   */
  vtkGetMacro(NumberOfStrokes, int);

protected:
  vtkOFBPainterWidget();
  ~vtkOFBPainterWidget() override;

  enum WidgetStateType
  {
    START = 0,
    PAINTING
  };
  int WidgetState;
  bool KeyboardShortcuts;
  int NumberOfStrokes;

  // The actions the callback mapper calls.
  static void SelectAction(vtkAbstractWidget* w);
  static void MoveAction(vtkAbstractWidget* w);
  static void EndSelectAction(vtkAbstractWidget* w);
  static void GrowBrushAction(vtkAbstractWidget* w);
  static void ShrinkBrushAction(vtkAbstractWidget* w);
  static void IncreaseStrengthAction(vtkAbstractWidget* w);
  static void DecreaseStrengthAction(vtkAbstractWidget* w);
  static void NextFalloffAction(vtkAbstractWidget* w);
  static void NextTargetAction(vtkAbstractWidget* w);
  static void NextBlendModeAction(vtkAbstractWidget* w);
  static void NextMirrorAction(vtkAbstractWidget* w);
  static void NextPaletteColorAction(vtkAbstractWidget* w);
  static void SelectPaletteColorAction(vtkAbstractWidget* w);
  static void UndoAction(vtkAbstractWidget* w);
  static void RedoAction(vtkAbstractWidget* w);

  // A key's change of the representation, given the key code typed; false when the key
  // was not taken (it then goes to the interactor style).
  using KeyFunction = bool (*)(vtkOFBPainterRepresentation* rep, char key);

  // Apply a key's change when KeyboardShortcuts is on; a taken key is not passed on and
  // invokes WidgetModifiedEvent.
  static void ApplyKey(vtkAbstractWidget* w, KeyFunction apply);

  // Set up the key actions and the default keys (the class description lists them).
  void MapKeys();
  using KeyCallback = void (*)(vtkAbstractWidget*);
  void MapKey(char key, int modifier, unsigned long widgetEvent, KeyCallback action);

  // Crosshair over the surface, the default cursor elsewhere.
  void SetCursor(int state) override;

private:
  vtkOFBPainterWidget(const vtkOFBPainterWidget&) = delete;
  void operator=(const vtkOFBPainterWidget&) = delete;
};

#endif
