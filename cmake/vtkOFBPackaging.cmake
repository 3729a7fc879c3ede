# vtkOFB outside its build tree: the CMake package that `find_package(vtkofb)`
# reads, the tests that use the installed package from a downstream project, and
# the Debian package (`cpack -G DEB` in the build tree). Included by the top-level
# CMakeLists.txt once the modules are built and wrapped.
#
# The package configuration follows VTK's own: the modules' targets and module
# properties written by vtk_module_build (and vtk_module_wrap_python), the
# external packages the modules declared with vtk_module_find_package exported by
# vtk_module_export_find_packages, VTK found with the modules they link, and a
# version file. It is written for the build tree too, so that a downstream
# project can also use a build with `-Dvtkofb_DIR=<build>/lib/cmake/vtkofb`.

include(CMakePackageConfigHelpers)

# As vtk_module_build's and vtk_module_wrap_python's CMAKE_DESTINATION.
set(vtkofb_cmake_destination "${CMAKE_INSTALL_LIBDIR}/cmake/vtkofb")
# The files vtk_module_build (PACKAGE ${CMAKE_PROJECT_NAME}) and
# vtk_module_wrap_python (PYTHON_PACKAGE vtkofb) write there.
set(vtkofb_targets_file "${CMAKE_PROJECT_NAME}-targets.cmake")
set(vtkofb_properties_file "${CMAKE_PROJECT_NAME}-vtk-module-properties.cmake")
set(vtkofb_python_properties_file "vtkofb-vtk-python-module-properties.cmake")
set(vtkofb_python_targets_file "vtkofb-python-targets.cmake")
set(vtkofb_find_packages_file "vtkofb-vtk-module-find-packages.cmake")

vtk_module_export_find_packages(
  CMAKE_DESTINATION "${vtkofb_cmake_destination}"
  FILE_NAME         "${vtkofb_find_packages_file}"
  MODULES           ${vtkofb_modules})

# The wrapped modules' targets (Python extension modules and vtkOFB::Python), as
# VTK exports its VTKPython set.
if (VTKOFB_WRAP_PYTHON)
  export(
    EXPORT    vtkOFBPython
    NAMESPACE vtkOFB::
    FILE      "${PROJECT_BINARY_DIR}/${vtkofb_cmake_destination}/${vtkofb_python_targets_file}")
  install(
    EXPORT      vtkOFBPython
    NAMESPACE   vtkOFB::
    FILE        "${vtkofb_python_targets_file}"
    DESTINATION "${vtkofb_cmake_destination}"
    COMPONENT   development)
endif ()

# The components (module names without the namespace) and every VTK module that
# they link, publicly or privately: the configuration finds VTK with those.
set(vtkofb_export_components)
set(vtkofb_export_vtk_components)
foreach (vtkofb_module IN LISTS vtkofb_modules)
  string(REGEX REPLACE "^OFB::" "" vtkofb_component "${vtkofb_module}")
  list(APPEND vtkofb_export_components "${vtkofb_component}")
  foreach (vtkofb_property IN ITEMS depends private_depends optional_depends)
    get_property(vtkofb_depends GLOBAL PROPERTY "_vtk_module_${vtkofb_module}_${vtkofb_property}")
    foreach (vtkofb_depend IN LISTS vtkofb_depends)
      if (vtkofb_depend MATCHES "^VTK::(.*)$" AND TARGET "${vtkofb_depend}")
        list(APPEND vtkofb_export_vtk_components "${CMAKE_MATCH_1}")
      endif ()
    endforeach ()
  endforeach ()
endforeach ()
list(REMOVE_DUPLICATES vtkofb_export_vtk_components)
list(SORT vtkofb_export_vtk_components)

# Install tree and build tree configurations; the prefix is computed from the
# file's location, so an installed tree (or an unpacked .deb) can be moved.
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/vtkofbConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/CMakeFiles/vtkofbConfig.cmake.install"
  INSTALL_DESTINATION "${vtkofb_cmake_destination}")
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/vtkofbConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/${vtkofb_cmake_destination}/vtkofbConfig.cmake"
  INSTALL_DESTINATION "${vtkofb_cmake_destination}"
  INSTALL_PREFIX "${PROJECT_BINARY_DIR}")
