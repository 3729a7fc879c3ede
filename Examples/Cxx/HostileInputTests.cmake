# Reliability under hostile input: every application, given a broken, huge or malicious
# image, mesh or stroke file, or asked to write where it cannot, exits non-zero with a
# message saying what is wrong, in bounded time, without crashing (expect_failure.py checks
# all three). The inputs are made at test time by make_hostile_inputs.py.
set(_hostile "${CMAKE_CURRENT_BINARY_DIR}/hostile")
set(_expect /usr/bin/python3 "${CMAKE_CURRENT_SOURCE_DIR}/expect_failure.py")
set(_strokes "${CMAKE_CURRENT_SOURCE_DIR}/OFBPaint/no-strokes.txt")
set(_spot "${PROJECT_SOURCE_DIR}/Testing/Data/spot.obj")
set(_small --resolution 64 --width 64 --height 64)
set(_hostile_tests)

add_test(NAME OFB.Examples.Hostile.MakeInputs
  COMMAND /usr/bin/python3 "${CMAKE_CURRENT_SOURCE_DIR}/make_hostile_inputs.py" "${_hostile}")
set_tests_properties(OFB.Examples.Hostile.MakeInputs PROPERTIES FIXTURES_SETUP ofb_hostile)

# Images: each kind through both entry points, --decal and --import-texture.
set(_images truncated.png truncated-header.png bad-crc.png bad-zlib.png zero-width.png
  zero-height.png width-2pow31.png implausible.png huge.bmp huge.ppm zero-size.ppm)
set(_image_messages "cut short" "header is cut short" "bad CRC" "corrupt compressed image data"
  "a side of 0" "a side of 0" "over the limit" "too little image data"
  "claimed size of 100000 x 100000" "claimed size of 100000 x 100000" "a side of 0")
foreach (_image IN LISTS _images)
  list(FIND _images "${_image}" _index)
  list(GET _image_messages ${_index} _message)
  set(_expected "cannot read '[^']*${_image}': [^\n]*${_message}")
  add_test(NAME OFB.Examples.Hostile.Decal.${_image}
    COMMAND ${_expect} "${_expected}" 20 $<TARGET_FILE:OFBPaint> ${_small}
      --decal "${_hostile}/${_image}" --strokes "${_strokes}" --image "${_hostile}/out.png")
  add_test(NAME OFB.Examples.Hostile.ImportTexture.${_image}
    COMMAND ${_expect} "${_expected}" 20 $<TARGET_FILE:OFBPaint> "${_spot}" ${_small}
      --import-texture "${_hostile}/${_image}" --strokes "${_strokes}"
      --image "${_hostile}/out.png")
  list(APPEND _hostile_tests OFB.Examples.Hostile.Decal.${_image}
    OFB.Examples.Hostile.ImportTexture.${_image})
endforeach ()
# The same small image, well formed, is taken.
add_test(NAME OFB.Examples.Hostile.Decal.GoodImage
  COMMAND $<TARGET_FILE:OFBPaint> ${_small} --decal "${_hostile}/good.png"
    --strokes "${_strokes}" --image "${_hostile}/good-out.png")
list(APPEND _hostile_tests OFB.Examples.Hostile.Decal.GoodImage)

# Meshes: refused before VTK's readers (PLY, STL) or filters (every format) see them; the
# PLY header claiming 10^9 vertices fails at once.
set(_meshes bad-index.obj bad-texture-index.obj bad-normal-index.obj bad-index.ply truncated.ply
  billion.ply truncated.stl bad-index.vtp)
set(_mesh_messages "vertex index 99999, not one of the 3 vertices"
  "texture coordinate index 99, not one of the 1" "normal index 7, not one of the 1"
  "vertex index 99999" "cut short" "1000000000 vertex elements, over the limit"
  "claiming 1000000 triangles" "polygon 0 uses point 99999, not one of the 3 points")
foreach (_mesh IN LISTS _meshes)
  list(FIND _meshes "${_mesh}" _index)
  list(GET _mesh_messages ${_index} _message)
  add_test(NAME OFB.Examples.Hostile.Mesh.${_mesh}
    COMMAND ${_expect} "cannot read '[^']*${_mesh}': [^\n]*${_message}" 1
      $<TARGET_FILE:OFBPaint> "${_hostile}/${_mesh}" --strokes "${_strokes}"
      --image "${_hostile}/out.png")
  list(APPEND _hostile_tests OFB.Examples.Hostile.Mesh.${_mesh})
