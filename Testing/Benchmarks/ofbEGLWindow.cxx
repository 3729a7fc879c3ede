#include "ofbEGLWindow.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkGenericOpenGLRenderWindow.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <dlfcn.h>
#include <vector>

namespace
{
/// The one EGL context of the process (a benchmark needs one).
struct EGLState
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLSurface Surface = EGL_NO_SURFACE;
  EGLContext Context = EGL_NO_CONTEXT;
};
EGLState TheEGL;

/// What glXGetCurrentDisplay answers while the EGL context is current: never dereferenced,
/// only compared by the glX functions below.
char FakeDisplay;

bool EGLIsCurrent()
{
  return TheEGL.Context != EGL_NO_CONTEXT && eglGetCurrentContext() == TheEGL.Context;
}

void MakeCurrent(vtkObject*, unsigned long, void*, void*)
{
  eglMakeCurrent(TheEGL.Display, TheEGL.Surface, TheEGL.Surface, TheEGL.Context);
}

void IsCurrent(vtkObject*, unsigned long, void*, void* callData)
{
  *static_cast<bool*>(callData) = EGLIsCurrent();
}

template<typename F>
F Next(const char* name)
{
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

bool OpenDisplay(int device, std::string& why)
{
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!queryDevices || !platformDisplay)
  {
    why = "EGL has no device enumeration (EGL_EXT_device_enumeration)";
    return false;
  }
  EGLint count = 0;
  queryDevices(0, nullptr, &count);
  if (device < 0 || device >= count)
  {
    why =
      "EGL device " + std::to_string(device) + " asked for, " + std::to_string(count) + " found";
    return false;
  }
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  queryDevices(count, devices.data(), &count);
  TheEGL.Display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[device], nullptr);
  EGLint major = 0, minor = 0;
  if (TheEGL.Display == EGL_NO_DISPLAY || !eglInitialize(TheEGL.Display, &major, &minor) ||
    !eglBindAPI(EGL_OPENGL_API))
  {
    why = "cannot initialise an OpenGL display on EGL device " + std::to_string(device);
    return false;
  }
  return true;
}

bool CreateContext(std::string& why)
{
  const EGLint configAttributes[] = { EGL_SURFACE_TYPE,
    EGL_PBUFFER_BIT,
    EGL_RENDERABLE_TYPE,
    EGL_OPENGL_BIT,
    EGL_RED_SIZE,
    8,
    EGL_GREEN_SIZE,
    8,
    EGL_BLUE_SIZE,
    8,
    EGL_ALPHA_SIZE,
    8,
    EGL_DEPTH_SIZE,
    24,
    EGL_NONE };
  EGLConfig config = nullptr;
  EGLint configs = 0;
  eglChooseConfig(TheEGL.Display, configAttributes, &config, 1, &configs);
  const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION,
    4,
    EGL_CONTEXT_MINOR_VERSION,
    5,
    EGL_CONTEXT_OPENGL_PROFILE_MASK,
    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
    EGL_NONE };
  if (configs > 0)
  {
    const EGLint surfaceAttributes[] = { EGL_WIDTH, 64, EGL_HEIGHT, 64, EGL_NONE };
    TheEGL.Surface = eglCreatePbufferSurface(TheEGL.Display, config, surfaceAttributes);
  }
  // Without a pbuffer configuration, a surfaceless context (EGL_KHR_surfaceless_context):
  // VTK renders into its own framebuffer objects either way.
  TheEGL.Context = eglCreateContext(TheEGL.Display,
    TheEGL.Surface != EGL_NO_SURFACE ? config : nullptr,
    EGL_NO_CONTEXT,
    contextAttributes);
  if (TheEGL.Context == EGL_NO_CONTEXT ||
    !eglMakeCurrent(TheEGL.Display, TheEGL.Surface, TheEGL.Surface, TheEGL.Context))
  {
    why = "no OpenGL 4.5 core context on the EGL device (EGL error " +
      std::to_string(eglGetError()) + ")";
    TheEGL.Context = EGL_NO_CONTEXT;
    return false;
  }
  return true;
}

