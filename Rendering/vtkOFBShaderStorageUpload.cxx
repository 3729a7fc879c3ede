// vtkOFBShaderStorage's uploads: the buffers' allocation and the transfer of the OFB's
// levels, changed ranges, arrays and lookup table into them.
#include "vtkOFBShaderStorage.h"

#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkOFB.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
// Bytes per sample of the per-sample buffers.
size_t BytesPerSample(int id)
{
  switch (id)
  {
    case vtkOFBShaderStorage::BUFFER_SAMPLES:
      return 2 * sizeof(vtkTypeUInt32); // depth, colour attribute
    case vtkOFBShaderStorage::BUFFER_NORMALS:
      return 3 * sizeof(float);
    case vtkOFBShaderStorage::BUFFER_INTENSITY:
      return 1; // [0, 1] in a byte, four to a word (a quarter of a float's cache footprint)
    default:
      return 4;
  }
}

// Scalar value of tuple t of `array`: component `component`, or the magnitude when it is
// negative and the array has several components.
float ScalarValue(vtkDataArray* array, vtkIdType t, int component)
{
  const int nc = array->GetNumberOfComponents();
  if (component < 0 && nc > 1)
  {
    double sum = 0.0;
    for (int c = 0; c < nc; ++c)
    {
      const double v = array->GetComponent(t, c);
      sum += v * v;
    }
    return static_cast<float>(std::sqrt(sum));
  }
  return static_cast<float>(array->GetComponent(t, std::max(component, 0)));
}
}

