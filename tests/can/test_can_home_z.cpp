// Homing a z axis over CAN: the third CiA 402 node on the in-process bus
// homes in mode 6 like x and y, kerf home's session homes z first, and kerf
// run's cross-check reads z's homed state from the drive at bring-up. A
// switch that never trips and an E-stop leave z unhomed, x and y unmoved.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "kerf/sim/can/virtual_can_bus.hpp"
#include "machine/homing.hpp"
#include "simulated/can_sim_link.hpp"

namespace kerf::test {
namespace {

// z at 500 counts/mm (x and y at 1000): z's own scale carries its speeds,
// home offset and search distance.
constexpr double kZCountsPerMm = 500.0;

config::Config z_config() {
  config::Config cfg;
  cfg.machine.axes.resize(3);
  for (config::Axis& a : cfg.machine.axes) {
    a.home_dir = -1;
    a.home_search_speed = 3000;  // mm/min: 50 mm/s
    a.home_latch_speed = 60;     // 1 mm/s: one count per 1 ms SYNC at 1000 counts/mm
    a.home_search_distance = 100;
    a.home_position = -2.0;
  }
  config::Axis& z = cfg.machine.axes[2];
  z.counts_per_mm = kZCountsPerMm;
  z.feed = 3000;
  z.accel = 500;
  z.home_dir = 1;            // up
  z.home_latch_speed = 120;  // 2 mm/s: one count per SYNC at 500 counts/mm
  z.home_position = 15.0;
  return cfg;
}

// Powered up at x 40, y 30, z 0; switches at x -2.5, y 1, z 6 mm (when asked).
std::unique_ptr<simulated::CanSimLink> z_link(bool z_switch = true) {
  simulated::CanSimOptions o = simulated::can_sim_options(z_config());
  o.start = {40.0, 30.0};
  o.has_home_switch[0] = o.has_home_switch[1] = true;
  o.home_switch[0] = -2.5;
  o.home_switch[1] = 1.0;
  o.has_home_switch[2] = z_switch;
  o.home_switch[2] = 6.0;
  std::string err;
  auto link = simulated::make_can_sim_link(o, err);
  EXPECT_TRUE(link) << err;
  return link;
}

TEST(CanHomeZ, FindsTheZSwitchOnTheThirdNodeWithinACount) {
  auto link = z_link();
  ASSERT_TRUE(link);
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(z_config(), 4u, *link, nullptr, state, error, nullptr)) << error;
  EXPECT_EQ(job::homed_names(state, 3), "z");
  EXPECT_LE(std::abs(link->home_latch(2) - 3000), 1);  // 6 mm at 500 counts/mm, within a count
  EXPECT_DOUBLE_EQ(state.position[2], 15.0);           // the switch became the home position
  EXPECT_DOUBLE_EQ(state.position[0], 40.0);           // x and y held
  EXPECT_DOUBLE_EQ(state.position[1], 30.0);
  hal::BoardStatus st;
  ASSERT_EQ(link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homed, 4);
  EXPECT_TRUE(machine::check_board_homed(state, *link, error)) << error;
  // A z move after homing runs from the home position on the third drive.
  hal::SegmentCommand down;
  down.seq = 1;
  down.end = {40.0, 30.0};
  down.z_move = true;
  down.z = 10.0;
  down.feed = 20.0;
  ASSERT_EQ(link->push(down, st), hal::LinkError::none) << link->last_error();
  ASSERT_EQ(link->command(hal::Command::start), hal::LinkError::none);
  ASSERT_EQ(link->command(hal::Command::finish), hal::LinkError::none);
  for (int i = 0; i < 5000 && st.state != hal::BoardState::done && st.state != hal::BoardState::fault; ++i) {
    link->tick();
    link->status(st);
  }
  ASSERT_EQ(st.state, hal::BoardState::done) << link->last_error();
  EXPECT_DOUBLE_EQ(st.z, 10.0);
  EXPECT_EQ(link->axes().axis(2).actual, 5000);  // 10 mm at 500 counts/mm
}

TEST(CanHomeZ, HomesZFirstThenXThenY) {
  auto link = z_link();
  ASSERT_TRUE(link);
  job::MachineState state;
  std::string error;
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* log = open_memstream(&text, &size);
  ASSERT_NE(log, nullptr);
  const bool ok = machine::home_axes(z_config(), 7u, *link, nullptr, state, error, log);
  std::fclose(log);
  const std::string lines(text, size);
  std::free(text);
  ASSERT_TRUE(ok) << error;
  EXPECT_EQ(lines, "home: z homed at 15.000 mm\nhome: x homed at -2.000 mm\nhome: y homed at -2.000 mm\n");
  EXPECT_EQ(job::homed_names(state, 3), "x y z");
  EXPECT_LE(std::abs(link->home_latch(0) - (-2500)), 1);
  EXPECT_LE(std::abs(link->home_latch(1) - 1000), 1);
  EXPECT_LE(std::abs(link->home_latch(2) - 3000), 1);
}

// z first: its switch never trips, so x and y never move and stay unhomed.
TEST(CanHomeZ, AZSwitchThatNeverTripsIsAFaultInsideTheSearchDistance) {
  config::Config cfg = z_config();
  cfg.machine.axes[2].home_search_distance = 5;
  auto link = z_link(false);
  ASSERT_TRUE(link);
  job::MachineState state;
  std::string error;
  EXPECT_FALSE(machine::home_axes(cfg, 7u, *link, nullptr, state, error, nullptr));
  EXPECT_EQ(error.rfind("z: ", 0), 0u) << error;
  EXPECT_NE(error.find("never tripped within the search distance"), std::string::npos) << error;
  EXPECT_EQ(job::homed_names(state, 3), "");
  EXPECT_GT(state.position[2], 4.8) << "it searched the whole distance";
  EXPECT_LE(state.position[2], 5.0) << "and stopped inside it";
  EXPECT_DOUBLE_EQ(state.position[0], 40.0);
  EXPECT_DOUBLE_EQ(state.position[1], 30.0);
}

// The E-stop pressed at the n-th read of the lines.
class EstopAfter final : public hal::Gpio {
 public:
  explicit EstopAfter(int n) : n_(n) {}
  bool read(double, hal::GpioInputs& in) override {
    in = {};
    in.estop = ++reads_ >= n_;
    return true;
  }
  bool set_torch(bool) override { return true; }
  const char* last_error() const override { return ""; }

