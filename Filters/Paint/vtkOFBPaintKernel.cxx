#include "vtkOFBPaintKernel.h"
#include "vtkOFBBrushFunctions.h"
#include "vtkOFBPaintKernelWork.h"
#include "vtkOFBPaintWaves.h"

#include "vtkFloatArray.h"
#include "vtkOFB.h"
#include "vtkOFBBrush.h"
#include "vtkOFBHugePages.h"
#include "vtkOFBPrefetch.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <thread>

using vtkofbbrush::Blend;
using vtkofbbrush::Facing;

namespace
{
/// The Custom falloff as the painter samples it: a table at x = i / (size - 1),
/// interpolated linearly (constant 1 without one).
struct CustomTableCurve
{
  const std::vector<double>& Table;
  double operator()(double x) const
  {
    const size_t n = this->Table.size();
    if (n < 2)
    {
      return 1.0;
    }
    const double f = x * static_cast<double>(n - 1);
    const size_t i = std::min(static_cast<size_t>(f), n - 2);
    const double w = f - static_cast<double>(i);
    return this->Table[i] + w * (this->Table[i + 1] - this->Table[i]);
  }
};

/// The brush's falloff at normalized distance x: Kind is the falloff when known when
/// compiling (the brush's default Smooth and the particles' default Constant, inlined),
/// -1 for the settings' falloff (chosen per sample).
template<int Kind>
inline double FalloffOf(const vtkOFBPaintSettings& s, double x)
{
  const vtkOFBBrush::FalloffType kind =
    Kind >= 0 ? static_cast<vtkOFBBrush::FalloffType>(Kind) : s.Falloff;
  return vtkofbbrush::Falloff(kind, x, CustomTableCurve{ s.CustomTable });
}

/**
 * A copy of `count` tuples of `components` values of `source`, made once by the first
 * thread that asks (`state`: 0 none, 1 copying, 2 done; the others wait for it) into
 * `copy`; `made` is called by the thread that made it.
 */
template<typename T, typename Made>
const T* CopyOnce(std::atomic<unsigned char>& state,
  std::unique_ptr<T[]>& copy,
  const T* source,
  vtkIdType count,
  int components,
  Made made)
{
  if (state.load(std::memory_order_acquire) != 2)
  {
    unsigned char expected = 0;
    if (state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel))
    {
      copy.reset(new T[components * count]);
      std::memcpy(copy.get(), source, components * count * sizeof(T));
      made();
      state.store(2, std::memory_order_release);
    }
    while (state.load(std::memory_order_acquire) != 2)
    {
      std::this_thread::yield();
    }
  }
  return copy.get();
}

// Progress is reported every this many visited samples (serial dabs only).
constexpr vtkIdType ProgressMask = (vtkIdType(1) << 20) - 1;

// Waves smaller than this run on the calling thread.
constexpr size_t MinParallelWave = 8;
// Calls of at least this many dabs report progress between dabs.
constexpr size_t ManyDabs = 4096;
// How many dabs ahead of the query's planning a dab's record is prefetched (the
// dabs of a wave are visited in spatial order, not in memory order).
constexpr vtkIdType DabLookAhead = 6;
}

//------------------------------------------------------------------------------
vtkOFBPaintKernel::vtkOFBPaintKernel()
  : Work(new Scratch)
{
}

