// GoogleTest units of vtkOFBLIC: streaks along the field on a plane and across the
// grids of a sphere, determinism, noise, masking, animation and progress (bad input:
// TestOFBLICInputs.cxx).
#include "vtkOFBLICTestHelpers.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICTracer.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTriangleFilter.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>

using namespace vtkofbtest;

namespace
{

/// The filter run on 1 thread, then again on 2 (the SMP default restored after).
void RunOnOneAndTwoThreads(vtkOFBLIC* lic,
  vtkOFB* ofb,
  vtkSmartPointer<vtkOFB>& one,
  vtkSmartPointer<vtkOFB>& two)
{
  vtkSMPTools::Initialize(1);
  one = RunLIC(lic, ofb);
  vtkSMPTools::Initialize(2);
  lic->Modified();
  two = RunLIC(lic, ofb);
  vtkSMPTools::Initialize(0);
}

// Whether two outputs have the same number of samples and bit-identical LIC arrays.
bool SameLIC(vtkOFB* a, vtkOFB* b)
{
  const vtkIdType n = a->GetNumberOfSamples();
  const float* la = LICValues(a);
  const float* lb = LICValues(b);
  return la && lb && n == b->GetNumberOfSamples() && std::memcmp(la, lb, n * sizeof(float)) == 0;
}
}

//------------------------------------------------------------------------------
TEST(LIC, FlatSquareUniformFieldGivesStreaksAlongTheField)
{
  const double angle = vtkMath::RadiansFromDegrees(30.0);
  const double dir[3] = { std::cos(angle), std::sin(angle), 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 256, UniformField(dir));
  ASSERT_GT(ofb->GetNumberOfSamples(), 50000);
  for (bool enhanced : { false, true })
  {
    vtkNew<vtkOFBLIC> lic;
    lic->SetEnhancedLIC(enhanced);
    vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
    ASSERT_EQ(out->GetNumberOfSamples(), ofb->GetNumberOfSamples());
    const float* values = LICValues(out);
    ASSERT_NE(values, nullptr);
    const double across[3] = { -dir[1], dir[0], 0.0 };
    const double s = ofb->GetCellSize();
    const Correlation along4 = Autocorrelation(out, values, dir, 4.0 * s, 30.0 * s);
    const Correlation across4 = Autocorrelation(out, values, across, 4.0 * s, 30.0 * s);
    std::cout << "enhanced " << enhanced << ": along " << along4.Value << ", across "
              << across4.Value << " (" << along4.Pairs << " pairs)\n";
    EXPECT_GT(along4.Pairs, 20000);
    EXPECT_GT(along4.Value, 0.5);
    EXPECT_GE(along4.Value, 5.0 * std::fabs(across4.Value));
  }
}

//------------------------------------------------------------------------------
TEST(LIC, PipeWithBumpHasATangentSwirlOnEveryGrid)
{
  // The pipe of the LIC quality measures: samples on all three grids, and a flow that the
  // sampler keeps (its tangential part) almost whole, since it runs along the wall.
  vtkSmartPointer<vtkPolyData> pipe = MakePipeWithBump(128, 128);
  vtkSmartPointer<vtkOFB> ofb = Build(pipe, 256);
  ASSERT_GT(ofb->GetNumberOfSamples(), 0);
  vtkIdType perAxis[3] = { 0, 0, 0 };
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    ++perAxis[ofb->GetSampleAxis(i)];
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_GT(perAxis[axis], ofb->GetNumberOfSamples() / 100) << "axis " << axis;
  }
  vtkDataArray* flow = ofb->GetSampleData()->GetVectors();
  ASSERT_NE(flow, nullptr);
  double kept = 0.0, total = 0.0;
  for (vtkIdType p = 0; p < pipe->GetNumberOfPoints(); ++p)
  {
    total += vtkMath::Norm(pipe->GetPointData()->GetVectors()->GetTuple3(p));
  }
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    kept += vtkMath::Norm(flow->GetTuple3(i));
  }
  EXPECT_GT(kept / ofb->GetNumberOfSamples(), 0.9 * total / pipe->GetNumberOfPoints());
}

