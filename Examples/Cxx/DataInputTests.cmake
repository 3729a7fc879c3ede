# Applications that open data: the pipe of make_data_inputs.py in every format read by
# ofbExampleData (a .vtp with a cell field, a .vtu, a legacy .vtk, a .vtm's blocks, a .pvd's
# time steps) through OFBLIC, OFBParticles and OFBPaint; OFBPaint's sparse strokes around
# the pipe paint one continuous ring (check_pipe_strokes.py). Bad data (a missing field, an
# unknown format, a time outside the range, an unknown block) fails with a message.
set(_data "${CMAKE_CURRENT_BINARY_DIR}/data")
set(_expect /usr/bin/python3 "${CMAKE_CURRENT_SOURCE_DIR}/expect_failure.py")
set(_data_tests)

add_test(NAME OFB.Examples.Data.MakeInputs
  COMMAND /usr/bin/python3 "${CMAKE_CURRENT_SOURCE_DIR}/make_data_inputs.py" "${_data}")
set_tests_properties(OFB.Examples.Data.MakeInputs PROPERTIES FIXTURES_SETUP ofb_data)

# OFBLIC on each format, with its vector field (cells or points) and its blocks and times.
set(_lic_names Vtp Vtu Vtk VtmBlock Pvd PvdStep)
set(_lic_args "pipe.vtp|--field|WSS" "pipe.vtu|--field|Velocity" "pipe.vtk|--field|Flow"
  "pipe.vtm|--field|WSS|--block|downstream" "series.pvd|--field|WSS|--time|0.6"
  "series.pvd|--field|WSS|--time-step|2")
set(_lic_messages "vtkPolyData, 1 block[^\n]*field 'WSS' on cells"
  "vtkUnstructuredGrid, 1 block[^\n]*field 'Velocity' on points"
  "legacy VTK vtkPolyData[^\n]*field 'Flow' on points"
  "1 block\\(s\\) \\(2 \\(downstream\\)\\), 1024 cells" "time step 1 of 0-2 \\(t = 0.5\\)"
  "time step 2 of 0-2 \\(t = 1\\)")
foreach (_name IN LISTS _lic_names)
  list(FIND _lic_names "${_name}" _index)
  list(GET _lic_args ${_index} _args)
  string(REPLACE "|" ";" _args "${_args}")
  list(GET _lic_messages ${_index} _message)
  list(GET _args 0 _file)
  list(REMOVE_AT _args 0)
  add_test(NAME OFB.Examples.Data.OFBLIC.${_name}
    COMMAND OFBLIC "${_data}/${_file}" ${_args} --resolution 96 --size 96
      --image "${_data}/lic-${_name}.png")
  set_tests_properties(OFB.Examples.Data.OFBLIC.${_name} PROPERTIES
    TIMEOUT 120 PASS_REGULAR_EXPRESSION "${_message}.*wrote [^\n]*lic-${_name}[.]png")
  list(APPEND _data_tests OFB.Examples.Data.OFBLIC.${_name})
endforeach ()

# OFBParticles: a cell field of a .vtm (both blocks) and a .vtu's point field.
add_test(NAME OFB.Examples.Data.OFBParticles.VtmCellField
  COMMAND OFBParticles "${_data}/pipe.vtm" --field WSS --particles 500 --resolution 96
    --steps 10 --width 96 --height 96 --view-up 0 1 0 --image "${_data}/particles-vtm.png")
set_tests_properties(OFB.Examples.Data.OFBParticles.VtmCellField PROPERTIES
  TIMEOUT 120
  PASS_REGULAR_EXPRESSION "2 block\\(s\\) \\(1 \\(upstream\\), 2 \\(downstream\\)\\)[^\n]*field 'WSS' on cells.*Wrote .* after 10 steps of 500 particles")
add_test(NAME OFB.Examples.Data.OFBParticles.Vtu
  COMMAND OFBParticles "${_data}/pipe.vtu" --field Velocity --particles 500 --resolution 96
    --steps 10 --width 96 --height 96 --view-up 0 1 0 --image "${_data}/particles-vtu.png")
set_tests_properties(OFB.Examples.Data.OFBParticles.Vtu PROPERTIES
  TIMEOUT 120 PASS_REGULAR_EXPRESSION "field 'Velocity' on points.*Wrote .* after 10 steps")
list(APPEND _data_tests OFB.Examples.Data.OFBParticles.VtmCellField
  OFB.Examples.Data.OFBParticles.Vtu)

# OFBPaint: a .vtm's blocks coloured by their cell field; on the .vtp, four stroke points a
# quarter turn apart around the pipe (one off the wall) painted as one ring, checked on
# the saved OFB.
add_test(NAME OFB.Examples.Data.OFBPaint.Field
  COMMAND OFBPaint "${_data}/pipe.vtm" --field WSS --resolution 96 --width 200 --height 200
    --strokes "${CMAKE_CURRENT_SOURCE_DIR}/OFBPaint/no-strokes.txt"
    --image "${_data}/paint-field.png")
