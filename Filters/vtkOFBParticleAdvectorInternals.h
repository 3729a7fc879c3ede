// The state of vtkOFBParticleAdvector between updates (private; shared by its two
// source files).
#ifndef vtkOFBParticleAdvectorInternals_h
#define vtkOFBParticleAdvectorInternals_h

#include "vtkOFBParticleAdvector.h"
#include "vtkOFBParticleSystem.h"
#include "vtkSmartPointer.h"

#include <string>

class vtkOFBBrush;
class vtkOFBPainter;
class vtkStaticCellLocator;

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
  vtkSmartPointer<vtkOFB> Copy; // the painted copy of the port-1 OFB
  vtkSmartPointer<vtkOFBPainter> Painter;
  vtkSmartPointer<vtkOFBBrush> Brush;
  vtkSmartPointer<vtkPolyData> Footprints;
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
  vtkOFBParticleSystem::Coloring Coloring;
  vtkSmartPointer<vtkDataArray> ScalarArray;
};

#endif
