// Private header of vtkOFBPainter: what a painter holds (the OFB, the brush, the paint
// kernel, the undo history and the stroke state), shared by its source files.
#ifndef vtkOFBPainterInternals_h
#define vtkOFBPainterInternals_h

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPaintKernel.h"
#include "vtkOFBPainter.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <deque>
#include <utility>
#include <vector>

namespace vtkofbpainter
{
/// One undo (or redo) step: the other value of every sample it changed.
struct Step
{
  std::vector<vtkOFBColorRecord> Colors;
  std::vector<vtkOFBNormalRecord> Normals;

  bool Empty() const { return this->Colors.empty() && this->Normals.empty(); }
  vtkIdType Bytes() const
  {
    return static_cast<vtkIdType>(this->Colors.size() * sizeof(vtkOFBColorRecord) +
      this->Normals.size() * sizeof(vtkOFBNormalRecord));
  }
  void Clear()
  {
    this->Colors.clear();
    this->Normals.clear();
  }
};
}

struct vtkOFBPainter::Internals
{
  vtkSmartPointer<vtkOFB> OFB;
  vtkSmartPointer<vtkOFBBrush> Brush;
  vtkSmartPointer<vtkPoints> StrokeDabs;
  vtkOFBPaintKernel Kernel;

  // What the OFB looked like after this painter's last change.
  bool Ready = false;
  vtkMTimeType LastMTime = 0;
  vtkMTimeType LastStructureTime = 0;
  vtkIdType LastNumberOfSamples = 0;
  vtkUnsignedCharArray* LastColors = nullptr;
  vtkFloatArray* LastNormals = nullptr;

  std::deque<vtkofbpainter::Step> UndoSteps;
  std::deque<vtkofbpainter::Step> RedoSteps;
  vtkofbpainter::Step Open;

  // Stroke state: the last point given, the last dab and the path length since.
  bool HasLastPoint = false;
  double LastPoint[3] = { 0.0, 0.0, 0.0 };
  double LastPressure = 1.0;
  bool HasLastDab = false;
  double LastDab[3] = { 0.0, 0.0, 0.0 };
  double SinceLastDab = 0.0;

  std::vector<std::pair<vtkIdType, vtkIdType>> Ranges;

  /// A dab at `center` with the brush's settings and `pressure`; false (with an error
  /// of `self`) if not finite.
  bool MakeDab(vtkOFBPainter* self, const double center[3], double pressure, vtkOFBDab& dab) const;
  /// Paint dabs with the settings of `self`, mark the changed ranges, call Modified();
  /// the changed count.
  vtkIdType Paint(vtkOFBPainter* self, std::vector<vtkOFBDab>& dabs);
  /// Each dab followed by its reflections (the mirrors of `self`).
  static void AddMirrorImages(const vtkOFBPainter* self, std::vector<vtkOFBDab>& dabs);

  vtkIdType HistoryBytes() const
  {
    vtkIdType b = this->Open.Bytes();
    for (const auto& s : this->UndoSteps)
    {
      b += s.Bytes();
    }
    for (const auto& s : this->RedoSteps)
    {
      b += s.Bytes();
    }
    return b;
  }
};

#endif
