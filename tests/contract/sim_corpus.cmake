# One G-code file through `kerf sim` (see CMakeLists.txt), then sim_corpus_check
# on its trace and report. Set: KERF, EMULATOR, CHECK, FILE, TOL, OUT_DIR, and
# REFUSED (a reason the file must be refused for; empty: it must run).
file(MAKE_DIRECTORY ${OUT_DIR})
execute_process(
  COMMAND ${EMULATOR} ${KERF} sim ${FILE} --tol ${TOL} --speed 0
          --trace ${OUT_DIR}/trace.csv --report ${OUT_DIR}/report.json
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}${err}")
if(NOT "${REFUSED}" STREQUAL "")
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${FILE}:[0-9]+: [^\n]*${REFUSED}")
    message(FATAL_ERROR "expected exit 2 and \"FILE:LINE: ...${REFUSED}\", got exit ${rc}")
  endif()
  return()
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "kerf sim exited ${rc}")
endif()
execute_process(
  COMMAND ${EMULATOR} ${CHECK} ${FILE} ${OUT_DIR}/trace.csv ${OUT_DIR}/report.json ${TOL}
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the run does not match the file")
endif()
