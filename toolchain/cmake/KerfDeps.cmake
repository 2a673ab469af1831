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
                   "backend, the simulated motion board and `kerf sim` are not built (install libmodbus-dev for the target)")
    set(KERF_HAVE_MODBUS OFF PARENT_SCOPE)
  endif()
endfunction()

# libgpiod (libgpiod-dev) for hal's GPIO backend. Its pkg-config version picks
# the API: 1.x compiles hal/gpio/src/gpiod_v1.cpp, 2.x gpiod_v2.cpp with
# KERF_GPIOD_V2 defined. A cross build looks only in the target's multiarch
# folders (libgpiod-dev:arm64 / :armhf) and exposes the one header through a
# link, as for libmodbus; without it the GPIO backend is left out (the
# simulated GPIO in sim/ is still built). -DKERF_WITH_GPIOD=OFF leaves it out
# on purpose, to check that the build stands without it.
option(KERF_WITH_GPIOD "Build the libgpiod GPIO backend when libgpiod is found" ON)
function(kerf_find_libgpiod)
  set(KERF_HAVE_GPIOD OFF PARENT_SCOPE)
  if(NOT KERF_WITH_GPIOD)
    message(STATUS "kerf: KERF_WITH_GPIOD=OFF: the libgpiod backend is not built")
    return()
  endif()
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    if(CMAKE_CROSSCOMPILING)
      set(saved "$ENV{PKG_CONFIG_LIBDIR}")
      set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/${KERF_TRIPLE}/pkgconfig")
      pkg_check_modules(KERF_GPIOD_PC QUIET libgpiod)
      set(ENV{PKG_CONFIG_LIBDIR} "${saved}")
    else()
      pkg_check_modules(KERF_GPIOD_PC QUIET libgpiod)
    endif()
  endif()
  if(CMAKE_CROSSCOMPILING)
    find_library(KERF_GPIOD_LIBRARY gpiod PATHS /usr/lib/${KERF_TRIPLE}
                 NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
    if(KERF_GPIOD_LIBRARY AND EXISTS /usr/include/gpiod.h)
      set(KERF_GPIOD_INCLUDE ${CMAKE_BINARY_DIR}/_headers/gpiod)
      file(MAKE_DIRECTORY ${KERF_GPIOD_INCLUDE})
      file(CREATE_LINK /usr/include/gpiod.h ${KERF_GPIOD_INCLUDE}/gpiod.h SYMBOLIC)
    endif()
  else()
    find_library(KERF_GPIOD_LIBRARY gpiod)
    find_path(KERF_GPIOD_INCLUDE gpiod.h)
  endif()
  if(KERF_GPIOD_LIBRARY AND KERF_GPIOD_INCLUDE AND KERF_GPIOD_PC_VERSION)
    add_library(kerf_dep_gpiod INTERFACE)
    target_link_libraries(kerf_dep_gpiod INTERFACE ${KERF_GPIOD_LIBRARY})
    target_include_directories(kerf_dep_gpiod SYSTEM INTERFACE ${KERF_GPIOD_INCLUDE})
    add_library(kerf::gpiod ALIAS kerf_dep_gpiod)
    set(KERF_HAVE_GPIOD ON PARENT_SCOPE)
    if(KERF_GPIOD_PC_VERSION VERSION_GREATER_EQUAL 2)
      set(KERF_GPIOD_V2 ON PARENT_SCOPE)
    else()
      set(KERF_GPIOD_V2 OFF PARENT_SCOPE)
    endif()
    message(STATUS "kerf: libgpiod ${KERF_GPIOD_PC_VERSION} found: GPIO backend built")
  else()
    message(STATUS "kerf: libgpiod not found for ${CMAKE_SYSTEM_PROCESSOR}: the GPIO backend "
                   "is not built (install libgpiod-dev for the target)")
  endif()
endfunction()
