// Homing a z axis over Modbus: the simulated board with a z axis runs the
// cycle for z too (command 7, axis mask bit 2), kerf home's session homes z
// first (the torch up) and then x and y, and kerf run's checks cover z.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "kerf/sim/scripted_gpio.hpp"
#include "home_bench.hpp"
#include "machine/homing.hpp"

namespace kerf::test {
namespace {

constexpr double kCount = 0.001;  // one register count, mm

// A board with a z axis powered up at x 40, y 30, z 0; switches at x -2.5,
// y 1, and (when asked) z 12 mm.
sim::BoardConfig z_home_config(bool z_switch, bool z_axis) {
  sim::BoardConfig bc;
  bc.start = {40.0, 30.0};
  if (z_axis) bc.z = {0.001, 50.0, 1000.0};
  bc.has_home_switch[0] = bc.has_home_switch[1] = true;
  bc.home_switch_at[0] = -2.5;
  bc.home_switch_at[1] = 1.0;
  bc.has_home_switch[2] = z_switch;
  bc.home_switch_at[2] = 12.0;
  return bc;
}

struct ZHomeRig : HomeBench {
  explicit ZHomeRig(Wire wire, bool z_switch = true, bool z_axis = true)
      : HomeBench(wire, z_home_config(z_switch, z_axis), std::make_unique<sim::EndpointExecutor>()) {}
};

hal::HomeCommand z_home() {
  hal::HomeCommand h;
  h.axis = 2;
  h.dir = 1;  // up
  h.search_speed = 50;
  h.latch_speed = 1;  // 1 µm per 1 ms period: the latch lands within a count
  h.search_distance = 100;
  h.backoff = 2;
  h.home_position = 15.0;
  return h;
}

class ModbusHomeZ : public ::testing::TestWithParam<Wire> {};

TEST_P(ModbusHomeZ, FindsTheZSwitchAtItsPositionWithinACount) {
  ZHomeRig rig(GetParam());
  rig.board->start_servo(0.0);
  ASSERT_EQ(rig.link->home(z_home(), {}), hal::LinkError::none) << rig.link->last_error();
  hal::BoardStatus st = rig.wait_homing_end();
  EXPECT_EQ(st.homing, hal::HomingState::done);
  EXPECT_EQ(st.state, hal::BoardState::idle);
  EXPECT_EQ(st.homed, 4);                              // z's bit, register 22
  EXPECT_NEAR(rig.board->last_latch(), 12.0, kCount);  // the latch tripped at the switch
  EXPECT_NEAR(st.z, 15.0, 1e-9);                       // and became the home position
  EXPECT_NEAR(st.position.x, 40.0, 1e-9);              // x and y untouched
  EXPECT_NEAR(st.position.y, 30.0, 1e-9);
  // A z move after homing starts from the home position.
  hal::SegmentCommand down;
  down.seq = 1;
  down.end = {40.0, 30.0};
  down.z_move = true;
  down.z = 10.0;
  down.feed = 20.0;
  ASSERT_EQ(rig.link->push(down, st), hal::LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::start), hal::LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), hal::LinkError::none);
  ASSERT_TRUE(rig.board->wait_until([](const hal::BoardStatus& b) { return b.state == hal::BoardState::done; }, 5));
  ASSERT_EQ(rig.link->status(st), hal::LinkError::none);
  EXPECT_NEAR(st.z, 10.0, 1e-9);
  EXPECT_EQ(st.homed, 4);
  double highest = 0;
  for (const sim::TraceSample& t : rig.board->trace()) highest = std::max(highest, t.z);
  EXPECT_LE(highest, 15.0 + 1e-9) << "the move went down from 15, not from the latch point";
  EXPECT_GT(highest, 12.0) << "the search went up to the switch";
}

// A board without a z axis answers command 7 for z with exception 03.
TEST_P(ModbusHomeZ, ABoardWithoutZRefusesToHomeIt) {
  ZHomeRig rig(GetParam(), false, false);
  rig.board->start_servo(0.0);
  EXPECT_NE(rig.link->home(z_home(), {}), hal::LinkError::none);
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homed, 0);
  EXPECT_EQ(st.homing, hal::HomingState::none);
}

