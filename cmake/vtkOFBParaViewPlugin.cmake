# The ParaView plugin (ParaView/, a CMake project of its own) built beside the modules
# when ParaView's development files are found. Included by the top-level CMakeLists.txt.
#
# ParaView's CMake package brings the targets of ParaView's VTK (9.2 in Debian), which
# cannot share a project with the VTK this build uses (VTK::CommonCore would be defined
# twice), so the plugin is an external project: configured and built in
# <build>/ParaView by the same `cmake --build`, its tests run by this project's ctest
# (OFB.ParaView.*). The main build never loads ParaView's package: without ParaView,
# nothing of this is done and nothing is needed.
#
# VTKOFB_BUILD_PARAVIEW_PLUGIN: AUTO (default: when found), ON (an error when not
# found) or OFF. VTKOFB_PARAVIEW_DIR: ParaView's CMake package folder; found, in order:
# - <build>/paraview-sdk/usr/lib/<multiarch>/cmake/paraview-5.11, the prefix that
#   scripts/paraview-sdk.sh makes with python3-paraview unpacked (Debian's paraview-dev
#   package names python3-paraview's files, which cannot be installed beside
#   python3-vtk9);
# - /usr/lib/<multiarch>/cmake/paraview-5.11 when python3-paraview is installed.

set(VTKOFB_BUILD_PARAVIEW_PLUGIN "AUTO" CACHE STRING
  "Build the ParaView plugin (ParaView/): AUTO (when ParaView 5.11 is found), ON or OFF")
set_property(CACHE VTKOFB_BUILD_PARAVIEW_PLUGIN PROPERTY STRINGS AUTO ON OFF)

if (VTKOFB_BUILD_PARAVIEW_PLUGIN STREQUAL "OFF")
  return ()
endif ()

if (NOT VTKOFB_PARAVIEW_DIR)
  set(vtkofb_paraview_candidates)
  if (CMAKE_LIBRARY_ARCHITECTURE)
    list(APPEND vtkofb_paraview_candidates
      "${PROJECT_BINARY_DIR}/paraview-sdk/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11"
      "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11")
  endif ()
  foreach (vtkofb_paraview_candidate IN LISTS vtkofb_paraview_candidates)
    # The package is usable with ParaView's Python modules beside it.
    get_filename_component(vtkofb_paraview_python
      "${vtkofb_paraview_candidate}/../../../python3/dist-packages/paraview/simple.py" ABSOLUTE)
    if (EXISTS "${vtkofb_paraview_candidate}/paraview-config.cmake" AND
        EXISTS "${vtkofb_paraview_python}")
      set(VTKOFB_PARAVIEW_DIR "${vtkofb_paraview_candidate}")
      break ()
    endif ()
  endforeach ()
endif ()

if (NOT VTKOFB_PARAVIEW_DIR)
  set(vtkofb_paraview_why
    "ParaView 5.11 not found: install paraview-dev and run scripts/paraview-sdk.sh ${PROJECT_BINARY_DIR} (scripts/test.sh does both)")
  if (VTKOFB_BUILD_PARAVIEW_PLUGIN STREQUAL "ON")
    message(FATAL_ERROR "VTKOFB_BUILD_PARAVIEW_PLUGIN is ON but ${vtkofb_paraview_why}")
  endif ()
  message(STATUS "ParaView plugin: off (${vtkofb_paraview_why})")
  return ()
endif ()
message(STATUS "ParaView plugin: on, with ${VTKOFB_PARAVIEW_DIR}")

include(ExternalProject)
set(vtkofb_paraview_build "${PROJECT_BINARY_DIR}/ParaView")
set(vtkofb_paraview_args
  "-DParaView_DIR=${VTKOFB_PARAVIEW_DIR}"
  "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}"
  "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
  "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
  "-DCMAKE_INSTALL_PREFIX=${CMAKE_INSTALL_PREFIX}"
  "-DBUILD_TESTING=${VTKOFB_BUILD_TESTING}"
  # For the package test: vtkOFB's package beside the plugin's.
  "-DVTKOFB_MAIN_BINARY_DIR=${PROJECT_BINARY_DIR}"
  "-DVTKOFB_MAIN_PYTHON_DESTINATION=${VTKOFB_PYTHON_DESTINATION}")
