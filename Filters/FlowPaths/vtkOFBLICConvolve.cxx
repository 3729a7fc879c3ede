// vtkOFBLIC's convolution (Eq. 4): the tiled fast LIC that traces seed streamlines and
// keeps them (TraceTile), and the gather along the kept streamlines (Convolve).
#include "vtkOFBLIC.h"

#include "vtkOFB.h"
#include "vtkOFBLICInternals.h"
#include "vtkOFBLICTracer.h"
#include "vtkOFBPrefetch.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <mutex>
#include <thread>
#include <vector>

namespace
{
// The most steps each way of a seed streamline of fast LIC, in NumberOfSteps: each gives
// the streamlines of the samples of its tile that it meets, and stops earlier once it
// meets no sample it can give one (see TraceTile).
constexpr int LongSteps = 10;

/**
 * Progress and abort of one parallel loop over tiles: the thread that called Update
 * sends the progress events (in steps of about 1 % of the loop) and reads AbortExecute
 * after each of its tiles (observers run where they would outside the loop); the other
 * threads see the abort through Aborted() and skip their remaining tiles.
 */
class TileProgress
{
public:
  TileProgress(vtkAlgorithm* algorithm, vtkIdType tiles, double from, double to)
    : Algorithm(algorithm)
    , Tiles(tiles)
    , From(from)
    , To(to)
    , Caller(std::this_thread::get_id())
  {
  }

  bool Aborted() const { return this->Abort.load(std::memory_order_relaxed); }

