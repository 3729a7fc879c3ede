#include "vtkOFBLIC.h"

#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBArrayLength.h"
#include "vtkOFBLICCache.h"
#include "vtkOFBLICEnhance.h"
#include "vtkOFBLICInternals.h"
#include "vtkOFBLICNoise.h"
#include "vtkOFBLICPack.h"
#include "vtkOFBLICTracer.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <string>

vtkStandardNewMacro(vtkOFBLIC);

//------------------------------------------------------------------------------
vtkOFBLIC::vtkOFBLIC()
  : NumberOfSteps(20)
  , StepSize(1.0)
  , NormalizeVectors(true)
  , FieldInterpolation(FIELD_NEAREST)
  , KernelType(KERNEL_BOX)
  , OrientedLIC(false)
  , Animate(false)
  , AnimationPhase(0.0)
  , NoiseType(NOISE_TYPE_GAUSSIAN)
  , NoiseGrainSize(1.0)
  , MinNoiseValue(0.0)
  , MaxNoiseValue(0.8)
  , NumberOfNoiseLevels(256)
  , ImpulseNoiseProbability(1.0)
  , ImpulseNoiseBackgroundValue(0.0)
  , NoiseGeneratorSeed(1)
  , NoiseArrayName(nullptr)
  , EnhancedLIC(true)
  , EnhanceContrast(ENHANCE_CONTRAST_OFF)
  , LowLICContrastEnhancementFactor(0.0)
  , HighLICContrastEnhancementFactor(0.0)
  , MaskThreshold(0.0)
  , MaskOnSurface(false)
  , MaskColor{ 0.5, 0.5, 0.5 }
  , MaskIntensity(0.0)
  , CacheStreamlines(true)
  , StreamlineReuseDistance(0.05)
  , NumberOfMaskedSamples(0)
  , LastRecomputed(0)
  , LastStructureMTime(0)
  , LastExecutionTime(0.0)
  , Reduction(nullptr)
  , FieldScale(0.0)
  , Internals(new vtkInternals)
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
}

