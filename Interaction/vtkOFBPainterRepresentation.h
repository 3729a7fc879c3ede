/**
 * @class   vtkOFBPainterRepresentation
 * @brief   The brush cursor and the painting state of vtkOFBPainterWidget
 *
 * vtkOFBPainterRepresentation is the vtkWidgetRepresentation of vtkOFBPainterWidget. It
 * picks the surface under the mouse with a vtkCellPicker (restricted to the painted prop
 * when one is given with SetPaintedProp), shows the brush there as a ring of the brush's
 * radius around the picked point, in the plane of the surface (aligned with the picked
 * normal) and drawn onto the surface through the OFB's samples (ConformCursor), lifted a
 * little along the normal so that the surface hides little of it, with a short tick along
 * the normal, and paints through a vtkOFBPainter: StartWidgetInteraction begins
 * a stroke, WidgetInteraction continues it to the surface point under the mouse (the
 * painter places dabs at its Spacing along the path), EndWidgetInteraction ends it (one
 * undo step per stroke).
 *
 * The representation paints into the OFB that the application holds (SetOFB, or the OFB
 * of the painter given with SetPainter), so that re-executing an upstream filter never
 * wipes the paint. A vtkOFBPolyDataMapper that renders that OFB uploads only the samples
 * the painter marked modified on the next Render().
 *
 * It creates a painter with a default brush (vtkOFBBrush's defaults, its colour the first
 * palette colour); SetPainter replaces it. Without a painter or without an OFB, painting
 * reports a clear error and changes nothing.
 *
 * The settings the widget's keys change are methods here, so that an application can bind
 * them to its own controls: ScaleRadius, AddStrength, NextFalloff, NextTarget,
 * NextBlendMode, NextMirror, SelectPaletteColor, NextPaletteColor, Undo and Redo.
 *
 * The stroke lifts the pen where the mouse leaves the surface, or where the picked point
 * jumps by more than MaximumJump brush radii between two events (from an ear onto the body
 * behind it, say): the stroke goes on from the next point without painting the gap.
 *
 * @sa vtkOFBPainterWidget vtkOFBPainter vtkOFBBrush vtkOFBSamplePicker
 */

#ifndef vtkOFBPainterRepresentation_h
#define vtkOFBPainterRepresentation_h

#include "vtkOFBInteractionModule.h" // for export macro
#include "vtkWidgetRepresentation.h"

#include <string> // for GetBrushDescription
#include <vector> // for Palette

class vtkActor;
class vtkCellPicker;
class vtkOFB;
class vtkOFBBrush;
class vtkOFBPainter;
class vtkPolyDataMapper;
class vtkPolyData;
class vtkProp;
class vtkProperty;
class vtkStaticCellLocator;

