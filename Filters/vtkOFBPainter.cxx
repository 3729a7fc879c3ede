#include "vtkOFBPainter.h"

#include "vtkObjectFactory.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkOFBPainter);

struct vtkOFBPainter::Internals
{
  vtkSmartPointer<vtkOFB> OFB;
  vtkSmartPointer<vtkOFBBrush> Brush;
  vtkSmartPointer<vtkPoints> StrokeDabs;
};

//------------------------------------------------------------------------------
vtkOFBPainter::vtkOFBPainter()
  : Impl(new Internals)
  , Spacing(0.25)
  , UndoLimit(256 << 20)
  , InStroke(false)
{
  this->DefaultColor[0] = this->DefaultColor[1] = this->DefaultColor[2] = 1.0;
  this->DefaultColor[3] = 1.0;
  this->Impl->Brush = vtkSmartPointer<vtkOFBBrush>::New();
  this->Impl->StrokeDabs = vtkSmartPointer<vtkPoints>::New();
}

vtkOFBPainter::~vtkOFBPainter() = default;

void vtkOFBPainter::SetOFB(vtkOFB* ofb)
{
  this->Impl->OFB = ofb;
  this->Modified();
}
vtkOFB* vtkOFBPainter::GetOFB() const
{
  return this->Impl->OFB;
}
void vtkOFBPainter::SetBrush(vtkOFBBrush* brush)
{
  this->Impl->Brush = brush;
  this->Modified();
}
vtkOFBBrush* vtkOFBPainter::GetBrush() const
{
  return this->Impl->Brush;
}
vtkIdType vtkOFBPainter::Dab(const double*)
{
  return 0;
}
vtkIdType vtkOFBPainter::Dab(double x, double y, double z)
{
  const double c[3] = { x, y, z };
  return this->Dab(c);
}
vtkIdType vtkOFBPainter::Dabs(vtkPoints*)
{
  return 0;
}
vtkIdType vtkOFBPainter::Dabs(vtkPolyData*)
{
  return 0;
}
void vtkOFBPainter::BeginStroke()
{
  this->InStroke = true;
}
vtkIdType vtkOFBPainter::StrokeTo(const double*, double)
{
  return 0;
}
vtkIdType vtkOFBPainter::StrokeTo(double x, double y, double z, double pressure)
{
  const double p[3] = { x, y, z };
  return this->StrokeTo(p, pressure);
}
void vtkOFBPainter::EndStroke()
{
  this->InStroke = false;
}
vtkPoints* vtkOFBPainter::GetStrokeDabs() const
{
  return this->Impl->StrokeDabs;
}
vtkIdType vtkOFBPainter::Undo()
{
  return 0;
}
vtkIdType vtkOFBPainter::Redo()
{
  return 0;
}
bool vtkOFBPainter::CanUndo() const
{
  return false;
}
bool vtkOFBPainter::CanRedo() const
{
  return false;
}
void vtkOFBPainter::ClearHistory() {}
int vtkOFBPainter::GetNumberOfUndoSteps() const
{
  return 0;
}
int vtkOFBPainter::GetNumberOfRedoSteps() const
{
  return 0;
}
vtkIdType vtkOFBPainter::GetUndoMemory() const
{
  return 0;
}
void vtkOFBPainter::ResetInitialValues() {}
vtkIdType vtkOFBPainter::GetScratchMemory() const
{
  return 0;
}
void vtkOFBPainter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