//------------------------------------------------------------------------------
vtkOFBLIC::~vtkOFBLIC()
{
  this->SetNoiseArrayName(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
unsigned long vtkOFBLIC::GetCacheMemorySize() const
{
  const vtkOFBLICCache& c = this->Internals->Cache;
  const std::size_t bytes = c.Samples.capacity() * sizeof(vtkOFBLICSample) + c.Mask.capacity() +
    c.TileFirst.capacity() * sizeof(vtkIdType) + c.TileIds.capacity() * sizeof(vtkTypeInt32) +
    c.Covered.capacity() + c.NeighbourCount.capacity() +
    c.NeighbourOffsets.capacity() * sizeof(vtkTypeInt16) +
    c.SearchedSamples.capacity() * sizeof(vtkOFBLICCache::SearchedSample) +
    c.SearchedIds.capacity() * sizeof(vtkTypeInt32) +
    (c.Noise.capacity() + c.Values.capacity() + c.Scratch.capacity()) * sizeof(float) +
    c.LinesBytes();
  return static_cast<unsigned long>((bytes + 1023) / 1024);
}

//------------------------------------------------------------------------------
void vtkOFBLIC::ReleaseCache()
{
  this->Internals->Cache.Clear();
}

//------------------------------------------------------------------------------
int vtkOFBLIC::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::CheckSettings()
{
  if (!(this->StepSize > 0.0) || !std::isfinite(this->StepSize))
  {
    vtkErrorMacro("StepSize must be positive and finite (it is " << this->StepSize << ").");
    return false;
  }
  const int mode = this->EnhanceContrast;
  const double factors[2] = { this->LowLICContrastEnhancementFactor,
    this->HighLICContrastEnhancementFactor };
  if ((mode != ENHANCE_CONTRAST_OFF && mode != ENHANCE_CONTRAST_LIC &&
        mode != ENHANCE_CONTRAST_COLOR && mode != ENHANCE_CONTRAST_BOTH) ||
    !std::all_of(factors, factors + 2, [](double f) { return f >= 0.0 && f <= 1.0; }))
  {
    vtkErrorMacro("EnhanceContrast must be OFF (0), LIC (1), COLOR (3) or BOTH (4), and the "
                  "LIC contrast enhancement factors in [0, 1] (they are "
      << mode << "; " << factors[0] << ", " << factors[1] << ").");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBLIC::FindField(vtkOFB* input)
{
  vtkPointData* sd = input->GetSampleData();
  vtkInformation* info = this->GetInputArrayInformation(0);
  vtkDataArray* vectors = nullptr;
  std::string what = "active vectors";
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    what = std::string("sample array '") + info->Get(vtkDataObject::FIELD_NAME()) + "'";
    vectors = sd->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  }
  else if (info && info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    vectors = sd->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
  }
  if (!vectors)
  {
    vtkErrorMacro("No vector field: the input OFB has no " << what
                                                           << " (set the field with "
                                                              "SetInputArrayToProcess).");
    return nullptr;
  }
  if (vectors->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The vector field '" << (vectors->GetName() ? vectors->GetName() : "") << "' has "
                                       << vectors->GetNumberOfComponents()
                                       << " components; LIC needs 3.");
    return nullptr;
  }
  if (vectors->GetNumberOfTuples() != input->GetNumberOfSamples())
  {
    vtkErrorMacro(
      "The vector field " << vtkOFBArrayLength(vectors, input->GetNumberOfSamples(), "samples."));
    return nullptr;
  }
  return vectors;
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::Prepare(vtkOFB* input, vtkDataArray* vectors, vtkDataArray* normals)
{
  vtkOFBLICCache& cache = this->Internals->Cache;
  const vtkIdType n = input->GetNumberOfSamples();
  const double structure = static_cast<double>(input->GetStructureMTime());
  vtkOFBLICCacheKey samplesKey;
  samplesKey.Add(structure)
    .Add(static_cast<double>(n))
    .Add(vectors)
    .Add(static_cast<double>(vectors->GetMTime()))
    .Add(normals)
    .Add(static_cast<double>(normals->GetMTime()))
    .Add(this->NormalizeVectors ? 1.0 : 0.0)
    .Add(this->NormalizeVectors ? 0.0 : this->FieldScale)
    .Add(this->MaskThreshold)
    .Add(this->MaskOnSurface ? 1.0 : 0.0);
  if (input->GetStructureMTime() != this->LastStructureMTime)
  {
    this->LastRecomputed |= RECOMPUTED_STRUCTURE;
    this->LastStructureMTime = input->GetStructureMTime();
  }
  if (cache.SamplesKey != samplesKey)
  {
    this->LastRecomputed |= RECOMPUTED_SAMPLES;
    // The noise depends on the samples' positions alone, which the structure gives
    // (its key has the structure's time): a new field on the same structure (a new
    // time step re-sampled by vtkOFBSampler) keeps it.
    cache.SamplesKey = vtkOFBLICCacheKey();
    cache.LinesKey = vtkOFBLICCacheKey();
    cache.Masked = this->PrepareSamples(input, vectors, normals);
    cache.SamplesKey = samplesKey;
  }
  this->NumberOfMaskedSamples = cache.Masked;
  if (cache.Masked == n)
  {
    vtkWarningMacro("The vector field is masked at every sample (zero, non-finite or below "
                    "MaskThreshold): the LIC is the mask value everywhere.");
  }
  vtkOFBLICCacheKey noiseKey;
  noiseKey.Add(structure).Add(static_cast<double>(n));
  vtkDataArray* noiseArray = this->NoiseArrayName && *this->NoiseArrayName
    ? input->GetSampleData()->GetArray(this->NoiseArrayName)
    : nullptr;
  if (noiseArray)
  {
    noiseKey.Add(noiseArray).Add(static_cast<double>(noiseArray->GetMTime()));
  }
  else
  {
    noiseKey.Add(this->NoiseArrayName && *this->NoiseArrayName ? 1.0 : 0.0)
      .Add(static_cast<double>(this->NoiseType))
      .Add(this->NoiseGrainSize)
      .Add(this->MinNoiseValue)
      .Add(this->MaxNoiseValue)
      .Add(static_cast<double>(this->NumberOfNoiseLevels))
      .Add(this->ImpulseNoiseProbability)
      .Add(this->ImpulseNoiseBackgroundValue)
      .Add(static_cast<double>(this->NoiseGeneratorSeed));
  }
  if (cache.NoiseKey != noiseKey)
  {
    this->LastRecomputed |= RECOMPUTED_NOISE;
    cache.NoiseKey = vtkOFBLICCacheKey();
    if (!this->PrepareNoise(input))
    {
      return false;
    }
    cache.NoiseKey = noiseKey;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBLIC::PrepareSamples(vtkOFB* input, vtkDataArray* vectors, vtkDataArray* normalsIn)
{
  const vtkIdType n = input->GetNumberOfSamples();
  vtkOFBLICCache& cache = this->Internals->Cache;
  vtkOFBLICBuffer<vtkOFBLICSample>& samples = cache.Samples;
  vtkOFBLICBuffer<unsigned char>& mask = cache.Mask;
  samples.resize(n);
  mask.resize(n);
  vtkFloatArray* floatNormals = vtkFloatArray::SafeDownCast(normalsIn);
  vtkFloatArray* floatVectors = vtkFloatArray::SafeDownCast(vectors);
  const vtkOFBLICPacker packer = { floatNormals ? floatNormals->GetPointer(0) : nullptr,
    normalsIn,
    floatVectors ? floatVectors->GetPointer(0) : nullptr,
    vectors,
    this->MaskThreshold,
    this->MaskOnSurface != 0,
    input->GetOrigin(),
    1.0 / input->GetCellSize() };
  vtkSMPThreadLocal<double> localMax(0.0);
  vtkSMPThreadLocal<vtkIdType> localMasked(0);
  // Position, normal, grid and tile, the tangential part of the field, the mask, and the
  // largest magnitude left (for NormalizeVectors off), row by row of cells in chunks of
  // rows; each chunk counts its samples per tile.
  const double* origin = input->GetOrigin();
  const double cellSize = input->GetCellSize();
  const vtkIdType* dims = input->GetDimensions();
  const vtkOFBLICTiles tiles(dims, origin, cellSize, n);
  const vtkTypeUInt32* offsets = input->GetCellOffsets()->GetPointer(0);
  const float* depths = input->GetDepths()->GetPointer(0);
  const vtkOFBLICRowChunks chunks(
    input, 4 * std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()));
  vtkOFBLICTileSort sort(chunks.Count, tiles.GetNumberOfTiles());
  vtkSMPTools::For(0,
    chunks.Count,
    1,
    [&](vtkIdType beginChunk, vtkIdType endChunk)
    {
      double& maxMag = localMax.Local();
      vtkIdType& masked = localMasked.Local();
      double x[3];
      for (vtkIdType chunk = beginChunk; chunk < endChunk; ++chunk)
      {
        for (vtkIdType r = chunks.Row[chunk]; r < chunks.Row[chunk + 1]; ++r)
        {
          const int a = chunks.GridOf(r);
          const int ua = (a + 1) % 3;
          const int va = (a + 2) % 3;
          const vtkIdType iv = r - chunks.RowBase[a];
          const vtkIdType row = input->GetGridCellBase(a) + iv * dims[ua];
          x[va] = origin[va] + (iv + 0.5) * cellSize;
          for (vtkIdType iu = 0; iu < dims[ua]; ++iu)
          {
            x[ua] = origin[ua] + (iu + 0.5) * cellSize;
            for (vtkIdType i = offsets[row + iu], end = offsets[row + iu + 1]; i < end; ++i)
            {
              x[a] = origin[a] + depths[i];
              const vtkIdType tile = tiles.TileOf(x);
              sort.Count(chunk, tile);
              samples[i].Flags = static_cast<vtkTypeInt32>(a | (tile << 3));
              masked += packer.Pack(samples[i], i, x, maxMag, mask[i]);
            }
          }
        }
      }
    });
  double maxMag = 0.0;
  for (double m : localMax)
  {
    maxMag = std::max(maxMag, m);
  }
  vtkIdType masked = 0;
  for (vtkIdType m : localMasked)
  {
    masked += m;
  }
  sort.Finish(chunks.Count, cache.TileFirst);
  cache.TileIds.resize(n);
  // Scale the field (unit vectors, or relative to the strongest flow) and list the
  // samples in their tiles.
  const bool normalize = this->NormalizeVectors;
  const double scale = this->FieldScale > 0.0 ? this->FieldScale : maxMag;
  vtkTypeInt32* tileIds = cache.TileIds.data();
  vtkSMPTools::For(0,
    chunks.Count,
    1,
    [&](vtkIdType beginChunk, vtkIdType endChunk)
    {
      for (vtkIdType chunk = beginChunk; chunk < endChunk; ++chunk)
      {
        for (vtkIdType i = chunks.First[chunk]; i < chunks.First[chunk + 1]; ++i)
        {
          sort.Place(chunk, samples[i].Tile(), i, tileIds);
          if (mask[i])
          {
            continue;
          }
          float* f = samples[i].Field;
          glm::dvec3 v = vtkOFBLICTracer::Vec(f);
          v /= normalize ? glm::length(v) : scale;
          for (int c = 0; c < 3; ++c)
          {
            f[c] = static_cast<float>(v[c]);
          }
        }
      }
    });
  return masked;
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::PrepareNoise(vtkOFB* input)
{
  const vtkIdType n = input->GetNumberOfSamples();
  vtkOFBLICBuffer<float>& noise = this->Internals->Cache.Noise;
  const vtkOFBLICSample* samples = this->Internals->Cache.Samples.data();
  noise.resize(n);
  if (this->NoiseArrayName && *this->NoiseArrayName)
  {
    vtkDataArray* array = input->GetSampleData()->GetArray(this->NoiseArrayName);
    if (!array || array->GetNumberOfTuples() != n)
    {
      vtkErrorMacro(
        "The noise array '" << this->NoiseArrayName << "' is not a sample array of the input OFB.");
      return false;
    }
    vtkSMPTools::For(0,
      n,
      4096,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          noise[i] = static_cast<float>(array->GetComponent(i, 0));
        }
      });
    return true;
  }
  vtkOFBLICNoiseSettings s;
  s.Type = this->NoiseType;
  s.Grain = this->NoiseGrainSize * input->GetCellSize();
  input->GetOrigin(s.Origin);
  s.MinValue = std::min(this->MinNoiseValue, this->MaxNoiseValue);
  s.MaxValue = std::max(this->MinNoiseValue, this->MaxNoiseValue);
  s.Levels = this->NumberOfNoiseLevels;
  s.ImpulseProbability = this->ImpulseNoiseProbability;
  s.ImpulseBackground = this->ImpulseNoiseBackgroundValue;
  s.Seed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(this->NoiseGeneratorSeed));
  const vtkOFBLICNoise generator(s);
  vtkOFBLICTracer frame;
  frame.SetOFB(input);
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        noise[i] = generator.Evaluate(frame.World(samples[i].Position));
      }
    });
  return true;
}

