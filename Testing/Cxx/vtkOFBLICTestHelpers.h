// Helpers of the LIC tests: test surfaces with a vector field, and the streak measures
// (correlation of the LIC between samples a few cells apart along and across the field).
#ifndef vtkOFBLICTestHelpers_h
#define vtkOFBLICTestHelpers_h

#include "vtkOFBTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkOFBLIC.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace vtkofbtest
{
/// v = f(x): a vector field given by a function of the position.
using VectorField = std::function<void(const double x[3], double v[3])>;

/// The square [-1, 1]^2 at z = 0, finely triangulated (200 x 200 quads, 80000 triangles).
inline vtkSmartPointer<vtkPolyData> MakeSquare()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(200, 200);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  vtkSmartPointer<vtkPolyData> out = triangles->GetOutput();
  return out;
}

/**
 * A pipe wall with a bump and a swirling flow: radius 1, length 4 along its axis, an
 * outward bump of height 0.35 and width about 0.5 on one side at mid-length, open ends.
 * The flow ("Flow", point vectors) runs along the axis at speed 1 and turns about it at
 * an angular speed of 1.2 + 0.6 sin(1.5 z). The pipe is then tilted (30 degrees about x,
 * 20 about y) so that its axis and the bump lie along no grid axis. `around` x `along`
 * quads, each cut into two triangles.
 */
inline vtkSmartPointer<vtkPolyData> MakePipeWithBump(int around = 256, int along = 256)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  for (int j = 0; j <= along; ++j)
  {
    const double z = -2.0 + 4.0 * j / along;
    for (int i = 0; i < around; ++i)
    {
      const double theta = 2.0 * vtkMath::Pi() * i / around;
      double dTheta = std::remainder(theta, 2.0 * vtkMath::Pi());
      const double bump = 0.35 * std::exp(-(z * z + dTheta * dTheta) / 0.25);
      const double r = 1.0 + bump;
      const double x[3] = { r * std::cos(theta), r * std::sin(theta), z };
      points->InsertNextPoint(x);
      const double omega = 1.2 + 0.6 * std::sin(1.5 * z);
      const double v[3] = { -omega * x[1], omega * x[0], 1.0 };
      flow->InsertNextTuple(v);
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j < along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const vtkIdType a = j * around + i;
      const vtkIdType b = j * around + (i + 1) % around;
      const vtkIdType c = a + around;
      const vtkIdType d = b + around;
      const vtkIdType t0[3] = { a, b, d };
      const vtkIdType t1[3] = { a, d, c };
      triangles->InsertNextCell(3, t0);
      triangles->InsertNextCell(3, t1);
    }
  }
  vtkNew<vtkPolyData> pipe;
  pipe->SetPoints(points);
  pipe->SetPolys(triangles);
  pipe->GetPointData()->SetVectors(flow);
  vtkNew<vtkTransform> tilt;
  tilt->RotateY(20.0);
  tilt->RotateX(30.0);
  vtkNew<vtkTransformPolyDataFilter> tilted;
  tilted->SetInputData(pipe);
  tilted->SetTransform(tilt); // rotates the active vectors too
  tilted->Update();
  vtkSmartPointer<vtkPolyData> out = tilted->GetOutput();
  return out;
}

/// Run a LIC filter on `ofb` and return its output (a new object).
inline vtkSmartPointer<vtkOFB> RunLIC(vtkOFBLIC* lic, vtkOFB* ofb)
{
  lic->SetInputData(ofb);
  lic->Update();
  vtkSmartPointer<vtkOFB> out = vtkSmartPointer<vtkOFB>::New();
  out->ShallowCopy(lic->GetOutput());
  return out;
}

/// The "LIC" sample array's values, or nullptr.
inline float* LICValues(vtkOFB* ofb)
{
  vtkFloatArray* a = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("LIC"));
  return a ? a->GetPointer(0) : nullptr;
}

