#include "vtkOFBSampler.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkOFB.h"
#include "vtkOFBSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkOFBSampler);

namespace
{
/**
 * Copy an array into an array-of-structures array of the same type (a no-op for
 * arrays already in that layout).
 */
vtkSmartPointer<vtkDataArray> AsAOS(vtkDataArray* array)
{
  if (array->HasStandardMemoryLayout())
  {
    return array;
  }
  vtkSmartPointer<vtkDataArray> copy =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(array->GetDataType()));
  copy->DeepCopy(array);
  return copy;
}

bool IsColorArray(vtkDataArray* array)
{
  return array && array->GetDataType() == VTK_UNSIGNED_CHAR &&
    (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4);
}
}

//------------------------------------------------------------------------------
vtkOFBSampler::vtkOFBSampler()
  : Resolution(1024)
  , MemoryLimit(8192)
  , UseInputColors(true)
  , PassPointArrays(true)
  , ProjectVectors(true)
  , NumberOfSkippedTriangles(0)
  , LastBuildTime(0.0)
{
  this->DefaultColor[0] = this->DefaultColor[1] = this->DefaultColor[2] = 255;
  this->DefaultColor[3] = 255;
}

//------------------------------------------------------------------------------
vtkOFBSampler::~vtkOFBSampler() = default;

