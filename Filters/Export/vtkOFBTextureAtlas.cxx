#include "vtkOFBTextureAtlas.h"

#include "vtkOFBAtlasCharts.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkOFB.h"
#include "vtkOFBInputChecks.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkOFBTextureAtlas);

namespace
{
// Which corner of a triangle is opposite its longest edge, and the tile extent the
// triangle needs in cells: its longest leg from that corner, or its longest edge over
// sqrt(2) (that edge lies on the tile's diagonal).
struct TriangleShape
{
  int Corner;
  double Extent;
};

TriangleShape Shape(const glm::dvec3 p[3])
{
  // Edge k is opposite corner k.
  const double l[3] = {
    glm::length(p[2] - p[1]), glm::length(p[0] - p[2]), glm::length(p[1] - p[0])
  };
  const int k = l[0] >= l[1] && l[0] >= l[2] ? 0 : (l[1] >= l[2] ? 1 : 2);
  const double e = std::max({ l[(k + 1) % 3], l[(k + 2) % 3], l[k] / std::sqrt(2.0) });
  return { k, std::isfinite(e) ? e : 0.0 };
}

/// The atlas's size as the field-data array "AtlasSize" of `output`.
void AddAtlasSize(vtkPolyData* output, const int size[2])
{
  vtkNew<vtkIntArray> array;
  array->SetName("AtlasSize");
  array->InsertNextValue(size[0]);
  array->InsertNextValue(size[1]);
  output->GetFieldData()->AddArray(array);
}
}

//------------------------------------------------------------------------------
vtkOFBTextureAtlas::vtkOFBTextureAtlas()
  : Layout(CHARTS)
  , TexelsPerCell(1.0)
  , ChartPadding(2)
  , MinimumTileSize(4)
  , MaximumTextureSize(16384)
  , AtlasSize{ 0, 0 }
  , EffectiveTexelsPerCell(0.0)
  , NumberOfCharts(0)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOFBTextureAtlas::~vtkOFBTextureAtlas() = default;

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::SetOFBConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::SetOFBData(vtkOFB* ofb)
{
  this->SetInputData(1, ofb);
}

//------------------------------------------------------------------------------
int vtkOFBTextureAtlas::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::LayOut(const double* extents,
  vtkIdType n,
  double density,
  int* side,
  int* origin)
{
  // Sides, rounded up to multiples of the smallest tile.
  const int m = this->MinimumTileSize;
  double area = 0.0;
  int largest = m;
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double want = std::min(std::ceil(extents[t] * density) + 1.0, 1048576.0);
    side[t] = std::max(m, static_cast<int>(std::ceil(want / m)) * m);
    area += static_cast<double>(side[t]) * side[t];
    largest = std::max(largest, side[t]);
  }
  // Rows of tiles, largest first, in an atlas about as wide as high.
  const double wide = std::max<double>(largest, std::ceil(std::sqrt(area * 1.02) / m) * m);
  if (wide > this->MaximumTextureSize)
  {
    return false;
  }
  const int width = static_cast<int>(wide);
  std::vector<vtkIdType> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(
    order.begin(), order.end(), [side](vtkIdType a, vtkIdType b) { return side[a] > side[b]; });
  long long x = 0;
  long long y = 0;
  long long rowHeight = 0;
  for (vtkIdType t : order)
  {
    if (x + side[t] > width)
    {
      x = 0;
      y += rowHeight;
      rowHeight = 0;
    }
    if (y + side[t] > this->MaximumTextureSize)
    {
      return false;
    }
    origin[2 * t] = static_cast<int>(x);
    origin[2 * t + 1] = static_cast<int>(y);
    rowHeight = std::max<long long>(rowHeight, side[t]);
    x += side[t];
  }
  this->AtlasSize[0] = width;
  this->AtlasSize[1] = static_cast<int>(y + rowHeight);
  return true;
}

