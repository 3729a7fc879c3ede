/**
 * @class   vtkOFBMergeBlocks
 * @brief   The blocks of a composite dataset as one surface, with each cell's block index
 *
 * vtkOFBMergeBlocks turns a composite dataset (vtkMultiBlockDataSet,
 * vtkPartitionedDataSetCollection, vtkPartitionedDataSet, ...) into one vtkPolyData: the
 * surface of every dataset block (a vtkPolyData as it is, any other dataset through
 * vtkDataSetSurfaceFilter), appended in the order of the blocks' flat indices. It is the
 * step by which vtkOFBSampler and vtkOFBBuilder build one OFB on one frame over all blocks,
 * and by which vtkOFBPolyDataMapper renders a composite surface; use it directly to give
 * the same surface to filters that take a vtkPolyData (vtkOFBParticleAdvector).
 *
 * - Block index: the output has an int cell array "BlockIndex" (BlockIndexArrayName())
 *   holding the flat index of each cell's block, as vtkDataObjectTreeIterator and
 *   vtkCompositeDataSet::GetCompositeIndex number blocks (the root is 0, every node,
 *   empty or not, counts, in depth-first order: the four blocks of a vtkMultiBlockDataSet
 *   are 1 to 4), the index vtkCompositePolyDataMapper2 and vtkCellPicker's
 *   GetFlatBlockIndex() use. A cell array of the input of that name is replaced.
 * - Points shared by blocks: with MergePoints (default on) a point of a block at exactly
 *   the coordinates of a point of an earlier block becomes that point, so that the
 *   triangles of neighbouring patches are neighbours in the output (particles walk across,
 *   normals are computed across) and the patches' border is no seam. Such a point takes
 *   each point array from the first of its blocks that has the array. Points of one block
 *   are never merged with each other.
 * - Arrays: the output has every numeric point and cell array of any block (by name; the
 *   first block that has a name sets its type and number of components). A block that lacks
 *   an array, has it with another number of components, or has it with another number of
 *   tuples than its points or cells (with a warning) gets the fill: NaN for float and double
 *   arrays, IntegerFillValue (default 0) for integer arrays. Arrays of another type than
 *   the first block's are converted. String, bit and unnamed arrays are left out. The
 *   active attributes (scalars, vectors, normals, texture coordinates) are those of the
 *   first block that has them; point normals only when every point has them (else they
 *   stay an array, and vtkOFBSampler computes normals for all).
 * - Blocks left out: empty nodes and datasets without cells (no cell of theirs in the
 *   output), and blocks that are not datasets (a vtkTable, ...), with a warning naming their
 *   flat index.
 *
 * A vtkDataSet input gives its surface with block index 0. A block whose cells name points
 * it does not have is an error, and so is a composite input without any dataset with
 * cells: both give an empty output.
 *
 * @sa vtkOFBSampler vtkOFBPolyDataMapper vtkCompositeDataDisplayAttributes
 */

#ifndef vtkOFBMergeBlocks_h
#define vtkOFBMergeBlocks_h

#include "vtkOFBCoreModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKOFBCORE_EXPORT vtkOFBMergeBlocks : public vtkPolyDataAlgorithm
{
public:
  static vtkOFBMergeBlocks* New();
  vtkTypeMacro(vtkOFBMergeBlocks, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Name of the cell array of block indices: "BlockIndex".
  static const char* BlockIndexArrayName() { return "BlockIndex"; }

  ///@{
  /**
   * Merge a block's points with the points of earlier blocks at exactly the same
   * coordinates (default on).
   */
  vtkSetMacro(MergePoints, bool);
  vtkGetMacro(MergePoints, bool);
  vtkBooleanMacro(MergePoints, bool);
  ///@}

  ///@{
  /**
   * Value given to integer arrays in the blocks that lack them (default 0; it must be
   * representable in the array's type). Float and double arrays get NaN.
   */
  vtkSetMacro(IntegerFillValue, double);
  vtkGetMacro(IntegerFillValue, double);
  ///@}

protected:
  vtkOFBMergeBlocks();
  ~vtkOFBMergeBlocks() override;

  /// Accepts a vtkCompositeDataSet or a vtkDataSet.
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool MergePoints;
  double IntegerFillValue;

private:
  vtkOFBMergeBlocks(const vtkOFBMergeBlocks&) = delete;
  void operator=(const vtkOFBMergeBlocks&) = delete;

  struct vtkInternals;
};

#endif
