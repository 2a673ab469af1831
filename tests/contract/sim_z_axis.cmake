# One G-code file through `kerf sim` on a machine with a z axis (see
# CMakeLists.txt): it runs to done, sim_corpus_check passes on its trace and
# report, and the report has the z moves and the final z the file asks for.
# Set: KERF, EMULATOR, CHECK, CONFIG, FILE, TOL, OUT_DIR, Z_MOVES, FINAL_Z (mm);
# LINK (optional): --link, e.g. can (the third CiA 402 node drives z).
set(link_args)
if(LINK)
  set(link_args --link ${LINK})
endif()
file(MAKE_DIRECTORY ${OUT_DIR})
execute_process(
  COMMAND ${EMULATOR} ${KERF} sim ${FILE} --config ${CONFIG} ${link_args} --tol ${TOL} --speed 0
          --trace ${OUT_DIR}/trace.csv --report ${OUT_DIR}/report.json
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}${err}")
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
