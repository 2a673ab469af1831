# Fails when a source, build or doc file outside tests/ is over the line limit,
# naming every such file and its line count. Data (point files, corpora) is
# not checked: only the suffixes below.
#
#   cmake -DROOT=<source tree> [-DLIMIT=600] -P check_file_sizes.cmake

cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED ROOT)
  message(FATAL_ERROR "check_file_sizes.cmake: -DROOT=... is required")
endif()
if(NOT DEFINED LIMIT)
  set(LIMIT 600)
endif()

set(patterns)
foreach(suffix cpp hpp h c cmake sh py md toml service)
  list(APPEND patterns ${ROOT}/*.${suffix})
endforeach()
list(APPEND patterns ${ROOT}/CMakeLists.txt)
file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE ${ROOT} ${patterns})
# tests/ has its own rules; build/ and hidden folders are not the source.
list(FILTER files EXCLUDE REGEX "^(tests|build)/|(^|/)\\.")

set(too_long)
foreach(file IN LISTS files)
  file(READ ${ROOT}/${file} text)
  string(LENGTH "${text}" with)
  string(REPLACE "\n" "" text "${text}")
  string(LENGTH "${text}" without)
  math(EXPR lines "${with} - ${without}")
  if(lines GREATER LIMIT)
    list(APPEND too_long "  ${file}: ${lines} lines")
  endif()
endforeach()

if(too_long)
  list(JOIN too_long "\n" shown)
  message(FATAL_ERROR "files over ${LIMIT} lines (split them):\n${shown}")
endif()
list(LENGTH files n)
message(STATUS "file sizes: ${n} files, none over ${LIMIT} lines")