//------------------------------------------------------------------------------
vtkOFBPaintKernel::~vtkOFBPaintKernel() = default;

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::Reset(vtkOFB* ofb, vtkUnsignedCharArray* colors, vtkFloatArray* normals)
{
  this->OFB = ofb;
  this->Colors = colors;
  this->Normals = normals;
  const vtkIdType n = ofb ? ofb->GetNumberOfSamples() : 0;
  if (n != this->NumberOfSamples || !this->Flags)
  {
    this->NumberOfSamples = n;
    this->Flags.reset(new unsigned char[std::max<vtkIdType>(n, 1)]);
    vtkofb::AdviseHugePages(this->Flags.get(), static_cast<size_t>(n)); // before the memset
    this->NumberOfChangedWords = (n >> 6) + 1;
    this->ChangedWords.reset(new std::atomic<vtkTypeUInt64>[this->NumberOfChangedWords]);
    this->NumberOfChangedChunks = (this->NumberOfChangedWords >> ChangedChunkShift) + 1;
  }
  std::memset(this->Flags.get(), 0, static_cast<size_t>(std::max<vtkIdType>(n, 1)));
  for (vtkIdType w = 0; w < this->NumberOfChangedWords; ++w)
  {
    this->ChangedWords[w].store(0, std::memory_order_relaxed);
  }
  this->ChangedChunks.store(0, std::memory_order_relaxed);
  this->ResetInitialValues();
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::SetArrays(vtkUnsignedCharArray* colors, vtkFloatArray* normals)
{
  this->Colors = colors;
  this->Normals = normals;
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::ResetInitialValues()
{
  const vtkIdType blocks = (this->NumberOfSamples >> InitialBlockShift) + 1;
  this->NumberOfInitialBlocks = blocks;
  this->InitialColors.clear();
  this->InitialNormals.clear();
  this->InitialColors.resize(blocks);
  this->InitialNormals.resize(blocks);
  this->InitialColorState.reset(new std::atomic<unsigned char>[blocks]);
  this->InitialNormalState.reset(new std::atomic<unsigned char>[blocks]);
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    this->InitialColorState[b].store(0, std::memory_order_relaxed);
    this->InitialNormalState[b].store(0, std::memory_order_relaxed);
  }
  this->InitialBlocksHeld = 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPaintKernel::GetMemory() const
{
  const vtkIdType block = vtkIdType(1) << InitialBlockShift;
  return this->NumberOfSamples + 8 * this->NumberOfChangedWords +
    2 * this->NumberOfInitialBlocks * static_cast<vtkIdType>(sizeof(void*) + 1) +
    this->InitialBlocksHeld.load() * block * 4;
}

//------------------------------------------------------------------------------
const unsigned char* vtkOFBPaintKernel::InitialColorBlock(vtkIdType b)
{
  const vtkIdType first = b << InitialBlockShift;
  const vtkIdType count =
    std::min(vtkIdType(1) << InitialBlockShift, this->NumberOfSamples - first);
  return CopyOnce(this->InitialColorState[b],
    this->InitialColors[b],
    this->Colors->GetPointer(4 * first),
    count,
    4,
    [this] { ++this->InitialBlocksHeld; });
}

//------------------------------------------------------------------------------
const float* vtkOFBPaintKernel::InitialNormalBlock(vtkIdType b)
{
  const vtkIdType first = b << InitialBlockShift;
  const vtkIdType count =
    std::min(vtkIdType(1) << InitialBlockShift, this->NumberOfSamples - first);
  // Three times the bytes of a colour block.
  return CopyOnce(this->InitialNormalState[b],
    this->InitialNormals[b],
    this->Normals->GetPointer(3 * first),
    count,
    3,
    [this] { this->InitialBlocksHeld += 3; });
}

//------------------------------------------------------------------------------
inline const unsigned char* vtkOFBPaintKernel::InitialColor(vtkIdType id, DabWork& work)
{
  const vtkIdType b = id >> InitialBlockShift;
  if (b != work.InitialColorBlockId)
  {
    work.InitialColors = this->InitialColorBlock(b);
    work.InitialColorBlockId = b;
  }
  return work.InitialColors + 4 * (id & ((vtkIdType(1) << InitialBlockShift) - 1));
}

//------------------------------------------------------------------------------
inline const float* vtkOFBPaintKernel::InitialNormal(vtkIdType id, DabWork& work)
{
  const vtkIdType b = id >> InitialBlockShift;
  if (b != work.InitialNormalBlockId)
  {
    work.InitialNormals = this->InitialNormalBlock(b);
    work.InitialNormalBlockId = b;
  }
  return work.InitialNormals + 3 * (id & ((vtkIdType(1) << InitialBlockShift) - 1));
}

//------------------------------------------------------------------------------
inline void vtkOFBPaintKernel::MarkChangedInWork(vtkIdType id, DabWork& work)
{
  // A dab's changes come in runs of increasing ids (rows of cells): gather a word's
  // bits and set them with one atomic OR (the word may hold samples another thread
  // of the wave changes).
  const vtkIdType w = id >> 6;
  if (w != work.ChangedWord)
  {
    this->FlushChanged(work);
    work.ChangedWord = w;
  }
  work.ChangedBits |= vtkTypeUInt64(1) << (id & 63);
}

//------------------------------------------------------------------------------
inline void vtkOFBPaintKernel::FlushChanged(DabWork& work)
{
  if (work.ChangedBits)
  {
    this->ChangedWords[work.ChangedWord].fetch_or(work.ChangedBits, std::memory_order_relaxed);
    work.ChangedChunks |= ChunkBit(work.ChangedWord);
    work.ChangedBits = 0;
  }
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::ReportProgress(DabWork& work) const
{
  if ((++work.Visited & ProgressMask) == 0)
  {
    const double total = static_cast<double>(this->NumberOfSamples);
    if (!(*work.Progress)(
          work.ProgressBase + work.ProgressSpan * std::min(1.0, work.Visited / total)))
    {
      work.Stop = true;
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::Paint(const std::vector<vtkOFBDab>& dabs,
  const vtkOFBPaintSettings& settings,
  std::vector<vtkOFBColorRecord>& colorUndo,
  std::vector<vtkOFBNormalRecord>& normalUndo,
  const std::function<bool(double)>& progress)
{
  if (dabs.empty() || this->NumberOfSamples == 0)
  {
    return;
  }
  Scratch& s = *this->Work;
  s.Waves.Compute(dabs, settings.Target == vtkOFBBrush::TARGET_SMEAR);
  const std::vector<int>& order = s.Waves.GetOrder();
  const std::vector<int>& waveStarts = s.Waves.GetWaveStarts();
  for (auto& local : s.Records)
  {
    local.Colors.clear();
    local.Normals.clear();
  }
  const double total = static_cast<double>(dabs.size());
  DabWork serial{ &s.Records.Local(), progress ? &progress : nullptr };
  // A call of many dabs also reports between dabs, about every hundredth of them (a
  // check per dab or wave, outside the per-sample loops).
  const size_t reportEvery =
    progress && dabs.size() >= ManyDabs ? std::max<size_t>(1, dabs.size() / 100) : 0;
  size_t nextReport = reportEvery;
  auto carryOn = [&](int k)
  {
    if (reportEvery && static_cast<size_t>(k) >= nextReport)
    {
      nextReport = static_cast<size_t>(k) + reportEvery;
      serial.Stop = serial.Stop || !progress(k / total);
    }
    return !serial.Stop;
  };
  for (size_t w = 0; w + 1 < waveStarts.size() && carryOn(waveStarts[w]); ++w)
  {
    const int begin = waveStarts[w];
    const int end = waveStarts[w + 1];
    if (static_cast<size_t>(end - begin) < MinParallelWave)
    {
      for (int k = begin; k < end && carryOn(k); ++k)
      {
        serial.Visited = 0;
        serial.ProgressBase = k / total;
        serial.ProgressSpan = 1.0 / total;
        this->PaintDabs(dabs, order.data() + k, 1, settings, serial);
      }
    }
    else
    {
      vtkSMPTools::For(begin,
        end,
        [&](vtkIdType first, vtkIdType last)
        {
          DabWork work{ &s.Records.Local(), nullptr };
          this->PaintDabs(dabs, order.data() + first, last - first, settings, work);
        });
    }
  }
  for (auto& local : s.Records)
  {
    colorUndo.insert(colorUndo.end(), local.Colors.begin(), local.Colors.end());
    normalUndo.insert(normalUndo.end(), local.Normals.begin(), local.Normals.end());
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPaintKernel::SetColors(const vtkIdType* ids,
  const unsigned char* rgba,
  vtkIdType count,
  bool recordUndo,
  std::vector<vtkOFBColorRecord>& colorUndo)
{
  unsigned char* colors = this->Colors->GetPointer(0);
  DabWork work{ &this->Work->Records.Local(), nullptr };
  vtkIdType changed = 0;
  for (vtkIdType k = 0; k < count; ++k)
  {
    const vtkIdType i = ids[k];
    unsigned char* c = colors + 4 * i;
    if (std::memcmp(c, rgba + 4 * k, 4) == 0)
    {
      continue;
    }
    this->InitialColor(i, work); // keep the initial value before the first change
    if (recordUndo && !(this->Flags[i] & COLOR_RECORDED))
    {
      colorUndo.push_back({ static_cast<vtkTypeUInt32>(i), { c[0], c[1], c[2], c[3] } });
      this->Flags[i] |= COLOR_RECORDED;
    }
    this->MarkChangedInWork(i, work);
    std::memcpy(c, rgba + 4 * k, 4);
    ++changed;
  }
  this->FlushChanged(work);
  this->ChangedChunks.fetch_or(work.ChangedChunks, std::memory_order_relaxed);
  return changed;
}

//------------------------------------------------------------------------------
bool vtkOFBPaintKernel::CentreNormal(const vtkOFBDab& dab, double n[3]) const
{
  glm::dvec3 v;
  if (dab.HasNormal)
  {
    v = glm::dvec3(dab.Normal[0], dab.Normal[1], dab.Normal[2]);
  }
  else
  {
    // The closest sample within the dab, so that it is never one another dab
    // of the same wave changes.
    const double s = this->OFB->GetCellSize();
    const vtkIdType id =
      this->OFB->FindClosestSample(dab.Center, std::min(dab.Radius, std::sqrt(3.0) * s));
    if (id < 0)
    {
      return false;
    }
    const float* m = this->Normals->GetPointer(3 * id);
    v = glm::dvec3(m[0], m[1], m[2]);
  }
  const double len = glm::length(v);
  if (!(len > 0.0) || !std::isfinite(len)) // no direction, or one too large to normalize
  {
    return false;
  }
  v /= len;
  n[0] = v.x;
  n[1] = v.y;
  n[2] = v.z;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBPaintKernel::SmearSource(const vtkOFBDab& dab,
  const vtkOFBPaintSettings& settings,
  float src[4]) const
{
  // The falloff-weighted mean colour under the brush at the previous position.
  const unsigned char* colors = this->Colors->GetPointer(0);
  const double invR = 1.0 / dab.Radius;
  double sum[4] = { 0.0, 0.0, 0.0, 0.0 };
  double weight = 0.0;
  this->OFB->ForEachSampleInSphere(dab.Previous,
    dab.Radius,
    [&](vtkIdType i, double d2)
    {
      const double g = FalloffOf<-1>(settings, std::sqrt(d2) * invR);
      for (int k = 0; k < 4; ++k)
      {
        sum[k] += g * colors[4 * i + k];
      }
      weight += g;
    });
  if (!(weight > 0.0))
  {
    return false;
  }
  for (int k = 0; k < 4; ++k)
  {
    src[k] = static_cast<float>(sum[k] / (255.0 * weight));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::PaintDabs(const std::vector<vtkOFBDab>& dabs,
  const int* order,
  vtkIdType count,
  const vtkOFBPaintSettings& settings,
  DabWork& work)
{
  if (settings.Target == vtkOFBBrush::TARGET_NORMAL)
  {
    for (vtkIdType k = 0; k < count; ++k)
    {
      const vtkOFBDab& dab = dabs[order[k]];
      double n[3] = { 0.0, 0.0, 0.0 };
      const bool aware = settings.NormalAware && this->CentreNormal(dab, n);
      const float cone[3] = {
        static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])
      };
      this->PaintNormals(dab, settings, aware ? cone : nullptr, work);
    }
  }
  // The default falloffs and blend mode compiled in, the others chosen per sample.
  else if (settings.BlendMode == vtkOFBBrush::BLEND_MIX)
  {
    this->PaintColorsWith<vtkOFBBrush::BLEND_MIX>(dabs, order, count, settings, work);
  }
  else
  {
    this->PaintColorsWith<-1>(dabs, order, count, settings, work);
  }
  this->FlushChanged(work); // before the wave ends
  this->ChangedChunks.fetch_or(work.ChangedChunks, std::memory_order_relaxed);
  work.ChangedChunks = 0;
}

//------------------------------------------------------------------------------
bool vtkOFBPaintKernel::ResolveColorDab(const vtkOFBDab& dab,
  const vtkOFBPaintSettings& settings,
  ColorDab& out) const
{
  for (int k = 0; k < 4; ++k)
  {
    out.Source[k] = dab.Color[k];
  }
  out.InverseRadius = 1.0 / dab.Radius;
  out.Strength = dab.Strength;
  double n[3] = { 0.0, 0.0, 0.0 };
  out.Aware = settings.NormalAware && this->Normals && this->CentreNormal(dab, n);
  for (int k = 0; k < 3; ++k)
  {
    out.Cone[k] = static_cast<float>(n[k]);
  }
  if (settings.Target == vtkOFBBrush::TARGET_SMEAR)
  {
    float carried[4];
    if (!dab.HasPrevious || !this->SmearSource(dab, settings, carried))
    {
      return false; // nothing to carry (the first dab of a stroke)
    }
    const float amount = static_cast<float>(settings.SmearAmount);
    for (int k = 0; k < 4; ++k)
    {
      out.Source[k] += amount * (carried[k] - out.Source[k]);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
template<int Mode>
void vtkOFBPaintKernel::PaintColorsWith(const std::vector<vtkOFBDab>& dabs,
  const int* order,
  vtkIdType count,
  const vtkOFBPaintSettings& settings,
  DabWork& work)
{
  switch (settings.Falloff)
  {
    case vtkOFBBrush::FALLOFF_SMOOTH:
      this->PaintColors<Mode, vtkOFBBrush::FALLOFF_SMOOTH>(dabs, order, count, settings, work);
      break;
    case vtkOFBBrush::FALLOFF_CONSTANT:
      this->PaintColors<Mode, vtkOFBBrush::FALLOFF_CONSTANT>(dabs, order, count, settings, work);
      break;
    default:
      this->PaintColors<Mode, -1>(dabs, order, count, settings, work);
      break;
  }
}

//------------------------------------------------------------------------------
template<int Mode, int FalloffKind>
void vtkOFBPaintKernel::PaintColors(const std::vector<vtkOFBDab>& dabs,
  const int* order,
  vtkIdType count,
  const vtkOFBPaintSettings& settings,
  DabWork& work)
{
  unsigned char* colors = this->Colors->GetPointer(0);
  unsigned char* flags = this->Flags.get();
  const std::atomic<vtkTypeUInt64>* changed = this->ChangedWords.get();
  const float* normals = this->Normals ? this->Normals->GetPointer(0) : nullptr;
  const float cosMax = static_cast<float>(settings.CosMaxAngle);
  const vtkOFBBrush::BlendModeType mode =
    Mode >= 0 ? static_cast<vtkOFBBrush::BlendModeType>(Mode) : settings.BlendMode;
  std::vector<vtkOFBColorRecord>& records = work.Records->Colors;
  std::vector<ColorDab>& state = work.Records->ColorDabs;
  state.resize(count);
  const unsigned char recordBit = settings.RecordUndo ? COLOR_RECORDED : 0;
  // The dabs are resolved (smear source, centre normal) as the pipelined query
  // reaches them; a dab with nothing to paint gets a NaN radius (no samples).
  this->OFB->ForEachSampleInSpheres(
    count,
    [&](vtkIdType k, double center[3], double& radius)
    {
      if (k + DabLookAhead < count)
      {
        const char* ahead = reinterpret_cast<const char*>(&dabs[order[k + DabLookAhead]]);
        VTKOFB_PREFETCH(ahead);
        VTKOFB_PREFETCH(ahead + sizeof(vtkOFBDab) - 1);
      }
      const vtkOFBDab& dab = dabs[order[k]];
      center[0] = dab.Center[0];
      center[1] = dab.Center[1];
      center[2] = dab.Center[2];
      radius = this->ResolveColorDab(dab, settings, state[k])
        ? dab.Radius
        : std::numeric_limits<double>::quiet_NaN();
    },
    [&](vtkIdType k, vtkIdType i, double d2)
    {
      if (work.Progress)
      {
        this->ReportProgress(work);
      }
      const ColorDab& dab = state[k];
      if (dab.Aware && !Facing(normals + 3 * i, dab.Cone, cosMax))
      {
        return;
      }
      const float g = static_cast<float>(
        dab.Strength * FalloffOf<FalloffKind>(settings, std::sqrt(d2) * dab.InverseRadius));
      if (g <= 0.0f)
      {
        return;
      }
      unsigned char* c = colors + 4 * i;
      const unsigned char* initial =
        mode == vtkOFBBrush::BLEND_ERASE ? this->InitialColor(i, work) : nullptr;
      unsigned char result[4];
      Blend<Mode>(c, dab.Source, g, mode, initial, result);
      if (std::memcmp(result, c, 4) == 0)
      {
        return;
      }
      this->InitialColor(i, work); // keep the initial value before the first change
      if (recordBit && !(flags[i] & recordBit))
      {
        records.push_back({ static_cast<vtkTypeUInt32>(i), { c[0], c[1], c[2], c[3] } });
        flags[i] |= recordBit;
      }
      this->MarkChangedInWork(i, work);
      std::memcpy(c, result, 4);
    },
    [colors, flags, recordBit, changed](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; i += 16)
      {
        VTKOFB_PREFETCH_WRITE(colors + 4 * i);
      }
      VTKOFB_PREFETCH_WRITE(colors + 4 * (last - 1));
      VTKOFB_PREFETCH_WRITE(changed + (first >> 6));
      VTKOFB_PREFETCH_WRITE(changed + ((last - 1) >> 6));
      if (!recordBit)
      {
        return;
      }
      for (vtkIdType i = first; i < last; i += 64)
      {
        VTKOFB_PREFETCH_WRITE(flags + i);
      }
      VTKOFB_PREFETCH_WRITE(flags + last - 1);
    });
}

//------------------------------------------------------------------------------
void vtkOFBPaintKernel::PaintNormals(const vtkOFBDab& dab,
  const vtkOFBPaintSettings& settings,
  const float* centreNormal,
  DabWork& work)
{
  float* out = this->Normals->GetPointer(0);
  unsigned char* flags = this->Flags.get();
  const float cosMax = static_cast<float>(settings.CosMaxAngle);
  const double invR = 1.0 / dab.Radius;
  const bool erase = settings.BlendMode == vtkOFBBrush::BLEND_ERASE;
  const glm::dvec3 c(dab.Center[0], dab.Center[1], dab.Center[2]);
  std::vector<vtkOFBNormalRecord>& records = work.Records->Normals;
  const unsigned char recordBit = settings.RecordUndo ? NORMAL_RECORDED : 0;
  this->OFB->ForEachSampleInSphere(dab.Center,
    dab.Radius,
    [&](vtkIdType i, double d2)
    {
      if (work.Progress)
      {
        this->ReportProgress(work);
      }
      float* n = out + 3 * i;
      if (centreNormal && !Facing(n, centreNormal, cosMax))
      {
        return;
      }
      const float g =
        static_cast<float>(dab.Strength * FalloffOf<-1>(settings, std::sqrt(d2) * invR));
      if (g <= 0.0f)
      {
        return;
      }
      const glm::vec3 old(n[0], n[1], n[2]);
      glm::vec3 v;
      if (erase)
      {
        const float* n0 = this->InitialNormal(i, work);
        const glm::vec3 initial(n0[0], n0[1], n0[2]);
        v = g >= 1.0f ? initial : old + g * (initial - old);
      }
      else
      {
        double x[3];
        this->OFB->GetSamplePosition(i, x);
        glm::dvec3 t = (glm::dvec3(x[0], x[1], x[2]) - c) * invR;
        const glm::dvec3 nd(old);
        t -= glm::dot(t, nd) * nd;
        v = glm::vec3(nd + settings.BumpDepth * g * t);
      }
      const float len = glm::length(v);
      if (!(len > 0.0f))
      {
        return;
      }
      if (!(erase && g >= 1.0f))
      {
        v /= len; // (a full erase restores the initial normal as it was)
      }
      if (v == old)
      {
        return;
      }
      this->InitialNormal(i, work); // keep the initial value before the first change
      if (recordBit && !(flags[i] & recordBit))
      {
        records.push_back({ static_cast<vtkTypeUInt32>(i), { old.x, old.y, old.z } });
        flags[i] |= recordBit;
      }
      this->MarkChangedInWork(i, work);
      n[0] = v.x;
      n[1] = v.y;
      n[2] = v.z;
    });
}
