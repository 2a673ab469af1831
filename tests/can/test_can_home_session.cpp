// `kerf home`'s session (machine::home_axes) over the in-process CAN link
// (simulated/can_sim_link.hpp), as `kerf-sim home --in-process` runs it: the
// switch found at its position within a count, a switch that never trips
// halted inside the search distance, an E-stop mid-search. And kerf run's
// cross-check (machine::check_board_homed): the drives report homed since
// their power-up (CiA 402 homing attained, read at bring-up), so a state file
// that says homed is refused against drives that were power-cycled.
#include <gtest/gtest.h>

#include <cstdlib>

#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"
#include "machine/homing.hpp"
#include "simulated/can_sim_link.hpp"

namespace kerf::test {
namespace {

// The E-stop pressed at the n-th read (never: n = 0).
class EstopAfter final : public hal::Gpio {
 public:
  explicit EstopAfter(int n) : n_(n) {}
  bool read(double, hal::GpioInputs& in) override {
    in = {};
    in.estop = n_ > 0 && ++reads_ >= n_;
    return true;
  }
  bool set_torch(bool) override { return true; }
  const char* last_error() const override { return ""; }

 private:
  int n_, reads_ = 0;
};

config::Config homing_config() {
  config::Config cfg;
  cfg.machine.axes.resize(2);
  for (config::Axis& a : cfg.machine.axes) {
    a.home_dir = -1;
    a.home_search_speed = 3000;  // mm/min: 50 mm/s
    a.home_latch_speed = 60;     // 1 mm/s: one count per 1 ms SYNC at 1000 counts/mm
    a.home_search_distance = 100;
    a.home_position = -2.0;
  }
  return cfg;
}

std::unique_ptr<simulated::CanSimLink> link_with_x_switch() {
  simulated::CanSimOptions o;
  o.start = {40.0, 30.0};
  o.has_home_switch[0] = true;  // x at -2.5 mm in the power-up frame; y has none
  o.home_switch[0] = -2.5;
  std::string err;
  auto link = simulated::make_can_sim_link(o, err);
  EXPECT_TRUE(link) << err;
  return link;
}

TEST(CanHomeSession, FindsTheSwitchAtItsPositionWithinACount) {
  const config::Config cfg = homing_config();
  auto link = link_with_x_switch();
  ASSERT_TRUE(link);
  EstopAfter lines(0);
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(cfg, 1u, *link, &lines, state, error, nullptr)) << error;
  EXPECT_TRUE(state.homed[0]);
  EXPECT_FALSE(state.homed[1]);
  EXPECT_LE(std::abs(link->home_latch(0) - (-2500)), 1);  // released at the switch, within a count
  EXPECT_DOUBLE_EQ(state.position[0], -2.0);             // which became the home position
  EXPECT_DOUBLE_EQ(state.position[1], 30.0);             // y held
  EXPECT_TRUE(machine::check_board_homed(state, *link, error)) << error;
}

TEST(CanHomeSession, ASwitchThatNeverTripsIsAFaultInsideTheSearchDistance) {
  config::Config cfg = homing_config();
  cfg.machine.axes[1].home_search_distance = 5;
  auto link = link_with_x_switch();
  ASSERT_TRUE(link);
  EstopAfter lines(0);
  job::MachineState state;
  std::string error;
  EXPECT_FALSE(machine::home_axes(cfg, 2u, *link, &lines, state, error, nullptr));
  EXPECT_NE(error.find("y: "), std::string::npos) << error;
  EXPECT_NE(error.find("never tripped within the search distance"), std::string::npos) << error;
  EXPECT_FALSE(state.homed[1]);
  const double travelled = 30.0 - state.position[1];
  EXPECT_GT(travelled, 4.8) << "it searched the whole distance";
  EXPECT_LE(travelled, 5.0) << "and stopped inside it";
}

TEST(CanHomeSession, AnEStopMidSearchLeavesTheAxisUnhomed) {
  const config::Config cfg = homing_config();
  auto link = link_with_x_switch();
  ASSERT_TRUE(link);
  EstopAfter lines(200);  // about 0.2 s of search at one read per SYNC
  job::MachineState state;
  state.homed[0] = true;  // an old flag: homing again drops it first
  std::string error;
  EXPECT_FALSE(machine::home_axes(cfg, 1u, *link, &lines, state, error, nullptr));
  EXPECT_NE(error.find("E-stop"), std::string::npos) << error;
  EXPECT_FALSE(state.homed[0]);
  EXPECT_LT(state.position[0], 40.0 - 5.0);  // it had moved
  EXPECT_GT(state.position[0], 0.0);         // and stopped well short of the switch
  hal::BoardStatus st;
  ASSERT_EQ(link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homed & 1u, 0u);
}

// kerf run after a power cycle: a new link on new drives says not homed.
TEST(CanHomeSession, KerfRunRefusesAStateFileTheDrivesContradict) {
  job::MachineState state;
  state.homed[0] = state.homed[1] = true;
  auto link = link_with_x_switch();
  ASSERT_TRUE(link);
  std::string error;
  EXPECT_FALSE(machine::check_board_homed(state, *link, error));
  EXPECT_NE(error.find("the board says x y not homed since its power-up"), std::string::npos) << error;
}

// The drive keeps its home across a new master (NMT reset node): a later
// kerf run finds it; a power cycle loses it.
TEST(CanHomeSession, TheDrivesHomedStateSurvivesANewMasterNotAPowerCycle) {
  sim::VirtualCanBus bus;
  for (std::uint8_t node : {1, 2}) {
    sim::DriveConfig d;
    d.node = node;
    d.start = 10000;
    d.following_window = 100000;
    d.has_home_switch = node == 1;
    d.home_switch = -500;
    bus.add_drive(d);
  }
  hal::CanOpenConfig cc;
  cc.nodes = {1, 2};
  auto up = [&](std::unique_ptr<hal::CanOpenMaster>& m) {
    std::string err;
    m = hal::CanOpenMaster::create(bus.master(), cc, err);
    ASSERT_TRUE(m) << err;
    ASSERT_EQ(m->bring_up(), hal::AxisError::none) << m->last_error();
  };
  std::unique_ptr<hal::CanOpenMaster> m;
  ASSERT_NO_FATAL_FAILURE(up(m));
  bool homed = true;
  ASSERT_EQ(m->homed_since_power_up(0, homed), hal::AxisError::none) << m->last_error();
  EXPECT_FALSE(homed);
  ASSERT_EQ(m->enable(), hal::AxisError::none) << m->last_error();
  hal::DriveHoming h;
  h.method = hal::canopen::kHomeNegativeSwitch;
  h.search_speed = 50000;
  h.latch_speed = 1000;
  h.max_travel = 100000;
  hal::DriveHomingResult r{};
  ASSERT_EQ(m->home(0, h, r, {}), hal::AxisError::none) << m->last_error();
  ASSERT_EQ(r, hal::DriveHomingResult::attained);
  m.reset();
  ASSERT_NO_FATAL_FAILURE(up(m));  // kerf run's own session
  ASSERT_EQ(m->homed_since_power_up(0, homed), hal::AxisError::none);
  EXPECT_TRUE(homed);
  ASSERT_EQ(m->homed_since_power_up(1, homed), hal::AxisError::none);
  EXPECT_FALSE(homed);  // y was never homed
  bus.drive(0).power_on(bus.now_us());
  m.reset();
  ASSERT_NO_FATAL_FAILURE(up(m));
  ASSERT_EQ(m->homed_since_power_up(0, homed), hal::AxisError::none);
  EXPECT_FALSE(homed);
}

}  // namespace
}  // namespace kerf::test