  void TileDone()
  {
    const vtkIdType done = ++this->Done;
    if (std::this_thread::get_id() != this->Caller)
    {
      return;
    }
    if (100 * done / this->Tiles > 100 * this->Reported / this->Tiles)
    {
      this->Reported = done;
      this->Algorithm->UpdateProgress(this->From + (this->To - this->From) * done / this->Tiles);
    }
    if (this->Algorithm->GetAbortExecute())
    {
      this->Abort = true;
    }
  }

private:
  vtkAlgorithm* Algorithm;
  vtkIdType Tiles;
  double From;
  double To;
  std::thread::id Caller;
  std::atomic<vtkIdType> Done{ 0 };
  std::atomic<bool> Abort{ false };
  vtkIdType Reported = 0; // read and written by the calling thread only
};

/**
 * The `length` ids of tile t's runs (ids[0] is the -1 before the first run) reduced in
 * place to those that the window of `steps` steps each way of one of the tile's samples
 * reads (as GatherRun does: up to a -1), a -1 for each gap: no window reaches a gap, so
 * none ends earlier. The samples' places (`where`) are moved with their ids; `places` is
 * a work buffer. Returns the new length.
 */
vtkIdType CompactRuns(const vtkOFBLICTiles& tiles,
  vtkIdType t,
  const unsigned char* mask,
  int steps,
  vtkTypeInt32* ids,
  vtkIdType length,
  vtkTypeInt32* where,
  std::vector<vtkTypeInt32>& places)
{
  // places[k]: 1 where a window reads id k, then its new place.
  places.assign(length, 0);
  tiles.ForEachSample(t,
    [&](vtkIdType i)
    {
      if (mask[i])
      {
        return;
      }
      const vtkIdType at = where[i];
      places[at] = 1;
      for (vtkIdType s = 1; s <= steps && ids[at + s] >= 0; ++s)
      {
        places[at + s] = 1;
      }
      for (vtkIdType s = 1; s <= steps && ids[at - s] >= 0; ++s)
      {
        places[at - s] = 1;
      }
    });
  vtkIdType out = 1; // ids[0] stays -1
  for (vtkIdType k = 1; k < length; ++k)
  {
    if (ids[k] >= 0 && places[k])
    {
      places[k] = static_cast<vtkTypeInt32>(out);
      ids[out++] = ids[k];
    }
    else if (ids[out - 1] >= 0)
    {
      ids[out++] = -1;
    }
  }
  if (ids[out - 1] >= 0)
  {
    ids[out++] = -1;
  }
  tiles.ForEachSample(t,
    [&](vtkIdType i)
    {
      if (!mask[i])
      {
        where[i] = places[where[i]];
      }
    });
  return out;
}
/**
 * The input values of a tile's `length` run ids copied in the runs' order into `values`
 * (0 at the -1 between runs), so that each window is read contiguously: for runs traced
 * just now (their ids were just written, the values not yet read). Kept runs (a second
 * pass, a re-convolution) are read through the ids instead: the tile's input stays in
 * the cache, and a copy would read and write every id of the runs, most of them more
 * than once.
 */
const float* CopyRunValues(const vtkTypeInt32* runs,
  vtkIdType length,
  const float* input,
  std::vector<float>& values)
{
  values.resize(std::max<std::size_t>(values.size(), length));
  for (vtkIdType k = 0; k < length; ++k)
  {
    values[k] = runs[k] >= 0 ? input[runs[k]] : 0.0f;
  }
  return values.data();
}
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::vtkInternals::Convolve(vtkOFBLIC* self,
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
  double progress1)
{
  vtkOFBLICCache& cache = this->Cache;
  parts = keep ? parts : nullptr;
  recombine = recombine && parts && !trace;
  if (parts && !recombine)
  {
    cache.Moments.resize(cache.Mask.size());
  }
  vtkOFBLICMoments* moments = parts ? cache.Moments.data() : nullptr;
  if (recombine)
  {
    return this->Recombine(self, *parts, input, output, progress1);
  }
  const unsigned char* mask = cache.Mask.data();
  const int steps = tracer.NumberOfSteps;
  const double* w = weights.data();
  const double inverseTotal = vtkOFBLICTracer::InverseTotal(w, steps);
  vtkOFBLICTiles tiles(
    tracer.Dimensions, tracer.Origin, tracer.CellSize, tracer.OFB->GetNumberOfSamples());
  tiles.First = cache.TileFirst.data();
  tiles.Ids = cache.TileIds.data();
  const vtkIdType numberOfTiles = tiles.GetNumberOfTiles();
  const bool fast = keep && trace;
  // Fast LIC: each thread appends the seed streamlines of its tiles to a store of its
  // own (the stores of an earlier tracing are reused); where a tile's runs start is
  // known once every tile is traced (stores grow).
  std::vector<vtkOFBLICRunStore*> freeStores;
  std::vector<std::pair<vtkOFBLICRunStore*, std::size_t>> tileStart;
  std::mutex storesMutex;
  if (fast)
  {
    this->ResetRuns(numberOfTiles, freeStores);
    tileStart.assign(numberOfTiles, { nullptr, 0 });
  }
  const vtkOFBLICPass pass = { &tracer,
    &tiles,
    keep,
    parts,
    moments,
    w,
    inverseTotal,
    steps,
    mask,
    cache.Where.data(),
    input,
    output };
  vtkSMPThreadLocal<vtkOFBLICRunStore*> localStore(nullptr);
  vtkSMPThreadLocal<std::vector<vtkTypeInt32>> localLine;
  vtkSMPThreadLocal<std::vector<float>> localValues; // a tile's run values
  // Runs kept only around the windows of keepSteps steps (see Compact below).
  const bool compact = fast && keepRuns && keepSteps > 0 && keepSteps < steps;
  vtkSMPThreadLocal<std::vector<vtkTypeInt32>> localPlaces;
  // One parallel loop over all tiles: loops over blocks of tiles would each wait for
  // their slowest tile.
  TileProgress progress(self, numberOfTiles, progress0, progress1);
  vtkSMPTools::For(0,
    numberOfTiles,
    1,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkTypeInt32>& local = localLine.Local();
      local.resize(std::max(2 * steps, 2 * LongSteps * steps + 1));
      vtkOFBLICRunStore*& store = localStore.Local();
      if (fast && !store)
      {
        store = this->TakeStore(freeStores, storesMutex, steps);
      }
      for (vtkIdType t = begin; t < end && !progress.Aborted(); ++t)
      {
        const vtkTypeInt32* runs = keep ? cache.TileRuns[t] : nullptr;
        if (fast && tiles.First[t] < tiles.First[t + 1])
        {
          runs = this->TraceTileRuns(tracer, tiles, t, *store, keepRuns, local, tileStart[t]);
        }
        // The tile's input values first (tracing did not touch them).
        tiles.ForEachSample(t, [&](vtkIdType i) { VTKOFB_PREFETCH(input + i); });
        const vtkIdType length = runs ? cache.TileRunLengths[t] : 0;
        const float* values =
          runs && trace ? CopyRunValues(runs, length, input, localValues.Local()) : nullptr;
        this->GatherTile(pass, t, runs, length, values, local.data());
        if (compact && runs)
        {
          this->CompactTileRuns(tiles, t, keepSteps, length, tileStart[t], localPlaces.Local());
        }
        progress.TileDone();
      }
    });
  if (progress.Aborted() || self->GetAbortExecute())
  {
    return false;
  }
  self->UpdateProgress(progress1);
  if (fast)
  {
    this->KeepRuns(keepRuns, compact ? keepSteps : steps, tileStart);
  }
  return true;
}

