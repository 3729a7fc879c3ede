// ParaView's array menus set "None" (or an empty name) for "no array": the choice
// SetInputArrayToProcess made for array `idx` of an algorithm is then removed, so that the
// algorithm falls back to its default (the active vectors). Shared by the sampler and the
// particles.
#ifndef vtkOFBParaViewArrayChoice_h
#define vtkOFBParaViewArrayChoice_h

#include "vtkAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"

#include <cstring>

namespace vtkofbparaview
{
/// True when `name` is ParaView's "no array": null, empty or "None".
inline bool IsNoArray(const char* name)
{
  return !name || *name == '\0' || std::strcmp(name, "None") == 0;
}

/// Removes the choice of input array `idx` of `algorithm`; true if there was one.
inline bool ClearArrayChoice(vtkAlgorithm* algorithm, int idx)
{
  vtkInformationVector* arrays =
    algorithm->GetInformation()->Get(vtkAlgorithm::INPUT_ARRAYS_TO_PROCESS());
  if (!arrays || idx < 0 || idx >= arrays->GetNumberOfInformationObjects())
  {
    return false;
  }
  vtkInformation* choice = arrays->GetInformationObject(idx);
  if (choice->GetNumberOfKeys() == 0)
  {
    return false;
  }
  choice->Clear();
  return true;
}

/**
 * For an override of SetInputArrayToProcess: when `name` is "no array", removes the
 * choice of input array `idx` of `algorithm` (Modified when there was one) and returns
 * true; otherwise returns false, and the caller sets the choice.
 */
inline bool ChooseNoArray(vtkAlgorithm* algorithm, int idx, const char* name)
{
  if (!IsNoArray(name))
  {
    return false;
  }
  if (ClearArrayChoice(algorithm, idx))
  {
    algorithm->Modified();
  }
  return true;
}
}

#endif
