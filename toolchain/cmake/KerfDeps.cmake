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
# A cross build looks for the target's multiarch library
# (/usr/lib/<triple>/libmodbus.so from libmodbus-dev:arm64 / :armhf); its
# headers are arch-independent and exposed through a link, as above, so the
# cross compiler never searches the host's /usr/include. When the target's
# library is not installed, the Modbus parts are left out of that build
# instead of failing it.
function(kerf_find_libmodbus)
  if(CMAKE_CROSSCOMPILING)
    find_library(KERF_MODBUS_LIBRARY modbus PATHS /usr/lib/${KERF_TRIPLE}
                 NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
    if(KERF_MODBUS_LIBRARY AND EXISTS /usr/include/modbus/modbus.h)
      set(KERF_MODBUS_INCLUDE ${CMAKE_BINARY_DIR}/_headers/modbus)
      file(MAKE_DIRECTORY ${KERF_MODBUS_INCLUDE})
      file(CREATE_LINK /usr/include/modbus ${KERF_MODBUS_INCLUDE}/modbus SYMBOLIC)
    endif()
  else()
    find_library(KERF_MODBUS_LIBRARY modbus)
    find_path(KERF_MODBUS_INCLUDE modbus/modbus.h)
  endif()
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