//------------------------------------------------------------------------------
const vtkTypeInt32* vtkOFBLIC::vtkInternals::TraceTileRuns(const vtkOFBLICTracer& tracer,
  const vtkOFBLICTiles& tiles,
  vtkIdType t,
  vtkOFBLICRunStore& store,
  bool keepRuns,
  std::vector<vtkTypeInt32>& line,
  std::pair<vtkOFBLICRunStore*, std::size_t>& start)
{
  if (!keepRuns)
  {
    // The tile's runs are read right away and then dropped: the store is this thread's
    // scratch, the same pages (in the cache) for every tile.
    store.Ids.resize(0);
  }
  start = { &store, store.size() };
  this->TraceTile(
    tracer, tiles, t, store, this->Cache.Covered.data(), this->Cache.Where.data(), line.data());
  this->Cache.TileRunLengths[t] = static_cast<vtkIdType>(store.size() - start.second);
  return store.Ids.data() + start.second;
}

//------------------------------------------------------------------------------
void vtkOFBLIC::vtkInternals::CompactTileRuns(const vtkOFBLICTiles& tiles,
  vtkIdType t,
  int keepSteps,
  vtkIdType length,
  const std::pair<vtkOFBLICRunStore*, std::size_t>& start,
  std::vector<vtkTypeInt32>& places)
{
  // The runs' ids that no window of keepSteps steps reads are dropped, in place: the
  // tile's next runs go right after (fewer pages touched), and a later pass reads fewer
  // ids.
  vtkOFBLICCache& cache = this->Cache;
  vtkOFBLICRunStore& store = *start.first;
  vtkTypeInt32* ids = store.Ids.data() + start.second;
  const vtkIdType kept =
    CompactRuns(tiles, t, cache.Mask.data(), keepSteps, ids, length, cache.Where.data(), places);
  cache.TileRunLengths[t] = kept;
  store.Ids.resize(start.second + kept);
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::vtkInternals::Recombine(vtkOFBLIC* self,
  const vtkOFBLICKernelParts& parts,
  const float* input,
  float* output,
  double progress1)
{
  // Another phase: the kept moments combined in the order of the samples, no run read.
  const vtkOFBLICCache& cache = this->Cache;
  const vtkIdType n = static_cast<vtkIdType>(cache.Mask.size());
  const unsigned char* masked = cache.Mask.data();
  const vtkOFBLICMoments* moments = cache.Moments.data();
  vtkSMPTools::For(0,
    n,
    1 << 16,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        output[i] = masked[i] ? input[i] : parts.Combine(moments[i], input[i]);
      }
    });
  if (self->GetAbortExecute())
  {
    return false;
  }
  self->UpdateProgress(progress1);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBLIC::vtkInternals::ResetRuns(vtkIdType numberOfTiles,
  std::vector<vtkOFBLICRunStore*>& freeStores)
{
  vtkOFBLICCache& cache = this->Cache;
  cache.Covered.resize(cache.Mask.size());
  cache.Where.resize(cache.Mask.size());
  cache.TileRuns.assign(numberOfTiles, nullptr);
  cache.TileRunLengths.assign(numberOfTiles, 0);
  for (auto& store : cache.Runs)
  {
    store->Ids.resize(0);
    freeStores.push_back(store.get());
  }
}

