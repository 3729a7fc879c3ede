#include "vtkOFBTexturedMeshWriter.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkImageShiftScale.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkOFB.h"
#include "vtkOFBMergeBlocks.h"
#include "vtkOFBParaViewGather.h"
#include "vtkOFBParaViewProbe.h"
#include "vtkOFBSamplePack.h"
#include "vtkOFBStagedFiles.h"
#include "vtkOFBTextureAtlas.h"
#include "vtkOFBTextureBaker.h"
#include "vtkOFBTexturedGLTF.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtksys/SystemTools.hxx"

#include <cctype>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOFBTexturedMeshWriter);
vtkCxxSetObjectMacro(vtkOFBTexturedMeshWriter, Controller, vtkMultiProcessController);

namespace
{
using SystemTools = vtksys::SystemTools;

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

/// `textured` as the OBJ `path` with its material (<stem>.mtl) and the texture `texels`
/// (<stem>.png) beside it: staged, checked, then renamed into place (the texture and the
/// material first, the .obj last); false with `message` the reason.
bool WriteOBJ(vtkPolyData* textured,
  vtkImageData* texels,
  const std::string& path,
  std::string& message)
{
  const std::string name = SystemTools::GetFilenameName(path);
  const std::string stem = SystemTools::GetFilenameWithoutLastExtension(name);
  const std::vector<std::string> names = { stem + ".png", stem + ".mtl", name };
  vtkOFBStagedFiles files(path);
  if (!files.Begin(names, message))
  {
    return false;
  }
  vtkNew<vtkPNGWriter> image;
  image->SetInputData(texels);
  image->SetFileName(files.Staged(names[0]).c_str());
  image->Write();
  vtkNew<vtkOBJWriter> obj;
  obj->SetInputData(0, textured);
  obj->SetTextureFileName(names[0].c_str());
  obj->SetFileName(files.Staged(name).c_str());
  obj->Write();
  if (image->GetErrorCode() != 0 || obj->GetErrorCode() != 0)
  {
    message = "cannot write '" + path + "'";
    return false;
  }
  return files.Check(names[0], message) && files.Check(names[1], message) &&
    files.Check(name, message) && files.Commit(names, message);
}

/// `textured` with the texture `texels` as the glTF 2.0 `path` (vtkGLTFExporter, the
/// texture embedded, normals written): staged, then renamed into place; false with
/// `message` the reason.
bool WriteGLTF(vtkPolyData* textured,
  vtkImageData* texels,
  const std::string& path,
  std::string& message)
{
  const std::string name = SystemTools::GetFilenameName(path);
  vtkOFBStagedFiles files(path);
  if (!files.Begin({ name }, message))
  {
    return false;
  }
  const std::string text = vtkOFBTexturedGLTF::WriteToString(textured, texels);
  if (text.empty())
  {
    message = "cannot write '" + path + "': the glTF exporter gave nothing";
    return false;
  }
  return files.Write(name, text, message) && files.Commit({ name }, message);
}

// A process's share of a distributed write, as one vtkPolyData sent to the first process:
// its piece without ghost cells, and in its field data the frame of its OFB and its owned
// samples (vtkOFBSamplePack, prefix SharePrefix).
const char* const SharePrefix = "vtkOFBWriter";
const char* const GhostName = "vtkGhostType";

vtkSmartPointer<vtkPolyData> MakeShare(vtkPolyData* input, vtkOFB* ofb)
{
  auto share = vtkSmartPointer<vtkPolyData>::New();
  if (input)
  {
    share->DeepCopy(input);
    share->RemoveGhostCells();
    share->GetCellData()->RemoveArray(GhostName);
    share->GetPointData()->RemoveArray(GhostName);
  }
  vtkNew<vtkFieldData> fields;
  share->SetFieldData(fields);
  vtkOFBSamplePack::Pack(ofb, fields, SharePrefix);
  return share;
}

/// The pieces of every process's share as one mesh, in the order of the processes: the
/// points of a piece at exactly the coordinates of a point of an earlier piece merged with
/// it (vtkOFBMergeBlocks; points of one piece are never merged with each other), without
/// field data.
vtkSmartPointer<vtkPolyData> MergeMeshes(const std::vector<vtkSmartPointer<vtkPolyData>>& shares)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  for (const auto& object : shares)
  {
    auto piece = vtkPolyData::SafeDownCast(object);
    if (piece && piece->GetNumberOfCells() > 0)
    {
      auto mesh = vtkSmartPointer<vtkPolyData>::New();
      mesh->ShallowCopy(piece);
      mesh->SetFieldData(nullptr);
      blocks->SetBlock(blocks->GetNumberOfBlocks(), mesh);
    }
  }
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  if (blocks->GetNumberOfBlocks() == 0)
  {
    return merged;
  }
  vtkNew<vtkOFBMergeBlocks> merge;
  merge->SetInputData(blocks);
  merge->MergePointsOn();
  merge->Update();
  merged->ShallowCopy(merge->GetOutput());
  merged->GetCellData()->RemoveArray(vtkOFBMergeBlocks::BlockIndexArrayName());
  return merged;
}

