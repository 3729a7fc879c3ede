#include "vtkOFBImageBackend.h"

#include <dlfcn.h>

#include <mutex>

namespace
{
/// The directory of the library holding this function ("" when unknown).
std::string ThisLibraryDirectory()
{
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&vtkOFBLoadImageBackend), &info) == 0 || !info.dli_fname)
  {
    return std::string();
  }
  const std::string path = info.dli_fname;
  const std::string::size_type slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}
}

const vtkOFBImageBackendAPI* vtkOFBLoadImageBackend(std::string& error)
{
  static std::once_flag once;
  static const vtkOFBImageBackendAPI* api = nullptr;
  static std::string problem;
  std::call_once(once,
    []()
    {
      // Beside this library (the build tree's lib/, the install's libdir), else wherever
      // the dynamic loader finds it.
      const std::string name = "libvtkOFBIOImageOpenImageIO.so";
      const std::string beside = ThisLibraryDirectory() + name;
      void* module = dlopen(beside.c_str(), RTLD_NOW | RTLD_LOCAL);
      std::string why = module ? std::string() : std::string(dlerror());
      if (!module)
      {
        module = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
      }
      if (!module)
      {
        problem = "cannot load OpenImageIO's module '" + beside + "' (" + why + ")";
        return;
      }
      using Get = const vtkOFBImageBackendAPI* (*)();
      auto get = reinterpret_cast<Get>(dlsym(module, "vtkOFBImageBackendGet"));
      api = get ? get() : nullptr;
      if (!api || api->Version != 1)
      {
        api = nullptr;
        problem = "'" + beside + "' is not vtkOFB's OpenImageIO module of this version";
      }
    });
  error = problem;
  return api;
}
