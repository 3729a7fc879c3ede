#include "vtkOFBViewResolution.h"

#include "vtkCamera.h"
#include "vtkDataSet.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkOFBViewResolution);

//------------------------------------------------------------------------------
vtkOFBViewResolution::vtkOFBViewResolution()
  : CellsPerPixel(1.0)
  , NoiseGrainPixels(2.0)
  , FootprintQuantile(0.5)
  , MinimumResolution(16)
  , MaximumResolution(4096)
  , Resolution(0)
  , NoiseGrainSize(0.0)
  , CellSize(0.0)
  , PixelSize(0.0)
  , NumberOfVisiblePoints(0)
{
}

//------------------------------------------------------------------------------
vtkOFBViewResolution::~vtkOFBViewResolution() = default;

//------------------------------------------------------------------------------
void vtkOFBViewResolution::ResetResults()
{
  this->Resolution = 0;
  this->NoiseGrainSize = 0.0;
  this->CellSize = 0.0;
  this->PixelSize = 0.0;
  this->NumberOfVisiblePoints = 0;
}

//------------------------------------------------------------------------------
bool vtkOFBViewResolution::Compute(vtkRenderer* renderer, vtkDataSet* surface)
{
  if (!surface || surface->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("Compute: no surface, or one without points.");
    this->ResetResults();
    return false;
  }
  const vtkIdType n = surface->GetNumberOfPoints();
  std::vector<double> points(static_cast<size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    surface->GetPoint(i, points.data() + 3 * i);
  }
  double b[6];
  surface->GetBounds(b);
  const double longest = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  return this->ComputeFromPoints(renderer, points.data(), n, longest);
}

//------------------------------------------------------------------------------
bool vtkOFBViewResolution::Compute(vtkRenderer* renderer, const double bounds[6])
{
  if (!bounds || !(bounds[1] >= bounds[0]) || !(bounds[3] >= bounds[2]) ||
    !(bounds[5] >= bounds[4]))
  {
    vtkErrorMacro("Compute: the bounds are not a box (min > max, or not numbers).");
    this->ResetResults();
    return false;
  }
  constexpr int N = 9;
  std::vector<double> points;
  points.reserve(3 * N * N * N);
  for (int k = 0; k < N; ++k)
  {
    for (int j = 0; j < N; ++j)
    {
      for (int i = 0; i < N; ++i)
      {
        const int ijk[3] = { i, j, k };
        for (int c = 0; c < 3; ++c)
        {
          points.push_back(bounds[2 * c] + (bounds[2 * c + 1] - bounds[2 * c]) * ijk[c] / (N - 1));
        }
      }
    }
  }
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  return this->ComputeFromPoints(renderer, points.data(), N * N * N, longest);
}

//------------------------------------------------------------------------------
bool vtkOFBViewResolution::ComputeFromPoints(vtkRenderer* renderer,
  const double* points,
  vtkIdType count,
  double longest)
{
  this->ResetResults();
  vtkCamera* camera = renderer ? renderer->GetActiveCamera() : nullptr;
  const int* size = renderer ? renderer->GetSize() : nullptr;
  if (!camera || !size || size[0] <= 0 || size[1] <= 0)
  {
    vtkErrorMacro("Compute: no renderer, camera or renderer size (render once first).");
    return false;
  }
  if (!(longest > 0.0) || !std::isfinite(longest))
  {
    vtkErrorMacro("Compute: the surface's bounds are empty or not finite.");
    return false;
  }
  const double aspect = static_cast<double>(size[0]) / size[1];
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  double position[3];
  double direction[3];
  camera->GetPosition(position);
  camera->GetDirectionOfProjection(direction);
  // World length of a pixel at view depth d: `slope` d (perspective) or `flat` (parallel).
  const double span = camera->GetUseHorizontalViewAngle() ? size[0] : size[1];
  const double slope =
    2.0 * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) / span;
  const double flat = 2.0 * camera->GetParallelScale() / size[1];
  const bool parallel = camera->GetParallelProjection() != 0;
  std::vector<double> pixels;
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double* x = points + 3 * i;
    const double in[4] = { x[0], x[1], x[2], 1.0 };
    double out[4];
    m->MultiplyPoint(in, out);
    if (!(out[3] > 0.0))
    {
      continue;
    }
    const double tol = 1.0 + 1.0e-9;
    if (std::abs(out[0]) > tol * out[3] || std::abs(out[1]) > tol * out[3] ||
      std::abs(out[2]) > tol * out[3])
    {
      continue;
    }
    const double depth = (x[0] - position[0]) * direction[0] + (x[1] - position[1]) * direction[1] +
      (x[2] - position[2]) * direction[2];
    const double pixel = parallel ? flat : slope * depth;
    if (pixel > 0.0 && std::isfinite(pixel))
    {
      pixels.push_back(pixel);
    }
  }
  if (pixels.empty())
  {
    vtkErrorMacro("Compute: no point of the surface is in the view.");
    return false;
  }
  const size_t q = std::min(pixels.size() - 1,
    static_cast<size_t>(std::floor(this->FootprintQuantile * (pixels.size() - 1) + 0.5)));
  std::nth_element(pixels.begin(), pixels.begin() + q, pixels.end());
  this->PixelSize = pixels[q];
  this->NumberOfVisiblePoints = static_cast<vtkIdType>(pixels.size());
  const double wanted = longest * this->CellsPerPixel / this->PixelSize;
  const int lo = this->MinimumResolution;
  const int hi = std::max(this->MaximumResolution, lo);
  const double resolution = std::ceil(std::min(wanted, 1.0e9)) + 2.0;
  this->Resolution = static_cast<int>(std::min<double>(std::max<double>(resolution, lo), hi));
  this->CellSize = longest / (this->Resolution - 2);
  this->NoiseGrainSize = std::max(1.0, this->NoiseGrainPixels * this->PixelSize / this->CellSize);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBViewResolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CellsPerPixel: " << this->CellsPerPixel << "\n";
  os << indent << "NoiseGrainPixels: " << this->NoiseGrainPixels << " pixels\n";
  os << indent << "FootprintQuantile: " << this->FootprintQuantile << "\n";
  os << indent << "MinimumResolution: " << this->MinimumResolution << "\n";
  os << indent << "MaximumResolution: " << this->MaximumResolution << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "NoiseGrainSize: " << this->NoiseGrainSize << " cells\n";
  os << indent << "CellSize: " << this->CellSize << "\n";
  os << indent << "PixelSize: " << this->PixelSize << "\n";
  os << indent << "NumberOfVisiblePoints: " << this->NumberOfVisiblePoints << "\n";
}