//------------------------------------------------------------------------------
vtkOFBLICRunStore* vtkOFBLIC::vtkInternals::TakeStore(std::vector<vtkOFBLICRunStore*>& freeStores,
  std::mutex& storesMutex,
  int steps)
{
  vtkOFBLICCache& cache = this->Cache;
  std::lock_guard<std::mutex> lock(storesMutex);
  if (freeStores.empty())
  {
    // Room for the runs of all samples at NumberOfSteps + 8 ids a sample (the horse and
    // the bunny need about 1.05 NumberOfSteps + 1): mapped, not touched, so growing
    // never copies in practice and only the pages used are faulted in.
    cache.Runs.emplace_back(new vtkOFBLICRunStore);
    cache.Runs.back()->Ids.reserve((steps + 8) * cache.Mask.size() + 4096);
    freeStores.push_back(cache.Runs.back().get());
  }
  vtkOFBLICRunStore* store = freeStores.back();
  freeStores.pop_back();
  return store;
}

//------------------------------------------------------------------------------
void vtkOFBLIC::vtkInternals::GatherTile(const vtkOFBLICPass& pass,
  vtkIdType t,
  const vtkTypeInt32* runs,
  vtkIdType length,
  const float* values,
  vtkTypeInt32* line)
{
  const int steps = pass.Steps;
  const double* w = pass.Weights;
  const double inverseTotal = pass.InverseTotal;
  const float* input = pass.Input;
  float* output = pass.Output;
  pass.Tiles->ForEachSample(t,
    [&](vtkIdType i)
    {
      if (pass.Mask[i])
      {
        output[i] = input[i];
        return;
      }
      if (!pass.Keep)
      {
        pass.Tracer->Trace(i, line);
        output[i] = vtkOFBLICTracer::Gather(i, line, steps, w, inverseTotal, input);
        return;
      }
      const vtkIdType at = pass.Where[i];
      const vtkOFBLICTracer::ThroughIds ids{ runs + at, input };
      if (pass.Parts)
      {
        if (values)
        {
          pass.Parts->Gather(runs + at, values + at, pass.Moments[i]);
        }
        else
        {
          pass.Parts->Gather(runs + at, ids, pass.Moments[i]);
        }
        output[i] = pass.Parts->Combine(pass.Moments[i], input[i]);
        return;
      }
      const bool inside = at >= steps && at + steps < length;
      if (values)
      {
        const float* v = values + at;
        if (!inside ||
          !vtkOFBLICTracer::GatherWhole(runs + at, v, steps, w, inverseTotal, output[i]))
        {
          output[i] = vtkOFBLICTracer::GatherRun(runs + at, v, steps, w, inverseTotal);
        }
      }
      else if (!inside ||
        !vtkOFBLICTracer::GatherWhole(runs + at, ids, steps, w, inverseTotal, output[i]))
      {
        output[i] = vtkOFBLICTracer::GatherRun(runs + at, ids, steps, w, inverseTotal);
      }
    });
}

