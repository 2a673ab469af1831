# Runs one case of the kerf command and checks what it did.
#
#   cmake -DKERF=<kerf binary> [-DEMULATOR=<emulator;args>] -DCASE_DIR=<case folder>
#         [-DEXAMPLES=<firmware/examples>] [-DVERSION=<x.y.z>] [-DOUT_DIR=<dir>]
#         -P run_case.cmake
#
# A case folder holds:
#   args             the arguments, one per line (no ';'); @EXAMPLES@ stands for
#                    firmware/examples. kerf runs in the case folder, so input
#                    files there are named by their plain name.
#   stdin            (optional) fed to kerf's standard input; /dev/null otherwise
#   rc               (optional) the expected exit code; 0 when absent
#   expected.stdout  standard output, compared byte for byte (an empty file for
#                    no output); @VERSION@ stands for the project version
#   stderr.regex     (optional) a CMake regex standard error must match
#
# In stderr.regex, \n stands for a newline.
#
# To regenerate expected.stdout from the binary, set KERF_UPDATE_GOLDEN=1 in the
# environment, then check every changed file by hand before keeping it.

cmake_minimum_required(VERSION 3.25)

foreach(var KERF CASE_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_case.cmake: -D${var}=... is required")
  endif()
endforeach()

# Arguments.
set(args "")
if(EXISTS ${CASE_DIR}/args)
  file(READ ${CASE_DIR}/args text)
  string(REPLACE "@EXAMPLES@" "${EXAMPLES}" text "${text}")
  string(REGEX REPLACE "\n$" "" text "${text}")
  if(NOT text STREQUAL "")
    string(REPLACE "\n" ";" args "${text}")
  endif()
endif()

set(stdin /dev/null)
if(EXISTS ${CASE_DIR}/stdin)
  set(stdin ${CASE_DIR}/stdin)
endif()

set(want_rc 0)
if(EXISTS ${CASE_DIR}/rc)
  file(STRINGS ${CASE_DIR}/rc want_rc LIMIT_COUNT 1)
  string(STRIP "${want_rc}" want_rc)
endif()

# EMULATOR is empty for native builds, a list such as "qemu-aarch64;-L;/usr/aarch64-linux-gnu"
# for cross builds.
execute_process(
  COMMAND ${EMULATOR} ${KERF} ${args}
  WORKING_DIRECTORY ${CASE_DIR}
  INPUT_FILE ${stdin}
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  RESULT_VARIABLE rc)

if(NOT EXISTS ${CASE_DIR}/expected.stdout AND NOT "$ENV{KERF_UPDATE_GOLDEN}")
  message(FATAL_ERROR "${CASE_DIR}/expected.stdout is missing")
endif()
if("$ENV{KERF_UPDATE_GOLDEN}")
  file(WRITE ${CASE_DIR}/expected.stdout "${out}")
endif()
file(READ ${CASE_DIR}/expected.stdout want_out)
if(DEFINED VERSION)
  string(REPLACE "@VERSION@" "${VERSION}" want_out "${want_out}")
endif()

set(failures "")
if(NOT "${rc}" STREQUAL "${want_rc}")
  string(APPEND failures "exit code: expected ${want_rc}, got ${rc}\n")
endif()
if(NOT "${out}" STREQUAL "${want_out}")
  string(APPEND failures "stdout differs from expected.stdout\n")
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
if(EXISTS ${CASE_DIR}/stderr.regex)
  file(READ ${CASE_DIR}/stderr.regex want_err)
  string(REGEX REPLACE "\n$" "" want_err "${want_err}")
  string(REPLACE "\\n" "\n" want_err "${want_err}")
  if(NOT "${err}" MATCHES "${want_err}")
    string(APPEND failures "stderr does not match stderr.regex: ${want_err}\n")
  endif()
endif()

string(REPLACE ";" " " shown "${EMULATOR} ${KERF} ${args}")
if(NOT failures STREQUAL "")
  message(FATAL_ERROR "case ${CASE_DIR}\ncommand: ${shown}\n${failures}--- stderr:\n${err}")
endif()
message(STATUS "ok: ${shown}\n${err}")
