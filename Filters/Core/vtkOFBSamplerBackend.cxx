#include "vtkOFBSamplerBackend.h"

#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkOFB.h"
#include "vtkOFBAttributeInterpolator.h"
#include "vtkOFBSampleArrays.h"
#include "vtkOFBSurface.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace
{
/**
 * Triangles per chunk of the estimate's parallel sum; the chunks' sums are added
 * in order, so that the estimate does not depend on the number of threads.
 */
constexpr vtkIdType EstimateChunk = 16384;
}

//------------------------------------------------------------------------------
vtkOFBSamplerBackend::vtkOFBSamplerBackend() = default;

//------------------------------------------------------------------------------
vtkOFBSamplerBackend::~vtkOFBSamplerBackend() = default;

//------------------------------------------------------------------------------
double vtkOFBSamplerBackend::EstimateBytes(const vtkOFBSurface& surface,
  const vtkIdType dims[3],
  double samples) const
{
  const vtkIdType points = surface.GetNumberOfPoints();
  const vtkIdType triangles = surface.GetNumberOfTriangles();
  const int vectorComponents = surface.Vectors ? 3 : 0;
  return vtkOFBSamplerBackend::EstimateSurfaceBytes(points, triangles, vectorComponents) +
    vtkOFBSamplerBackend::EstimateOutputBytes(surface, dims, samples) +
    this->EstimateWorkBytes(points, triangles, samples);
}

//------------------------------------------------------------------------------
double vtkOFBSamplerBackend::EstimateBytes(vtkIdType points, vtkIdType triangles) const
{
  return vtkOFBSamplerBackend::EstimateSurfaceBytes(points, triangles, 0) +
    this->EstimateWorkBytes(points, triangles, 0.0);
}

//------------------------------------------------------------------------------
double vtkOFBSamplerBackend::EstimateSurfaceBytes(vtkIdType points,
  vtkIdType triangles,
  int vectorComponents)
{
  // Per point: coordinates (doubles), unit normals, the sums of area-weighted
  // normals (doubles) and the copied vector field (floats). Per triangle: point
  // ids and the flag that keeps it.
  const double perPoint = 24.0 + 12.0 + 24.0 + 4.0 * vectorComponents;
  const double perTriangle = 3.0 * sizeof(vtkIdType) + 1.0;
  return perPoint * static_cast<double>(points) + perTriangle * static_cast<double>(triangles);
}

//------------------------------------------------------------------------------
double vtkOFBSamplerBackend::EstimateOutputBytes(const vtkOFBSurface& surface,
  const vtkIdType dims[3],
  double samples)
{
  double cells = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    cells += static_cast<double>(dims[(a + 1) % 3]) * static_cast<double>(dims[(a + 2) % 3]);
  }
  // Per sample: depth, cell index, colour, normal, the build's temporaries
  // (triangle, two barycentrics), the vector field and the other arrays.
  double perSample = 4 + 4 + 4 + 12 + 12;
  if (surface.Vectors)
  {
    perSample += 12;
  }
  for (const auto& array : surface.Arrays)
  {
    perSample += array->GetNumberOfComponents() * array->GetDataTypeSize();
  }
  // Per cell: the offsets and the build's counters.
  return cells * 8.0 + samples * perSample;
}

