/**
 * @class   vtkOFBPainter
 * @brief   Paints dabs and strokes of a vtkOFBBrush in place into a vtkOFB
 *
 * vtkOFBPainter applies the volume brush of the paper "Sample-based Surface
 * Coloring" (section 5, Eq. 1-3; normal painting of section 9.2.1) to an OFB that
 * the application holds, in place: `Dab(center)` paints one dab, `Dabs(points)`
 * many at once, `Dabs(polydata)` many with per-dab parameters, and
 * `BeginStroke()` / `StrokeTo(p, pressure)` / `EndStroke()` places dabs along a
 * path every `Spacing * radius`. See vtkOFBBrush for the falloffs, blend modes
 * and targets.
 *
 * Every painting call returns the number of distinct samples whose value changed,
 * marks exactly those samples modified on the OFB (`vtkOFB::MarkSamplesModified`,
 * adjacent ids merged into ranges) so that vtkOFBPolyDataMapper uploads only
 * them, and calls the OFB's Modified() once (not once per dab). Candidates come
 * from the projections of each dab's bounding box on the three grids
 * (`vtkOFB::ForEachSampleInSphere`), never a scan of all samples.
 *
 * Many dabs are painted in parallel (vtkSMPTools) with the result of painting
 * them one after the other in their order: dabs are grouped into waves in which
 * no two dabs share a sample (nor a smear source), each dab in the wave after the
 * last earlier dab it overlaps, and waves run one after the other. The result is
 * therefore the same with any number of threads.
 *
 * Per-dab arrays of `Dabs(vtkPolyData*)` (point data, all optional; a dab without
 * one uses the brush's setting):
 *   "Radius"   1 component, world units
 *   "Color"    3 or 4 components, floating point in [0, 1] or unsigned char 0-255
 *   "Strength" 1 component in [0, 1]
 *   "Pressure" 1 component in [0, 1] (see vtkOFBBrush::PressureAffectsRadius)
 *   "PreviousPosition" 3 components: the smear source of the dab (Smear target);
 *              dabs without one carry no colour (as the first dab of a stroke)
 *   "Normal"   3 components: the normal at the dab centre for NormalAware brushes
 *
 * Colours: a sample's colour is the "Colors" sample array (RGBA unsigned char).
 * An OFB without one gets it on the first colour dab, filled with DefaultColor.
 * The Erase blend mode brings a sample back to its *initial* colour: the colour
 * it had when this painter first changed it (the painter keeps these values,
 * copied block by block as it first changes them; for a "Colors" array the
 * painter created, DefaultColor). The same holds for normals painted with the
 * Normal target. ResetInitialValues() takes the current values as the new
 * initial ones.
 *
 * Undo and redo: each call outside a stroke, and each stroke (BeginStroke to
 * EndStroke), is one step. A step keeps only the previous values of the samples
 * it changed (sample id and value), so its memory is proportional to the number
 * of changed samples. The oldest steps are dropped when the history exceeds
 * UndoLimit bytes; with an UndoLimit of 0 no previous value is kept at all (the
 * particle advector paints so). If the OFB was changed by something else since this painter's
 * last change (its modification time moved on, or its samples were rebuilt), the
 * history no longer describes it: the painter drops it, with a warning.
 *
 * Progress: a call whose dabs cover many samples, or that paints many dabs, invokes
 * vtkCommand::ProgressEvent (call data: a double in [0, 1]) as it goes. An observer
 * may call AbortPaintOn() to stop the call at the next dab (see AbortPaint).
 *
 * Calls during a call: while a painting call runs (its progress observers run inside
 * it), the painter holds references to the OFB, the brush and the arrays it paints,
 * and takes the OFB with vtkOFB::BeginExclusiveWrite, so that nothing it reads is
 * freed under it: the OFB then refuses Initialize(), ShallowCopy(), DeepCopy() and
 * rebuilds with an error, and this painter refuses SetOFB and its other painting,
 * stroke and history calls with an error. An array removed from the OFB meanwhile
 * ("Colors", "Normals") receives the rest of the call; the next call finds the OFB
 * changed and drops the history (see above). A second painter (or a second thread
 * using this painter) that starts a call on an OFB being painted gets an error and
 * paints nothing: paint one OFB from one painter at a time.
 *
 * Bad input gives an error and changes nothing (returns 0): no OFB, no brush, an empty
 * OFB, a NaN or infinite centre, a radius that is not positive and finite, more dabs
 * than MaximumDabsPerCall.
 *
 * @sa vtkOFBBrush vtkOFBPaintFilter vtkOFBPolyDataMapper
 */

