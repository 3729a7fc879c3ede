// Private header of vtkOFBLIC: what it keeps between updates (the packed samples, the
// noise, the traced streamlines and work buffers), each part with the key of what it was
// computed from.
#ifndef vtkOFBLICCache_h
#define vtkOFBLICCache_h

#include "vtkOFBHugePages.h"
#include "vtkOFBLICTracer.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

/// A list of the values an intermediate result depends on, compared bit for bit.
class vtkOFBLICCacheKey
{
public:
  vtkOFBLICCacheKey& Add(double v)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof(bits));
    this->Values.push_back(bits);
    return *this;
  }
  vtkOFBLICCacheKey& Add(std::uint64_t v)
  {
    this->Values.push_back(v);
    return *this;
  }
  vtkOFBLICCacheKey& Add(const void* p)
  {
    return this->Add(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p)));
  }
  vtkOFBLICCacheKey& Add(const vtkOFBLICCacheKey& o)
  {
    this->Values.insert(this->Values.end(), o.Values.begin(), o.Values.end());
    return *this;
  }
  bool empty() const { return this->Values.empty(); }
  bool operator==(const vtkOFBLICCacheKey& o) const { return this->Values == o.Values; }
  bool operator!=(const vtkOFBLICCacheKey& o) const { return !(*this == o); }

private:
  std::vector<std::uint64_t> Values;
};

/**
 * An array of trivially copyable T whose values are not initialized (resize() leaves
 * them undefined, even the old ones when it grows): vtkOFBLIC writes every value before
 * reading it, so clearing would only cost time. Large arrays are mapped in 2 MiB pages
 * where the system offers them (Linux transparent huge pages), which makes the first
 * touch of a new array hundreds of times fewer page faults (from 256 KiB on).
 */
template<typename T>
class vtkOFBLICBuffer
{
public:
  vtkOFBLICBuffer() = default;
  vtkOFBLICBuffer(const vtkOFBLICBuffer&) = delete;
  vtkOFBLICBuffer& operator=(const vtkOFBLICBuffer&) = delete;
  ~vtkOFBLICBuffer() { this->Release(); }

  void resize(std::size_t n)
  {
    if (n > this->Capacity)
    {
      this->Release();
      this->Allocate(n);
    }
    this->Size = n;
  }
  void Release()
  {
    if (this->Data)
    {
#ifdef __linux__
      if (this->Mapped)
      {
        munmap(this->Mapped, this->MappedBytes);
      }
      else
#endif
      {
        std::free(this->Data);
      }
    }
    this->Data = nullptr;
    this->Mapped = nullptr;
    this->Size = this->Capacity = this->MappedBytes = 0;
  }
  /// Capacity for at least n values (at least doubled when it grows), the values kept.
  void reserve(std::size_t n)
  {
    if (n <= this->Capacity)
    {
      return;
    }
    vtkOFBLICBuffer bigger;
    bigger.Allocate(std::max(n, 2 * this->Capacity));
    if (this->Size)
    {
      std::memcpy(static_cast<void*>(bigger.Data), this->Data, this->Size * sizeof(T));
    }
    bigger.Size = this->Size;
    this->swap(bigger);
  }
  void swap(vtkOFBLICBuffer& o)
  {
    std::swap(this->Data, o.Data);
    std::swap(this->Mapped, o.Mapped);
    std::swap(this->MappedBytes, o.MappedBytes);
    std::swap(this->Size, o.Size);
    std::swap(this->Capacity, o.Capacity);
  }
  T* data()
  {
    return this->Data;
  }
  const T* data() const
  {
    return this->Data;
  }
  std::size_t size() const
  {
    return this->Size;
  }
  std::size_t capacity() const
  {
    return this->Capacity;
  }
  bool empty() const
  {
    return this->Size == 0;
  }
  T& operator[](std::size_t i)
  {
    return this->Data[i];
  }
  const T& operator[](std::size_t i) const
  {
    return this->Data[i];
  }

private:
  void Allocate(std::size_t n)
  {
    const std::size_t bytes = n * sizeof(T);
#ifdef __linux__
    constexpr std::size_t huge = std::size_t(2) << 20;
    // From 256 KiB: a fault of a 4 KiB page costs microseconds under a hypervisor, so even
    // a buffer of a fraction of a huge page is faulted in faster as one.
    if (bytes >= huge / 8)
    {
      // Over-map by a page and use the 2 MiB aligned part inside.
      const std::size_t mapped = (bytes + 2 * huge - 1) / huge * huge;
      void* p = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p != MAP_FAILED)
      {
        const std::size_t address = reinterpret_cast<std::size_t>(p);
        const std::size_t aligned = (address + huge - 1) / huge * huge;
        vtkofb::AdviseHugePages(reinterpret_cast<void*>(aligned), mapped - (aligned - address));
        this->Mapped = p;
        this->MappedBytes = mapped;
        this->Data = reinterpret_cast<T*>(aligned);
        this->Capacity = n;
        return;
      }
    }
#endif
    this->Data = static_cast<T*>(std::malloc(std::max<std::size_t>(bytes, 1)));
    if (!this->Data)
    {
      throw std::bad_alloc();
    }
    this->Capacity = n;
  }

  T* Data = nullptr;
  void* Mapped = nullptr;
  std::size_t MappedBytes = 0;
  std::size_t Size = 0;
  std::size_t Capacity = 0;
};

