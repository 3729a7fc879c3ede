#include "vtkOFBPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOFB.h"
#include "vtkOFBLookupFS.h"
#include "vtkOFBPyramid.h"
#include "vtkOFBShaderStorage.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkOFBPolyDataMapper);

namespace
{
// Above this many samples in a cell, the lookups binary-search a cell's depths before their
// linear scans (OFB_DEEP_CELLS); below, the scans alone read fewer words.
constexpr int DeepCellSamples = 8;
}

//------------------------------------------------------------------------------
vtkOFBPolyDataMapper::vtkOFBPolyDataMapper()
  : LookupMode(Nearest)
  , InterpolationRadius(std::sqrt(3.0))
  , MipmapBias(0.0)
  , MaximumNumberOfMipmapLevels(8)
  , MinimumMipmapResolution(8)
  , ColorSource(Paint)
  , ScalarArrayName(nullptr)
  , ScalarComponent(0)
  , IntensityArrayName(nullptr)
  , IntensityModulation(false)
  , IntensityWeight(1.0)
  , UsePaintedNormals(false)
  , LastUploadedSampleCount(0)
  , LastRenderUsedOFB(false)
  , OFBActive(false)
  , SourceScalars(false)
  , UseIntensity(false)
  , UseNormals(false)
  , DeepCells(false)
  , Storage(new vtkOFBShaderStorage)
  , Pyramid(vtkOFBPyramid::New())
  , Ranges(vtkIdTypeArray::New())
  , UploadedOFB(nullptr)
  , UploadedPyramidTime(0)
  , UploadedLUTTime(0)
  , CheckedWindow(nullptr)
  , CheckedWindowSupported(false)
  , WarnedOFB(nullptr)
  , WarnedMTime(0)
{
  this->UploadedLUTRange[0] = this->UploadedLUTRange[1] = 0.0;
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOFBPolyDataMapper::~vtkOFBPolyDataMapper()
{
  // Buffers still held here belong to a window that outlived this mapper: free them
  // in that window's context when it is still current, else leave them to it.
  if (this->Storage->GetWindow() && this->Storage->GetMemorySize() > 0)
  {
    vtkOpenGLRenderWindow* window = this->Storage->GetWindow();
    if (window->IsCurrent())
    {
      this->Storage->ReleaseGraphicsResources();
    }
  }
  delete this->Storage;
  this->Pyramid->Delete();
  this->Ranges->Delete();
  this->SetScalarArrayName(nullptr);
  this->SetIntensityArrayName(nullptr);
}

//------------------------------------------------------------------------------
int vtkOFBPolyDataMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOFB");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetOFB(vtkOFB* ofb)
{
  this->SetInputDataInternal(1, ofb);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetOFBConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBPolyDataMapper::GetOFB()
{
  if (this->GetNumberOfInputConnections(1) < 1)
  {
    return nullptr;
  }
  return vtkOFB::SafeDownCast(this->GetInputDataObject(1, 0));
}

//------------------------------------------------------------------------------
const char* vtkOFBPolyDataMapper::GetLookupModeAsString(int mode)
{
  switch (mode)
  {
    case Nearest:
      return "Nearest";
    case InverseDistance:
      return "InverseDistance";
    case Mipmapped:
      return "Mipmapped";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
const char* vtkOFBPolyDataMapper::GetColorSourceAsString(int source)
{
  switch (source)
  {
    case Paint:
      return "Paint";
    case Scalars:
      return "Scalars";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPolyDataMapper::GetGPUMemorySize()
{
  return static_cast<vtkIdType>(this->Storage->GetMemorySize());
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::WarnOnce(const std::string& message)
{
  if (this->Warnings.insert(message).second)
  {
    vtkWarningMacro(<< message);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Storage->GetWindow() &&
    (!window || window == static_cast<vtkWindow*>(this->Storage->GetWindow())))
  {
    this->Storage->GetWindow()->MakeCurrent();
    this->Storage->ReleaseGraphicsResources();
    this->Storage->SetWindow(nullptr);
    this->UploadedOFB = nullptr;
    this->UploadedLUTTime = 0;
    this->CheckedWindow = nullptr;
  }
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::PrepareOFB(vtkRenderer* ren, vtkActor* act)
{
  (void)act;
  this->LastUploadedSampleCount = 0;
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    vtkAlgorithm* producer = this->GetInputAlgorithm(1, 0);
    if (producer)
    {
      producer->Update();
    }
  }
  vtkOFB* ofb = this->GetOFB();
  if (ofb != this->WarnedOFB || this->GetMTime() > this->WarnedMTime)
  {
    this->Warnings.clear();
    this->WarnedOFB = ofb;
    this->WarnedMTime = this->GetMTime();
  }
  if (!ofb)
  {
    this->WarnOnce("No OFB (SetOFB or SetOFBConnection): rendering without OFB colours.");
    return false;
  }
  if (ofb->GetNumberOfSamples() == 0 || !(ofb->GetCellSize() > 0.0))
  {
    this->WarnOnce("The OFB is empty: rendering without OFB colours.");
    return false;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (window != this->CheckedWindow)
  {
    this->CheckedWindow = window;
    this->CheckedWindowSupported =
      vtkOFBShaderStorage::IsSupported(window, this->CheckedWindowReason);
  }
  if (!this->CheckedWindowSupported)
  {
    this->WarnOnce("Shader storage buffers are unavailable (" + this->CheckedWindowReason +
      "): rendering without OFB colours.");
    return false;
  }
  if (window != this->Storage->GetWindow())
  {
    if (this->Storage->GetWindow())
    {
      this->Storage->GetWindow()->MakeCurrent();
      this->Storage->ReleaseGraphicsResources();
      window->MakeCurrent();
    }
    this->Storage->SetWindow(window);
    this->UploadedOFB = nullptr;
    this->UploadedLUTTime = 0;
  }

  // What the shader reads.
  vtkOFBShaderStorage::Selection selection;
  this->SourceScalars = false;
  if (this->ColorSource == Scalars)
  {
    selection.ScalarName = this->ScalarArrayName ? this->ScalarArrayName : "";
    selection.ScalarComponent = this->ScalarComponent;
    if (vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::Scalars, selection))
    {
      this->SourceScalars = true;
      selection.Colors = false;
    }
    else
    {
      selection.ScalarName.clear();
      this->WarnOnce(std::string("Scalar array \"") +
        (this->ScalarArrayName ? this->ScalarArrayName : "") +
        "\" (or its component) is not in the OFB sample data: colouring with the paint.");
    }
  }
  if (!this->SourceScalars &&
    !vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::Colors, selection))
  {
    this->WarnOnce("The OFB has no RGB(A) unsigned char \"Colors\" sample array: rendering "
                   "without OFB colours.");
    return false;
  }
  this->UseIntensity = false;
  if (this->IntensityModulation)
  {
    selection.IntensityName = this->IntensityArrayName ? this->IntensityArrayName : "";
    this->UseIntensity =
      vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::Intensity, selection) != nullptr;
    if (!this->UseIntensity)
    {
      selection.IntensityName.clear();
      this->WarnOnce(std::string("Intensity array \"") +
        (this->IntensityArrayName ? this->IntensityArrayName : "") +
        "\" is not in the OFB sample data: no intensity modulation.");
    }
  }
  selection.Normals = this->UsePaintedNormals &&
    vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::Normals, selection) != nullptr;
  if (this->UsePaintedNormals && !selection.Normals)
  {
    this->WarnOnce("The OFB has no 3-component \"Normals\" sample array: shading with the "
                   "surface normals.");
  }
  this->UseNormals = selection.Normals;

  // The surface should lie in the OFB's frame; parts outside keep the property colour.
  vtkPolyData* input = this->GetInput();
  if (input && input->GetNumberOfPoints() > 0)
  {
    double sb[6];
    double fb[6];
    input->GetBounds(sb);
    ofb->GetBounds(fb);
    const double tol = ofb->GetCellSize();
    for (int i = 0; i < 3; ++i)
    {
      if (sb[2 * i] < fb[2 * i] - tol || sb[2 * i + 1] > fb[2 * i + 1] + tol)
      {
        this->WarnOnce("The surface extends beyond the OFB's frame (was the OFB built from "
                       "another surface?): parts outside keep the property colour.");
        break;
      }
    }
  }

  // Levels: the OFB, then the mipmap pyramid.
  std::vector<vtkOFB*> levels(1, ofb);
  if (this->LookupMode == Mipmapped)
  {
    this->Pyramid->SetInputOFB(ofb);
    this->Pyramid->SetSurface(input);
    this->Pyramid->SetMaximumNumberOfLevels(
      std::min(this->MaximumNumberOfMipmapLevels, vtkOFBShaderStorage::MaximumNumberOfLevels));
    this->Pyramid->SetMinimumResolution(this->MinimumMipmapResolution);
    if (this->Pyramid->UpdateLevels())
    {
      for (int k = 1; k < this->Pyramid->GetNumberOfLevels(); ++k)
      {
        levels.push_back(this->Pyramid->GetLevel(k));
      }
    }
    else
    {
      this->WarnOnce("The mipmap pyramid could not be built: using level 0 only.");
    }
  }
  else if (this->Pyramid->GetInputOFB())
  {
    this->Pyramid->SetInputOFB(nullptr);
    this->Pyramid->SetSurface(nullptr);
  }

  // Upload: everything on a structure or selection change, else the modified ranges.
  std::ostringstream key;
  key << levels.size() << "|" << selection.Colors << "|" << selection.ScalarName << "|"
      << selection.ScalarComponent << "|" << selection.IntensityName << "|" << selection.Normals;
  const bool mipmapped = levels.size() > 1;
  const bool full = ofb != this->UploadedOFB || key.str() != this->UploadKey ||
    ofb->GetStructureMTime() > this->UploadTime.GetMTime() ||
    (mipmapped && this->Pyramid->GetStructureTime() > this->UploadedPyramidTime) ||
    this->Storage->GetMemorySize() == 0;
  window->MakeCurrent();
  if (full)
  {
    std::string error;
    const vtkIdType n = this->Storage->UploadAll(levels, selection, error);
    if (n < 0)
    {
      this->UploadedOFB = nullptr;
      this->WarnOnce("Could not upload the OFB (" + error + "): rendering without OFB colours.");
      return false;
    }
    this->LastUploadedSampleCount = n;
    this->UploadedOFB = ofb;
    this->UploadKey = key.str();
  }
  else
  {
    ofb->GetSampleRangesModifiedSince(this->UploadTime.GetMTime(), this->Ranges);
    this->LastUploadedSampleCount =
      this->Storage->UploadRanges(levels, 0, selection, this->Ranges);
    if (mipmapped)
    {
      if (this->Ranges->GetNumberOfTuples() > 0 &&
        this->Pyramid->GetArraysTime() <= this->UploadTime.GetMTime())
      {
        this->Pyramid->UpdateArrays();
      }
      if (this->Pyramid->GetArraysTime() > this->UploadTime.GetMTime())
      {
        for (size_t k = 1; k < levels.size(); ++k)
        {
          this->Ranges->Initialize();
          this->Ranges->SetNumberOfComponents(2);
          const vtkIdType all[2] = { 0, levels[k]->GetNumberOfSamples() };
          this->Ranges->InsertNextTypedTuple(all);
          this->LastUploadedSampleCount +=
            this->Storage->UploadRanges(levels, static_cast<int>(k), selection, this->Ranges);
        }
      }
    }
  }
  this->UploadedPyramidTime = this->Pyramid->GetStructureTime();
  this->UploadTime.Modified();

  // The lookup table, sampled over the scalar range.
  if (this->SourceScalars)
  {
    vtkScalarsToColors* lut = this->GetLookupTable();
    double range[2] = { this->ScalarRange[0], this->ScalarRange[1] };
    if (this->UseLookupTableScalarRange)
    {
      const double* lutRange = lut->GetRange();
      range[0] = lutRange[0];
      range[1] = lutRange[1];
    }
    else
    {
      lut->SetRange(range);
    }
    if (lut->GetMTime() > this->UploadedLUTTime || range[0] != this->UploadedLUTRange[0] ||
      range[1] != this->UploadedLUTRange[1])
    {
      this->Storage->UploadLookupTable(lut, range);
      this->UploadedLUTTime = lut->GetMTime();
      this->UploadedLUTRange[0] = range[0];
      this->UploadedLUTRange[1] = range[1];
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  this->OFBActive = this->PrepareOFB(ren, act);
  this->LastRenderUsedOFB = this->OFBActive;
  std::ostringstream key;
  if (this->OFBActive)
  {
    this->DeepCells = this->Storage->GetMaximumCellSamples() > DeepCellSamples;
    key << this->LookupMode << "|" << this->SourceScalars << "|" << this->UseIntensity << "|"
        << this->UseNormals << "|" << this->DeepCells;
  }
  if (key.str() != this->ShaderKey)
  {
    this->ShaderKey = key.str();
    this->ShaderKeyTime.Modified();
  }
  if (this->OFBActive)
  {
    this->Storage->Bind();
  }
  this->Superclass::RenderPiece(ren, act);
  if (this->OFBActive)
  {
    this->Storage->Unbind();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  return rebuild || cellBO.ShaderSourceTime < this->ShaderKeyTime;
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->OFBActive)
  {
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    std::string gs = shaders[vtkShader::Geometry]->GetSource();
    std::string fs = shaders[vtkShader::Fragment]->GetSource();

    // Vertex shader: the position in level-0 OFB cells.
    vtkShaderProgram::Substitute(vs, "//VTK::PositionVC::Dec",
      "//VTK::PositionVC::Dec\n"
      "uniform vec3 ofbPositionScale;\n"
      "uniform vec3 ofbPositionShift;\n"
      "out vec3 ofbGridVSOutput;\n");
    vtkShaderProgram::Substitute(vs, "//VTK::PositionVC::Impl",
      "//VTK::PositionVC::Impl\n"
      "  ofbGridVSOutput = vertexMC.xyz * ofbPositionScale + ofbPositionShift;\n");

    // Geometry shader (wide lines, edges): pass it through.
    if (!gs.empty())
    {
      vtkShaderProgram::Substitute(gs, "//VTK::Clip::Dec",
        "//VTK::Clip::Dec\n"
        "in vec3 ofbGridVSOutput[];\n"
        "out vec3 ofbGridGSOutput;\n");
      vtkShaderProgram::Substitute(gs, "//VTK::Clip::Impl",
        "//VTK::Clip::Impl\n"
        "    ofbGridGSOutput = ofbGridVSOutput[i];\n");
      shaders[vtkShader::Geometry]->SetSource(gs);
    }

    // Fragment shader: storage blocks, the lookup, and the colour it gives. Bit casts read
    // the depths packed with the colours (ARB_shader_bit_encoding, checked by
    // vtkOFBShaderStorage::IsSupported); gl_HelperInvocation (ARB_ES3_1_compatibility, used
    // where the context offers it) keeps helper lanes out of the lookup fallbacks.
    vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
      "//VTK::System::Dec\n"
      "#extension GL_ARB_shader_storage_buffer_object : require\n"
      "#extension GL_ARB_shader_bit_encoding : enable\n"
      "#extension GL_ARB_ES3_1_compatibility : enable\n");
    std::ostringstream defines;
    defines << "//VTK::Color::Dec\n"
            << "#define OFB_MODE " << this->LookupMode << "\n"
            << "#define OFB_MAX_LEVELS " << vtkOFBShaderStorage::MaximumNumberOfLevels << "\n";
    if (this->SourceScalars)
    {
      defines << "#define OFB_SOURCE_SCALARS 1\n";
    }
    if (this->UseIntensity)
    {
      defines << "#define OFB_USE_INTENSITY 1\n";
    }
    if (this->UseNormals)
    {
      defines << "#define OFB_USE_NORMALS 1\n";
    }
    if (this->DeepCells)
    {
      defines << "#define OFB_DEEP_CELLS 1\n";
    }
    vtkShaderProgram::Substitute(fs, "//VTK::Color::Dec", defines.str() + vtkOFBLookupFS);
    vtkShaderProgram::Substitute(fs, "//VTK::UniformFlow::Impl",
      "//VTK::UniformFlow::Impl\n"
      "  vec3 ofbDx = dFdx(ofbGridVSOutput);\n"
      "  vec3 ofbDy = dFdy(ofbGridVSOutput);\n"
      "  vec3 ofbFaceNormal = cross(ofbDx, ofbDy);\n"
      "  float ofbLod = log2(max(max(length(ofbDx), length(ofbDy)), 1.0e-6));\n");
    vtkShaderProgram::Substitute(fs, "//VTK::Color::Impl",
      "//VTK::Color::Impl\n"
      "  ofbAccum ofbAcc = ofbLookup(ofbGridVSOutput, ofbFaceNormal, ofbLod);\n"
      "  if (ofbAcc.weight > 0.0)\n"
      "  {\n"
      "    vec4 ofbColor = ofbResolve(ofbAcc);\n"
      "    ambientColor = ambientIntensity * ofbColor.rgb;\n"
      "    diffuseColor = diffuseIntensity * ofbColor.rgb;\n"
      "    opacity = opacity * ofbColor.a;\n"
      "  }\n");
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->OFBActive && this->UseNormals)
  {
    // After the superclass's normal code: replace the normal by the painted one, on the
    // side of the interpolated (already front-facing) normal.
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    if (fs.find("normalVCVSOutput") != std::string::npos)
    {
      vtkShaderProgram::Substitute(fs, "//VTK::Light::Impl",
        "#ifdef OFB_USE_NORMALS\n"
        "  if (ofbAcc.weight > 0.0 && dot(ofbAcc.normal, ofbAcc.normal) > 0.0)\n"
        "  {\n"
        "    vec3 ofbN = normalize(ofbNormalMatrix * ofbAcc.normal);\n"
        "    normalVCVSOutput = dot(ofbN, normalVCVSOutput) < 0.0 ? -ofbN : ofbN;\n"
        "  }\n"
        "#endif\n"
        "//VTK::Light::Impl\n");
      shaders[vtkShader::Fragment]->SetSource(fs);
    }
  }
  this->Superclass::ReplaceShaderLight(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  vtkOFB* ofb = this->OFBActive ? this->UploadedOFB : nullptr;
  if (!program || !ofb || !program->IsUniformUsed("ofbPositionScale"))
  {
    return;
  }
  this->Storage->SetBlockBindings(program);

  // vertexMC is (x - shift) * scale when the VBO shifts and scales coordinates.
  double shift[3] = { 0.0, 0.0, 0.0 };
  double scale[3] = { 1.0, 1.0, 1.0 };
  vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO("vertexMC");
  if (vbo && vbo->GetCoordShiftAndScaleEnabled())
  {
    const std::vector<double>& sh = vbo->GetShift();
    const std::vector<double>& sc = vbo->GetScale();
    for (int i = 0; i < 3 && i < static_cast<int>(sh.size()) && i < static_cast<int>(sc.size());
         ++i)
    {
      shift[i] = sh[i];
      scale[i] = sc[i];
    }
  }
  const double* origin = ofb->GetOrigin();
  const double s = ofb->GetCellSize();
  float posScale[3];
  float posShift[3];
  for (int i = 0; i < 3; ++i)
  {
    posScale[i] = static_cast<float>(1.0 / (scale[i] * s));
    posShift[i] = static_cast<float>((shift[i] - origin[i]) / s);
  }
  program->SetUniform3f("ofbPositionScale", posScale);
  program->SetUniform3f("ofbPositionShift", posShift);

  // Levels.
  const int nl = this->Storage->GetNumberOfLevels();
  float transforms[4 * vtkOFBShaderStorage::MaximumNumberOfLevels] = { 0.0f };
  const vtkOFB* levels[vtkOFBShaderStorage::MaximumNumberOfLevels] = { nullptr };
  levels[0] = ofb;
  for (int l = 1; l < nl; ++l)
  {
    levels[l] = this->Pyramid->GetLevel(l);
  }
  for (int l = 0; l < nl && levels[l]; ++l)
  {
    vtkOFB* level = const_cast<vtkOFB*>(levels[l]);
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
  program->SetUniform1iv("ofbLevelDims", 3 * nl, this->Storage->GetLevelDims().data());
  program->SetUniform1iv("ofbLevelCellBase", 3 * nl, this->Storage->GetLevelCellBase().data());
  program->SetUniform1iv("ofbLevelSampleBase", nl, this->Storage->GetLevelSampleBase().data());
  program->SetUniformf("ofbMipmapBias", static_cast<float>(this->MipmapBias));
  program->SetUniformf("ofbRadius", static_cast<float>(this->InterpolationRadius));
  program->SetUniformi("ofbNearestVisits", 15); // 3 grids + 2x2 cells in each of the 3

  if (this->SourceScalars)
  {
    const double span = this->UploadedLUTRange[1] - this->UploadedLUTRange[0];
    const float range[2] = { static_cast<float>(this->UploadedLUTRange[0]),
      static_cast<float>(span != 0.0 ? 1.0 / span : 0.0) };
    program->SetUniform2f("ofbScalarRange", range);
    program->SetUniformi("ofbLUTSize", vtkOFBShaderStorage::LUTSize);
  }
  if (this->UseIntensity)
  {
    program->SetUniformf("ofbIntensityWeight", static_cast<float>(this->IntensityWeight));
  }
  if (this->UseNormals && program->IsUniformUsed("ofbNormalMatrix"))
  {
    // Model to view normals, as vtkOpenGLPolyDataMapper computes "normalMatrix".
    vtkOpenGLCamera* cam = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
    vtkMatrix4x4* wcdc;
    vtkMatrix4x4* wcvc;
    vtkMatrix3x3* norms;
    vtkMatrix4x4* vcdc;
    cam->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
    vtkNew<vtkMatrix3x3> normalMatrix;
    normalMatrix->DeepCopy(norms);
    vtkOpenGLActor* glActor = vtkOpenGLActor::SafeDownCast(act);
    if (glActor && !act->GetIsIdentity())
    {
      vtkMatrix4x4* mcwc;
      vtkMatrix3x3* anorms;
      glActor->GetKeyMatrices(mcwc, anorms);
      vtkMatrix3x3::Multiply3x3(anorms, norms, normalMatrix);
    }
    program->SetUniformMatrix("ofbNormalMatrix", normalMatrix);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OFB: " << this->GetOFB() << "\n";
  os << indent << "LookupMode: " << GetLookupModeAsString(this->LookupMode) << "\n";
  os << indent << "InterpolationRadius: " << this->InterpolationRadius << " cells\n";
  os << indent << "MipmapBias: " << this->MipmapBias << "\n";
  os << indent << "MaximumNumberOfMipmapLevels: " << this->MaximumNumberOfMipmapLevels << "\n";
  os << indent << "MinimumMipmapResolution: " << this->MinimumMipmapResolution << "\n";
  os << indent << "ColorSource: " << GetColorSourceAsString(this->ColorSource) << "\n";
  os << indent << "ScalarArrayName: " << (this->ScalarArrayName ? this->ScalarArrayName : "(none)")
     << "\n";
  os << indent << "ScalarComponent: " << this->ScalarComponent << "\n";
  os << indent
     << "IntensityArrayName: " << (this->IntensityArrayName ? this->IntensityArrayName : "(none)")
     << "\n";
  os << indent << "IntensityModulation: " << (this->IntensityModulation ? "On" : "Off") << "\n";
  os << indent << "IntensityWeight: " << this->IntensityWeight << "\n";
  os << indent << "UsePaintedNormals: " << (this->UsePaintedNormals ? "On" : "Off") << "\n";
  os << indent << "LastUploadedSampleCount: " << this->LastUploadedSampleCount << "\n";
  os << indent << "LastRenderUsedOFB: " << (this->LastRenderUsedOFB ? "true" : "false") << "\n";
  os << indent << "GPUMemorySize: " << this->Storage->GetMemorySize() << " bytes\n";
}