class VTKOFBINTERACTION_EXPORT vtkOFBPainterRepresentation : public vtkWidgetRepresentation
{
public:
  static vtkOFBPainterRepresentation* New();
  vtkTypeMacro(vtkOFBPainterRepresentation, vtkWidgetRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Interaction states: the mouse off the surface, on it, or painting a stroke.
  enum InteractionStateType
  {
    OUTSIDE = 0,
    ON_SURFACE,
    PAINTING
  };

  ///@{
  /**
   * The painter that paints the strokes, with its brush and OFB. The representation
   * creates one with a default brush and no OFB; null disables painting (with an error
   * when a stroke starts).
   */
  void SetPainter(vtkOFBPainter* painter);
  vtkGetObjectMacro(Painter, vtkOFBPainter);
  ///@}

  ///@{
  /**
   * The OFB painted into: forwarded to the painter (null without one).
   */
  void SetOFB(vtkOFB* ofb);
  vtkOFB* GetOFB();
  ///@}

  /**
   * The painter's brush (null without a painter).
   */
  vtkOFBBrush* GetBrush();

  ///@{
  /**
   * The prop whose surface is painted (default none: any pickable prop of the renderer).
   * Picking only this prop keeps other actors from catching the brush.
   */
  void SetPaintedProp(vtkProp* prop);
  vtkGetObjectMacro(PaintedProp, vtkProp);
  ///@}

  ///@{
  /**
   * Tolerance of the surface picker, as a fraction of the window diagonal (default 0.0005).
   */
  vtkSetClampMacro(PickTolerance, double, 0.0, 1.0);
  vtkGetMacro(PickTolerance, double);
  ///@}

  ///@{
  /**
   * Lift the pen where two consecutive surface points of a stroke are farther apart than
   * MaximumJump brush radii (default 4).
   */
  vtkSetClampMacro(MaximumJump, double, 0.5, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumJump, double);
  ///@}

  ///@{
  /**
   * Stroke stabilizer (a paint program's "lazy mouse"), in brush radii (0-100, default 0:
   * off). The brush trails the cursor on a string this long: a move that leaves the
   * cursor within that distance of the last painted point paints nothing, a longer one
   * paints up to the point that far short of the cursor, on the segment toward it. Small
   * jitters of the hand then leave no trace and the stroke runs smoother. MaximumJump
   * is measured between the cursor's surface points, not from the trailing brush.
   */
  vtkSetClampMacro(StabilizerDistance, double, 0.0, 100.0);
  vtkGetMacro(StabilizerDistance, double);
  ///@}

  ///@{
  /**
   * The cursor: the ring's number of points (default 64); its lift along the normal, as
   * a fraction of the brush radius (default 0.05; plus half a cell with ConformCursor);
   * ConformCursor (default on) moves each ring point to the nearest OFB sample, so that
   * the ring follows the surface where the brush's sphere cuts it, instead of lying flat
   * in the tangent plane.
   */
  vtkSetClampMacro(CursorResolution, int, 8, 1024);
  vtkGetMacro(CursorResolution, int);
  vtkSetClampMacro(CursorLift, double, 0.0, 1.0);
  vtkGetMacro(CursorLift, double);
  vtkSetMacro(ConformCursor, bool);
  vtkGetMacro(ConformCursor, bool);
  vtkBooleanMacro(ConformCursor, bool);
  ///@}

  /**
   * Property of the cursor (lines, width 2, unlit). Its colour follows the brush's colour
   * when the target is colour; it is light blue for normal painting and yellow for smear.
   */
  vtkGetObjectMacro(CursorProperty, vtkProperty);

  ///@{
  /**
   * Steps of the key actions: ScaleRadius(+1) multiplies the brush radius by
   * RadiusFactor (default 1.25), ScaleRadius(-1) divides by it, within a quarter of an
   * OFB cell and the OFB's diagonal; AddStrength(+1) adds StrengthStep (default 0.1) to
   * the strength, clamped to [0, 1].
   */
  vtkSetClampMacro(RadiusFactor, double, 1.001, 10.0);
  vtkGetMacro(RadiusFactor, double);
  vtkSetClampMacro(StrengthStep, double, 0.001, 1.0);
  vtkGetMacro(StrengthStep, double);
  ///@}

  ///@{
  /**
   * The palette of brush colours (RGBA in [0, 1]) chosen with SelectPaletteColor (number
   * keys 1-9) or NextPaletteColor ('c'). Default: red, orange, yellow, green, cyan, blue,
   * purple, white, black, all opaque.
   */
  void SetPaletteColor(int index, double r, double g, double b, double a = 1.0);
  int GetNumberOfPaletteColors() const { return static_cast<int>(this->Palette.size() / 4); }
  void SetNumberOfPaletteColors(int n);
  bool GetPaletteColor(int index, double rgba[4]) const;
  ///@}

  /**
   * The palette colour last selected (0 after construction).
   */
  vtkGetMacro(PaletteIndex, int);

  ///@{
  /**
   * Key actions: change the brush (no effect, with an error, without a painter or
   * brush). The Next* methods cycle: falloffs Constant to Gaussian (Custom is skipped: it
   * needs a curve), targets colour, normal, smear, blend modes Mix to EraseAlpha, the
   * painter's mirror none, x, y, z (vtkOFBPainter::MirrorX, one axis at a time; the
   * painter's MirrorOrigin is left as it is). SelectPaletteColor returns false for an
   * index outside the palette.
   */
  void ScaleRadius(int steps);
  void AddStrength(int steps);
  void NextFalloff();
  void NextTarget();
  void NextBlendMode();
  void NextMirror();
  bool SelectPaletteColor(int index);
  void NextPaletteColor();
  ///@}

  ///@{
  /**
   * Undo or redo the last stroke; the number of samples changed (0 when there is nothing
   * to undo or redo, or while a stroke is painted).
   */
  vtkIdType Undo();
  vtkIdType Redo();
  ///@}

  /**
   * A one-line description of the brush (radius, strength, colour, falloff, target, blend
   * mode) for an application's status text.
   */
  std::string GetBrushDescription();

  ///@{
  /**
   * The surface point and normal under the mouse at the last pick (valid when the
   * interaction state is OnSurface or Painting).
   */
  vtkGetVector3Macro(CursorPosition, double);
  vtkGetVector3Macro(CursorNormal, double);
  ///@}

  /**
   * The cursor's lines (read only): a ring on the surface where the brush's sphere cuts
   * it and a tick along the normal, and one more of each at every reflection the
   * painter paints too (vtkOFBPainter::MirrorX/Y/Z).
   */
  vtkPolyData* GetCursorPolyData() { return this->CursorPolyData; }

  /**
   * Samples changed by the current (or last) stroke so far.
   */
  vtkGetMacro(StrokeSamplesChanged, vtkIdType);

  /**
   * Whether a stroke can start: a painter with an OFB and a brush. Reports an error
   * saying what is missing when not.
   */
  bool CanPaint();

  ///@{
  /**
   * The vtkWidgetRepresentation interface. ComputeInteractionState picks the surface at
   * (X, Y) and moves the cursor there; StartWidgetInteraction begins a stroke at the
   * picked point, WidgetInteraction continues it, EndWidgetInteraction ends it.
   */
  int ComputeInteractionState(int X, int Y, int modify = 0) override;
  void StartWidgetInteraction(double eventPos[2]) override;
  void WidgetInteraction(double eventPos[2]) override;
  void EndWidgetInteraction(double eventPos[2]) override;
  void BuildRepresentation() override;
  void PlaceWidget(double bounds[6]) override;
  ///@}

  ///@{
  /**
   * Rendering of the cursor.
   */
  void GetActors(vtkPropCollection* pc) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;
  int RenderOpaqueGeometry(vtkViewport* viewport) override;
  int RenderTranslucentPolygonalGeometry(vtkViewport* viewport) override;
  vtkTypeBool HasTranslucentPolygonalGeometry() override;
  double* GetBounds() VTK_SIZEHINT(6) override;
  ///@}

protected:
  vtkOFBPainterRepresentation();
  ~vtkOFBPainterRepresentation() override;

  // Pick the surface at display (x, y): true with CursorPosition/CursorNormal set.
  bool PickSurface(double x, double y);
  // Continue the stroke to the last picked point, lifting the pen over a miss or a jump.
  void ContinueStroke(bool hit);
  // Keep the picker's cell locator on the painted actor's surface up to date.
  void UpdatePickLocator();
  // The cursor's ring and tick for brush radius r.
  void BuildCursorGeometry(double r);
  // The cursor colour for the brush's target.
  void UpdateCursorColor();
  // Undo (or redo) the painter steps of the last widget stroke.
  vtkIdType StepHistory(bool undo);

  vtkOFBPainter* Painter;
  vtkProp* PaintedProp;
  vtkCellPicker* Picker;
  double PickTolerance;
  double MaximumJump;
  double StabilizerDistance;
  int CursorResolution;
  double CursorLift;
  double RadiusFactor;
  double StrengthStep;
  std::vector<double> Palette; // RGBA quadruples
  int PaletteIndex;

  double CursorPosition[3];
  double CursorNormal[3];
  double LastStrokePoint[3];
  double LastPickedPoint[3];   // the cursor's last surface point in the stroke
  bool PenDown;                // a stroke is open
  bool HasLastPoint;           // LastStrokePoint is the stroke's last painted point
  bool PiecePainted;           // the current painter stroke has had a StrokeTo
  int StrokePieces;            // painter strokes of the current widget stroke
  std::vector<int> UndoPieces; // painter strokes of each widget stroke, oldest first
  std::vector<int> RedoPieces;
  vtkIdType StrokeSamplesChanged;

  // The cursor: a ring in the surface's plane and a tick along the normal.
  bool ConformCursor;
  vtkPolyData* CursorPolyData;
  vtkStaticCellLocator* PickLocator;
  bool PickLocatorInstalled;
  vtkPolyDataMapper* CursorMapper;
  vtkActor* CursorActor;
  vtkProperty* CursorProperty;

private:
  vtkOFBPainterRepresentation(const vtkOFBPainterRepresentation&) = delete;
  void operator=(const vtkOFBPainterRepresentation&) = delete;
};

#endif
