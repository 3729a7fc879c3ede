# Where an installed vtkOFB puts its Python package, and how its installed
# libraries and Python modules find each other and VTK without environment
# variables. Included by the top-level CMakeLists.txt after VTK is found (the
# Python version comes from VTK's Python component) and before the modules are
# built and wrapped, since both read the settings made here.
#
# VTKOFB_PYTHON_DESTINATION (relative to the prefix; the build tree uses the same
# layout) defaults to where Debian's /usr/bin/python3 looks for modules of that
# prefix:
#   /usr         lib/python3/dist-packages       Debian's directory for packaged
#                                                modules (python3-vtk9's vtkmodules)
#   /usr/local   lib/python3.X/dist-packages     on Debian's default sys.path
#   other        lib/python3.X/dist-packages     put it on PYTHONPATH
# Debian's python3 does not search /usr/local/lib/python3/dist-packages.

if (NOT DEFINED VTKOFB_PYTHON_DESTINATION)
  if (CMAKE_INSTALL_PREFIX MATCHES "^/usr/?$")
    set(VTKOFB_PYTHON_DESTINATION "lib/python3/dist-packages")
  else ()
    if (NOT DEFINED Python3_VERSION_MINOR)
      find_package(Python3 QUIET COMPONENTS Interpreter)
    endif ()
    if (DEFINED Python3_VERSION_MINOR)
      set(VTKOFB_PYTHON_DESTINATION
        "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages")
    else ()
      set(VTKOFB_PYTHON_DESTINATION "lib/python3/dist-packages")
    endif ()
  endif ()
endif ()

# Installed libraries find each other next to themselves ($ORIGIN), and any
# library they link from outside the system directories (a VTK of another prefix)
# where it was at build time. The Python modules get their own $ORIGIN-relative
# path to the libraries from vtk_module_wrap_python(LIBRARY_DESTINATION).
list(APPEND CMAKE_INSTALL_RPATH "$ORIGIN")
set(CMAKE_INSTALL_RPATH_USE_LINK_PATH ON)
