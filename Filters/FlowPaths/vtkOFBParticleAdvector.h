/**
 * @class   vtkOFBParticleAdvector
 * @brief   Particles that move on a triangle surface along a vector field and paint an OFB
 *
 * The surface particles of the paper "Sample-based Surface Coloring" (section 6).
 * The paper snaps its particles to OFB samples and says this is too inaccurate for
 * scientific visualization; here a particle is a triangle and barycentric
 * coordinates, so its position always lies exactly on the surface, and a step
 * moves it in its triangle's plane, crosses edges into the neighbouring triangles
 * and turns the rest of the displacement about each shared edge. The particles
 * are therefore accurate surface streamlines (port 2 gives them as polylines).
 *
 * Inputs:
 * - port 0: the surface, a vtkPolyData with a vector field. The field is the
 *   point array chosen with SetInputArrayToProcess(0, 0, 0, association, name)
 *   (default: the active point vectors); each use projects it into the tangent
 *   plane of the triangle at hand. A cell array (or, without a point field, the
 *   active cell vectors) holds on its cells' triangles, as vtkOFBSampler's cell
 *   arrays do: each triangle carries its cell's vector. Polygons are triangulated; lines and
 * vertices are ignored. A missing field, one without 3 components, one that is zero everywhere or
 * has non-finite values gives an error and empty outputs.
 * - port 1 (optional): the OFB to paint. The advector paints a copy that it keeps
 *   from step to step (taken again when that input changes); port 0 of the output
 *   is that copy. Alternatively SetOFB() gives an OFB that the application holds:
 *   it is painted in place (and port 0 shares it) and wins over port 1.
 * - port 2 (optional, SetSourceData / SetSourceConnection / SetSeeds): seed points.
 *   Each seed is moved to the closest point of the surface (vtkStaticCellLocator;
 *   a point on an edge or a vertex goes onto the triangle of smallest centroid there);
 *   seeds with non-finite coordinates, or farther than MaximumSeedDistance cells
 *   from the surface, are rejected with a warning. Without seeds,
 *   NumberOfParticles seeds are drawn area-uniformly over the surface from
 *   RandomSeed.
 *
 * Units. A "cell" is the cell size of the OFB painted, or without one 1/1024 of the
 * longest side of the surface's bounds. With NormalizeVectors (default) every
 * particle travels StepSize cells of arc per step; without it the field is scaled
 * by 1 / its largest length, so that the fastest point moves StepSize cells per
 * step and particles keep their relative speeds (a common time step).
 *
 * Each step every moving particle advances with the integrator (Euler, midpoint
 * RK2, classical RK4, or Cash-Karp RK45 in sub-steps whose error is kept under
 * ErrorTolerance cells), then paints a footprint at its new position through a
 * vtkOFBPainter with the advector's brush (GetBrush()): its falloff, blend mode,
 * target, strength (the footprints' opacity) and the rest, except its radius and
 * colour: a footprint has a radius of FootprintRadius cells and the particle's
 * colour. With the brush's Smear target the footprint carries the colour found at the
 * particle's previous position, by the brush's SmearAmount (paper Eq. 3). The
 * footprints of a step are painted together, in particle order, which gives the same
 * result with any number of threads.
 *
 * A particle stops where the field is zero or where it reaches a boundary edge of
 * an open surface. Without a Lifetime a stopped particle stays (no particle is
 * ever lost or duplicated); with one, a particle is reseeded when its age reaches
 * Lifetime steps or at the step after it stopped: at its own seed point, or at a
 * new random point drawn from its own random stream (seeded by RandomSeed, the
 * particle id and its number of reseeds), so the result does not depend on the
 * number of threads.
 *
 * Chains (paper 6.2.1): with ChainLength L > 1 each seed releases L particles, one
 * every ChainSpacing steps: particle k of a chain (k = 0 the first) appears at its
 * seed when the step count reaches k * ChainSpacing (painting a footprint there)
 * and moves from the next step on. It paints with radius FootprintRadius * (1 - k / L) and
 * strength (the brush's Strength) * (1 - k / L): the later ones, which follow behind, leave
 * smaller, fainter footprints, a tail.
 *
 * Colour modes: Constant (Color), FromSeeds (the seed point array
 * SeedColorArrayName, or the seeds' active scalars: unsigned char 0-255 or
 * floating point in [0, 1], 1 (grey), 3 or 4 (alpha times the brush's Strength) components),
 * ByScalar (the surface point array ScalarArrayName, component 0, interpolated at
 * the particle through LookupTable; without one a blue-to-red table over the
 * array's range), Periodic (the paper's Fig. 6: at step s the colour goes from
 * red through blue to green and back to red over ColorPeriod steps, linearly:
 * red at s = 0, blue at s = P/3, green at s = 2P/3, the same for every particle).
 *
 * Time. The advector counts steps from the seeds (GetCurrentStep()). A request
 * for time t (UPDATE_TIME_STEP, as VTK's animation sends) moves the particles to
 * step floor(t): forward by stepping, backward by restarting from the seeds (paint
 * already in an OFB given with SetOFB stays). Step() advances StepsPerUpdate steps
 * at once (for animation loops: Step(), then Render()). Changing a setting that
 * moves particles (integrator, step size, seeds...) or an input restarts them
 * from the seeds on the next update; appearance settings (colours, footprint,
 * trail length) apply from the next step.
 *
 * Unsteady fields. When the surface (port 0) reports TIME_STEPS, time is the
 * input's and the particles follow pathlines, as vtkParticleTracer does: a request
 * for time t asks the input for the step at or after t and keeps the step before
 * from the previous update, one input step at a time when t is beyond the next one
 * (CONTINUE_EXECUTING); the field is linear in time between the two (at the
 * middle of each integration step), and the particles go on from their time to t
 * in steps of at most StepSize cells for the fastest point (NormalizeVectors does
 * not apply). A new time step of the same geometry changes the field alone (no
 * restart); a time before the particles' time restarts them from the seeds there;
 * times outside the input's steps hold the nearest step's field (clamped, as VTK's
 * readers do); a non-finite time is an error. Step() has no effect then. The
 * outputs' DATA_TIME_STEP is the particles' time.
 *
 * Outputs: port 0 the painted OFB; port 1 the particles as vertices, with point
 * arrays "Velocity" (the field at the particle in its tangent plane, world units,
 * reversed for backward tracing), "Age" (steps since release or reseed), "Id",
 * "ChainIndex" and "Color" (RGBA unsigned char, alpha the footprint's strength); port 2 their
 * trails, a polyline of each particle's last TrailLength positions (with "Id").
 * Particles of a chain not yet released are not in the outputs.
 *
 * @sa vtkOFBPainter vtkOFBBrush vtkStreamTracer
 */

