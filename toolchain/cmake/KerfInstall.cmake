# Installing kerf (`cmake --install`) and packaging it as a .deb (`cpack`).
#
# cmake --install BUILD [--prefix P] puts in P:
#   bin/kerf                              the command (no simulator in it)
#   bin/kerf-sim, bin/kerf-board-sim,     the simulator and the bench's board and
#   bin/kerf-drive-sim                    drives (component sim)
#   lib/libkerf_core.a, lib/libkerf_io.a, the fitting core, the point-file and
#   lib/libkerf_job.a                     fit-output I/O, and the job reader
#                                         (G-code) and fitting pipeline on top
#   include/kerf/...                      the core's headers (#include <kerf/fit/fit.hpp>)
#   include/kerf_io/io/...                kerf_io's (#include <io/fit_output.hpp>)
#   include/kerf_job/job/...              kerf_job's (#include <job/gcode_reader.hpp>)
#   lib/cmake/kerf/                       find_package(kerf): kerf::core, kerf::io, kerf::job
#   lib/pkgconfig/kerf.pc                 pkg-config --cflags --libs kerf
#   share/kerf/systemd/kerf.service       the unit and the example configuration,
#   share/doc/kerf/examples/kerf.toml     for reference
#
# Two .debs (cpack -G DEB in the build folder): kerf (components runtime, dev
# and system) and kerf-sim (component sim), so that what is flashed onto a
# machine need not carry the simulator. kerf installs under /usr and adds, as
# component "system" (never part of a plain `cmake --install`, so that a local
# install cannot touch the host's /etc or /lib), the unit as
# /lib/systemd/system/kerf.service and the configuration as the conffiles
# /etc/kerf/kerf.toml and /etc/default/kerf.
#
# The libraries are static and kerf links them in: the package's run-time
# dependencies are the C and C++ runtimes, plus libmodbus and libgpiod where
# the build found them (the host). dpkg-shlibdeps computes Depends for a
# native build; it cannot read a cross build's target libraries (they are not
# in the host's dpkg database: toolchain/fetch_target_libs.sh only extracts
# them), so a cross build states them by hand.

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(kerf_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/kerf)
set(kerf_io_includedir ${CMAKE_INSTALL_INCLUDEDIR}/kerf_io)
set(kerf_job_includedir ${CMAKE_INSTALL_INCLUDEDIR}/kerf_job)

# Consumers compile the headers as C++20, as kerf does.
target_compile_features(kerf_core INTERFACE cxx_std_20)
set_target_properties(kerf_core PROPERTIES EXPORT_NAME core)
set_target_properties(kerf_io PROPERTIES EXPORT_NAME io)
set_target_properties(kerf_job PROPERTIES EXPORT_NAME job)

install(TARGETS kerf RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(TARGETS kerf-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT sim)
foreach(tool kerf-board-sim kerf-drive-sim)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT sim)
  endif()
