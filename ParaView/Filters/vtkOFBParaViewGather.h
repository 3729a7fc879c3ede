// What the OFB writers under MPI share: every process's share (a data object) on the
// first process, one point-to-point message each, which the controller splits where a
// message is beyond MPI's int counts (a collective Gather of data objects is not: its
// counts and offsets are ints, 2 GiB in all).
#ifndef vtkOFBParaViewGather_h
#define vtkOFBParaViewGather_h

#include "vtkDataObject.h"
#include "vtkMultiProcessController.h"
#include "vtkSmartPointer.h"

#include <vector>

namespace vtkofbparaview
{
/// The tag of the shares' messages.
constexpr int ShareTag = 46431;

/**
 * Every process's `share` on the first process, in the order of the processes (empty on
 * the others); each share received into a new object of the first process's share's
 * type. False where a message failed (on the first process; the others return true).
 */
inline bool GatherShares(vtkMultiProcessController* controller,
  vtkDataObject* share,
  std::vector<vtkSmartPointer<vtkDataObject>>& shares)
{
  shares.clear();
  if (controller->GetLocalProcessId() != 0)
  {
    return controller->Send(share, 0, ShareTag) != 0;
  }
  bool ok = true;
  shares.emplace_back(share);
  for (int r = 1; r < controller->GetNumberOfProcesses(); ++r)
  {
    vtkSmartPointer<vtkDataObject> received;
    received.TakeReference(share->NewInstance());
    ok = controller->Receive(received, r, ShareTag) != 0 && ok;
    shares.push_back(received);
  }
  return ok;
}
}

#endif
