// The replaced global operator new of tests/link/alloc_trap.hpp.
#include "alloc_trap.hpp"

#include <cstdlib>
#include <new>

namespace {
thread_local bool g_counting = false;
thread_local long g_allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace kerf::test {

void alloc_trap_start() {
  g_allocations = 0;
  g_counting = true;
}
void alloc_trap_pause() { g_counting = false; }
void alloc_trap_resume() { g_counting = true; }
void alloc_trap_stop() { g_counting = false; }
long alloc_trap_count() { return g_allocations; }

}  // namespace kerf::test
