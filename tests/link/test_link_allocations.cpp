// The link's cyclic path (push, status, command) allocates nothing: this
// binary replaces the global operator new and counts calls while the host
// side streams. The board's server thread also runs in this process, so the
// count is per thread: only the calling (host) thread is measured.
#include <gtest/gtest.h>


#include "alloc_trap.hpp"
#include "link_rig.hpp"

namespace kerf::test {
namespace {

class LinkAllocations : public ::testing::TestWithParam<Wire> {};

TEST_P(LinkAllocations, PushStatusAndCommandDoNotAllocate) {
  RigOptions opt;
  opt.capacity = 64;
  LinkRig rig(GetParam(), opt);
  const auto segs = job(50);  // built before counting
  hal::BoardStatus st;
  alloc_trap_start();
  bool ok = rig.link->command(hal::Command::start) == hal::LinkError::none;
  for (const auto& s : segs) ok = ok && rig.link->push(s, st) == hal::LinkError::none;
  ok = ok && rig.link->status(st) == hal::LinkError::none;
  alloc_trap_pause();
  ASSERT_TRUE(ok) << rig.link->last_error();
  EXPECT_EQ(st.last_accepted, 50u);
  EXPECT_EQ(alloc_trap_count(), 0);
  // The counter itself works: a vector allocates.
  alloc_trap_resume();
  std::vector<int> v(10);
  alloc_trap_pause();
  EXPECT_EQ(alloc_trap_count(), 1);
}

INSTANTIATE_TEST_SUITE_P(Wires, LinkAllocations, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test