//------------------------------------------------------------------------------
bool vtkOFBShaderStorage::Allocate(int id, size_t bytes)
{
  bytes = std::max<size_t>(bytes, 16); // an empty SSBO binding is an error
  if (this->Handles[id] && this->Sizes[id] == bytes)
  {
    return true;
  }
  if (!this->Handles[id])
  {
    glGenBuffers(1, &this->Handles[id]);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handles[id]);
  // Clear earlier errors, at most 16 (a lost context may report one on every call).
  for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k)
  {
  }
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_DRAW);
  const bool ok = glGetError() == GL_NO_ERROR;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  this->Sizes[id] = ok ? bytes : 0;
  return ok;
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::Upload(int id, size_t offset, size_t bytes, const void* data)
{
  if (bytes == 0 || !this->Handles[id] || offset + bytes > this->Sizes[id])
  {
    return;
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handles[id]);
  glBufferSubData(
    GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  this->UploadedBytes += bytes;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::UploadArray(int id,
  vtkDataArray* array,
  vtkIdType first,
  vtkIdType last,
  vtkIdType base)
{
  if (!array || first >= last)
  {
    return;
  }
  if (id == BUFFER_INTENSITY)
  {
    this->UploadIntensity(array, first, last, base);
    return;
  }
  if (id == BUFFER_FLOW)
  {
    if (base == 0) // level 0 alone
    {
      this->UploadFlow(array, first, last);
    }
    return;
  }
  const size_t n = static_cast<size_t>(last - first);
  const size_t bps = BytesPerSample(id);
  const size_t offset = static_cast<size_t>(base + first) * bps;
  this->Scratch.resize(n * bps);
  float* dst = reinterpret_cast<float*>(this->Scratch.data());
  if (id == BUFFER_NORMALS)
  {
    for (size_t i = 0; i < n; ++i)
    {
      double t[3];
      array->GetTuple(first + static_cast<vtkIdType>(i), t);
      dst[3 * i] = static_cast<float>(t[0]);
      dst[3 * i + 1] = static_cast<float>(t[1]);
      dst[3 * i + 2] = static_cast<float>(t[2]);
    }
  }
  else
  {
    for (size_t i = 0; i < n; ++i)
    {
      dst[i] = ScalarValue(array, first + static_cast<vtkIdType>(i), 0);
    }
  }
  this->Upload(id, offset, n * bps, dst);
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::UploadIntensity(vtkDataArray* array,
  vtkIdType first,
  vtkIdType last,
  vtkIdType base)
{
  // Whole words: the samples from first rounded down to a multiple of 4 to last rounded up
  // (a level's base is a multiple of 4; bytes past its last sample are 0).
  const vtkIdType n = array->GetNumberOfTuples();
  first &= ~vtkIdType(3);
  last = (last + 3) & ~vtkIdType(3);
  const size_t count = static_cast<size_t>(last - first);
  this->Scratch.resize(count);
  unsigned char* dst = this->Scratch.data();
  for (size_t i = 0; i < count; ++i)
  {
    const vtkIdType t = first + static_cast<vtkIdType>(i);
    const float v = t < n ? ScalarValue(array, t, 0) : 0.0f;
    // Clamped to [0, 1] (NaN to 0), rounded to 1/255.
    dst[i] = static_cast<unsigned char>(v > 0.0f ? std::min(v, 1.0f) * 255.0f + 0.5f : 0.0f);
  }
  this->Upload(BUFFER_INTENSITY, static_cast<size_t>(base + first), count, dst);
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::UploadFlow(vtkDataArray* array, vtkIdType first, vtkIdType last)
{
  // The unit vector of the field, x, y and z rounded to 1/511 as 10-bit two's complement
  // integers at bits 0, 10 and 20 of a word; 0 where the field vanishes (or is not finite).
  const size_t n = static_cast<size_t>(last - first);
  this->Scratch.resize(n * sizeof(vtkTypeUInt32));
  vtkTypeUInt32* dst = reinterpret_cast<vtkTypeUInt32*>(this->Scratch.data());
  for (size_t i = 0; i < n; ++i)
  {
    double v[3];
    array->GetTuple(first + static_cast<vtkIdType>(i), v);
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    vtkTypeUInt32 word = 0;
    if (length > 1.0e-30 && std::isfinite(length))
    {
      for (int c = 0; c < 3; ++c)
      {
        const long q = std::lround(511.0 * std::max(-1.0, std::min(1.0, v[c] / length)));
        word |= (static_cast<vtkTypeUInt32>(q) & 0x3FFu) << (10 * c);
      }
    }
    dst[i] = word;
  }
  this->Upload(BUFFER_FLOW,
    static_cast<size_t>(first) * sizeof(vtkTypeUInt32),
    n * sizeof(vtkTypeUInt32),
    dst);
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::UploadSamples(vtkOFB* ofb,
  vtkDataArray* attribute,
  const Selection& selection,
  vtkIdType first,
  vtkIdType last,
  vtkIdType base)
{
  if (first >= last)
  {
    return;
  }
  const size_t n = static_cast<size_t>(last - first);
  this->Scratch.resize(n * BytesPerSample(BUFFER_SAMPLES));
  vtkTypeUInt32* dst = reinterpret_cast<vtkTypeUInt32*>(this->Scratch.data());
  // Depths in cells of the level.
  const float* depths = ofb->GetDepths()->GetPointer(first);
  const double inv = 1.0 / ofb->GetCellSize();
  for (size_t i = 0; i < n; ++i)
  {
    const float depth = static_cast<float>(depths[i] * inv);
    std::memcpy(&dst[2 * i], &depth, 4);
    dst[2 * i + 1] = 0;
  }
  auto* colors = vtkUnsignedCharArray::SafeDownCast(attribute);
  if (selection.Colors && colors)
  {
    // RGBA bytes are the packed little-endian uint the shader unpacks.
    const int nc = colors->GetNumberOfComponents();
    const unsigned char* src = colors->GetPointer(nc * first);
    for (size_t i = 0; i < n; ++i)
    {
      unsigned char rgba[4] = { 0, 0, 0, 255 };
      std::memcpy(rgba, src + nc * i, std::min(nc, 4));
      std::memcpy(&dst[2 * i + 1], rgba, 4);
    }
  }
  else if (!selection.Colors && attribute)
  {
    for (size_t i = 0; i < n; ++i)
    {
      const float value =
        ScalarValue(attribute, first + static_cast<vtkIdType>(i), selection.ScalarComponent);
      std::memcpy(&dst[2 * i + 1], &value, 4);
    }
  }
  this->Upload(BUFFER_SAMPLES,
    static_cast<size_t>(base + first) * BytesPerSample(BUFFER_SAMPLES),
    n * BytesPerSample(BUFFER_SAMPLES),
    dst);
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBShaderStorage::UploadAll(const std::vector<vtkOFB*>& levels,
  const Selection& selection,
  std::string& error)
{
  this->LevelCellBase.clear();
  this->LevelSampleBase.clear();
  this->LevelDims.clear();
  vtkIdType totalCells = 0;
  vtkIdType totalSamples = 0; // with the levels' padding
  vtkIdType uploaded = 0;
  for (vtkOFB* ofb : levels)
  {
    const vtkIdType* dims = ofb->GetDimensions();
    for (int a = 0; a < 3; ++a)
    {
      this->LevelCellBase.push_back(static_cast<int>(totalCells + ofb->GetGridCellBase(a)));
      this->LevelDims.push_back(static_cast<int>(dims[a]));
    }
    this->LevelSampleBase.push_back(static_cast<int>(totalSamples));
    totalCells += ofb->GetNumberOfCells() + 1;
    // Levels start at multiples of 4 samples: the intensity's words hold one level each.
    totalSamples += (ofb->GetNumberOfSamples() + 3) & ~vtkIdType(3);
    uploaded += ofb->GetNumberOfSamples();
  }
  if (totalCells > VTK_INT_MAX || totalSamples > VTK_INT_MAX)
  {
    error = "the OFB is too large for 32-bit indices in the shader";
    return -1;
  }
  const size_t ns = static_cast<size_t>(totalSamples);
  bool ok = this->Allocate(BUFFER_OFFSETS, static_cast<size_t>(totalCells) * 4) &&
    this->Allocate(BUFFER_SAMPLES, ns * BytesPerSample(BUFFER_SAMPLES));
  const int arrays[3] = { BUFFER_INTENSITY, BUFFER_NORMALS, BUFFER_FLOW };
  const bool wanted[3] = {
    !selection.IntensityName.empty(), selection.Normals, !selection.FlowName.empty()
  };
  for (int k = 0; k < 3 && ok; ++k)
  {
    if (wanted[k])
    {
      // The flow of level 0 alone (the flow-aligned filter reads level 0 only).
      const size_t count =
        arrays[k] == BUFFER_FLOW ? static_cast<size_t>(levels[0]->GetNumberOfSamples()) : ns;
      ok = this->Allocate(arrays[k], count * BytesPerSample(arrays[k]));
    }
    else if (this->Handles[arrays[k]])
    {
      glDeleteBuffers(1, &this->Handles[arrays[k]]);
      this->Handles[arrays[k]] = 0;
      this->Sizes[arrays[k]] = 0;
    }
  }
  if (!ok)
  {
    error = "could not allocate " + std::to_string(ns) + " samples of GPU memory";
    this->FreeBuffers();
    return -1;
  }
  size_t cellOffset = 0;
  this->MaximumCellSamples = 0;
  for (size_t l = 0; l < levels.size(); ++l)
  {
    vtkOFB* ofb = levels[l];
    const vtkIdType nc = ofb->GetNumberOfCells() + 1;
    const vtkTypeUInt32* offsets = ofb->GetCellOffsets()->GetPointer(0);
    vtkTypeUInt32 most = 0;
    for (vtkIdType c = 0; c + 1 < nc; ++c)
    {
      most = std::max(most, offsets[c + 1] - offsets[c]);
    }
    this->MaximumCellSamples = std::max(this->MaximumCellSamples, static_cast<int>(most));
    this->Upload(BUFFER_OFFSETS,
      cellOffset * 4,
      static_cast<size_t>(nc) * 4,
      ofb->GetCellOffsets()->GetPointer(0));
    cellOffset += static_cast<size_t>(nc);
    const vtkIdType n = ofb->GetNumberOfSamples();
    this->UploadSamples(ofb,
      GetArray(ofb, selection.Colors ? ATTRIBUTE_COLORS : ATTRIBUTE_SCALARS, selection),
      selection,
      0,
      n,
      this->LevelSampleBase[l]);
    for (int k = 0; k < 3; ++k)
    {
      if (wanted[k] && (arrays[k] != BUFFER_FLOW || l == 0))
      {
        this->UploadArray(
          arrays[k], GetArray(ofb, arrays[k], selection), 0, n, this->LevelSampleBase[l]);
      }
    }
  }
  vtkOpenGLStaticCheckErrorMacro("failed after uploading the OFB");
  return uploaded;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBShaderStorage::UploadRanges(const std::vector<vtkOFB*>& levels,
  int level,
  const Selection& selection,
  vtkIdTypeArray* ranges,
  unsigned int buffers)
{
  if (!(buffers & AllArrays))
  {
    return 0;
  }
  if (level < 0 || level >= static_cast<int>(levels.size()) ||
    level >= static_cast<int>(this->LevelSampleBase.size()) || !ranges)
  {
    return 0;
  }
  vtkOFB* ofb = levels[level];
  const bool samples = (buffers & (1u << BUFFER_SAMPLES)) != 0;
  vtkDataArray* attribute =
    GetArray(ofb, selection.Colors ? ATTRIBUTE_COLORS : ATTRIBUTE_SCALARS, selection);
  const int arrays[3] = { BUFFER_INTENSITY, BUFFER_NORMALS, BUFFER_FLOW };
  const bool wanted[3] = { !selection.IntensityName.empty() && (buffers & (1u << BUFFER_INTENSITY)),
    selection.Normals && (buffers & (1u << BUFFER_NORMALS)),
    !selection.FlowName.empty() && level == 0 && (buffers & (1u << BUFFER_FLOW)) };
  vtkDataArray* sources[3];
  for (int k = 0; k < 3; ++k)
  {
    sources[k] = wanted[k] ? GetArray(ofb, arrays[k], selection) : nullptr;
  }
  const vtkIdType n = ofb->GetNumberOfSamples();
  vtkIdType count = 0;
  for (vtkIdType r = 0; r < ranges->GetNumberOfTuples(); ++r)
  {
    const vtkIdType first = std::max<vtkIdType>(0, ranges->GetTypedComponent(r, 0));
    const vtkIdType last = std::min(n, ranges->GetTypedComponent(r, 1));
    if (first >= last)
    {
      continue;
    }
    if (samples)
    {
      this->UploadSamples(ofb, attribute, selection, first, last, this->LevelSampleBase[level]);
    }
    for (int k = 0; k < 3; ++k)
    {
      this->UploadArray(arrays[k], sources[k], first, last, this->LevelSampleBase[level]);
    }
    count += last - first;
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::UploadLookupTable(vtkScalarsToColors* lut, const double range[2])
{
  if (!lut || !this->Allocate(BUFFER_LUT, LUTSize * 4 * sizeof(float)))
  {
    return;
  }
  std::vector<float> table(LUTSize * 4);
  for (int i = 0; i < LUTSize; ++i)
  {
    const double v = range[0] + (range[1] - range[0]) * i / (LUTSize - 1.0);
    double rgb[3];
    lut->GetColor(v, rgb);
    table[4 * i] = static_cast<float>(rgb[0]);
    table[4 * i + 1] = static_cast<float>(rgb[1]);
    table[4 * i + 2] = static_cast<float>(rgb[2]);
    table[4 * i + 3] = static_cast<float>(lut->GetOpacity(v));
  }
  this->Upload(BUFFER_LUT, 0, table.size() * sizeof(float), table.data());
}
