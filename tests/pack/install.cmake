# `cmake --install` of the build into a fresh prefix (the fixture the
# find_package and pkg-config tests use).
#   cmake -DBUILD_DIR=... -DPREFIX=... -P install.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}${err}")
endif()
foreach(f bin/kerf lib/libkerf_core.a lib/libkerf_io.a lib/libkerf_job.a lib/cmake/kerf/kerfConfig.cmake
          lib/pkgconfig/kerf.pc include/kerf/fit/fit.hpp include/kerf_io/io/fit_output.hpp
          share/kerf/systemd/kerf.service share/doc/kerf/examples/kerf.toml)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "cmake --install did not install ${f}")
  endif()
endforeach()
# A plain install must never write the host's /etc or /lib (component "system").
foreach(f etc/kerf/kerf.toml lib/systemd/system/kerf.service)
  if(EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "cmake --install installed ${f}: the system component leaked")
  endif()
endforeach()