INSTANTIATE_TEST_SUITE_P(Wires, ModbusHomeZ, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

// kerf home's session on a three-axis machine.
config::Config z_config() {
  config::Config c;
  c.file = "kerf.toml";
  c.machine.axes = {config::Axis{}, config::Axis{}, config::Axis{}};
  for (config::Axis& a : c.machine.axes) {
    a.home_search_speed = 3000;  // mm/min
    a.home_latch_speed = 60;
    a.home_search_distance = 100;
    a.home_backoff = 1;
  }
  c.machine.axes[0].home_position = 5.0;
  c.machine.axes[1].home_position = -1.0;
  c.machine.axes[2].home_dir = 1;
  c.machine.axes[2].home_position = 15.0;
  return c;
}

// The session's log ("home: z homed at ..." per axis), as home_axes writes it.
struct Log {
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* f = open_memstream(&text, &size);
  ~Log() {
    if (f != nullptr) std::fclose(f);
    std::free(text);
  }
  std::string str() {
    std::fflush(f);
    return std::string(text, size);
  }
};

TEST(HomeZSession, HomesZFirstThenXThenY) {
  ZHomeRig rig(Wire::tcp);
  rig.board->start_servo(0.0);
  sim::ScriptedGpio gpio;
  job::MachineState state;
  std::string error;
  Log log;
  ASSERT_TRUE(machine::home_axes(z_config(), 7u, *rig.link, &gpio, state, error, log.f)) << error;
  EXPECT_EQ(log.str(), "home: z homed at 15.000 mm\nhome: x homed at 5.000 mm\nhome: y homed at -1.000 mm\n");
  EXPECT_EQ(job::homed_names(state, 3), "x y z");
  EXPECT_EQ(rig.board->status().homed, 7);
  EXPECT_NEAR(state.position[0], 5.0, 1e-9);
  EXPECT_NEAR(state.position[1], -1.0, 1e-9);
  EXPECT_NEAR(state.position[2], 15.0, 1e-9);
  // The board's own trace: z had reached its home before x first moved.
  const std::vector<sim::TraceSample> trace = rig.board->trace();
  std::size_t last_z = 0, first_x = trace.size();
  for (std::size_t i = 0; i < trace.size(); ++i) {
    if (std::abs(trace[i].z - 15.0) > 1e-9) last_z = i;
    if (first_x == trace.size() && std::abs(trace[i].pos.x - 40.0) > 1e-9) first_x = i;
  }
  EXPECT_GT(last_z, 0u);
  EXPECT_LT(last_z, first_x);
  config::Config c = z_config();
  c.machine.state = "state.txt";
  std::string why;
  EXPECT_TRUE(machine::check_homed(c, state, false, why)) << why;
  EXPECT_TRUE(machine::check_board_homed(state, *rig.link, why)) << why;
}

// z first: its switch never trips, so x and y never move and stay unhomed.
TEST(HomeZSession, AZSwitchThatNeverTripsIsAFaultInsideTheSearchDistance) {
  ZHomeRig rig(Wire::tcp, false);
  rig.board->start_servo(0.0);
  config::Config c = z_config();
  c.machine.axes[2].home_search_distance = 5;
  job::MachineState state;
  std::string error;
  EXPECT_FALSE(machine::home_axes(c, 7u, *rig.link, nullptr, state, error, nullptr));
  EXPECT_EQ(error.rfind("z: ", 0), 0u) << error;
  EXPECT_NE(error.find("never tripped within the search distance"), std::string::npos) << error;
  EXPECT_EQ(job::homed_names(state, 3), "");
  const hal::BoardStatus st = rig.board->status();
  EXPECT_EQ(st.state, hal::BoardState::fault);
  EXPECT_NE(st.faults & hal::kFaultHoming, 0);
  EXPECT_EQ(st.homed, 0);
  EXPECT_NEAR(st.z, 5.0, kCount);  // stopped at the search distance, not past it
  for (const sim::TraceSample& t : rig.board->trace()) {
    EXPECT_LE(t.z, 5.0 + 1e-9);
    EXPECT_DOUBLE_EQ(t.pos.x, 40.0);
    EXPECT_DOUBLE_EQ(t.pos.y, 30.0);
  }
}

// kerf run's rule: on a machine with z, x and y homed is not enough.
TEST(HomeZCheck, KerfRunRefusesAnUnhomedZ) {
  config::Config c = z_config();
  c.machine.state = "state.txt";
  job::MachineState state;
  state.homed[0] = state.homed[1] = true;
  std::string why;
  EXPECT_FALSE(machine::check_homed(c, state, false, why));
  EXPECT_EQ(why, "the machine is not homed (only x y in state.txt): run `kerf home` first");
  state.homed[2] = true;
  EXPECT_TRUE(machine::check_homed(c, state, false, why)) << why;
  // A two-axis machine needs x and y only, as before.
  c.machine.axes.pop_back();
  state.homed[2] = false;
  EXPECT_TRUE(machine::check_homed(c, state, false, why)) << why;
}

// The cross-check covers z: a power-cycled board lost z's home.
TEST(HomeZCheck, KerfRunRefusesABoardThatLostZsHome) {
  job::MachineState state;
  std::string error;
  {
    ZHomeRig rig(Wire::tcp);
    rig.board->start_servo(0.0);
    ASSERT_TRUE(machine::home_axes(z_config(), 4u, *rig.link, nullptr, state, error, nullptr)) << error;
    EXPECT_TRUE(state.homed[2]);
    EXPECT_FALSE(state.homed[0]);
    EXPECT_TRUE(machine::check_board_homed(state, *rig.link, error)) << error;
  }
  ZHomeRig power_cycled(Wire::tcp);
  EXPECT_FALSE(machine::check_board_homed(state, *power_cycled.link, error));
  EXPECT_EQ(error, "the state file says homed, but the board says z not homed since its power-up (was it "
                   "power-cycled?): run `kerf home` again");
}

}  // namespace
}  // namespace kerf::test