/**
 * A new one-component output array of n values. From 256 KiB on, its memory is 2 MiB
 * aligned and advised for transparent huge pages (freed with free() by the array): the
 * first write to a new array otherwise takes a page fault every 4 KiB, which under a
 * hypervisor costs more than the LIC's own work on the array.
 */
template<typename ArrayT>
vtkSmartPointer<ArrayT> vtkOFBLICNewOutputArray(const char* name, vtkIdType n)
{
  using ValueT = typename ArrayT::ValueType;
  vtkSmartPointer<ArrayT> array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
#ifdef __linux__
  const std::size_t huge = std::size_t(2) << 20;
  const std::size_t bytes = static_cast<std::size_t>(n) * sizeof(ValueT);
  void* data = nullptr;
  if (bytes >= huge / 8)
  {
    const std::size_t rounded = (bytes + huge - 1) / huge * huge;
    if (posix_memalign(&data, huge, rounded) == 0)
    {
      vtkofb::AdviseHugePages(data, rounded);
      array->SetArray(static_cast<ValueT*>(data), n, 0, ArrayT::VTK_DATA_ARRAY_FREE);
      return array;
    }
  }
#endif
  array->SetNumberOfTuples(n);
  return array;
}

/**
 * The seed streamlines of fast LIC that one thread traced, tile after tile, as sample
 * ids, each streamline with -1 before and after it (see vtkOFBLIC::TraceTile).
 */
struct vtkOFBLICRunStore
{
  vtkOFBLICBuffer<vtkTypeInt32> Ids;

  std::size_t size() const { return this->Ids.size(); }
  /// Room for n more ids; returns where they go.
  vtkTypeInt32* Extend(std::size_t n)
  {
    const std::size_t old = this->Ids.size();
    this->Ids.reserve(old + n);
    this->Ids.resize(old + n);
    return this->Ids.data() + old;
  }
};

/**
 * What vtkOFBLIC keeps between updates (see the class description), each part with the
 * key of what it was computed from; an empty key is never valid.
 */
