/**
 * @class   vtkOFBSurfaceRepresentation
 * @brief   ParaView's surface representation coloured per fragment from an OFB
 *
 * vtkOFBSurfaceRepresentation is the "OFB Surface" representation of ParaView's render
 * view: a vtkGeometryRepresentationWithFaces (so it has every property of the "Surface"
 * representation) whose mapper is a vtkOFBPolyDataMapper. It builds the OFB itself, on
 * the process that renders, from the surface the view delivers to it (a vtkOFBSampler,
 * then a vtkOFBLIC when the LIC is on), and colours every fragment from the samples, as
 * the "Surface LIC" representation computes its LIC in its mapper from the same surface.
 * Where its input carries an OFB (the output of OFB Probe, vtkOFBParaViewProbe, holds the
 * OFB it probed: painted by OFB Paint Strokes, OFB Particles, with an OFB LIC's "LIC"),
 * and UseInputOFB is on (default), that OFB colours the surface instead, at its own
 * resolution: the paint is the OFB's, not the mesh's vertex colours. Where the data is
 * rendered in the process that computed it (pvpython, pvbatch, pvserver rendering
 * remotely) that OFB is used as it is; a pvserver also packs its owned samples into the
 * surface it delivers (PackInputOFB, vtkOFBSamplePack), and a client that renders the
 * surface locally merges the packs of the server processes into the same OFB
 * (DeliveredOFB, in ProcessViewRequest), or, where they cannot be merged, reports it and
 * builds its own.
 * - Colour by Solid Color, or by an array with Map Scalars off (direct colours, such as
 *   OFB Probe's "Colors"): the paint, the "Colors" sample array. It holds the input OFB's
 *   paint, else the surface's RGB(A) byte colours where its active point scalars are such
 *   (a painted mesh), else the representation's DiffuseColor.
 * - Colour by an array (point or cell): the sample array of that name (the sampler
 *   interpolates every point array into the samples, and gives each sample its cell's
 *   value of every cell array) mapped through ParaView's colour map (the representation's
 *   LookupTable, over the map's own range, component or magnitude as the map's vector
 *   mode says).
 * - OFBLIC on, with the vector array chosen with SelectOFBInputVectors: the LIC of that
 *   field on the samples (an input OFB's "LIC" array as it is, where it has one),
 *   combined with the colour (OFBLICColorMode: blend or map, OFBLICIntensity,
 *   OFBMapModeBias; vtkOFBColoring's formulas, those of VTK's surface LIC). The LIC is
 *   computed once per change of the surface or of a LIC setting, not per frame.
 *
 * OFBResolution (cells along the longest side of the surface's bounds) sets the
 * colour resolution, OFBLookupMode how a fragment reads the samples (the mapper's
 * lookup modes). The OFB is rebuilt only when the surface or a construction setting
 * changes; a change of the colour array, the solid colour or a time step with the same
 * geometry re-samples the attributes alone (vtkOFBSampler's STRUCTURE_REUSE_ALWAYS).
 *
 * Under MPI (the global controller has more than one process: pvbatch or pvserver
 * under mpiexec, where ParaView distributes the surface), each process builds the OFB of
 * its piece on the frame of the whole surface: the sampler is a vtkOFBPSampler (an
 * all-reduce of the pieces' bounds, vtkOFBPSampler::AllReduceBounds) and the LIC a
 * vtkOFBPLIC (the contrast stretches from every piece's samples), so that the pieces'
 * samples lie on the same three grids as one process's and no seam shows where the
 * pieces meet in the composited image. An input OFB (OFB Probe's) is already on the
 * whole surface's frame (OFB Sampler is a vtkOFBPSampler) and is used as it is. Every
 * process takes part in the collective calls at every render, also one whose piece is
 * empty: the representation updates its OFB before the render, on every process at once,
 * whenever any process needs it, and hands the mapper the result as data (SetOFB, and
 * the LIC pyramid with SetPyramid), so that the mapper never updates the pipeline on one
 * process alone (SynchronizeOFB). ParaView's geometry filter removes ghost cells from the
 * surface it delivers: where the input is polygonal with ghost cells (GhostCellsGenerator
 * upstream) and the delivered surface has the input's owned cells, the input itself is
 * sampled, ghost cells included; the representation does not ask for ghost cells. The
 * LIC reads the owned samples of the other processes within its streamlines' reach,
 * whatever the ghost depth (vtkOFBPLIC GhostSamples exchange). The coarser levels of the
 * mapper's LIC pyramid (the Automatic lookup's, a vtkOFBPLICPyramid) are sampled from
 * each process's piece on frames derived from level 0's, the same on every process, and
 * filtered and convolved from every process's owned samples within reach, on every
 * process together (SynchronizePyramid), not by the mapper. GetOFBFrame() (the information
 * property OFBFrame) gives the frame of the OFB rendered.
 *
 * The level-of-detail mapper (ParaView's decimated surface while interacting with a
 * large surface) is the plain one of the superclass: it shows the same colour array
 * per vertex, without the OFB.
 *
 * The OFB settings are named with an OFB prefix, so that they do not clash with the
 * "Surface LIC" representation's, which extends the same composite representation.
 *
 * @sa vtkOFBPolyDataMapper vtkOFBSampler vtkOFBLIC vtkOFBColoring
 */

