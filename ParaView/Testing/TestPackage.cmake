# OFBPlugin.Package: the plugin's Debian package, alone and beside vtkOFB's.
#
# cmake -DCPACK=... -DDPKG_DEB=... -DPVBATCH=... -DPARAVIEW_PYTHON=... -DBUILD_DIR=...
#       -DWORK_DIR=... -DSCRIPT=... -DPLUGIN_SUBDIR=lib/<multiarch>/paraview-5.11/plugins
#       [-DMAIN_BUILD_DIR=... -DMAIN_PYTHON_DESTINATION=... -DPYTHON=...] -P TestPackage.cmake
#
# 1. `cpack -G DEB` in the plugin's build tree writes vtkofb-paraview-plugin_*.deb, which
#    depends on paraview and holds the plugin folder alone.
# 2. Unpacked into a folder, its plugin loads in pvbatch and works (its libraries find
#    each other through $ORIGIN run paths, ParaView's through the system).
# 3. With MAIN_BUILD_DIR (the main project's build), vtkofb_*.deb is made too: the two
#    packages have no file in common (they install together), and unpacked into one
#    folder both Python worlds work from it: `import vtkofb` in Debian's python3
#    (python3-vtk9) and the plugin in ParaView's pvbatch.

function (run name)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  message(STATUS "${name}: ${output}${error}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${name} failed (${result})")
  endif ()
  set("${name}_output" "${output}" PARENT_SCOPE)
endfunction ()

function (expect text regex what)
  if (NOT text MATCHES "${regex}")
    message(FATAL_ERROR "expected ${what} (${regex})")
  endif ()
  message(STATUS "ok: ${what}")
endfunction ()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/root")
run(cpack "${CPACK}" -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}")
file(GLOB plugin_deb "${WORK_DIR}/vtkofb-paraview-plugin_*.deb")
list(LENGTH plugin_deb count)
if (NOT count EQUAL 1)
  message(FATAL_ERROR "expected one vtkofb-paraview-plugin_*.deb, found: ${plugin_deb}")
endif ()
run(info "${DPKG_DEB}" --info "${plugin_deb}")
expect("${info_output}" "Package: vtkofb-paraview-plugin\n" "the plugin package's name")
expect("${info_output}" "Depends: paraview \\(>= [0-9.]+\\), paraview \\(<< [0-9.]+\\)\n"
  "a dependency on Debian's paraview alone")
run(contents "${DPKG_DEB}" --contents "${plugin_deb}")
string(REPLACE "." "\\." subdir_regex "${PLUGIN_SUBDIR}")
expect("${contents_output}" " \\./usr/${subdir_regex}/OFB/OFB\\.so\n" "the plugin")
foreach (module IN ITEMS Core Paint FlowPaths Export Rendering ParaView)
  expect("${contents_output}" " \\./usr/${subdir_regex}/OFB/libvtkOFB${module}\\.so"
    "the ${module} module beside it")
endforeach ()
if (contents_output MATCHES "/include/|/cmake/|dist-packages")
  message(FATAL_ERROR "the plugin package holds headers, CMake or Python files")
endif ()
run(extract "${DPKG_DEB}" -x "${plugin_deb}" "${WORK_DIR}/root")
set(plugin "${WORK_DIR}/root/usr/${PLUGIN_SUBDIR}/OFB/OFB.so")
run(pvbatch "${CMAKE_COMMAND}" -E env "PYTHONPATH=${PARAVIEW_PYTHON}"
  "${PVBATCH}" --force-offscreen-rendering "${SCRIPT}" "${plugin}")
expect("${pvbatch_output}" "the installed OFB plugin works" "the unpacked plugin loads and works")

if (NOT MAIN_BUILD_DIR)
  return ()
endif ()
run(main_cpack "${CPACK}" -G DEB --config "${MAIN_BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}")
file(GLOB main_deb "${WORK_DIR}/vtkofb_*.deb")
run(main_contents "${DPKG_DEB}" --contents "${main_deb}")
# Files (not folders) of each package: none in common.
foreach (which IN ITEMS contents main_contents)
  string(REGEX MATCHALL " \\./[^\n]*[^/\n]\n" files "${${which}_output}")
  set("${which}_files" ${files})
endforeach ()
set(common ${contents_files})
list(REMOVE_ITEM common ${main_contents_files})
list(LENGTH contents_files plugin_count)
list(LENGTH common left)
if (NOT left EQUAL plugin_count)
  message(FATAL_ERROR "the two packages share files")
endif ()
message(STATUS "ok: vtkofb and vtkofb-paraview-plugin share no file")
run(main_extract "${DPKG_DEB}" -x "${main_deb}" "${WORK_DIR}/root")
# Debian's python3 with nothing but PATH and PYTHONPATH: Examples/Build/ofbInstalled.py
# imports vtkofb from the folder (the VTK world: python3-vtk9's vtkmodules).
run(vtk_python env -i PATH=/usr/bin:/bin
  "PYTHONPATH=${WORK_DIR}/root/usr/${MAIN_PYTHON_DESTINATION}"
  "${PYTHON}" -B "${SOURCE_DIR}/Examples/Build/ofbInstalled.py")
file(REAL_PATH "${WORK_DIR}/root/usr/${MAIN_PYTHON_DESTINATION}/vtkofb" package_dir)
string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" package_regex "${package_dir}")
expect("${vtk_python_output}" "from ${package_regex}\n"
  "import vtkofb in Debian's python3 from the same folder")
expect("${vtk_python_output}" "[1-9][0-9]* samples" "vtkofb samples a surface")
run(pvbatch_again "${CMAKE_COMMAND}" -E env "PYTHONPATH=${PARAVIEW_PYTHON}"
  "${PVBATCH}" --force-offscreen-rendering "${SCRIPT}" "${plugin}")
expect("${pvbatch_again_output}" "the installed OFB plugin works"
  "the plugin in ParaView's Python from the same folder")
