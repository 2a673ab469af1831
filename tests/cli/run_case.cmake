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

if("$ENV{KERF_UPDATE_GOLDEN}")
  set(golden_file ${CASE_DIR}/expected.stdout)  # run_and_check.cmake writes it
elseif(NOT EXISTS ${CASE_DIR}/expected.stdout)
  message(FATAL_ERROR "${CASE_DIR}/expected.stdout is missing")
else()
  file(READ ${CASE_DIR}/expected.stdout want_out)
  if(DEFINED VERSION)
    string(REPLACE "@VERSION@" "${VERSION}" want_out "${want_out}")
  endif()
endif()
if(EXISTS ${CASE_DIR}/stderr.regex)
  file(READ ${CASE_DIR}/stderr.regex want_err)
  string(REGEX REPLACE "\n$" "" want_err "${want_err}")
  string(REPLACE "\\n" "\n" want_err "${want_err}")
endif()

set(work_dir ${CASE_DIR})
set(case_name ${CASE_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/run_and_check.cmake)
