#include "vtkOFBTexturedMeshWriter.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkGLTFExporter.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkImageShiftScale.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkOFB.h"
#include "vtkOFBParaViewProbe.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtksys/SystemTools.hxx"

#include <cstdio> // std::rename
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h> // getpid

vtkStandardNewMacro(vtkOFBTexturedMeshWriter);

namespace
{
using SystemTools = vtksys::SystemTools;

/// A folder beside the target that holds the files until all are complete; removed
/// (with whatever is left in it) when it goes out of scope.
class StagingFolder
{
public:
  explicit StagingFolder(const std::string& target)
  {
    std::string dir = SystemTools::GetFilenamePath(SystemTools::CollapseFullPath(target));
    this->Target = dir;
    this->Path = dir + "/." + SystemTools::GetFilenameName(target) + ".partial-" +
      std::to_string(static_cast<long>(getpid()));
    SystemTools::RemoveADirectory(this->Path);
    this->Made = SystemTools::MakeDirectory(this->Path).IsSuccess();
  }
  ~StagingFolder()
  {
    if (this->Made)
    {
      SystemTools::RemoveADirectory(this->Path);
    }
  }
  bool Ok() const { return this->Made; }
  std::string Staged(const std::string& name) const { return this->Path + "/" + name; }
  std::string Final(const std::string& name) const { return this->Target + "/" + name; }
  /// Renames `names`, in order, from the folder to the target's folder.
  bool Commit(const std::vector<std::string>& names) const
  {
    for (const std::string& name : names)
    {
      if (!SystemTools::FileExists(this->Staged(name)) ||
        std::rename(this->Staged(name).c_str(), this->Final(name).c_str()) != 0)
      {
        return false;
      }
    }
    return true;
  }

private:
  std::string Target;
  std::string Path;
  bool Made = false;
};

/// `image` as RGB unsigned char: unsigned char arrays keep their values, others are
/// mapped from [0, 1] to 0-255; one or two components become grey.
vtkSmartPointer<vtkImageData> ToRGB(vtkImageData* image)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> bytes = image;
  if (scalars->GetDataType() != VTK_UNSIGNED_CHAR)
  {
    vtkNew<vtkImageShiftScale> scale;
    scale->SetInputData(image);
    scale->SetScale(255.0);
    scale->SetOutputScalarTypeToUnsignedChar();
    scale->ClampOverflowOn();
    scale->Update();
    bytes = scale->GetOutput();
  }
  vtkNew<vtkImageExtractComponents> rgb;
  rgb->SetInputData(bytes);
  if (scalars->GetNumberOfComponents() >= 3)
  {
    rgb->SetComponents(0, 1, 2);
  }
  else
  {
    rgb->SetComponents(0, 0, 0);
  }
  rgb->Update();
  return rgb->GetOutput();
}
}

//------------------------------------------------------------------------------
vtkOFBTexturedMeshWriter::vtkOFBTexturedMeshWriter()
  : FileName(nullptr)
  , ArrayName(nullptr)
  , TextureSize(2048)
  , WrittenTextureSize{ 0, 0 }
{
}

