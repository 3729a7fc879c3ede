#include "ofbPaintExport.h"
#include "ofbPaintErrors.h"

#include "ofbExampleFiles.h"
#include "ofbExampleImage.h"
#include "ofbExampleMesh.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkOFB.h"
#include "vtkOFBImageReader.h"
#include "vtkOFBImageWriter.h"
#include "vtkOFBProbeFilter.h"
#include "vtkOFBStagedFiles.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkOFBTextureProjector.h"
#include "vtkOFBTexturedGLTF.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace
{
using SystemTools = vtksys::SystemTools;
using ofbexample::FirstError;

/// The lines of the OBJ at `path` that are faces, or -1 when its last line is cut short.
long long CountFaces(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long faces = 0;
  bool complete = true;
  while (std::getline(in, line))
  {
    faces += line.compare(0, 2, "f ") == 0;
    complete = !in.eof(); // the last line ended with its newline
  }
  return complete ? faces : -1;
}

/// The faces vtkOBJWriter writes for `surface`: its polygons and its strips' triangles.
long long ExpectedFaces(vtkPolyData* surface)
{
  long long faces = surface->GetNumberOfPolys();
  vtkCellArray* strips = surface->GetStrips();
  for (vtkIdType i = 0; i < strips->GetNumberOfCells(); ++i)
  {
    faces += std::max<vtkIdType>(0, strips->GetCellSize(i) - 2);
  }
  return faces;
}

/// The float texture `lic` as the 32-bit float OpenEXR staged as `name` (vtkOFBImageWriter),
/// read back (vtkOFBImageReader) and compared bit for bit.
bool WriteFloatTexture(vtkImageData* lic,
  vtkOFBStagedFiles& files,
  const std::string& name,
  std::string& message)
{
  vtkNew<FirstError> errors;
  vtkNew<vtkOFBImageWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(lic);
  writer->SetFileName(files.Staged(name).c_str());
  if (writer->Write() == 0 || errors->Count > 0)
  {
    message = "cannot write '" + files.Final(name) + "'" + errors->Suffix();
    return false;
  }
  vtkNew<vtkOFBImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(files.Staged(name).c_str());
  reader->Update();
  vtkDataArray* written = lic->GetPointData()->GetScalars();
  vtkDataArray* read = reader->GetOutput()->GetPointData()->GetScalars();
  if (errors->Count > 0 || !read || read->GetDataType() != VTK_FLOAT ||
    read->GetNumberOfValues() != written->GetNumberOfValues() ||
    std::memcmp(read->GetVoidPointer(0),
      written->GetVoidPointer(0),
      sizeof(float) * written->GetNumberOfValues()) != 0)
  {
    return files.Incomplete(name, message);
  }
  return files.Check(name, message);
}

/**
 * The textured OBJ: its texture PNG (and, with `lic`, the float LIC over the same texture
 * coordinates as <stem>_LIC.exr), its .mtl and the .obj staged (the writer given the
 * staged .obj and the texture's final file name, so that the .mtl and the .obj name the
 * final files), checked (the .obj's faces counted back, the .mtl compared with what it
 * must say, the OpenEXR read back), then renamed into place: the textures, the material,
 * the .obj last.
 */
bool WriteOBJ(vtkPolyData* surface,
  vtkImageData* texels,
  vtkImageData* lic,
  const std::string& path,
  std::string& message)
{
  const std::string name = SystemTools::GetFilenameName(path);
  const std::string stem = SystemTools::GetFilenameWithoutLastExtension(name);
  const std::string png = stem + ".png", mtl = stem + ".mtl", exr = stem + "_LIC.exr";
  std::vector<std::string> names = { png, mtl, name };
  if (lic)
  {
    names.insert(names.begin(), exr);
  }
  vtkOFBStagedFiles files(path);
  std::string bytes;
  if (!files.Begin(names, message) || !ofbexample::EncodePNG(texels, bytes, message) ||
    !files.Write(png, bytes, message) || (lic && !WriteFloatTexture(lic, files, exr, message)))
  {
    return false;
  }
  vtkNew<FirstError> errors;
  vtkNew<vtkOBJWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(0, surface);
  writer->SetTextureFileName(png.c_str());
  writer->SetFileName(files.Staged(name).c_str());
  if (writer->Write() == 0 || errors->Count > 0 || writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    message = "cannot write '" + path + "'" + errors->Suffix();
    return false;
  }
  std::ifstream material(files.Staged(mtl), std::ios::binary);
  const std::string said(
    (std::istreambuf_iterator<char>(material)), std::istreambuf_iterator<char>());
  if (!files.Check(mtl, message) || !files.Check(name, message))
  {
    return false;
  }
  if (said != "newmtl " + stem + "\nmap_Kd " + png + "\n")
  {
    return files.Incomplete(mtl, message);
  }
  if (CountFaces(files.Staged(name)) != ExpectedFaces(surface))
  {
    return files.Incomplete(name, message);
  }
  return files.Commit(names, message);
}

/// `bytes` as the one file `path`, staged and renamed into place.
bool WriteBytes(const std::string& bytes, const std::string& path, std::string& message)
{
  const std::string name = SystemTools::GetFilenameName(path);
  vtkOFBStagedFiles files(path);
  return files.Begin({ name }, message) && files.Write(name, bytes, message) &&
    files.Commit({ name }, message);
}

/**
 * The PLY with vertex colours: vtkPLYWriter writes the staged file (VTK 9.1's writer
 * leaves its output string empty), which is then read back through the checks of
 * ofbExampleMesh (complete header and body) before it is renamed into place.
 */
bool WritePLY(vtkPolyData* probed, const std::string& path, std::string& message)
{
  const std::string name = SystemTools::GetFilenameName(path);
  vtkOFBStagedFiles files(path);
  if (!files.Begin({ name }, message))
  {
    return false;
  }
  vtkNew<FirstError> errors;
  vtkNew<vtkPLYWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(probed);
  writer->SetFileName(files.Staged(name).c_str());
  writer->SetArrayName("Colors");
  writer->EnableAlphaOn();
  if (writer->Write() == 0 || errors->Count > 0 || writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    message = "cannot write '" + path + "'" + errors->Suffix();
    return false;
  }
  std::string problem;
  if (!files.Check(name, message))
  {
    return false;
  }
  if (!ofbexample::CheckPLYFile(files.Staged(name), problem))
  {
    return files.Incomplete(name, message);
  }
  return files.Commit({ name }, message);
}

/// The VTP with every sample array: written into a string, then as above.
bool WriteVTP(vtkPolyData* probed, const std::string& path, std::string& message)
{
  vtkNew<FirstError> errors;
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(probed);
  writer->WriteToOutputStringOn();
  const std::string bytes = writer->Write() != 0 ? writer->GetOutputString() : "";
  if (errors->Count > 0 || bytes.empty())
  {
    message = "cannot write '" + path + "'" + errors->Suffix();
    return false;
  }
  return WriteBytes(bytes, path, message);
}

/// glTF 2.0 (vtkOFBTexturedGLTF: the image embedded), written as above.
bool WriteGLTF(vtkPolyData* surface,
  vtkImageData* texels,
  const std::string& path,
  std::string& message)
{
  vtkNew<FirstError> errors;
  const std::string text = vtkOFBTexturedGLTF::WriteToString(surface, texels, errors);
  if (errors->Count > 0 || text.empty())
  {
    message = "cannot write '" + path + "'" + errors->Suffix();
    return false;
  }
  return WriteBytes(text, path, message);
}

/**
 * The textured OBJ (with the LIC as an OpenEXR where the OFB has one) or glTF: the surface
 * with its texture coordinates, or those of an atlas, and the paint baked into an RGB
 * texture; `message` says what was written.
 */
bool ExportTextured(vtkPolyData* surface,
  vtkOFB* ofb,
  const std::string& path,
  const std::string& ext,
  int textureSize,
  std::string& message)
{
  vtkNew<FirstError> errors;
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
  rgb->AddObserver(vtkCommand::ErrorEvent, errors);
  rgb->SetInputConnection(baker->GetOutputPort());
  rgb->SetComponents(0, 1, 2);
  rgb->Update();
  vtkImageData* texels = rgb->GetOutput();
  if (errors->Count > 0 || texels->GetNumberOfPoints() == 0)
  {
    message = "cannot export '" + path + "': baking the texture failed" + errors->Suffix();
    return false;
  }
  // An OBJ also gets the LIC's intensity, where the OFB has one, as a 32-bit float
  // OpenEXR over the same texture coordinates: exact, for renderers and compositors.
  auto* licArray = vtkFloatArray::SafeDownCast(ofb->GetSampleData()->GetArray("LIC"));
  vtkNew<vtkOFBTextureBaker> licBaker;
  vtkImageData* lic = nullptr;
  if (ext == ".obj" && licArray && licArray->GetNumberOfComponents() == 1)
  {
    licBaker->AddObserver(vtkCommand::ErrorEvent, errors);
    licBaker->SetInputData(textured);
    licBaker->SetOFBData(ofb);
    licBaker->SetArrayName("LIC");
    licBaker->SetTextureSize(size);
    licBaker->Update();
    lic = licBaker->GetOutput();
    if (errors->Count > 0 || lic->GetNumberOfPoints() == 0)
    {
      message = "cannot export '" + path + "': baking the LIC failed" + errors->Suffix();
      return false;
    }
  }
  if (!(ext == ".obj" ? WriteOBJ(textured, texels, lic, path, message)
                      : WriteGLTF(textured, texels, path, message)))
  {
    return false;
  }
  std::ostringstream done;
  done << "wrote " << path << " with a " << size[0] << " x " << size[1] << " texture ("
       << baker->GetNumberOfBakedTexels() << " texels baked";
  if (generated)
  {
    done << ", texture coordinates made: " << atlas->GetNumberOfCharts()
         << " charts on the OFB's grids";
  }
  done << ")";
  if (lic)
  {
    done << " and the LIC as " << SystemTools::GetFilenameWithoutLastExtension(path)
         << "_LIC.exr (32-bit float, read back bit for bit)";
  }
  message = done.str();
  return true;
}

/// The PLY with vertex colours or the VTP with every sample array, through
/// vtkOFBProbeFilter; `message` says what was written.
bool ExportProbed(vtkPolyData* surface,
  vtkOFB* ofb,
  const std::string& path,
  const std::string& ext,
  std::string& message)
{
  vtkNew<FirstError> errors;
  vtkNew<vtkOFBProbeFilter> probe;
  probe->AddObserver(vtkCommand::ErrorEvent, errors);
  probe->SetInputData(surface);
  probe->SetOFBData(ofb);
  probe->Update();
  if (errors->Count > 0)
  {
    message = "cannot export '" + path + "'" + errors->Suffix();
    return false;
  }
  if (!(ext == ".ply" ? WritePLY(probe->GetOutput(), path, message)
                      : WriteVTP(probe->GetOutput(), path, message)))
  {
    return false;
  }
  std::ostringstream done;
  done << "wrote " << path << " (" << probe->GetOutput()->GetNumberOfPoints() << " points with "
       << (ext == ".ply" ? "vertex colours" : "the sample arrays") << ")";
  message = done.str();
  return true;
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
  const std::string why = vtkOFBStagedFiles::WhyNotWritable(path);
  if (!why.empty())
  {
    message = "cannot write '" + path + "': " + why; // before the work of baking
    return false;
  }
  if (ext == ".obj" || ext == ".gltf")
  {
    return ExportTextured(surface, ofb, path, ext, textureSize, message);
  }
  if (ext != ".ply" && ext != ".vtp")
  {
    message = "cannot export to '" + ext + "' files (use .obj, .gltf, .ply or .vtp)";
    return false;
  }
  return ExportProbed(surface, ofb, path, ext, message);
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
  vtkSmartPointer<vtkImageData> image =
    ofbexample::ReadImageChecked(imagePath, ofbexample::DefaultMaximumImagePixels, message);
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

}
