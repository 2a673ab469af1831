// The link's cyclic path (push, status, command) allocates nothing: this
// binary replaces the global operator new and counts calls while the host
// side streams. The board's server thread also runs in this process, so the
// count is per thread: only the calling (host) thread is measured.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>

#include "link_rig.hpp"

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
namespace {

class LinkAllocations : public ::testing::TestWithParam<Wire> {};

TEST_P(LinkAllocations, PushStatusAndCommandDoNotAllocate) {
  RigOptions opt;
  opt.capacity = 64;
  LinkRig rig(GetParam(), opt);
  const auto segs = job(50);  // built before counting
  hal::BoardStatus st;
  g_allocations = 0;
  g_counting = true;
  bool ok = rig.link->command(hal::Command::start) == hal::LinkError::none;
  for (const auto& s : segs) ok = ok && rig.link->push(s, st) == hal::LinkError::none;
  ok = ok && rig.link->status(st) == hal::LinkError::none;
  g_counting = false;
  ASSERT_TRUE(ok) << rig.link->last_error();
  EXPECT_EQ(st.last_accepted, 50u);
  EXPECT_EQ(g_allocations, 0);
  // The counter itself works: a vector allocates.
  g_counting = true;
  std::vector<int> v(10);
  g_counting = false;
  EXPECT_EQ(g_allocations, 1);
}

INSTANTIATE_TEST_SUITE_P(Wires, LinkAllocations, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test