#ifndef vtkOFBParticleAdvector_h
#define vtkOFBParticleAdvector_h

#include "vtkAlgorithm.h"
#include "vtkOFBFlowPathsModule.h" // for export macro
#include "vtkSmartPointer.h"       // for member

#include <cstdint> // for HashGeometry
#include <memory>  // for std::unique_ptr
#include <vector>  // for FindOwnedTriangles

class vtkAlgorithmOutput;
class vtkDataArray;
class vtkOFB;
class vtkOFBBrush;
class vtkOFBParticleExchange;
class vtkDataSet;
class vtkPolyData;
class vtkScalarsToColors;

class VTKOFBFLOWPATHS_EXPORT vtkOFBParticleAdvector : public vtkAlgorithm
{
public:
  static vtkOFBParticleAdvector* New();
  vtkTypeMacro(vtkOFBParticleAdvector, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Integrators
  {
    EULER = 0,
    RK2 = 1,
    RK4 = 2,
    RK45 = 3
  };

  enum Directions
  {
    FORWARD = 0,
    BACKWARD = 1
  };

  enum ColorModes
  {
    COLOR_CONSTANT = 0,
    COLOR_FROM_SEEDS = 1,
    COLOR_BY_SCALAR = 2,
    COLOR_PERIODIC = 3
  };

  ///@{
  /**
   * Inputs: the surface (port 0), the OFB to paint (port 1, optional), the seeds
   * (port 2, optional). SetInputData(port, data) sets any of them, as
   * vtkPolyDataAlgorithm::SetInputData does.
   */
  void SetInputData(vtkDataObject* surface);
  void SetInputData(int port, vtkDataObject* input);
  void SetOFBData(vtkOFB* ofb);
  void SetOFBConnection(vtkAlgorithmOutput* output);
  void SetSourceData(vtkPolyData* seeds);
  void SetSourceConnection(vtkAlgorithmOutput* output);
  void SetSeeds(vtkPolyData* seeds) { this->SetSourceData(seeds); }
  ///@}

  ///@{
  /**
   * An OFB held by the application, painted in place (default none). It wins over
   * the OFB of port 1.
   */
  void SetOFB(vtkOFB* ofb);
  vtkGetObjectMacro(OFB, vtkOFB);
  ///@}

  ///@{
  /**
   * Outputs: the painted OFB (port 0), the particles (port 1), the trails (port 2).
   * GetOutput(port) returns any of them, as vtkPolyDataAlgorithm::GetOutput does.
   */
  vtkOFB* GetOutput();
  vtkDataObject* GetOutput(int port);
  vtkPolyData* GetParticles();
  vtkPolyData* GetTrails();
  ///@}

  ///@{
  /**
   * Integrator (default RK4).
   */
  vtkSetClampMacro(Integrator, int, EULER, RK45);
  vtkGetMacro(Integrator, int);
  void SetIntegratorToEuler() { this->SetIntegrator(EULER); }
  void SetIntegratorToRK2() { this->SetIntegrator(RK2); }
  void SetIntegratorToRK4() { this->SetIntegrator(RK4); }
  void SetIntegratorToRK45() { this->SetIntegrator(RK45); }
  ///@}

  ///@{
  /**
   * Length of a step in cells (default 1). Must be positive and finite, and at most
   * four times the surface's longest side in cells: another value gives an error and
   * empty outputs.
   */
  vtkSetMacro(StepSize, double);
  vtkGetMacro(StepSize, double);
  ///@}

  ///@{
  /**
   * RK45: the largest error of a sub-step, in cells (default 1e-3).
   */
  vtkSetClampMacro(ErrorTolerance, double, 1e-12, 1e6);
  vtkGetMacro(ErrorTolerance, double);
  ///@}

  ///@{
  /**
   * Whether every particle moves StepSize cells of arc per step (default on), or
   * the field keeps its relative speeds (see the class description).
   */
  vtkSetMacro(NormalizeVectors, bool);
  vtkGetMacro(NormalizeVectors, bool);
  vtkBooleanMacro(NormalizeVectors, bool);
  ///@}

  ///@{
  /**
   * Direction of travel (default FORWARD).
   */
  vtkSetClampMacro(Direction, int, FORWARD, BACKWARD);
  vtkGetMacro(Direction, int);
  void SetDirectionToForward() { this->SetDirection(FORWARD); }
  void SetDirectionToBackward() { this->SetDirection(BACKWARD); }
  ///@}

  ///@{
  /**
   * Steps made by Step() (default 1).
   */
  vtkSetClampMacro(StepsPerUpdate, int, 1, VTK_INT_MAX);
  vtkGetMacro(StepsPerUpdate, int);
  ///@}

  ///@{
  /**
   * Lifetime of a particle in steps, after which it is reseeded; 0 (default) for
   * an unlimited life.
   */
  vtkSetClampMacro(Lifetime, int, 0, VTK_INT_MAX);
  vtkGetMacro(Lifetime, int);
  ///@}

  ///@{
  /**
   * Number of random seeds when no seed points are given (default 1000), and the
   * seed of their random numbers (default 0).
   */
  vtkSetClampMacro(NumberOfParticles, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(NumberOfParticles, vtkIdType);
  vtkSetMacro(RandomSeed, unsigned int);
  vtkGetMacro(RandomSeed, unsigned int);
  ///@}

  ///@{
  /**
   * Seed points farther than this from the surface, in cells, are rejected with a
   * warning (default 10); nearer ones are moved onto it.
   */
  vtkSetClampMacro(MaximumSeedDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumSeedDistance, double);
  ///@}

  ///@{
  /**
   * Chains: particles per seed (default 1) and steps between their releases
   * (default 1).
   */
  vtkSetClampMacro(ChainLength, int, 1, 1000000);
  vtkGetMacro(ChainLength, int);
  vtkSetClampMacro(ChainSpacing, int, 1, 1000000);
  vtkGetMacro(ChainSpacing, int);
  ///@}

  ///@{
  /**
   * Colour mode (default COLOR_CONSTANT), see the class description.
   */
  vtkSetClampMacro(ColorMode, int, COLOR_CONSTANT, COLOR_PERIODIC);
  vtkGetMacro(ColorMode, int);
  void SetColorModeToConstant() { this->SetColorMode(COLOR_CONSTANT); }
  void SetColorModeToFromSeeds() { this->SetColorMode(COLOR_FROM_SEEDS); }
  void SetColorModeToByScalar() { this->SetColorMode(COLOR_BY_SCALAR); }
  void SetColorModeToPeriodic() { this->SetColorMode(COLOR_PERIODIC); }
  static const char* GetColorModeAsString(int mode);
  ///@}

  ///@{
  /**
   * Constant colour, RGB in [0, 1] (default red).
   */
  vtkSetVector3Macro(Color, double);
  vtkGetVector3Macro(Color, double);
  ///@}

  ///@{
  /**
   * Footprint radius in cells (default 2.5). The brush's Radius, in world units, is
   * not used.
   */
  vtkSetClampMacro(FootprintRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FootprintRadius, double);
  ///@}

  ///@{
  /**
   * The brush of the footprints (a default vtkOFBBrush unless set, with the Constant
   * falloff): falloff, blend mode, target (Color, or Smear for paper Eq. 3; Normal
   * paints bumps into an OFB with normals), Strength (the footprints' opacity,
   * default 1) and SmearAmount. Its Radius and Color are not used (see the class
   * description). A change of the brush applies from the next step.
   */
  void SetBrush(vtkOFBBrush* brush);
  vtkOFBBrush* GetBrush() const;
  ///@}

  ///@{
  /**
   * Whether the particles paint (default on).
   */
  vtkSetMacro(Paint, bool);
  vtkGetMacro(Paint, bool);
  vtkBooleanMacro(Paint, bool);
  ///@}

  ///@{
  /**
   * Periodic colour mode: steps of one period (default 60).
   */
  vtkSetClampMacro(ColorPeriod, int, 1, VTK_INT_MAX);
  vtkGetMacro(ColorPeriod, int);
  ///@}

  ///@{
  /**
   * FromSeeds colour mode: the seed point array (default none: the active scalars).
   */
  vtkSetStringMacro(SeedColorArrayName);
  vtkGetStringMacro(SeedColorArrayName);
  ///@}

  ///@{
  /**
   * ByScalar colour mode: the surface point array and the lookup table (default
   * none: blue to red over the array's range).
   */
  vtkSetStringMacro(ScalarArrayName);
  vtkGetStringMacro(ScalarArrayName);
  void SetLookupTable(vtkScalarsToColors* lut);
  vtkGetObjectMacro(LookupTable, vtkScalarsToColors);
  ///@}

  ///@{
  /**
   * Positions kept in each particle's trail (default 16; at least 2).
   */
  vtkSetClampMacro(TrailLength, int, 2, 1000000);
  vtkGetMacro(TrailLength, int);
  ///@}

  ///@{
  /**
   * Most memory the particles may take, in MiB (default 4096): the seeds times
   * ChainLength particles, each with its state and a trail of TrailLength positions,
   * and their output. The advector estimates it before it allocates the particles and
   * fails with an error (no particles, empty outputs) when the estimate exceeds the
   * limit, rather than running out of memory.
   */
  vtkSetClampMacro(MemoryLimit, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MemoryLimit, vtkIdType);
  ///@}

  /**
   * Modification time including the brush's.
   */
  vtkMTimeType GetMTime() override;

  /**
   * Advance StepsPerUpdate steps now (updating the inputs first) and update the
   * outputs.
   */
  void Step();

  /**
   * Put the particles back at their seeds on the next update.
   */
  void Reset();

  /**
   * Steps made since the seeds.
   */
  vtkIdType GetCurrentStep() const;

  /**
   * The footprints of the last step as given to the painter: a point per
   * footprint with "Radius" (world units), "Color" (RGBA float), "Strength" and,
   * with smear, "PreviousPosition".
   */
  vtkPolyData* GetFootprints();

  /**
   * The size of a cell in world units used by the last update.
   */
  double GetCellSize() const;

  ///@{
  /**
   * Wall-clock time (ms) the last update spent moving the particles, painting
   * their footprints (filling the footprint arrays and the painter's Dabs call)
   * and building the three outputs, as vtkOFBSampler::GetLastBuildTime and
   * vtkOFBLIC::GetLastExecutionTime. For benchmarks and profiling.
   */
  double GetLastAdvectionTime() const;
  double GetLastPaintingTime() const;
  double GetLastOutputTime() const;
  ///@}

  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

protected:
  vtkOFBParticleAdvector();
  ~vtkOFBParticleAdvector() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  virtual int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  /// An unsteady input is asked for the time step at or after the requested time.
  virtual int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  virtual int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  ///@{
  /**
   * The steps of RequestData (see the .cxx).
   */
  bool CheckSettings();
  /// The surface, field and OFB prepared, the particles started when needed (false:
  /// no output this time).
  bool PrepareUpdate(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkDataSet* seeds,
    bool& restart);
  /// The step to go to (false, particles stopped: no output).
  bool PlanSteps(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector,
    vtkDataSet* seeds,
    bool restart,
    vtkIdType& target);
  /// Pathlines: the time this execution goes to (Goal), the next one asked for.
  bool PlanPathlineSteps(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector,
    vtkDataSet* seeds,
    bool restart);
  /// The steps up to `target` (every process's most), the footprints painted.
  void AdvanceTo(vtkIdType target);
  /// The painted OFB, the particles and trails, and their time.
  void WriteOutputs(vtkInformationVector* outputVector);
  /// No particles until they start again.
  void StopParticles();
  ///@{
  /**
   * Pathlines through an unsteady input (vtkOFBParticleAdvectorTime.cxx): whether
   * port 0 reports TIME_STEPS; a hash of a surface's points and cells; keep the
   * field of a new time step (the newer of the two around the particles' time);
   * the steps from the particles' time to `time` (their duration in the
   * internals); the field and stepper of step k.
   */
  bool IsUnsteady(vtkInformationVector** inputVector) const;
  static uint64_t HashGeometry(vtkPolyData* surface);
  void KeepField(vtkPolyData* surface, vtkDataArray* vectors, bool rebuilt);
  vtkIdType PlanUnsteadySteps(double time);
  void PrepareUnsteadyStep(vtkIdType k);
  ///@}
  bool PrepareSurface(vtkPolyData* surface, vtkInformationVector** inputVector, bool& rebuilt);
  /// The surface's vector field and its association, checked (null, with an error, if none).
  vtkDataArray* FindSurfaceVectors(vtkPolyData* surface,
    vtkInformationVector** inputVector,
    int& association);
  /// The walker, owned triangles and locator of the surface's triangles.
  bool BuildWalker(vtkPolyData* surface, vtkDataArray* vectors, bool perCell);
  /// The distance (world units) under which points are one point of the surface.
  static double MergeTolerance(vtkPolyData* surface);
  bool PrepareOFB(vtkOFB* inputOFB, vtkPolyData* surface);
  bool NeedsRestart(vtkDataSet* seeds);
  /// False, with an error, when the particles would exceed MemoryLimit.
  bool StartParticles(vtkDataSet* seeds);
  /// StartParticles' checks (false with an error), then the start once they passed.
  bool CheckStart(vtkDataSet* seeds);
  bool StartCheckedParticles(vtkDataSet* seeds);
  void LocateSeeds(vtkDataSet* seeds);
  void PrepareColoring(vtkPolyData* surface);
  void PaintFootprints();
  void ClearFootprints();
  void FillParticles(vtkPolyData* output);
  void FillTrails(vtkPolyData* output);
  ///@}

  /// The step that the outputs' time request asks for (steady particles), else `otherwise`.
  static vtkIdType RequestedStep(vtkInformationVector* outputVector, vtkIdType otherwise);
  /// The time that the outputs' time request asks for, else `otherwise`.
  static double RequestedTime(vtkInformationVector* outputVector, double otherwise);

  ///@{
  /**
   * Distributed runs (vtkOFBParticleAdvectorDistributed.cxx), with Exchange set: the
   * triangles this process owns (not ghost cells), the seeds located over every
   * process (each seed's owner: the process whose own triangle is closest), and after
   * each step the particles' states sent to every process and the particles that left
   * this process's triangles handed to their new owner. Whether this process outputs
   * particle i (always without Exchange).
   */
  void FindOwnedTriangles(vtkPolyData* surface, const std::vector<vtkIdType>& polygonCells);
  bool LocateSeedsOverProcesses(vtkDataSet* seeds);
  void ExchangeParticles();
  /// ExchangeParticles' steps: the states of the other processes' particles taken from
  /// `all` (every process's records), the records of those that left their process's
  /// triangles into `leaving`; those handed to the processes that own where they are.
  void ReceiveStates(const std::vector<double>& all, std::vector<vtkIdType>& leaving);
  void HandOff(const std::vector<double>& all, const std::vector<vtkIdType>& leaving);
  bool OutputsParticle(vtkIdType i) const;
  /**
   * Whether the ghost cells of every process's piece reach a step beyond its own
   * triangles: when they do not, and a piece can grow, RequiredGhostLevels is raised
   * and the pipeline asked to execute again (CONTINUE_EXECUTING), and true is
   * returned (the caller outputs nothing this time). A collective call: `hasPiece`
   * false for a process with an empty piece.
   */
  bool AskForDeeperGhostCells(vtkInformation* request,
    vtkInformationVector** inputVector,
    bool hasPiece);
  /// The edges where this process's piece ends (PieceBorder), after FindOwnedTriangles.
  void FindPieceBorder();
  /// Whether no triangle this process owns is within `reach` of where its piece ends.
  bool GhostCellsCover(double reach);
  /**
   * The collective calls of one update, for a process whose piece is empty (it has no
   * particles): the restart agreement, the start (seeds located over every process),
   * with an `unsteady` input the pathlines' plan, the number of steps and each step's
   * exchange, as the other processes make them.
   */
  void ParticipateWithoutPiece(vtkInformation* request,
    vtkDataSet* seeds,
    vtkInformationVector* outputVector,
    bool unsteady);
  /// StartParticles's collective calls, for a process whose piece is empty.
  bool StartWithoutPiece(vtkDataSet* seeds);
  /**
   * PlanPathlineSteps's and PlanUnsteadySteps's collective calls, for a process whose
   * piece is empty: the plan of the others (the time the particles go to, the input
   * step read, whether the pipeline executes again) taken from them.
   */
  bool PlanPathlineWithoutPiece(vtkInformation* request,
    vtkDataSet* seeds,
    vtkInformationVector* outputVector);
  /**
   * Of the triangles through the point `x` (within 1e-9 cells; `cell` is one of them),
   * the one with the smallest centroid (x, then y, then z), among the owned ones when
   * `ownedOnly`: a seed on an edge or a vertex starts on the same triangle whatever
   * the order of the triangles. Its centroid into `centroid`.
   */
  vtkIdType CanonicalTriangle(const double x[3],
    vtkIdType cell,
    bool ownedOnly,
    double centroid[3]);
  ///@}

  /**
   * The collective calls of a distributed run (see vtkOFBParticleExchange); null (the
   * default) for one process. Set by vtkOFBPParticleAdvector for its RequestData.
   */
  vtkOFBParticleExchange* Exchange = nullptr;

  /// Particles that left their process's triangles (on any process), counted by
  /// ExchangeParticles.
  vtkIdType NumberOfHandOffs = 0;

  /// Distributed runs: the ghost levels of the surface that a step needs, at least (0
  /// until a piece's ghost cells were found shallower than a step; never lowered).
  int RequiredGhostLevels = 0;

  vtkOFB* OFB;
  vtkScalarsToColors* LookupTable;
  int Integrator;
  double StepSize;
  double ErrorTolerance;
  bool NormalizeVectors;
  int Direction;
  int StepsPerUpdate;
  int Lifetime;
  vtkIdType NumberOfParticles;
  unsigned int RandomSeed;
  double MaximumSeedDistance;
  int ChainLength;
  int ChainSpacing;
  int ColorMode;
  double Color[3];
  double FootprintRadius;
  vtkSmartPointer<vtkOFBBrush> Brush;
  bool Paint;
  int ColorPeriod;
  char* SeedColorArrayName;
  char* ScalarArrayName;
  int TrailLength;
  vtkIdType MemoryLimit;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

private:
  vtkOFBParticleAdvector(const vtkOFBParticleAdvector&) = delete;
  void operator=(const vtkOFBParticleAdvector&) = delete;
};

#endif
