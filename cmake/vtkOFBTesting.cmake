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
vtkofb_mark_display_tests(
  [EXECUTABLES <target>...]
  [TESTS <test>...]
  [DIRECTORY])

For tests that open windows (render windows, offscreen ones included). They share the
one X display of `xvfb-run`, which fails two ways under `ctest -j N` and even serially:
an X server resets when its last client disconnects, and a window opened during the
reset cannot connect ("bad X server connection").

- EXECUTABLES: the test programs keep a connection to the display open for their whole
  run (Testing/Cxx/vtkOFBKeepDisplayOpen.cxx is linked in), so that a test that closes a
  window and opens another never meets a reset.
- TESTS, DIRECTORY (every test added so far in the calling directory): the tests get a
  common RESOURCE_LOCK, so that ctest runs at most one of them at a time (the other
  tests still run beside it), and the label `display` (`ctest -L display` runs them).

vtkofb_add_gtests(... DISPLAY ...) does both for GoogleTest executables.
#]==]
function (vtkofb_mark_display_tests)
  cmake_parse_arguments(PARSE_ARGV 0 _vtkofb_display "DIRECTORY" "" "EXECUTABLES;TESTS")
  if (_vtkofb_display_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "vtkofb_mark_display_tests: unknown arguments "
      "'${_vtkofb_display_UNPARSED_ARGUMENTS}' (use EXECUTABLES, TESTS or DIRECTORY)")
  endif ()
  if (NOT TARGET X11::X11)
    find_package(X11 QUIET)
  endif ()
  foreach (target IN LISTS _vtkofb_display_EXECUTABLES)
    if (TARGET X11::X11)
      target_sources("${target}" PRIVATE "${_vtkofb_root}/Testing/Cxx/vtkOFBKeepDisplayOpen.cxx")
      target_link_libraries("${target}" PRIVATE X11::X11)
    endif ()
  endforeach ()
  set(tests ${_vtkofb_display_TESTS})
  if (_vtkofb_display_DIRECTORY)
    get_property(directory_tests DIRECTORY PROPERTY TESTS)
    list(APPEND tests ${directory_tests})
  endif ()
  if (tests)
    set_property(TEST ${tests} APPEND PROPERTY RESOURCE_LOCK vtkofb_display)
    set_property(TEST ${tests} APPEND PROPERTY LABELS display)
  endif ()
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
    vtkofb_mark_display_tests(EXECUTABLES "${name}")
    list(APPEND properties RESOURCE_LOCK vtkofb_display LABELS display)
  endif ()
  gtest_discover_tests("${name}"
    TEST_PREFIX       "${_vtkofb_gtests_PREFIX}"
    DISCOVERY_TIMEOUT 60
    PROPERTIES        ${properties})
endfunction ()