 private:
  int n_, reads_ = 0;
};

// An E-stop while z searches halts it there, unhomed; x and y never start.
TEST(CanHomeZ, AnEStopMidSearchLeavesZUnhomedAndXYUntouched) {
  auto link = z_link();
  ASSERT_TRUE(link);
  EstopAfter lines(60);  // about 60 ms of search at one read per SYNC: 1.5 mm of the 6
  job::MachineState state;
  state.homed[2] = true;  // an old flag: homing again drops it first
  std::string error;
  EXPECT_FALSE(machine::home_axes(z_config(), 7u, *link, &lines, state, error, nullptr));
  EXPECT_EQ(error.rfind("z: E-stop", 0), 0u) << error;
  EXPECT_EQ(job::homed_names(state, 3), "");
  EXPECT_GT(state.position[2], 0.5);  // it had moved up
  EXPECT_LT(state.position[2], 5.0);  // and stopped short of the switch
  EXPECT_DOUBLE_EQ(state.position[0], 40.0);
  EXPECT_DOUBLE_EQ(state.position[1], 30.0);
  hal::BoardStatus st;
  ASSERT_EQ(link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homed, 0);
}

// The machine's link on a given bus (kerf run's bring-up, as open_machine_can_link).
class BusLink final : public machine::CanMasterLink {
 public:
  bool open(hal::CanBus& bus, const machine::CanLinkOptions& o, std::string& error) {
    return start(bus, o, false, error);
  }
};

// kerf run reads z's homed state from the third drive at bring-up: a new
// master finds the home (the drive kept it), a power-cycled drive lost it.
TEST(CanHomeZ, KerfRunReadsZsHomedStateFromTheThirdDrive) {
  sim::VirtualCanBus bus;
  for (std::uint8_t node : {1, 2, 3}) {
    sim::DriveConfig d;
    d.node = node;
    d.has_home_switch = node == 3;
    d.home_switch = 3000;  // z: 6 mm
    bus.add_drive(d);
  }
  machine::CanLinkOptions o;
  machine::read_can_link_options(z_config(), o);
  job::MachineState state;
  std::string error;
  {
    BusLink link;
    ASSERT_TRUE(link.open(bus.master(), o, error)) << error;
    ASSERT_TRUE(machine::home_axes(z_config(), 4u, link, nullptr, state, error, nullptr)) << error;
  }
  ASSERT_TRUE(state.homed[2]);
  {
    BusLink link;  // kerf run's own session
    ASSERT_TRUE(link.open(bus.master(), o, error)) << error;
    hal::BoardStatus st;
    ASSERT_EQ(link.status(st), hal::LinkError::none);
    EXPECT_EQ(st.homed, 4);
    EXPECT_TRUE(machine::check_board_homed(state, link, error)) << error;
  }
  bus.drive(2).power_on(bus.now_us());
  BusLink link;
  ASSERT_TRUE(link.open(bus.master(), o, error)) << error;
  EXPECT_FALSE(machine::check_board_homed(state, link, error));
  EXPECT_NE(error.find("the board says z not homed since its power-up"), std::string::npos) << error;
}

}  // namespace
}  // namespace kerf::test