/// The same vector `dir` everywhere.
inline VectorField UniformField(const double dir[3])
{
  const double d[3] = { dir[0], dir[1], dir[2] };
  return [d](const double*, double v[3])
  {
    for (int c = 0; c < 3; ++c)
    {
      v[c] = d[c];
    }
  };
}

/// Rotation about `axis` through the origin: v = axis x x (axis normalized).
inline VectorField RotationField(const double axis[3])
{
  double a[3] = { axis[0], axis[1], axis[2] };
  vtkMath::Normalize(a);
  return [a](const double x[3], double v[3]) { vtkMath::Cross(a, x, v); };
}

/// A copy of `mesh` (arrays shared) with the point vectors "Flow" = field(point).
inline vtkSmartPointer<vtkPolyData> WithField(vtkPolyData* mesh, const VectorField& field)
{
  vtkSmartPointer<vtkPolyData> copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(mesh);
  vtkNew<vtkFloatArray> flow;
  flow->SetName("Flow");
  flow->SetNumberOfComponents(3);
  flow->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3], v[3];
    mesh->GetPoint(p, x);
    field(x, v);
    flow->SetTuple(p, v);
  }
  copy->GetPointData()->SetVectors(flow);
  return copy;
}

/// The OFB of `mesh` at `resolution` with the sample field "Flow" (projected).
inline vtkSmartPointer<vtkOFB> BuildWithField(vtkPolyData* mesh,
  int resolution,
  const VectorField& field)
{
  vtkSmartPointer<vtkPolyData> withField = WithField(mesh, field);
  return Build(withField, resolution);
}

/// Pearson correlation over pairs of values.
struct Correlation
{
  double Value = 0.0;
  vtkIdType Pairs = 0;
};

inline Correlation Pearson(const std::vector<double>& a, const std::vector<double>& b)
{
  Correlation c;
  c.Pairs = static_cast<vtkIdType>(a.size());
  if (a.size() < 2)
  {
    return c;
  }
  double ma = 0.0, mb = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    ma += a[i];
    mb += b[i];
  }
  ma /= a.size();
  mb /= b.size();
  double cov = 0.0, va = 0.0, vb = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    cov += (a[i] - ma) * (b[i] - mb);
    va += (a[i] - ma) * (a[i] - ma);
    vb += (b[i] - mb) * (b[i] - mb);
  }
  c.Value = (va > 0.0 && vb > 0.0) ? cov / std::sqrt(va * vb) : 0.0;
  return c;
}

/**
 * On the square of MakeSquare: the correlation of `values` between each sample farther
 * than `margin` from the border and the sample closest to it moved by `distance` along
 * the unit vector `dir`.
 */
inline Correlation Autocorrelation(vtkOFB* ofb,
  const float* values,
  const double dir[3],
  double distance,
  double margin)
{
  std::vector<double> a, b;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    if (std::fabs(x[0]) > 1.0 - margin || std::fabs(x[1]) > 1.0 - margin)
    {
      continue;
    }
    const double y[3] = {
      x[0] + distance * dir[0], x[1] + distance * dir[1], x[2] + distance * dir[2]
    };
    const vtkIdType j = ofb->FindClosestSample(y);
    if (j >= 0)
    {
      a.push_back(values[i]);
      b.push_back(values[j]);
    }
  }
  return Pearson(a, b);
}

/// Streak measure on a sphere about the origin with a rotation about `axis`.
struct StreakMeasure
{
  double Along = 0.0;
  double Across = 0.0;
  vtkIdType Pairs = 0;
};

/**
 * Correlation of `values` at 4 cells along and across the rotation about `axis`, over
 * the samples within 60 degrees of the equator that are near a change of grid (the two
 * largest components of the normal within 0.15 of each other; `nearGridChange`) or not.
 */
