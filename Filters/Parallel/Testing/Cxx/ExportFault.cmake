# ctest driver of TestOFBPExportFault: the distributed write with a process killed, then
# the check of what it left. -D: PROGRAM, MPIEXEC, NPFLAG, PROCESSES, DIR.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
execute_process(
  COMMAND "${MPIEXEC}" ${NPFLAG} ${PROCESSES} "${PROGRAM}" "${DIR}"
  RESULT_VARIABLE run_result
  OUTPUT_VARIABLE run_output
  ERROR_VARIABLE run_output)
message(STATUS "mpiexec exit status ${run_result} (a killed process makes it non-zero)")
execute_process(
  COMMAND "${PROGRAM}" --check "${DIR}" ${PROCESSES}
  RESULT_VARIABLE check_result
  OUTPUT_VARIABLE check_output
  ERROR_VARIABLE check_output)
message(STATUS "${check_output}")
if (NOT check_result EQUAL 0)
  message(FATAL_ERROR "A killed writer left a partial or stray file:\n${run_output}")
endif ()
