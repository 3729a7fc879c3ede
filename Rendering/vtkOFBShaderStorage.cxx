#include "vtkOFBShaderStorage.h"

#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkOFB.h"
#include "vtkOFBPyramid.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <sstream>

namespace
{
// Binding points of the buffers: away from the low points that other code binds.
constexpr unsigned int BindingBase = 8;
}

//------------------------------------------------------------------------------
vtkOFBShaderStorage::vtkOFBShaderStorage()
  : Pyramid(vtkSmartPointer<vtkOFBPyramid>::New())
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
bool vtkOFBShaderStorage::SetPyramid(vtkOFBPyramid* pyramid)
{
  if (pyramid ? pyramid == this->Pyramid : this->OwnPyramid)
  {
    return false;
  }
  if (this->Pyramid->GetInputOFB())
  {
    this->Pyramid->SetInputOFB(nullptr);
    this->Pyramid->SetSurface(nullptr);
  }
  this->OwnPyramid = !pyramid;
  if (pyramid)
  {
    this->Pyramid = pyramid;
  }
  else
  {
    this->Pyramid = vtkSmartPointer<vtkOFBPyramid>::New();
  }
  // Another pyramid's levels: everything is uploaded again.
  this->UploadedOFB = nullptr;
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
      << selection.ScalarComponent << "|" << selection.IntensityName << "|" << selection.Normals
      << "|" << selection.FlowName;
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
  const int ids[4] = { BUFFER_SAMPLES, BUFFER_INTENSITY, BUFFER_NORMALS, BUFFER_FLOW };
  const bool wanted[4] = {
    true, !selection.IntensityName.empty(), selection.Normals, !selection.FlowName.empty()
  };
  unsigned int whole = 0;
  for (int k = 0; k < 4; ++k)
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
  this->UploadedArrays[BUFFER_FLOW] =
    selection.FlowName.empty() ? nullptr : GetArray(ofb, BUFFER_FLOW, selection);
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
  static const char* names[NUMBER_OF_BUFFERS] = { "ofbOffsetsBlock",
    "ofbSamplesBlock",
    "ofbIntensityBlock",
    "ofbNormalsBlock",
    "ofbFlowBlock",
    "ofbLUTBlock" };
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
    case BUFFER_FLOW:
      array = selection.FlowName.empty() ? nullptr : pd->GetArray(selection.FlowName.c_str());
      return (array && array->GetNumberOfComponents() == 3) ? array : nullptr;
    default:
      return nullptr;
  }
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
