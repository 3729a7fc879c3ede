/**
 * @class   vtkOFBTexturedMeshWriter
 * @brief   Writes a mesh with an OFB's paint baked into its texture: OBJ or glTF
 *
 * The input (port 0) is the mesh, a vtkPolyData; the OFB is the one given with
 * SetOFB(), else the one the input carries (vtkOFBParaViewProbe's output, which is what
 * ParaView's File > Save Data hands over from an OFB Probe). The file's extension picks
 * the format:
 * - `.obj`: the mesh with texture coordinates, a `.mtl` and the texture as a `.png`
 *   beside it (the `.mtl` and `.png` named after the `.obj`);
 * - `.gltf`: glTF 2.0, one file with the texture embedded (vtkGLTFExporter), normals
 *   written.
 * The texture: a mesh with texture coordinates keeps them and gets a TextureSize x
 * TextureSize texture; a mesh without gets the charts of a vtkOFBTextureAtlas (a texel a
 * cell, at most TextureSize a side). vtkOFBTextureBaker bakes ArrayName (default: the
 * paint, "Colors") into it; an array other than unsigned char is mapped from [0, 1] to
 * grey levels 0-255 (a LIC), its first three components.
 *
 * Files are written into a temporary folder beside the target and renamed into place
 * when all are complete (the texture and material first, the `.obj` last), so a failure
 * or a kill leaves the files that were there before and no partial file under the
 * target's name (vtkOFBStagedFiles: the folder a killed write leaves,
 * `.<name>.tmp-<host>-<process id>-<n>`, is removed by the next write into that folder on the
 * same machine).
 *
 * Bad input (no OFB, an empty mesh, an unknown extension or array, a folder that cannot
 * be written) gives an error and writes nothing.
 *
 * Distributed input (a Controller of more than one process, as under `mpiexec pvbatch`
 * or a pvserver of several ranks, where each process has its piece of the mesh and an
 * OFB with that piece's samples on the frame common to all pieces, vtkOFBPSampler):
 * every process sends its piece without ghost cells, and its OFB's owned samples (those
 * with a zero "vtkGhostType" sample value), to the first process (one message each, as
 * VTK XML in raw binary: bit for bit, of any size; vtkOFBParaViewGather.h). There the
 * pieces are appended and the points of a piece at exactly the coordinates of a point of
 * an earlier piece merged with it (vtkOFBMergeBlocks), the samples put together cell by
 * cell in order of depth (the order one process has them), and the file set is baked and
 * written as one process writes it; the other processes write nothing. Every process
 * takes part, also with an empty piece, and every process ends with the same result: the
 * same error code and WrittenTextureSize. The mesh's cells come in the order of the
 * pieces, so the files list them in another order than one process's; the mesh and the
 * colour each cell gets are the same. Pieces whose border points are not at exactly the
 * same coordinates keep them apart (no tolerance; points of one piece are never merged
 * with each other, so a mesh's own seams stay).
 *
 * @sa vtkOFBTextureBaker vtkOFBTextureAtlas vtkOFBParaViewProbe vtkOFBStagedFiles
 */

#ifndef vtkOFBTexturedMeshWriter_h
#define vtkOFBTexturedMeshWriter_h

#include "vtkOFBParaViewModule.h" // for export macro
#include "vtkSmartPointer.h"      // for member
#include "vtkWriter.h"

class vtkMultiProcessController;
class vtkOFB;
class vtkPolyData;

class VTKOFBPARAVIEW_EXPORT vtkOFBTexturedMeshWriter : public vtkWriter
{
public:
  static vtkOFBTexturedMeshWriter* New();
  vtkTypeMacro(vtkOFBTexturedMeshWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to write, `.obj` or `.gltf` (default none).
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The texture's size in texels a side for a mesh with texture coordinates, and the
   * largest side of an atlas for one without (16 to 16384; default 2048).
   */
  vtkSetClampMacro(TextureSize, int, 16, 16384);
  vtkGetMacro(TextureSize, int);
  ///@}

  ///@{
  /**
   * The sample array baked (default null: the paint, "Colors").
   */
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  ///@{
  /**
   * The OFB to bake (default null: the one the input carries under
   * vtkOFBParaViewProbe::OFB()).
   */
  void SetOFB(vtkOFB* ofb);
  vtkOFB* GetOFB() const;
  ///@}

  /**
   * The texture's size in texels of the last write (0 0 before one or after a failure).
   */
  vtkGetVector2Macro(WrittenTextureSize, int);

  ///@{
  /**
   * The processes that share the mesh (default: the global controller at construction).
   * Null or a single process: each process writes its own input. More processes: a
   * collective write (see the class documentation); every process must call Write().
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkOFBTexturedMeshWriter();
  ~vtkOFBTexturedMeshWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// Asks for this process's piece (of the Controller's processes) when there are more.
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  void WriteData() override;

  /// Bakes `mesh` with `ofb` into the file; false (with an error) on a failure.
  bool WriteMesh(vtkPolyData* mesh, vtkOFB* ofb);
  /// The collective write over the Controller's processes.
  void WriteDistributed(vtkPolyData* input, vtkOFB* ofb);

  char* FileName;
  char* ArrayName;
  int TextureSize;
  int WrittenTextureSize[2];
  vtkSmartPointer<vtkOFB> OFB;
  vtkMultiProcessController* Controller;

private:
  vtkOFBTexturedMeshWriter(const vtkOFBTexturedMeshWriter&) = delete;
  void operator=(const vtkOFBTexturedMeshWriter&) = delete;
};

#endif