foreach (vtkofb_var IN ITEMS CMAKE_C_COMPILER_LAUNCHER CMAKE_CXX_COMPILER_LAUNCHER)
  if (${vtkofb_var})
    list(APPEND vtkofb_paraview_args "-D${vtkofb_var}=${${vtkofb_var}}")
  endif ()
endforeach ()
ExternalProject_Add(vtkofb-paraview-plugin
  SOURCE_DIR       "${PROJECT_SOURCE_DIR}/ParaView"
  BINARY_DIR       "${vtkofb_paraview_build}"
  CMAKE_ARGS       ${vtkofb_paraview_args}
  # Its own sources and the modules' are outside ExternalProject's view: always build
  # (an up-to-date build is a quick make pass).
  BUILD_ALWAYS     ON
  INSTALL_COMMAND  ""
  TEST_COMMAND     ""
  # Its output goes to the console as it builds (make's jobserver is shared).
  USES_TERMINAL_BUILD ON)

# The plugin's tests, run from this project's ctest.
if (VTKOFB_BUILD_TESTING)
  set(vtkofb_paraview_tests Filters StateAndTrace VersionCheck Example Package
    SurfaceRepresentation SurfaceRepresentationExample LICBenchmark)
  # pvpython through scripts/paraview-sdk.sh's wrapper, where ParaView is its prefix.
  if (EXISTS "${VTKOFB_PARAVIEW_DIR}/../../../../../bin/pvpython")
    list(APPEND vtkofb_paraview_tests PvPython)
  endif ()
  foreach (vtkofb_test IN LISTS vtkofb_paraview_tests)
    add_test(
      NAME    "OFB.ParaView.${vtkofb_test}"
      COMMAND "${CMAKE_CTEST_COMMAND}" --test-dir "${vtkofb_paraview_build}"
        -R "^OFBPlugin\\.${vtkofb_test}$" --output-on-failure --no-tests=error)
    set_tests_properties("OFB.ParaView.${vtkofb_test}" PROPERTIES
      LABELS  "ParaView"
      TIMEOUT 900)
  endforeach ()
  # The distributed tests (1, 2 and 3 processes under mpiexec; WriterFaults: the writer
  # killed under MPI and given OFBs on different frames, no display) and the client tests
  # (a pvserver of 1 and 2 processes with a pvpython client, and the paraview GUI): one
  # test here each, as their runs compare with the one-process or pvbatch runs.
  find_package(MPI QUIET COMPONENTS C)
  if (MPIEXEC_EXECUTABLE)
    foreach (vtkofb_test IN ITEMS Distributed SurfaceDistributed DistributedStrokes
        WriterDistributed WriterFaults Clients)
      add_test(
        NAME    "OFB.ParaView.${vtkofb_test}"
        COMMAND "${CMAKE_CTEST_COMMAND}" --test-dir "${vtkofb_paraview_build}"
          -R "^OFBPlugin\\.${vtkofb_test}\\." --output-on-failure --no-tests=error)
      set_tests_properties("OFB.ParaView.${vtkofb_test}" PROPERTIES
        LABELS  "ParaView;MPI"
        PROCESSORS 2
        TIMEOUT 900)
    endforeach ()
    set_tests_properties("OFB.ParaView.Clients" PROPERTIES TIMEOUT 1200)
  endif ()
  # The tests that render share xvfb-run's display with the other display tests
  # (docs/testing.md, "Tests that open windows"); their scripts keep a connection open.
  set(vtkofb_paraview_render_tests OFB.ParaView.Filters OFB.ParaView.StateAndTrace
    OFB.ParaView.Example OFB.ParaView.SurfaceRepresentation
    OFB.ParaView.SurfaceRepresentationExample
    OFB.ParaView.LICBenchmark)
  foreach (vtkofb_test IN ITEMS Distributed SurfaceDistributed DistributedStrokes WriterDistributed
      Clients)
    if (TEST OFB.ParaView.${vtkofb_test})
      list(APPEND vtkofb_paraview_render_tests OFB.ParaView.${vtkofb_test})
    endif ()
  endforeach ()
  set_property(TEST ${vtkofb_paraview_render_tests} APPEND PROPERTY
    RESOURCE_LOCK vtkofb_display)
  set_property(TEST ${vtkofb_paraview_render_tests} APPEND PROPERTY
    LABELS display)
  set_tests_properties(OFB.ParaView.Package PROPERTIES
    RESOURCE_LOCK "vtkofb-install"
    RUN_SERIAL    TRUE)
endif ()
