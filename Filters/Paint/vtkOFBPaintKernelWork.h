// Private header of vtkOFBPaintKernel: what a call keeps per thread and from call to call
// (vtkOFBPaintKernel.cxx paints, vtkOFBPaintKernelChanges.cxx collects the changed
// samples), and bit helpers.
#ifndef vtkOFBPaintKernelWork_h
#define vtkOFBPaintKernelWork_h

#include "vtkOFBPaintKernel.h"
#include "vtkOFBPaintWaves.h"
#include "vtkSMPThreadLocal.h"

#include <functional>
#include <utility>
#include <vector>

// Number of trailing zero bits of a non-zero word.
inline int vtkOFBTrailingZeros(vtkTypeUInt64 v)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(v);
#else
  int n = 0;
  for (; !(v & 1); v >>= 1)
  {
    ++n;
  }
  return n;
#endif
}

// Smallest b with 2^b >= v, for v >= 1.
inline int vtkOFBCeilLog2(vtkTypeUInt64 v)
{
  if (v <= 1)
  {
    return 0;
  }
#if defined(__GNUC__) || defined(__clang__)
  return 64 - __builtin_clzll(v - 1);
#else
  int b = 0;
  for (--v; v; v >>= 1)
  {
    ++b;
  }
  return b;
#endif
}

/// Per-thread undo records of one call, and scratch for resolved dabs.
struct vtkOFBPaintKernel::LocalRecords
{
  std::vector<vtkOFBColorRecord> Colors;
  std::vector<vtkOFBNormalRecord> Normals;
  std::vector<ColorDab> ColorDabs;
};

/// What one thread needs while painting dabs, and what it knows already: the last
/// changed-block flag it set and the last initial-value block it made sure of (both
/// stay so until the end of the call), so that a run of samples in one block pays
/// for the shared, atomic state once.
struct vtkOFBPaintKernel::DabWork
{
  LocalRecords* Records;
  const std::function<bool(double)>* Progress; // null in parallel waves
  bool Stop = false;                           // the progress function asked to stop
  vtkIdType Visited = 0;
  double ProgressBase = 0.0;
  double ProgressSpan = 0.0;
  vtkIdType ChangedWord = -1; // the word of the changed bits gathered in ChangedBits
  vtkTypeUInt64 ChangedBits = 0;
  vtkTypeUInt64 ChangedChunks = 0; // ChunkBit of the words set, published by PaintDabs
  vtkIdType InitialColorBlockId = -1;
  const unsigned char* InitialColors = nullptr;
  vtkIdType InitialNormalBlockId = -1;
  const float* InitialNormals = nullptr;
};

/// Buffers of Paint(), kept from call to call.
struct vtkOFBPaintKernel::Scratch
{
  vtkOFBPaintWaves Waves;
  std::vector<std::vector<std::pair<vtkIdType, vtkIdType>>> ChangedParts;
  std::vector<vtkIdType> ChangedChunkList; // the chunks of changed words of a call
  std::vector<vtkIdType> ChangedCounts;
  std::vector<vtkIdType> GapHistograms; // 64 buckets a chunk: gaps by CeilLog2
  vtkSMPThreadLocal<LocalRecords> Records;
};

#endif
