# The .deb: built with cpack from this build, unpacked with dpkg -x into a
# scratch root, and the installed kerf run from there.
#   cmake -DCPACK_CONFIG=<build>/CPackConfig.cmake -DOUT=<scratch> -DARCH=amd64|arm64
#         -DVERSION=x.y.z -DSOURCE_DIR=<tree> -DPOINTS=<point file> [-DEMULATOR=list]
#         [-DOBJDUMP=<objdump>] -P check_deb.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "${cmd} failed (${rc}):\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run(cpack --config ${CPACK_CONFIG} -B ${OUT}/cpack)
set(deb ${OUT}/cpack/kerf_${VERSION}_${ARCH}.deb)
if(NOT EXISTS ${deb})
  file(GLOB made ${OUT}/cpack/*.deb)
  message(FATAL_ERROR "expected ${deb}, cpack made: ${made}")
endif()
file(SIZE ${deb} size)
message(STATUS "${deb}: ${size} bytes")

# Control fields.
run(dpkg-deb -f ${deb} Package Architecture Version Depends)
message(STATUS "${out}")
if(NOT out MATCHES "Package: kerf\n" OR NOT out MATCHES "Architecture: ${ARCH}\n"
   OR NOT out MATCHES "Version: ${VERSION}\n" OR NOT out MATCHES "Depends: [^\n]*libc6")
  message(FATAL_ERROR "control fields of ${deb} are wrong:\n${out}")
endif()
run(dpkg-deb -e ${deb} ${OUT}/control)
file(READ ${OUT}/control/conffiles conffiles)
foreach(f /etc/kerf/kerf.toml /etc/default/kerf)
  if(NOT conffiles MATCHES "${f}\n")
    message(FATAL_ERROR "${f} is not a conffile:\n${conffiles}")
  endif()
endforeach()

# Unpacked: every file where it belongs, the unit and config as in the tree.
run(dpkg -x ${deb} ${OUT}/root)
set(root ${OUT}/root)
foreach(f usr/bin/kerf usr/lib/libkerf_core.a usr/lib/libkerf_io.a usr/lib/libkerf_job.a
          usr/lib/cmake/kerf/kerfConfig.cmake usr/lib/cmake/kerf/kerfTargets.cmake
          usr/lib/pkgconfig/kerf.pc usr/include/kerf/fit/fit.hpp
          usr/include/kerf_job/job/gcode_reader.hpp lib/systemd/system/kerf.service
          etc/kerf/kerf.toml etc/default/kerf usr/share/doc/kerf/examples/kerf.toml)
  if(NOT EXISTS ${root}/${f})
    message(FATAL_ERROR "${deb} lacks /${f}")
  endif()
endforeach()
file(SHA256 ${root}/lib/systemd/system/kerf.service unit_sum)
file(SHA256 ${SOURCE_DIR}/firmware/systemd/kerf.service src_sum)
file(SHA256 ${root}/etc/kerf/kerf.toml toml_sum)
file(SHA256 ${SOURCE_DIR}/firmware/examples/kerf.toml src_toml_sum)
if(NOT unit_sum STREQUAL src_sum OR NOT toml_sum STREQUAL src_toml_sum)
  message(FATAL_ERROR "the packaged unit or config differs from the source tree's")
endif()
file(READ ${root}/lib/systemd/system/kerf.service unit)
if(NOT unit MATCHES "ExecStart=/usr/bin/kerf ")
  message(FATAL_ERROR "the unit does not start /usr/bin/kerf, where the package puts it")
endif()

# Depends names a libc6 at least as new as the newest GLIBC_ symbol version
# kerf needs (for a cross build, Depends is written by hand).
if(OBJDUMP)
  run(${OBJDUMP} -T ${root}/usr/bin/kerf)
  string(REGEX MATCHALL "GLIBC_2\\.[0-9]+" versions "${out}")
  set(need 0)
  foreach(v IN LISTS versions)
    string(REGEX REPLACE "GLIBC_2\\." "" minor ${v})
    if(minor GREATER need)
      set(need ${minor})
    endif()
  endforeach()
  run(dpkg-deb -f ${deb} Depends)
  if(NOT out MATCHES "libc6 \\(>= 2\\.([0-9]+)\\)" OR CMAKE_MATCH_1 LESS need)
    message(FATAL_ERROR "kerf needs GLIBC_2.${need}; Depends says: ${out}")
  endif()
endif()

# Every shared library kerf needs is in Depends (a cross build's libmodbus5
# and libgpiod2 are written by hand), and the binary has no RPATH or RUNPATH
# left (a cross build links them from the build tree's extracted packages).
if(OBJDUMP)
  run(${OBJDUMP} -p ${root}/usr/bin/kerf)
  set(dynamic "${out}")
  if(dynamic MATCHES "(RPATH|RUNPATH) +([^\n]*)")
    message(FATAL_ERROR "the packaged kerf keeps ${CMAKE_MATCH_1} ${CMAKE_MATCH_2}")
  endif()
  string(REGEX MATCHALL "NEEDED +[^\n]+" needed "${dynamic}")
  run(dpkg-deb -f ${deb} Depends)
  set(depends "${out}")
  foreach(entry IN LISTS needed)
    string(REGEX REPLACE "NEEDED +" "" soname "${entry}")
    if(soname MATCHES "^(libc|libm)\\.so\\.6$|^ld-linux")
      set(pkg libc6)
    elseif(soname STREQUAL "libstdc++.so.6")
      set(pkg libstdc\\+\\+6)
    elseif(soname STREQUAL "libgcc_s.so.1")
      set(pkg libgcc-s1)
    elseif(soname STREQUAL "libmodbus.so.5")
      set(pkg libmodbus5)
    elseif(soname STREQUAL "libgpiod.so.2")
      set(pkg libgpiod2)
    elseif(soname MATCHES "^lib(asan|ubsan)\\.so\\.([0-9]+)$")
      set(pkg lib${CMAKE_MATCH_1}${CMAKE_MATCH_2})  # the sanitizer build's runtimes
    else()
      message(FATAL_ERROR "kerf needs ${soname}: add its package to this check and to Depends")
    endif()
    if(NOT depends MATCHES "(^|[ ,])${pkg}( |,|\n|$)")
      message(FATAL_ERROR "kerf needs ${soname}, but Depends lacks its package: ${depends}")
    endif()
    message(STATUS "NEEDED ${soname}: in Depends")
  endforeach()
endif()

# The installed command runs (under qemu-user for a cross build).
set(kerf ${root}/usr/bin/kerf)
run(${EMULATOR} ${kerf} --version)
if(NOT out MATCHES "${VERSION}")
  message(FATAL_ERROR "kerf --version printed: ${out}")
endif()
run(${EMULATOR} ${kerf} fit --tol 0.1 ${POINTS})
if(NOT out MATCHES "Number of arcs is Narc = [1-9]")
  message(FATAL_ERROR "kerf fit printed:\n${out}")
endif()
run(${EMULATOR} ${kerf} fit --tol 0.1 --criterion band --format gcode ${POINTS})
if(NOT out MATCHES "\nG0 X[-0-9.]+ Y[-0-9.]+\nG[23] X")
  message(FATAL_ERROR "kerf fit --format gcode printed:\n${out}")
endif()
