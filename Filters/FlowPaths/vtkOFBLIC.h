/**
 * @class   vtkOFBLIC
 * @brief   Line integral convolution of a tangent vector field on the samples of a vtkOFB
 *
 * vtkOFBLIC computes a line integral convolution (LIC) value at every sample of its
 * input OFB (paper "Sample-based Surface Coloring", section 6.2.3, Eq. 4, Fig. 10):
 * noise is averaged, with a kernel, along the streamline of a tangent vector field
 * traced forward and backward from the sample over the surface. The result is on the
 * surface, not on the screen: computed once, it stays attached to the surface when the
 * camera moves (VTK's vtkSurfaceLICInterface works in image space and recomputes every
 * frame).
 *
 * Output: the input OFB (its arrays shared, not copied) with two sample arrays added:
 * - "LIC" (float, one component, in [0, 1]) at every sample;
 * - "LICMask" (unsigned char, 1 where the field is masked, else 0), for a mapper that
 *   blends MaskColor by MaskIntensity as VTK does. At masked samples "LIC" holds
 *   mix(1, luminance(MaskColor), MaskIntensity), so that a display that multiplies a
 *   colour by LIC shows VTK's masked colour for a grey MaskColor.
 *
 * The field: a 3-component sample array chosen with SetInputArrayToProcess(0, 0, 0,
 * vtkDataObject::FIELD_ASSOCIATION_POINTS, name); by default the active vectors of the
 * sample data (vtkOFBSampler writes the input's vector field there, projected into the
 * tangent plane with ProjectVectors). Its component along the sample normal ("Normals",
 * the active normals) is removed here in any case.
 *
 * Streamlines are traced in 3-D (see vtkOFBLICTracer.h): a step moves the position
 * by the field, looks up the nearest sample (vtkOFB::FindSample, else
 * vtkOFB::FindClosestSample) and projects the position onto its tangent plane, so a
 * streamline continues across the three grids and over edges of the surface. The
 * noise is a function of the 3-D position (a lattice of NoiseGrainSize cells), so it
 * is the same wherever grids meet. Together: no seam where the samples change grid.
 *
 * VTK's surface LIC settings that compute the LIC keep their names and meanings here
 * (step size and grain in OFB cells instead of pixels). How the LIC is combined with a
 * colour (VTK's ColorMode, LICIntensity, MapModeBias, the colour part of EnhanceContrast
 * with its colour factors) is not computed here: it is a vtkOFBColoring's, which
 * vtkOFBPolyDataMapper (display) and vtkOFBMapToColors (export) read.
 *
 * Tracing is fast LIC (Stalling and Hege): the samples are taken tile by tile (the
 * samples of all three grids in a cube of 64 x 64 x 64 cells); from each sample of the
 * tile not yet given a streamline, a longer one is traced both ways, and every sample
 * of the tile that it passes within StreamlineReuseDistance across the flow (0.05
 * cells) gets the NumberOfSteps steps each way around that meeting as its streamline.
 * Each way goes on while it keeps meeting samples it can give a streamline to (at most
 * 10 NumberOfSteps steps) and stops NumberOfSteps steps after the last such sample.
 * Each sample's streamline thus runs within 0.05 cells of its own position, where the
 * sample's own streamline runs, and reads almost the same samples: the LIC correlates
 * about 0.96 with the one traced from every sample, with no dashes where neighbours'
 * streamlines come from different long ones and no seams at the tile planes, for about
 * NumberOfSteps traced steps a sample instead of 2 NumberOfSteps. Tiles are
 * independent, so the result does not depend on the number of threads.
 *
 * Streamlines are traced once and kept (CacheStreamlines, default on): an update that
 * changes only the kernel, AnimationPhase, the noise or the enhancement re-convolves by
 * reading the kept streamlines instead of tracing them again, which makes an animation
 * frame many times cheaper than the first computation. What is kept, per sample: the
 * seed streamlines as sample ids (4 bytes each, about NumberOfSteps + 1 a sample: each
 * sample's streamline is a window of one of them) and the sample's place in them (4
 * bytes); with Animate on, the three sums of its window that another AnimationPhase
 * combines without reading the streamlines (16 bytes; see docs/lic.md). With Animate on
 * and EnhancedLIC off a new AnimationPhase reads only these sums, so the seed
 * streamlines are read tile by tile as they are traced and not kept; with Animate and
 * EnhancedLIC on only their ids that the second pass's windows read are kept (in both
 * cases another kernel or noise traces again); 40 bytes of
 * packed position, normal and field, 1 byte of mask, 4 of noise and 4 of the tiles'
 * sample lists, plus 9 bytes of work buffers; with EnhancedLIC also the
 * high-pass's neighbours of each sample (17 bytes: a count and up to 8 offsets), found
 * once, so that an enhanced re-convolution does not search them again. The streamlines
 * are traced again when the input's structure, field or normals array (pointer or
 * MTime), NumberOfSteps, StepSize, NormalizeVectors, FieldInterpolation,
 * StreamlineReuseDistance, MaskThreshold or MaskOnSurface change. With CacheStreamlines
 * off only the packed samples, mask, noise, tile lists and work buffers are kept (57
 * bytes a sample), every update traces again, and every sample traces its own
 * streamline from its own position (the plain LIC: about twice the steps of fast LIC,
 * and none kept). GetCacheMemorySize() gives what is held.
 *
 * The convolution runs with vtkSMPTools; every sample is computed independently, so the
 * result is the same for any number of threads. Progress events (in steps of about
 * 1 % of a pass) are sent and AbortExecute is honoured between tiles, by the thread that
 * called Update (an aborted run gives an empty output).
 *
 * Bad input: no field array, a field without 3 components or an input without
 * "Normals": an error and an empty output. NaN and zero vectors are masked; a field
 * masked everywhere gives a warning and LIC equal to the mask value everywhere. A
 * StepSize that is not positive or not finite gives an error and an empty output. An
 * empty OFB gives an empty OFB with empty "LIC" and "LICMask" arrays.
 *
 * @sa vtkOFB vtkOFBSampler vtkOFBPolyDataMapper
 */

