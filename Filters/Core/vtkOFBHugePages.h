/**
 * @file    vtkOFBHugePages.h
 * @brief   Ask for transparent huge pages on a large array (private)
 *
 * Writes over huge pages miss the TLB less, which speeds up rebuilds that write
 * over the memory of the previous output. Faulting a 2 MiB page in costs less than
 * 512 pages of 4 KiB on bare metal but can cost more under a hypervisor, so first
 * builds may be slower. Call before the array's
 * first touch; a no-op where madvise has no MADV_HUGEPAGE.
 */

#ifndef vtkOFBHugePages_h
#define vtkOFBHugePages_h

#include "vtkDataArray.h"

#include <cstddef>
#include <cstdint>
#if defined(__linux__)
#include <sys/mman.h>
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
}

#endif
