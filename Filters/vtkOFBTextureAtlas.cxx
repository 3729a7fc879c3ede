#include "vtkOFBTextureAtlas.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkOFB.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

vtkStandardNewMacro(vtkOFBTextureAtlas);

namespace
{
// Bits 0, 2, 4, ... of v packed into the low half (the x of a Morton code; y is v >> 1).
vtkTypeUInt64 Deinterleave(vtkTypeUInt64 v)
{
  v &= 0x5555555555555555ULL;
  v = (v | (v >> 1)) & 0x3333333333333333ULL;
  v = (v | (v >> 2)) & 0x0F0F0F0F0F0F0F0FULL;
  v = (v | (v >> 4)) & 0x00FF00FF00FF00FFULL;
  v = (v | (v >> 8)) & 0x0000FFFF0000FFFFULL;
  v = (v | (v >> 16)) & 0x00000000FFFFFFFFULL;
  return v;
}

int NextPowerOfTwo(double x)
{
  int p = 1;
  while (p < x && p < (1 << 30))
  {
    p *= 2;
  }
  return p;
}

// A triangle's corners in OFB cells, the one opposite the longest edge first.
struct Corners
{
  glm::dvec3 P0;
  glm::dvec3 E1; // P1 - P0
  glm::dvec3 E2; // P2 - P0
};

Corners GetCorners(vtkPoints* points, const vtkIdType* ids, const double* origin, double s)
{
  glm::dvec3 p[3];
  for (int k = 0; k < 3; ++k)
  {
    double x[3];
    points->GetPoint(ids[k], x);
    p[k] = (glm::dvec3(x[0], x[1], x[2]) - glm::dvec3(origin[0], origin[1], origin[2])) / s;
  }
  // Edge k is opposite corner k.
  const double l[3] = {
    glm::length(p[2] - p[1]), glm::length(p[0] - p[2]), glm::length(p[1] - p[0])
  };
  const int k0 = l[0] >= l[1] && l[0] >= l[2] ? 0 : (l[1] >= l[2] ? 1 : 2);
  const glm::dvec3& a = p[k0];
  return Corners{ a, p[(k0 + 1) % 3] - a, p[(k0 + 2) % 3] - a };
}

// Bisection of a sorted list of [first, last] ranges: whether `id` is in one.
bool InRanges(const vtkIdType* r, vtkIdType n, vtkIdType id)
{
  vtkIdType lo = 0;
  vtkIdType hi = n;
  while (lo < hi)
  {
    const vtkIdType mid = (lo + hi) / 2;
    if (r[2 * mid + 1] < id)
    {
      lo = mid + 1;
    }
    else
    {
      hi = mid;
    }
  }
  return lo < n && r[2 * lo] <= id;
}
}

//------------------------------------------------------------------------------
vtkOFBTextureAtlas::vtkOFBTextureAtlas()
  : TexelsPerCell(1.0)
  , MinimumTileSize(4)
  , MaximumTextureSize(16384)
  , Width(0)
  , Height(0)
  , EffectiveTexelsPerCell(0.0)
  , TileLevels(0)
  , CoveredTexels(0)
  , BuiltSurfaceTime(0)
  , BuiltStructureTime(0)
  , BuiltSettingsTime(0)
{
}

