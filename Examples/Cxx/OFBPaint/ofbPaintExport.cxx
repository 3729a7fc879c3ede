#include "ofbPaintExport.h"
#include "ofbPaintErrors.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkGLTFExporter.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkOFB.h"
#include "vtkOFBProbeFilter.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkOFBTextureProjector.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <sstream>

namespace
{
using SystemTools = vtksys::SystemTools;

bool WriteOBJ(vtkPolyData* surface,
  vtkAlgorithm* image,
  const std::string& path,
  vtkCommand* errors)
{
  vtkNew<vtkOBJWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(0, surface);
  writer->SetInputConnection(1, image->GetOutputPort());
  writer->SetFileName(path.c_str());
  return writer->Write() != 0;
}

/// glTF 2.0 through vtkGLTFExporter, which writes a scene: the surface as the one actor of
/// a renderer (never rendered), the image as its texture.
bool WriteGLTF(vtkPolyData* surface,
  vtkAlgorithm* image,
  const std::string& path,
  vtkCommand* errors)
{
  image->Update();
  vtkNew<vtkImageData> texels;
  texels->ShallowCopy(image->GetOutputDataObject(0));
  if (texels->GetNumberOfPoints() == 0)
  {
    return false;
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(texels);
  texture->InterpolateOn();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  vtkNew<vtkGLTFExporter> exporter;
  exporter->AddObserver(vtkCommand::ErrorEvent, errors);
  exporter->SetRenderWindow(window);
  exporter->SetFileName(path.c_str());
  exporter->InlineDataOn();
  exporter->SaveNormalOn();
  exporter->Write();
  return SystemTools::FileExists(path, true);
}
}

namespace ofbpaint
{
std::string DefaultExportPath(const std::string& meshPath, const std::string& what)
{
  return SystemTools::GetFilenameWithoutLastExtension(meshPath) + "_" + what + ".obj";
}

bool ExportPainting(vtkPolyData* surface,
  vtkOFB* ofb,
  const std::string& path,
  int textureSize,
  std::string& message)
{
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path));
  vtkNew<FirstError> errors;
  std::ostringstream done;
  if (ext == ".obj" || ext == ".gltf")
  {
    // A mesh without texture coordinates gets an atlas of charts on the OFB's grids, a
    // texel a cell where textureSize allows.
    vtkSmartPointer<vtkPolyData> textured = surface;
    int size[2] = { textureSize, textureSize };
    vtkNew<vtkOFBTextureAtlas> atlas;
    const bool generated = !surface->GetPointData()->GetTCoords();
    if (generated)
    {
      atlas->AddObserver(vtkCommand::ErrorEvent, errors);
      atlas->SetInputData(surface);
      atlas->SetOFBData(ofb);
      atlas->SetMaximumTextureSize(std::max(16, textureSize));
      atlas->Update();
      textured = atlas->GetOutput();
      atlas->GetAtlasSize(size);
      if (!errors->Text.empty() || size[0] == 0)
      {
        message = "cannot lay out a texture for '" + path + "': " + errors->Text;
        return false;
      }
    }
    // The paint as an RGB texture (opaque: an alpha channel makes viewers sort the mesh as
    // translucent), written by the OBJ writer beside the .obj with its .mtl, or into the
    // .gltf (a textured mesh with its normals, the image embedded).
    vtkNew<vtkOFBTextureBaker> baker;
    baker->AddObserver(vtkCommand::ErrorEvent, errors);
    baker->SetInputData(textured);
    baker->SetOFBData(ofb);
    baker->SetTextureSize(size);
    vtkNew<vtkImageExtractComponents> rgb;
    rgb->SetInputConnection(baker->GetOutputPort());
    rgb->SetComponents(0, 1, 2);
    const bool written = ext == ".obj" ? WriteOBJ(textured, rgb, path, errors)
                                       : WriteGLTF(textured, rgb, path, errors);
    if (!written || !errors->Text.empty())
    {
      message = "cannot export '" + path + "'" + (errors->Text.empty() ? "" : ": " + errors->Text);
      return false;
    }
    done << "wrote " << path << " with a " << size[0] << " x " << size[1] << " texture ("
         << baker->GetNumberOfBakedTexels() << " texels baked";
    if (generated)
    {
      done << ", texture coordinates made: " << atlas->GetNumberOfCharts()
           << " charts on the OFB's grids";
    }
    done << ")";
    message = done.str();
    return true;
  }
  if (ext != ".ply" && ext != ".vtp")
  {
    message = "cannot export to '" + ext + "' files (use .obj, .gltf, .ply or .vtp)";
    return false;
  }
  vtkNew<vtkOFBProbeFilter> probe;
  probe->AddObserver(vtkCommand::ErrorEvent, errors);
  probe->SetInputData(surface);
  probe->SetOFBData(ofb);
  probe->Update();
  int ok = 0;
  if (ext == ".ply")
  {
    vtkNew<vtkPLYWriter> writer;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    writer->SetInputConnection(probe->GetOutputPort());
    writer->SetFileName(path.c_str());
    writer->SetArrayName("Colors");
    writer->EnableAlphaOn();
    ok = writer->Write();
  }
  else
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    writer->SetInputConnection(probe->GetOutputPort());
    writer->SetFileName(path.c_str());
    ok = writer->Write();
  }
  if (!ok || !errors->Text.empty())
  {
    message = "cannot export '" + path + "'" + (errors->Text.empty() ? "" : ": " + errors->Text);
    return false;
  }
  done << "wrote " << path << " (" << probe->GetOutput()->GetNumberOfPoints() << " points with "
       << (ext == ".ply" ? "vertex colours" : "the sample arrays") << ")";
  message = done.str();
  return true;
}

vtkSmartPointer<vtkOFB> ImportTexture(vtkPolyData* surface,
  vtkOFB* ofb,
  const std::string& imagePath,
  std::string& message)
{
  if (!surface->GetPointData()->GetTCoords())
  {
    message = "the surface has no texture coordinates to import '" + imagePath + "' through";
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> image = ReadImage(imagePath, message);
  if (!image)
  {
    return nullptr;
  }
  vtkNew<FirstError> errors;
  vtkNew<vtkOFBTextureProjector> projector;
  projector->AddObserver(vtkCommand::ErrorEvent, errors);
  projector->SetInputData(ofb);
  projector->SetMeshData(surface);
  projector->SetTextureData(image);
  projector->Update();
  if (!errors->Text.empty() || projector->GetOutput()->GetNumberOfSamples() == 0)
  {
    message =
      "cannot import '" + imagePath + "'" + (errors->Text.empty() ? "" : ": " + errors->Text);
    return nullptr;
  }
  vtkSmartPointer<vtkOFB> out = projector->GetOutput();
  std::ostringstream done;
  done << "imported " << imagePath << " into " << projector->GetNumberOfProjectedSamples()
       << " samples";
  message = done.str();
  return out;
}

vtkSmartPointer<vtkImageData> ReadImage(const std::string& path, std::string& message)
{
  vtkSmartPointer<vtkImageReader2> reader =
    vtk::TakeSmartPointer(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
  if (!reader)
  {
    message = "cannot read '" + path + "' as an image";
    return nullptr;
  }
  vtkNew<FirstError> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  if (!errors->Text.empty() || !image || image->GetNumberOfPoints() == 0)
  {
    message = "cannot read '" + path + "'" + (errors->Text.empty() ? "" : ": " + errors->Text);
    return nullptr;
  }
  return image;
}
}
