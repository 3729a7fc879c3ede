// vtkOFBPainter::SetSampleColors: colours computed elsewhere written as undoable paint.
#include "vtkOFBPainter.h"
#include "vtkOFBPainterInternals.h"

#include "vtkIdTypeArray.h"
#include "vtkUnsignedCharArray.h"

//------------------------------------------------------------------------------
vtkIdType vtkOFBPainter::SetSampleColors(vtkIdTypeArray* ids, vtkUnsignedCharArray* colors)
{
  CallScope scope(this, "SetSampleColors");
  if (!scope)
  {
    return 0;
  }
  if (!ids || !colors || colors->GetNumberOfComponents() != 4 ||
    colors->GetNumberOfTuples() != ids->GetNumberOfTuples() || ids->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("SetSampleColors: give one id a sample and one RGBA tuple an id.");
    return 0;
  }
  if (!this->Prepare(true, false))
  {
    return 0;
  }
  vtkInternals& internals = *this->Internals;
  const vtkIdType n = internals.OFB->GetNumberOfSamples();
  const vtkIdType count = ids->GetNumberOfTuples();
  const vtkIdType* id = ids->GetPointer(0);
  for (vtkIdType k = 0; k < count; ++k)
  {
    if (id[k] < 0 || id[k] >= n)
    {
      vtkErrorMacro(
        "SetSampleColors: sample id " << id[k] << " is outside [0, " << n << "): nothing written.");
      return 0;
    }
  }
  if (this->UndoLimit <= 0)
  {
    this->DropHistory(); // no previous values kept (as Paint does)
  }
  internals.Kernel.SetColors(
    id, colors->GetPointer(0), count, this->UndoLimit > 0, internals.Open.Colors);
  const vtkIdType changed = this->Finish();
  if (!this->InStroke)
  {
    this->CloseStep();
  }
  return changed;
}
