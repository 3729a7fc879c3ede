# OFB.Install.DebianPackage (see CMakeLists.txt): make the Debian package, check
# its fields and contents, unpack it and import its Python package.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPYTHON_DESTINATION=...
#         -DWRAP_PYTHON=ON|OFF -DCPACK=... -DDPKG_DEB=... -DSOVERSION=0.1 -P TestDebianPackage.cmake
include("${CMAKE_CURRENT_LIST_DIR}/InstallTestHelpers.cmake")

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
run(cpack "${CPACK}" -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}")
file(GLOB packages "${WORK_DIR}/vtkofb_*.deb")
list(LENGTH packages count)
if (NOT count EQUAL 1)
  message(FATAL_ERROR "expected one vtkofb_*.deb in ${WORK_DIR}, found: ${packages}")
endif ()

run(info "${DPKG_DEB}" --info "${packages}")
expect("${info_output}" "Package: vtkofb\n" "the package name")
expect("${info_output}" " prerm " "the prerm script that removes Python's byte code")
expect("${info_output}" "Depends:[^\n]*libvtk9\\.1" "a dependency on libvtk9.1")
if (WRAP_PYTHON)
  expect("${info_output}" "Depends:[^\n]*python3-vtk9" "a dependency on python3-vtk9")
endif ()

# Paths under /usr, whatever the build's prefix (GNUInstallDirs may add a
# multiarch directory to lib).
run(contents QUIET "${DPKG_DEB}" --contents "${packages}")
set(lib "\\./usr/lib/([a-z0-9_-]+/)?")
string(REPLACE "." "\\." SOVERSION_REGEX "${SOVERSION}")
foreach (module IN ITEMS Core Paint FlowPaths Export Rendering Interaction TestingImage)
  expect("${contents_output}" " ${lib}libvtkOFB${module}\\.so\\.[0-9.]+\n" "the ${module} library")
  expect("${contents_output}" " ${lib}libvtkOFB${module}\\.so\\.${SOVERSION_REGEX} -> "
    "the ${module} library's soname link")
  expect("${contents_output}" " \\./usr/include/vtkofb/vtkOFB${module}Module\\.h\n"
    "the ${module} export header")
endforeach ()
expect("${contents_output}" " \\./usr/include/vtkofb/vtkOFB\\.h\n" "vtkOFB.h")
foreach (file IN ITEMS vtkofbConfig.cmake vtkofbConfigVersion.cmake vtkOFB-targets.cmake
    vtkOFB-vtk-module-properties.cmake vtkofb-vtk-module-find-packages.cmake)
  string(REPLACE "." "\\." file_regex "${file}")
  expect("${contents_output}" " ${lib}cmake/vtkofb/${file_regex}\n" "CMake file ${file}")
endforeach ()

if (WRAP_PYTHON)
  string(REPLACE "." "\\." python_regex "./usr/${PYTHON_DESTINATION}/vtkofb/")
  expect("${contents_output}" " ${python_regex}__init__\\.py\n" "the package's __init__.py")
  foreach (module IN ITEMS Core Paint FlowPaths Export Rendering Interaction TestingImage)
    expect("${contents_output}" " ${python_regex}vtkOFB${module}[^/\n]*\\.so\n"
      "the wrapped ${module} module")
  endforeach ()

  # The unpacked tree works where it lies: its libraries find each other and VTK
  # through their run paths.
  run(extract "${DPKG_DEB}" -x "${packages}" "${WORK_DIR}/root")
  run_python_example("${WORK_DIR}/root/usr/${PYTHON_DESTINATION}")
endif ()
