// Private header of vtkOFBLIC: its internals, what it keeps between updates (the cache)
// and the convolution passes over it (vtkOFBLICConvolve.cxx).
#ifndef vtkOFBLICInternals_h
#define vtkOFBLICInternals_h

#include "vtkOFBLIC.h"
#include "vtkOFBLICCache.h"
#include "vtkOFBLICTracer.h"
#include "vtkType.h"

#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

/**
 * What one convolution pass (vtkOFBLIC::vtkInternals::Convolve) reads while it gathers
 * the samples of a tile: the tracer and tiles, whether the streamlines are kept (else each
 * sample traces its own), the kernel (as parts with their moments, Animate on, or as
 * weights), the mask, where each sample's window starts in its tile's runs, and the
 * input and output values.
 */
struct vtkOFBLICPass
{
  const vtkOFBLICTracer* Tracer;
  const vtkOFBLICTiles* Tiles;
  bool Keep;
  const vtkOFBLICKernelParts* Parts;
  vtkOFBLICMoments* Moments;
  const double* Weights;
  double InverseTotal;
  int Steps;
  const unsigned char* Mask;
  const vtkTypeInt32* Where;
  const float* Input;
  float* Output;
};

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

  /// Another phase from the kept moments, without reading the runs (Convolve's
  /// `recombine`). False when aborted.
  bool Recombine(vtkOFBLIC* self,
    const vtkOFBLICKernelParts& parts,
    const float* input,
    float* output,
    double progress1);

  /// Before fast LIC traces: the per-sample and per-tile buffers sized, the kept run
  /// stores emptied and listed in `freeStores`.
  void ResetRuns(vtkIdType numberOfTiles, std::vector<vtkOFBLICRunStore*>& freeStores);

  /// A run store for a thread: a free one, else a new one with room for `steps` + 8 ids
  /// a sample.
  vtkOFBLICRunStore* TakeStore(std::vector<vtkOFBLICRunStore*>& freeStores,
    std::mutex& storesMutex,
    int steps);

  /**
   * Eq. 4 at every sample of tile t: along its window in the tile's `runs` (`length`
   * ids; `values`: the input copied in the runs' order, or null to read it through the
   * ids), or, streamlines not kept, along its own streamline traced into `line`.
   */
  void GatherTile(const vtkOFBLICPass& pass,
    vtkIdType t,
    const vtkTypeInt32* runs,
    vtkIdType length,
    const float* values,
    vtkTypeInt32* line);

  /// TraceTile into `store` (emptied first without `keepRuns`), where the tile's runs
  /// start into `start` and their length into the cache; returns the first run id.
  const vtkTypeInt32* TraceTileRuns(const vtkOFBLICTracer& tracer,
    const vtkOFBLICTiles& tiles,
    vtkIdType t,
    vtkOFBLICRunStore& store,
    bool keepRuns,
    std::vector<vtkTypeInt32>& line,
    std::pair<vtkOFBLICRunStore*, std::size_t>& start);

  /// Tile t's runs (`length` ids from `start`) reduced to the ids that the windows of
  /// `keepSteps` steps each way read (a kept second pass's); `places` is a work buffer.
  void CompactTileRuns(const vtkOFBLICTiles& tiles,
    vtkIdType t,
    int keepSteps,
    vtkIdType length,
    const std::pair<vtkOFBLICRunStore*, std::size_t>& start,
    std::vector<vtkTypeInt32>& places);

  /// After fast LIC traced: the runs kept (where each tile's start, `runSteps` steps each
  /// way of every window) or, without `keepRuns`, dropped.
  void KeepRuns(bool keepRuns,
    int runSteps,
    const std::vector<std::pair<vtkOFBLICRunStore*, std::size_t>>& tileStart);

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
