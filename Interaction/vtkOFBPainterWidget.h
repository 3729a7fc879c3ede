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
   * Whether a stroke is being painted.
   */
  bool IsPainting() const { return this->WidgetState == Painting; }

  /**
   * Number of strokes painted since the widget was created.
   */
  vtkGetMacro(NumberOfStrokes, int);

protected:
  vtkOFBPainterWidget();
  ~vtkOFBPainterWidget() override;

  enum WidgetStateType
  {
    Start = 0,
    Painting
  };
  int WidgetState;
  bool KeyboardShortcuts;
  int NumberOfStrokes;

  // The actions the callback mapper calls.
  static void SelectAction(vtkAbstractWidget* w);
  static void MoveAction(vtkAbstractWidget* w);
  static void EndSelectAction(vtkAbstractWidget* w);
  static void KeyAction(vtkAbstractWidget* w);

  // Crosshair over the surface, the default cursor elsewhere.
  void SetCursor(int state) override;

  // Apply the key of the current CharEvent; false when the key is not the widget's.
  bool HandleKey(vtkOFBPainterRepresentation* rep);

private:
  vtkOFBPainterWidget(const vtkOFBPainterWidget&) = delete;
  void operator=(const vtkOFBPainterWidget&) = delete;
};

#endif
