# Shared by the cross toolchain files. Set KERF_TRIPLE (the Debian tool
# prefix) and KERF_TARGET_ROOT (where the target's headers and libraries
# live) before including this.
#
# Debian's cross compilers are not sysroot based: they already search
# KERF_TARGET_ROOT. Point find_* there too, never at the host's /usr/include
# or /usr/lib.
set(CMAKE_FIND_ROOT_PATH ${KERF_TARGET_ROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# The target's binutils, so the core symbol check (CMAKE_NM) reads the right
# object format and the size report (CMAKE_SIZE) is the target's.
foreach(tool AR RANLIB NM OBJCOPY OBJDUMP STRIP SIZE)
  string(TOLOWER ${tool} name)
  find_program(CMAKE_${tool} ${KERF_TRIPLE}-${name} REQUIRED)
endforeach()
