// The OFB plugin's check, when it is loaded, that the ParaView loading it is the one it
// was built against (paraview_add_plugin INITIALIZERS).
#ifndef vtkOFBParaViewVersionCheck_h
#define vtkOFBParaViewVersionCheck_h

#include <string>

/**
 * The message that the OFB plugin, built for ParaView `builtMajor`.`builtMinor`, gives
 * in ParaView `major`.`minor`: empty when the versions match, else what is wrong and
 * what to do.
 */
std::string vtkOFBParaViewVersionMismatch(int builtMajor, int builtMinor, int major, int minor);

/**
 * Compares the ParaView version the plugin was compiled against (PARAVIEW_VERSION_MAJOR
 * and _MINOR) with the one of the running ParaView (vtkSMProxyManager::GetVersionMajor
 * and GetVersionMinor, resolved in the running process) and reports a mismatch as an
 * error through vtkOutputWindow, in the console, the GUI's output messages or the
 * Python shell. Called when the plugin is loaded.
 */
void vtkOFBParaViewCheckVersion();

#endif
