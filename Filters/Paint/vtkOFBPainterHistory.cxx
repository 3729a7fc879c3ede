// vtkOFBPainter's undo history: the steps of previous values, their limit, undo and redo.
#include "vtkOFBPainter.h"

#include "vtkOFB.h"
#include "vtkOFBPaintKernel.h"
#include "vtkOFBPainterInternals.h"

#include <algorithm>
#include <cstring>
#include <deque>

//------------------------------------------------------------------------------
void vtkOFBPainter::CloseStep()
{
  vtkInternals& internals = *this->Internals;
  if (internals.Open.Empty())
  {
    return;
  }
  internals.Kernel.ClearRecorded(internals.Open.Colors, internals.Open.Normals);
  // A step records each sample once, so the order of its records does not matter to
  // Restore(). Spare capacity beyond a quarter is given back.
  auto trim = [](auto& v)
  {
    if (v.capacity() > v.size() + v.size() / 4)
    {
      v.shrink_to_fit();
    }
  };
  trim(internals.Open.Colors);
  trim(internals.Open.Normals);
  internals.UndoSteps.push_back(std::move(internals.Open));
  internals.Open = vtkofbpainter::Step();
  internals.RedoSteps.clear();
  this->EnforceUndoLimit();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::EnforceUndoLimit()
{
  vtkInternals& internals = *this->Internals;
  vtkIdType bytes = internals.HistoryBytes();
  while (bytes > this->UndoLimit && !internals.RedoSteps.empty())
  {
    bytes -= internals.RedoSteps.back().Bytes(); // the step furthest from now
    internals.RedoSteps.pop_back();
  }
  while (bytes > this->UndoLimit && !internals.UndoSteps.empty())
  {
    bytes -= internals.UndoSteps.front().Bytes(); // the oldest step
    internals.UndoSteps.pop_front();
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Restore(bool undo)
{
  CallScope scope(this, undo ? "Undo" : "Redo");
  if (!scope)
  {
    return 0;
  }
  if (this->InStroke)
  {
    this->FinishStroke();
  }
  vtkInternals& internals = *this->Internals;
  std::deque<vtkofbpainter::Step>& from = undo ? internals.UndoSteps : internals.RedoSteps;
  std::deque<vtkofbpainter::Step>& to = undo ? internals.RedoSteps : internals.UndoSteps;
  if (from.empty() || !internals.OFB)
  {
    return 0;
  }
  // Drops the history if something else changed the OFB meanwhile.
  if (!this->Prepare(false, false) || from.empty())
  {
    return 0;
  }
  vtkofbpainter::Step step = std::move(from.back());
  from.pop_back();
  // Swap each recorded value with the current one: the step becomes its inverse.
  if (!step.Colors.empty() && internals.HeldColors)
  {
    unsigned char* colors = internals.HeldColors->GetPointer(0);
    for (auto& r : step.Colors)
    {
      unsigned char* c = colors + 4 * static_cast<vtkIdType>(r.Id);
      for (int k = 0; k < 4; ++k)
      {
        std::swap(c[k], r.Value[k]);
      }
      internals.Kernel.MarkChanged(r.Id);
    }
  }
  if (!step.Normals.empty() && internals.HeldNormals)
  {
    float* normals = internals.HeldNormals->GetPointer(0);
    for (auto& r : step.Normals)
    {
      float* n = normals + 3 * static_cast<vtkIdType>(r.Id);
      for (int k = 0; k < 3; ++k)
      {
        std::swap(n[k], r.Value[k]);
      }
      internals.Kernel.MarkChanged(r.Id);
    }
  }
  to.push_back(std::move(step));
  return this->Finish();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Undo()
{
  return this->Restore(true);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::Redo()
{
  return this->Restore(false);
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::CanUndo() const
{
  return !this->Internals->UndoSteps.empty() || !this->Internals->Open.Empty();
}

//------------------------------------------------------------------------------
bool vtkOFBPainter::CanRedo() const
{
  return !this->Internals->RedoSteps.empty();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::ClearHistory()
{
  CallScope scope(this, "ClearHistory");
  if (scope)
  {
    this->DropHistory();
  }
}

//------------------------------------------------------------------------------
void vtkOFBPainter::DropHistory()
{
  vtkInternals& internals = *this->Internals;
  if (internals.Ready)
  {
    internals.Kernel.ClearRecorded(internals.Open.Colors, internals.Open.Normals);
  }
  internals.Open.Clear();
  internals.UndoSteps.clear();
  internals.RedoSteps.clear();
}

//------------------------------------------------------------------------------
int vtkOFBPainter::GetNumberOfUndoSteps() const
{
  return static_cast<int>(this->Internals->UndoSteps.size()) +
    (this->Internals->Open.Empty() ? 0 : 1);
}

//------------------------------------------------------------------------------
int vtkOFBPainter::GetNumberOfRedoSteps() const
{
  return static_cast<int>(this->Internals->RedoSteps.size());
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::GetUndoMemory() const
{
  return this->Internals->HistoryBytes();
}

//------------------------------------------------------------------------------
void vtkOFBPainter::ResetInitialValues()
{
  CallScope scope(this, "ResetInitialValues");
  if (scope)
  {
    this->Internals->Kernel.ResetInitialValues();
  }
}

