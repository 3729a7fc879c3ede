// What the OFB writers under MPI share: each process's piece asked for, and every
// process's share (a vtkPolyData) on the first process, bit for bit: each share travels
// as a VTK XML file in raw binary (a controller's Send or Gather of a data object writes
// the legacy format in ASCII, which keeps 6 to 11 significant digits of a value), in one
// point-to-point message that the controller splits where it is beyond MPI's int counts
// (a collective gather's counts and offsets are ints: 2 GiB in all).
#ifndef vtkOFBParaViewGather_h
#define vtkOFBParaViewGather_h

#include "vtkCharArray.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <string>
#include <vector>

namespace vtkofbparaview
{
/// The tag of the shares' messages.
constexpr int ShareTag = 46431;

/**
 * For a writer's ProcessRequest: under several processes, a REQUEST_UPDATE_EXTENT asks
 * for this process's piece (of the controller's processes, without ghost levels), as
 * ParaView's parallel writers do; a writer has no output to copy a piece request from,
 * else every process would ask for the whole data (piece 0 of 1). True where it did.
 */
inline bool RequestOwnPiece(vtkMultiProcessController* controller,
  vtkInformation* request,
  vtkInformationVector** inputVector)
{
  if (!request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()) || !controller ||
    controller->GetNumberOfProcesses() <= 1 || inputVector[0]->GetNumberOfInformationObjects() == 0)
  {
    return false;
  }
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), controller->GetLocalProcessId());
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
    controller->GetNumberOfProcesses());
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return true;
}

/// `share` as a VTK XML file in raw binary (every value bit for bit).
inline std::string SerializeShare(vtkPolyData* share)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(share);
  writer->WriteToOutputStringOn();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToNone();
  writer->SetHeaderTypeToUInt64();
  writer->Write();
  return writer->GetOutputString();
}

/// The share that SerializeShare wrote into `bytes`; null where they do not parse.
inline vtkSmartPointer<vtkPolyData> DeserializeShare(const std::string& bytes)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(bytes);
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> share = reader->GetOutput();
  return share;
}

/**
 * Every process's `share` on the first process, in the order of the processes (empty on
 * the others), bit for bit. False where a message failed or did not parse (on the first
 * process; the others return true).
 */
inline bool GatherShares(vtkMultiProcessController* controller,
  vtkPolyData* share,
  std::vector<vtkSmartPointer<vtkPolyData>>& shares)
{
  shares.clear();
  if (controller->GetLocalProcessId() != 0)
  {
    const std::string bytes = SerializeShare(share);
    vtkIdType length = static_cast<vtkIdType>(bytes.size());
    return controller->Send(&length, 1, 0, ShareTag) != 0 &&
      controller->Send(bytes.data(), length, 0, ShareTag) != 0;
  }
  bool ok = true;
  shares.emplace_back(share);
  for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
  {
    vtkIdType length = 0;
    std::string bytes;
    if (controller->Receive(&length, 1, r, ShareTag) && length >= 0)
    {
      bytes.resize(static_cast<size_t>(length));
      ok = controller->Receive(&bytes[0], length, r, ShareTag) != 0 && ok;
    }
    else
    {
      ok = false;
    }
    vtkSmartPointer<vtkPolyData> received = DeserializeShare(bytes);
    ok = received != nullptr && ok;
    shares.push_back(received ? received : vtkSmartPointer<vtkPolyData>::New());
  }
  return ok;
}
}

#endif
