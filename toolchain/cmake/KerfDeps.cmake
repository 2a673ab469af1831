# Third-party code from Debian packages.

# Header-only packages live in the host's /usr/include, which a cross compiler
# must not search (it would find x86-64 glibc headers). Expose just the one
# package's header folder through a link in the build tree instead.
function(kerf_header_only name header_dir)
  if(NOT EXISTS /usr/include/${header_dir})
    message(FATAL_ERROR "/usr/include/${header_dir} not found: run toolchain/setup.sh")
  endif()
  set(dir ${CMAKE_BINARY_DIR}/_headers/${name})
  file(MAKE_DIRECTORY ${dir})
  file(CREATE_LINK /usr/include/${header_dir} ${dir}/${header_dir} SYMBOLIC)
  add_library(kerf_dep_${name} INTERFACE)
  target_include_directories(kerf_dep_${name} SYSTEM INTERFACE ${dir})
  add_library(kerf::${name} ALIAS kerf_dep_${name})
endfunction()

# libmodbus (libmodbus-dev) for hal's Modbus backend and the simulated board.
# A cross build searches only the target's multiarch folders; when the
# target's package (libmodbus-dev:arm64 / :armhf) is not installed, the Modbus
# parts are left out of that build instead of failing it.
function(kerf_find_libmodbus)
  if(CMAKE_CROSSCOMPILING)
    set(hints PATHS /usr/lib/${KERF_TRIPLE} /usr/include/${KERF_TRIPLE} NO_DEFAULT_PATH)
  endif()
  find_library(KERF_MODBUS_LIBRARY modbus ${hints})
  find_path(KERF_MODBUS_INCLUDE modbus/modbus.h ${hints})
  if(KERF_MODBUS_LIBRARY AND KERF_MODBUS_INCLUDE)
    add_library(kerf_dep_modbus INTERFACE)
    target_link_libraries(kerf_dep_modbus INTERFACE ${KERF_MODBUS_LIBRARY})
    target_include_directories(kerf_dep_modbus SYSTEM INTERFACE ${KERF_MODBUS_INCLUDE})
    add_library(kerf::modbus ALIAS kerf_dep_modbus)
    set(KERF_HAVE_MODBUS ON PARENT_SCOPE)
  else()
    message(STATUS "kerf: libmodbus not found for ${CMAKE_SYSTEM_PROCESSOR}: the Modbus "
                   "backend, sim/ and `kerf sim` are not built (install libmodbus-dev for the target)")
    set(KERF_HAVE_MODBUS OFF PARENT_SCOPE)
  endif()
endfunction()