//------------------------------------------------------------------------------
int vtkOFBTextureAtlas::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkOFB* ofb = vtkOFB::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->AtlasSize[0] = this->AtlasSize[1] = 0;
  this->EffectiveTexelsPerCell = 0.0;
  this->NumberOfCharts = 0;
  if (!ofb || ofb->GetNumberOfSamples() == 0 || !(ofb->GetCellSize() > 0.0))
  {
    vtkErrorMacro("No OFB, or an empty one (SetOFBData or SetOFBConnection).");
    return 1;
  }
  // Cells naming points that do not exist, and short arrays (copied to the output),
  // are refused before anything reads them.
  std::string error;
  if (input &&
    (!vtkOFBCheckCellPointIds(input, error) || !vtkOFBCheckAttributeArrays(input, error)))
  {
    vtkErrorMacro("The surface (input port 0) is invalid: " << error << ".");
    return 1;
  }
  vtkCellArray* polys = input ? input->GetPolys() : nullptr;
  if (!polys || polys->GetNumberOfCells() == 0 || !input->GetPoints())
  {
    vtkErrorMacro("The surface has no polygons.");
    return 1;
  }
  if (input->GetNumberOfStrips() > 0 || polys->GetMaxCellSize() != 3 ||
    polys->GetNumberOfConnectivityIds() != 3 * polys->GetNumberOfCells())
  {
    vtkErrorMacro("The surface has triangle strips or polygons that are not triangles: apply "
                  "vtkTriangleFilter first.");
    return 1;
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro("Vertices and lines have no texture: left out.");
  }
  // Each triangle's corners, and for Triangles its shape in cells.
  const vtkIdType n = polys->GetNumberOfCells();
  const double s = ofb->GetCellSize();
  const bool tiles = this->Layout == TRIANGLES;
  std::vector<double> extents(tiles ? n : 0);
  std::vector<int> corner(tiles ? n : 0);
  std::vector<vtkIdType> ids(3 * n);
  {
    auto iter = vtk::TakeSmartPointer(polys->NewIterator());
    vtkIdType t = 0;
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++t)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      glm::dvec3 p[3];
      for (int k = 0; k < 3; ++k)
      {
        double x[3];
        input->GetPoint(pts[k], x);
        p[k] = glm::dvec3(x[0], x[1], x[2]) / s;
        ids[3 * t + k] = pts[k];
      }
      if (tiles)
      {
        const TriangleShape shape = Shape(p);
        corner[t] = shape.Corner;
        extents[t] = shape.Extent;
      }
    }
  }
  this->UpdateProgress(0.3);
  if (this->Layout == CHARTS)
  {
    if (!this->MakeCharts(input, ofb, ids.data(), output))
    {
      this->AtlasSize[0] = this->AtlasSize[1] = 0;
      this->NumberOfCharts = 0;
      vtkErrorMacro("The charts do not fit a texture of " << this->MaximumTextureSize
                                                          << " texels a side even at 1/8 "
                                                             "texel a cell.");
    }
    this->UpdateProgress(1.0);
    return 1;
  }
  // Halve the density until the atlas fits.
  std::vector<int> side(n);
  std::vector<int> origin(2 * n);
  for (double density = this->TexelsPerCell; density >= 0.125 - 1e-12; density /= 2.0)
  {
    if (this->LayOut(extents.data(), n, density, side.data(), origin.data()))
    {
      this->EffectiveTexelsPerCell = density;
      break;
    }
    this->AtlasSize[0] = this->AtlasSize[1] = 0;
  }
  if (this->EffectiveTexelsPerCell == 0.0)
  {
    vtkErrorMacro("The triangles do not fit a texture of " << this->MaximumTextureSize
                                                           << " texels a side even at 1/8 "
                                                              "texel a cell.");
    return 1;
  }
  this->WarnOfDensity();
  this->NumberOfCharts = static_cast<int>(n);
  this->UpdateProgress(0.6);

  this->MakeOutput(input, ids.data(), corner.data(), side.data(), origin.data(), output);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::MakeOutput(vtkPolyData* input,
  const vtkIdType* ids,
  const int* corner,
  const int* side,
  const int* origin,
  vtkPolyData* output)
{
  const vtkIdType n = input->GetPolys()->GetNumberOfCells();
  vtkSmartPointer<vtkPolyData> source = vtkOFBTextureAtlas::WithNormals(input);

  // The triangles with their own corners, each corner at its tile's corner texel centre.
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(3 * n);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("AtlasTCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(3 * n);
  vtkPointData* inPD = source->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyTCoordsOff();
  outPD->CopyAllocate(inPD, 3 * n);
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, n);
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(n, 3 * n);
  const double w = this->AtlasSize[0];
  const double h = this->AtlasSize[1];
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double x0 = origin[2 * t] + 0.5;
    const double y0 = origin[2 * t + 1] + 0.5;
    const double far = side[t] - 1.0;
    const double uv[3][2] = { { x0, y0 }, { x0 + far, y0 }, { x0, y0 + far } };
    vtkIdType cell[3];
    for (int k = 0; k < 3; ++k)
    {
      // Cyclic from the corner opposite the longest edge: the orientation is kept.
      const vtkIdType src = ids[3 * t + (corner[t] + k) % 3];
      const vtkIdType dst = 3 * t + k;
      points->SetPoint(dst, input->GetPoint(src));
      outPD->CopyData(inPD, src, dst);
      tcoords->SetTypedComponent(dst, 0, static_cast<float>(uv[k][0] / w));
      tcoords->SetTypedComponent(dst, 1, static_cast<float>(uv[k][1] / h));
      cell[k] = dst;
    }
    triangles->InsertNextCell(3, cell);
    outCD->CopyData(inCD, firstPoly + t, t);
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  outPD->SetTCoords(tcoords);
  AddAtlasSize(output, this->AtlasSize);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkOFBTextureAtlas::WithNormals(vtkPolyData* input)
{
  // Smooth shading survives the repeated points: point normals, computed where missing.
  vtkSmartPointer<vtkPolyData> source = input;
  if (!input->GetPointData()->GetNormals())
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(input);
    normals->SplittingOff();
    normals->ConsistencyOff();
    normals->ComputeCellNormalsOff();
    normals->Update();
    source = normals->GetOutput();
  }
  return source;
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::WarnOfDensity()
{
  if (this->EffectiveTexelsPerCell < this->TexelsPerCell)
  {
    vtkWarningMacro("The atlas holds " << this->EffectiveTexelsPerCell << " texels a cell, not "
                                       << this->TexelsPerCell << ", to fit "
                                       << this->MaximumTextureSize << " texels a side.");
  }
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::MakeCharts(vtkPolyData* input,
  vtkOFB* ofb,
  const vtkIdType* ids,
  vtkPolyData* output)
{
  const vtkIdType n = input->GetPolys()->GetNumberOfCells();
  const vtkIdType np = input->GetNumberOfPoints();
  std::vector<double> x(static_cast<size_t>(3 * np));
  for (vtkIdType p = 0; p < np; ++p)
  {
    input->GetPoint(p, &x[3 * p]);
  }
  // The densest atlas that fits, down to 1/8 texel a cell: the side grows about linearly
  // with the density (the padding does not), so each try scales the density by the room
  // there is (at least 10 % down; half where a try learns no size), 1/8 itself tried last;
  // then a few halvings of the gap between the fitting density and the one above it.
  vtkOFBAtlasCharts charts;
  charts.Prepare(x.data(), ids, n);
  int tries = 0;
  auto build = [&](double d)
  {
    // Progress from 0.3 towards 0.6 with each try (a few on most meshes).
    this->UpdateProgress(0.6 - 0.3 / ++tries);
    return charts.Build(x.data(),
      ids,
      n,
      ofb->GetOrigin(),
      ofb->GetCellSize(),
      d,
      this->ChartPadding,
      this->MaximumTextureSize);
  };
  double density = this->TexelsPerCell;
  double tooDense = 0.0;
  for (int attempt = 0; attempt < 64 && density >= 0.125 - 1e-12; ++attempt)
  {
    if (build(density))
    {
      this->EffectiveTexelsPerCell = density;
      break;
    }
    tooDense = density;
    const int side = std::max(charts.Width, charts.Height);
    const double next =
      density * (side > 0 ? std::min(0.9, 0.98 * this->MaximumTextureSize / side) : 0.5);
    density = next < 0.125 && density > 0.125 + 1e-12 ? 0.125 : next;
  }
  bool built = true; // charts holds the layout of EffectiveTexelsPerCell
  for (int k = 0; k < 4 && this->EffectiveTexelsPerCell > 0.0 &&
       tooDense > 1.02 * this->EffectiveTexelsPerCell;
       ++k)
  {
    const double middle = 0.5 * (this->EffectiveTexelsPerCell + tooDense);
    built = build(middle);
    (built ? this->EffectiveTexelsPerCell : tooDense) = middle;
  }
  if (!built)
  {
    build(this->EffectiveTexelsPerCell);
  }
  if (this->EffectiveTexelsPerCell == 0.0)
  {
    return false;
  }
  this->WarnOfDensity();
  this->AtlasSize[0] = charts.Width;
  this->AtlasSize[1] = charts.Height;
  this->NumberOfCharts = charts.GetNumberOfCharts();
  this->UpdateProgress(0.6);

  // A point of each chart its triangles use: the corners sorted by (point, chart).
  std::vector<vtkIdType> order(static_cast<size_t>(3 * n));
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](vtkIdType c) { return std::make_pair(ids[c], charts.ChartOf[c / 3]); };
  std::sort(order.begin(), order.end(), [&](vtkIdType a, vtkIdType b) { return key(a) < key(b); });
  std::vector<vtkIdType> newId(static_cast<size_t>(3 * n));
  std::vector<vtkIdType> firstCorner; // per output point
  for (size_t k = 0; k < order.size(); ++k)
  {
    if (k == 0 || key(order[k]) != key(order[k - 1]))
    {
      firstCorner.push_back(order[k]);
    }
    newId[order[k]] = static_cast<vtkIdType>(firstCorner.size()) - 1;
  }

  vtkSmartPointer<vtkPolyData> source = vtkOFBTextureAtlas::WithNormals(input);
  const vtkIdType m = static_cast<vtkIdType>(firstCorner.size());
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(m);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("AtlasTCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(m);
  vtkPointData* inPD = source->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyTCoordsOff();
  outPD->CopyAllocate(inPD, m);
  for (vtkIdType q = 0; q < m; ++q)
  {
    const vtkIdType src = ids[firstCorner[q]];
    const glm::dvec2 uv = charts.TexelCoordinates(&x[3 * src], charts.ChartOf[firstCorner[q] / 3]);
    points->SetPoint(q, &x[3 * src]);
    outPD->CopyData(inPD, src, q);
    tcoords->SetTypedComponent(q, 0, static_cast<float>(uv.x / charts.Width));
    tcoords->SetTypedComponent(q, 1, static_cast<float>(uv.y / charts.Height));
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(n, 3 * n);
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, n);
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  for (vtkIdType t = 0; t < n; ++t)
  {
    triangles->InsertNextCell(3, &newId[3 * t]);
    outCD->CopyData(inCD, firstPoly + t, t);
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  outPD->SetTCoords(tcoords);
  AddAtlasSize(output, this->AtlasSize);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layout: " << (this->Layout == CHARTS ? "Charts" : "Triangles") << "\n";
  os << indent << "TexelsPerCell: " << this->TexelsPerCell << "\n";
  os << indent << "ChartPadding: " << this->ChartPadding << " texels\n";
  os << indent << "MinimumTileSize: " << this->MinimumTileSize << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "AtlasSize: " << this->AtlasSize[0] << " x " << this->AtlasSize[1] << "\n";
  os << indent << "EffectiveTexelsPerCell: " << this->EffectiveTexelsPerCell << "\n";
  os << indent << "NumberOfCharts: " << this->NumberOfCharts << "\n";
}
