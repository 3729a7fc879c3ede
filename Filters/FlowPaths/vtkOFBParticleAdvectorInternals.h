// The state of vtkOFBParticleAdvector between updates (private; shared by its two
// source files).
#ifndef vtkOFBParticleAdvectorInternals_h
#define vtkOFBParticleAdvectorInternals_h

#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleSystem.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

class vtkCellArray;
class vtkDoubleArray;
class vtkFloatArray;
class vtkIdTypeArray;
class vtkIntArray;
class vtkOFBPainter;
class vtkPoints;
class vtkStaticCellLocator;
class vtkUnsignedCharArray;

/// The arrays of the footprints and outputs, kept from step to step so that a
/// step allocates nothing once their sizes are reached.
struct vtkOFBParticleArrays
{
  vtkOFBParticleArrays();
  ~vtkOFBParticleArrays();
  // Footprints.
  vtkSmartPointer<vtkPoints> DabPoints;
  vtkSmartPointer<vtkDoubleArray> DabRadius;
  vtkSmartPointer<vtkFloatArray> DabColor;
  vtkSmartPointer<vtkDoubleArray> DabStrength;
  vtkSmartPointer<vtkDoubleArray> DabPrevious;
  // Particles.
  vtkSmartPointer<vtkPoints> Points;
  vtkSmartPointer<vtkCellArray> Verts;
  vtkSmartPointer<vtkIdTypeArray> VertOffsets;
  vtkSmartPointer<vtkIdTypeArray> VertConnectivity;
  vtkSmartPointer<vtkDoubleArray> Velocity;
  vtkSmartPointer<vtkIntArray> Age;
  vtkSmartPointer<vtkIdTypeArray> Ids;
  vtkSmartPointer<vtkIntArray> Chain;
  vtkSmartPointer<vtkUnsignedCharArray> Color;
  // Trails.
  vtkSmartPointer<vtkPoints> TrailPoints;
  vtkSmartPointer<vtkCellArray> Lines;
  vtkSmartPointer<vtkIdTypeArray> LineOffsets;
  vtkSmartPointer<vtkIdTypeArray> LineConnectivity;
  vtkSmartPointer<vtkIdTypeArray> TrailIds;
};

/// Everything that places or moves particles: a change restarts them.
struct vtkOFBParticleMotionKey
{
  int Integrator;
  double StepSize;
  double ErrorTolerance;
  bool NormalizeVectors;
  int Direction;
  int Lifetime;
  vtkIdType NumberOfParticles;
  unsigned int RandomSeed;
  double MaximumSeedDistance;
  int ChainLength;
  int ChainSpacing;
  int TrailLength;
  std::string SeedColorArrayName;
  bool operator==(const vtkOFBParticleMotionKey& o) const
  {
    return this->Integrator == o.Integrator && this->StepSize == o.StepSize &&
      this->ErrorTolerance == o.ErrorTolerance && this->NormalizeVectors == o.NormalizeVectors &&
      this->Direction == o.Direction && this->Lifetime == o.Lifetime &&
      this->NumberOfParticles == o.NumberOfParticles && this->RandomSeed == o.RandomSeed &&
      this->MaximumSeedDistance == o.MaximumSeedDistance && this->ChainLength == o.ChainLength &&
      this->ChainSpacing == o.ChainSpacing && this->TrailLength == o.TrailLength &&
      this->SeedColorArrayName == o.SeedColorArrayName;
  }
};

class vtkOFBParticleAdvector::vtkInternals
{
public:
  vtkOFBTriangleWalker Walker;
  vtkOFBParticleSystem System;
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  vtkSmartPointer<vtkOFB> Copy;           // the painted copy of the port-1 OFB
  vtkSmartPointer<vtkOFBPainter> Painter; // paints with the advector's brush
  vtkSmartPointer<vtkPolyData> Footprints;
  vtkOFBParticleArrays Arrays;
  vtkSmartPointer<vtkPolyData> Surface; // the input's triangles
  double CellSize = 0.0;
  bool Started = false;
  bool ResetRequested = false;
  vtkIdType PendingSteps = 0;
  vtkOFBParticleMotionKey Motion{};
  // What the walker and the particles were made from.
  vtkPolyData* SurfaceObject = nullptr;
  vtkMTimeType SurfaceTime = 0;
  vtkDataArray* VectorArray = nullptr;
  vtkMTimeType VectorTime = 0;
  vtkDataObject* SeedObject = nullptr;
  vtkMTimeType SeedTime = 0;
  vtkDataObject* OFBObject = nullptr;
  vtkMTimeType OFBTime = 0;
  vtkOFB* Target = nullptr; // the OFB painted (held, the copy, or none)
  vtkOFB* LastTarget = nullptr;
  double LastCellSize = 0.0;
  bool TargetChanged = false;
  // Distributed runs: per walker triangle, 1 where this process owns it; per particle,
  // 1 where this process advances and outputs it.
  std::vector<unsigned char> TriangleOwned;
  std::vector<unsigned char> Owned;
  std::vector<unsigned char> SeedOwned; // per seed, 1 where this process owns it
  // The edges where this process's piece ends (walker triangle, edge): the boundary
  // edges of its outermost ring of ghost triangles. The reach (world units) last
  // checked against them, and whether the ghost cells cover it; the ghost levels and
  // triangles of the piece at that check.
  std::vector<std::pair<vtkIdType, int>> PieceBorder;
  double CheckedReach = -1.0;
  bool CoversReach = true;
  int CheckedLevels = -1;
  vtkIdType CheckedTriangles = -1;
  vtkOFBParticleSystem::Coloring Coloring;
  // Wall-clock milliseconds of the last update's parts.
  double AdvectionTime = 0.0;
  double PaintingTime = 0.0;
  double OutputTime = 0.0;
  std::vector<vtkIdType> Slots; // where each particle's output starts (kept between steps)
  // An unsteady input (TIME_STEPS on port 0): the fields (3 per point) of the two
  // time steps around the particles' time, their times and largest speeds.
  bool Unsteady = false;
  bool FieldPerCell = false; // the field is a cell array (3 per cell), else per point
  uint64_t GeometryHash = 0;
  std::vector<double> FieldOld, FieldNew, Blend;
  double TimeOld = 0.0, TimeNew = 0.0;
  double SpeedOld = 0.0, SpeedNew = 0.0;
  double ParticleTime = 0.0; // the time the particles are at
  double StepDuration = 0.0; // of the steps of this update
  double StepSpeed = 0.0;    // the largest speed of the two fields (of all processes)
  double Goal = 0.0;         // the time this execution takes the particles to
  vtkSmartPointer<vtkDataArray> ScalarArray;
};

#endif
