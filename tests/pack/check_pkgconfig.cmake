# pkg-config from an install: `pkg-config --cflags --libs kerf` with
# PKG_CONFIG_PATH at PREFIX, then the consumer program compiled and linked
# with exactly those flags, and run.
#   cmake -DPREFIX=... -DLIBDIR=lib -DSOURCE=<main.cpp> -DBINARY=<scratch> -DCXX=<compiler>
#         [-DEMULATOR=list] [-DCXX_FLAGS=...] [-DLD_FLAGS=...] -P check_pkgconfig.cmake
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/run_consumer.cmake)
file(REMOVE_RECURSE ${BINARY})
file(MAKE_DIRECTORY ${BINARY})
# Only the install's .pc files: never a kerf installed on the host.
set(ENV{PKG_CONFIG_LIBDIR} ${PREFIX}/${LIBDIR}/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")
execute_process(COMMAND pkg-config --cflags --libs kerf RESULT_VARIABLE rc
                OUTPUT_VARIABLE flags ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs kerf failed (${rc}): ${err}")
endif()
if(NOT flags MATCHES "-lkerf_io" OR NOT flags MATCHES "-I")
  message(FATAL_ERROR "pkg-config kerf gave: ${flags}")
endif()
separate_arguments(flag_list UNIX_COMMAND "${flags}")
# The build's own flags too (the sanitizers of debug-asan must link the same way).
separate_arguments(build_flags UNIX_COMMAND "${CXX_FLAGS} ${LD_FLAGS}")
execute_process(COMMAND ${CXX} -std=c++20 -O2 ${build_flags} ${SOURCE} ${flag_list} -o ${BINARY}/consumer
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compiling with `${flags}` failed (${rc}):\n${out}${err}")
endif()
kerf_run_consumer(${BINARY}/consumer "${EMULATOR}")