class vtkOFBLICCache
{
public:
  vtkOFBLICCacheKey SamplesKey; // Samples, Mask, Masked
  vtkOFBLICBuffer<vtkOFBLICSample> Samples;
  vtkOFBLICBuffer<unsigned char> Mask;
  vtkIdType Masked = 0;
  std::vector<vtkIdType> TileFirst; // the samples of each tile (vtkOFBLICTiles)
  vtkOFBLICBuffer<vtkTypeInt32> TileIds;
  vtkOFBLICCacheKey NoiseKey;
  vtkOFBLICBuffer<float> Noise;
  vtkOFBLICCacheKey LinesKey;          // Where, Runs, TileRuns
  vtkOFBLICBuffer<vtkTypeInt32> Where; // per sample: its place in its tile's seed streamlines
  std::vector<std::unique_ptr<vtkOFBLICRunStore>> Runs; // one a thread that traced
  std::vector<const vtkTypeInt32*> TileRuns;            // per tile: its first run id
  std::vector<vtkIdType> TileRunLengths;                // per tile: its ids in the runs
  int RunSteps = 0;             // the steps each way of every sample's window that the runs hold
  vtkOFBLICCacheKey MomentsKey; // Moments: LinesKey, NoiseKey and the kernel
  vtkOFBLICBuffer<vtkOFBLICMoments> Moments; // per sample (Animate on: re-convolution)
  vtkOFBLICBuffer<unsigned char> Covered;    // samples given their streamline, while tracing
  vtkOFBLICBuffer<float> Values;             // work buffers, kept to avoid allocating every update
  vtkOFBLICBuffer<float> Scratch;
  // The high-pass's neighbours of each sample (EnhancedLIC; see vtkOFBLICHighPass): a
  // count, or SearchNeighbours, and up to MaxNeighbours offsets to their ids.
  static constexpr int MaxNeighbours = 8;
  static constexpr unsigned char SearchNeighbours = 255;
  vtkOFBLICCacheKey NeighboursKey; // the SamplesKey they were found for
  vtkOFBLICBuffer<unsigned char> NeighbourCount;
  vtkOFBLICBuffer<vtkTypeInt16> NeighbourOffsets;
  struct SearchedSample // a sample whose neighbours did not fit, and where its ids are
  {
    vtkIdType Id;
    vtkIdType First; // in SearchedIds
    vtkIdType Count;
  };
  std::vector<SearchedSample> SearchedSamples;
  std::vector<vtkTypeInt32> SearchedIds; // their neighbours, in the order they are summed

  void Clear()
  {
    this->SamplesKey = this->NoiseKey = this->LinesKey = this->MomentsKey = vtkOFBLICCacheKey();
    this->Masked = 0;
    this->Samples.Release();
    this->Mask.Release();
    std::vector<vtkIdType>().swap(this->TileFirst);
    this->TileIds.Release();
    this->Noise.Release();
    this->ReleaseLines();
    this->Covered.Release();
    this->Values.Release();
    this->Scratch.Release();
    this->NeighboursKey = vtkOFBLICCacheKey();
    this->NeighbourCount.Release();
    this->NeighbourOffsets.Release();
    std::vector<SearchedSample>().swap(this->SearchedSamples);
    std::vector<vtkTypeInt32>().swap(this->SearchedIds);
  }

  void ReleaseLines()
  {
    this->MomentsKey = vtkOFBLICCacheKey();
    this->Moments.Release();
    this->Where.Release();
    this->Runs.clear();
    std::vector<const vtkTypeInt32*>().swap(this->TileRuns);
    std::vector<vtkIdType>().swap(this->TileRunLengths);
    this->RunSteps = 0;
  }

  std::size_t LinesBytes() const
  {
    std::size_t bytes = this->Where.capacity() * sizeof(vtkTypeInt32) +
      this->Moments.capacity() * sizeof(vtkOFBLICMoments) +
      this->TileRuns.capacity() * sizeof(const vtkTypeInt32*) +
      this->TileRunLengths.capacity() * sizeof(vtkIdType);
    for (const auto& r : this->Runs)
    {
      bytes += r->Ids.size() * sizeof(vtkTypeInt32); // the pages used of a larger mapping
    }
    return bytes;
  }
};

#endif
