// What every fuzz target does on a broken promise: say which and abort, so
// libFuzzer keeps the input as a crash-* reproducer.
#pragma once

#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(cond, what)                                                     \
  do {                                                                             \
    if (!(cond)) {                                                                 \
      std::fprintf(stderr, "%s:%d: fuzz check failed: %s (%s)\n", __FILE__, __LINE__, \
                   #cond, what);                                                   \
      std::abort();                                                                \
    }                                                                              \
  } while (0)