//------------------------------------------------------------------------------
vtkOFBTextureAtlas::~vtkOFBTextureAtlas() = default;

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::Initialize()
{
  this->Width = this->Height = 0;
  this->EffectiveTexelsPerCell = 0.0;
  this->TileLevels = 0;
  this->CoveredTexels = 0;
  this->Maps.clear();
  this->TileSize.clear();
  this->TileOrigin.clear();
  this->Samples.clear();
  this->BuiltSurface = nullptr;
  this->BuiltOFB = nullptr;
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::Build(vtkPolyData* surface, vtkOFB* ofb)
{
  if (surface && ofb && surface == this->BuiltSurface && ofb == this->BuiltOFB &&
    surface->GetMTime() == this->BuiltSurfaceTime &&
    ofb->GetStructureMTime() == this->BuiltStructureTime &&
    this->GetMTime() == this->BuiltSettingsTime && this->Width > 0)
  {
    return true;
  }
  this->Initialize();
  this->ErrorMessage.clear();
  if (!this->CheckInput(surface, ofb) || !this->LayOut(surface, ofb))
  {
    vtkErrorMacro(<< this->ErrorMessage);
    this->Initialize();
    return false;
  }
  this->FindTexelSamples(surface, ofb);
  this->BuiltSurface = surface;
  this->BuiltOFB = ofb;
  this->BuiltSurfaceTime = surface->GetMTime();
  this->BuiltStructureTime = ofb->GetStructureMTime();
  this->BuiltSettingsTime = this->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::CheckInput(vtkPolyData* surface, vtkOFB* ofb)
{
  if (!surface || !ofb)
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: no surface or no OFB.";
    return false;
  }
  if (ofb->GetNumberOfSamples() == 0 || !(ofb->GetCellSize() > 0.0))
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: the OFB is empty.";
    return false;
  }
  if (ofb->GetNumberOfSamples() > std::numeric_limits<vtkTypeInt32>::max())
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: the OFB has more than 2^31 samples.";
    return false;
  }
  if (surface->GetNumberOfStrips() > 0)
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: the surface has triangle strips (apply "
                         "vtkTriangleFilter first).";
    return false;
  }
  vtkCellArray* polys = surface->GetPolys();
  if (!polys || polys->GetNumberOfCells() == 0 || !surface->GetPoints())
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: the surface has no polygons.";
    return false;
  }
  if (polys->GetMaxCellSize() != 3 ||
    polys->GetNumberOfConnectivityIds() != 3 * polys->GetNumberOfCells())
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: the surface has polygons that are not triangles "
                         "(apply vtkTriangleFilter first).";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::LayOut(vtkPolyData* surface, vtkOFB* ofb)
{
  vtkCellArray* polys = surface->GetPolys();
  vtkPoints* points = surface->GetPoints();
  const vtkIdType nt = polys->GetNumberOfCells();
  const double* origin = ofb->GetOrigin();
  const double s = ofb->GetCellSize();
  // The longest leg and half the diagonal of each triangle, in cells.
  std::vector<double> extent(nt);
  {
    auto iter = vtk::TakeSmartPointer(polys->NewIterator());
    vtkIdType t = 0;
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++t)
    {
      vtkIdType npts;
      const vtkIdType* ids;
      iter->GetCurrentCell(npts, ids);
      const Corners c = GetCorners(points, ids, origin, s);
      const double e = std::max(
        { glm::length(c.E1), glm::length(c.E2), glm::length(c.E2 - c.E1) / std::sqrt(2.0) });
      extent[t] = std::isfinite(e) ? e : 0.0;
    }
  }
  // Halve the density until the atlas fits.
  const vtkTypeUInt64 maxSide = static_cast<vtkTypeUInt64>(this->MaximumTextureSize);
  for (double density = this->TexelsPerCell; density >= 0.125 - 1e-12; density /= 2.0)
  {
    this->TileSize.resize(nt);
    vtkTypeUInt64 area = 0;
    int smallest = std::numeric_limits<int>::max();
    int largest = 0;
    for (vtkIdType t = 0; t < nt; ++t)
    {
      const double want = std::ceil(extent[t] * density) + 1.0;
      const int side = std::max(this->MinimumTileSize, NextPowerOfTwo(std::min(want, 65536.0)));
      this->TileSize[t] = side;
      area += static_cast<vtkTypeUInt64>(side) * side;
      smallest = std::min(smallest, side);
      largest = std::max(largest, side);
    }
    vtkTypeUInt64 w = 1;
    while (w * w < area || w < static_cast<vtkTypeUInt64>(largest))
    {
      w *= 2;
    }
    const vtkTypeUInt64 h =
      (area <= w * w / 2 && static_cast<vtkTypeUInt64>(largest) <= w / 2) ? w / 2 : w;
    if (w > maxSide || h > maxSide)
    {
      continue;
    }
    this->Width = static_cast<int>(w);
    this->Height = static_cast<int>(h);
    this->EffectiveTexelsPerCell = density;
    this->TileLevels = static_cast<int>(std::round(std::log2(smallest)));
    break;
  }
  if (this->Width == 0)
  {
    this->ErrorMessage = "vtkOFBTextureAtlas: the triangles do not fit a texture of " +
      std::to_string(this->MaximumTextureSize) + " texels a side even at 1/8 texel a cell.";
    return false;
  }
  // Largest tiles first: each starts at a multiple of its area in Morton order.
  std::vector<vtkIdType> order(nt);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(),
    order.end(),
    [this](vtkIdType a, vtkIdType b) { return this->TileSize[a] > this->TileSize[b]; });
  this->TileOrigin.resize(2 * nt);
  vtkTypeUInt64 offset = 0;
  for (vtkIdType t : order)
  {
    this->TileOrigin[2 * t] = static_cast<int>(Deinterleave(offset));
    this->TileOrigin[2 * t + 1] = static_cast<int>(Deinterleave(offset >> 1));
    offset += static_cast<vtkTypeUInt64>(this->TileSize[t]) * this->TileSize[t];
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::FindTexelSamples(vtkPolyData* surface, vtkOFB* ofb)
{
  vtkCellArray* polys = surface->GetPolys();
  vtkPoints* points = surface->GetPoints();
  const vtkIdType nt = polys->GetNumberOfCells();
  const double* origin = ofb->GetOrigin();
  const double s = ofb->GetCellSize();
  const int width = this->Width;
  this->Maps.assign(8 * nt, 0.0f);
  this->Samples.assign(static_cast<size_t>(this->Width) * this->Height, -1);
  vtkTypeInt32* samples = this->Samples.data();
  float* maps = this->Maps.data();
  const double invW = 1.0 / this->Width;
  const double invH = 1.0 / this->Height;
  vtkSMPTools::For(0,
    nt,
    [&](vtkIdType begin, vtkIdType end)
    {
      auto iter = vtk::TakeSmartPointer(polys->NewIterator());
      for (vtkIdType t = begin; t < end; ++t)
      {
        vtkIdType npts;
        const vtkIdType* ids;
        iter->GetCellAtId(t, npts, ids);
        const Corners c = GetCorners(points, ids, origin, s);
        const int side = this->TileSize[t];
        const glm::dvec2 q0(this->TileOrigin[2 * t] + 0.5, this->TileOrigin[2 * t + 1] + 0.5);
        const double leg = side - 1.0;
        // The linear part maps E1 to (leg, 0), E2 to (0, leg) and the normal to 0.
        const glm::dvec3 n = glm::cross(c.E1, c.E2);
        const double n2 = glm::dot(n, n);
        glm::dvec3 row0(0.0);
        glm::dvec3 row1(0.0);
        glm::dvec3 unit(0.0, 0.0, 1.0);
        if (n2 > 0.0 && std::isfinite(n2))
        {
          const glm::dmat3 m(c.E1, c.E2, n / std::sqrt(n2)); // columns
          const glm::dmat3 inv = glm::inverse(m);
          // Rows of inv: the barycentric-like coordinates of a point relative to P0.
          row0 = leg * glm::dvec3(inv[0][0], inv[1][0], inv[2][0]);
          row1 = leg * glm::dvec3(inv[0][1], inv[1][1], inv[2][1]);
          unit = n / std::sqrt(n2);
        }
        const double b0 = q0.x - glm::dot(row0, c.P0);
        const double b1 = q0.y - glm::dot(row1, c.P0);
        float* m = maps + 8 * t;
        m[0] = static_cast<float>(row0.x * invW);
        m[1] = static_cast<float>(row0.y * invW);
        m[2] = static_cast<float>(row0.z * invW);
        m[3] = static_cast<float>(b0 * invW);
        m[4] = static_cast<float>(row1.x * invH);
        m[5] = static_cast<float>(row1.y * invH);
        m[6] = static_cast<float>(row1.z * invH);
        m[7] = static_cast<float>(b1 * invH);
        // The grids in the order of alignment with the normal, as the mapper tries them.
        const glm::dvec3 an = glm::abs(unit);
        int axes[3] = { 0, 1, 2 };
        std::sort(axes, axes + 3, [&an](int a, int b) { return an[a] > an[b]; });
        for (int j = 0; j < side; ++j)
        {
          vtkTypeInt32* texel = samples +
            static_cast<size_t>(this->TileOrigin[2 * t + 1] + j) * width + this->TileOrigin[2 * t];
          for (int i = 0; i < side; ++i)
          {
            double u = side > 1 ? i / leg : 0.0;
            double v = side > 1 ? j / leg : 0.0;
            if (u + v > 1.0)
            {
              const double k = 1.0 / (u + v);
              u *= k;
              v *= k;
            }
            const glm::dvec3 g = c.P0 + u * c.E1 + v * c.E2;
            const double x[3] = { origin[0] + g.x * s, origin[1] + g.y * s, origin[2] + g.z * s };
            vtkIdType id = -1;
            for (int k = 0; k < 3 && id < 0; ++k)
            {
              const double axis[3] = {
                axes[k] == 0 ? 1.0 : 0.0, axes[k] == 1 ? 1.0 : 0.0, axes[k] == 2 ? 1.0 : 0.0
              };
              id = ofb->FindSample(x, axis);
            }
            if (id < 0)
            {
              id = ofb->FindClosestSample(x);
            }
            texel[i] = static_cast<vtkTypeInt32>(id);
          }
        }
      }
    });
  this->CoveredTexels = 0;
  for (vtkTypeInt32 id : this->Samples)
  {
    this->CoveredTexels += id >= 0;
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBTextureAtlas::GetNumberOfSamplesBuilt() const
{
  vtkOFB* ofb = this->BuiltOFB;
  return this->Width > 0 && ofb ? ofb->GetNumberOfSamples() : VTK_ID_MAX;
}

//------------------------------------------------------------------------------
template<typename Writer>
void vtkOFBTextureAtlas::ForEachTexel(vtkIdTypeArray* ranges,
  int rows[2],
  const Writer& write) const
{
  const vtkTypeInt32* samples = this->Samples.data();
  const vtkIdType nr = ranges ? ranges->GetNumberOfTuples() : 0;
  const vtkIdType* r = ranges && nr > 0 ? ranges->GetPointer(0) : nullptr;
  const int width = this->Width;
  int first = this->Height;
  int last = -1;
  if (ranges && nr == 0)
  {
    if (rows)
    {
      rows[0] = first;
      rows[1] = last;
    }
    return;
  }
  vtkSMPThreadLocal<std::pair<int, int>> touched(std::make_pair(this->Height, -1));
  vtkSMPTools::For(0,
    this->Height,
    [&](vtkIdType y0, vtkIdType y1)
    {
      std::pair<int, int>& mine = touched.Local();
      for (vtkIdType y = y0; y < y1; ++y)
      {
        bool any = false;
        const size_t rowStart = static_cast<size_t>(y) * width;
        for (int x = 0; x < width; ++x)
        {
          const vtkTypeInt32 id = samples[rowStart + x];
          if (r && (id < 0 || !InRanges(r, nr, id)))
          {
            continue;
          }
          write(rowStart + x, id);
          any = true;
        }
        if (any)
        {
          mine.first = std::min(mine.first, static_cast<int>(y));
          mine.second = std::max(mine.second, static_cast<int>(y));
        }
      }
    });
  for (const auto& t : touched)
  {
    first = std::min(first, t.first);
    last = std::max(last, t.second);
  }
  if (rows)
  {
    rows[0] = first;
    rows[1] = last;
  }
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::GatherCoverage(unsigned char* out) const
{
  this->ForEachTexel(
    nullptr, nullptr, [out](size_t texel, vtkTypeInt32 id) { out[texel] = id >= 0 ? 255 : 0; });
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::GatherColors(vtkDataArray* colors,
  unsigned char* out,
  vtkIdTypeArray* ranges,
  int rows[2]) const
{
  auto* bytes = vtkArrayDownCast<vtkUnsignedCharArray>(colors);
  const int nc = colors ? colors->GetNumberOfComponents() : 0;
  if (!bytes || (nc != 3 && nc != 4) ||
    colors->GetNumberOfTuples() < this->GetNumberOfSamplesBuilt())
  {
    return false;
  }
  const unsigned char* c = bytes->GetPointer(0);
  this->ForEachTexel(ranges,
    rows,
    [out, c, nc](size_t texel, vtkTypeInt32 id)
    {
      unsigned char* o = out + 4 * texel;
      if (id < 0)
      {
        o[0] = o[1] = o[2] = o[3] = 0;
        return;
      }
      const unsigned char* p = c + static_cast<size_t>(nc) * id;
      const unsigned int a = nc == 4 ? p[3] : 255u;
      for (int k = 0; k < 3; ++k)
      {
        o[k] = static_cast<unsigned char>((p[k] * a + 127u) / 255u);
      }
      o[3] = static_cast<unsigned char>(a);
    });
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::GatherScalars(vtkDataArray* array,
  int component,
  float* out,
  vtkIdTypeArray* ranges,
  int rows[2]) const
{
  if (!array || component >= array->GetNumberOfComponents() ||
    array->GetNumberOfTuples() < this->GetNumberOfSamplesBuilt())
  {
    return false;
  }
  this->ForEachTexel(ranges,
    rows,
    [out, array, component](size_t texel, vtkTypeInt32 id)
    {
      double v = 0.0;
      if (id >= 0)
      {
        if (component >= 0)
        {
          v = array->GetComponent(id, component);
        }
        else
        {
          for (int k = 0; k < array->GetNumberOfComponents(); ++k)
          {
            const double x = array->GetComponent(id, k);
            v += x * x;
          }
          v = std::sqrt(v);
        }
      }
      out[texel] = static_cast<float>(v);
    });
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::GatherIntensity(vtkDataArray* array,
  unsigned short* out,
  vtkIdTypeArray* ranges,
  int rows[2]) const
{
  if (!array || array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfTuples() < this->GetNumberOfSamplesBuilt())
  {
    return false;
  }
  auto* floats = vtkArrayDownCast<vtkFloatArray>(array);
  const float* f = floats ? floats->GetPointer(0) : nullptr;
  this->ForEachTexel(ranges,
    rows,
    [out, array, f](size_t texel, vtkTypeInt32 id)
    {
      double v = 0.0;
      if (id >= 0)
      {
        v = f ? f[id] : array->GetComponent(id, 0);
        v = std::isfinite(v) ? std::min(std::max(v, 0.0), 1.0) : 0.0;
      }
      out[texel] = static_cast<unsigned short>(std::lround(v * 65535.0));
    });
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBTextureAtlas::GatherNormals(vtkDataArray* normals,
  signed char* out,
  vtkIdTypeArray* ranges,
  int rows[2]) const
{
  if (!normals || normals->GetNumberOfComponents() != 3 ||
    normals->GetNumberOfTuples() < this->GetNumberOfSamplesBuilt())
  {
    return false;
  }
  this->ForEachTexel(ranges,
    rows,
    [out, normals](size_t texel, vtkTypeInt32 id)
    {
      signed char* o = out + 4 * texel;
      o[0] = o[1] = o[2] = o[3] = 0;
      if (id < 0)
      {
        return;
      }
      double n[3];
      normals->GetTuple(id, n);
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(len > 0.0) || !std::isfinite(len))
      {
        return;
      }
      for (int k = 0; k < 3; ++k)
      {
        o[k] = static_cast<signed char>(std::lround(127.0 * n[k] / len));
      }
    });
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBTextureAtlas::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TexelsPerCell: " << this->TexelsPerCell << "\n";
  os << indent << "MinimumTileSize: " << this->MinimumTileSize << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "Size: " << this->Width << " x " << this->Height << " texels\n";
  os << indent << "EffectiveTexelsPerCell: " << this->EffectiveTexelsPerCell << "\n";
  os << indent << "Triangles: " << this->GetNumberOfTriangles() << "\n";
  os << indent << "CoveredTexels: " << this->CoveredTexels << "\n";
}
