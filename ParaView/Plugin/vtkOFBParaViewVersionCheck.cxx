#include "vtkOFBParaViewVersionCheck.h"

#include "vtkOutputWindow.h"
#include "vtkPVVersion.h"
#include "vtkSMProxyManager.h"

#include <sstream>

//------------------------------------------------------------------------------
std::string vtkOFBParaViewVersionMismatch(int builtMajor, int builtMinor, int major, int minor)
{
  if (builtMajor == major && builtMinor == minor)
  {
    return std::string();
  }
  std::ostringstream message;
  message << "The OFB plugin was built for ParaView " << builtMajor << "." << builtMinor
          << " and is loaded into ParaView " << major << "." << minor
          << ": plugins work only in the ParaView version they were built against. "
          << "Build it against this ParaView (cmake -S ParaView -B <build> "
          << "-DParaView_DIR=<this ParaView's lib/cmake/paraview-" << major << "." << minor
          << "> in vtkOFB's sources) or use ParaView " << builtMajor << "." << builtMinor << ".";
  return message.str();
}

//------------------------------------------------------------------------------
void vtkOFBParaViewCheckVersion()
{
  const std::string message = vtkOFBParaViewVersionMismatch(PARAVIEW_VERSION_MAJOR,
    PARAVIEW_VERSION_MINOR,
    vtkSMProxyManager::GetVersionMajor(),
    vtkSMProxyManager::GetVersionMinor());
  if (!message.empty())
  {
    vtkOutputWindow::GetInstance()->DisplayErrorText((message + "\n").c_str());
  }
}