TEST(LIC, EnhancedSecondPassTakesHalfTheSteps)
{
  // EnhancedLIC written out with the filter's public pieces: a first LIC of 10 steps,
  // stretched so that its quantiles 0.1 % and 99.9 % go to 0 and 1, its high-pass (the
  // sample plus three times its difference to the mean of the samples within 1.5 cells)
  // clamped to [0, 1], then a LIC of that as noise with 5 steps (as VTK's second pass,
  // half the steps). Without kept streamlines every sample traces its own, so both ways
  // read the same streamlines.
  const double angle = vtkMath::RadiansFromDegrees(30.0);
  const double dir[3] = { std::cos(angle), std::sin(angle), 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 128, UniformField(dir));
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 10000);
  auto run = [](vtkOFB* input, int steps, bool enhanced, const char* noise)
  {
    vtkNew<vtkOFBLIC> lic;
    lic->SetNumberOfSteps(steps);
    lic->SetEnhancedLIC(enhanced);
    lic->CacheStreamlinesOff();
    lic->SetNoiseArrayName(noise);
    return RunLIC(lic, input);
  };
  vtkSmartPointer<vtkOFB> enhanced = run(ofb, 10, true, nullptr);
  vtkSmartPointer<vtkOFB> first = run(ofb, 10, false, nullptr);
  const float* first1 = LICValues(first);
  ASSERT_NE(first1, nullptr);
  std::vector<double> sorted(first1, first1 + n);
  std::sort(sorted.begin(), sorted.end());
  const double q0 = sorted[static_cast<std::size_t>(0.001 * n)];
  const double q1 = sorted[static_cast<std::size_t>(0.999 * n)];
  ASSERT_GT(q1, q0);
  std::vector<double> p(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    p[i] = std::min(1.0, std::max(0.0, (first1[i] - q0) / (q1 - q0)));
  }
  std::vector<double> highPass(n);
  const double radius = 1.5 * ofb->GetCellSize();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    double sum = 0.0;
    int count = 0;
    ofb->ForEachSampleInSphere(x,
      radius,
      [&](vtkIdType j, double)
      {
        if (j != i)
        {
          sum += p[j];
          ++count;
        }
      });
    ASSERT_GE(count, 3);
    highPass[i] = std::min(1.0, std::max(0.0, p[i] + 3.0 * (p[i] - sum / count)));
  }
  vtkNew<vtkFloatArray> noise;
  noise->SetName("HighPass");
  noise->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    noise->SetValue(i, static_cast<float>(highPass[i]));
  }
  vtkNew<vtkOFB> withNoise;
  withNoise->ShallowCopy(ofb);
  withNoise->GetSampleData()->AddArray(noise);
  const float* e = LICValues(enhanced);
  ASSERT_NE(e, nullptr);
  for (int steps : { 5, 10 })
  {
    vtkSmartPointer<vtkOFB> second = run(withNoise, steps, false, "HighPass");
    const float* q = LICValues(second);
    ASSERT_NE(q, nullptr);
    // The second pass stretched as the filter does: its 0.02 and 0.98 quantiles to 0 and 1.
    std::vector<double> second2(q, q + n);
    std::sort(second2.begin(), second2.end());
    const double s0 = second2[static_cast<std::size_t>(0.02 * n)];
    const double s1 = second2[static_cast<std::size_t>(0.98 * n)];
    ASSERT_GT(s1, s0);
    double largest = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double stretched = std::min(1.0, std::max(0.0, (q[i] - s0) / (s1 - s0)));
      largest = std::max(largest, std::fabs(e[i] - stretched));
    }
    std::cout << "second pass of " << steps << " steps: largest difference " << largest << "\n";
    if (steps == 5)
    {
      // Summation order, and the filter's quantiles read from a histogram (to about 1e-4
      // of the first pass's range) instead of sorted values.
      EXPECT_LT(largest, 1e-3);
    }
    else
    {
      EXPECT_GT(largest, 1e-2); // the whole NumberOfSteps would be another result
    }
  }
}

