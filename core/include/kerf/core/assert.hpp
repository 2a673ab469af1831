// One hook for contract violations. The build chooses what it does through
// KERF_ASSERT_MODE: 0 = compiled out, 1 = call kerf_assert_failed (default).
// core/ never throws; the default handler is __builtin_trap, and a host build
// may link its own kerf_assert_failed (tests do, to report file and line).
#pragma once

#ifndef KERF_ASSERT_MODE
#define KERF_ASSERT_MODE 1
#endif

extern "C" [[noreturn]] void kerf_assert_failed(const char* expr, const char* file, int line);

#if KERF_ASSERT_MODE == 0
#define KERF_ASSERT(cond) static_cast<void>(sizeof(cond))
#else
#define KERF_ASSERT(cond) \
  ((cond) ? static_cast<void>(0) : kerf_assert_failed(#cond, __FILE__, __LINE__))
#endif
