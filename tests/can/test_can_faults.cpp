// Faults on the CANopen link while a job runs: heartbeat loss, EMCY,
// bus-off, and a drive that refuses enable. Each must stop safely (torch
// off, the axes at rest on the path), give a clear error naming the drive
// and the last completed segment, lose no setpoint (every SYNC sent carries
// one per drive) and lose or repeat no segment.
#include "can_rig.hpp"

namespace kerf::test {
namespace {

using hal::BoardState;
using hal::LinkError;
using namespace hal::canopen;

enum class Kind { heartbeat_loss, emcy, bus_off };

struct FaultRig : CspRig {
  FaultRig() : CspRig(2) {}
  // Four 10 mm lines along x at 50 mm/s, torch on.
  void start_job() {
    hal::BoardStatus st;
    for (std::uint32_t k = 1; k <= 4; ++k) {
      hal::SegmentCommand s;
      s.seq = k;
      s.end = {10.0 * k, 0.0};
      s.feed = 50.0;
      ASSERT_EQ(link->push(s, st), LinkError::none) << link->last_error();
    }
    ASSERT_EQ(link->command(hal::Command::start), LinkError::none);
    ASSERT_EQ(link->command(hal::Command::finish), LinkError::none);
  }
  void inject(Kind k) {
    if (k == Kind::heartbeat_loss) bus.drive(1).inject(sim::DriveFault::heartbeat_loss, bus.now_us());
    if (k == Kind::emcy) bus.drive(0).inject(sim::DriveFault::emcy, bus.now_us());
    if (k == Kind::bus_off) bus.inject_bus_off();
  }
};

// Every SYNC on the bus carried exactly one setpoint per drive.
std::size_t syncs_without_setpoints(const std::vector<sim::LoggedFrame>& log) {
  int since[3] = {0, 0, 0};
  std::size_t bad = 0;
  for (const auto& l : log) {
    if (!l.from_master) continue;
    if ((l.frame.id & 0x780) == kRpdo1) ++since[l.frame.id & 3];
    if (l.frame.id == kSync) {
      bad += since[1] != 1 || since[2] != 1;
      since[1] = since[2] = 0;
    }
  }
  return bad;
}

class CanFault : public ::testing::TestWithParam<Kind> {};

TEST_P(CanFault, SafeStopClearErrorNoLostSetpointLastSegmentNamed) {
  FaultRig rig;
  rig.start_job();
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 15.0; }, 5000));
  hal::BoardStatus st;
  rig.link->status(st);
  ASSERT_TRUE(st.torch);
  const double at_fault = st.position.x;
  rig.inject(GetParam());
  // Heartbeat loss shows after the consumer time (60 ms); the rest at once.
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::fault; }, 200));
  for (int i = 0; i < 300; ++i) rig.link->cycle();  // braking, then at rest
  rig.link->status(st);
  const hal::BoardStatus stopped = st;
  for (int i = 0; i < 50; ++i) rig.link->cycle();
  rig.link->status(st);
  EXPECT_EQ(st.state, BoardState::fault);
  EXPECT_FALSE(st.torch);
  EXPECT_EQ(st.executing, 0u);
  EXPECT_EQ(st.position.x, stopped.position.x) << "not at rest";
  EXPECT_EQ(st.position.y, 0.0) << "off the path";
  // Up to 62 ms (the 60 ms heartbeat timeout, detected on the next SYNCs)
  // at 50 mm/s, plus the 0.625 mm braking distance.
  EXPECT_LT(st.position.x, at_fault + 0.062 * 50.0 + 0.7);
  const std::uint16_t want = GetParam() == Kind::heartbeat_loss ? hal::kFaultHeartbeat
                             : GetParam() == Kind::emcy         ? hal::kFaultEmcy
                                                                : hal::kFaultBusOff;
  EXPECT_TRUE(st.faults & want) << st.faults;
  const std::string err = rig.link->last_error();
  EXPECT_NE(err.find("last completed segment " + std::to_string(st.last_executed)), std::string::npos) << err;
  if (GetParam() == Kind::heartbeat_loss) {
    EXPECT_NE(err.find("node 2): heartbeat lost"), std::string::npos) << err;
  }
  if (GetParam() == Kind::emcy) {
    EXPECT_NE(err.find("node 1): emergency: EMCY error code 0x2310"), std::string::npos) << err;
  }
  if (GetParam() == Kind::bus_off) {
    EXPECT_NE(err.find("bus-off"), std::string::npos) << err;
  }
  EXPECT_EQ(syncs_without_setpoints(rig.bus.log()), 0u);
  // Completed segments ran once each, in order; nothing after the fault.
  std::vector<std::uint32_t> ran = rig.link->executed();
  ASSERT_EQ(ran.size(), st.last_executed);
  for (std::size_t i = 0; i < ran.size(); ++i) EXPECT_EQ(ran[i], i + 1);
  EXPECT_LT(st.last_executed, 4u);
}

