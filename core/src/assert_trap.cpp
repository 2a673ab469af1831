// The default contract-violation handler: stop dead. It is weak so that a
// host build (the tests) can link one that reports the expression and line.
#include "kerf/core/assert.hpp"

extern "C" __attribute__((weak)) void kerf_assert_failed(const char*, const char*, int) {
  __builtin_trap();
}
