# Third-party code from Debian packages, as the targets kerf::cli11,
# kerf::tomlplusplus, kerf::modbus and kerf::gpiod.

# A header-only package. With CONFIG, the host build uses the package's own
# CMake config. A cross build cannot: its include folder is the host's
# /usr/include, which a cross compiler must not search (it would find x86-64
# glibc headers), so just the package's header folder is exposed through a
# link in the build tree.
function(kerf_header_only name header_dir)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "CONFIG")
  if(arg_CONFIG AND NOT CMAKE_CROSSCOMPILING)
    list(GET arg_CONFIG 0 package)
    list(GET arg_CONFIG 1 imported)
    find_package(${package} CONFIG REQUIRED)
    add_library(kerf::${name} ALIAS ${imported})
    return()
  endif()
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

# A library through its pkg-config file, as kerf::<name>; sets
# KERF_HAVE_<NAME> and, when found, <PREFIX>_VERSION. A cross build reads only
# the target's .pc files that toolchain/fetch_target_libs.sh extracted into
# KERF_TARGET_LIBS (build/_sysroot/<triple>, set by the toolchain file), as a
# pkg-config sysroot; a cross build without them leaves the library out.
function(kerf_pkg_library name module)
  string(TOUPPER ${name} upper)
  set(prefix KERF_PC_${upper})
  find_package(PkgConfig REQUIRED)
  if(CMAKE_CROSSCOMPILING)
    set(pc_dir ${KERF_TARGET_LIBS}/usr/lib/${KERF_TRIPLE}/pkgconfig)
    if(NOT KERF_TARGET_LIBS OR NOT EXISTS ${pc_dir}/${module}.pc)
      set(KERF_HAVE_${upper} OFF PARENT_SCOPE)
      return()
    endif()
    set(saved_libdir "$ENV{PKG_CONFIG_LIBDIR}")
    set(saved_sysroot "$ENV{PKG_CONFIG_SYSROOT_DIR}")
    set(ENV{PKG_CONFIG_LIBDIR} ${pc_dir})
    set(ENV{PKG_CONFIG_SYSROOT_DIR} ${KERF_TARGET_LIBS})
    # pkg_check_modules finds the library file in the -L folder, under the sysroot.
    list(APPEND CMAKE_FIND_ROOT_PATH ${KERF_TARGET_LIBS})
  endif()
  pkg_check_modules(${prefix} QUIET IMPORTED_TARGET GLOBAL ${module})
  if(CMAKE_CROSSCOMPILING)
    set(ENV{PKG_CONFIG_LIBDIR} "${saved_libdir}")
    set(ENV{PKG_CONFIG_SYSROOT_DIR} "${saved_sysroot}")
  endif()
  set(KERF_HAVE_${upper} ${${prefix}_FOUND} PARENT_SCOPE)
  if(NOT ${prefix}_FOUND)
    return()
  endif()
  set(${prefix}_VERSION ${${prefix}_VERSION} PARENT_SCOPE)
  # The extracted libraries are not where the target's linker looks for their
  # own dependencies (the toolchain file's emulator sets LD_LIBRARY_PATH).
  if(CMAKE_CROSSCOMPILING)
    set_property(TARGET PkgConfig::${prefix} APPEND PROPERTY INTERFACE_LINK_OPTIONS
                 "LINKER:-rpath-link,${KERF_TARGET_LIBS}/usr/lib/${KERF_TRIPLE}")
  endif()
  add_library(kerf::${name} ALIAS PkgConfig::${prefix})
endfunction()

# libmodbus (libmodbus-dev) for hal's Modbus backend and the simulated board.
# Without it the Modbus parts are left out of the build instead of failing it.
function(kerf_find_libmodbus)
  kerf_pkg_library(modbus libmodbus)
  if(NOT KERF_HAVE_MODBUS)
    message(STATUS "kerf: libmodbus not found for ${CMAKE_SYSTEM_PROCESSOR}: the Modbus "
                   "backend (kerf run keeps CAN), the simulated motion board and `kerf-sim sim` are not built (install libmodbus-dev for the target)")
  endif()
  set(KERF_HAVE_MODBUS ${KERF_HAVE_MODBUS} PARENT_SCOPE)
endfunction()

# libgpiod (libgpiod-dev) for hal's GPIO backend. Its version picks the API:
# 1.x compiles hal/gpio/src/gpiod_v1.cpp, 2.x gpiod_v2.cpp with KERF_GPIOD_V2
# defined. Without it the GPIO backend is left out (the simulated GPIO in sim/
# is still built). -DKERF_WITH_GPIOD=OFF leaves it out on purpose, to check
# that the build stands without it.
option(KERF_WITH_GPIOD "Build the libgpiod GPIO backend when libgpiod is found" ON)
function(kerf_find_libgpiod)
  set(KERF_HAVE_GPIOD OFF PARENT_SCOPE)
  if(NOT KERF_WITH_GPIOD)
    message(STATUS "kerf: KERF_WITH_GPIOD=OFF: the libgpiod backend is not built")
    return()
  endif()
  kerf_pkg_library(gpiod libgpiod)
  if(NOT KERF_HAVE_GPIOD)
    message(STATUS "kerf: libgpiod not found for ${CMAKE_SYSTEM_PROCESSOR}: the GPIO backend "
                   "is not built (install libgpiod-dev for the target)")
    return()
  endif()
  set(KERF_HAVE_GPIOD ON PARENT_SCOPE)
  if(KERF_PC_GPIOD_VERSION VERSION_GREATER_EQUAL 2)
    set(KERF_GPIOD_V2 ON PARENT_SCOPE)
  else()
    set(KERF_GPIOD_V2 OFF PARENT_SCOPE)
  endif()
  message(STATUS "kerf: libgpiod ${KERF_PC_GPIOD_VERSION} found: GPIO backend built")
endfunction()
