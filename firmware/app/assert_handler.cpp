// A core contract violation is a bug in kerf, never a reaction to input: say
// where it happened before stopping, instead of core's silent trap.
#include <cstdio>
#include <cstdlib>

#include "kerf/core/assert.hpp"

extern "C" void kerf_assert_failed(const char* expr, const char* file, int line) {
  std::fprintf(stderr, "kerf: internal error: assertion %s failed at %s:%d\n", expr, file, line);
  std::abort();
}
