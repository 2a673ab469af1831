# Cross build for 64-bit ARM Linux (the SBC) with Debian's cross compiler
# (g++-aarch64-linux-gnu). Test binaries run under qemu-user through
# CMAKE_CROSSCOMPILING_EMULATOR (ctest and gtest_discover_tests use it).
# Floating point matches the host: the top-level CMakeLists.txt turns off
# fused multiply-add contraction, which aarch64 GCC would otherwise apply.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(KERF_TRIPLE aarch64-linux-gnu)
set(KERF_TARGET_ROOT /usr/${KERF_TRIPLE})

set(CMAKE_C_COMPILER   ${KERF_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${KERF_TRIPLE}-g++)
include(${CMAKE_CURRENT_LIST_DIR}/cmake/CrossBinutils.cmake)

# The target's libmodbus and libgpiod, extracted from Debian's arm64 packages
# by toolchain/fetch_target_libs.sh (KerfDeps.cmake links them from there).
# Under qemu-user the loader and libc stay the cross toolchain's (-L); only
# those two libraries come from LD_LIBRARY_PATH, which holds nothing else.
cmake_path(ABSOLUTE_PATH CMAKE_CURRENT_LIST_DIR NORMALIZE OUTPUT_VARIABLE kerf_toolchain_dir)
set(KERF_TARGET_LIBS ${kerf_toolchain_dir}/../build/_sysroot/${KERF_TRIPLE})
cmake_path(NORMAL_PATH KERF_TARGET_LIBS)

set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64;-L;${KERF_TARGET_ROOT}
    -E;LD_LIBRARY_PATH=${KERF_TARGET_LIBS}/usr/lib/${KERF_TRIPLE})
