/**
 * @file    vtkOFBHugePages.h
 * @brief   Ask for transparent huge pages on a large array (private)
 *
 * Faulting in a 2 MiB page costs much less than faulting in 512 pages of 4 KiB,
 * and the first touch of fresh arrays otherwise dominates building an OFB; a
 * build's scattered writes also miss the TLB less. AdviseHugePages asks for them
 * on an array before its first touch (a no-op where madvise has no
 * MADV_HUGEPAGE). Memory that malloc takes from its heap, though, may already
 * be mapped in 4 KiB pages by earlier allocations of the process: the output
 * arrays of a sampler are therefore mapped on their own (AllocateOnHugePages).
 */

#ifndef vtkOFBHugePages_h
#define vtkOFBHugePages_h

#include "vtkDataArray.h"

#include <cstddef>
#include <cstdint>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define VTK_OFB_HUGE_PAGES 1
#endif

namespace vtkofb
{
inline void AdviseHugePages(void* data, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const uintptr_t huge = uintptr_t(1) << 21;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(data) + huge - 1) & ~(huge - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(data) + bytes) & ~(huge - 1);
  if (end > begin)
  {
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)data;
  (void)bytes;
#endif
}

inline void AdviseHugePages(vtkDataArray* array)
{
  AdviseHugePages(
    array->GetVoidPointer(0), static_cast<size_t>(array->GetDataSize()) * array->GetDataTypeSize());
}

/// Where a mapping of AllocateHugePages starts, just before the memory it returns.
struct HugeMapping
{
  void* Base;
  size_t Bytes;
};

/**
 * `bytes` of fresh memory on 2 MiB boundaries, in its own mapping, with huge
 * pages asked for; null where there are none (then allocate as usual). Release
 * with FreeHugePages.
 */
inline void* AllocateHugePages(size_t bytes)
{
#if defined(VTK_OFB_HUGE_PAGES)
  const size_t huge = size_t(1) << 21;
  const size_t rounded = (bytes + huge - 1) & ~(huge - 1);
  const size_t mapped = rounded + huge; // room to align, and for the HugeMapping
  void* base = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (base == MAP_FAILED)
  {
    return nullptr;
  }
  const uintptr_t first = reinterpret_cast<uintptr_t>(base) + sizeof(HugeMapping);
  auto* data = reinterpret_cast<char*>((first + huge - 1) & ~(huge - 1));
  madvise(data, rounded, MADV_HUGEPAGE);
  reinterpret_cast<HugeMapping*>(data)[-1] = { base, mapped };
  return data;
#else
  (void)bytes;
  return nullptr;
#endif
}

/// Release memory of AllocateHugePages (a free function for vtkAbstractArray).
inline void FreeHugePages(void* data)
{
#if defined(VTK_OFB_HUGE_PAGES)
  if (data)
  {
    const HugeMapping mapping = static_cast<HugeMapping*>(data)[-1];
    munmap(mapping.Base, mapping.Bytes);
  }
#else
  (void)data;
#endif
}

/**
 * Give `array` (its components set) `tuples` uninitialized tuples of its own
 * mapping on huge pages, which it frees with FreeHugePages (and leaves, copying,
 * if it grows). False, and the array untouched, for less than 4 MiB, an array
 * without the standard memory layout, or where there are no huge pages: then
 * allocate as usual.
 */
inline bool AllocateOnHugePages(vtkDataArray* array, vtkIdType tuples)
{
  const vtkIdType values = tuples * array->GetNumberOfComponents();
  const size_t bytes = static_cast<size_t>(values) * array->GetDataTypeSize();
  if (bytes < (size_t(4) << 20) || !array->HasStandardMemoryLayout())
  {
    return false;
  }
  void* data = AllocateHugePages(bytes);
  if (!data)
  {
    return false;
  }
  array->SetVoidArray(data, values, 0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(FreeHugePages);
  return true;
}
}

#endif