void Observe(vtkGenericOpenGLRenderWindow* window,
  unsigned long event,
  void (*callback)(vtkObject*, unsigned long, void*, void*))
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(callback);
  window->AddObserver(event, command);
}
}

vtkSmartPointer<vtkRenderWindow> ofbbench::NewEGLRenderWindow(int device, std::string& why)
{
  if (TheEGL.Context == EGL_NO_CONTEXT && !(OpenDisplay(device, why) && CreateContext(why)))
  {
    return nullptr;
  }
  MakeCurrent(nullptr, 0, nullptr, nullptr);
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  Observe(window, vtkCommand::WindowMakeCurrentEvent, MakeCurrent);
  Observe(window, vtkCommand::WindowIsCurrentEvent, IsCurrent);
  window->SetSupportsOpenGL(1);
  window->SetIsDirect(1);
  window->SetReadyForRendering(true);
  window->SetSize(64, 64);
  bool failed = false;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&failed);
  onError->SetCallback([](vtkObject*, unsigned long, void* clientData, void*)
    { *static_cast<bool*>(clientData) = true; });
  const unsigned long errors = window->AddObserver(vtkCommand::ErrorEvent, onError);
  window->OpenGLInit();
  window->RemoveObserver(errors);
  if (failed)
  {
    why = "VTK could not load OpenGL on the EGL context";
    return nullptr;
  }
  return window;
}

// GLEW's GLX half, as VTK 9.1 calls it: glxewInit asks glXGetCurrentDisplay (through
// glXGetProcAddressARB), then glXQueryVersion and glXGetClientString. With the EGL
// context current these answer for a GLX 1.4 with no extensions, and the OpenGL
// functions come from EGL; otherwise every call goes on to GLX.
extern "C"
{
  using ofbGLXProc = void (*)();
  void* glXGetCurrentDisplay();
  ofbGLXProc glXGetProcAddressARB(const unsigned char* name);
  ofbGLXProc glXGetProcAddress(const unsigned char* name);
  int glXQueryVersion(void* display, int* major, int* minor);
  const char* glXGetClientString(void* display, int name);

  void* glXGetCurrentDisplay()
  {
    if (EGLIsCurrent())
    {
      return &FakeDisplay;
    }
    static auto next = Next<void* (*)()>("glXGetCurrentDisplay");
    return next ? next() : nullptr;
  }

  ofbGLXProc glXGetProcAddressARB(const unsigned char* name)
  {
    const char* text = reinterpret_cast<const char*>(name);
    if (std::strcmp(text, "glXGetCurrentDisplay") == 0)
    {
      return reinterpret_cast<ofbGLXProc>(&glXGetCurrentDisplay);
    }
    if (EGLIsCurrent() && std::strncmp(text, "glX", 3) != 0)
    {
      return reinterpret_cast<ofbGLXProc>(eglGetProcAddress(text));
    }
    static auto next = Next<ofbGLXProc (*)(const unsigned char*)>("glXGetProcAddressARB");
    return next ? next(name) : nullptr;
  }

  ofbGLXProc glXGetProcAddress(const unsigned char* name)
  {
    return glXGetProcAddressARB(name);
  }

  int glXQueryVersion(void* display, int* major, int* minor)
  {
    if (display == &FakeDisplay)
    {
      *major = 1;
      *minor = 4;
      return 1;
    }
    static auto next = Next<int (*)(void*, int*, int*)>("glXQueryVersion");
    return next ? next(display, major, minor) : 0;
  }

  const char* glXGetClientString(void* display, int name)
  {
    if (display == &FakeDisplay)
    {
      return "";
    }
    static auto next = Next<const char* (*)(void*, int)>("glXGetClientString");
    return next ? next(display, name) : nullptr;
  }
}