inline StreakMeasure SphereStreaks(vtkOFB* ofb,
  const float* values,
  const double axis[3],
  bool nearGridChange)
{
  vtkDataArray* normals = ofb->GetSampleData()->GetNormals();
  const double d = 4.0 * ofb->GetCellSize();
  std::vector<double> a, b, c, e;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3], n[3], along[3], across[3];
    ofb->GetSamplePosition(i, x);
    normals->GetTuple(i, n);
    if (std::fabs(vtkMath::Dot(n, axis)) > std::sin(vtkMath::RadiansFromDegrees(60.0)))
    {
      continue;
    }
    double m[3] = { std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) };
    std::sort(m, m + 3);
    if ((m[2] - m[1] < 0.15) != nearGridChange)
    {
      continue;
    }
    vtkMath::Cross(axis, x, along);
    vtkMath::Normalize(along);
    vtkMath::Cross(n, along, across);
    double ya[3], yc[3];
    for (int k = 0; k < 3; ++k)
    {
      ya[k] = x[k] + d * along[k];
      yc[k] = x[k] + d * across[k];
    }
    const vtkIdType ja = ofb->FindClosestSample(ya);
    const vtkIdType jc = ofb->FindClosestSample(yc);
    if (ja >= 0 && jc >= 0)
    {
      a.push_back(values[i]);
      b.push_back(values[ja]);
      c.push_back(values[i]);
      e.push_back(values[jc]);
    }
  }
  StreakMeasure s;
  const Correlation along = Pearson(a, b);
  s.Along = along.Value;
  s.Pairs = along.Pairs;
  s.Across = Pearson(c, e).Value;
  return s;
}

/**
 * The fraction of samples whose closest sample of another grid within `radius` cells
 * (where there is one) has the same value.
 */
inline double FractionEqualAcrossGrids(vtkOFB* ofb, const float* values, double radius)
{
  vtkIdType pairs = 0;
  vtkIdType equal = 0;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    double x[3];
    ofb->GetSamplePosition(i, x);
    const int axis = ofb->GetSampleAxis(i);
    vtkIdType best = -1;
    double bestD2 = 1e300;
    ofb->ForEachSampleInSphere(x,
      radius * ofb->GetCellSize(),
      [&](vtkIdType j, double d2)
      {
        if (ofb->GetSampleAxis(j) != axis && d2 < bestD2)
        {
          bestD2 = d2;
          best = j;
        }
      });
    if (best >= 0)
    {
      ++pairs;
      equal += values[best] == values[i];
    }
  }
  return pairs ? static_cast<double>(equal) / pairs : 0.0;
}

/// The contrast of values in [0, 1]: their 1st and 99th percentiles (linear
/// interpolation between the closest ranks, as numpy's percentile) and standard deviation.
struct ContrastMeasure
{
  double Low = 0.0;
  double High = 0.0;
  double Std = 0.0;
  vtkIdType Count = 0;
  double Span() const { return this->High - this->Low; }
};

inline ContrastMeasure MeasureContrast(std::vector<double> values)
{
  ContrastMeasure c;
  c.Count = static_cast<vtkIdType>(values.size());
  if (values.empty())
  {
    return c;
  }
  std::sort(values.begin(), values.end());
  auto percentile = [&values](double p)
  {
    const double at = p / 100.0 * (values.size() - 1);
    const std::size_t k = static_cast<std::size_t>(std::floor(at));
    const std::size_t k1 = std::min(k + 1, values.size() - 1);
    return values[k] + (at - k) * (values[k1] - values[k]);
  };
  c.Low = percentile(1.0);
  c.High = percentile(99.0);
  double mean = 0.0;
  for (double v : values)
  {
    mean += v;
  }
  mean /= values.size();
  double variance = 0.0;
  for (double v : values)
  {
    variance += (v - mean) * (v - mean);
  }
  c.Std = std::sqrt(variance / values.size());
  return c;
}

