// Private header of vtkOFBPainter: what a painter holds (the OFB, the brush, the paint
// kernel, the undo history and the stroke state), shared by its source files.
#ifndef vtkOFBPainterInternals_h
#define vtkOFBPainterInternals_h

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBPaintKernel.h"
#include "vtkOFBPainter.h"
#include "vtkOFBStrokeSampler.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <atomic>
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

struct vtkOFBPainter::vtkInternals
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
  // Weak: an array freed since (removed from the OFB) reads as null, and a new array at
  // the same address is not taken for the old one.
  vtkWeakPointer<vtkUnsignedCharArray> LastColors;
  vtkWeakPointer<vtkFloatArray> LastNormals;
  bool HadColors = false;
  bool HadNormals = false;

  // A public call in progress (see vtkOFBPainter::CallScope): what it holds so that an
  // observer of its progress cannot free it.
  std::atomic<bool> InCall{ false };
  vtkSmartPointer<vtkOFB> HeldOFB;
  vtkSmartPointer<vtkOFBBrush> HeldBrush;
  vtkSmartPointer<vtkUnsignedCharArray> HeldColors;
  vtkSmartPointer<vtkFloatArray> HeldNormals;

  std::deque<vtkofbpainter::Step> UndoSteps;
  std::deque<vtkofbpainter::Step> RedoSteps;
  vtkofbpainter::Step Open;

  // Stroke state: the last point given (on the surface with FollowSurface), the last dab and the walk of the dabs.
  bool HasLastPoint = false;
  double LastPoint[3] = { 0.0, 0.0, 0.0 };
  double LastPressure = 1.0;
  bool HasLastDab = false;
  double LastDab[3] = { 0.0, 0.0, 0.0 };
  vtkOFBStrokeSampler Sampler;

  std::vector<std::pair<vtkIdType, vtkIdType>> Ranges;

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

/**
 * One public call of a painter: refuses a call made during another (from a progress
 * observer, or from a second thread), holds the OFB and the brush until the call
 * returns, and takes the OFB from other writers (vtkOFB::BeginExclusiveWrite) so that
 * nothing the call reads through raw pointers is freed or rebuilt under it.
 */
class vtkOFBPainter::CallScope
{
public:
  CallScope(vtkOFBPainter* painter, const char* what);
  ~CallScope();
  CallScope(const CallScope&) = delete;
  CallScope& operator=(const CallScope&) = delete;
  explicit operator bool() const { return this->Entered; }

private:
  vtkOFBPainter* Painter;
  bool Entered = false;
};

#endif
