# A job on a machine with a z axis stopped by an E-stop, then resumed from its
# journal (see CMakeLists.txt): the resumed run ends done with every segment
# run exactly once over both runs and Z where the program leaves it.
# Set: KERF, FILE, CONFIG, OUT_DIR, SEGMENTS, FINAL_Z (mm).
file(MAKE_DIRECTORY ${OUT_DIR})
file(REMOVE ${OUT_DIR}/job.journal)
execute_process(
  COMMAND ${KERF} sim ${FILE} --config ${CONFIG} --speed 0 --journal ${OUT_DIR}/job.journal --fault estop@20
          --report ${OUT_DIR}/first.json
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}${err}")
file(READ ${OUT_DIR}/first.json first)
string(JSON state GET "${first}" state)
if(NOT state STREQUAL "estop")
  message(FATAL_ERROR "the first run should stop at the E-stop, got ${state}")
endif()
execute_process(
  COMMAND ${KERF} sim ${FILE} --config ${CONFIG} --speed 0 --journal ${OUT_DIR}/job.journal --resume
          --report ${OUT_DIR}/resumed.json
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}${err}")
file(READ ${OUT_DIR}/resumed.json resumed)
string(JSON state GET "${resumed}" state)
string(JSON total GET "${resumed}" segments_executed_total)
string(JSON duplicates GET "${resumed}" duplicates)
string(REGEX MATCH "\"final_z\": ([-0-9.]+)" final_z "${resumed}")
if(NOT rc EQUAL 0 OR NOT state STREQUAL "done" OR NOT total EQUAL ${SEGMENTS} OR NOT duplicates EQUAL 0
   OR NOT "${CMAKE_MATCH_1}" MATCHES "^${FINAL_Z}0*$")
  message(FATAL_ERROR "expected done, ${SEGMENTS} segments in all, 0 duplicates, final z ${FINAL_Z}; got exit ${rc}, "
                      "${state}, ${total}, ${duplicates}, ${CMAKE_MATCH_1}")
endif()
