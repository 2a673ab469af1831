// The scalar types the core library is instantiated for: kerf::Fixed always,
// double unless the target has no FPU (KERF_CORE_FIXED_ONLY, the Cortex-M0
// build). Each src/*.cpp lists its instantiations once, as a macro of S,
// and applies it to every type here.
#pragma once

#ifdef KERF_CORE_FIXED_ONLY
#define KERF_FOR_EACH_SCALAR(list) list(Fixed)
#else
#define KERF_FOR_EACH_SCALAR(list) list(Fixed) list(double)
#endif
