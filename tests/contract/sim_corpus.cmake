# One G-code file through `kerf sim` (see CMakeLists.txt), then sim_corpus_check
# on its trace and report. Set: KERF, EMULATOR, CHECK, FILE, TOL, OUT_DIR, and
# REFUSED (a reason the file must be refused for; empty: it must run).
# On a machine with a z axis also set CONFIG (its configuration), Z_MOVES and
# FINAL_Z (mm) that the report must show, and optionally LINK (--link).
set(args)
if(CONFIG)
  list(APPEND args --config ${CONFIG})
endif()
if(LINK)
  list(APPEND args --link ${LINK})
endif()
file(MAKE_DIRECTORY ${OUT_DIR})
execute_process(
  COMMAND ${EMULATOR} ${KERF} sim ${FILE} ${args} --tol ${TOL} --speed 0
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
if(NOT DEFINED Z_MOVES)
  return()
endif()
file(READ ${OUT_DIR}/report.json report)
string(JSON state GET "${report}" state)
string(JSON z_moves ERROR_VARIABLE no_z GET "${report}" z_moves)
# As written (%.6f): string(JSON) would read it back as a double.
string(REGEX MATCH "\"final_z\": ([-0-9.]+)" final_z "${report}")
set(final_z "${CMAKE_MATCH_1}")
if(NOT state STREQUAL "done" OR no_z OR final_z STREQUAL "")
  message(FATAL_ERROR "expected state done with z_moves and final_z, got state ${state} (${no_z})")
endif()
if(NOT z_moves EQUAL ${Z_MOVES} OR NOT "${final_z}" MATCHES "^${FINAL_Z}0*$")
  message(FATAL_ERROR "expected ${Z_MOVES} z moves ending at z ${FINAL_Z}, got ${z_moves} ending at ${final_z}")
endif()
# The trace's last sample (its last column, z_mm) is there too.
file(SIZE ${OUT_DIR}/trace.csv size)
math(EXPR from "${size} - 120")
file(READ ${OUT_DIR}/trace.csv tail OFFSET ${from})
if(NOT tail MATCHES ",${FINAL_Z}0*\n$")
  message(FATAL_ERROR "the trace does not end at z ${FINAL_Z}: ...${tail}")
endif()
