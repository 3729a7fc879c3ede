#include "vtkOFBCompositeSurface.h"

#include "vtkCellData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkIntArray.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>

vtkStandardNewMacro(vtkOFBCompositeSurface);

//------------------------------------------------------------------------------
vtkOFBCompositeSurface::vtkOFBCompositeSurface()
  : Surface(vtkSmartPointer<vtkPolyData>::New())
{
}

//------------------------------------------------------------------------------
vtkOFBCompositeSurface::~vtkOFBCompositeSurface() = default;

//------------------------------------------------------------------------------
void vtkOFBCompositeSurface::SetDisplayAttributes(vtkCompositeDataDisplayAttributes* attributes)
{
  if (this->DisplayAttributes != attributes)
  {
    this->DisplayAttributes = attributes;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkCompositeDataDisplayAttributes* vtkOFBCompositeSurface::GetDisplayAttributes() const
{
  return this->DisplayAttributes;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkOFBCompositeSurface::GetSurface(vtkCompositeDataSet* input)
{
  vtkMTimeType changed = std::max(this->GetMTime(), input ? input->GetMTime() : 0);
  if (input)
  {
    // A block changed in place (its own Modified()) changes the surface too.
    auto iter = vtk::TakeSmartPointer(input->NewIterator());
    for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
    {
      changed = std::max(changed, iter->GetCurrentDataObject()->GetMTime());
    }
  }
  if (input == this->LastInput && changed <= this->BuildTime && this->DisplayAttributes &&
    this->DisplayAttributes->GetMTime() > this->BuildTime)
  {
    // Only the display attributes changed (a view may set them again before every
    // render): the same surface unless a block's visibility changed, so that what is
    // built from the surface (the OFB, its levels) is not built again.
    const std::vector<char> previous = this->Visible;
    this->Visible.clear();
    unsigned int index = 0;
    this->ComputeVisibility(input, true, index);
    if (this->Visible == previous)
    {
      this->BuildTime.Modified();
      return this->Surface;
    }
  }
  if (this->DisplayAttributes)
  {
    changed = std::max(changed, this->DisplayAttributes->GetMTime());
  }
  if (input == this->LastInput && changed <= this->BuildTime)
  {
    return this->Surface;
  }
  this->LastInput = input;
  this->BuildTime.Modified();
  this->Surface = vtkSmartPointer<vtkPolyData>::New();
  if (!input || input->GetNumberOfCells() == 0)
  {
    // Nothing to draw, and not an error: a piece without cells (a ParaView client that
    // renders remotely holds empty blocks; a process of a distributed surface may).
    return this->Surface;
  }
  this->Merge->SetInputData(input);
  this->Merge->Update();
  this->Visible.clear();
  unsigned int index = 0;
  this->ComputeVisibility(input, true, index);
  this->ExtractVisible(this->Merge->GetOutput());
  this->Merge->SetInputData(nullptr);
  return this->Surface;
}

//------------------------------------------------------------------------------
void vtkOFBCompositeSurface::ComputeVisibility(vtkDataObject* node,
  bool parentVisible,
  unsigned int& index)
{
  const unsigned int flat = index++;
  const bool visible =
    node && this->DisplayAttributes && this->DisplayAttributes->HasBlockVisibility(node)
    ? this->DisplayAttributes->GetBlockVisibility(node)
    : parentVisible;
  if (this->Visible.size() <= flat)
  {
    this->Visible.resize(flat + 1, 1);
  }
  this->Visible[flat] = visible ? 1 : 0;
  // Children in the order (and with the empty nodes) that give the flat indices.
  if (auto* tree = vtkDataObjectTree::SafeDownCast(node))
  {
    for (vtkDataObject* child : vtk::Range(tree, vtk::DataObjectTreeOptions::None))
    {
      this->ComputeVisibility(child, visible, index);
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBCompositeSurface::ExtractVisible(vtkPolyData* merged)
{
  auto* blocks = vtkIntArray::SafeDownCast(
    merged->GetCellData()->GetArray(vtkOFBMergeBlocks::BlockIndexArrayName()));
  const vtkIdType nCells = merged->GetNumberOfCells();
  auto isVisible = [this](int block) {
    return block < 0 || static_cast<size_t>(block) >= this->Visible.size() || this->Visible[block];
  };
  vtkIdType kept = 0;
  for (vtkIdType c = 0; blocks && c < nCells; ++c)
  {
    kept += isVisible(blocks->GetValue(c)) ? 1 : 0;
  }
  if (!blocks || kept == nCells)
  {
    this->Surface->ShallowCopy(merged);
    return;
  }
  // The points and point data stay whole: only cells are dropped. Merged cells are in
  // vtkPolyData's order (vertices, lines, polygons, strips), so inserting the kept ones
  // in order gives them ids in the same order.
  vtkPolyData* out = this->Surface;
  out->SetPoints(merged->GetPoints());
  out->GetPointData()->PassData(merged->GetPointData());
  out->AllocateEstimate(kept, 3);
  vtkCellData* inCD = merged->GetCellData();
  vtkCellData* outCD = out->GetCellData();
  outCD->CopyAllocate(inCD, kept);
  for (vtkIdType c = 0; c < nCells; ++c)
  {
    if (!isVisible(blocks->GetValue(c)))
    {
      continue;
    }
    vtkIdType npts;
    const vtkIdType* pts;
    merged->GetCellPoints(c, npts, pts);
    const vtkIdType id = out->InsertNextCell(merged->GetCellType(c), npts, pts);
    outCD->CopyData(inCD, c, id);
  }
  out->Squeeze();
}

//------------------------------------------------------------------------------
void vtkOFBCompositeSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DisplayAttributes: " << this->DisplayAttributes.Get() << "\n";
}
