// A stand-in for another ParaView version, for the plugin's version check test: loaded
// first (LD_PRELOAD) into pvbatch, its vtkSMProxyManager::GetVersionMinor is the one
// that every caller in the process resolves to, as the running ParaView's own would be
// in a ParaView of another version.
#include "vtkPVVersion.h"
#include "vtkSMProxyManager.h"

int vtkSMProxyManager::GetVersionMinor()
{
  return PARAVIEW_VERSION_MINOR + 1;
}
