/**
 * @file    vtkOFBPrefetch.h
 * @brief   Cache prefetch hints for the hot loops over samples (not wrapped)
 *
 * `VTKOFB_PREFETCH(p)` hints that the cache line at `p` is read soon,
 * `VTKOFB_PREFETCH_WRITE(p)` that it is written soon; nothing where the compiler has
 * no such builtin. On x86 the hint is a volatile instruction: GCC takes
 * __builtin_prefetch for free of side effects, so a caller's prefetch functor that it
 * does not inline is deleted as a call that does nothing, with its prefetches.
 *
 * Installed for vtkOFB's sphere queries (vtkOFBSphereQuery.h) and the modules that
 * prefetch their own arrays along them.
 */

#ifndef vtkOFBPrefetch_h
#define vtkOFBPrefetch_h

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#define VTKOFB_PREFETCH(p)                                                                         \
  __asm__ __volatile__("prefetcht0 %0" : : "m"(*reinterpret_cast<const char*>(p)))
#if defined(__PRFCHW__)
#define VTKOFB_PREFETCH_WRITE(p)                                                                   \
  __asm__ __volatile__("prefetchw %0" : : "m"(*reinterpret_cast<const char*>(p)))
#else
#define VTKOFB_PREFETCH_WRITE(p) VTKOFB_PREFETCH(p)
#endif
#elif defined(__GNUC__) || defined(__clang__)
#define VTKOFB_PREFETCH(p) __builtin_prefetch(p)
#define VTKOFB_PREFETCH_WRITE(p) __builtin_prefetch((p), 1)
#else
#define VTKOFB_PREFETCH(p) ((void)(p))
#define VTKOFB_PREFETCH_WRITE(p) ((void)(p))
#endif

#endif