//------------------------------------------------------------------------------
double vtkOFBSamplerBackend::EstimateSamples(const vtkOFBSurface& surface, double cellSize)
{
  // Projected area and perimeter of each triangle on its grid, in cells (summed per
  // chunk in parallel, then over the chunks in order).
  const double* points = surface.Points.data();
  const vtkIdType* triangles = surface.Triangles.data();
  const vtkIdType nTris = surface.GetNumberOfTriangles();
  const vtkIdType nChunks = (nTris + EstimateChunk - 1) / EstimateChunk;
  std::vector<double> sums(nChunks, 0.0);
  vtkSMPTools::For(0,
    nChunks,
    1,
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        for (vtkIdType t = c * EstimateChunk; t < std::min(nTris, (c + 1) * EstimateChunk); ++t)
        {
          const double* p0 = points + 3 * triangles[3 * t];
          const double* p1 = points + 3 * triangles[3 * t + 1];
          const double* p2 = points + 3 * triangles[3 * t + 2];
          double e1[3], e2[3], e3[3], n[3];
          for (int k = 0; k < 3; ++k)
          {
            e1[k] = p1[k] - p0[k];
            e2[k] = p2[k] - p0[k];
            e3[k] = e2[k] - e1[k];
          }
          vtkMath::Cross(e1, e2, n);
          const double area = 0.5 * std::max({ std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) });
          const double perimeter = vtkMath::Norm(e1) + vtkMath::Norm(e2) + vtkMath::Norm(e3);
          sums[c] += area / (cellSize * cellSize) + 0.5 * perimeter / cellSize + 1.0;
        }
      }
    });
  double samples = 0.0;
  for (const double sum : sums)
  {
    samples += sum;
  }
  return samples;
}

//------------------------------------------------------------------------------
bool vtkOFBSamplerBackend::CheckMemoryLimit(double bytes, double limit, std::string& error)
{
  if (bytes <= limit)
  {
    return true;
  }
  std::ostringstream os;
  os << "The build needs about " << bytes / 1048576.0 << " MiB, over the memory limit of "
     << limit / 1048576.0 << " MiB. Lower the resolution, simplify the surface or raise "
     << "MemoryLimit.";
  error = os.str();
  return false;
}

//------------------------------------------------------------------------------
bool vtkOFBSamplerBackend::InterpolateAttributes(const vtkOFBSurface& surface,
  vtkOFB* output,
  const vtkTypeUInt32* triangles,
  const float* w1,
  const float* w2)
{
  const vtkIdType n = output->GetNumberOfSamples();
  vtkOFBSampleArrays arrays(surface, n, output);
  unsigned char* outColors = arrays.Colors->GetPointer(0);
  float* outNormals = arrays.Normals->GetPointer(0);
  float* outVectors = arrays.Vectors ? arrays.Vectors->GetPointer(0) : nullptr;
  const vtkOFBAttributeInterpolator interpolator(surface);
  vtkSMPTools::For(0,
    n,
    4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      float normal[3], vector[3], scratch;
      vtkOFBAttributeInterpolator::Run run;
      for (int k = 0; k < 3; ++k)
      {
        run.Normals[k] = normal + k;
        run.Vectors[k] = vector + k;
      }
      run.Scratch = &scratch;
      for (vtkIdType i = begin; i < end; ++i)
      {
        run.RGBA = outColors + 4 * i;
        interpolator.Interpolate(triangles[i], 1, w1 + i, w2 + i, run);
        if (!interpolator.PointColors)
        {
          std::memcpy(run.RGBA, interpolator.DefaultColor, 4);
        }
        std::copy(normal, normal + 3, outNormals + 3 * i);
        if (outVectors)
        {
          std::copy(vector, vector + 3, outVectors + 3 * i);
        }
      }
    });
  std::vector<bool> interpolated;
  for (size_t k = 0; k < surface.Arrays.size(); ++k)
  {
    vtkDataArray* in = surface.Arrays[k];
    vtkDataArray* out = arrays.Others[k];
    interpolated.push_back(vtkOFBAttributeInterpolator::IsInterpolable(in));
    if (interpolated.back())
    {
      vtkSMPTools::For(0,
        n,
        4096,
        [&](vtkIdType begin, vtkIdType end)
        {
          vtkOFBAttributeInterpolator::InterpolateArray(in,
            out,
            begin,
            end - begin,
            surface.Triangles.data(),
            triangles + begin,
            w1 + begin,
            w2 + begin,
            nullptr,
            surface.GetArrayCells(k));
        });
    }
  }
  arrays.Attach(surface, output->GetSampleData(), interpolated);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBSamplerBackend::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackendName: " << this->GetBackendName() << "\n";
}
