// A z axis over CANopen CSP: a third CiA 402 node on the in-process bus. The
// link runs z moves at rest in XY and sends the z target every SYNC beside x
// and y; the z drive ends on the z moves' ends; a z axis without a third
// drive is refused at creation.
#include <cmath>

#include "can_rig.hpp"

namespace kerf::test {
namespace {

using hal::BoardState;
using hal::LinkError;
using namespace hal::canopen;

hal::CspConfig z_config() {
  hal::CspConfig c;
  c.z = {0.001, 30.0, 500.0};  // the period is the SYNC's
  c.z_counts_per_mm = 400.0;
  return c;
}

hal::SegmentCommand line(std::uint32_t seq, double x) {
  hal::SegmentCommand s;
  s.seq = seq;
  s.end = {x, 0.0};
  s.feed = 50.0;
  return s;
}

hal::SegmentCommand z_move(std::uint32_t seq, double x, double z) {
  hal::SegmentCommand s = line(seq, x);
  s.z_move = true;
  s.z = z;
  s.feed = 30.0;
  return s;
}

TEST(CanZ, ZMovesRunOnTheThirdDriveAtRestInXy) {
  CanRig rig(3);
  rig.up();
  std::string err;
  auto link = hal::CspSegmentLink::create(*rig.master, z_config(), err);
  ASSERT_TRUE(link) << err;
  hal::BoardStatus st;
  for (const hal::SegmentCommand& s : {line(1, 5), z_move(2, 5, -2), line(3, 10), z_move(4, 10, 3)})
    ASSERT_EQ(link->push(s, st), LinkError::none) << link->last_error();
  ASSERT_EQ(link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(link->command(hal::Command::finish), LinkError::none);
  for (int i = 0; i < 20000 && st.state != BoardState::done && st.state != BoardState::fault; ++i) {
    link->cycle();
    link->status(st);
  }
  ASSERT_EQ(st.state, BoardState::done) << link->last_error();
  EXPECT_EQ(link->executed(), (std::vector<std::uint32_t>{1, 2, 3, 4}));
  EXPECT_DOUBLE_EQ(st.z, 3.0);
  EXPECT_EQ(rig.bus.drive(2).actual(), 1200);  // 3 mm at 400 counts/mm
  EXPECT_EQ(rig.bus.drive(0).actual(), 10000);
  // z changes only while a z move runs, and then x and y stand still.
  const std::vector<hal::CspSample> trace = link->trace();
  ASSERT_EQ(trace.size(), link->trace_total()) << "the trace ring wrapped";
  std::int64_t lowest = 0;
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const hal::CspSample& a = trace[k - 1];
    const hal::CspSample& b = trace[k];
    lowest = std::min(lowest, b.target_z);
    if (b.target_z != a.target_z) {
      EXPECT_EQ(b.target[0], a.target[0]) << "cycle " << b.cycle;
      EXPECT_EQ(b.target[1], a.target[1]);
      EXPECT_TRUE(b.seq == 2 || b.seq == 4 || b.seq == 0) << b.seq;
    }
  }
  EXPECT_EQ(lowest, -800);
  // Every SYNC after bring-up carries one setpoint for each of the 3 nodes.
  std::size_t since[4] = {}, syncs = 0, bad = 0;
  for (const sim::LoggedFrame& l : rig.bus.log()) {
    if (!l.from_master) continue;
    if ((l.frame.id & 0x780) == kRpdo1 && (l.frame.id & 0x7F) <= 3) ++since[l.frame.id & 0x7F];
    if (l.frame.id == kSync) {
      ++syncs;
      for (int n = 1; n <= 3; ++n) {
        if (since[n] != 1) ++bad;
        since[n] = 0;
      }
    }
  }
  EXPECT_GT(syncs, 500u);
  EXPECT_EQ(bad, 0u);
}

TEST(CanZ, AZAxisNeedsAThirdDrive) {
  CanRig rig(2);
  rig.up();
  std::string err;
  EXPECT_FALSE(hal::CspSegmentLink::create(*rig.master, z_config(), err));
  EXPECT_NE(err.find("third drive"), std::string::npos) << err;
}

}  // namespace
}  // namespace kerf::test