//------------------------------------------------------------------------------
TEST(LIC, SphereRotationStreaksHaveNoDropWhereTheGridChanges)
{
  const double axis[3] = { 0.0, 0.0, 1.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSphere(1.0, 128), 256, RotationField(axis));
  vtkNew<vtkOFBLIC> lic;
  vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
  ASSERT_EQ(out->GetNumberOfSamples(), ofb->GetNumberOfSamples());
  const float* values = LICValues(out);
  ASSERT_NE(values, nullptr);
  // Samples within 60 degrees of the equator, split by how close they are to a
  // change of grid (the two largest normal components within 0.15 of each other).
  const StreakMeasure switching = SphereStreaks(out, values, axis, true);
  const StreakMeasure elsewhere = SphereStreaks(out, values, axis, false);
  std::cout << "near grid changes: along " << switching.Along << ", across " << switching.Across
            << " (" << switching.Pairs << ")\n"
            << "elsewhere: along " << elsewhere.Along << ", across " << elsewhere.Across << " ("
            << elsewhere.Pairs << ")\n";
  ASSERT_GT(switching.Pairs, 5000);
  ASSERT_GT(elsewhere.Pairs, 5000);
  EXPECT_GE(elsewhere.Along, 5.0 * std::fabs(elsewhere.Across));
  EXPECT_GE(switching.Along, 5.0 * std::fabs(switching.Across));
  EXPECT_GE(switching.Along, 0.9 * elsewhere.Along);
}

//------------------------------------------------------------------------------
TEST(LIC, InverseDistanceFieldGivesStreaksWithoutSeamsToo)
{
  const double axis[3] = { 0.0, 0.0, 1.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSphere(1.0, 64), 128, RotationField(axis));
  vtkNew<vtkOFBLIC> lic;
  lic->SetFieldInterpolationToInverseDistance();
  vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
  const float* values = LICValues(out);
  ASSERT_NE(values, nullptr);
  const StreakMeasure switching = SphereStreaks(out, values, axis, true);
  const StreakMeasure elsewhere = SphereStreaks(out, values, axis, false);
  std::cout << "inverse distance: near grid changes along " << switching.Along << ", across "
            << switching.Across << "; elsewhere along " << elsewhere.Along << ", across "
            << elsewhere.Across << "\n";
  EXPECT_GE(elsewhere.Along, 5.0 * std::fabs(elsewhere.Across));
  EXPECT_GE(switching.Along, 5.0 * std::fabs(switching.Across));
  EXPECT_GE(switching.Along, 0.9 * elsewhere.Along);
}

//------------------------------------------------------------------------------
TEST(LIC, IdenticalWithOneAndTwoThreads)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  const double axis[3] = { 0.3, 1.0, 0.2 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(bunny, 192, RotationField(axis));
  vtkNew<vtkOFBLIC> lic;
  lic->SetNumberOfSteps(10);
  lic->SetNoiseGeneratorSeed(7);
  vtkSmartPointer<vtkOFB> one, two;
  RunOnOneAndTwoThreads(lic, ofb, one, two);
  const vtkIdType n = one->GetNumberOfSamples();
  ASSERT_GT(n, 0);
  ASSERT_EQ(n, two->GetNumberOfSamples());
  EXPECT_TRUE(SameLIC(one, two));
  // Another seed gives another result.
  lic->SetNoiseGeneratorSeed(8);
  vtkSmartPointer<vtkOFB> other = RunLIC(lic, ofb);
  EXPECT_FALSE(SameLIC(one, other));
}

