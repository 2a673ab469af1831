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

# A cross build's target libraries: first the Debian packages that
# toolchain/fetch_target_libs.sh extracts into KERF_TARGET_LIBS (set by the
# toolchain file: build/_sysroot/<triple>), then the multiarch folder
# /usr/lib/<triple> (libfoo-dev:arm64 installed through dpkg multiarch). The
# library's headers come from the same place and are exposed through a link
# in the build tree, as above, so the cross compiler never searches a whole
# include folder. Sets <var>_LIBRARY (cache) and <var>_INCLUDE_ROOT.
function(kerf_find_target_library var name header)
  set(dirs /usr/lib/${KERF_TRIPLE})
  if(KERF_TARGET_LIBS)
    list(PREPEND dirs ${KERF_TARGET_LIBS}/usr/lib/${KERF_TRIPLE})
  endif()
  find_library(${var}_LIBRARY ${name} PATHS ${dirs} NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
  set(root /usr/include)
  if(KERF_TARGET_LIBS AND ${var}_LIBRARY MATCHES "^${KERF_TARGET_LIBS}/")
    set(root ${KERF_TARGET_LIBS}/usr/include)
  endif()
  if(${var}_LIBRARY AND EXISTS ${root}/${header})
    set(${var}_INCLUDE_ROOT ${root} PARENT_SCOPE)
  else()
    set(${var}_INCLUDE_ROOT "" PARENT_SCOPE)
  endif()
endfunction()

# An extracted library is not where the target's loader looks: the linker is
# told where its own dependencies are (-rpath-link), and the toolchain file's
# emulator sets LD_LIBRARY_PATH for qemu-user.
function(kerf_link_target_library dep library)
  target_link_libraries(${dep} INTERFACE ${library})
  get_filename_component(dir ${library} DIRECTORY)
  if(CMAKE_CROSSCOMPILING AND NOT dir STREQUAL "/usr/lib/${KERF_TRIPLE}")
    target_link_options(${dep} INTERFACE "LINKER:-rpath-link,${dir}")
  endif()
endfunction()

# libmodbus (libmodbus-dev) for hal's Modbus backend and the simulated board.
# A cross build looks for the target's library as kerf_find_target_library
# says. When it is not there, the Modbus parts are left out of that build
# instead of failing it.
function(kerf_find_libmodbus)
  if(CMAKE_CROSSCOMPILING)
    kerf_find_target_library(KERF_MODBUS modbus modbus/modbus.h)
    if(KERF_MODBUS_INCLUDE_ROOT)
      set(KERF_MODBUS_INCLUDE ${CMAKE_BINARY_DIR}/_headers/modbus)
      file(MAKE_DIRECTORY ${KERF_MODBUS_INCLUDE})
      file(CREATE_LINK ${KERF_MODBUS_INCLUDE_ROOT}/modbus ${KERF_MODBUS_INCLUDE}/modbus SYMBOLIC)
    endif()
  else()
    find_library(KERF_MODBUS_LIBRARY modbus)
    find_path(KERF_MODBUS_INCLUDE modbus/modbus.h)
  endif()
  if(KERF_MODBUS_LIBRARY AND KERF_MODBUS_INCLUDE)
    add_library(kerf_dep_modbus INTERFACE)
    kerf_link_target_library(kerf_dep_modbus ${KERF_MODBUS_LIBRARY})
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
# KERF_GPIOD_V2 defined. A cross build looks for the target's library and
# libgpiod.pc as for libmodbus; without it the GPIO backend is left out (the
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
      if(KERF_TARGET_LIBS)
        set(ENV{PKG_CONFIG_LIBDIR} "${KERF_TARGET_LIBS}/usr/lib/${KERF_TRIPLE}/pkgconfig:$ENV{PKG_CONFIG_LIBDIR}")
      endif()
      pkg_check_modules(KERF_GPIOD_PC QUIET libgpiod)
      set(ENV{PKG_CONFIG_LIBDIR} "${saved}")
    else()
      pkg_check_modules(KERF_GPIOD_PC QUIET libgpiod)
    endif()
  endif()
  if(CMAKE_CROSSCOMPILING)
    kerf_find_target_library(KERF_GPIOD gpiod gpiod.h)
    if(KERF_GPIOD_INCLUDE_ROOT)
      set(KERF_GPIOD_INCLUDE ${CMAKE_BINARY_DIR}/_headers/gpiod)
      file(MAKE_DIRECTORY ${KERF_GPIOD_INCLUDE})
      file(CREATE_LINK ${KERF_GPIOD_INCLUDE_ROOT}/gpiod.h ${KERF_GPIOD_INCLUDE}/gpiod.h SYMBOLIC)
    endif()
  else()
    find_library(KERF_GPIOD_LIBRARY gpiod)
    find_path(KERF_GPIOD_INCLUDE gpiod.h)
  endif()
  if(KERF_GPIOD_LIBRARY AND KERF_GPIOD_INCLUDE AND KERF_GPIOD_PC_VERSION)
    add_library(kerf_dep_gpiod INTERFACE)
    kerf_link_target_library(kerf_dep_gpiod ${KERF_GPIOD_LIBRARY})
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
