/**
 * @class   vtkOFBSamplePack
 * @brief   an OFB's owned samples as field data arrays, and packs merged back into an OFB
 *
 * vtkOFBSamplePack carries an OFB where only a dataset travels: ParaView's serialized
 * transfers (vtkMultiProcessController's Send and Gather of a data object, the legacy
 * format vtkMPIMoveData delivers geometry in) keep a dataset's field data arrays but
 * neither information keys nor objects of the process. Pack() adds to a vtkFieldData the
 * frame of an OFB and its owned samples (those with no, or a zero, "vtkGhostType"), each
 * array named with a prefix:
 * - `<prefix>Frame`: 7 doubles, the origin (x, y, z), the cell size and the dimensions;
 * - `<prefix>Cell`: a sample's global cell index (unsigned 32-bit);
 * - `<prefix>Depth`: a sample's depth (float);
 * - `<prefix>Sample_<name>`: every sample array but "vtkGhostType", as it is;
 * - `<prefix>Attributes`: for each attribute type (vtkDataSetAttributes::AttributeTypes:
 *   the active scalars, vectors, normals, ...), the rank of its array among the packed
 *   sample arrays, -1 for none (the active vectors are the mapper's flow field).
 * A packed sample costs 8 bytes plus its arrays' (e.g. 4 for RGBA "Colors", 4 for a float
 * "LIC", 12 for float normals); a pack adds 7 doubles and NUM_ATTRIBUTES ints. Merge() rebuilds one
 * OFB from the packs of any number of pieces on one frame, the samples of each grid cell in order
 * of depth (ties in the order of the packs), and refuses packs whose frames differ or whose arrays
 * are inconsistent (a problem string, no OFB), never reading outside an array.
 *
 * vtkOFBTexturedMeshWriter gathers every process's pack on the first one; the OFB
 * Surface representation (vtkOFBSurfaceRepresentation) packs each server process's
 * input OFB into the surface it delivers to a client that renders locally
 * (PackIntoBlocks), and the client merges the packs of the pieces it receives
 * (UpdateMergedOFB, MergeFromBlocks).
 *
 * @sa vtkOFBTexturedMeshWriter vtkOFBParaViewProbe
 */

#ifndef vtkOFBSamplePack_h
#define vtkOFBSamplePack_h

#include "vtkOFBParaViewModule.h" // for export macro
#include "vtkObject.h"

#ifndef __VTK_WRAP__
#include "vtkSmartPointer.h" // for the merged OFB
#include <string>            // for the prefixes and problems
#include <vector>            // for the packs
#endif

class vtkDataObject;
class vtkFieldData;
class vtkOFB;

class VTKOFBPARAVIEW_EXPORT vtkOFBSamplePack : public vtkObject
{
public:
  static vtkOFBSamplePack* New();
  vtkTypeMacro(vtkOFBSamplePack, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Adds to `fields` the frame of `ofb` and its owned samples, the arrays named with
   * `prefix` (replacing arrays of the same names). Returns the number of samples packed:
   * -1 where `ofb` has no frame (nothing added), 0 where it owns no sample (the frame
   * alone).
   */
  static vtkIdType Pack(vtkOFB* ofb, vtkFieldData* fields, const char* prefix);

  /**
   * Removes from `fields` every array whose name starts with `prefix`.
   */
  static void RemovePacks(vtkFieldData* fields, const char* prefix);

  /**
   * Bytes a packed sample of `ofb` takes: its cell index and depth (8) and every packed
   * sample array's tuple.
   */
  static vtkIdType GetBytesPerSample(vtkOFB* ofb);

  /**
   * The prefix of the packs of ParaView's delivered pieces: "vtkOFBPiece", then the
   * process's rank and "_".
   */
  static const char* PiecePrefix() { return "vtkOFBPiece"; }

  /**
   * Packs `ofb` (Pack()) into the field data of the first polygonal block of `blocks`
   * (a vtkMultiBlockDataSet, the piece a ParaView representation delivers) with the
   * prefix PiecePrefix() + `rank` + "_". The block is replaced by a shallow copy with its
   * own field data, so that data shared upstream is not changed. Returns the number of
   * samples packed (-1: nothing packed, no such block or no frame).
   */
  static vtkIdType PackIntoBlocks(vtkDataObject* blocks, vtkOFB* ofb, int rank);

  /**
   * The sum of the modification times of the arrays of the packs (prefix PiecePrefix())
   * in the field data of `data` and of its blocks: 0 without packs; changes where a pack
   * array is added, removed, replaced (a new delivery of other data) or modified, not
   * where the same arrays come in another data object (a shallow copy).
   */
  static vtkMTimeType GetPacksMTime(vtkDataObject* data);

  /**
   * The OFB merged from the packs of `data` (MergeFromBlocks), kept in this object and
   * merged again only where the packs changed (GetPacksMTime), so that a receiver calls it
   * at every render. Null without packs (or without `data`), and null with an error,
   * reported once per problem, where they cannot be merged.
   */
  vtkOFB* UpdateMergedOFB(vtkDataObject* data);

#ifndef __VTK_WRAP__
  /**
   * A pack: the field data holding it, and its prefix.
   */
  struct PackRef
  {
    vtkFieldData* Fields;
    std::string Prefix;
  };

  /**
   * The packs of `fields` whose prefix starts with `base` (a `<prefix>Frame` array names
   * one), in the order of their prefixes (shorter first, then alphabetical: rank order
   * for PiecePrefix()).
   */
  static std::vector<PackRef> FindPacks(vtkFieldData* fields, const char* base);

  /**
   * One OFB from `packs`: their frame (the first pack's) and all their samples. A pack
   * with a frame and neither cells nor depths adds no sample. Null without any frame;
   * null with `problem` set (a sentence without final period) where the frames differ or
   * a pack is inconsistent (a frame of other than 7 finite values, cells and depths of
   * other types or lengths, a cell outside the frame, a depth not finite, a sample array
   * of another length).
   */
  static vtkSmartPointer<vtkOFB> Merge(const std::vector<PackRef>& packs, std::string& problem);

  /**
   * The OFB merged from the packs (prefix PiecePrefix()) in the field data of every block
   * of `data` (a dataset or a composite dataset, as delivered to a client, whose
   * processes' pieces ParaView appended block by block). Null without packs; null with
   * `problem` set where they cannot be merged (Merge()).
   */
  static vtkSmartPointer<vtkOFB> MergeFromBlocks(vtkDataObject* data, std::string& problem);
#endif

protected:
  vtkOFBSamplePack();
  ~vtkOFBSamplePack() override;

#ifndef __VTK_WRAP__
  vtkSmartPointer<vtkOFB> MergedOFB; // UpdateMergedOFB's result
  vtkMTimeType MergedPacksTime;      // GetPacksMTime of the packs it was merged from
  std::string MergeProblem;          // why those packs could not be merged, if so
#endif

private:
  vtkOFBSamplePack(const vtkOFBSamplePack&) = delete;
  void operator=(const vtkOFBSamplePack&) = delete;
};

#endif