#ifndef vtkOFBPainter_h
#define vtkOFBPainter_h

#include "vtkOFBPaintModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <memory> // for std::unique_ptr
#include <vector> // for the dab lists

class vtkOFB;
class vtkOFBBrush;
class vtkIdTypeArray;
class vtkPoints;
class vtkPolyData;
class vtkUnsignedCharArray;
struct vtkOFBDab;

class VTKOFBPAINT_EXPORT vtkOFBPainter : public vtkObject
{
public:
  static vtkOFBPainter* New();
  vtkTypeMacro(vtkOFBPainter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OFB painted in place (default none). Setting another OFB ends the stroke
   * and drops the undo history and the initial values.
   */
  void SetOFB(vtkOFB* ofb);
  vtkOFB* GetOFB() const;
  ///@}

  ///@{
  /**
   * The brush (a default vtkOFBBrush unless set). Changing the brush during a
   * stroke applies to the dabs placed after the change.
   */
  void SetBrush(vtkOFBBrush* brush);
  vtkOFBBrush* GetBrush() const;
  ///@}

  ///@{
  /**
   * Paint one dab at `center` (world coordinates) with the brush's settings.
   * Returns the number of samples changed.
   */
  vtkIdType Dab(const double center[3]);
  vtkIdType Dab(double x, double y, double z);
  ///@}

  /**
   * Paint one dab at every point of `centers`, in order (see the class
   * description for the parallel painting). Returns the number of samples changed.
   */
  vtkIdType Dabs(vtkPoints* centers);

  /**
   * Paint one dab at every point of `dabs`, with the per-dab point arrays listed in
   * the class description. Returns the number of samples changed.
   */
  vtkIdType Dabs(vtkPolyData* dabs);

  /**
   * Write colours computed elsewhere into the samples `ids` (RGBA bytes `colors`, one
   * tuple per id: a decal stamped with vtkOFBTextureProjector, a script's own paint) as
   * paint of this painter: one undo step (part of the stroke when one is open), only
   * the samples that change recorded and marked modified. Returns the number of samples
   * changed; an id outside the OFB or a tuple count unlike the ids' is an error (nothing
   * written).
   */
  vtkIdType SetSampleColors(vtkIdTypeArray* ids, vtkUnsignedCharArray* colors);

  ///@{
  /**
   * Strokes. BeginStroke() starts an undo step; StrokeTo(p, pressure) moves the
   * brush to `p` with `pressure` in [0, 1] (clamped), placing the first dab at the
   * first point and then dabs every Spacing * radius along the path (the radius at
   * each dab, scaled by the pressure interpolated along the segment when the brush
   * has PressureAffectsRadius); EndStroke() closes the step. With FollowSurface (the
   * default) each point is first moved onto the surface (to the closest sample) and the
   * path between two points follows the surface (see SetFollowSurface). StrokeTo outside a
   * stroke begins one. Each StrokeTo returns the number of samples it changed.
   * With the Smear target each dab carries the colour found at the previous dab.
   */
  void BeginStroke();
  vtkIdType StrokeTo(const double p[3], double pressure = 1.0);
  vtkIdType StrokeTo(double x, double y, double z, double pressure = 1.0);
  void EndStroke();
  bool IsInStroke() const { return this->InStroke; }
  ///@}

  /**
   * The centres of the dabs placed by the current stroke, or the last one when no
   * stroke is open (the stroke's spacing made visible; read only).
   */
  vtkPoints* GetStrokeDabs() const;

  ///@{
  /**
   * Distance between consecutive dabs of a stroke as a fraction of the radius
   * (0.01-10; default 0.25).
   * Dabs are at least an eighth of an OFB cell apart (a radius of 0, from a pressure
   * of 0, would place them without end), and a call that would place more than 2^24
   * dabs along its strokes is an error that paints nothing.
   */
  vtkSetClampMacro(Spacing, double, 0.01, 10.0);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * Strokes that follow the surface (default on). StrokeTo moves each point to the
   * closest sample of the OFB, however far from the surface it is given, and joins two
   * points by a path over the surface: a walk from sample to sample, two cells a step,
   * each step to the nearby sample closest to the next point whose normal is not turned
   * more than 120 degrees from the last (so a stroke on a pipe goes around the wall and
   * never through the inside, and never steps onto the opposite wall of a thin pipe or
   * the back of a thin plate). Off: the dabs are placed at the points given and along the
   * straight chords between them (a volume brush moved through space).
   * vtkOFBPaintFilter's strokes follow the same setting of its painter.
   */
  vtkSetMacro(FollowSurface, bool);
  vtkGetMacro(FollowSurface, bool);
  vtkBooleanMacro(FollowSurface, bool);
  ///@}

  ///@{
  /**
   * Symmetric painting (a paint program's mirror options): with MirrorX every dab is
   * also painted at its reflection in the plane x = MirrorOrigin[0], likewise MirrorY
   * and MirrorZ, and with two or three of them at the reflections in their
   * combinations (up to 8 dabs for one). The reflections are painted in the same call
   * and undo step, right after their dab, with its radius, colour and strength, their
   * smear source and centre normal reflected too; a reflection whose centre equals
   * one already painted for that dab (a centre on a mirror plane) is not painted again.
   * GetStrokeDabs() lists the dabs placed, not their reflections. Default off, origin
   * (0, 0, 0) in world coordinates (OFBPaint puts it at the centre of the mesh's box).
   */
  vtkSetMacro(MirrorX, bool);
  vtkGetMacro(MirrorX, bool);
  vtkBooleanMacro(MirrorX, bool);
  vtkSetMacro(MirrorY, bool);
  vtkGetMacro(MirrorY, bool);
  vtkBooleanMacro(MirrorY, bool);
  vtkSetMacro(MirrorZ, bool);
  vtkGetMacro(MirrorZ, bool);
  vtkBooleanMacro(MirrorZ, bool);
  vtkSetVector3Macro(MirrorOrigin, double);
  vtkGetVector3Macro(MirrorOrigin, double);
  ///@}

  ///@{
  /**
   * Most dabs one call paints, counted after mirror reflection (default 2^22 =
   * 4,194,304; at least 1). A Dab, Dabs or StrokeTo call that would paint more is an
   * error naming the limit that paints nothing, refused before the dabs are stored.
   * Dabs cost about 50 bytes each besides the time they take to paint.
   */
  vtkSetClampMacro(MaximumDabsPerCall, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumDabsPerCall, vtkIdType);
  ///@}

  ///@{
  /**
   * Stop the painting call in progress: set it from a ProgressEvent observer and the
   * call stops before its next dab (a dab already begun is finished). What was painted
   * stays painted, is marked modified and makes the undo step as usual. Every painting
   * call clears it when it starts.
   */
  vtkSetMacro(AbortPaint, bool);
  vtkGetMacro(AbortPaint, bool);
  vtkBooleanMacro(AbortPaint, bool);
  ///@}

  /**
   * True while a painting call runs (in its progress observers).
   */
  bool IsPainting() const;

  /**
   * Take the settings of `source`: Spacing, the mirror settings, DefaultColor,
   * MaximumDabsPerCall, UndoLimit and FollowSurface (not its OFB, brush, history or stroke).
   * vtkOFBPaintFilter paints with the settings of the painter it holds so.
   */
  void CopySettings(vtkOFBPainter* source);

  /**
   * The reflections of `point` that mirror painting paints besides it, in the order
   * painted: up to 7 points (3 doubles each) in `reflections`, and for each in `axes` the
   * axes it flips (bit 0 x, 1 y, 2 z: a vector at the point, a normal say, reflects by
   * negating those components). A reflection equal to the point or to an earlier one is
   * left out. Returns how many; 0 without a mirror.
   */
  int GetMirrorReflections(const double point[3], double reflections[21], int axes[7]) const;

  ///@{
  /**
   * The colour of a "Colors" array the painter creates on an OFB that has none,
   * RGBA in [0, 1] (default opaque white, the sampler's default).
   */
  vtkSetVector4Macro(DefaultColor, double);
  vtkGetVector4Macro(DefaultColor, double);
  ///@}

  ///@{
  /**
   * Undo and redo one step (see the class description). Undo() and Redo() return
   * the number of samples restored (0 when there is nothing to undo or redo). An
   * open stroke is ended first.
   */
  vtkIdType Undo();
  vtkIdType Redo();
  bool CanUndo() const;
  bool CanRedo() const;
  void ClearHistory();
  int GetNumberOfUndoSteps() const;
  int GetNumberOfRedoSteps() const;
  ///@}

  ///@{
  /**
   * Most memory the undo and redo history may take, in bytes (default 256 MiB);
   * 0 keeps no history. The step being painted is always kept whole.
   */
  vtkSetClampMacro(UndoLimit, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(UndoLimit, vtkIdType);
  ///@}

  /**
   * Memory of the undo and redo history, in bytes.
   */
  vtkIdType GetUndoMemory() const;

  /**
   * Take the current colours and normals as the initial values the Erase blend
   * mode restores.
   */
  void ResetInitialValues();

  /**
   * Memory of the painter's working data (initial values, per-sample flags), in bytes.
   */
  vtkIdType GetScratchMemory() const;

protected:
  vtkOFBPainter();
  ~vtkOFBPainter() override;

  /// Check the OFB and its arrays (creating "Colors" when needed); drop the
  /// history if something else changed the OFB. False (with an error) if unusable.
  bool Prepare(bool needColors, bool needNormals);
  /// Mark the samples changed since the last call modified on the OFB.
  vtkIdType Finish();
  /// Close the open undo step (sorted by sample id), dropping the redo steps.
  void CloseStep();
  void EnforceUndoLimit();
  /// Undo (true) or redo (false) one step.
  vtkIdType Restore(bool undo);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  double Spacing;
  double DefaultColor[4];
  vtkIdType UndoLimit;
  bool MirrorX;
  bool MirrorY;
  bool MirrorZ;
  double MirrorOrigin[3];
  bool InStroke;
  vtkIdType MaximumDabsPerCall;
  bool AbortPaint;
  bool FollowSurface;

private:
  /// Marks the painter busy and holds the OFB and brush for one public call.
  class CallScope;
  friend class CallScope;
  /// False, with an error, without a brush.
  bool CheckBrush(const char* what);
  /// False, with an error naming the limit, when `count` dabs are too many.
  bool CheckDabCount(vtkIdType count, const char* what);
  /// The stroke steps without the checks of the public calls.
  void StartStroke();
  void FinishStroke();
  void DropHistory();

  // The dab steps name vtkOFBDab, a type of the implementation: private, so that a
  // subclass needs only the installed headers.
  /// A dab at `center` with the brush's settings and `pressure`; false if not finite.
  bool MakeDab(const double center[3], double pressure, vtkOFBDab& dab);
  /// Paint dabs, mark the changed ranges, call Modified(); the changed count.
  vtkIdType Paint(std::vector<vtkOFBDab>& dabs);
  /// Each dab followed by its reflections (MirrorX, MirrorY, MirrorZ).
  void AddMirrorImages(std::vector<vtkOFBDab>& dabs) const;

  vtkOFBPainter(const vtkOFBPainter&) = delete;
  void operator=(const vtkOFBPainter&) = delete;
};

#endif