//------------------------------------------------------------------------------
void vtkOFBLIC::vtkInternals::KeepRuns(bool keepRuns,
  int runSteps,
  const std::vector<std::pair<vtkOFBLICRunStore*, std::size_t>>& tileStart)
{
  vtkOFBLICCache& cache = this->Cache;
  if (!keepRuns)
  {
    std::vector<const vtkTypeInt32*>().swap(cache.TileRuns);
    std::vector<vtkIdType>().swap(cache.TileRunLengths);
    return;
  }
  cache.RunSteps = runSteps;
  for (std::size_t t = 0; t < tileStart.size(); ++t)
  {
    if (tileStart[t].first)
    {
      cache.TileRuns[t] = tileStart[t].first->Ids.data() + tileStart[t].second;
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBLIC::vtkInternals::TraceTile(const vtkOFBLICTracer& tracer,
  const vtkOFBLICTiles& tiles,
  vtkIdType tile,
  vtkOFBLICRunStore& store,
  unsigned char* covered,
  vtkTypeInt32* where,
  vtkTypeInt32* sequence)
{
  const unsigned char* mask = this->Cache.Mask.data();
  const vtkOFBLICSample* samples = tracer.Samples;
  const int n = tracer.NumberOfSteps;
  const int m = LongSteps * n;
  const std::size_t start = store.size();
  // A window of a streamline that passes a sample farther aside than ReuseDistance reads
  // other samples than the sample's own streamline (dashes, seams at the tile planes).
  const float reach2 = tracer.ReuseDistance * tracer.ReuseDistance;
  // Per step of the run: whether it passed a sample it can give a window to (forward
  // steps, backward steps, then the run in its order).
  std::vector<unsigned char> nearBuffer(4 * m + 4);
  unsigned char* near = nearBuffer.data();
  unsigned char* line = near + 2 * m + 2;
  *store.Extend(1) = -1;
  // The tile's records, depths and cell offsets are read in order first (streams the
  // hardware follows), so that the streamlines' random order of visits finds them in
  // the cache. Loads, not prefetch hints: a processor may drop hints issued thousands in
  // a row, and then the tracing misses the cache.
  vtkTypeUInt32 touched = 0;
  tiles.ForEachSample(tile,
    [&](vtkIdType i)
    {
      vtkTypeUInt32 depthBits;
      std::memcpy(&depthBits, tracer.Depths + i, sizeof(depthBits));
      touched += static_cast<vtkTypeUInt32>(samples[i].Flags) ^ depthBits;
      covered[i] = 0;
    });
  for (int a = 0; a < 3; ++a)
  {
    // A step reads the offsets of the cell under it and of the next one (one load a
    // cache line of 16 offsets).
    vtkIdType r[4];
    tiles.GetCellRange(tile, a, tracer.Dimensions, r);
    const vtkIdType rowLength = tracer.Dimensions[(a + 1) % 3];
    for (vtkIdType v = r[2]; v < r[3]; ++v)
    {
      const vtkTypeUInt32* row = tracer.Offsets + tracer.CellBase[a] + v * rowLength;
      for (vtkIdType u = r[0]; u <= r[1]; u += 16)
      {
        touched += row[u];
      }
    }
  }
  vtkOFBLICKeep(touched);
  tiles.ForEachSample(tile,
    [&](vtkIdType i)
    {
      if (mask[i] || covered[i])
      {
        return;
      }
      // A long streamline through i: backward steps reversed, i, forward steps. A
      // direction stops early once its last n samples are of other tiles, covered or
      // passed farther than ReuseDistance across the flow: every sample before them that it can
      // still cover has its full window.
      int ahead, back;
      bool aheadEnded, backEnded;
      vtkTypeInt32* backward = sequence + m + 1;
      unsigned char* nearAhead = near;
      unsigned char* nearBack = near + m + 1;
      tracer.TraceBoth(
        i,
        m,
        std::max(n, 1),
        [&](vtkIdType k, const glm::vec3& p, int dir, int step)
        {
          const vtkOFBLICSample& sk = samples[k];
          bool useful = sk.Tile() == tile && !covered[k];
          if (useful)
          {
            const glm::vec3 d = p - vtkOFBLICTracer::Vec3(sk.Position);
            const glm::vec3 f = vtkOFBLICTracer::Vec3(sk.Field);
            const float ff = glm::dot(f, f);
            const float along = glm::dot(d, f);
            useful = glm::dot(d, d) * ff - along * along < reach2 * ff;
          }
          (dir > 0 ? nearAhead : nearBack)[step] = useful;
          return useful;
        },
        sequence,
        ahead,
        aheadEnded,
        backward,
        back,
        backEnded);
      // The run in the store: -1 (already there), backward reversed, i, forward, -1.
      const int length = back + 1 + ahead;
      vtkTypeInt32* run = store.Extend(length + 1);
      const std::size_t base = store.size() - (length + 1) - start;
      std::reverse_copy(backward, backward + back, run);
      run[back] = static_cast<vtkTypeInt32>(i);
      std::copy(sequence, sequence + ahead, run + back + 1);
      run[length] = -1;
      std::reverse_copy(nearBack, nearBack + back, line);
      line[back] = 1;
      std::copy(nearAhead, nearAhead + ahead, line + back + 1);
      // Every sample of the tile met within ReuseDistance across the flow gets the window around
      // its meeting as its streamline: where the streamline stopped by itself, a window may end
      // there (as a sample's own streamline would); where it ran out of steps or went idle, the
      // window must fit.
      const int low = backEnded ? 0 : n;
      const int high = aheadEnded ? length - 1 : length - 1 - n;
      for (int t = low; t <= high; ++t)
      {
        const vtkIdType k = run[t];
        if (!line[t] || samples[k].Tile() != tile || covered[k])
        {
          continue;
        }
        covered[k] = 1;
        where[k] = static_cast<vtkTypeInt32>(base + t);
      }
    });
}
