# The file-size check (toolchain/cmake/check_file_sizes.cmake) on a made-up
# tree: it must fail on a 601-line source file and name it with its count,
# pass a 600-line one, and skip tests/ and data files.
#
#   cmake -DCHECK=<check_file_sizes.cmake> -DWORK=<scratch dir> -P check_sizes_fails.cmake

cmake_minimum_required(VERSION 3.25)

function(write_lines path count)
  string(REPEAT "x\n" ${count} text)
  file(WRITE ${path} "${text}")
endfunction()

function(run_check var)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK} -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${var}_rc ${rc} PARENT_SCOPE)
  set(${var}_out "${out}${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
write_lines(${WORK}/firmware/too_long.cpp 601)
write_lines(${WORK}/core/at_limit.hpp 600)
write_lines(${WORK}/tests/long_test.cpp 900)
write_lines(${WORK}/firmware/examples/points.txt 900)

run_check(long)
if(long_rc EQUAL 0)
  message(FATAL_ERROR "the check passed a 601-line file:\n${long_out}")
endif()
if(NOT long_out MATCHES "firmware/too_long\\.cpp: 601 lines")
  message(FATAL_ERROR "the check did not name firmware/too_long.cpp with 601 lines:\n${long_out}")
endif()
foreach(allowed at_limit long_test points)
  if(long_out MATCHES "${allowed}")
    message(FATAL_ERROR "the check named ${allowed}, which it must allow:\n${long_out}")
  endif()
endforeach()

file(REMOVE ${WORK}/firmware/too_long.cpp)
run_check(fine)
if(NOT fine_rc EQUAL 0)
  message(FATAL_ERROR "the check failed a tree with no file over 600 lines:\n${fine_out}")
endif()
message(STATUS "the size check fails on 601 lines and passes 600")