//------------------------------------------------------------------------------
std::vector<double> vtkOFBLIC::ComputeKernel(int n, bool animation) const
{
  std::vector<double> w(2 * n + 1, 1.0);
  const double pi = 3.141592653589793;
  for (int s = -n; s <= n; ++s)
  {
    const double t = n > 0 ? static_cast<double>(s) / n : 0.0; // in [-1, 1]
    double k = 1.0;
    if (this->KernelType == KERNEL_GAUSSIAN)
    {
      k = std::exp(-2.0 * t * t); // standard deviation 1/2 of the half-length
    }
    else if (this->KernelType == KERNEL_HANN)
    {
      k = 0.5 * (1.0 + std::cos(pi * s / (n + 1.0)));
    }
    if (this->OrientedLIC)
    {
      k *= (s + n + 1.0) / (2.0 * n + 2.0);
    }
    if (animation && this->Animate && n > 0)
    {
      k *= 0.5 * (1.0 + std::cos(2.0 * pi * (static_cast<double>(s) / n + this->AnimationPhase)));
    }
    w[s + n] = k;
  }
  return w;
}

//------------------------------------------------------------------------------
void vtkOFBLIC::WriteOutput(vtkOFB* input,
  vtkOFB* output,
  const float* values,
  const unsigned char* mask,
  vtkIdType n)
{
  // A re-run over the same input (another AnimationPhase) writes into the previous
  // output's LIC and LICMask, recycled by the pipeline (vtkOFB::Recycle), and marks
  // Modified() only what changed; the shallow copy of an unchanged input keeps the
  // output's structure time, so the mapper uploads the LIC array alone.
  vtkSmartPointer<vtkFloatArray> lic =
    vtkFloatArray::SafeDownCast(output->TakeSpareArray("LIC", VTK_FLOAT, 1, n));
  vtkSmartPointer<vtkUnsignedCharArray> maskArray =
    vtkUnsignedCharArray::SafeDownCast(output->TakeSpareArray("LICMask", VTK_UNSIGNED_CHAR, 1, n));
  const bool newMask = !maskArray;
  if (!lic)
  {
    lic = vtkOFBLICNewOutputArray<vtkFloatArray>("LIC", n);
  }
  if (newMask)
  {
    maskArray = vtkOFBLICNewOutputArray<vtkUnsignedCharArray>("LICMask", n);
  }
  lic->SetNumberOfTuples(n);
  maskArray->SetNumberOfTuples(n);
  // LIC (clamped to [0, 1]) and the mask.
  const double luminance =
    0.2126 * this->MaskColor[0] + 0.7152 * this->MaskColor[1] + 0.0722 * this->MaskColor[2];
  const float maskValue =
    static_cast<float>(1.0 + this->MaskIntensity * (std::min(1.0, std::max(0.0, luminance)) - 1.0));
  float* licOut = lic->GetPointer(0);
  unsigned char* maskOut = maskArray->GetPointer(0);
  std::atomic<bool> maskChanged(false);
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      bool changed = false;
      for (vtkIdType i = begin; i < end; ++i)
      {
        // A new mask array holds no values yet: nothing to compare (it is new anyway).
        changed |= !newMask && maskOut[i] != mask[i];
        maskOut[i] = mask[i];
        licOut[i] = mask[i] ? maskValue : std::min(1.0f, std::max(0.0f, values[i]));
      }
      if (changed)
      {
        maskChanged.store(true, std::memory_order_relaxed);
      }
    });
  lic->Modified();
  if (maskChanged.load() && !newMask)
  {
    maskArray->Modified();
  }
  // The input's arrays shared, LIC and the mask added.
  output->ShallowCopy(input);
  output->GetSampleData()->AddArray(lic);
  output->GetSampleData()->AddArray(maskArray);
}

