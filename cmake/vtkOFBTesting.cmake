# CMake helpers of vtkOFB's tests, benchmarks and examples. Each CMakeLists.txt that
# uses them includes this file by path (once per directory).
include_guard(DIRECTORY)

get_filename_component(_vtkofb_root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

#[==[
vtkofb_use_test_data(<target>...)

Gives each target the bundled meshes and the shared C++ test helpers: the macro
VTKOFB_DATA_DIR ("<source>/Testing/Data", without a trailing slash) and the include
directory Testing/Cxx (vtkOFBTestUtilities.h, vtkOFBReadMesh.h).
#]==]
function (vtkofb_use_test_data)
  foreach (target IN LISTS ARGN)
    target_compile_definitions("${target}" PRIVATE
      "VTKOFB_DATA_DIR=\"${_vtkofb_root}/Testing/Data\"")
    target_include_directories("${target}" PRIVATE "${_vtkofb_root}/Testing/Cxx")
  endforeach ()
endfunction ()

#[==[
vtkofb_mark_display_tests(<test>...)

Tests that open a window (render windows, offscreen ones included) share the one X
display of `xvfb-run`; run concurrently under `ctest -j N` they can lose the server
connection. This gives them a common RESOURCE_LOCK, so that ctest runs at most one
of them at a time (the other tests still run beside it), and the label `display`
(`ctest -L display` runs only them).
#]==]
function (vtkofb_mark_display_tests)
  if (NOT ARGN)
    return ()
  endif ()
  set_property(TEST ${ARGN} APPEND PROPERTY RESOURCE_LOCK vtkofb_display)
  set_property(TEST ${ARGN} APPEND PROPERTY LABELS display)
endfunction ()

#[==[
vtkofb_add_gtests(<executable>
  PREFIX <test name prefix>
  [DISPLAY]
  [TIMEOUT <seconds>]
  SOURCES <file>...)

A GoogleTest executable of the module whose Testing/Cxx/CMakeLists.txt calls it. It
links the module and the module's TEST_DEPENDS (as vtk_module_test_executable does for
VTK's own tests, object factories included), GoogleTest with its main, and the test
data (vtkofb_use_test_data). Its tests are discovered after the build
(gtest_discover_tests) and named <prefix><Suite>.<Test>. DISPLAY: the tests open
windows (see vtkofb_mark_display_tests). TIMEOUT: per test, default 300 s.
#]==]
function (vtkofb_add_gtests name)
  cmake_parse_arguments(PARSE_ARGV 1 _vtkofb_gtests "DISPLAY" "PREFIX;TIMEOUT" "SOURCES")
  if (NOT _vtkofb_gtests_TIMEOUT)
    set(_vtkofb_gtests_TIMEOUT 300)
  endif ()
  vtk_module_test_executable("${name}" ${_vtkofb_gtests_SOURCES})
  target_link_libraries("${name}" PRIVATE GTest::gtest GTest::gtest_main)
  vtkofb_use_test_data("${name}")
  set(properties TIMEOUT "${_vtkofb_gtests_TIMEOUT}")
  if (_vtkofb_gtests_DISPLAY)
    list(APPEND properties RESOURCE_LOCK vtkofb_display LABELS display)
  endif ()
  gtest_discover_tests("${name}"
    TEST_PREFIX       "${_vtkofb_gtests_PREFIX}"
    DISCOVERY_TIMEOUT 60
    PROPERTIES        ${properties})
endfunction ()
