/**
 * @class   vtkOFBCompositeSurface
 * @brief   The visible surface of a composite input of vtkOFBPolyDataMapper (private)
 *
 * The blocks of a composite dataset merged into one vtkPolyData by vtkOFBMergeBlocks
 * (with the cell array "BlockIndex", the same surface vtkOFBSampler builds the OFB of),
 * without the cells of the blocks that the display attributes hide. A block's visibility
 * is its own (vtkCompositeDataDisplayAttributes::SetBlockVisibility) or, without one,
 * its parent's, as in vtkCompositePolyDataMapper2. The surface is rebuilt only when the
 * input or the attributes change.
 */

#ifndef vtkOFBCompositeSurface_h
#define vtkOFBCompositeSurface_h

#include "vtkNew.h" // for Merge
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members
#include "vtkWeakPointer.h"  // for LastInput

#include <vector> // for Visible

class vtkCompositeDataDisplayAttributes;
class vtkCompositeDataSet;
class vtkDataObject;
class vtkOFBMergeBlocks;
class vtkPolyData;

class vtkOFBCompositeSurface : public vtkObject
{
public:
  static vtkOFBCompositeSurface* New();
  vtkTypeMacro(vtkOFBCompositeSurface, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Per-block visibility (default none: every block visible).
   */
  void SetDisplayAttributes(vtkCompositeDataDisplayAttributes* attributes);
  vtkCompositeDataDisplayAttributes* GetDisplayAttributes() const;
  ///@}

  /**
   * The merged visible blocks of `input` (empty when none is visible or none has cells).
   */
  vtkPolyData* GetSurface(vtkCompositeDataSet* input);

protected:
  vtkOFBCompositeSurface();
  ~vtkOFBCompositeSurface() override;

private:
  vtkOFBCompositeSurface(const vtkOFBCompositeSurface&) = delete;
  void operator=(const vtkOFBCompositeSurface&) = delete;

  /// Visible[flat index] for `node` and its subtree, `index` its flat index (advanced).
  void ComputeVisibility(vtkDataObject* node, bool parentVisible, unsigned int& index);

  /// The cells of Merge's output whose block is visible.
  void ExtractVisible(vtkPolyData* merged);

  vtkSmartPointer<vtkCompositeDataDisplayAttributes> DisplayAttributes;
  vtkNew<vtkOFBMergeBlocks> Merge;
  vtkSmartPointer<vtkPolyData> Surface;
  std::vector<char> Visible;
  vtkWeakPointer<vtkDataObject> LastInput;
  vtkTimeStamp BuildTime;
};

#endif