//------------------------------------------------------------------------------
TEST(LIC, LargeBoxWithFewSamplesIsTiledToo)
{
  // A thin ribbon along the diagonal of its box at 1100 cells: 64-cell tiles of the box
  // would be far more than its samples need (vtkOFBLICTiles takes larger ones). The
  // result must not depend on that: the same on 1 and 2 threads, and a re-convolution
  // from the kept streamlines equal to a fresh computation.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(1.0, 1.0, 1.0);
  plane->SetPoint2(0.02, -0.02, 0.0);
  plane->SetResolution(400, 4);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  const double dir[3] = { 1.0, 1.0, 1.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(triangles->GetOutput(), 1100, UniformField(dir));
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 1000);
  const vtkIdType* dims = ofb->GetDimensions();
  const vtkIdType tiles64 = ((dims[0] + 63) / 64) * ((dims[1] + 63) / 64) * ((dims[2] + 63) / 64);
  ASSERT_GT(tiles64, std::max<vtkIdType>(4096, n / 256)); // the case this test is for
  vtkNew<vtkOFBLIC> lic;
  lic->SetNumberOfSteps(10);
  lic->AnimateOn();
  vtkSmartPointer<vtkOFB> one, two;
  RunOnOneAndTwoThreads(lic, ofb, one, two);
  EXPECT_TRUE(SameLIC(one, two));
  const float* values = LICValues(two);
  ASSERT_NE(values, nullptr);
  double sum = 0.0;
  double sum2 = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    ASSERT_GE(values[i], 0.0f);
    ASSERT_LE(values[i], 1.0f);
    sum += values[i];
    sum2 += values[i] * values[i];
  }
  const double mean = sum / n;
  EXPECT_GT(sum2 / n - mean * mean, 1e-3); // a LIC, not a constant
  lic->SetAnimationPhase(0.4);
  vtkSmartPointer<vtkOFB> phase = RunLIC(lic, ofb);
  vtkNew<vtkOFBLIC> fresh;
  fresh->SetNumberOfSteps(10);
  fresh->AnimateOn();
  fresh->SetAnimationPhase(0.4);
  EXPECT_TRUE(SameLIC(phase, RunLIC(fresh, ofb)));
  EXPECT_FALSE(SameLIC(phase, two));
}

//------------------------------------------------------------------------------
TEST(LIC, TracerClosestSampleIsTheOFBs)
{
  // The tracer's fallback lookup is a copy of vtkOFB::FindClosestSample specialised to
  // its radius of sqrt(3) cells (no query planning): it must find the same sample.
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  const double axis[3] = { 0.3, 1.0, 0.2 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(bunny, 96, RotationField(axis));
  ASSERT_GT(ofb->GetNumberOfSamples(), 0);
  vtkOFBLICTracer tracer;
  tracer.SetOFB(ofb);
  tracer.SearchRadius = std::sqrt(3.0) * ofb->GetCellSize();
  double b[6];
  ofb->GetBounds(b);
  vtkMinimalStandardRandomSequence* random = vtkMinimalStandardRandomSequence::New();
  random->SetSeed(11);
  int found = 0;
  for (int k = 0; k < 20000; ++k)
  {
    // Points near samples (most queries find one) and anywhere in the box.
    double q[3];
    const vtkIdType i = static_cast<vtkIdType>(random->GetValue() * ofb->GetNumberOfSamples());
    random->Next();
    ofb->GetSamplePosition(std::min(i, ofb->GetNumberOfSamples() - 1), q);
    for (int c = 0; c < 3; ++c)
    {
      q[c] = k % 4 == 0 ? b[2 * c] + random->GetValue() * (b[2 * c + 1] - b[2 * c])
                        : q[c] + (random->GetValue() - 0.5) * 3.0 * ofb->GetCellSize();
      random->Next();
    }
    const vtkIdType expected = ofb->FindClosestSample(q, tracer.SearchRadius);
    ASSERT_EQ(tracer.FindClosest(glm::dvec3(q[0], q[1], q[2])), expected) << "query " << k;
    found += expected >= 0;
  }
  random->Delete();
  EXPECT_GT(found, 10000); // the comparison covered hits, not only misses
}

//------------------------------------------------------------------------------
TEST(LIC, ZeroStepsGiveTheNoiseBack)
{
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 128, UniformField(dir));
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkFloatArray> noise;
  noise->SetName("MyNoise");
  noise->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    noise->SetValue(i, static_cast<float>((i * 7919) % 1000) / 999.0f);
  }
  ofb->GetSampleData()->AddArray(noise);
  vtkNew<vtkOFBLIC> lic;
  lic->SetNumberOfSteps(0);
  lic->SetNoiseArrayName("MyNoise");
  vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
  ASSERT_EQ(out->GetNumberOfSamples(), n);
  EXPECT_EQ(std::memcmp(LICValues(out), noise->GetPointer(0), n * sizeof(float)), 0);
  // With 20 steps it is no longer the noise.
  lic->SetNumberOfSteps(20);
  out = RunLIC(lic, ofb);
  EXPECT_NE(std::memcmp(LICValues(out), noise->GetPointer(0), n * sizeof(float)), 0);
}

