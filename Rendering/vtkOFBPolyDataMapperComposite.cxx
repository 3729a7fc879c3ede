// vtkOFBPolyDataMapper's composite input: the merged visible blocks
// (vtkOFBCompositeSurface) rendered in one draw with one OFB, and their bounds.
#include "vtkOFBPolyDataMapper.h"

#include "vtkCommand.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkExecutive.h"
#include "vtkMath.h"
#include "vtkOFBCompositeSurface.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetCompositeDataDisplayAttributes(
  vtkCompositeDataDisplayAttributes* attributes)
{
  if (!this->CompositeSurface)
  {
    this->CompositeSurface = vtkSmartPointer<vtkOFBCompositeSurface>::New();
  }
  if (this->CompositeSurface->GetDisplayAttributes() != attributes)
  {
    this->CompositeSurface->SetDisplayAttributes(attributes);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkCompositeDataDisplayAttributes* vtkOFBPolyDataMapper::GetCompositeDataDisplayAttributes()
{
  return this->CompositeSurface ? this->CompositeSurface->GetDisplayAttributes() : nullptr;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkOFBPolyDataMapper::GetRenderedSurface()
{
  auto* composite = vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!composite)
  {
    return this->GetInput();
  }
  if (!this->CompositeSurface)
  {
    this->CompositeSurface = vtkSmartPointer<vtkOFBCompositeSurface>::New();
  }
  return this->CompositeSurface->GetSurface(composite);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::RenderSurface(vtkRenderer* ren, vtkActor* act)
{
  if (!vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0)))
  {
    this->Superclass::RenderPiece(ren, act);
    return;
  }
  // vtkOpenGLPolyDataMapper::RenderPiece with the merged visible blocks as the input (as
  // vtkCompositePolyDataMapper2's helper draws its blocks: the window releases the
  // mapper's resources through its renderers' props).
  if (ren->GetRenderWindow()->CheckAbortStatus())
  {
    return;
  }
  this->InvokeEvent(vtkCommand::StartEvent, nullptr);
  if (!this->Static)
  {
    this->GetInputAlgorithm()->Update();
  }
  this->InvokeEvent(vtkCommand::EndEvent, nullptr);
  this->CurrentInput = this->GetRenderedSurface();
  if (!this->CurrentInput || !this->CurrentInput->GetPoints() ||
    this->CurrentInput->GetNumberOfCells() == 0)
  {
    return;
  }
  this->UpdateCameraShiftScale(ren, act);
  this->RenderPieceStart(ren, act);
  this->RenderPieceDraw(ren, act);
  this->RenderPieceFinish(ren, act);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ComputeBounds()
{
  if (!vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0)))
  {
    this->Superclass::ComputeBounds();
    return;
  }
  // The bounds of the visible blocks' cells (what is drawn), as vtkCompositePolyDataMapper2.
  vtkPolyData* surface = this->GetRenderedSurface();
  if (surface && surface->GetNumberOfCells() > 0)
  {
    surface->GetCellsBounds(this->Bounds);
  }
  else
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
}
