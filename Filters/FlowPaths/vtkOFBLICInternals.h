// Private header of vtkOFBLIC: its internals, what it keeps between updates (the cache)
// and the convolution passes over it (vtkOFBLICConvolve.cxx).
#ifndef vtkOFBLICInternals_h
#define vtkOFBLICInternals_h

#include "vtkOFBLIC.h"
#include "vtkOFBLICCache.h"
#include "vtkOFBLICTracer.h"
#include "vtkType.h"

#include <vector>

struct vtkOFBLIC::vtkInternals
{
  vtkOFBLICCache Cache;

  /**
   * One convolution of `input` into `output` over all samples, tile by tile, with the
   * progress of `self` from `progress0` to `progress1`. With `keep`, each sample's
   * streamline is read from the kept runs of fast LIC, traced first (TraceTile) when
   * `trace` is true; else every sample traces its own. Without `keepRuns` the runs
   * traced are read tile by tile and not kept (only the moments of `parts` are); with
   * `keepSteps` in [1, NumberOfSteps) they are kept only where a sample's window of
   * `keepSteps` steps each way reads them (the second pass of an animated EnhancedLIC,
   * whose first pass reads the moments). With
   * `parts` (kept runs, Animate
   * on), each sample's vtkOFBLICMoments are gathered into the cache (or, with
   * `recombine`, taken from it without reading the runs) and combined for the phase of
   * `parts`; `weights` is then not used. False when aborted.
   */
  bool Convolve(vtkOFBLIC* self,
    const vtkOFBLICTracer& tracer,
    bool keep,
    bool trace,
    bool keepRuns,
    int keepSteps,
    const std::vector<double>& weights,
    const vtkOFBLICKernelParts* parts,
    bool recombine,
    const float* input,
    float* output,
    double progress0,
    double progress1);

  /**
   * The streamlines of the samples of one tile (fast LIC): from each sample not yet
   * given one, a seed streamline of up to LongSteps NumberOfSteps steps each way is
   * traced (each way stopping early once its last NumberOfSteps samples are of other
   * tiles, already given one or passed too far aside) and appended to `store` as a run;
   * every sample of the tile it passes within ReuseDistance across the flow gets the window
   * of NumberOfSteps steps each way around that meeting:
   * `where` receives the meeting's place in the runs of the tile, `covered` marks it.
   * `sequence` is a buffer of 2 LongSteps NumberOfSteps + 1 ids.
   */
  void TraceTile(const vtkOFBLICTracer& tracer,
    const vtkOFBLICTiles& tiles,
    vtkIdType tile,
    vtkOFBLICRunStore& store,
    unsigned char* covered,
    vtkTypeInt32* where,
    vtkTypeInt32* sequence);
};

#endif