# 0.x: a new minor version may change the API.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/${vtkofb_cmake_destination}/vtkofbConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(
  FILES       "${PROJECT_BINARY_DIR}/CMakeFiles/vtkofbConfig.cmake.install"
  DESTINATION "${vtkofb_cmake_destination}"
  RENAME      "vtkofbConfig.cmake"
  COMPONENT   development)
install(
  FILES       "${PROJECT_BINARY_DIR}/${vtkofb_cmake_destination}/vtkofbConfigVersion.cmake"
  DESTINATION "${vtkofb_cmake_destination}"
  COMPONENT   development)

# The Debian package: everything `cmake --install` installs, in one package that
# depends on Debian's VTK packages. `cpack -G DEB` in the build tree writes
# vtkofb_<version>_<arch>.deb; its prefix is /usr (CPack's default for DEB).
set(CPACK_PACKAGE_NAME "vtkofb")
set(CPACK_PACKAGE_VENDOR "vtkOFB")
set(CPACK_PACKAGE_CONTACT "vtkOFB maintainers <vtkofb@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Orthogonal Fragment Buffers for VTK: sample-based surface colouring")
set(CPACK_PACKAGE_DESCRIPTION
  "VTK 9.1 modules OFB::Core, OFB::Paint, OFB::FlowPaths, OFB::Export,
OFB::Rendering, OFB::Interaction and OFB::TestingImage (libraries, headers and the CMake
package found with find_package(vtkofb)) and the vtkofb
Python package for Debian's python3-vtk9.")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
if (EXISTS "${PROJECT_SOURCE_DIR}/LICENSE")
  set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
endif ()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
# Debian's VTK, at the version built against. dpkg-shlibdeps (dpkg-dev), where
# present, names every library the binaries link (libvtk9.1, libc6, libstdc++6,
# ...) with its exact version; without it, libvtk9.1 is named here.
find_program(VTKOFB_DPKG_SHLIBDEPS dpkg-shlibdeps)
mark_as_advanced(VTKOFB_DPKG_SHLIBDEPS)
set(vtkofb_deb_depends)
if (VTKOFB_DPKG_SHLIBDEPS)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
else ()
  list(APPEND vtkofb_deb_depends "libvtk9.1 (>= ${VTK_MAJOR_VERSION}.${VTK_MINOR_VERSION})")
endif ()
if (VTKOFB_WRAP_PYTHON)
  # The extension modules are built for this Python's ABI.
  math(EXPR vtkofb_python_next_minor "${Python3_VERSION_MINOR} + 1")
  list(APPEND vtkofb_deb_depends
    "python3-vtk9 (>= ${VTK_MAJOR_VERSION}.${VTK_MINOR_VERSION})"
    "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}~)"
    "python3 (<< ${Python3_VERSION_MAJOR}.${vtkofb_python_next_minor})")
endif ()
string(REPLACE ";" ", " CPACK_DEBIAN_PACKAGE_DEPENDS "${vtkofb_deb_depends}")
# find_package(vtkofb) needs VTK's CMake package and headers.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libvtk9-dev (>= ${VTK_MAJOR_VERSION}.${VTK_MINOR_VERSION})")
# A shlibs file and the ldconfig trigger for the libraries. (CPack warns that the
# Python extension modules have no soname: they are not libraries to link.)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
if (VTKOFB_WRAP_PYTHON)
  # Removal also removes the byte code Python wrote into the package's directory.
  if (NOT DEFINED CPACK_PACKAGING_INSTALL_PREFIX)
    set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
  endif ()
  configure_file("${CMAKE_CURRENT_LIST_DIR}/vtkofb-prerm.in"
    "${PROJECT_BINARY_DIR}/CMakeFiles/deb/prerm" @ONLY)
  set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA "${PROJECT_BINARY_DIR}/CMakeFiles/deb/prerm")
  set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
endif ()
if (NOT DEFINED CPACK_GENERATOR)
  set(CPACK_GENERATOR "DEB")
endif ()
include(CPack)

if (VTKOFB_BUILD_TESTING)
  add_subdirectory("${PROJECT_SOURCE_DIR}/Testing/Install" "${PROJECT_BINARY_DIR}/Testing/Install")
endif ()
