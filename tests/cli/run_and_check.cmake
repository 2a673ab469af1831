# Runs kerf once and checks its exit code, standard output and standard error.
# Included by run_case.cmake (a golden folder) and run_bad_input.cmake (a row
# of bad_input.tsv), which set:
#   KERF, EMULATOR     the binary, and the emulator list for cross builds
#   args               the arguments (a list)
#   work_dir, stdin    where kerf runs, and what it reads
#   want_rc, want_out  the expected exit code and standard output
#   want_err           (optional) a CMake regex standard error must match
#   case_name, OUT_DIR the case, for messages, and where to put a diff (optional)
#   golden_file        (optional) where to write the output in place of checking
#                      it (KERF_UPDATE_GOLDEN=1)

# EMULATOR is empty for native builds, a list such as "qemu-aarch64;-L;/usr/aarch64-linux-gnu"
# for cross builds.
execute_process(
  COMMAND ${EMULATOR} ${KERF} ${args}
  WORKING_DIRECTORY ${work_dir}
  INPUT_FILE ${stdin}
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  RESULT_VARIABLE rc)

if(DEFINED golden_file)
  file(WRITE ${golden_file} "${out}")
  set(want_out "${out}")
endif()

set(failures "")
if(NOT "${rc}" STREQUAL "${want_rc}")
  string(APPEND failures "exit code: expected ${want_rc}, got ${rc}\n")
endif()
if(NOT "${out}" STREQUAL "${want_out}")
  string(APPEND failures "stdout differs from the expected\n")
  if(DEFINED OUT_DIR)
    file(WRITE ${OUT_DIR}/actual.stdout "${out}")
    file(WRITE ${OUT_DIR}/expected.stdout "${want_out}")
    execute_process(COMMAND diff -u ${OUT_DIR}/expected.stdout ${OUT_DIR}/actual.stdout
                    OUTPUT_VARIABLE diff ERROR_QUIET)
    string(APPEND failures "${diff}")
  else()
    string(APPEND failures "--- expected:\n${want_out}--- actual:\n${out}")
  endif()
endif()
if(DEFINED want_err)
  if(NOT "${err}" MATCHES "${want_err}")
    string(APPEND failures "stderr does not match: ${want_err}\n")
  endif()
endif()

string(REPLACE ";" " " shown "${EMULATOR} ${KERF} ${args}")
if(NOT failures STREQUAL "")
  message(FATAL_ERROR "case ${case_name}\ncommand: ${shown}\n${failures}--- stderr:\n${err}")
endif()
message(STATUS "ok: ${shown}\n${err}")