//------------------------------------------------------------------------------
int vtkOFBSampler::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkOFB* output = vtkOFB::GetData(outputVector);
  output->Initialize();
  this->NumberOfSkippedTriangles = 0;
  this->LastBuildTime = 0.0;

  const double start = vtkTimerLog::GetUniversalTime();
  vtkOFBSurface surface;
  this->UpdateProgress(0.0);
  if (!this->PrepareSurface(input, surface))
  {
    return 1;
  }
  this->UpdateProgress(0.05);
  if (!this->SampleOnCPU(surface, output))
  {
    output->Initialize();
    return 1;
  }
  this->LastBuildTime = 1000.0 * (vtkTimerLog::GetUniversalTime() - start);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::PrepareSurface(vtkPolyData* input, vtkOFBSurface& surface)
{
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input surface is empty: no points.");
    return false;
  }
  const vtkIdType nLinesVerts = input->GetNumberOfLines() + input->GetNumberOfVerts();
  if (nLinesVerts > 0)
  {
    vtkWarningMacro("Ignoring " << input->GetNumberOfLines() << " lines and "
                                << input->GetNumberOfVerts() << " vertices of the input.");
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips: nothing to sample.");
    return false;
  }

  // Points, checked finite.
  const vtkIdType nPoints = input->GetNumberOfPoints();
  surface.Points.resize(3 * nPoints);
  {
    const auto range = vtk::DataArrayValueRange<3>(input->GetPoints()->GetData());
    vtkIdType i = 0;
    for (const double value : range)
    {
      if (!std::isfinite(value))
      {
        vtkErrorMacro("The input has non-finite (NaN or Inf) point coordinates, point "
          << i / 3 << ".");
        return false;
      }
      surface.Points[i++] = value;
    }
  }

  // Triangles: the input's own cells when they are all triangles, else a triangulation.
  vtkSmartPointer<vtkPolyData> mesh = input;
  vtkCellArray* polys = input->GetPolys();
  if (input->GetNumberOfStrips() > 0 || polys->IsHomogeneous() != 3)
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->SetPoints(input->GetPoints());
    copy->SetPolys(input->GetPolys());
    copy->SetStrips(input->GetStrips());
    auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
    triangulate->SetInputData(copy);
    triangulate->PassLinesOff();
    triangulate->PassVertsOff();
    triangulate->Update();
    mesh = triangulate->GetOutput();
  }
  const double* P = surface.Points.data();
  surface.Triangles.reserve(3 * mesh->GetNumberOfPolys());
  {
    auto iter = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* ids;
      iter->GetCurrentCell(npts, ids);
      if (npts != 3)
      {
        continue;
      }
      if (ids[0] < 0 || ids[1] < 0 || ids[2] < 0 || ids[0] >= nPoints || ids[1] >= nPoints ||
        ids[2] >= nPoints)
      {
        vtkErrorMacro("The input has a polygon with an invalid point id.");
        return false;
      }
      double e1[3], e2[3], n[3];
      for (int k = 0; k < 3; ++k)
      {
        e1[k] = P[3 * ids[1] + k] - P[3 * ids[0] + k];
        e2[k] = P[3 * ids[2] + k] - P[3 * ids[0] + k];
      }
      vtkMath::Cross(e1, e2, n);
      if (vtkMath::Dot(n, n) == 0.0)
      {
        ++this->NumberOfSkippedTriangles;
        continue;
      }
      surface.Triangles.insert(surface.Triangles.end(), ids, ids + 3);
    }
  }
  if (this->NumberOfSkippedTriangles > 0)
  {
    vtkWarningMacro("Skipped " << this->NumberOfSkippedTriangles << " zero-area triangles.");
  }
  if (surface.Triangles.empty())
  {
    vtkErrorMacro("The input has no triangle of non-zero area: nothing to sample.");
    return false;
  }

  // Bounds of the points the triangles use.
  double* b = surface.Bounds;
  b[0] = b[2] = b[4] = VTK_DOUBLE_MAX;
  b[1] = b[3] = b[5] = -VTK_DOUBLE_MAX;
  for (const vtkIdType id : surface.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      b[2 * k] = std::min(b[2 * k], P[3 * id + k]);
      b[2 * k + 1] = std::max(b[2 * k + 1], P[3 * id + k]);
    }
  }

  // Normals: the input's point normals, else area-weighted ones.
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* inNormals = pd->GetNormals();
  surface.Normals.assign(3 * nPoints, 0.0f);
  if (inNormals && inNormals->GetNumberOfComponents() == 3 &&
    inNormals->GetNumberOfTuples() == nPoints)
  {
    for (vtkIdType i = 0; i < nPoints; ++i)
    {
      double n[3];
      inNormals->GetTuple(i, n);
      const double len = vtkMath::Norm(n);
      if (std::isfinite(len) && len > 0.0)
      {
        for (int k = 0; k < 3; ++k)
        {
          surface.Normals[3 * i + k] = static_cast<float>(n[k] / len);
        }
      }
    }
  }
  else
  {
    inNormals = nullptr;
    std::vector<double> acc(3 * nPoints, 0.0);
    const vtkIdType* T = surface.Triangles.data();
    for (vtkIdType t = 0; t < surface.GetNumberOfTriangles(); ++t)
    {
      double e1[3], e2[3], n[3];
      for (int k = 0; k < 3; ++k)
      {
        e1[k] = P[3 * T[3 * t + 1] + k] - P[3 * T[3 * t] + k];
        e2[k] = P[3 * T[3 * t + 2] + k] - P[3 * T[3 * t] + k];
      }
      vtkMath::Cross(e1, e2, n); // length is twice the area: area weighting
      for (int c = 0; c < 3; ++c)
      {
        for (int k = 0; k < 3; ++k)
        {
          acc[3 * T[3 * t + c] + k] += n[k];
        }
      }
    }
    for (vtkIdType i = 0; i < nPoints; ++i)
    {
      const double len = vtkMath::Norm(&acc[3 * i]);
      if (len > 0.0)
      {
        for (int k = 0; k < 3; ++k)
        {
          surface.Normals[3 * i + k] = static_cast<float>(acc[3 * i + k] / len);
        }
      }
    }
  }

  // The vector field: the array chosen with SetInputArrayToProcess, else the vectors.
  vtkDataArray* vectors = nullptr;
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  if (arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_ASSOCIATION()))
  {
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    vectors = this->GetInputArrayToProcess(0, input, association);
    if (!vectors || association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      vtkErrorMacro("The vector field chosen with SetInputArrayToProcess is not a point array "
                    "of the input.");
      return false;
    }
  }
  else
  {
    vectors = pd->GetVectors();
  }
  if (vectors && vectors->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The vector field '" << (vectors->GetName() ? vectors->GetName() : "")
                                       << "' must have 3 components, it has "
                                       << vectors->GetNumberOfComponents() << ".");
    return false;
  }
  if (vectors)
  {
    auto v = vtkSmartPointer<vtkFloatArray>::New();
    v->DeepCopy(vectors);
    v->SetName(vectors->GetName() ? vectors->GetName() : "Vectors");
    surface.Vectors = v;
  }
  surface.ProjectVectors = this->ProjectVectors;

  // Initial paint.
  std::memcpy(surface.DefaultColor, this->DefaultColor, 4);
  vtkDataArray* colors = nullptr;
  if (this->UseInputColors)
  {
    if (IsColorArray(pd->GetScalars()))
    {
      colors = pd->GetScalars();
    }
    else if (IsColorArray(pd->GetArray("Colors")))
    {
      colors = pd->GetArray("Colors");
    }
  }
  if (colors)
  {
    surface.Colors = vtkUnsignedCharArray::SafeDownCast(AsAOS(colors));
  }

  // Every other point array.
  if (this->PassPointArrays)
  {
    for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* array = pd->GetArray(i);
      if (!array || array == inNormals || array == vectors || array == colors ||
        array->GetDataType() == VTK_BIT || array->GetNumberOfTuples() != nPoints ||
        !array->GetName() || !std::strcmp(array->GetName(), "Colors") ||
        !std::strcmp(array->GetName(), "Normals") ||
        (surface.Vectors && !std::strcmp(array->GetName(), surface.Vectors->GetName())))
      {
        continue;
      }
      if (array == pd->GetTCoords())
      {
        surface.TCoordsIndex = static_cast<int>(surface.Arrays.size());
      }
      surface.Arrays.push_back(AsAOS(array));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBSampler::ComputeFrame(
  const vtkOFBSurface& surface, double origin[3], double& cellSize, vtkIdType dims[3])
{
  if (this->Resolution < 3 || this->Resolution > 65536)
  {
    vtkErrorMacro("Resolution must be in [3, 65536], it is " << this->Resolution << ".");
    return false;
  }
  const double* b = surface.Bounds;
  const double longest = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  if (!(longest > 0.0) || !std::isfinite(longest))
  {
    vtkErrorMacro("The input bounds are degenerate: nothing to sample.");
    return false;
  }
  cellSize = longest / (this->Resolution - 2);
  for (int a = 0; a < 3; ++a)
  {
    const double cells = std::ceil((b[2 * a + 1] - b[2 * a]) / cellSize - 1e-9);
    dims[a] = std::max<vtkIdType>(1, static_cast<vtkIdType>(cells)) + 2;
    origin[a] = 0.5 * (b[2 * a] + b[2 * a + 1]) - 0.5 * dims[a] * cellSize;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkOFBSampler::EstimateMemory(vtkPolyData* input)
{
  vtkOFBSurface surface;
  double origin[3], cellSize;
  vtkIdType dims[3];
  if (!this->PrepareSurface(input, surface) ||
    !this->ComputeFrame(surface, origin, cellSize, dims))
  {
    return -1.0;
  }
  return this->EstimateBytes(surface, dims, cellSize);
}

//------------------------------------------------------------------------------
double vtkOFBSampler::EstimateBytes(
  const vtkOFBSurface& surface, const vtkIdType dims[3], double cellSize, double samples)
{
  // Projected area and perimeter of each triangle on its grid, in cells.
  const double* P = surface.Points.data();
  const vtkIdType* T = surface.Triangles.data();
  const bool estimate = samples < 0.0;
  samples = estimate ? 0.0 : samples;
  for (vtkIdType t = 0; estimate && t < surface.GetNumberOfTriangles(); ++t)
  {
    double e1[3], e2[3], e3[3], n[3];
    for (int k = 0; k < 3; ++k)
    {
      e1[k] = P[3 * T[3 * t + 1] + k] - P[3 * T[3 * t] + k];
      e2[k] = P[3 * T[3 * t + 2] + k] - P[3 * T[3 * t] + k];
      e3[k] = e2[k] - e1[k];
    }
    vtkMath::Cross(e1, e2, n);
    const double area = 0.5 * std::max({ std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) });
    const double perimeter = vtkMath::Norm(e1) + vtkMath::Norm(e2) + vtkMath::Norm(e3);
    samples += area / (cellSize * cellSize) + 0.5 * perimeter / cellSize + 1.0;
  }
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
void vtkOFBSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "DefaultColor: (" << static_cast<int>(this->DefaultColor[0]) << ", "
     << static_cast<int>(this->DefaultColor[1]) << ", " << static_cast<int>(this->DefaultColor[2])
     << ", " << static_cast<int>(this->DefaultColor[3]) << ")\n";
  os << indent << "UseInputColors: " << (this->UseInputColors ? "On" : "Off") << "\n";
  os << indent << "PassPointArrays: " << (this->PassPointArrays ? "On" : "Off") << "\n";
  os << indent << "ProjectVectors: " << (this->ProjectVectors ? "On" : "Off") << "\n";
  os << indent << "NumberOfSkippedTriangles: " << this->NumberOfSkippedTriangles << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << " ms\n";
}