//------------------------------------------------------------------------------
vtkOFBTexturedMeshWriter::~vtkOFBTexturedMeshWriter()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkOFBTexturedMeshWriter::SetOFB(vtkOFB* ofb)
{
  if (this->OFB != ofb)
  {
    this->OFB = ofb;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkOFB* vtkOFBTexturedMeshWriter::GetOFB() const
{
  return this->OFB;
}

//------------------------------------------------------------------------------
int vtkOFBTexturedMeshWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkOFBTexturedMeshWriter::WriteData()
{
  this->WrittenTextureSize[0] = this->WrittenTextureSize[1] = 0;
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  vtkOFB* ofb = this->OFB ? this->OFB.Get() : vtkOFBParaViewProbe::GetOFB(input);
  const std::string path = this->FileName ? this->FileName : "";
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path));
  if (path.empty())
  {
    vtkErrorMacro("No file name to write.");
    return;
  }
  if (ext != ".obj" && ext != ".gltf")
  {
    vtkErrorMacro("Cannot write '" << path << "': the extension must be .obj or .gltf.");
    return;
  }
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("Cannot write '" << path << "': the input has no polygons.");
    return;
  }
  if (!ofb || ofb->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("Cannot write '" << path
                                   << "': no OFB, or an empty one (write the output of OFB "
                                      "Probe, or give one with SetOFB).");
    return;
  }
  const char* arrayName = this->ArrayName && *this->ArrayName ? this->ArrayName : "Colors";
  if (!ofb->GetSampleData()->GetArray(arrayName))
  {
    vtkErrorMacro(
      "Cannot write '" << path << "': the OFB has no sample array '" << arrayName << "'.");
    return;
  }

  // The mesh with texture coordinates: its own, or an atlas's charts.
  vtkSmartPointer<vtkPolyData> textured = input;
  int size[2] = { this->TextureSize, this->TextureSize };
  vtkNew<vtkOFBTextureAtlas> atlas;
  if (!input->GetPointData()->GetTCoords())
  {
    atlas->SetInputData(input);
    atlas->SetOFBData(ofb);
    atlas->SetMaximumTextureSize(this->TextureSize);
    atlas->Update();
    textured = atlas->GetOutput();
    atlas->GetAtlasSize(size);
    if (size[0] <= 0 || size[1] <= 0 || textured->GetNumberOfPoints() == 0)
    {
      vtkErrorMacro("Cannot write '" << path << "': no texture atlas for the mesh.");
      return;
    }
  }
  this->UpdateProgress(0.2);
  vtkNew<vtkOFBTextureBaker> baker;
  baker->SetInputData(textured);
  baker->SetOFBData(ofb);
  baker->SetArrayName(arrayName);
  baker->SetTextureSize(size);
  baker->Update();
  vtkSmartPointer<vtkImageData> texels = ToRGB(baker->GetOutput());
  if (!texels || texels->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("Cannot write '" << path << "': baking the texture failed.");
    return;
  }
  this->UpdateProgress(0.7);

  StagingFolder staging(path);
  if (!staging.Ok())
  {
    vtkErrorMacro("Cannot write '" << path << "': its folder cannot be written.");
    return;
  }
  const std::string name = SystemTools::GetFilenameName(path);
  const std::string stem = SystemTools::GetFilenameWithoutLastExtension(name);
  std::vector<std::string> names;
  if (ext == ".obj")
  {
    const std::string png = stem + ".png";
    vtkNew<vtkPNGWriter> image;
    image->SetInputData(texels);
    image->SetFileName(staging.Staged(png).c_str());
    image->Write();
    vtkNew<vtkOBJWriter> obj;
    obj->SetInputData(0, textured);
    obj->SetTextureFileName(png.c_str());
    obj->SetFileName(staging.Staged(name).c_str());
    obj->Write();
    if (image->GetErrorCode() != 0 || obj->GetErrorCode() != 0)
    {
      vtkErrorMacro("Cannot write '" << path << "'.");
      return;
    }
    names = { png, stem + ".mtl", name };
  }
  else
  {
    vtkNew<vtkTexture> texture;
    texture->SetInputData(texels);
    texture->InterpolateOn();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(textured);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    vtkNew<vtkRenderWindow> window;
    window->AddRenderer(renderer);
    vtkNew<vtkGLTFExporter> exporter;
    exporter->SetRenderWindow(window);
    exporter->InlineDataOn();
    exporter->SaveNormalOn();
    const std::string text = exporter->WriteToString();
    std::ofstream out(staging.Staged(name), std::ios::binary);
    out << text;
    out.close();
    if (text.empty() || !out)
    {
      vtkErrorMacro("Cannot write '" << path << "'.");
      return;
    }
    names = { name };
  }
  if (!staging.Commit(names))
  {
    vtkErrorMacro("Cannot write '" << path << "': renaming the files into place failed.");
    return;
  }
  this->WrittenTextureSize[0] = size[0];
  this->WrittenTextureSize[1] = size[1];
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkOFBTexturedMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "TextureSize: " << this->TextureSize << "\n";
  os << indent << "OFB: " << this->OFB.Get() << "\n";
}