//------------------------------------------------------------------------------
TEST(LIC, GeneratedNoiseHasItsRangeLevelsAndNoSeamBetweenGrids)
{
  const double axis[3] = { 0.0, 0.0, 1.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSphere(1.0, 64), 128, RotationField(axis));
  for (int type :
    { vtkOFBLIC::NOISE_TYPE_UNIFORM, vtkOFBLIC::NOISE_TYPE_GAUSSIAN, vtkOFBLIC::NOISE_TYPE_PERLIN })
  {
    vtkNew<vtkOFBLIC> lic;
    lic->SetNumberOfSteps(0);
    lic->SetNoiseType(type);
    lic->SetNoiseGrainSize(4);
    lic->SetMinNoiseValue(0.2);
    lic->SetMaxNoiseValue(0.6);
    lic->SetNumberOfNoiseLevels(8);
    vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
    const float* values = LICValues(out);
    std::set<float> levels;
    for (vtkIdType i = 0; i < out->GetNumberOfSamples(); ++i)
    {
      levels.insert(values[i]);
      ASSERT_GE(values[i], 0.2f - 1e-6f);
      ASSERT_LE(values[i], 0.6f + 1e-6f);
    }
    EXPECT_LE(levels.size(), 8u) << "noise type " << type;
    EXPECT_GE(levels.size(), 4u) << "noise type " << type;
    // Samples of different grids at (nearly) the same point read the same noise.
    const double seam = FractionEqualAcrossGrids(out, values, 0.3);
    std::cout << "noise type " << type << ": equal across grids " << seam << "\n";
    EXPECT_GT(seam, 0.7) << "noise type " << type;
  }
  // Impulse noise: about the probability of the lattice cells is drawn.
  vtkNew<vtkOFBLIC> impulse;
  impulse->SetNumberOfSteps(0);
  impulse->SetNoiseType(vtkOFBLIC::NOISE_TYPE_UNIFORM);
  impulse->SetMinNoiseValue(0.5);
  impulse->SetMaxNoiseValue(1.0);
  impulse->SetImpulseNoiseProbability(0.1);
  impulse->SetImpulseNoiseBackgroundValue(0.0);
  vtkSmartPointer<vtkOFB> out = RunLIC(impulse, ofb);
  const float* values = LICValues(out);
  vtkIdType drawn = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfSamples(); ++i)
  {
    drawn += values[i] > 0.0f;
  }
  const double fraction = static_cast<double>(drawn) / out->GetNumberOfSamples();
  EXPECT_NEAR(fraction, 0.1, 0.03);
}

//------------------------------------------------------------------------------
TEST(LIC, MaskingWhereTheFieldIsWeak)
{
  vtkSmartPointer<vtkPolyData> square = MakeSquare();
  // A vortex whose speed grows with the distance from the centre (0 there).
  vtkNew<vtkFloatArray> v;
  v->SetName("Flow");
  v->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < square->GetNumberOfPoints(); ++p)
  {
    double x[3];
    square->GetPoint(p, x);
    v->InsertNextTuple3(-x[1], x[0], 0.0);
  }
  square->GetPointData()->SetVectors(v);
  vtkSmartPointer<vtkOFB> ofb = Build(square, 128);
  vtkNew<vtkOFBLIC> lic;
  lic->SetMaskThreshold(0.2);
  lic->SetMaskIntensity(1.0);
  lic->SetMaskColor(0.25, 0.25, 0.25);
  vtkSmartPointer<vtkOFB> out = RunLIC(lic, ofb);
  vtkUnsignedCharArray* mask =
    vtkUnsignedCharArray::SafeDownCast(out->GetSampleData()->GetArray("LICMask"));
  ASSERT_NE(mask, nullptr);
  const float* values = LICValues(out);
  vtkIdType masked = 0;
  vtkIdType wrong = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfSamples(); ++i)
  {
    double x[3];
    out->GetSamplePosition(i, x);
    const double speed = std::sqrt(x[0] * x[0] + x[1] * x[1]);
    const bool expected = speed < 0.2;
    if (std::fabs(speed - 0.2) > 2.0 * out->GetCellSize())
    {
      wrong += (mask->GetValue(i) != 0) != expected;
    }
    if (mask->GetValue(i))
    {
      ++masked;
      EXPECT_NEAR(values[i], 0.25f, 1e-5f);
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(masked, 100);
  EXPECT_EQ(masked, lic->GetNumberOfMaskedSamples());
}

//------------------------------------------------------------------------------
TEST(LIC, AnimationPhaseMovesTheStreaksAndRepeats)
{
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 128, UniformField(dir));
  vtkNew<vtkOFBLIC> lic;
  lic->AnimateOn();
  lic->SetEnhancedLIC(false);
  vtkSmartPointer<vtkOFB> a = RunLIC(lic, ofb);
  lic->SetAnimationPhase(0.25);
  vtkSmartPointer<vtkOFB> b = RunLIC(lic, ofb);
  lic->SetAnimationPhase(1.0);
  vtkSmartPointer<vtkOFB> c = RunLIC(lic, ofb);
  const vtkIdType n = a->GetNumberOfSamples();
  double changed = 0.0;
  double repeated = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    changed = std::max(changed, std::fabs(double(LICValues(a)[i]) - LICValues(b)[i]));
    repeated = std::max(repeated, std::fabs(double(LICValues(a)[i]) - LICValues(c)[i]));
  }
  EXPECT_GT(changed, 0.05);
  EXPECT_LT(repeated, 1e-4);
}