#ifndef vtkOFBLIC_h
#define vtkOFBLIC_h

#include "vtkOFBAlgorithm.h"
#include "vtkOFBFlowPathsModule.h" // for export macro

#include <vector> // for the prepared field

class vtkDataArray;
class vtkOFBLICReduction;
class vtkOFBLICTracer;

class VTKOFBFLOWPATHS_EXPORT vtkOFBLIC : public vtkOFBAlgorithm
{
public:
  static vtkOFBLIC* New();
  vtkTypeMacro(vtkOFBLIC, vtkOFBAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Convolution kernels over the streamline (KernelType).
  enum KernelTypes
  {
    KERNEL_BOX = 0,
    KERNEL_GAUSSIAN = 1,
    KERNEL_HANN = 2
  };

  /// How the field is read along a streamline (FieldInterpolation).
  enum FieldInterpolations
  {
    FIELD_NEAREST = 0,
    FIELD_INVERSE_DISTANCE = 1
  };

  /// Noise distributions (NoiseType), as vtkSurfaceLICInterface.
  enum NoiseTypes
  {
    NOISE_TYPE_UNIFORM = 0,
    NOISE_TYPE_GAUSSIAN = 1,
    NOISE_TYPE_PERLIN = 2
  };

  /// EnhanceContrast modes, as vtkSurfaceLICInterface.
  enum EnhanceContrastModes
  {
    ENHANCE_CONTRAST_OFF = 0,
    ENHANCE_CONTRAST_LIC = 1,
    ENHANCE_CONTRAST_COLOR = 3,
    ENHANCE_CONTRAST_BOTH = 4
  };

  ///@{
  /**
   * Integration steps in each direction (default 20, as VTK; 0..10000). 0 gives the
   * noise back.
   */
  vtkSetClampMacro(NumberOfSteps, int, 0, 10000);
  vtkGetMacro(NumberOfSteps, int);
  ///@}

  ///@{
  /**
   * Length of a step in OFB cells (default 1, as VTK's one pixel: a step reaches about
   * the next sample). Must be positive and finite; other values give an error at update
   * time. With NormalizeVectors off it is the step where the field is strongest.
   */
  vtkSetMacro(StepSize, double);
  vtkGetMacro(StepSize, double);
  ///@}

  ///@{
  /**
   * Normalize the field during integration (default on, as VTK): every step covers
   * StepSize cells. Off: a step covers StepSize cells times |v| / max |v| (max over the
   * samples not masked), so streaks are shorter where the flow is slow.
   */
  vtkSetMacro(NormalizeVectors, bool);
  vtkGetMacro(NormalizeVectors, bool);
  vtkBooleanMacro(NormalizeVectors, bool);
  ///@}

  ///@{
  /**
   * How a step reads the field: FIELD_NEAREST (default: the vector of the sample the
   * streamline is at) or FIELD_INVERSE_DISTANCE (Shepard weights over the samples
   * within 1.5 cells on the same side of the surface: smoother streamlines where the
   * field turns, about three times the cost).
   */
  vtkSetClampMacro(FieldInterpolation, int, FIELD_NEAREST, FIELD_INVERSE_DISTANCE);
  vtkGetMacro(FieldInterpolation, int);
  void SetFieldInterpolationToNearest() { this->SetFieldInterpolation(FIELD_NEAREST); }
  void SetFieldInterpolationToInverseDistance()
  {
    this->SetFieldInterpolation(FIELD_INVERSE_DISTANCE);
  }
  ///@}

  ///@{
  /**
   * Kernel k(t) of Eq. 4 over the 2 NumberOfSteps + 1 steps: KERNEL_BOX (default, as
   * VTK's convolution), KERNEL_GAUSSIAN (standard deviation half the half-length) or
   * KERNEL_HANN (raised cosine).
   */
  vtkSetClampMacro(KernelType, int, KERNEL_BOX, KERNEL_HANN);
  vtkGetMacro(KernelType, int);
  void SetKernelTypeToBox() { this->SetKernelType(KERNEL_BOX); }
  void SetKernelTypeToGaussian() { this->SetKernelType(KERNEL_GAUSSIAN); }
  void SetKernelTypeToHann() { this->SetKernelType(KERNEL_HANN); }
  ///@}

  ///@{
  /**
   * Oriented LIC (default off): the kernel is multiplied by a ramp rising from 0 at the
   * backward end to 1 at the forward end, so that each noise spot draws a streak that
   * brightens along the flow and ends sharply: the streaks show the direction, not only
   * the orientation. Works best with sparse noise (ImpulseNoiseProbability about 0.1).
   */
  vtkSetMacro(OrientedLIC, bool);
  vtkGetMacro(OrientedLIC, bool);
  vtkBooleanMacro(OrientedLIC, bool);
  ///@}

  ///@{
  /**
   * Animation (default off): the kernel is multiplied by a ripple
   * (1 + cos(2 pi (s / NumberOfSteps + AnimationPhase))) / 2 over step s, whose crests
   * move forward along the flow as AnimationPhase grows (Forssell and Cohen's periodic
   * motion filter). AnimationPhase is in periods (default 0): 0 and 1 give the same
   * result, so a loop from 0 to 1 in equal steps repeats smoothly.
   */
  vtkSetMacro(Animate, bool);
  vtkGetMacro(Animate, bool);
  vtkBooleanMacro(Animate, bool);
  vtkSetMacro(AnimationPhase, double);
  vtkGetMacro(AnimationPhase, double);
  ///@}

  ///@{
  /**
   * Generated noise (as vtkSurfaceLICInterface with GenerateNoiseTexture): NoiseType
   * (default NOISE_TYPE_GAUSSIAN), NoiseGrainSize (edge of a noise lattice cell, in OFB
   * cells, default 1), MinNoiseValue / MaxNoiseValue (range, default 0 and 0.8),
   * NumberOfNoiseLevels (default 256), ImpulseNoiseProbability (default 1: every
   * lattice cell drawn; below 1 the others get ImpulseNoiseBackgroundValue, default 0)
   * and NoiseGeneratorSeed (default 1).
   */
  vtkSetClampMacro(NoiseType, int, NOISE_TYPE_UNIFORM, NOISE_TYPE_PERLIN);
  vtkGetMacro(NoiseType, int);
  vtkSetClampMacro(NoiseGrainSize, double, 0.01, 1.0e6);
  vtkGetMacro(NoiseGrainSize, double);
  vtkSetClampMacro(MinNoiseValue, double, 0.0, 1.0);
  vtkGetMacro(MinNoiseValue, double);
  vtkSetClampMacro(MaxNoiseValue, double, 0.0, 1.0);
  vtkGetMacro(MaxNoiseValue, double);
  vtkSetClampMacro(NumberOfNoiseLevels, int, 1, 1 << 24);
  vtkGetMacro(NumberOfNoiseLevels, int);
  vtkSetClampMacro(ImpulseNoiseProbability, double, 0.0, 1.0);
  vtkGetMacro(ImpulseNoiseProbability, double);
  vtkSetClampMacro(ImpulseNoiseBackgroundValue, double, 0.0, 1.0);
  vtkGetMacro(ImpulseNoiseBackgroundValue, double);
  vtkSetMacro(NoiseGeneratorSeed, int);
  vtkGetMacro(NoiseGeneratorSeed, int);
  ///@}

  ///@{
  /**
   * Take the noise from a sample array instead of generating it (VTK's NoiseDataSet):
   * its first component, values used as given (expected in [0, 1]). Default none
   * (generate). A name that is not a sample array gives an error.
   */
  vtkSetStringMacro(NoiseArrayName);
  vtkGetStringMacro(NoiseArrayName);
  ///@}

  ///@{
  /**
   * Enhanced LIC (default on, as VTK): a second convolution of the first pass's result,
   * as VTK's vtkLineIntegralConvolution2D does it: the first pass stretched to [0, 1],
   * high-pass filtered (the sample plus three times its difference to the mean of the
   * samples within 1.5 cells) and clamped to [0, 1], which sharpens the streaks and gives
   * them the full range; the second pass takes half the steps each way (NumberOfSteps /
   * 2, at least 1): its input is already smooth along the flow. The stretch maps the
   * first pass's quantiles 0.1 % and 99.9 % (VTK maps its minimum and maximum, which here
   * are those of the few samples whose streamlines are short), so that the LIC spans
   * [0, 1] without another stretch: its 1st and 99th percentiles are within 0.02 of 0 and
   * 1 with the default noise. Off: the LIC is the first pass, an average of many noise
   * values, of a narrow range (about 0.35 to 0.45 with the default noise) unless
   * EnhanceContrast stretches it.
   */
  vtkSetMacro(EnhancedLIC, bool);
  vtkGetMacro(EnhancedLIC, bool);
  vtkBooleanMacro(EnhancedLIC, bool);
  ///@}

  ///@{
  /**
   * Contrast enhancement (default ENHANCE_CONTRAST_OFF, as VTK: with EnhancedLIC the
   * LIC has the full range already), as VTK: with _LIC or _BOTH the final LIC is
   * stretched, L = (L - m) / (M - m), where m = min + Low * (max - min) and
   * M = max - High * (max - min) over the samples not masked, with Low and High the
   * LIC factors (default 0); the colour part of _COLOR and _BOTH (the lightness of the
   * final colour) is the display's: a vtkOFBColoring's EnhanceColorContrast with its
   * colour factors. Another mode, or a factor outside [0, 1] (NaN included), is an error
   * at update time.
   */
  vtkSetMacro(EnhanceContrast, int);
  vtkGetMacro(EnhanceContrast, int);
  vtkSetMacro(LowLICContrastEnhancementFactor, double);
  vtkGetMacro(LowLICContrastEnhancementFactor, double);
  vtkSetMacro(HighLICContrastEnhancementFactor, double);
  vtkGetMacro(HighLICContrastEnhancementFactor, double);
  ///@}

  ///@{
  /**
   * Masking, as VTK: samples where |v| < MaskThreshold (default 0, in the field's units)
   * are masked; with MaskOnSurface (default off) |v| is that of the tangential part,
   * else of the field as given. Zero and non-finite vectors are always masked.
   * Streamlines stop at masked samples. MaskColor (default grey 0.5) and MaskIntensity
   * (default 0) say how a display shows them (see the class description).
   */
  vtkSetMacro(MaskThreshold, double);
  vtkGetMacro(MaskThreshold, double);
  vtkSetMacro(MaskOnSurface, bool);
  vtkGetMacro(MaskOnSurface, bool);
  vtkBooleanMacro(MaskOnSurface, bool);
  vtkSetVector3Macro(MaskColor, double);
  vtkGetVector3Macro(MaskColor, double);
  vtkSetClampMacro(MaskIntensity, double, 0.0, 1.0);
  vtkGetMacro(MaskIntensity, double);
  ///@}

  ///@{
  /**
   * Keep the traced streamlines between updates (default on), so that a new
   * AnimationPhase, kernel, noise or enhancement re-convolves without tracing (see the
   * class description for the memory: about NumberOfSteps + 1 ids of 4 bytes a sample).
   * Turn it off for an OFB too large to keep them; every update then traces again, and
   * every sample its own streamline (about twice the steps of the default).
   */
  vtkSetMacro(CacheStreamlines, bool);
  vtkGetMacro(CacheStreamlines, bool);
  vtkBooleanMacro(CacheStreamlines, bool);
  ///@}

  ///@{
  /**
   * How far across the flow, in cells, a streamline traced through another sample may
   * pass a sample and still be read as that sample's streamline (fast LIC, with
   * CacheStreamlines on; default 0.05). A window of a streamline half a cell aside reads
   * other samples at about a third of its steps, so that neighbours whose windows come
   * from different streamlines differ more than neighbours on one: dashes along the
   * streaks and seams at the tile planes. At 0.05 the LIC correlates about 0.96 with
   * the one traced from every sample and shows neither, for about NumberOfSteps traced
   * steps a sample; 1 reads every sample met (about 3.3 steps a sample, 2 to 3 times
   * faster to compute, with the dashes); 0 traces every sample's own streamline
   * and keeps it (2 NumberOfSteps steps a sample).
   */
  vtkSetClampMacro(StreamlineReuseDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(StreamlineReuseDistance, double);
  ///@}

  /**
   * Memory held between updates (kept streamlines, packed samples, noise, work
   * buffers), in KiB (vtkDataObject's convention).
   */
  unsigned long GetCacheMemorySize() const;

  /**
   * Release what is kept between updates (the next update computes everything again).
   */
  void ReleaseCache();

  /**
   * Samples masked by the last update.
   */
  vtkGetMacro(NumberOfMaskedSamples, vtkIdType);

  /// What an update computed again rather than took from the cache (bits of LastRecomputed).
  enum RecomputedParts
  {
    RECOMPUTED_STRUCTURE = 1,  ///< the input's structure changed (not the same frame and samples)
    RECOMPUTED_SAMPLES = 2,    ///< the samples' field packed again (a new field or mask)
    RECOMPUTED_NOISE = 4,      ///< the noise (it depends on the structure and noise settings)
    RECOMPUTED_STREAMLINES = 8 ///< the streamlines traced again (CacheStreamlines)
  };

  /**
   * What the last update computed again, a combination of RecomputedParts; the
   * convolution itself is always done. A new time step of the same surface through
   * vtkOFBSampler's attribute-only re-sampling keeps the input's structure: the
   * noise is kept, the field is packed and the streamlines traced again
   * (RECOMPUTED_SAMPLES | RECOMPUTED_STREAMLINES). With the debug flag on, each
   * update says so.
   */
  vtkGetMacro(LastRecomputed, int);

  /**
   * Wall-clock time of the last update (ms).
   */
  vtkGetMacro(LastExecutionTime, double);

  /**
   * Settings beyond the LIC's own that the LIC of a coarser level of a pyramid takes
   * from this one (vtkOFBLICPyramid copies the LIC settings, then calls this on the
   * level's LIC, an instance of this class made with NewInstance()): a subclass's. The
   * default does nothing; vtkOFBPLIC gives its controller and LevelGhostSamples.
   */
  virtual void CopySettingsToLevel(vtkOFBLIC* level);

protected:
  vtkOFBLIC();
  ~vtkOFBLIC() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// False, with an error, when StepSize or the contrast enhancement settings are bad.
  bool CheckSettings();

  /// The field array chosen with SetInputArrayToProcess (error and null if bad).
  vtkDataArray* FindField(vtkOFB* input);

  /// FindField, and the sample normals into `normals`: null, with an error, if either
  /// is missing or bad.
  vtkDataArray* FindFieldAndNormals(vtkOFB* input, vtkDataArray*& normals);

  /// The tracer of this filter's settings over the prepared samples of `input`.
  void SetUpTracer(vtkOFB* input, vtkOFBLICTracer& tracer);

  /**
   * The LIC of the prepared cache into its Values: the first pass (Eq. 4, tracing or
   * re-convolving the kept streamlines), then ComputeEnhancedPass and the contrast
   * stretch. False when aborted.
   */
  bool ComputeLIC(vtkOFB* input);

  /**
   * EnhancedLIC's second pass over the first pass in the cache's Values: high-pass,
   * convolution with `secondSteps` steps each way along the kept streamlines (`keep`)
   * or traced ones, stretch to the full range. False when aborted.
   */
  bool ComputeEnhancedPass(vtkOFB* input,
    const vtkOFBLICTracer& tracer,
    bool keep,
    int secondSteps);

  /**
   * The packed samples, mask and noise in the cache, computed again only where what
   * they depend on changed. False on error.
   */
  bool Prepare(vtkOFB* input, vtkDataArray* vectors, vtkDataArray* normals);

  /**
   * The packed samples (position in cells from the origin, unit normal, tangential
   * field, grid and mask flags) and the mask, into the cache. Returns the number of
   * masked samples.
   */
  vtkIdType PrepareSamples(vtkOFB* input, vtkDataArray* vectors, vtkDataArray* normals);

  /// The noise of every sample into the cache: generated, or from NoiseArrayName.
  /// False on error.
  bool PrepareNoise(vtkOFB* input);

  /// The kernel's 2 n + 1 weights for n steps each way (index n is t = 0); without
  /// `animation`, without the factor of Animate.
  std::vector<double> ComputeKernel(int n, bool animation = true) const;

  /// The input's arrays shared, with "LIC" (values clamped, the mask value where masked)
  /// and "LICMask" added.
  void WriteOutput(vtkOFB* input,
    vtkOFB* output,
    const float* values,
    const unsigned char* mask,
    vtkIdType n);

  int NumberOfSteps;
  double StepSize;
  bool NormalizeVectors;
  int FieldInterpolation;
  int KernelType;
  bool OrientedLIC;
  bool Animate;
  double AnimationPhase;
  int NoiseType;
  double NoiseGrainSize;
  double MinNoiseValue;
  double MaxNoiseValue;
  int NumberOfNoiseLevels;
  double ImpulseNoiseProbability;
  double ImpulseNoiseBackgroundValue;
  int NoiseGeneratorSeed;
  char* NoiseArrayName;
  bool EnhancedLIC;
  int EnhanceContrast;
  double LowLICContrastEnhancementFactor;
  double HighLICContrastEnhancementFactor;
  double MaskThreshold;
  bool MaskOnSurface;
  double MaskColor[3];
  double MaskIntensity;
  bool CacheStreamlines;
  double StreamlineReuseDistance;
  vtkIdType NumberOfMaskedSamples;
  int LastRecomputed;
  vtkMTimeType LastStructureMTime;
  double LastExecutionTime;

  /**
   * Combines the statistics of the contrast stretches with those of other processes
   * (see vtkOFBLICReduction); null (the default) for one process. A distributed
   * subclass (vtkOFBPLIC) sets it for the time of its RequestData.
   */
  vtkOFBLICReduction* Reduction;

  /**
   * With NormalizeVectors off, the magnitude the field is divided by: when positive,
   * the largest tangential magnitude of every process's samples (set by vtkOFBPLIC);
   * 0 (the default): the largest of this OFB's samples.
   */
  double FieldScale;

private:
  vtkOFBLIC(const vtkOFBLIC&) = delete;
  void operator=(const vtkOFBLIC&) = delete;

  // What is kept between updates (packed samples, noise, streamlines, work buffers) and
  // the convolution passes that use it (vtkOFBLICInternals.h).
  struct vtkInternals;
  vtkInternals* Internals;
};

#endif
