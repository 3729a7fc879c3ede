# OFB.Install.Downstream (see CMakeLists.txt): install, then use the install as a
# downstream project would, from C++ and from Python.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPYTHON_DESTINATION=...
#         -DWRAP_PYTHON=ON|OFF -DGENERATOR=... [-DCXX_COMPILER=... -DC_COMPILER=...
#         -DCOMPILER_LAUNCHER=...] -P TestDownstream.cmake
include("${CMAKE_CURRENT_LIST_DIR}/InstallTestHelpers.cmake")

set(prefix "${WORK_DIR}/prefix")
set(example "${WORK_DIR}/example")
file(REMOVE_RECURSE "${prefix}" "${example}" "${WORK_DIR}/sphere.ofb")
file(MAKE_DIRECTORY "${WORK_DIR}")

run(install QUIET "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach (file IN ITEMS
    lib/cmake/vtkofb/vtkofbConfig.cmake
    lib/cmake/vtkofb/vtkofbConfigVersion.cmake
    include/vtkofb/vtkOFB.h
    include/vtkofb/vtkOFBRenderingModule.h)
  if (NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif ()
endforeach ()
# Private headers stay out of the prefix, so that the example's subclasses
# (ofbSubclass) fail to compile if an installed header needs one.
foreach (file IN ITEMS
    vtkOFBLICCache.h
    vtkOFBLICInternals.h
    vtkOFBLICTracer.h
    vtkOFBModifiedRanges.h
    vtkOFBPainterInternals.h
    vtkOFBShaderStorage.h)
  if (EXISTS "${prefix}/include/vtkofb/${file}")
    message(FATAL_ERROR "private header installed: ${file}")
  endif ()
endforeach ()

# The example finds this prefix only: no package registry, no build tree.
set(configure_args
  -S "${SOURCE_DIR}/Examples/Build" -B "${example}" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=Release
  "-DCMAKE_PREFIX_PATH=${prefix}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
  -DOFB_EXAMPLE_HEADER_TEST=ON)
foreach (setting IN ITEMS CXX_COMPILER C_COMPILER)
  if (${setting})
    list(APPEND configure_args "-DCMAKE_${setting}=${${setting}}")
  endif ()
endforeach ()
if (COMPILER_LAUNCHER)
  list(APPEND configure_args
    "-DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER}"
    "-DCMAKE_C_COMPILER_LAUNCHER=${COMPILER_LAUNCHER}")
endif ()
run(configure "${CMAKE_COMMAND}" ${configure_args})
file(STRINGS "${example}/CMakeCache.txt" found_dir REGEX "^vtkofb_DIR:")
expect("${found_dir}" "=${prefix}/lib/cmake/vtkofb$" "vtkofb_DIR in the prefix")
run(build "${CMAKE_COMMAND}" --build "${example}" --parallel 2)

# The example compiled against the prefix's headers, never the source or build tree's
# (the prefix and the example lie under the build tree: they are allowed).
file(READ "${example}/compile_commands.json" compile_commands)
string(REGEX MATCHALL "-(I|isystem) *[^ \"]+" includes "${compile_commands}")
set(prefix_included OFF)
foreach (include IN LISTS includes)
  string(REGEX REPLACE "^-(I|isystem) *" "" dir "${include}")
  string(FIND "${dir}" "${prefix}/" in_prefix)
  string(FIND "${dir}" "${example}" in_example)
  string(FIND "${dir}" "${SOURCE_DIR}" in_source)
  string(FIND "${dir}" "${BUILD_DIR}" in_build)
  if (dir STREQUAL "${prefix}/include/vtkofb")
    set(prefix_included ON)
  endif ()
  if (NOT in_prefix EQUAL 0 AND NOT in_example EQUAL 0 AND (in_source EQUAL 0 OR in_build EQUAL 0))
    message(FATAL_ERROR "the example includes from the source or build tree: ${dir}")
  endif ()
endforeach ()
if (NOT prefix_included)
  message(FATAL_ERROR "the example does not include ${prefix}/include/vtkofb")
endif ()

# No display and no library path: the program links the installed libraries.
run(cxx_example env -i PATH=/usr/bin:/bin "${example}/ofbInstalled" "${WORK_DIR}/sphere.ofb")
expect("${cxx_example_output}" "[1-9][0-9]* samples" "a sample count")
expect("${cxx_example_output}" "render window class vtk[A-Za-z]*OpenGLRenderWindow"
  "an OpenGL render window")
expect("${cxx_example_output}" "interactor style vtkInteractorStyleSwitch;"
  "the interactor style of InteractionStyle's factory")
expect("${cxx_example_output}" "image comparison passed \\(correlation 1\\)"
  "the image comparison of OFB::TestingImage")

# Subclasses of the algorithms, compiled against the installed headers alone.
run(cxx_subclass env -i PATH=/usr/bin:/bin "${example}/ofbSubclass")
expect("${cxx_subclass_output}" "[1-9][0-9]* samples sampled and convolved by subclasses"
  "the subclasses' run")

# The installed libraries find each other through $ORIGIN.
find_program(READELF readelf)
if (READELF)
  file(GLOB libraries "${prefix}/lib/libvtkOFB*.so.*")
  foreach (library IN LISTS libraries)
    run(readelf QUIET "${READELF}" -d "${library}")
    expect("${readelf_output}" "R(UN)?PATH[^\n]*\\$ORIGIN" "an $ORIGIN run path in ${library}")
    message(STATUS "${library}: run path $ORIGIN")
  endforeach ()
endif ()

if (WRAP_PYTHON)
  run_python_example("${prefix}/${PYTHON_DESTINATION}")
endif ()