//------------------------------------------------------------------------------
int vtkOFBLIC::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkOFB* input = vtkOFB::GetData(inputVector[0]);
  vtkOFB* output = vtkOFB::GetData(outputVector);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->NumberOfMaskedSamples = 0;
  this->LastRecomputed = 0;
  if (!input || !output)
  {
    vtkErrorMacro("No input OFB.");
    return 0;
  }
  // Every error leaves an empty output.
  if (!this->CheckSettings())
  {
    output->Initialize();
    return 1;
  }
  const vtkIdType n = input->GetNumberOfSamples();
  if (n == 0)
  {
    this->WriteOutput(input, output, nullptr, nullptr, 0);
    return 1;
  }
  vtkDataArray* normals = nullptr;
  vtkDataArray* vectors = this->FindFieldAndNormals(input, normals);
  if (!vectors || !this->Prepare(input, vectors, normals))
  {
    output->Initialize();
    return 1;
  }
  this->UpdateProgress(0.05);
  if (!this->ComputeLIC(input))
  {
    output->Initialize();
    return 1;
  }
  vtkOFBLICCache& cache = this->Internals->Cache;
  this->WriteOutput(input, output, cache.Values.data(), cache.Mask.data(), n);
  this->UpdateProgress(1.0);
  timer->StopTimer();
  this->LastExecutionTime = 1000.0 * timer->GetElapsedTime();
  return 1;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBLIC::FindFieldAndNormals(vtkOFB* input, vtkDataArray*& normals)
{
  vtkDataArray* vectors = this->FindField(input);
  normals = input->GetSampleData()->GetNormals();
  if (!normals)
  {
    normals = input->GetSampleData()->GetArray(vtkOFB::NormalsArrayName());
  }
  if (!vectors)
  {
    return nullptr;
  }
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The input OFB has no 3-component \"Normals\" sample array.");
    return nullptr;
  }
  return vectors;
}

