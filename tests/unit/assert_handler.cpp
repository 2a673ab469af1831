// Tests report a broken core contract with its expression and place, then stop.
#include <cstdio>
#include <cstdlib>

#include "kerf/core/assert.hpp"

extern "C" void kerf_assert_failed(const char* expr, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: contract violated: %s\n", file, line, expr);
  std::abort();
}