endforeach()
install(TARGETS kerf_core kerf_io kerf_job EXPORT kerfTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
# The core's headers a consumer compiles: the fit entry headers (fit.hpp,
# band.hpp, biarc.hpp, stream.hpp, stream_band.hpp), what they include, and
# the core, geometry and motion headers. The fitters' definitions
# (fit/band/pair.hpp, fit/biarc/joints.hpp, ...) stay behind: the library
# holds their instantiations.
set(kerf_core_include ${PROJECT_SOURCE_DIR}/core/include)
function(kerf_include_closure out)
  set(pending ${ARGN})
  set(done "")
  while(pending)
    list(POP_FRONT pending header)
    if(header IN_LIST done)
      continue()
    endif()
    list(APPEND done ${header})
    file(STRINGS ${kerf_core_include}/${header} includes REGEX "^#include \"kerf/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
      list(APPEND pending ${included})
    endforeach()
  endwhile()
  set(${out} ${done} PARENT_SCOPE)
endfunction()
file(GLOB kerf_fit_entries RELATIVE ${kerf_core_include} ${kerf_core_include}/kerf/fit/*.hpp)
file(GLOB_RECURSE kerf_base_headers RELATIVE ${kerf_core_include}
  ${kerf_core_include}/kerf/core/*.hpp ${kerf_core_include}/kerf/geom/*.hpp
  ${kerf_core_include}/kerf/motion/*.hpp)
kerf_include_closure(kerf_installed_headers ${kerf_fit_entries} ${kerf_base_headers})
foreach(header IN LISTS kerf_installed_headers)
  get_filename_component(header_dir ${header} DIRECTORY)
  install(FILES ${kerf_core_include}/${header}
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${header_dir} COMPONENT dev)
endforeach()
file(GLOB kerf_io_headers ${PROJECT_SOURCE_DIR}/firmware/io/*.hpp)
install(FILES ${kerf_io_headers} DESTINATION ${kerf_io_includedir}/io COMPONENT dev)
file(GLOB kerf_job_headers ${PROJECT_SOURCE_DIR}/firmware/job/*.hpp)
install(FILES ${kerf_job_headers} DESTINATION ${kerf_job_includedir}/job COMPONENT dev)

install(EXPORT kerfTargets NAMESPACE kerf:: DESTINATION ${kerf_cmake_dir} COMPONENT dev)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/kerfConfig.cmake.in
  ${CMAKE_BINARY_DIR}/pack/kerfConfig.cmake INSTALL_DESTINATION ${kerf_cmake_dir})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/pack/kerfConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/pack/kerfConfig.cmake
              ${CMAKE_BINARY_DIR}/pack/kerfConfigVersion.cmake
  DESTINATION ${kerf_cmake_dir} COMPONENT dev)

# kerf.pc finds the prefix from its own place, so that it stays right under
# any --prefix and inside the .deb.
file(RELATIVE_PATH kerf_pc_to_prefix /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
string(REGEX REPLACE "/$" "" kerf_pc_to_prefix "${kerf_pc_to_prefix}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/kerf.pc.in ${CMAKE_BINARY_DIR}/pack/kerf.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/pack/kerf.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

install(FILES ${PROJECT_SOURCE_DIR}/firmware/systemd/kerf.service
  DESTINATION ${CMAKE_INSTALL_DATADIR}/kerf/systemd COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/firmware/examples/kerf.toml
  DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples COMPONENT runtime)

# Only in the package: absolute paths, hence DESTDIR staging (CPACK_SET_DESTDIR).
install(FILES ${PROJECT_SOURCE_DIR}/firmware/systemd/kerf.service
  DESTINATION /lib/systemd/system COMPONENT system EXCLUDE_FROM_ALL)
install(FILES ${PROJECT_SOURCE_DIR}/firmware/examples/kerf.toml
  DESTINATION /etc/kerf COMPONENT system EXCLUDE_FROM_ALL)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/kerf.default
  DESTINATION /etc/default RENAME kerf COMPONENT system EXCLUDE_FROM_ALL)

# --- CPack: two .debs, kerf (runtime, dev, system) and kerf-sim (sim) ---------
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(kerf_deb_arch amd64)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
  set(kerf_deb_arch arm64)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^arm")
  set(kerf_deb_arch armhf)
else()
  set(kerf_deb_arch ${CMAKE_SYSTEM_PROCESSOR})
endif()
set(KERF_DEB_ARCH ${kerf_deb_arch} CACHE INTERNAL "Debian architecture of this build")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME kerf)
set(CPACK_PACKAGE_VENDOR kerf)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "kerf maintainers <kerf@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Controller for NC thermal-cutting machines (plasma, oxy, laser)")
set(CPACK_PACKAGE_DESCRIPTION
  "kerf fits cutting paths with the fewest arcs within a tolerance, welds G-code polylines into arcs, and runs jobs on the machine (systemd unit kerf.service). Includes the static libraries, headers, CMake package and pkg-config file.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_PREFIX /usr)  # what the DESTDIR install below uses
set(CPACK_SET_DESTDIR ON)  # the "system" component installs to /etc and /lib
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ONE_PER_GROUP)
set(CPACK_COMPONENTS_ALL runtime dev system sim)
set(CPACK_COMPONENT_RUNTIME_GROUP kerf)
set(CPACK_COMPONENT_DEV_GROUP kerf)
set(CPACK_COMPONENT_SYSTEM_GROUP kerf)
set(CPACK_COMPONENT_SIM_GROUP sim)
set(CPACK_DEBIAN_KERF_PACKAGE_NAME kerf)
set(CPACK_DEBIAN_SIM_PACKAGE_NAME kerf-sim)
set(CPACK_DEBIAN_SIM_DESCRIPTION
  "kerf-sim runs the kerf controller on simulated machines (kerf-sim sim), kerf run's loop with scripted lines against the bench's simulators (kerf-sim run), and the simulated Modbus motion board and CiA 402 drives as processes (kerf-board-sim, kerf-drive-sim). Not for a machine's controller.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # kerf_0.1.0_amd64.deb, kerf-sim_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${kerf_deb_arch})
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.invalid/kerf")
if(CMAKE_CROSSCOMPILING)
  # Debian 12's (bookworm's) runtimes, what the cross compiler links against
  # (pack_deb checks libc6 against the GLIBC_ versions the binary needs, and
  # that every shared library kerf needs is named here), and libmodbus and
  # libgpiod as their bookworm packages' shlibs files give them.
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
  set(kerf_deb_depends "libc6 (>= 2.35), libgcc-s1 (>= 3.0), libstdc++6 (>= 12)")
  set(kerf_sim_deb_depends "${kerf_deb_depends}")
  if(KERF_HAVE_MODBUS)  # kerf run's Modbus link (machine/), kerf-sim sim's board
    string(APPEND kerf_deb_depends ", libmodbus5 (>= 3.1.6)")
    string(APPEND kerf_sim_deb_depends ", libmodbus5 (>= 3.1.6)")
  else()
    message(STATUS "kerf: the ${kerf_deb_arch} .deb's kerf run has the CAN link only (no libmodbus for the target)")
  endif()
  if(KERF_HAVE_GPIOD)  # kerf run's lines (machine/, linked by both)
    string(APPEND kerf_deb_depends ", libgpiod2 (>= 1.6.3)")
    string(APPEND kerf_sim_deb_depends ", libgpiod2 (>= 1.6.3)")
  endif()
  set(CPACK_DEBIAN_KERF_PACKAGE_DEPENDS "${kerf_deb_depends}")
  set(CPACK_DEBIAN_SIM_PACKAGE_DEPENDS "${kerf_sim_deb_depends}")
else()
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
endif()
set(CPACK_DEBIAN_KERF_PACKAGE_CONTROL_EXTRA ${CMAKE_CURRENT_LIST_DIR}/deb/conffiles)
include(CPack)