//------------------------------------------------------------------------------
TEST(LIC, KeptStreamlinesGiveTheResultOfAFreshComputation)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  const double axis[3] = { 0.3, 1.0, 0.2 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(bunny, 128, RotationField(axis));
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 0);
  for (int enhanced = 0; enhanced < 2; ++enhanced)
  {
    // Re-convolved from the kept streamlines: a new phase, then a new kernel and noise.
    vtkNew<vtkOFBLIC> kept;
    kept->SetNumberOfSteps(8);
    kept->SetEnhancedLIC(enhanced != 0);
    kept->AnimateOn();
    RunLIC(kept, ofb);
    const unsigned long keptKiB = kept->GetCacheMemorySize();
    kept->SetAnimationPhase(0.3);
    vtkSmartPointer<vtkOFB> phase = RunLIC(kept, ofb);
    kept->SetKernelTypeToHann();
    kept->SetNoiseGeneratorSeed(5);
    vtkSmartPointer<vtkOFB> kernel = RunLIC(kept, ofb);
    // A new filter computing everything for the same settings.
    vtkNew<vtkOFBLIC> fresh;
    fresh->SetNumberOfSteps(8);
    fresh->SetEnhancedLIC(enhanced != 0);
    fresh->AnimateOn();
    fresh->SetAnimationPhase(0.3);
    vtkSmartPointer<vtkOFB> freshPhase = RunLIC(fresh, ofb);
    fresh->SetKernelTypeToHann();
    fresh->SetNoiseGeneratorSeed(5);
    vtkSmartPointer<vtkOFB> freshKernel = RunLIC(fresh, ofb);
    // Without keeping them, every sample traces its own streamline (not the fast LIC's
    // windows of longer streamlines): another LIC of the same field and noise, correlated
    // with it (two LICs of independent noise are not).
    vtkNew<vtkOFBLIC> unkept;
    unkept->CacheStreamlinesOff();
    unkept->SetNumberOfSteps(8);
    unkept->SetEnhancedLIC(enhanced != 0);
    unkept->AnimateOn();
    unkept->SetAnimationPhase(0.3);
    vtkSmartPointer<vtkOFB> unkeptPhase = RunLIC(unkept, ofb);
    // The kept streamlines are at least 8 bytes a sample more: the sample's place in the
    // runs of its tile, and the runs (which hold every sample at least once).
    EXPECT_GE(keptKiB, unkept->GetCacheMemorySize() + n * 8 / 1024);
    std::vector<double> a(LICValues(phase), LICValues(phase) + n);
    std::vector<double> b(LICValues(unkeptPhase), LICValues(unkeptPhase) + n);
    EXPECT_GT(Pearson(a, b).Value, 0.5) << "enhanced " << enhanced;
    EXPECT_TRUE(SameLIC(phase, freshPhase));
    EXPECT_TRUE(SameLIC(kernel, freshKernel));
    EXPECT_FALSE(SameLIC(phase, kernel));
  }
}

