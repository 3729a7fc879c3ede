/**
 * @class   vtkOFBPaintFilter
 * @brief   Paints strokes into a copy of a vtkOFB, as a pipeline algorithm
 *
 * vtkOFBPaintFilter is vtkOFBPainter for pipelines and ParaView-style scripts.
 * Port 0 takes the OFB, port 1 (optional) the strokes as a vtkPolyData: each
 * polyline (or line) is a stroke whose dabs are placed every `Spacing` times the
 * radius along it (the Spacing of GetPainter(), by the walk of vtkOFBPainter::StrokeTo),
 * and each vertex cell is a single dab. With the painter's FollowSurface (the default)
 * every point is first moved onto the surface (the closest sample) and the dabs between
 * two points follow a path over the surface, as vtkOFBPainter::StrokeTo places them
 * (see vtkOFBPainter::SetFollowSurface). Optional point arrays
 * give per-point values, interpolated along the strokes (see vtkOFBPainter's
 * per-dab arrays) by the length walked along each path: "Radius" (world units),
 * "Color" (3 or 4 components, floating point in [0, 1] or unsigned char), "Strength"
 * and "Pressure" (in [0, 1]);
 * points without them use the settings of the brush (GetBrush()). With the Smear target each dab
 * carries the colour from the previous dab of its stroke.
 *
 * The output is a painted copy: the arrays the brush changes ("Colors", or
 * "Normals" for the Normal target) are deep copies, everything else is shared
 * with the input, which stays untouched. All strokes are painted in one call of
 * vtkOFBPainter::Dabs (in parallel, with the result of painting them in order).
 *
 * Bad input (no OFB, an empty OFB, non-finite stroke points, radii that are not
 * positive and finite) gives an error and an empty output. Without strokes the
 * output is the input's copy, unpainted. The filter reports progress.
 *
 * @sa vtkOFBPainter vtkOFBBrush
 */

#ifndef vtkOFBPaintFilter_h
#define vtkOFBPaintFilter_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBPaintModule.h" // for export macro
#include "vtkSmartPointer.h"   // for member

class vtkOFB;
class vtkOFBBrush;
class vtkOFBStrokeExchange;
class vtkOFBPainter;
class vtkPolyData;

class VTKOFBPAINT_EXPORT vtkOFBPaintFilter : public vtkOFBAlgorithm
{
public:
  static vtkOFBPaintFilter* New();
  vtkTypeMacro(vtkOFBPaintFilter, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The strokes (port 1): a connection or a data object.
   */
  void SetStrokesConnection(vtkAlgorithmOutput* output);
  void SetStrokesData(vtkPolyData* strokes);
  ///@}

  ///@{
  /**
   * The brush (a default vtkOFBBrush unless set).
   */
  void SetBrush(vtkOFBBrush* brush);
  vtkOFBBrush* GetBrush() const;
  ///@}

  ///@{
  /**
   * The painter whose settings the filter paints with (a default vtkOFBPainter unless
   * set): Spacing (the distance between the dabs of a stroke), DefaultColor (of a
   * "Colors" array created for an OFB that has none) and the mirror settings (MirrorX,
   * MirrorY, MirrorZ, MirrorOrigin). The filter paints its output with a painter of its
   * own that takes these settings (vtkOFBPainter::CopySettings) and the filter's brush:
   * this painter's OFB, brush, undo history and UndoLimit are not used or changed.
   */
  void SetPainter(vtkOFBPainter* painter);
  vtkOFBPainter* GetPainter() const;
  ///@}

  /**
   * The number of samples the last execution changed.
   */
  vtkGetMacro(NumberOfChangedSamples, vtkIdType);

  /**
   * Modification time including the brush's and the painter's.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkOFBPaintFilter();
  ~vtkOFBPaintFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The strokes to paint, given those of input port 1 (null when it has none): the
   * same here; a distributed subclass (vtkOFBPPaintFilter) returns every process's.
   * Called once per execution, before the input is checked.
   */
  virtual vtkSmartPointer<vtkPolyData> GetStrokes(vtkPolyData* strokes);

  /// The dabs of `strokes` (per-dab point arrays) on `ofb`, or null with an error.
  vtkSmartPointer<vtkPolyData> MakeDabs(vtkPolyData* strokes, vtkOFB* ofb);

  vtkSmartPointer<vtkOFBBrush> Brush;
  vtkSmartPointer<vtkOFBPainter> Painter;
  vtkIdType NumberOfChangedSamples;

  /**
   * The collective calls of a distributed run (see vtkOFBStrokeExchange), set by a
   * distributed subclass for the time of its RequestData; null (the default): one
   * process. With it, the input may have no samples (an empty piece): its output is the
   * input, and it still takes part in placing the strokes on the surface.
   */
  vtkOFBStrokeExchange* Exchange = nullptr;

private:
  vtkOFBPaintFilter(const vtkOFBPaintFilter&) = delete;
  void operator=(const vtkOFBPaintFilter&) = delete;
};

#endif