set_tests_properties(OFB.Examples.Data.OFBPaint.Field PROPERTIES
  TIMEOUT 120 PASS_REGULAR_EXPRESSION "2 block[^\n]*field 'WSS' on cells.*Wrote ")
add_test(NAME OFB.Examples.Data.OFBPaint.PipeStrokes
  COMMAND OFBPaint "${_data}/pipe.vtp" --resolution 128 --width 200 --height 200
    --strokes "${_data}/pipe-strokes.txt" --image "${_data}/paint-pipe.png"
    --save "${_data}/paint-pipe.ofb")
set_tests_properties(OFB.Examples.Data.OFBPaint.PipeStrokes PROPERTIES
  TIMEOUT 120 FIXTURES_SETUP ofb_data_paint PASS_REGULAR_EXPRESSION "Replayed [^\n]*5 points")
list(APPEND _data_tests OFB.Examples.Data.OFBPaint.Field OFB.Examples.Data.OFBPaint.PipeStrokes)
if (VTKOFB_WRAP_PYTHON)
  add_test(NAME OFB.Examples.Data.OFBPaint.PipeStrokesRing
    COMMAND /usr/bin/python3 "${CMAKE_CURRENT_SOURCE_DIR}/OFBPaint/check_pipe_strokes.py"
      "${_data}/paint-pipe.ofb")
  set_tests_properties(OFB.Examples.Data.OFBPaint.PipeStrokesRing PROPERTIES
    TIMEOUT 120 FIXTURES_REQUIRED ofb_data_paint PASS_REGULAR_EXPRESSION "check passed"
    ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/${VTKOFB_PYTHON_DESTINATION};LD_LIBRARY_PATH=${CMAKE_LIBRARY_OUTPUT_DIRECTORY};PYTHONDONTWRITEBYTECODE=1")
  list(APPEND _data_tests OFB.Examples.Data.OFBPaint.PipeStrokesRing)
endif ()

# Bad data: a message naming what is wrong and a non-zero exit, before any window.
add_test(NAME OFB.Examples.Data.Bad.MissingFieldLIC
  COMMAND ${_expect} "has no point or cell array 'Nope'. its arrays: cell vectors: WSS" 30
    $<TARGET_FILE:OFBLIC> "${_data}/pipe.vtp" --field Nope --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.MissingFieldParticles
  COMMAND ${_expect} "has no point or cell array 'Nope'. its arrays: point vectors: Velocity"
    30 $<TARGET_FILE:OFBParticles> "${_data}/pipe.vtu" --field Nope --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.MissingFieldPaint
  COMMAND ${_expect} "has no point or cell array 'Nope'" 30 $<TARGET_FILE:OFBPaint>
    "${_data}/pipe.vtm" --field Nope --strokes "${_data}/pipe-strokes.txt"
    --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.ScalarAsVectors
  COMMAND ${_expect} "'Pressure' of '[^']*' has 1 component\\(s\\), not a vector field" 30
    $<TARGET_FILE:OFBLIC> "${_data}/pipe.vtp" --field Pressure --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.UnknownFormat
  COMMAND ${_expect} "cannot read '[^']*wrong.xyz': unknown format" 30
    $<TARGET_FILE:OFBPaint> "${_data}/wrong.xyz" --strokes "${_data}/pipe-strokes.txt"
    --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.TimeOutsideRange
  COMMAND ${_expect} "time 7 is outside the file's 3 time steps, times 0 to 1" 30
    $<TARGET_FILE:OFBLIC> "${_data}/series.pvd" --field WSS --time 7 --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.TimeStepOutsideRange
  COMMAND ${_expect} "time step 3 is outside the file's 3 time steps.*steps 0 to 2" 30
    $<TARGET_FILE:OFBParticles> "${_data}/series.pvd" --time-step 3 --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.TimeWithoutSteps
  COMMAND ${_expect} "the file has no time steps" 30 $<TARGET_FILE:OFBPaint>
    "${_data}/pipe.vtp" --time 1 --strokes "${_data}/pipe-strokes.txt" --image "${_data}/out.png")
add_test(NAME OFB.Examples.Data.Bad.UnknownBlock
  COMMAND ${_expect} "no block 'inlet'; its blocks \\(flat index and name\\): 1 \\(upstream\\), 2 \\(downstream\\)"
    30 $<TARGET_FILE:OFBLIC> "${_data}/pipe.vtm" --block inlet --image "${_data}/out.png")
list(APPEND _data_tests OFB.Examples.Data.Bad.MissingFieldLIC
  OFB.Examples.Data.Bad.MissingFieldParticles OFB.Examples.Data.Bad.MissingFieldPaint
  OFB.Examples.Data.Bad.ScalarAsVectors OFB.Examples.Data.Bad.UnknownFormat
  OFB.Examples.Data.Bad.TimeOutsideRange OFB.Examples.Data.Bad.TimeStepOutsideRange
  OFB.Examples.Data.Bad.TimeWithoutSteps OFB.Examples.Data.Bad.UnknownBlock)

set_tests_properties(${_data_tests} PROPERTIES FIXTURES_REQUIRED ofb_data)
vtkofb_mark_display_tests(TESTS ${_data_tests})
