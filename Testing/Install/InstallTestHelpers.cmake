# Helpers of TestDownstream.cmake and TestDebianPackage.cmake (cmake -P scripts).

# run(<name> [QUIET] <command>...): runs the command, prints its output (with
# QUIET, only when it fails) and stops the test with an error when it fails. The
# output is left in <name>_output.
function (run name)
  set(command ${ARGN})
  set(quiet OFF)
  if (ARGV1 STREQUAL "QUIET")
    set(quiet ON)
    list(REMOVE_AT command 0)
  endif ()
  execute_process(
    COMMAND         ${command}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE output
    ERROR_VARIABLE  output)
  if (NOT quiet OR NOT result EQUAL 0)
    message(STATUS "${name}:\n${output}")
  endif ()
  if (NOT result EQUAL 0)
    string(REPLACE ";" " " command "${command}")
    message(FATAL_ERROR "${name} failed (${result}): ${command}")
  endif ()
  set("${name}_output" "${output}" PARENT_SCOPE)
endfunction ()

# expect(<text> <regex> <what>): fails unless the text matches the regular expression.
function (expect text regex what)
  if (NOT text MATCHES "${regex}")
    message(FATAL_ERROR "expected ${what} (/${regex}/)")
  endif ()
endfunction ()

# run_python_example(<python dir>): Examples/Build/ofbInstalled.py with Debian's
# python3 and nothing in its environment but PATH and PYTHONPATH=<python dir>, so
# the package must find its libraries and VTK's without LD_LIBRARY_PATH. It must
# report the package in <python dir>.
function (run_python_example python_dir)
  run(python_example env -i PATH=/usr/bin:/bin "PYTHONPATH=${python_dir}"
    /usr/bin/python3 -B "${SOURCE_DIR}/Examples/Build/ofbInstalled.py")
  file(REAL_PATH "${python_dir}/vtkofb" package_dir)
  string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" package_regex "${package_dir}")
  expect("${python_example_output}" "from ${package_regex}\n" "vtkofb from ${package_dir}")
  expect("${python_example_output}" "[1-9][0-9]* samples" "a sample count")
  expect("${python_example_output}" "paint written to and read back from a PNG [(]png[)]"
    "an image round trip through the installed OpenImageIO module")
endfunction ()