/// Every process's owned samples as one OFB on their common frame (vtkOFBSamplePack::Merge:
/// the samples of each grid cell in order of depth, ties in the order of the processes);
/// null without a frame, and null with `problem` set when the processes' frames differ.
vtkSmartPointer<vtkOFB> MergeSamples(const std::vector<vtkSmartPointer<vtkPolyData>>& shares,
  std::string& problem)
{
  std::vector<vtkOFBSamplePack::PackRef> packs;
  for (const auto& share : shares)
  {
    packs.push_back({ share ? share->GetFieldData() : nullptr, SharePrefix });
  }
  return vtkOFBSamplePack::Merge(packs, problem);
}
}

//------------------------------------------------------------------------------
vtkOFBTexturedMeshWriter::vtkOFBTexturedMeshWriter()
  : FileName(nullptr)
  , ArrayName(nullptr)
  , TextureSize(2048)
  , WrittenTextureSize{ 0, 0 }
  , Controller(nullptr)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOFBTexturedMeshWriter::~vtkOFBTexturedMeshWriter()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
  this->SetController(nullptr);
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
vtkTypeBool vtkOFBTexturedMeshWriter::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (vtkofbparaview::RequestOwnPiece(this->Controller, request, inputVector))
  {
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkOFBTexturedMeshWriter::WriteData()
{
  this->WrittenTextureSize[0] = this->WrittenTextureSize[1] = 0;
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  vtkOFB* ofb = this->OFB ? this->OFB.Get() : vtkOFBParaViewProbe::GetOFB(input);
  const std::string path = this->FileName ? this->FileName : "";
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path));
  // The same on every process: no collective call yet.
  if (path.empty())
  {
    vtkErrorMacro("No file name to write.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  if (ext != ".obj" && ext != ".gltf")
  {
    vtkErrorMacro("Cannot write '" << path << "': the extension must be .obj or .gltf.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  if (this->Controller && this->Controller->GetNumberOfProcesses() > 1)
  {
    this->WriteDistributed(input, ofb);
  }
  else if (!this->WriteMesh(input, ofb))
  {
    this->SetErrorCode(vtkErrorCode::UserError);
  }
}

//------------------------------------------------------------------------------
bool vtkOFBTexturedMeshWriter::WriteMesh(vtkPolyData* input, vtkOFB* ofb)
{
  const std::string path = this->FileName ? this->FileName : "";
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(path));
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("Cannot write '" << path << "': the input has no polygons.");
    return false;
  }
  if (!ofb || ofb->GetNumberOfSamples() == 0)
  {
    vtkErrorMacro("Cannot write '" << path
                                   << "': no OFB, or an empty one (write the output of OFB "
                                      "Probe, or give one with SetOFB).");
    return false;
  }
  const char* arrayName = this->ArrayName && *this->ArrayName ? this->ArrayName : "Colors";
  if (!ofb->GetSampleData()->GetArray(arrayName))
  {
    vtkErrorMacro(
      "Cannot write '" << path << "': the OFB has no sample array '" << arrayName << "'.");
    return false;
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
      return false;
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
    return false;
  }
  this->UpdateProgress(0.7);

  std::string message;
  if (!(ext == ".obj" ? WriteOBJ(textured, texels, path, message)
                      : WriteGLTF(textured, texels, path, message)))
  {
    message[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(message[0])));
    vtkErrorMacro(<< message << ".");
    return false;
  }
  this->WrittenTextureSize[0] = size[0];
  this->WrittenTextureSize[1] = size[1];
  this->UpdateProgress(1.0);
  return true;
}

//------------------------------------------------------------------------------
void vtkOFBTexturedMeshWriter::WriteDistributed(vtkPolyData* input, vtkOFB* ofb)
{
  // Every process's share on the first process (one message each), which writes; then
  // one broadcast of the result. Every process makes both calls, whatever its piece.
  vtkMultiProcessController* controller = this->Controller;
  const int rank = controller->GetLocalProcessId();
  vtkSmartPointer<vtkPolyData> share = MakeShare(input, ofb);
  std::vector<vtkSmartPointer<vtkPolyData>> shares;
  int result[3] = { 0, 0, 0 }; // success, written texture size
  if (!vtkofbparaview::GatherShares(controller, share, shares))
  {
    vtkErrorMacro("Cannot write '" << this->FileName << "': gathering the pieces failed.");
  }
  else if (rank == 0)
  {
    this->UpdateProgress(0.1);
    vtkSmartPointer<vtkPolyData> mesh = MergeMeshes(shares);
    std::string problem;
    vtkSmartPointer<vtkOFB> merged = MergeSamples(shares, problem);
    shares.clear();
    if (!problem.empty())
    {
      vtkErrorMacro("Cannot write '" << this->FileName << "': " << problem << ".");
    }
    else if (this->WriteMesh(mesh, merged))
    {
      result[0] = 1;
      result[1] = this->WrittenTextureSize[0];
      result[2] = this->WrittenTextureSize[1];
    }
  }
  controller->Broadcast(result, 3, 0);
  this->WrittenTextureSize[0] = result[1];
  this->WrittenTextureSize[1] = result[2];
  if (!result[0])
  {
    this->SetErrorCode(vtkErrorCode::UserError);
  }
}

//------------------------------------------------------------------------------
void vtkOFBTexturedMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
  os << indent << "TextureSize: " << this->TextureSize << "\n";
  os << indent << "OFB: " << this->OFB.Get() << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "WrittenTextureSize: " << this->WrittenTextureSize[0] << " "
     << this->WrittenTextureSize[1] << "\n";
}
