#include "vtkOFBPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOFB.h"
#include "vtkOFBColoring.h"
#include "vtkOFBLIC.h"
#include "vtkOFBLICPyramid.h"
#include "vtkOFBLookupFS.h"
#include "vtkOFBLookupModes.h"
#include "vtkOFBMapToColors.h"
#include "vtkOFBPolyDataMapperInternals.h"
#include "vtkOFBPyramid.h"
#include "vtkOFBShaderStorage.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkOFBPolyDataMapper);

namespace
{
// Above this many samples in a cell, the lookups binary-search a cell's depths before their
// linear scans (OFB_DEEP_CELLS); below, the scans alone read fewer words.
constexpr int DeepCellSamples = 8;
}

//------------------------------------------------------------------------------
vtkOFBPolyDataMapper::vtkOFBPolyDataMapper()
  : LookupMode(LOOKUP_AUTOMATIC)
  , ResolvedLookupMode(LOOKUP_NEAREST)
  , AutomaticLevelLIC(true)
  , UserPyramid(false)
  , InterpolationRadius(std::sqrt(3.0))
  , MipmapBias(0.0)
  , MaximumNumberOfMipmapLevels(8)
  , MinimumMipmapResolution(8)
  , Coloring(vtkOFBColoring::New())
  , LightnessRange{ 0.0, 0.0 }
  , UsePaintedNormals(false)
  , FlowAlignedFiltering(true)
  , MaximumFlowFilterOffset(2.0)
  , LastUploadedSampleCount(0)
  , LastRenderUsedOFB(false)
  , OFBActive(false)
  , SourceScalars(false)
  , UseIntensity(false)
  , UseNormals(false)
  , DeepCells(false)
  , LevelIntensity(false)
  , UseFlow(false)
  , FlowInView(false)
  , IntensityMean(0.5)
  , MeanTime(0)
  , Storage(new vtkStorage)
  , AlphaTranslucent(false)
  , AlphaHint(0)
  , WarnedMTime(0)
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOFBPolyDataMapper::~vtkOFBPolyDataMapper()
{
  this->Coloring->Delete();
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetColoring(vtkOFBColoring* coloring)
{
  if (!coloring)
  {
    vtkErrorMacro("SetColoring(nullptr) is refused: the mapper keeps its colouring.");
    return;
  }
  if (coloring == this->Coloring)
  {
    return;
  }
  coloring->Register(this);
  this->Coloring->UnRegister(this);
  this->Coloring = coloring;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOFBPolyDataMapper::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Coloring->GetMTime());
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
  this->Superclass::FillInputPortInformation(port, info);
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
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
  const vtkOFBLookupModeInfo* info = vtkOFBFindLookupMode(mode);
  return info ? info->Name : "Unknown";
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetLookupMode(int mode)
{
  if (!vtkOFBFindLookupMode(mode))
  {
    vtkErrorMacro("SetLookupMode: " << mode << " is not a LookupModes value; the lookup mode stays "
                                    << GetLookupModeAsString(this->LookupMode) << ".");
    return;
  }
  if (this->LookupMode != mode)
  {
    this->LookupMode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetPyramid(vtkOFBPyramid* pyramid)
{
  this->UserPyramid = pyramid != nullptr;
  if (this->Storage->SetPyramid(pyramid))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFBPyramid* vtkOFBPolyDataMapper::GetPyramid()
{
  return this->Storage->GetPyramid();
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPolyDataMapper::GetGPUMemorySize()
{
  return static_cast<vtkIdType>(this->Storage->GetMemorySize());
}

//------------------------------------------------------------------------------
vtkIdType vtkOFBPolyDataMapper::GetUploadedBytes()
{
  return static_cast<vtkIdType>(this->Storage->GetUploadedBytes());
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
  this->Storage->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  this->OFBActive = this->PrepareOFB(ren);
  this->LastRenderUsedOFB = this->OFBActive;
  this->FlowInView = this->OFBActive && this->UseFlow && this->FlowFilterInView(ren, act);
  this->UpdateShaderKey();
  if (this->OFBActive)
  {
    this->Storage->Bind();
  }
  this->RenderSurface(ren, act);
  if (this->OFBActive)
  {
    this->Storage->Unbind();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::PrepareOFB(vtkRenderer* ren)
{
  this->LastUploadedSampleCount = 0;
  vtkOFB* ofb = this->UpdateOFBInput();
  vtkSelection selection;
  if (!this->CheckOFB(ofb) || !this->PrepareContext(ren) || !this->SelectArrays(ofb, selection))
  {
    return false;
  }
  this->ResolveLookupMode();
  this->UpdateAutomaticPyramid();
  this->SelectFlow(ofb, selection);
  this->CheckSurfaceInFrame(ofb);
  if (!this->UploadOFB(ofb, selection))
  {
    return false;
  }
  this->UpdateLevelIntensity(ofb);
  if (this->SourceScalars)
  {
    this->UploadLookupTable();
  }
  if (this->Coloring->GetEnhanceColorContrast())
  {
    this->UpdateLightnessRange(ofb);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ResolveLookupMode()
{
  this->ResolvedLookupMode = this->LookupMode;
  if (this->LookupMode == LOOKUP_AUTOMATIC)
  {
    this->ResolvedLookupMode = this->UseIntensity ? LOOKUP_SMOOTH : LOOKUP_NEAREST;
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::UpdateLightnessRange(vtkOFB* ofb)
{
  // The colours change with the OFB (painting, a new LIC), the mapper's settings and the
  // colouring with its lookup table (in the mapper's MTime).
  if (this->LightnessTime.GetMTime() > std::max(ofb->GetMTime(), this->GetMTime()))
  {
    return;
  }
  vtkNew<vtkOFBMapToColors> colors;
  colors->SetColoring(this->Coloring);
  colors->ComputeLightnessRange(ofb, this->LightnessRange);
  this->LightnessTime.Modified();
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::UpdateOFBProducer()
{
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    vtkAlgorithm* producer = this->GetInputAlgorithm(1, 0);
    if (producer)
    {
      producer->Update();
    }
  }
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBPolyDataMapper::UpdateOFBInput()
{
  this->UpdateOFBProducer();
  vtkOFB* ofb = this->GetOFB();
  if (ofb != this->WarnedOFB || this->GetMTime() > this->WarnedMTime)
  {
    this->Warnings.clear();
    this->WarnedOFB = ofb;
    this->WarnedMTime = this->GetMTime();
  }
  return ofb;
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::CheckOFB(vtkOFB* ofb)
{
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
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::PrepareContext(vtkRenderer* ren)
{
  std::string why;
  if (!this->Storage->SetContext(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()), why))
  {
    this->WarnOnce(
      "Shader storage buffers are unavailable (" + why + "): rendering without OFB colours.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::SelectArrays(vtkOFB* ofb, vtkSelection& selection)
{
  vtkOFBColoring* coloring = this->Coloring;
  this->SourceScalars = false;
  if (coloring->GetColorSource() == vtkOFBColoring::COLOR_SOURCE_SCALARS)
  {
    selection.ScalarName = coloring->GetScalarArrayName();
    selection.ScalarComponent = coloring->GetScalarComponent();
    if (vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::ATTRIBUTE_SCALARS, selection))
    {
      this->SourceScalars = true;
      selection.Colors = false;
    }
    else
    {
      selection.ScalarName.clear();
      this->WarnOnce(std::string("Scalar array \"") + coloring->GetScalarArrayName() +
        "\" (or its component) is not in the OFB sample data, or is shorter than the "
        "samples: colouring with the paint.");
    }
  }
  if (!this->SourceScalars &&
    !vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::ATTRIBUTE_COLORS, selection))
  {
    this->WarnOnce("The OFB has no RGB(A) unsigned char \"Colors\" sample array of one tuple a "
                   "sample: rendering without OFB colours.");
    return false;
  }
  this->UseIntensity = false;
  if (coloring->GetIntensityModulation())
  {
    selection.IntensityName = coloring->GetIntensityArrayName();
    this->UseIntensity = vtkOFBShaderStorage::GetArray(
                           ofb, vtkOFBShaderStorage::BUFFER_INTENSITY, selection) != nullptr;
    if (!this->UseIntensity)
    {
      selection.IntensityName.clear();
      this->WarnOnce(std::string("Intensity array \"") + coloring->GetIntensityArrayName() +
        "\" is not in the OFB sample data, or is shorter than the samples: no intensity "
        "modulation.");
    }
  }
  selection.Normals = this->UsePaintedNormals &&
    vtkOFBShaderStorage::GetArray(ofb, vtkOFBShaderStorage::BUFFER_NORMALS, selection) != nullptr;
  if (this->UsePaintedNormals && !selection.Normals)
  {
    this->WarnOnce("The OFB has no 3-component \"Normals\" sample array of one tuple a sample: "
                   "shading with the surface normals.");
  }
  this->UseNormals = selection.Normals;
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::CheckSurfaceInFrame(vtkOFB* ofb)
{
  // The surface should lie in the OFB's frame; parts outside keep the property colour.
  vtkPolyData* input = this->GetRenderedSurface();
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return;
  }
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
      return;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::UploadOFB(vtkOFB* ofb, const vtkSelection& selection)
{
  if (!this->Storage->UpdateLevels(ofb,
        this->GetRenderedSurface(),
        vtkOFBFindLookupMode(this->ResolvedLookupMode)->Pyramid,
        this->MaximumNumberOfMipmapLevels,
        this->MinimumMipmapResolution))
  {
    this->WarnOnce("The mipmap pyramid could not be built: using level 0 only.");
  }
  std::string error;
  const vtkIdType count = this->Storage->UploadChanges(selection, error);
  if (count < 0)
  {
    this->WarnOnce("Could not upload the OFB (" + error + "): rendering without OFB colours.");
    return false;
  }
  this->LastUploadedSampleCount = count;
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::UploadLookupTable()
{
  // The colouring's lookup table, sampled over the scalar range.
  double range[2];
  vtkScalarsToColors* lut = this->Coloring->PrepareLookupTable(range);
  this->Storage->UpdateLookupTable(lut, range);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::UpdateShaderKey()
{
  std::ostringstream key;
  if (this->OFBActive)
  {
    this->DeepCells = this->Storage->GetMaximumCellSamples() > DeepCellSamples;
    key << this->ResolvedLookupMode << "|" << this->SourceScalars << "|" << this->UseIntensity
        << "|" << this->UseNormals << "|" << this->DeepCells << "|"
        << this->Coloring->GetLICColorMode() << "|" << this->Coloring->GetEnhanceColorContrast()
        << "|" << this->LevelIntensity << "|" << this->FlowInView;
  }
  if (key.str() != this->ShaderKey)
  {
    this->ShaderKey = key.str();
    this->ShaderKeyTime.Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkOFBPolyDataMapper::GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO,
  vtkRenderer* ren,
  vtkActor* act)
{
  const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  return rebuild || cellBO.ShaderSourceTime < this->ShaderKeyTime;
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReplaceShaderPositionVC(std::map<vtkShader::Type, vtkShader*> shaders,
  vtkRenderer* ren,
  vtkActor* act)
{
  if (this->OFBActive)
  {
    // Vertex shader: the position in level-0 OFB cells, for the fragment shader's lookup.
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    vtkShaderProgram::Substitute(vs,
      "//VTK::PositionVC::Dec",
      "//VTK::PositionVC::Dec\n"
      "uniform vec3 ofbPositionScale;\n"
      "uniform vec3 ofbPositionShift;\n"
      "out vec3 ofbGridVSOutput;\n");
    vtkShaderProgram::Substitute(vs,
      "//VTK::PositionVC::Impl",
      "//VTK::PositionVC::Impl\n"
      "  ofbGridVSOutput = vertexMC.xyz * ofbPositionScale + ofbPositionShift;\n");
    shaders[vtkShader::Vertex]->SetSource(vs);

    // Geometry shader (wide lines, edges): pass it through.
    std::string gs = shaders[vtkShader::Geometry]->GetSource();
    if (!gs.empty())
    {
      vtkShaderProgram::Substitute(gs,
        "//VTK::PositionVC::Dec",
        "//VTK::PositionVC::Dec\n"
        "in vec3 ofbGridVSOutput[];\n"
        "out vec3 ofbGridGSOutput;\n");
      vtkShaderProgram::Substitute(gs,
        "//VTK::PositionVC::Impl",
        "//VTK::PositionVC::Impl\n"
        "    ofbGridGSOutput = ofbGridVSOutput[i];\n");
      shaders[vtkShader::Geometry]->SetSource(gs);
    }
  }
  this->Superclass::ReplaceShaderPositionVC(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReplaceShaderColor(std::map<vtkShader::Type, vtkShader*> shaders,
  vtkRenderer* ren,
  vtkActor* act)
{
  if (this->OFBActive)
  {
    // Fragment shader: storage blocks, the lookup, and the colour it gives, after the
    // superclass's colour code. Bit casts read the depths packed with the colours
    // (ARB_shader_bit_encoding, checked by vtkOFBShaderStorage::IsSupported);
    // gl_HelperInvocation (ARB_ES3_1_compatibility, used where the context offers it) keeps
    // helper lanes out of the lookup fallbacks.
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fs,
      "//VTK::System::Dec",
      "//VTK::System::Dec\n"
      "#extension GL_ARB_shader_storage_buffer_object : require\n"
      "#extension GL_ARB_shader_bit_encoding : enable\n"
      "#extension GL_ARB_ES3_1_compatibility : enable\n");
    std::ostringstream defines;
    defines << "//VTK::Color::Dec\n";
    for (const vtkOFBLookupModeInfo& info : vtkOFBLookupModeInfos)
    {
      defines << "#define " << info.Define << " " << info.Mode << "\n";
    }
    defines << "#define OFB_LOOKUP_MODE " << vtkOFBFindLookupMode(this->ResolvedLookupMode)->Define
            << "\n"
            << "#define OFB_MAX_LEVELS " << vtkOFBShaderStorage::MaximumNumberOfLevels << "\n"
            << "#define OFB_LIC_MODE " << this->Coloring->GetLICColorMode() << "\n";
    const std::pair<bool, const char*> flags[] = { { this->SourceScalars, "OFB_SOURCE_SCALARS" },
      { this->UseIntensity, "OFB_USE_INTENSITY" },
      { this->UseNormals, "OFB_USE_NORMALS" },
      { this->DeepCells, "OFB_DEEP_CELLS" },
      { this->LevelIntensity, "OFB_LEVEL_INTENSITY" },
      { this->FlowInView, "OFB_FLOW_FILTER" },
      { this->Coloring->GetEnhanceColorContrast(), "OFB_ENHANCE_COLOR" } };
    for (const auto& flag : flags)
    {
      if (flag.first)
      {
        defines << "#define " << flag.second << " 1\n";
      }
    }
    vtkShaderProgram::Substitute(fs, "//VTK::Color::Dec", defines.str() + vtkOFBLookupFS);
    vtkShaderProgram::Substitute(fs,
      "//VTK::UniformFlow::Impl",
      "//VTK::UniformFlow::Impl\n"
      "  vec3 ofbDx = dFdx(ofbGridVSOutput);\n"
      "  vec3 ofbDy = dFdy(ofbGridVSOutput);\n"
      "  vec3 ofbFaceNormal = cross(ofbDx, ofbDy);\n"
      "  float ofbLod = log2(max(max(length(ofbDx), length(ofbDy)), 1.0e-6));\n");
    vtkShaderProgram::Substitute(fs,
      "//VTK::Color::Impl",
      "//VTK::Color::Impl\n"
      "  ofbAccum ofbAcc = ofbLookup(ofbGridVSOutput, ofbFaceNormal, ofbLod);\n"
      "  if (ofbAcc.weight > 0.0)\n"
      "  {\n"
      "    vec4 ofbColor = ofbResolve(ofbAcc);\n"
      "    ambientColor = ambientIntensity * ofbColor.rgb;\n"
      "    diffuseColor = diffuseIntensity * ofbColor.rgb;\n"
      "    opacity = opacity * ofbColor.a;\n"
      "  }\n");
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
  this->Superclass::ReplaceShaderColor(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReplaceShaderNormal(std::map<vtkShader::Type, vtkShader*> shaders,
  vtkRenderer* ren,
  vtkActor* act)
{
  this->Superclass::ReplaceShaderNormal(shaders, ren, act);
  if (!this->OFBActive || !this->UseNormals)
  {
    return;
  }
  // After the superclass's normal code, before the lighting: replace the normal by the
  // painted one, on the side of the interpolated (already front-facing) normal.
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  if (fs.find("normalVCVSOutput") != std::string::npos)
  {
    vtkShaderProgram::Substitute(fs,
      "//VTK::Light::Impl",
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

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::ReplaceShaderLight(std::map<vtkShader::Type, vtkShader*> shaders,
  vtkRenderer* ren,
  vtkActor* act)
{
  this->Superclass::ReplaceShaderLight(shaders, ren, act);
  // After the lighting: the LIC of blend mode mixed in unlit (ofbBlendLIC).
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  if (this->OFBActive && fs.find("ofbBlendLIC") != std::string::npos)
  {
    vtkShaderProgram::Substitute(fs,
      "//VTK::Light::Impl",
      "  gl_FragData[0].rgb = ofbBlendLIC(gl_FragData[0].rgb, ofbAcc);\n"
      "//VTK::Light::Impl\n");
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO,
  vtkRenderer* ren,
  vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  vtkOFB* ofb = this->OFBActive ? this->Storage->GetUploadedOFB() : nullptr;
  if (!program || !ofb || !program->IsUniformUsed("ofbPositionScale"))
  {
    return;
  }
  this->Storage->SetUniforms(program, this->SourceScalars);

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
  program->SetUniformf("ofbMipmapBias", static_cast<float>(this->MipmapBias));
  program->SetUniformf("ofbRadius", static_cast<float>(this->InterpolationRadius));
  program->SetUniformi("ofbNearestVisits", 15); // 3 grids + 2x2 cells in each of the 3

  vtkOFBColoring* coloring = this->Coloring;
  if (this->UseIntensity)
  {
    program->SetUniformf("ofbIntensityWeight", static_cast<float>(coloring->GetIntensityWeight()));
    program->SetUniformf("ofbLICIntensity", static_cast<float>(coloring->GetLICIntensity()));
    program->SetUniformf("ofbMapModeBias", static_cast<float>(coloring->GetMapModeBias()));
    if (this->LevelIntensity)
    {
      program->SetUniformf("ofbIntensityMean", static_cast<float>(this->IntensityMean));
    }
    if (this->FlowInView)
    {
      program->SetUniformf("ofbFlowOffsetMax", static_cast<float>(this->MaximumFlowFilterOffset));
    }
  }
  if (coloring->GetEnhanceColorContrast())
  {
    // Lightness stretch: x the low end m, y 1 / (M - m) (0 where M <= m: no stretch).
    const double span = this->LightnessRange[1] - this->LightnessRange[0];
    const double m =
      this->LightnessRange[0] + coloring->GetLowColorContrastEnhancementFactor() * span;
    const double M =
      this->LightnessRange[1] - coloring->GetHighColorContrastEnhancementFactor() * span;
    const float stretch[2] = { static_cast<float>(m),
      static_cast<float>(M > m ? 1.0 / (M - m) : 0.0) };
    program->SetUniform2f("ofbLightnessStretch", stretch);
  }
  if (this->UseNormals && program->IsUniformUsed("ofbNormalMatrix"))
  {
    this->SetNormalMatrix(program, ren, act);
  }
}

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::SetNormalMatrix(vtkShaderProgram* program,
  vtkRenderer* ren,
  vtkActor* act)
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

//------------------------------------------------------------------------------
void vtkOFBPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OFB: " << this->GetOFB() << "\n";
  os << indent << "CompositeDataDisplayAttributes: " << this->GetCompositeDataDisplayAttributes()
     << "\n";
  os << indent << "LookupMode: " << GetLookupModeAsString(this->LookupMode) << "\n";
  os << indent << "ResolvedLookupMode: " << GetLookupModeAsString(this->ResolvedLookupMode) << "\n";
  os << indent << "InterpolationRadius: " << this->InterpolationRadius << " cells\n";
  os << indent << "MipmapBias: " << this->MipmapBias << "\n";
  os << indent << "MaximumNumberOfMipmapLevels: " << this->MaximumNumberOfMipmapLevels << "\n";
  os << indent << "MinimumMipmapResolution: " << this->MinimumMipmapResolution << "\n";
  os << indent << "AutomaticLevelLIC: " << (this->AutomaticLevelLIC ? "On" : "Off") << "\n";
  os << indent << "Pyramid: " << this->Storage->GetPyramid()->GetClassName() << " ("
     << this->Storage->GetPyramid() << ")\n";
  os << indent << "Coloring:\n";
  this->Coloring->PrintSelf(os, indent.GetNextIndent());
  os << indent << "UsePaintedNormals: " << (this->UsePaintedNormals ? "On" : "Off") << "\n";
  os << indent << "FlowAlignedFiltering: " << (this->FlowAlignedFiltering ? "On" : "Off") << "\n";
  os << indent << "MaximumFlowFilterOffset: " << this->MaximumFlowFilterOffset << " cells\n";
  os << indent << "FlowArrayName: \"" << this->FlowArrayName << "\"\n";
  os << indent << "ResolvedFlowArrayName: \"" << this->ResolvedFlowArrayName << "\"\n";
  os << indent << "LastUploadedSampleCount: " << this->LastUploadedSampleCount << "\n";
  os << indent << "LastRenderUsedOFB: " << (this->LastRenderUsedOFB ? "true" : "false") << "\n";
  os << indent << "GPUMemorySize: " << this->Storage->GetMemorySize() << " bytes\n";
  os << indent << "UploadedBytes: " << this->Storage->GetUploadedBytes() << "\n";
}