endforeach ()
# The other applications read meshes through the same helper.
add_test(NAME OFB.Examples.Hostile.Mesh.OFBLIC
  COMMAND ${_expect} "OFBLIC: cannot read .*vertex index 99999" 1
    $<TARGET_FILE:OFBLIC> "${_hostile}/bad-index.ply" --image "${_hostile}/out.png")
add_test(NAME OFB.Examples.Hostile.Mesh.OFBParticles
  COMMAND ${_expect} "OFBParticles: cannot read .*not one of the 3 vertices" 1
    $<TARGET_FILE:OFBParticles> "${_hostile}/bad-index.obj" --image "${_hostile}/out.png")
add_test(NAME OFB.Examples.Hostile.Mesh.OFBDemo
  COMMAND ${_expect} "OFBDemo: cannot read .*1000000000 vertex" 1
    $<TARGET_FILE:OFBDemo> "${_hostile}/billion.ply" --output "${_hostile}/out.png")
list(APPEND _hostile_tests OFB.Examples.Hostile.Mesh.OFBLIC OFB.Examples.Hostile.Mesh.OFBParticles
  OFB.Examples.Hostile.Mesh.OFBDemo)

# Simulation data (ofbExampleData): refused before VTK's filters see them, by each
# application in turn.
set(_data_inputs bad-index.vtu truncated.vtu missing-part.pvd nested.pvd no-datasets.pvd
  legacy-garbage.vtk)
set(_data_messages "cell 0 uses point 99999, not one of the 4 points" "no polygons"
  "its file 'not-there.vtp': no such file" "a collection inside a collection"
  "the collection lists no DataSet" "Could not read file")
set(_data_apps OFBLIC OFBParticles OFBPaint OFBLIC OFBParticles OFBPaint)
foreach (_input IN LISTS _data_inputs)
  list(FIND _data_inputs "${_input}" _index)
  list(GET _data_messages ${_index} _message)
  list(GET _data_apps ${_index} _app)
  set(_extra)
  if (_app STREQUAL "OFBPaint")
    set(_extra --strokes "${_strokes}")
  endif ()
  add_test(NAME OFB.Examples.Hostile.Data.${_input}
    COMMAND ${_expect} "${_app}: cannot read '[^']*${_input}': [^\n]*${_message}" 30
      $<TARGET_FILE:${_app}> "${_hostile}/${_input}" ${_extra} --image "${_hostile}/out.png")
  list(APPEND _hostile_tests OFB.Examples.Hostile.Data.${_input})
endforeach ()

# Stroke files: no directories, devices or FIFOs; bounded size, lines and dabs.
set(_stroke_inputs "${_hostile}/strokes-directory" /dev/zero "${_hostile}/strokes.fifo"
  "${_hostile}/too-large.txt" "${_hostile}/too-many-lines.txt" "${_hostile}/dab-bomb.txt")
set(_stroke_names Directory DevZero FIFO TooLarge TooManyLines DabBomb)
set(_stroke_messages "a directory, not a stroke file" "not a regular file"
  "not a regular file" "larger than the limit of 16777216 bytes"
  "longer than the limit of 1000000 lines" "more than 100000 dabs, the limit of a stroke")
foreach (_name IN LISTS _stroke_names)
  list(FIND _stroke_names "${_name}" _index)
  list(GET _stroke_inputs ${_index} _input)
  list(GET _stroke_messages ${_index} _message)
  add_test(NAME OFB.Examples.Hostile.Strokes.${_name}
    COMMAND ${_expect} "${_message}" 30 $<TARGET_FILE:OFBPaint> ${_small}
      --strokes "${_input}" --image "${_hostile}/out.png")
  list(APPEND _hostile_tests OFB.Examples.Hostile.Strokes.${_name})
endforeach ()

# Exit statuses: what could not be written or was refused by the library fails the run.
add_test(NAME OFB.Examples.Hostile.Exit.ParticlesImageIsDirectory
  COMMAND ${_expect} "cannot write '[^']*strokes-directory': it is a directory" 60
    $<TARGET_FILE:OFBParticles> --particles 100 --resolution 64 --steps 2 --width 64 --height 64
    --image "${_hostile}/strokes-directory")