//------------------------------------------------------------------------------
TEST(LIC, AnimatedLICWithoutEnhancementKeepsOnlyTheSums)
{
  vtkSmartPointer<vtkPolyData> bunny = ReadMesh("stanford-bunny.obj");
  ASSERT_NE(bunny, nullptr);
  const double axis[3] = { 0.3, 1.0, 0.2 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(bunny, 128, RotationField(axis));
  const vtkIdType n = ofb->GetNumberOfSamples();
  ASSERT_GT(n, 0);
  // Animate on, EnhancedLIC off: a new phase reads only the kept sums, so the streamlines
  // are not kept (less memory than the same LIC keeping them, Animate off).
  vtkNew<vtkOFBLIC> sums;
  sums->SetNumberOfSteps(8);
  sums->EnhancedLICOff();
  sums->AnimateOn();
  RunLIC(sums, ofb);
  vtkNew<vtkOFBLIC> runs;
  runs->SetNumberOfSteps(8);
  runs->EnhancedLICOff();
  RunLIC(runs, ofb);
  EXPECT_GE(runs->GetCacheMemorySize(), sums->GetCacheMemorySize() + n * 8 / 1024);
  // A new phase: combined from the sums, nothing traced; another kernel: traced again,
  // the result of a fresh filter.
  sums->SetAnimationPhase(0.4);
  vtkSmartPointer<vtkOFB> phase = RunLIC(sums, ofb);
  EXPECT_EQ(sums->GetLastRecomputed() & vtkOFBLIC::RECOMPUTED_STREAMLINES, 0);
  sums->SetKernelTypeToHann();
  vtkSmartPointer<vtkOFB> hann = RunLIC(sums, ofb);
  EXPECT_NE(sums->GetLastRecomputed() & vtkOFBLIC::RECOMPUTED_STREAMLINES, 0);
  vtkNew<vtkOFBLIC> fresh;
  fresh->SetNumberOfSteps(8);
  fresh->EnhancedLICOff();
  fresh->AnimateOn();
  fresh->SetAnimationPhase(0.4);
  EXPECT_TRUE(SameLIC(phase, RunLIC(fresh, ofb)));
  fresh->SetKernelTypeToHann();
  EXPECT_TRUE(SameLIC(hann, RunLIC(fresh, ofb)));
  // EnhancedLIC turned on: its second pass reads the streamlines, traced again.
  sums->EnhancedLICOn();
  vtkSmartPointer<vtkOFB> enhanced = RunLIC(sums, ofb);
  EXPECT_NE(sums->GetLastRecomputed() & vtkOFBLIC::RECOMPUTED_STREAMLINES, 0);
  fresh->EnhancedLICOn();
  EXPECT_TRUE(SameLIC(enhanced, RunLIC(fresh, ofb)));
  // Its runs are kept only where the second pass's windows read them: a new phase
  // traces nothing, another kernel traces again; both as a fresh filter.
  sums->SetAnimationPhase(0.7);
  fresh->SetAnimationPhase(0.7);
  vtkSmartPointer<vtkOFB> enhancedPhase = RunLIC(sums, ofb);
  EXPECT_EQ(sums->GetLastRecomputed() & vtkOFBLIC::RECOMPUTED_STREAMLINES, 0);
  EXPECT_TRUE(SameLIC(enhancedPhase, RunLIC(fresh, ofb)));
  sums->SetKernelTypeToGaussian();
  fresh->SetKernelTypeToGaussian();
  vtkSmartPointer<vtkOFB> enhancedKernel = RunLIC(sums, ofb);
  EXPECT_NE(sums->GetLastRecomputed() & vtkOFBLIC::RECOMPUTED_STREAMLINES, 0);
  EXPECT_TRUE(SameLIC(enhancedKernel, RunLIC(fresh, ofb)));
}

//------------------------------------------------------------------------------
TEST(LIC, ChangedFieldOrStepsTraceAgain)
{
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 96, UniformField(dir));
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkNew<vtkOFBLIC> kept;
  kept->EnhancedLICOff();
  vtkSmartPointer<vtkOFB> before = RunLIC(kept, ofb);
  // The field turned by 90 degrees in place (the same array, Modified()).
  vtkDataArray* field = ofb->GetSampleData()->GetVectors();
  ASSERT_NE(field, nullptr);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v[3];
    field->GetTuple(i, v);
    field->SetTuple3(i, -v[1], v[0], v[2]);
  }
  field->Modified();
  kept->Modified();
  vtkSmartPointer<vtkOFB> turned = RunLIC(kept, ofb);
  vtkNew<vtkOFBLIC> fresh;
  fresh->EnhancedLICOff();
  vtkSmartPointer<vtkOFB> freshTurned = RunLIC(fresh, ofb);
  EXPECT_FALSE(SameLIC(before, turned));
  EXPECT_TRUE(SameLIC(turned, freshTurned));
  // Other steps: the streamlines are traced again, as a fresh filter does.
  kept->SetNumberOfSteps(7);
  fresh->SetNumberOfSteps(7);
  EXPECT_TRUE(SameLIC(RunLIC(kept, ofb), RunLIC(fresh, ofb)));
  kept->SetStepSize(0.6);
  fresh->SetStepSize(0.6);
  EXPECT_TRUE(SameLIC(RunLIC(kept, ofb), RunLIC(fresh, ofb)));
  kept->ReleaseCache();
  EXPECT_EQ(kept->GetCacheMemorySize(), 0ul);
}

