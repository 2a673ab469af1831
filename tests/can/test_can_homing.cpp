// CiA 402 homing mode (6) on the in-process bus: the master sets the method,
// speeds and offset by SDO, starts it with controlword bit 4 and follows the
// statusword; the simulated drive searches its switch at a configured position.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/can/csp_segment_link.hpp"
#include "kerf/hal/canopen.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

namespace kerf::test {
namespace {

using hal::AxisError;
using hal::DriveHomingResult;

struct HomingRig {
  sim::VirtualCanBus bus;
  std::unique_ptr<hal::CanOpenMaster> master;
  HomingRig() {
    hal::CanOpenConfig cfg;
    cfg.nodes = {1, 2};
    for (std::uint8_t node : cfg.nodes) {
      sim::DriveConfig d;
      d.node = node;
      d.start = node == 1 ? 40000 : 30000;  // counts: wherever the axes powered up
      d.following_window = 100000;
      d.has_home_switch = node == 1;  // x has a switch at -2.5 mm, y none
      d.home_switch = -2500;
      bus.add_drive(d);
    }
    std::string err;
    master = hal::CanOpenMaster::create(bus.master(), cfg, err);
    if (!master) throw std::runtime_error(err);
    if (master->bring_up() != AxisError::none || master->enable() != AxisError::none)
      throw std::runtime_error(master->last_error());
  }
};

hal::DriveHoming x_homing() {
  hal::DriveHoming h;
  h.method = hal::canopen::kHomeNegativeSwitch;
  h.search_speed = 50000;  // 50 mm/s at 1000 counts/mm
  h.latch_speed = 1000;    // one count per 1 ms SYNC: the latch lands within a count
  h.home_offset = -2000;
  h.max_travel = 100000;
  return h;
}

TEST(CanHoming, FindsTheSwitchAtItsPositionWithinACount) {
  HomingRig rig;
  DriveHomingResult r{};
  ASSERT_EQ(rig.master->home(0, x_homing(), r, {}), AxisError::none) << rig.master->last_error();
  EXPECT_EQ(r, DriveHomingResult::attained);
  EXPECT_LE(std::abs(rig.bus.drive(0).last_latch() - (-2500)), 1);  // released at the switch
  EXPECT_EQ(rig.master->axis(0).actual, -2000);                      // which became the home offset
  EXPECT_EQ(rig.master->axis(1).actual, 30000);                      // y held
  // Back in CSP, enabled, the target at the new position: the next cycles hold still.
  std::uint32_t mode = 0;
  ASSERT_EQ(rig.master->sdo_read(0, hal::canopen::kModeDisplay, 0, mode), AxisError::none);
  EXPECT_EQ(static_cast<std::int8_t>(mode), hal::canopen::kModeCsp);
  for (int i = 0; i < 5; ++i) ASSERT_EQ(rig.master->cycle(), AxisError::none) << rig.master->last_error();
  EXPECT_EQ(rig.master->axis(0).actual, -2000);
  EXPECT_EQ(rig.master->axis(0).target, -2000);
}

TEST(CanHoming, ASwitchThatNeverTripsIsHaltedInsideTheSearchDistance) {
  HomingRig rig;
  hal::DriveHoming h = x_homing();
  h.max_travel = 25000;
  DriveHomingResult r{};
  ASSERT_EQ(rig.master->home(1, h, r, {}), AxisError::none) << rig.master->last_error();  // y: no switch
  EXPECT_EQ(r, DriveHomingResult::no_switch);
  const std::int32_t travelled = 30000 - rig.master->axis(1).actual;
  EXPECT_GT(travelled, 25000 - 200);  // it searched the whole distance
  EXPECT_LE(travelled, 25000);        // and stopped inside it
  for (int i = 0; i < 5; ++i) ASSERT_EQ(rig.master->cycle(), AxisError::none);
  EXPECT_EQ(rig.master->axis(1).actual, 30000 - travelled);  // stopped, and stays
}

TEST(CanHoming, AnEStopMidSearchHaltsItUnhomed) {
  HomingRig rig;
  int polls = 0;
  DriveHomingResult r{};
  ASSERT_EQ(rig.master->home(0, x_homing(), r, [&] { return ++polls > 200; }), AxisError::none);
  EXPECT_EQ(r, DriveHomingResult::aborted);
  const std::int32_t at = rig.master->axis(0).actual;
  EXPECT_LT(at, 40000 - 5000);  // it had moved (about 10 mm in 0.2 s)
  EXPECT_GT(at, 0);             // and stopped well short of the switch
  for (int i = 0; i < 5; ++i) ASSERT_EQ(rig.master->cycle(), AxisError::none);
  EXPECT_EQ(rig.master->axis(0).actual, at);
}

TEST(CanHoming, TheDriveRefusesAnUnknownMethod) {
  HomingRig rig;
  hal::DriveHoming h = x_homing();
  h.method = 35;  // not a switch method this drive runs
  DriveHomingResult r{};
  EXPECT_EQ(rig.master->home(0, h, r, {}), AxisError::sdo_abort);
}

// Through the segment link (what kerf home uses): homed, and a segment after
// it starts at the home position.
TEST(CanHoming, TheCspLinkHomesThenRunsFromTheHomePosition) {
  HomingRig rig;
  std::string err;
  auto link = hal::CspSegmentLink::create(*rig.master, hal::CspConfig{}, err);
  ASSERT_TRUE(link) << err;
  hal::HomeCommand h;
  h.axis = 0;
  h.dir = -1;
  h.search_speed = 50;
  h.latch_speed = 1;
  h.search_distance = 100;
  h.home_position = -2.0;
  ASSERT_EQ(link->home(h, {}), hal::LinkError::none) << link->last_error();
  hal::BoardStatus st;
  ASSERT_EQ(link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homing, hal::HomingState::done);
  EXPECT_EQ(st.homed, 1);
  EXPECT_EQ(st.state, hal::BoardState::idle);
  EXPECT_NEAR(st.position.x, -2.0, 1e-9);
  hal::SegmentCommand s;
  s.seq = 1;
  s.end = {0.0, 30.0};
  s.feed = 20;
  ASSERT_EQ(link->push(s, st), hal::LinkError::none) << link->last_error();
  ASSERT_EQ(link->command(hal::Command::start), hal::LinkError::none);
  ASSERT_EQ(link->command(hal::Command::finish), hal::LinkError::none);
  for (int i = 0; i < 5000 && st.state != hal::BoardState::done; ++i) {
    link->cycle();
    link->status(st);
  }
  EXPECT_EQ(st.state, hal::BoardState::done) << link->last_error();
  EXPECT_EQ(rig.master->axis(0).actual, 0);  // 2 mm from home, no jump, no following error
  h.axis = 1;  // y has no switch: a fault with the homing bit
  h.search_distance = 5;
  ASSERT_EQ(link->home(h, {}), hal::LinkError::none);
  ASSERT_EQ(link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homing, hal::HomingState::no_switch);
  EXPECT_EQ(st.state, hal::BoardState::fault);
  EXPECT_NE(st.faults & hal::kFaultHoming, 0);
  EXPECT_EQ(st.homed, 1);
}

}  // namespace
}  // namespace kerf::test