add_test(NAME OFB.Examples.Hostile.Exit.ParticlesImageReadOnly
  COMMAND ${_expect} "cannot write '/proc/version'" 60
    $<TARGET_FILE:OFBParticles> --particles 100 --resolution 64 --steps 2 --width 64 --height 64
    --image /proc/version)
add_test(NAME OFB.Examples.Hostile.Exit.ParticlesTooMany
  COMMAND ${_expect} "OFBParticles: .*[Mm]emory" 120
    $<TARGET_FILE:OFBParticles> --particles 100000000 --resolution 64 --steps 2 --width 64
    --height 64 --image "${_hostile}/out.png")
add_test(NAME OFB.Examples.Hostile.Exit.ParticlesUnknownColor
  COMMAND ${_expect} "Usage: OFBParticles" 10 $<TARGET_FILE:OFBParticles> --color nosuch)
add_test(NAME OFB.Examples.Hostile.Exit.ParticlesUnknownField
  COMMAND ${_expect} "OFBParticles: '[^']*horse.ply' has no point or cell array 'nosuch'" 30
    $<TARGET_FILE:OFBParticles> --field nosuch)
add_test(NAME OFB.Examples.Hostile.Exit.LICImageIsDirectory
  COMMAND ${_expect} "cannot write '[^']*strokes-directory': it is a directory" 120
    $<TARGET_FILE:OFBLIC> --resolution 64 --size 64 --image "${_hostile}/strokes-directory")
add_test(NAME OFB.Examples.Hostile.Exit.DemoOutputIsDirectory
  COMMAND ${_expect} "cannot write '[^']*strokes-directory': it is a directory" 120
    $<TARGET_FILE:OFBDemo> --resolution 64 --width 128 --height 64
    --output "${_hostile}/strokes-directory")
# A PNG that does not fit on the disk names the cause (not VTK's "Ran out of disk space").
add_test(NAME OFB.Examples.Hostile.Exit.PaintImageDiskFull
  COMMAND ${_expect} --file-size-limit 2000 "cannot write '[^']*full.png': File too large" 60
    $<TARGET_FILE:OFBPaint> ${_small} --strokes "${_strokes}" --image "${_hostile}/full.png")
# OFBLIC's export is OFBPaint's: a full disk fails it with the cause.
add_test(NAME OFB.Examples.Hostile.Exit.LICExportDiskFull
  COMMAND ${_expect} --file-size-limit 200000 "cannot write '[^']*lic-full.obj': File too large"
    120 $<TARGET_FILE:OFBLIC> --resolution 64 --size 64 --image "${_hostile}/lic-view.png"
    --export "${_hostile}/lic-full.obj")
list(APPEND _hostile_tests OFB.Examples.Hostile.Exit.LICExportDiskFull)
list(APPEND _hostile_tests OFB.Examples.Hostile.Exit.ParticlesImageIsDirectory
  OFB.Examples.Hostile.Exit.ParticlesImageReadOnly OFB.Examples.Hostile.Exit.ParticlesTooMany
  OFB.Examples.Hostile.Exit.ParticlesUnknownColor OFB.Examples.Hostile.Exit.ParticlesUnknownField
  OFB.Examples.Hostile.Exit.LICImageIsDirectory OFB.Examples.Hostile.Exit.DemoOutputIsDirectory
  OFB.Examples.Hostile.Exit.PaintImageDiskFull)

# Exports: atomic and checked (a full disk, a directory in the way, kill -9 mid-export).
add_test(NAME OFB.Examples.Hostile.ExportFailures
  COMMAND /usr/bin/python3 "${CMAKE_CURRENT_SOURCE_DIR}/OFBPaint/check_export_failures.py"
    $<TARGET_FILE:OFBPaint> "${CMAKE_CURRENT_SOURCE_DIR}/OFBPaint/demo-strokes.txt"
    "${CMAKE_CURRENT_BINARY_DIR}/export-failures")
set_tests_properties(OFB.Examples.Hostile.ExportFailures PROPERTIES
  TIMEOUT 600 PASS_REGULAR_EXPRESSION "check passed" FAIL_REGULAR_EXPRESSION "FAIL")
list(APPEND _hostile_tests OFB.Examples.Hostile.ExportFailures)

set_tests_properties(${_hostile_tests} PROPERTIES FIXTURES_REQUIRED ofb_hostile)
vtkofb_mark_display_tests(TESTS ${_hostile_tests})
