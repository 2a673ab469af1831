# find_package(kerf) from an install: configures, builds and runs
# tests/pack/consumer against PREFIX.
#   cmake -DPREFIX=... -DSOURCE=<consumer> -DBINARY=<scratch> [-DTOOLCHAIN=file]
#         [-DEMULATOR=list] [-DCXX_FLAGS=...] [-DLD_FLAGS=...] -DGENERATOR=... -P check_consumer.cmake
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/run_consumer.cmake)
file(REMOVE_RECURSE ${BINARY})
# The build's own flags (the sanitizers of debug-asan must link the same way).
set(args -S ${SOURCE} -B ${BINARY} -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${PREFIX}
         -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
         "-DCMAKE_EXE_LINKER_FLAGS=${LD_FLAGS}")
if(TOOLCHAIN)
  # A cross toolchain roots package searches in the target's root
  # (CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY): name the package folder instead.
  list(APPEND args -DCMAKE_TOOLCHAIN_FILE=${TOOLCHAIN} -Dkerf_DIR=${PREFIX}/lib/cmake/kerf)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed (${rc}):\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed (${rc}):\n${out}${err}")
endif()
kerf_run_consumer(${BINARY}/consumer "${EMULATOR}")