/// The contrast of the "LIC" sample array of `ofb` over its samples not masked ("LICMask"
/// 0, where there is one); no values if there is no "LIC".
inline ContrastMeasure LICContrast(vtkOFB* ofb)
{
  vtkDataArray* lic = ofb->GetSampleData()->GetArray("LIC");
  vtkDataArray* mask = ofb->GetSampleData()->GetArray("LICMask");
  std::vector<double> values;
  for (vtkIdType i = 0; lic && i < lic->GetNumberOfTuples(); ++i)
  {
    if (!mask || mask->GetComponent(i, 0) == 0.0)
    {
      values.push_back(lic->GetComponent(i, 0));
    }
  }
  return MeasureContrast(values);
}

/**
 * Pearson correlation of two LIC arrays of the same OFB over the samples that are not
 * masked (`mask`, e.g. the "LICMask" array; null: all samples).
 */
inline Correlation CorrelationUnmasked(vtkOFB* ofb,
  const float* a,
  const float* b,
  const unsigned char* mask)
{
  std::vector<double> x, y;
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    if (!mask || !mask[i])
    {
      x.push_back(a[i]);
      y.push_back(b[i]);
    }
  }
  return Pearson(x, y);
}

/**
 * The mean |values(i) - values(j)| over the unmasked samples i, where j is the sample
 * closest to the point one cell downstream of i along the sample vectors (their active
 * vectors), split by whether i and j lie on different grids or the same grid, and by
 * whether a plane of the `tileSize`-cell tiles of the OFB's box lies between them.
 * Dashes or seams of a LIC show as a larger difference across than elsewhere.
 */
struct DownstreamDifference
{
  double GridSwitch = 0.0; // i and j on different grids
  double SameGrid = 0.0;
  double TilePlane = 0.0; // a tile plane between i and j
  double InTile = 0.0;
  vtkIdType Pairs[4] = { 0, 0, 0, 0 }; // in the order above
};

inline DownstreamDifference DownstreamDifferences(vtkOFB* ofb,
  const float* values,
  const unsigned char* mask,
  int tileSize = 64)
{
  DownstreamDifference d;
  vtkDataArray* vectors = ofb->GetSampleData()->GetVectors();
  if (!vectors)
  {
    return d;
  }
  double origin[3];
  ofb->GetOrigin(origin);
  const double cell = ofb->GetCellSize();
  const double tile = tileSize * cell;
  double sums[4] = { 0.0, 0.0, 0.0, 0.0 };
  for (vtkIdType i = 0; i < ofb->GetNumberOfSamples(); ++i)
  {
    if (mask && mask[i])
    {
      continue;
    }
    double x[3], v[3];
    ofb->GetSamplePosition(i, x);
    vectors->GetTuple(i, v);
    const double length = vtkMath::Norm(v);
    if (!(length > 0.0))
    {
      continue;
    }
    const double y[3] = {
      x[0] + cell * v[0] / length, x[1] + cell * v[1] / length, x[2] + cell * v[2] / length
    };
    const vtkIdType j = ofb->FindClosestSample(y);
    if (j < 0 || j == i || (mask && mask[j]))
    {
      continue;
    }
    double xj[3];
    ofb->GetSamplePosition(j, xj);
    const double diff = std::fabs(static_cast<double>(values[i]) - values[j]);
    const int grid = ofb->GetSampleAxis(i) != ofb->GetSampleAxis(j) ? 0 : 1;
    bool plane = false;
    for (int a = 0; a < 3; ++a)
    {
      plane =
        plane || std::floor((x[a] - origin[a]) / tile) != std::floor((xj[a] - origin[a]) / tile);
    }
    const int where = plane ? 2 : 3;
    sums[grid] += diff;
    sums[where] += diff;
    ++d.Pairs[grid];
    ++d.Pairs[where];
  }
  double* means[4] = { &d.GridSwitch, &d.SameGrid, &d.TilePlane, &d.InTile };
  for (int k = 0; k < 4; ++k)
  {
    *means[k] = d.Pairs[k] ? sums[k] / d.Pairs[k] : 0.0;
  }
  return d;
}
}

#endif
