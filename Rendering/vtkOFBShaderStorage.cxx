#include "vtkOFBShaderStorage.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkOFB.h"
#include "vtkOFBPyramid.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace
{
// Binding points of the buffers: away from the low points that other code binds.
constexpr unsigned int BindingBase = 8;

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
vtkOFBShaderStorage::vtkOFBShaderStorage()
{
  for (int i = 0; i < NUMBER_OF_BUFFERS; ++i)
  {
    this->Handles[i] = 0;
    this->Sizes[i] = 0;
  }
}

//------------------------------------------------------------------------------
vtkOFBShaderStorage::~vtkOFBShaderStorage()
{
  // Buffers still held here belong to a window that outlived the mapper: free them in that
  // window's context when it is current, else leave them to it.
  if (this->Window && this->GetMemorySize() > 0 && this->Window->IsCurrent())
  {
    this->FreeBuffers();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBShaderStorage::SetContext(vtkOpenGLRenderWindow* window, std::string& why)
{
  if (!window || window != this->CheckedWindow)
  {
    this->CheckedWindow = window;
    this->CheckedWindowSupported = IsSupported(window, this->CheckedWindowReason);
  }
  if (!this->CheckedWindowSupported)
  {
    why = this->CheckedWindowReason;
    return false;
  }
  if (window != this->Window)
  {
    // The buffers are deleted in the old window's context; where that window is gone
    // (this weak pointer is cleared before its destructor releases graphics resources),
    // FreeBuffers only forgets their names, which mean nothing, or other objects, in the
    // new context.
    if (this->Window)
    {
      this->Window->MakeCurrent();
    }
    this->FreeBuffers();
    window->MakeCurrent();
    this->Window = window;
    this->ForgetUploads();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBShaderStorage::UpdateLevels(vtkOFB* ofb,
  vtkPolyData* surface,
  bool mipmapped,
  int maximumLevels,
  int minimumResolution)
{
  this->Levels.assign(1, ofb);
  if (!mipmapped)
  {
    if (this->Pyramid->GetInputOFB())
    {
      this->Pyramid->SetInputOFB(nullptr);
      this->Pyramid->SetSurface(nullptr);
    }
    return true;
  }
  this->Pyramid->SetInputOFB(ofb);
  this->Pyramid->SetSurface(surface);
  this->Pyramid->SetMaximumNumberOfLevels(std::min(maximumLevels, MaximumNumberOfLevels));
  this->Pyramid->SetMinimumResolution(minimumResolution);
  if (!this->Pyramid->UpdateLevels())
  {
    return false;
  }
  for (int k = 1; k < this->Pyramid->GetNumberOfLevels(); ++k)
  {
    this->Levels.push_back(this->Pyramid->GetLevel(k));
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBShaderStorage::UploadChanges(const Selection& selection, std::string& error)
{
  vtkOFB* ofb = this->Levels.empty() ? nullptr : this->Levels[0];
  if (!ofb || !this->Window)
  {
    error = "no OFB or no window";
    return -1;
  }
  std::ostringstream key;
  key << this->Levels.size() << "|" << selection.Colors << "|" << selection.ScalarName << "|"
      << selection.ScalarComponent << "|" << selection.IntensityName << "|" << selection.Normals;
  const bool mipmapped = this->Levels.size() > 1;
  const bool full = ofb != this->UploadedOFB || key.str() != this->UploadKey ||
    ofb->GetStructureMTime() > this->UploadTime.GetMTime() ||
    (mipmapped && this->Pyramid->GetStructureTime() > this->UploadedPyramidTime) ||
    this->GetMemorySize() == 0;
  this->Window->MakeCurrent();
  vtkIdType count = 0;
  if (full)
  {
    count = this->UploadAll(this->Levels, selection, error);
    if (count < 0)
    {
      this->UploadedOFB = nullptr;
      return -1;
    }
    this->UploadedOFB = ofb;
    this->UploadKey = key.str();
  }
  else
  {
    const unsigned int whole = this->UploadChangedArrays(selection, count);
    ofb->GetSampleRangesModifiedSince(this->UploadTime.GetMTime(), this->Ranges);
    count += this->UploadRanges(this->Levels, 0, selection, this->Ranges, AllArrays & ~whole);
    if (mipmapped)
    {
      count += this->UploadCoarseLevels(selection, whole);
    }
  }
  this->RecordArrays(selection);
  this->UploadedPyramidTime = this->Pyramid->GetStructureTime();
  this->UploadTime.Modified();
  return count;
}

//------------------------------------------------------------------------------
unsigned int vtkOFBShaderStorage::UploadChangedArrays(const Selection& selection, vtkIdType& count)
{
  vtkOFB* ofb = this->Levels[0];
  const vtkIdType n = ofb->GetNumberOfSamples();
  const int base = this->LevelSampleBase.empty() ? 0 : this->LevelSampleBase[0];
  const int ids[3] = { BUFFER_SAMPLES, BUFFER_INTENSITY, BUFFER_NORMALS };
  const bool wanted[3] = { true, !selection.IntensityName.empty(), selection.Normals };
  unsigned int whole = 0;
  for (int k = 0; k < 3; ++k)
  {
    vtkDataArray* array = !wanted[k]
      ? nullptr
      : GetArray(ofb,
          ids[k] == BUFFER_SAMPLES ? (selection.Colors ? ATTRIBUTE_COLORS : ATTRIBUTE_SCALARS)
                                   : ids[k],
          selection);
    if (!array ||
      (array == this->UploadedArrays[ids[k]] && array->GetMTime() <= this->UploadTime.GetMTime()))
    {
      continue;
    }
    if (ids[k] == BUFFER_SAMPLES)
    {
      this->UploadSamples(ofb, array, selection, 0, n, base);
    }
    else
    {
      this->UploadArray(ids[k], array, 0, n, base);
    }
    whole |= 1u << ids[k];
    count = n;
  }
  return whole;
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::RecordArrays(const Selection& selection)
{
  vtkOFB* ofb = this->Levels[0];
  this->UploadedArrays[BUFFER_SAMPLES] =
    GetArray(ofb, selection.Colors ? ATTRIBUTE_COLORS : ATTRIBUTE_SCALARS, selection);
  this->UploadedArrays[BUFFER_INTENSITY] =
    selection.IntensityName.empty() ? nullptr : GetArray(ofb, BUFFER_INTENSITY, selection);
  this->UploadedArrays[BUFFER_NORMALS] =
    selection.Normals ? GetArray(ofb, BUFFER_NORMALS, selection) : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBShaderStorage::UploadCoarseLevels(const Selection& selection, unsigned int whole)
{
  // Level 0 changed since the last upload: filter the coarser levels' attributes again,
  // only the arrays modified (a new LIC: the LIC alone), or, where samples changed in
  // place (ranges, e.g. painting), only the samples of each level that read them, and
  // upload those.
  const bool inPlace = this->Ranges->GetNumberOfTuples() > 0;
  if ((whole || inPlace) && this->Pyramid->GetArraysTime() <= this->UploadTime.GetMTime())
  {
    this->Pyramid->UpdateModifiedArrays();
  }
  if (this->Pyramid->GetArraysTime() <= this->UploadTime.GetMTime())
  {
    return 0;
  }
  // Every buffer where other arrays may have changed too: samples changed in place, or
  // the pyramid computed all arrays again since the last upload; the samples marked on
  // each level where the pyramid filtered those alone.
  const bool everything = this->Pyramid->GetAllArraysTime() > this->UploadTime.GetMTime();
  const bool all = inPlace || !whole || everything;
  const bool marked = inPlace && !whole && !everything;
  const unsigned int buffers = all ? AllArrays : whole;
  vtkIdType count = 0;
  for (size_t k = 1; k < this->Levels.size(); ++k)
  {
    if (marked)
    {
      this->Levels[k]->GetSampleRangesModifiedSince(this->UploadTime.GetMTime(), this->Ranges);
    }
    else
    {
      this->Ranges->Initialize();
      this->Ranges->SetNumberOfComponents(2);
      const vtkIdType range[2] = { 0, this->Levels[k]->GetNumberOfSamples() };
      this->Ranges->InsertNextTypedTuple(range);
    }
    count +=
      this->UploadRanges(this->Levels, static_cast<int>(k), selection, this->Ranges, buffers);
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::UpdateLookupTable(vtkScalarsToColors* lut, const double range[2])
{
  if (!lut)
  {
    return;
  }
  if (lut != this->UploadedLUT || lut->GetMTime() > this->UploadedLUTTime ||
    range[0] != this->UploadedLUTRange[0] || range[1] != this->UploadedLUTRange[1])
  {
    this->UploadLookupTable(lut, range);
    this->UploadedLUT = lut;
    this->UploadedLUTTime = lut->GetMTime();
    this->UploadedLUTRange[0] = range[0];
    this->UploadedLUTRange[1] = range[1];
  }
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::SetUniforms(vtkShaderProgram* program, bool scalars)
{
  vtkOFB* ofb = this->UploadedOFB;
  if (!program || !ofb)
  {
    return;
  }
  this->SetBlockBindings(program);
  // Level l's position is the level-0 position (in level-0 cells) scaled and shifted.
  const int nl = std::min(this->GetNumberOfLevels(), static_cast<int>(this->Levels.size()));
  const double* origin = ofb->GetOrigin();
  const double s = ofb->GetCellSize();
  float transforms[4 * MaximumNumberOfLevels] = { 0.0f };
  for (int l = 0; l < nl; ++l)
  {
    vtkOFB* level = this->Levels[l];
    const double sl = level->GetCellSize();
    const double* ol = level->GetOrigin();
    for (int i = 0; i < 3; ++i)
    {
      transforms[4 * l + i] = static_cast<float>((origin[i] - ol[i]) / sl);
    }
    transforms[4 * l + 3] = static_cast<float>(s / sl);
  }
  program->SetUniformi("ofbNumberOfLevels", nl);
  program->SetUniform4fv("ofbLevelTransform", nl, transforms);
  program->SetUniform1iv("ofbLevelDims", 3 * nl, this->LevelDims.data());
  program->SetUniform1iv("ofbLevelCellBase", 3 * nl, this->LevelCellBase.data());
  program->SetUniform1iv("ofbLevelSampleBase", nl, this->LevelSampleBase.data());
  if (scalars)
  {
    const double span = this->UploadedLUTRange[1] - this->UploadedLUTRange[0];
    const float range[2] = { static_cast<float>(this->UploadedLUTRange[0]),
      static_cast<float>(span != 0.0 ? 1.0 / span : 0.0) };
    program->SetUniform2f("ofbScalarRange", range);
    program->SetUniformi("ofbLUTSize", LUTSize);
  }
}

//------------------------------------------------------------------------------
bool vtkOFBShaderStorage::IsSupported(vtkOpenGLRenderWindow* window, std::string& why)
{
  if (!window)
  {
    why = "the render window is not an OpenGL one";
    return false;
  }
  window->MakeCurrent();
  if (!window->IsCurrent())
  {
    why = "the render window has no current OpenGL context";
    return false;
  }
  if (!(GLEW_VERSION_4_3 || GLEW_ARB_shader_storage_buffer_object))
  {
    why = "the OpenGL context offers neither OpenGL 4.3 nor ARB_shader_storage_buffer_object";
    return false;
  }
  if (!(GLEW_VERSION_3_3 || GLEW_ARB_shader_bit_encoding))
  {
    why = "the OpenGL context offers neither OpenGL 3.3 nor ARB_shader_bit_encoding";
    return false;
  }
  GLint blocks = 0;
  glGetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &blocks);
  GLint bindings = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
  if (blocks < NUMBER_OF_BUFFERS || bindings < static_cast<GLint>(BindingBase + NUMBER_OF_BUFFERS))
  {
    why = "the OpenGL context offers too few fragment shader storage blocks (" +
      std::to_string(blocks) + ") or bindings (" + std::to_string(bindings) + ")";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
const char* vtkOFBShaderStorage::GetBlockName(int id)
{
  static const char* names[NUMBER_OF_BUFFERS] = {
    "ofbOffsetsBlock", "ofbSamplesBlock", "ofbIntensityBlock", "ofbNormalsBlock", "ofbLUTBlock"
  };
  return (id >= 0 && id < NUMBER_OF_BUFFERS) ? names[id] : "";
}

//------------------------------------------------------------------------------
unsigned int vtkOFBShaderStorage::GetBindingPoint(int id)
{
  return BindingBase + static_cast<unsigned int>(id);
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBShaderStorage::GetArray(vtkOFB* ofb, int id, const Selection& selection)
{
  // An array with fewer tuples than samples is as good as missing (its upload would read
  // past its end).
  vtkDataArray* array = ofb ? FindArray(ofb->GetSampleData(), id, selection) : nullptr;
  return array && array->GetNumberOfTuples() >= ofb->GetNumberOfSamples() ? array : nullptr;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkOFBShaderStorage::FindArray(vtkPointData* pd, int id, const Selection& selection)
{
  if (!pd)
  {
    return nullptr;
  }
  vtkDataArray* array = nullptr;
  switch (id)
  {
    case ATTRIBUTE_COLORS:
    {
      array = pd->GetArray(vtkOFB::ColorsArrayName());
      if (!array)
      {
        array = pd->GetScalars();
      }
      vtkUnsignedCharArray* uc = vtkUnsignedCharArray::SafeDownCast(array);
      return (uc && (uc->GetNumberOfComponents() == 3 || uc->GetNumberOfComponents() == 4))
        ? uc
        : nullptr;
    }
    case ATTRIBUTE_SCALARS:
      array = selection.ScalarName.empty() ? nullptr : pd->GetArray(selection.ScalarName.c_str());
      if (array && selection.ScalarComponent >= array->GetNumberOfComponents())
      {
        return nullptr;
      }
      return array;
    case BUFFER_INTENSITY:
      array =
        selection.IntensityName.empty() ? nullptr : pd->GetArray(selection.IntensityName.c_str());
      return array;
    case BUFFER_NORMALS:
      array = pd->GetArray(vtkOFB::NormalsArrayName());
      if (!array)
      {
        array = pd->GetNormals();
      }
      return (array && array->GetNumberOfComponents() == 3) ? array : nullptr;
    default:
      return nullptr;
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
  const int arrays[2] = { BUFFER_INTENSITY, BUFFER_NORMALS };
  const bool wanted[2] = { !selection.IntensityName.empty(), selection.Normals };
  for (int k = 0; k < 2 && ok; ++k)
  {
    if (wanted[k])
    {
      ok = this->Allocate(arrays[k], ns * BytesPerSample(arrays[k]));
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
    for (int k = 0; k < 2; ++k)
    {
      if (wanted[k])
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
  const int arrays[2] = { BUFFER_INTENSITY, BUFFER_NORMALS };
  const bool wanted[2] = { !selection.IntensityName.empty() && (buffers & (1u << BUFFER_INTENSITY)),
    selection.Normals && (buffers & (1u << BUFFER_NORMALS)) };
  vtkDataArray* sources[2];
  for (int k = 0; k < 2; ++k)
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
    for (int k = 0; k < 2; ++k)
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

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::Bind()
{
  for (int i = 0; i < NUMBER_OF_BUFFERS; ++i)
  {
    if (this->Handles[i])
    {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GetBindingPoint(i), this->Handles[i]);
    }
  }
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::Unbind()
{
  for (int i = 0; i < NUMBER_OF_BUFFERS; ++i)
  {
    if (this->Handles[i])
    {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GetBindingPoint(i), 0);
    }
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::SetBlockBindings(vtkShaderProgram* program)
{
  if (!program || program->GetHandle() == 0)
  {
    return;
  }
  const GLuint handle = static_cast<GLuint>(program->GetHandle());
  for (int i = 0; i < NUMBER_OF_BUFFERS; ++i)
  {
    const GLuint index =
      glGetProgramResourceIndex(handle, GL_SHADER_STORAGE_BLOCK, GetBlockName(i));
    if (index != GL_INVALID_INDEX)
    {
      glShaderStorageBlockBinding(handle, index, GetBindingPoint(i));
    }
  }
}

//------------------------------------------------------------------------------
size_t vtkOFBShaderStorage::GetMemorySize() const
{
  size_t total = 0;
  for (int i = 0; i < NUMBER_OF_BUFFERS; ++i)
  {
    total += this->Sizes[i];
  }
  return total;
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Window && (!window || window == static_cast<vtkWindow*>(this->Window)))
  {
    this->Window->MakeCurrent();
    this->FreeBuffers();
    this->Window = nullptr;
    this->CheckedWindow = nullptr;
    this->ForgetUploads();
  }
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::ForgetUploads()
{
  this->UploadedOFB = nullptr;
  this->UploadedLUT = nullptr;
  this->UploadedLUTTime = 0;
}

//------------------------------------------------------------------------------
void vtkOFBShaderStorage::FreeBuffers()
{
  for (int i = 0; i < NUMBER_OF_BUFFERS; ++i)
  {
    if (this->Handles[i] && this->Window)
    {
      glDeleteBuffers(1, &this->Handles[i]);
    }
    this->Handles[i] = 0;
    this->Sizes[i] = 0;
  }
  this->LevelCellBase.clear();
  this->LevelSampleBase.clear();
  this->LevelDims.clear();
  this->MaximumCellSamples = 0;
}
