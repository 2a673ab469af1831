# Bare-metal Cortex-M0 (arm-none-eabi, newlib; ARMv6-M, no FPU, no divide instruction). Only the freestanding core is
# built (the preset sets KERF_CORE_ONLY=ON and KERF_CORE_FIXED_ONLY=ON: no FPU, so only
# the kerf::Fixed instantiations); the build prints its size and
# fails if it needs an allocator, exceptions, stdio or system calls.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR cortex-m0)

set(CMAKE_C_COMPILER   arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)

# No OS to link a test program against: compiler checks build a static library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(KERF_CPU_FLAGS "-mcpu=cortex-m0 -mthumb -mfloat-abi=soft")
set(CMAKE_C_FLAGS_INIT   "${KERF_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${KERF_CPU_FLAGS} -ffunction-sections -fdata-sections -fno-exceptions -fno-rtti")
set(CMAKE_ASM_FLAGS_INIT "${KERF_CPU_FLAGS}")

set(KERF_TRIPLE arm-none-eabi)
set(KERF_TARGET_ROOT /usr/lib/arm-none-eabi)
include(${CMAKE_CURRENT_LIST_DIR}/cmake/CrossBinutils.cmake)
