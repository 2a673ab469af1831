// The Cortex-M programs' contract-violation handler: print where through
// semihosting (the tests fail on "contract violated"), then stop.
#include <cstdio>

#include "kerf/core/assert.hpp"

extern "C" void kerf_assert_failed(const char* expr, const char* file, int line) {
  std::printf("%s:%d: contract violated: %s\n", file, line, expr);
  for (;;) {
  }
}