//------------------------------------------------------------------------------
void vtkOFBLIC::SetUpTracer(vtkOFB* input, vtkOFBLICTracer& tracer)
{
  tracer.SetOFB(input);
  tracer.Samples = this->Internals->Cache.Samples.data();
  tracer.NumberOfSteps = this->NumberOfSteps;
  tracer.Step = static_cast<float>(this->StepSize);
  tracer.SearchRadius = std::sqrt(3.0) * input->GetCellSize();
  tracer.FieldRadius =
    this->FieldInterpolation == FIELD_INVERSE_DISTANCE ? 1.5 * input->GetCellSize() : 0.0;
  tracer.ReuseDistance = static_cast<float>(this->StreamlineReuseDistance);
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::ComputeLIC(vtkOFB* input)
{
  // Convolve (Eq. 4), then the enhanced pass and the contrast stretch.
  const vtkIdType n = input->GetNumberOfSamples();
  vtkOFBLICCache& cache = this->Internals->Cache;
  vtkOFBLICTracer tracer;
  this->SetUpTracer(input, tracer);
  const std::vector<double> weights = this->ComputeKernel(this->NumberOfSteps);
  // The kept streamlines, traced during the first pass when they are not valid.
  vtkOFBLICCacheKey linesKey = cache.SamplesKey;
  linesKey.Add(static_cast<double>(this->NumberOfSteps))
    .Add(this->StepSize)
    .Add(static_cast<double>(this->FieldInterpolation))
    .Add(this->StreamlineReuseDistance);
  const bool keep = this->CacheStreamlines && this->NumberOfSteps > 0;
  const bool enhanced = this->EnhancedLIC && this->NumberOfSteps > 0;
  // Animated fast LIC: the first pass from each sample's moments (vtkOFBLICKernelParts),
  // combined again without reading the runs while the lines, noise and kernel stay.
  // Without EnhancedLIC nothing else reads the runs again for a new phase: only the
  // moments are kept; with it, only the ids that the second pass's windows read (another
  // kernel or noise traces again).
  const bool animated = keep && this->Animate;
  const bool keepRuns = keep && (!animated || enhanced);
  const int secondSteps = std::max(1, this->NumberOfSteps / 2);
  const int keepSteps = animated && enhanced ? secondSteps : 0;
  const bool linesValid = keep && cache.LinesKey == linesKey;
  const bool haveRuns = linesValid && !cache.TileRuns.empty();
  const bool wholeRuns = haveRuns && cache.RunSteps >= this->NumberOfSteps;
  vtkOFBLICKernelParts parts;
  vtkOFBLICCacheKey momentsKey;
  bool recombine = false;
  if (animated)
  {
    parts.Set(
      this->ComputeKernel(this->NumberOfSteps, false), this->NumberOfSteps, this->AnimationPhase);
    momentsKey.Add(linesKey)
      .Add(cache.NoiseKey)
      .Add(static_cast<double>(this->KernelType))
      .Add(this->OrientedLIC ? 1.0 : 0.0);
    recombine = linesValid && cache.MomentsKey == momentsKey && (haveRuns || !keepRuns);
  }
  const bool trace = !wholeRuns && !recombine;
  if (!keep)
  {
    cache.LinesKey = vtkOFBLICCacheKey();
    cache.ReleaseLines();
  }
  else if (trace)
  {
    cache.LinesKey = vtkOFBLICCacheKey();
  }
  if (trace && this->NumberOfSteps > 0)
  {
    this->LastRecomputed |= RECOMPUTED_STREAMLINES;
  }
  vtkDebugMacro(
    "Recomputed:" << (this->LastRecomputed & RECOMPUTED_STRUCTURE ? " structure" : "")
                  << (this->LastRecomputed & RECOMPUTED_SAMPLES ? " samples" : "")
                  << (this->LastRecomputed & RECOMPUTED_NOISE ? " noise" : "")
                  << (this->LastRecomputed & RECOMPUTED_STREAMLINES ? " streamlines" : "")
                  << "; convolved.");
  cache.MomentsKey = vtkOFBLICCacheKey();
  vtkOFBLICBuffer<float>& values = cache.Values;
  values.resize(n);
  if (!this->Internals->Convolve(this,
        tracer,
        keep,
        trace,
        keepRuns,
        keepSteps,
        weights,
        animated ? &parts : nullptr,
        recombine,
        cache.Noise.data(),
        values.data(),
        0.05,
        enhanced ? 0.5 : 0.95))
  {
    return false;
  }
  if (keep)
  {
    cache.LinesKey = linesKey;
  }
  if (animated)
  {
    cache.MomentsKey = momentsKey;
  }
  if (enhanced && !this->ComputeEnhancedPass(input, tracer, keep, secondSteps))
  {
    return false;
  }
  if (this->EnhanceContrast == ENHANCE_CONTRAST_LIC ||
    this->EnhanceContrast == ENHANCE_CONTRAST_BOTH)
  {
    vtkOFBLICStretch(values.data(),
      n,
      cache.Mask.data(),
      this->LowLICContrastEnhancementFactor,
      this->HighLICContrastEnhancementFactor,
      this->Reduction);
  }

  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBLIC::ComputeEnhancedPass(vtkOFB* input,
  const vtkOFBLICTracer& tracer,
  bool keep,
  int secondSteps)
{
  const vtkIdType n = input->GetNumberOfSamples();
  vtkOFBLICCache& cache = this->Internals->Cache;
  vtkOFBLICBuffer<float>& values = cache.Values;
  vtkOFBLICHighPass(input, cache, this->Reduction);
  vtkOFBLICBuffer<float>& pass1 = cache.Scratch;
  pass1.swap(values);
  values.resize(n);
  // Half the steps each way, as VTK's second pass (its input is smooth along the flow).
  vtkOFBLICTracer second = tracer;
  second.NumberOfSteps = secondSteps;
  const std::vector<double> weights2 = this->ComputeKernel(second.NumberOfSteps);
  if (!this->Internals->Convolve(this,
        second,
        keep,
        false,
        true,
        0,
        weights2,
        nullptr,
        false,
        pass1.data(),
        values.data(),
        0.5,
        0.95))
  {
    return false;
  }
  // The second pass stretched to the full range as the first (its quantiles
  // vtkOFBLICFinalStretchTail and 1 - vtkOFBLICFinalStretchTail to 0 and 1): a LIC
  // averages its input, so without this it would span about half of [0, 1].
  vtkOFBLICStretchTails(
    values.data(), n, cache.Mask.data(), vtkOFBLICFinalStretchTail, this->Reduction);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBLIC::CopySettingsToLevel(vtkOFBLIC*) {}

//------------------------------------------------------------------------------
void vtkOFBLIC::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "StepSize: " << this->StepSize << " cells\n";
  os << indent << "NormalizeVectors: " << (this->NormalizeVectors ? "On" : "Off") << "\n";
  os << indent << "FieldInterpolation: " << this->FieldInterpolation << "\n";
  os << indent << "KernelType: " << this->KernelType << "\n";
  os << indent << "OrientedLIC: " << (this->OrientedLIC ? "On" : "Off") << "\n";
  os << indent << "Animate: " << (this->Animate ? "On" : "Off") << "\n";
  os << indent << "AnimationPhase: " << this->AnimationPhase << "\n";
  os << indent << "NoiseType: " << this->NoiseType << "\n";
  os << indent << "NoiseGrainSize: " << this->NoiseGrainSize << " cells\n";
  os << indent << "MinNoiseValue: " << this->MinNoiseValue << "\n";
  os << indent << "MaxNoiseValue: " << this->MaxNoiseValue << "\n";
  os << indent << "NumberOfNoiseLevels: " << this->NumberOfNoiseLevels << "\n";
  os << indent << "ImpulseNoiseProbability: " << this->ImpulseNoiseProbability << "\n";
  os << indent << "ImpulseNoiseBackgroundValue: " << this->ImpulseNoiseBackgroundValue << "\n";
  os << indent << "NoiseGeneratorSeed: " << this->NoiseGeneratorSeed << "\n";
  os << indent << "NoiseArrayName: " << (this->NoiseArrayName ? this->NoiseArrayName : "(none)")
     << "\n";
  os << indent << "EnhancedLIC: " << (this->EnhancedLIC ? "On" : "Off") << "\n";
  os << indent << "EnhanceContrast: " << this->EnhanceContrast << "\n";
  os << indent << "LowLICContrastEnhancementFactor: " << this->LowLICContrastEnhancementFactor
     << "\n";
  os << indent << "HighLICContrastEnhancementFactor: " << this->HighLICContrastEnhancementFactor
     << "\n";
  os << indent << "MaskThreshold: " << this->MaskThreshold << "\n";
  os << indent << "MaskOnSurface: " << (this->MaskOnSurface ? "On" : "Off") << "\n";
  os << indent << "MaskColor: (" << this->MaskColor[0] << ", " << this->MaskColor[1] << ", "
     << this->MaskColor[2] << ")\n";
  os << indent << "MaskIntensity: " << this->MaskIntensity << "\n";
  os << indent << "CacheStreamlines: " << (this->CacheStreamlines ? "On" : "Off") << "\n";
  os << indent << "StreamlineReuseDistance: " << this->StreamlineReuseDistance << " cells\n";
  os << indent << "NumberOfMaskedSamples: " << this->NumberOfMaskedSamples << "\n";
  os << indent << "LastRecomputed: " << this->LastRecomputed << "\n";
  os << indent << "LastExecutionTime: " << this->LastExecutionTime << " ms\n";
}