#ifndef vtkOFBSurfaceRepresentation_h
#define vtkOFBSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkOFBParaViewRepresentationModule.h" // for export macro

#include "vtkSmartPointer.h" // for InputOFB

#include <string> // for the vector array name

class vtkAlgorithm;
class vtkDataObject;
class vtkOFB;
class vtkOFBLIC;
class vtkOFBLICPyramid;
class vtkOFBPLIC;
class vtkOFBPSampler;
class vtkOFBPolyDataMapper;
class vtkOFBSamplePack;
class vtkOFBSampler;
class vtkPolyData;

class VTKOFBPARAVIEWREPRESENTATION_EXPORT vtkOFBSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkOFBSurfaceRepresentation* New();
  vtkTypeMacro(vtkOFBSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Also hands the delivered surface to the OFB's sampler and the block visibilities to
   * the OFB mapper before a render.
   */
  int ProcessViewRequest(vtkInformationRequestKey* requestType,
    vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  ///@{
  /**
   * Cells along the longest side of the surface's bounds (vtkOFBSampler's Resolution,
   * 3..65536, default 1024): the colour resolution of the surface.
   */
  void SetOFBResolution(int resolution);
  int GetOFBResolution();
  ///@}

  ///@{
  /**
   * How a fragment reads its colour from the samples, a vtkOFBPolyDataMapper::LookupModes
   * value (default LOOKUP_AUTOMATIC: Smooth for a LIC, else Nearest).
   */
  void SetOFBLookupMode(int mode);
  int GetOFBLookupMode();
  ///@}

  ///@{
  /**
   * Colour from the OFB that the input carries (vtkOFBParaViewProbe's output), where it
   * does and this process has it (default on). Off: the OFB is always built here.
   */
  void SetUseInputOFB(bool use);
  vtkGetMacro(UseInputOFB, bool);
  ///@}

  /**
   * The OFB the last render coloured from: the input's (UseInputOFB) or the one built
   * here (null before the first render).
   */
  vtkOFB* GetRenderedOFB();

  /**
   * The frame of the OFB the last render coloured from, as 7 numbers: origin (x, y, z),
   * cell size, dimensions (cells along x, y, z); zeros before the first render or without
   * an OFB. Where that OFB is a LIC without a frame (a process whose piece is empty), the
   * frame of the OFB the LIC reads. Under MPI every process gives the frame of the whole
   * surface.
   */
  double* GetOFBFrame() VTK_SIZEHINT(7);

  ///@{
  /**
   * The LIC on the samples (default off). Without a vector array (SelectOFBInputVectors)
   * the surface's active point vectors are the field.
   */
  void SetOFBLIC(bool enable);
  vtkGetMacro(OFBLIC, bool);
  ///@}

  /**
   * The vector array of the LIC, as the "Surface LIC" representation's
   * SelectInputVectors (the first three arguments are ignored; a point or a cell array).
   */
  void SelectOFBInputVectors(int, int, int, int fieldAssociation, const char* name);

  ///@{
  /**
   * vtkOFBLIC's settings: steps each way (default 20), step size in OFB cells (default
   * 1), noise grain in OFB cells (default 1), the enhanced two-pass LIC (default on),
   * normalized vectors (default on).
   */
  void SetOFBNumberOfSteps(int steps);
  void SetOFBStepSize(double size);
  void SetOFBNoiseGrainSize(double size);
  void SetOFBEnhancedLIC(bool enhanced);
  void SetOFBNormalizeVectors(bool normalize);
  ///@}

  ///@{
  /**
   * How the LIC combines with the colour (vtkOFBColoring): OFBLICColorMode 0 blend
   * (default), 1 map; OFBLICIntensity the LIC's share in blend (0..1, default 0.8 here,
   * as ParaView's Surface LIC, so that the colour map shows under the LIC);
   * OFBMapModeBias added to the LIC in map (-1..1, default 0).
   */
  void SetOFBLICColorMode(int mode);
  void SetOFBLICIntensity(double intensity);
  void SetOFBMapModeBias(double bias);
  ///@}

  ///@{
  /**
   * The OFB objects, for tests and scripts that run in the rendering process.
   */
  vtkOFBPolyDataMapper* GetOFBMapper() { return this->OFBMapper; }
  vtkOFBSampler* GetOFBSampler();
  vtkOFBLIC* GetOFBLICFilter();
  ///@}

  /**
   * Also the paint of a surface without colours of its own (vtkOFBSampler's DefaultColor).
   */
  void SetDiffuseColor(double r, double g, double b) override;

protected:
  vtkOFBSurfaceRepresentation();
  ~vtkOFBSurfaceRepresentation() override;

  /**
   * Also keeps the OFB that the input carries (InputOFB), in the process that has the
   * input.
   */
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * The superclass's, then the OFB colouring: paint or the colour array through the
   * lookup table, the LIC, and which OFB (sampler or LIC) the mapper reads.
   */
  void UpdateColoringParameters() override;

  ///@{
  /**
   * Steps of UpdateColoringParameters: the colour source from the colour array
   * (UpdateColorSource) and the OFB the mapper reads with the LIC's colouring
   * (UpdateLICConnection), and the vector field of the sampler and the LIC (UpdateVectors:
   * the chosen array when the LIC is on and the surface has it; returns whether the LIC
   * has a field: the chosen array or the active point vectors).
   */
  void UpdateColorSource();
  void UpdateLICConnection();
  bool UpdateVectors();
  ///@}

  /**
   * Number of components of the array `name` of `association` (null: the active point
   * vectors) in the first dataset of `data` that has it (0 when none).
   */
  static int GetNumberOfComponents(vtkDataObject* data, int association, const char* name);

  /**
   * Whether `data` is polygonal (a vtkPolyData, or a composite dataset of them) with a
   * ghost cell array ("vtkGhostType") in some block.
   */
  static bool HasGhostCells(vtkDataObject* data);

  /**
   * Cells of `data` (a dataset or the datasets of a composite one); with `ownedOnly`, those
   * whose "vtkGhostType" is 0.
   */
  static vtkIdType CountCells(vtkDataObject* data, bool ownedOnly);

  /**
   * Under MPI, at every render on every process: agrees with the other processes on
   * whether the LIC runs and which OFB it reads (a process whose piece is empty has no
   * field), then updates the OFB the mapper reads on every process where any process needs
   * it, so that the collective calls of vtkOFBPSampler and vtkOFBPLIC are made by all
   * processes together, never by the mapper of one alone.
   */
  void SynchronizeOFB();

  /**
   * Under MPI, with the LIC pyramid: brings the pyramid's levels of `ofb` up to date as the
   * mapper's render would, then computes the levels' LICs (vtkOFBPLIC, collective calls)
   * on every process together, with the largest number of levels of any process, where
   * any process needs them (vtkOFBLICPyramid::DeferLevelLICs).
   */
  void SynchronizePyramid(vtkOFB* ofb);

  /**
   * Whether `algorithm`'s output is older than the algorithm or its inputs (the update
   * that the mapper's would run), following its inputs upstream.
   */
  static bool NeedsUpdate(vtkAlgorithm* algorithm);

  /**
   * On a server (pvserver, not pvbatch), where the input OFB is shown: packs this
   * process's owned samples of it into the surface delivered to the client
   * (vtkOFBSamplePack::PackIntoBlocks), so that a client rendering locally shows the same
   * OFB. Run in RequestData, once per change of the data.
   */
  void PackInputOFB();

  vtkOFBPolyDataMapper* OFBMapper;
  vtkOFBPSampler* Sampler;
  vtkOFBPLIC* LIC;
  bool OFBLIC;
  bool UseInputOFB;
  vtkSmartPointer<vtkOFB> InputOFB; // the OFB the input carries, if any
  std::string VectorsName;
  int VectorsAssociation;
  std::string SamplerVectors; // the field set on the sampler ("": its default)
  std::string LICVectors;     // the field set on the LIC ("": its default)
  bool WarnedNoVectors;       // warned that the LIC has no field, until it has one
  // Under MPI: whether some process's piece has the LIC's field, an input OFB, an input
  // OFB with a LIC (SynchronizeOFB); the stand-ins of a process without piece or OFB.
  bool AnyLICField;
  bool AnyInputOFB;
  bool AnyInputLIC;
  vtkSmartPointer<vtkPolyData> EmptyPiece;
  vtkSmartPointer<vtkDataObject> GhostedInput;  // under MPI, the input with its ghost cells
  vtkSmartPointer<vtkOFBLICPyramid> LICPyramid; // under MPI, the mapper's LIC pyramid
  vtkAlgorithm* OFBSource; // under MPI, the algorithm whose output the mapper is handed
  vtkIdType GhostedCells;  // the owned cells of GhostedInput
  vtkSmartPointer<vtkOFB> EmptyOFB;
  vtkSmartPointer<vtkOFB> DeliveredOFB; // the input OFB packed into the delivered surface
  vtkSmartPointer<vtkOFBSamplePack> DeliveredPacks; // merges DeliveredOFB from the packs
  double OFBFrame[7];

private:
  vtkOFBSurfaceRepresentation(const vtkOFBSurfaceRepresentation&) = delete;
  void operator=(const vtkOFBSurfaceRepresentation&) = delete;
};

#endif
