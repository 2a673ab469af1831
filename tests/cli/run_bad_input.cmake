# Runs one row of bad_input.tsv (see its header) and checks what kerf did.
#
#   cmake -DKERF=<kerf binary> [-DEMULATOR=<emulator;args>] -DCASE=<name>
#         -DEXAMPLES=<firmware/examples> -DOUT_DIR=<dir> -P run_bad_input.cmake
#
# The table is read with string(FIND), not as a CMake list: regexes hold ';'
# and '[', which list operations would split or nest.

cmake_minimum_required(VERSION 3.25)

foreach(var KERF CASE EXAMPLES OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_bad_input.cmake: -D${var}=... is required")
  endif()
endforeach()

file(READ ${CMAKE_CURRENT_LIST_DIR}/bad_input.tsv table)
string(FIND "\n${table}" "\n${CASE}\t" at)
if(at LESS 0)
  message(FATAL_ERROR "run_bad_input.cmake: no row ${CASE} in bad_input.tsv")
endif()
string(SUBSTRING "${table}" ${at} -1 row)
string(FIND "${row}" "\n" end)
string(SUBSTRING "${row}" 0 ${end} row)

# The row's five fields, in order.
set(fields name want_rc arg_text want_err want_out)
foreach(field IN LISTS fields)
  string(FIND "${row}" "\t" tab)
  if(tab LESS 0)
    set(${field} "${row}")
    set(row "")
  else()
    string(SUBSTRING "${row}" 0 ${tab} ${field})
    math(EXPR next "${tab} + 1")
    string(SUBSTRING "${row}" ${next} -1 row)
  endif()
endforeach()
if(NOT row STREQUAL "")
  message(FATAL_ERROR "run_bad_input.cmake: row ${CASE} has more than five fields")
endif()

string(REPLACE "@EXAMPLES@" "${EXAMPLES}" arg_text "${arg_text}")
string(REPLACE "@CASES@" "${CMAKE_CURRENT_LIST_DIR}/cases" arg_text "${arg_text}")
string(REPLACE " " ";" args "${arg_text}")
string(REPLACE "\\n" "\n" want_err "${want_err}")
string(REPLACE "\\n" "\n" want_out "${want_out}")

# A fresh, empty folder with the case's input files.
set(work_dir ${OUT_DIR}/work)
file(REMOVE_RECURSE ${work_dir})
file(MAKE_DIRECTORY ${work_dir})
set(stdin /dev/null)
file(GLOB inputs ${CMAKE_CURRENT_LIST_DIR}/bad_input/${CASE}.*)
foreach(input IN LISTS inputs)
  get_filename_component(name ${input} NAME)
  string(LENGTH "${CASE}." skip)
  string(SUBSTRING "${name}" ${skip} -1 name)
  if(name STREQUAL "stdin")
    set(stdin ${input})
  else()
    file(COPY_FILE ${input} ${work_dir}/${name})
  endif()
endforeach()

set(case_name "${CASE} (bad_input.tsv)")
include(${CMAKE_CURRENT_LIST_DIR}/run_and_check.cmake)
