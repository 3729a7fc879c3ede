// An OpenGL 4.5 core context on an EGL device, wrapped in a vtkGenericOpenGLRenderWindow,
// for benchmarks on a Linux machine with a GPU driver and no X display (a compute node,
// a container). Debian's VTK 9.1 is built for X11 only; this gives its OpenGL code a
// context without one.
//
// VTK 9.1 initialises GLEW, whose GLX half fails without an X display (after it has loaded
// every OpenGL function). ofbEGLWindow.cxx therefore answers GLEW's three GLX queries
// itself while the EGL context is in use, and forwards them to GLX otherwise; the program
// that links it must export its symbols (ENABLE_EXPORTS) so that GLEW sees them.
#ifndef ofbEGLWindow_h
#define ofbEGLWindow_h

#include "vtkSmartPointer.h"

#include <string>

class vtkRenderWindow;

namespace ofbbench
{
/// A render window on EGL device `device` (0: the first one), initialised and current;
/// nullptr with `why` set when there is no EGL device or no OpenGL 4.5 core context on it.
vtkSmartPointer<vtkRenderWindow> NewEGLRenderWindow(int device, std::string& why);
}

#endif