//------------------------------------------------------------------------------
TEST(LIC, KernelsAndOrientedLICDiffer)
{
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 128, UniformField(dir));
  vtkNew<vtkOFBLIC> lic;
  lic->SetEnhancedLIC(false);
  vtkSmartPointer<vtkOFB> box = RunLIC(lic, ofb);
  const vtkIdType n = box->GetNumberOfSamples();
  for (int variant = 0; variant < 3; ++variant)
  {
    lic->SetKernelType(variant == 0 ? vtkOFBLIC::KERNEL_GAUSSIAN : vtkOFBLIC::KERNEL_HANN);
    lic->SetOrientedLIC(variant == 2);
    vtkSmartPointer<vtkOFB> other = RunLIC(lic, ofb);
    EXPECT_FALSE(SameLIC(box, other));
    for (vtkIdType i = 0; i < n; ++i)
    {
      ASSERT_GE(LICValues(other)[i], 0.0f);
      ASSERT_LE(LICValues(other)[i], 1.0f);
    }
  }
}

//------------------------------------------------------------------------------
TEST(LIC, InputUntouchedAndArraysShared)
{
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 128, UniformField(dir));
  const int arrays = ofb->GetSampleData()->GetNumberOfArrays();
  vtkNew<vtkOFBLIC> lic;
  lic->SetInputData(ofb);
  lic->Update();
  vtkOFB* out = lic->GetOutput();
  EXPECT_EQ(ofb->GetSampleData()->GetNumberOfArrays(), arrays);
  EXPECT_EQ(ofb->GetSampleData()->GetArray("LIC"), nullptr);
  EXPECT_EQ(out->GetSampleData()->GetNumberOfArrays(), arrays + 2);
  EXPECT_EQ(out->GetSampleData()->GetNormals(), ofb->GetSampleData()->GetNormals());
  EXPECT_EQ(out->GetDepths(), ofb->GetDepths());
}

//------------------------------------------------------------------------------
TEST(LIC, ProgressAndAbort)
{
  const double dir[3] = { 1.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOFB> ofb = BuildWithField(MakeSquare(), 256, UniformField(dir));
  vtkNew<vtkOFBLIC> lic;
  int events = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&events);
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* client, void*)
    {
      int* count = static_cast<int*>(client);
      if (++*count == 3)
      {
        static_cast<vtkOFBLIC*>(caller)->AbortExecuteOn();
      }
    });
  lic->AddObserver(vtkCommand::ProgressEvent, progress);
  lic->SetInputData(ofb);
  lic->Update();
  EXPECT_GE(events, 3);
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), 0); // aborted: empty output
  lic->AbortExecuteOff();
  lic->RemoveAllObservers();
  lic->Modified();
  lic->Update();
  EXPECT_EQ(lic->GetOutput()->GetNumberOfSamples(), ofb->GetNumberOfSamples());
}
