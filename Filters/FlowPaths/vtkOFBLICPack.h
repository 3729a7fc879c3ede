// Private header of vtkOFBLIC: what packing the samples for the tracer needs besides the
// loop itself (vtkOFBLIC::PrepareSamples): one sample's record, the rows of the three
// grids in chunks of about equal numbers of samples, and the lists of the samples of
// each tile (vtkOFBLICTiles) built from per-chunk counts.
#ifndef vtkOFBLICPack_h
#define vtkOFBLICPack_h

#include "vtkDataArray.h"
#include "vtkOFB.h"
#include "vtkOFBLICTracer.h"
#include "vtkType.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

/**
 * Packs one sample's record for the tracer: position, unit normal (float normals are
 * used as given, the sampler's are unit), the tangential part of the field and the mask
 * (zero, non-finite or below the threshold). Pack returns 1 for a masked sample.
 */
struct vtkOFBLICPacker
{
  const float* Normals;       // float normals, else null
  vtkDataArray* NormalsArray; // the normals of any type
  const float* Vectors;       // float vectors, else null
  vtkDataArray* VectorsArray; // the field of any type
  double Threshold;
  bool OnSurface;
  const double* Origin;   // the OFB's origin and cell size: the record's position is
  double InverseCellSize; // in cells from the origin (vtkOFBLICSample)

  vtkIdType Pack(vtkOFBLICSample& s,
    vtkIdType i,
    const double x[3],
    double& maxMag,
    unsigned char& mask) const
  {
    double t[3];
    glm::dvec3 nrm;
    if (this->Normals)
    {
      nrm = vtkOFBLICTracer::Vec(this->Normals, i);
    }
    else
    {
      this->NormalsArray->GetTuple(i, t);
      nrm = glm::dvec3(t[0], t[1], t[2]);
      const double len = glm::length(nrm);
      nrm = (len > 0.0 && std::isfinite(len)) ? nrm / len : glm::dvec3(0.0);
    }
    for (int c = 0; c < 3; ++c)
    {
      s.Position[c] = static_cast<float>((x[c] - this->Origin[c]) * this->InverseCellSize);
      s.Normal[c] = static_cast<float>(nrm[c]);
      s.Field[c] = 0.0f;
    }
    // The float normal, as the tracer reads it.
    nrm = vtkOFBLICTracer::Vec(s.Normal);
    if (this->Vectors)
    {
      t[0] = this->Vectors[3 * i];
      t[1] = this->Vectors[3 * i + 1];
      t[2] = this->Vectors[3 * i + 2];
    }
    else
    {
      this->VectorsArray->GetTuple(i, t);
    }
    const glm::dvec3 v(t[0], t[1], t[2]);
    const glm::dvec3 tangent = v - glm::dot(v, nrm) * nrm;
    const double mag = glm::length(tangent);
    const double test = this->OnSurface ? mag : glm::length(v);
    if (!(mag > 0.0) || !std::isfinite(mag) || !std::isfinite(test) || test < this->Threshold)
    {
      mask = 1;
      s.Flags |= 4;
      return 1;
    }
    mask = 0;
    maxMag = std::max(maxMag, mag);
    for (int c = 0; c < 3; ++c)
    {
      s.Field[c] = static_cast<float>(tangent[c]);
    }
    return 0;
  }
};

/**
 * The rows of cells of the three grids (grid 0's rows, then grid 1's, then grid 2's, the
 * order of the sample ids) in Count chunks of consecutive rows, each starting at the
 * first row whose first sample is at or after c n / Count: chunk c holds rows
 * [Row[c], Row[c + 1]) and samples [First[c], First[c + 1]).
 */
struct vtkOFBLICRowChunks
{
  vtkIdType RowBase[4] = { 0, 0, 0, 0 }; // first row of each grid
  vtkIdType Count = 1;
  std::vector<vtkIdType> Row;
  std::vector<vtkIdType> First;

  vtkOFBLICRowChunks(vtkOFB* ofb, vtkIdType wanted)
  {
    const vtkIdType n = ofb->GetNumberOfSamples();
    const vtkIdType* dims = ofb->GetDimensions();
    const vtkTypeUInt32* offsets = ofb->GetCellOffsets()->GetPointer(0);
    for (int a = 0; a < 3; ++a)
    {
      this->RowBase[a + 1] = this->RowBase[a] + dims[(a + 2) % 3];
    }
    const vtkIdType rows = this->RowBase[3];
    auto firstSample = [&](vtkIdType r) -> vtkIdType
    {
      if (r >= rows)
      {
        return n;
      }
      const int a = this->GridOf(r);
      return offsets[ofb->GetGridCellBase(a) + (r - this->RowBase[a]) * dims[(a + 1) % 3]];
    };
    this->Count = std::max<vtkIdType>(1, std::min(rows, wanted));
    this->Row.assign(this->Count + 1, rows);
    this->First.assign(this->Count + 1, n);
    this->Row[0] = 0;
    for (vtkIdType c = 0; c < this->Count; ++c)
    {
      vtkIdType lo = c > 0 ? this->Row[c - 1] : 0;
      vtkIdType hi = rows;
      const vtkIdType target = n * c / this->Count;
      while (c > 0 && lo < hi)
      {
        const vtkIdType mid = (lo + hi) / 2;
        if (firstSample(mid) < target)
        {
          lo = mid + 1;
        }
        else
        {
          hi = mid;
        }
      }
      this->Row[c] = c > 0 ? lo : 0;
      this->First[c] = firstSample(this->Row[c]);
    }
  }

  /// The grid of row r.
  int GridOf(vtkIdType r) const
  {
    return r < this->RowBase[1] ? 0 : (r < this->RowBase[2] ? 1 : 2);
  }
};

/**
 * A counting sort of the sample ids by tile over row chunks: each chunk counts its
 * samples per tile (Count), Finish turns the counts into where each chunk's samples of
 * each tile go and writes the tiles' starts, and Place puts a sample in its tile's list.
 * Within a tile the lists hold the samples chunk after chunk in increasing order,
 * whatever the number of threads.
 */
class vtkOFBLICTileSort
{
public:
  vtkOFBLICTileSort(vtkIdType chunks, vtkIdType tiles)
    : Tiles(tiles)
    , Slots(static_cast<std::size_t>(chunks * tiles), 0)
  {
  }

  void Count(vtkIdType chunk, vtkIdType tile) { ++this->Slots[chunk * this->Tiles + tile]; }

  /// first[t]: where tile t's list starts (Tiles + 1 entries).
  void Finish(vtkIdType chunks, std::vector<vtkIdType>& first)
  {
    first.resize(this->Tiles + 1);
    vtkIdType next = 0;
    for (vtkIdType tile = 0; tile < this->Tiles; ++tile)
    {
      first[tile] = next;
      for (vtkIdType chunk = 0; chunk < chunks; ++chunk)
      {
        vtkTypeUInt32& slot = this->Slots[chunk * this->Tiles + tile];
        const vtkTypeUInt32 count = slot;
        slot = static_cast<vtkTypeUInt32>(next);
        next += count;
      }
    }
    first[this->Tiles] = next;
  }

  void Place(vtkIdType chunk, vtkIdType tile, vtkIdType i, vtkTypeInt32* ids)
  {
    ids[this->Slots[chunk * this->Tiles + tile]++] = static_cast<vtkTypeInt32>(i);
  }

private:
  vtkIdType Tiles;
  std::vector<vtkTypeUInt32> Slots; // per chunk and tile
};

#endif
