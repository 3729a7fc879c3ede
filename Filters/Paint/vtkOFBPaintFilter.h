/**
 * @class   vtkOFBPaintFilter
 * @brief   Paints strokes into a copy of a vtkOFB, as a pipeline algorithm
 *
 * vtkOFBPaintFilter is vtkOFBPainter for pipelines and ParaView-style scripts.
 * Port 0 takes the OFB, port 1 (optional) the strokes as a vtkPolyData: each
 * polyline (or line) is a stroke whose dabs are placed every `Spacing` times the
 * radius along it, and each vertex cell is a single dab. Optional point arrays
 * give per-point values, interpolated along the strokes (see vtkOFBPainter's
 * per-dab arrays): "Radius" (world units), "Color" (3 or 4 components, floating
 * point in [0, 1] or unsigned char), "Strength" and "Pressure" (in [0, 1]);
 * points without them use the brush's settings. With the Smear target each dab
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
#include "vtkSmartPointer.h"     // for member

class vtkOFBBrush;
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
   * Distance between the dabs of a stroke as a fraction of the radius
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
   * Colour of the "Colors" array created for an OFB that has none, RGBA in
   * [0, 1] (default opaque white).
   */
  vtkSetVector4Macro(DefaultColor, double);
  vtkGetVector4Macro(DefaultColor, double);
  ///@}

  ///@{
  /**
   * Symmetric painting: every dab also at its reflections in the planes through
   * MirrorOrigin across the axes set (see vtkOFBPainter::SetMirrorX). Default off,
   * origin (0, 0, 0).
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

  /**
   * The number of samples the last execution changed.
   */
  vtkGetMacro(NumberOfChangedSamples, vtkIdType);

  /**
   * Modification time including the brush's.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkOFBPaintFilter();
  ~vtkOFBPaintFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The dabs of `strokes` (per-dab point arrays) on an OFB of cells `cellSize` wide, or
  /// null with an error.
  vtkSmartPointer<vtkPolyData> MakeDabs(vtkPolyData* strokes, double cellSize);

  vtkSmartPointer<vtkOFBBrush> Brush;
  double Spacing;
  double DefaultColor[4];
  bool MirrorX;
  bool MirrorY;
  bool MirrorZ;
  double MirrorOrigin[3];
  vtkIdType NumberOfChangedSamples;

private:
  vtkOFBPaintFilter(const vtkOFBPaintFilter&) = delete;
  void operator=(const vtkOFBPaintFilter&) = delete;
};

#endif