INSTANTIATE_TEST_SUITE_P(Kinds, CanFault, ::testing::Values(Kind::heartbeat_loss, Kind::emcy, Kind::bus_off),
                         [](const auto& i) {
                           return i.param == Kind::heartbeat_loss ? std::string("HeartbeatLoss")
                                  : i.param == Kind::emcy         ? std::string("Emcy")
                                                                  : std::string("BusOff");
                         });

// After an EMCY and a fault reset (rising edge of bit 7, enable again) the
// job continues from the last completed segment with new sequence numbers.
TEST(CanFaultRecovery, EmcyThenFaultResetFinishesTheJob) {
  FaultRig rig;
  rig.start_job();
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 15.0; }, 5000));
  rig.inject(Kind::emcy);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::fault; }, 10));
  for (int i = 0; i < 100; ++i) rig.link->cycle();
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::idle; }, 10))
      << rig.link->last_error();
  EXPECT_EQ(rig.bus.drive(0).state(), DriveState::operation_enabled);
  hal::BoardStatus st;
  rig.link->status(st);
  const std::uint32_t done = st.last_executed;
  std::uint32_t seq = st.last_accepted;
  for (std::uint32_t k = done + 1; k <= 4; ++k) {
    hal::SegmentCommand s;
    s.seq = ++seq;
    s.end = {10.0 * k, 0.0};
    s.feed = 50.0;
    ASSERT_EQ(rig.link->push(s, st), LinkError::none) << rig.link->last_error();
  }
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::done; }, 5000))
      << rig.link->last_error();
  rig.link->status(st);
  EXPECT_DOUBLE_EQ(st.position.x, 40.0);
  EXPECT_EQ(syncs_without_setpoints(rig.bus.log()), 0u);
}

// A drive that refuses enable when the fault is reset: the link stays in
// fault and says which drive and where it stuck.
TEST(CanFaultRecovery, ADriveRefusingEnableKeepsTheFault) {
  FaultRig rig;
  rig.start_job();
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 15.0; }, 5000));
  rig.inject(Kind::emcy);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::fault; }, 10));
  for (int i = 0; i < 100; ++i) rig.link->cycle();
  rig.bus.drive(0).inject(sim::DriveFault::enable_refused, rig.bus.now_us());
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  rig.link->cycle();  // runs the reset and the enable sequence
  hal::BoardStatus st;
  rig.link->status(st);
  EXPECT_EQ(st.state, BoardState::fault);
  EXPECT_TRUE(st.faults & hal::kFaultDrive);
  const std::string err = rig.link->last_error();
  EXPECT_NE(err.find("node 1): enable refused"), std::string::npos) << err;
  EXPECT_NE(err.find("switched on"), std::string::npos) << err;
  EXPECT_EQ(syncs_without_setpoints(rig.bus.log()), 0u);
}

TEST(CanFaultRecovery, BusOffRecoversWhenTheBusDoes) {
  FaultRig rig;
  rig.start_job();
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 15.0; }, 5000));
  rig.inject(Kind::bus_off);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::fault; }, 10));
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  rig.link->cycle();
  hal::BoardStatus st;
  rig.link->status(st);
  EXPECT_EQ(st.state, BoardState::fault) << "reset while still bus-off";
  EXPECT_NE(std::string(rig.link->last_error()).find("not recovered"), std::string::npos) << rig.link->last_error();
  rig.bus.recover();
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::idle; }, 10))
      << rig.link->last_error();
  // The next segment starts where the drives stand.
  rig.link->status(st);
  EXPECT_EQ(rig.master->axis(0).target, rig.master->axis(0).actual);
}

}  // namespace
}  // namespace kerf::test

namespace kerf::test {
namespace {

// The plant's following error beyond the drive's window (0x6065): the drive
// faults with EMCY 0x8611 and statusword bit 13, and the link stops.
TEST(CanFollowingError, BeyondTheWindowTheDriveFaults) {
  CspRig rig;
  // 50 mm/s at 1 ms SYNC is 50 counts a period; a 20-count window is too tight.
  ASSERT_EQ(rig.master->sdo_write(0, kFollowingWindow, 0, 20, 4), hal::AxisError::none) << rig.master->last_error();
  hal::BoardStatus st;
  hal::SegmentCommand s;
  s.seq = 1;
  s.end = {10.0, 0.0};
  s.feed = 50.0;
  ASSERT_EQ(rig.link->push(s, st), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& b) { return b.state == BoardState::fault; }, 1000));
  rig.link->status(st);
  EXPECT_TRUE(st.faults & hal::kFaultEmcy);
  EXPECT_NE(std::string(rig.link->last_error()).find("node 1): emergency: EMCY error code 0x8611"), std::string::npos)
      << rig.link->last_error();
  EXPECT_EQ(rig.bus.drive(0).state(), DriveState::fault);
  EXPECT_TRUE(rig.bus.drive(0).statusword() & kSwFollowingError);
  // The window as set allows the ramp's first steps: the fault came once the speed passed 20 counts/period.
  EXPECT_GT(rig.bus.drive(0).actual(), 0);
}

}  // namespace
}  // namespace kerf::test
