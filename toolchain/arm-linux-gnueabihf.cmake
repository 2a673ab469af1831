# Cross build for 32-bit ARM Linux, hard float (armhf SBC) with Debian's cross
# compiler (g++-arm-linux-gnueabihf). Test binaries run under qemu-user through
# CMAKE_CROSSCOMPILING_EMULATOR (ctest and gtest_discover_tests use it).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(KERF_TRIPLE arm-linux-gnueabihf)
set(KERF_TARGET_ROOT /usr/${KERF_TRIPLE})

set(CMAKE_C_COMPILER   ${KERF_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${KERF_TRIPLE}-g++)
include(${CMAKE_CURRENT_LIST_DIR}/cmake/CrossBinutils.cmake)

set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm;-L;${KERF_TARGET_ROOT})
