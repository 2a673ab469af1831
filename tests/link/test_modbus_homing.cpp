// Homing over Modbus: the simulated board runs the cycle itself (command 7,
// the home block at 40..51) against switches at configured positions.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "kerf/hal/modbus/register_map.hpp"
#include "kerf/sim/motion_executor.hpp"
#include "kerf/sim/scripted_gpio.hpp"
#include "home_bench.hpp"
#include "machine/homing.hpp"
#include "machine/homing_gpio.hpp"
#include "machine/jog.hpp"

namespace kerf::test {
namespace {

namespace map = hal::modbus_map;
constexpr double kCount = 0.001;  // one register count, mm

// The x switch at -2.5; y has one (at 1) only when asked. interpolate:
// core/motion's interpolator (ramps, feed) rather than a jump to each end.
sim::BoardConfig home_config(bool y_switch) {
  sim::BoardConfig bc;
  bc.start = {40.0, 30.0};  // wherever the axes powered up
  bc.has_home_switch[0] = true;
  bc.home_switch_at[0] = -2.5;
  bc.has_home_switch[1] = y_switch;
  bc.home_switch_at[1] = 1.0;
  return bc;
}

std::unique_ptr<sim::SegmentExecutor> home_executor(bool interpolate) {
  std::string err;
  std::unique_ptr<sim::SegmentExecutor> exec = std::make_unique<sim::EndpointExecutor>();
  if (interpolate) exec = sim::make_motion_executor(sim::MotionConfig{}, err);
  if (!exec) throw std::runtime_error(err);
  return exec;
}

struct HomeRig : HomeBench {
  explicit HomeRig(Wire wire, bool y_switch = false, bool interpolate = false)
      : HomeBench(wire, home_config(y_switch), home_executor(interpolate)) {}
};

hal::HomeCommand x_home() {
  hal::HomeCommand h;
  h.axis = 0;
  h.dir = -1;
  h.search_speed = 50;
  h.latch_speed = 1;  // 1 µm per 1 ms period: the latch lands within a count
  h.search_distance = 100;
  h.backoff = 2;
  h.home_position = -2.0;
  return h;
}

class ModbusHoming : public ::testing::TestWithParam<Wire> {};

TEST_P(ModbusHoming, FindsTheSwitchAtItsPositionWithinACount) {
  HomeRig rig(GetParam());
  rig.board->start_servo(0.0);
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homed, 0);  // powers up unhomed
  ASSERT_EQ(rig.link->home(x_home(), {}), hal::LinkError::none);
  st = rig.wait_homing_end();
  EXPECT_EQ(st.homing, hal::HomingState::done);
  EXPECT_EQ(st.state, hal::BoardState::idle);
  EXPECT_EQ(st.homed, 1);
  EXPECT_NEAR(rig.board->last_latch(), -2.5, kCount);  // the latch tripped at the switch
  EXPECT_NEAR(st.position.x, -2.0, 1e-9);                // and became the home position
  EXPECT_NEAR(st.position.y, 30.0, 1e-9);                // y untouched
  // A segment after homing starts from the home position.
  hal::SegmentCommand s = line_to(1);
  ASSERT_EQ(rig.link->push(s, st), hal::LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::start), hal::LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), hal::LinkError::none);
  ASSERT_TRUE(rig.board->wait_until([](const hal::BoardStatus& b) { return b.state == hal::BoardState::done; }, 5));
  EXPECT_EQ(rig.board->status().homed, 1);
  EXPECT_NEAR(rig.board->status().position.x, 1.0, 1e-9);
}

TEST_P(ModbusHoming, ASwitchThatNeverTripsIsAFaultInsideTheSearchDistance) {
  HomeRig rig(GetParam());
  rig.board->start_servo(0.0);
  hal::HomeCommand h = x_home();
  h.axis = 1;  // y has no switch
  h.search_distance = 25;
  ASSERT_EQ(rig.link->home(h, {}), hal::LinkError::none);
  const hal::BoardStatus st = rig.wait_homing_end();
  EXPECT_EQ(st.homing, hal::HomingState::no_switch);
  EXPECT_EQ(st.state, hal::BoardState::fault);
  EXPECT_NE(st.faults & hal::kFaultHoming, 0);
  EXPECT_EQ(st.homed, 0);
  EXPECT_NEAR(st.position.y, 30.0 - 25.0, kCount);  // stopped at the search distance, not past it
  for (const auto& t : rig.board->trace()) EXPECT_GE(t.pos.y, 5.0 - 1e-9);
  EXPECT_STREQ(hal::to_string(st.homing), "the switch never tripped within the search distance");
}

TEST_P(ModbusHoming, AnAbortMidSearchStopsItAndLeavesTheAxisUnhomed) {
  HomeRig rig(GetParam());
  rig.board->start_servo(1.0);  // real time, so the abort lands mid-search
  hal::HomeCommand h = x_home();
  h.search_speed = 20;  // 42.5 mm to the switch: 2 s
  ASSERT_EQ(rig.link->home(h, {}), hal::LinkError::none);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(rig.link->command(hal::Command::abort), hal::LinkError::none);
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homing, hal::HomingState::aborted);
  EXPECT_EQ(st.state, hal::BoardState::fault);
  EXPECT_NE(st.faults & hal::kFaultAbort, 0);
  EXPECT_EQ(st.homed, 0);
  EXPECT_LT(st.position.x, 40.0);  // it had moved
  EXPECT_GT(st.position.x, 0.0);   // and stopped short of the switch
  const double stopped = st.position.x;
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_EQ(rig.link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.position.x, stopped);  // and stays stopped
}

TEST_P(ModbusHoming, HomeIsRefusedWhileRunning) {
  HomeRig rig(GetParam());
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->command(hal::Command::start), hal::LinkError::none);
  EXPECT_EQ(rig.link->home(x_home(), {}), hal::LinkError::rejected);  // exception 03
  ASSERT_EQ(rig.link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.homing, hal::HomingState::none);
}

INSTANTIATE_TEST_SUITE_P(Wires, ModbusHoming, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

TEST(HomeBlock, RoundTripsAndRefusesBadBlocks) {
  std::uint16_t r[map::kHomeRegs];
  hal::HomeCommand h = x_home(), back;
  ASSERT_TRUE(map::encode_home(h, r));
  const char* reason = nullptr;
  ASSERT_TRUE(map::decode_home(r, back, reason));
  EXPECT_EQ(back.axis, 0);
  EXPECT_EQ(back.dir, -1);
  EXPECT_DOUBLE_EQ(back.home_position, -2.0);
  EXPECT_DOUBLE_EQ(back.latch_speed, 1.0);
  r[map::kHomeAxisMask] = 3;  // two axes at once
  EXPECT_FALSE(map::decode_home(r, back, reason));
  h.dir = 0;  // "here": no search, so no distance needed
  h.search_distance = 0;
  ASSERT_TRUE(map::encode_home(h, r));
  ASSERT_TRUE(map::decode_home(r, back, reason)) << reason;
  EXPECT_EQ(back.dir, 0);
  r[map::kHomeDir] = 2;
  EXPECT_FALSE(map::decode_home(r, back, reason));
  h.dir = -1;  // a search needs its distance
  EXPECT_FALSE(map::encode_home(h, r));
  h.search_distance = 100;
  h.search_speed = 0;
  EXPECT_FALSE(map::encode_home(h, r));
}

// kerf home's session (machine::home_axes): both axes homed into the state
// file's fields; the E-stop line aborts the cycle and leaves the axis unhomed.
config::Config session_config() {
  config::Config c;
  c.machine.axes = {config::Axis{}, config::Axis{}};
  for (config::Axis& a : c.machine.axes) {
    a.home_search_speed = 3000;  // mm/min
    a.home_latch_speed = 60;
    a.home_search_distance = 100;
    a.home_backoff = 1;
  }
  c.machine.axes[0].home_position = 5.0;
  c.machine.axes[1].home_position = -1.0;
  return c;
}

TEST(HomeSession, HomesXThenYIntoTheStateFile) {
  HomeRig rig(Wire::tcp, true);
  rig.board->start_servo(0.0);
  sim::ScriptedGpio gpio;
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(session_config(), 3u, *rig.link, &gpio, state, error, nullptr)) << error;
  EXPECT_TRUE(state.homed[0]);
  EXPECT_TRUE(state.homed[1]);
  EXPECT_EQ(job::homed_names(state, 3), "x y");
  ASSERT_TRUE(state.has_position);
  EXPECT_NEAR(state.position[0], 5.0, 1e-9);
  EXPECT_NEAR(state.position[1], -1.0, 1e-9);
  EXPECT_EQ(rig.board->status().homed, 3);
  std::string why;
  EXPECT_TRUE(machine::check_homed([] { auto c = session_config(); c.machine.state = "s"; return c; }(), state, false, why)) << why;
}

// kerf run's cross-check once the link is up: the board's register 22 must
// say homed for each axis the state file does. A power-cycled board (a new
// one) has lost its home.
TEST(HomeSession, KerfRunCrossChecksTheBoardsHomedFlag) {
  job::MachineState state;
  std::string error;
  {
    HomeRig rig(Wire::tcp, true);
    rig.board->start_servo(0.0);
    ASSERT_TRUE(machine::home_axes(session_config(), 3u, *rig.link, nullptr, state, error, nullptr)) << error;
    EXPECT_TRUE(machine::check_board_homed(state, *rig.link, error)) << error;
  }
  HomeRig power_cycled(Wire::tcp, true);
  power_cycled.board->start_servo(0.0);
  EXPECT_FALSE(machine::check_board_homed(state, *power_cycled.link, error));
  EXPECT_EQ(error, "the state file says homed, but the board says x y not homed since its power-up (was it "
                   "power-cycled?): run `kerf home` again");
  ASSERT_TRUE(machine::home_axes(session_config(), 1u, *power_cycled.link, nullptr, state, error, nullptr));
  EXPECT_FALSE(machine::check_board_homed(state, *power_cycled.link, error));
  EXPECT_NE(error.find("the board says y not homed"), std::string::npos) << error;
}

TEST(HomeSession, TheEStopAbortsItAndTheAxisStaysUnhomed) {
  HomeRig rig(Wire::tcp, true);
  rig.board->start_servo(1.0);  // real time: x needs 42.5 mm / 10 mm/s
  config::Config c = session_config();
  c.machine.axes[0].home_search_speed = 600;
  sim::ScriptedGpio gpio;
  ASSERT_TRUE(gpio.estop_at(0.3, true));
  job::MachineState state;
  state.homed[0] = state.homed[1] = true;  // an old flag: homing again clears it first
  std::string error;
  EXPECT_FALSE(machine::home_axes(c, 3u, *rig.link, &gpio, state, error, nullptr));
  EXPECT_EQ(error, "x: E-stop: homing aborted, the axis is not homed");
  EXPECT_FALSE(state.homed[0]);
  const hal::BoardStatus st = rig.board->status();
  EXPECT_EQ(st.homing, hal::HomingState::aborted);
  EXPECT_EQ(st.homed, 0);
  EXPECT_GT(st.position.x, 30.0);  // stopped about 3 mm into a 42.5 mm search
  std::string why;
  c.machine.state = "s";
  EXPECT_FALSE(machine::check_homed(c, state, false, why));
}

TEST(StateFile, KeepsTheHomedAxesAndThePosition) {
  const std::string path = ::testing::TempDir() + "kerf_homed_state.txt";
  job::MachineState s;
  s.homed[0] = s.homed[1] = true;
  s.has_position = true;
  s.position[0] = 12.5;
  s.position[1] = -3.25;
  std::string error;
  ASSERT_TRUE(job::save_machine_state(path, s, error)) << error;
  job::MachineState back;
  ASSERT_TRUE(job::load_machine_state(path, back, error)) << error;
  EXPECT_TRUE(back.homed[0] && back.homed[1] && !back.homed[2]);
  EXPECT_TRUE(job::all_homed(back, 2));
  EXPECT_FALSE(job::all_homed(back, 3));
  EXPECT_EQ(back.position[1], -3.25);
  EXPECT_TRUE(back.other.empty());  // proper fields, not unknown keys
}

// Jog and touch-off (machine/jog.hpp) on the homed board.
TEST(Jog, MovesToTheTargetThenTouchOffMakesItX0Y0) {
  HomeRig rig(Wire::tcp, true);
  rig.board->start_servo(0.0);
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(session_config(), 3u, *rig.link, nullptr, state, error, nullptr)) << error;
  Vec2<double> at{};
  ASSERT_TRUE(machine::jog_to(*rig.link, nullptr, {17.5, -1.0}, 20.0, at, error)) << error;
  EXPECT_NEAR(at.x, 17.5, 1e-9);
  ASSERT_TRUE(machine::jog_to(*rig.link, nullptr, {17.5, 4.0}, 20.0, at, error)) << error;  // again, from done
  EXPECT_NEAR(at.y, 4.0, 1e-9);
  state.coord = 1;  // G55 active
  state.g92_on = true;
  state.g92[0] = 1.0;
  machine::touch_off(state, at);
  EXPECT_DOUBLE_EQ(state.g5x[1][0], 16.5);  // work = machine - G55 - G92 = 0
  EXPECT_DOUBLE_EQ(state.g5x[1][1], 4.0);
  EXPECT_DOUBLE_EQ(state.g5x[0][0], 0.0);  // G54 untouched
}

TEST(Jog, StopsAtTheSoftLimit) {
  HomeRig rig(Wire::tcp, true);
  rig.board->start_servo(0.0);
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(session_config(), 3u, *rig.link, nullptr, state, error, nullptr)) << error;
  motion::SoftLimits<double> lim;
  lim.on[0] = true;
  lim.min[0] = 0;
  lim.max[0] = 50;  // y unlimited
  Vec2<double> to{5.0 + 1000.0, 70.0};  // 1000 mm on from x = 5
  EXPECT_TRUE(machine::clamp_to_limits(to, lim));
  EXPECT_EQ(to.x, 50.0);
  EXPECT_EQ(to.y, 70.0);
  Vec2<double> at{};
  ASSERT_TRUE(machine::jog_to(*rig.link, nullptr, to, 50.0, at, error)) << error;
  EXPECT_NEAR(at.x, 50.0, 1e-9);  // at the limit, not past it
  Vec2<double> inside{20.0, 1.0};
  EXPECT_FALSE(machine::clamp_to_limits(inside, lim));
}

TEST(Jog, TheEStopStopsItOnThePath) {
  HomeRig rig(Wire::tcp, true, true);
  rig.board->start_servo(1.0);
  config::Config c = session_config();
  c.machine.axes[0].home_search_speed = 6000;
  c.machine.axes[0].home_latch_speed = 600;
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(c, 1u, *rig.link, nullptr, state, error, nullptr)) << error;
  sim::ScriptedGpio gpio;
  ASSERT_TRUE(gpio.estop_at(0.2, true));
  Vec2<double> at{};
  EXPECT_FALSE(machine::jog_to(*rig.link, &gpio, {100.0, 30.0}, 10.0, at, error));
  EXPECT_EQ(error, "E-stop: the jog stopped");
  EXPECT_EQ(rig.board->status().state, hal::BoardState::fault);
  EXPECT_GT(at.x, 5.0);   // it had moved
  EXPECT_LT(at.x, 40.0);  // and stopped about 2 mm into a 95 mm jog
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_NEAR(rig.board->status().position.x, at.x, 0.5);  // braked, not travelling on
}

// Continuous jog (jog until released): to the soft limit at most, stopped by
// the operator letting go (a ramp to a stop on the path, then idle) or the
// E-stop. Refused before homing: tests/cli/bad_input.tsv (jog_continuous_not_homed).
motion::SoftLimits<double> x_limits() {
  motion::SoftLimits<double> lim;
  lim.on[0] = true;
  lim.min[0] = 0;
  lim.max[0] = 50;  // y unlimited
  return lim;
}

TEST(JogContinuous, StopsAtTheSoftLimit) {
  HomeRig rig(Wire::tcp, true);
  rig.board->start_servo(0.0);
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(session_config(), 3u, *rig.link, nullptr, state, error, nullptr)) << error;
  Vec2<double> to{};
  EXPECT_FALSE(machine::continuous_target({5.0, -1.0}, 1, 1, x_limits(), to));  // y has no limits
  ASSERT_TRUE(machine::continuous_target({5.0, -1.0}, 0, 1, x_limits(), to));
  EXPECT_EQ(to.x, 50.0);
  EXPECT_EQ(to.y, -1.0);
  Vec2<double> at{};
  ASSERT_TRUE(machine::jog_until_released(*rig.link, nullptr, to, 50.0, [] { return false; }, at, error)) << error;
  EXPECT_NEAR(at.x, 50.0, 1e-9);  // at the limit, not past it
  ASSERT_TRUE(machine::continuous_target(at, 0, -1, x_limits(), to));
  EXPECT_EQ(to.x, 0.0);
}

TEST(JogContinuous, StopsOnThePathWhenReleased) {
  HomeRig rig(Wire::tcp, true, true);
  rig.board->start_servo(1.0);
  config::Config c = session_config();
  c.machine.axes[0].home_search_speed = 6000;
  c.machine.axes[0].home_latch_speed = 600;
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(c, 1u, *rig.link, nullptr, state, error, nullptr)) << error;
  const auto t0 = std::chrono::steady_clock::now();
  auto released = [&] { return std::chrono::steady_clock::now() - t0 > std::chrono::milliseconds(200); };
  Vec2<double> at{};
  ASSERT_TRUE(machine::jog_until_released(*rig.link, nullptr, {50.0, 30.0}, 10.0, released, at, error)) << error;
  EXPECT_GT(at.x, 5.5);   // it had moved (about 2 mm in 0.2 s)
  EXPECT_LT(at.x, 20.0);  // and stopped far short of the limit
  const hal::BoardStatus st = rig.board->status();
  EXPECT_EQ(st.state, hal::BoardState::idle);  // released is no fault: ready for the next jog
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(rig.board->status().position.x, at.x);  // stopped, and stays
  ASSERT_TRUE(machine::jog_to(*rig.link, nullptr, {at.x + 1.0, 30.0}, 10.0, at, error)) << error;
}

TEST(JogContinuous, TheEStopStopsIt) {
  HomeRig rig(Wire::tcp, true, true);
  rig.board->start_servo(1.0);
  config::Config c = session_config();
  c.machine.axes[0].home_search_speed = 6000;
  c.machine.axes[0].home_latch_speed = 600;
  job::MachineState state;
  std::string error;
  ASSERT_TRUE(machine::home_axes(c, 1u, *rig.link, nullptr, state, error, nullptr)) << error;
  sim::ScriptedGpio gpio;
  ASSERT_TRUE(gpio.estop_at(0.2, true));
  Vec2<double> at{};
  EXPECT_FALSE(machine::jog_until_released(*rig.link, &gpio, {50.0, 30.0}, 10.0, [] { return false; }, at, error));
  EXPECT_EQ(error, "E-stop: the jog stopped");
  EXPECT_EQ(rig.board->status().state, hal::BoardState::fault);
  EXPECT_GT(at.x, 5.0);
  EXPECT_LT(at.x, 20.0);
}

// A GPIO home switch (home_input): kerf searches it with jog moves and the
// board takes the latch point as the home (home block dir 0). The double is a
// switch fixed on the machine: program input 3 reads x <= at, x in the
// power-up frame (the board's position plus the frame shift the test gives it
// once the board has taken its new home).
class SwitchAt final : public hal::Gpio {
 public:
  SwitchAt(sim::MotionBoard& b, bool present, double at, double estop_after_s = -1)
      : board_(b), present_(present), at_(at), estop_after_(estop_after_s) {}
  bool read(double now_s, hal::GpioInputs& in) override {
    in = {};
    in.estop = estop_after_ >= 0 && now_s >= estop_after_;
    return true;
  }
  bool read_input(int number, double, bool& value) override {
    value = number == 3 && present_ && board_.status().position.x + shift_ <= at_;
    return true;
  }
  void shift(double s) { shift_ = s; }
  bool set_torch(bool) override { return true; }
  const char* last_error() const override { return ""; }

 private:
  sim::MotionBoard& board_;
  bool present_;
  double at_, estop_after_;
  double shift_ = 0;
};

config::Config gpio_switch_config() {
  config::Config c = session_config();
  c.machine.axes[0].home_input = 3;
  c.machine.axes[0].home_search_speed = 1200;  // 20 mm/s
  c.machine.axes[0].home_latch_speed = 30;     // 0.5 mm/s
  c.machine.axes[0].home_search_distance = 60;
  c.machine.axes[0].home_backoff = 0.5;
  hal::GpioProgramLine l;
  l.number = 3;
  c.gpio.inputs.push_back(l);
  return c;
}

TEST(GpioHomeSwitch, FoundAtItsPositionWithinAFewPollsOfLatchTravel) {
  HomeRig rig(Wire::tcp, false, true);  // the board's own x switch is not the one searched: its frame is
  rig.board->start_servo(1.0);
  SwitchAt sw(*rig.board, true, 37.0);  // 3 mm from where x powered up (40)
  const config::Config c = gpio_switch_config();
  hal::HomeCommand here;
  std::string error;
  ASSERT_TRUE(machine::search_gpio_switch(*rig.link, sw, machine::home_command(c.machine, 0), 3, here, error))
      << error;
  EXPECT_EQ(here.dir, 0);
  const double before = rig.board->status().position.x;  // at rest, power-up frame
  ASSERT_EQ(rig.link->home(here, {}), hal::LinkError::none) << rig.link->last_error();
  const hal::BoardStatus st = rig.wait_homing_end();
  EXPECT_EQ(st.homing, hal::HomingState::done);
  EXPECT_EQ(st.homed & 1u, 1u);
  EXPECT_EQ(st.state, hal::BoardState::idle);
  sw.shift(before - st.position.x);
  // Where the switch is, in the new frame: jog back until it trips at the
  // latch speed again; that is home_position (5), within 50 ms of latch
  // travel (the host polls the board and the line, about 10 ms a round, once
  // for the latch and once for this check; seen: 12-16 µm at 0.5 mm/s).
  Vec2<double> at{}, seen{};
  ASSERT_TRUE(machine::jog_until_released(*rig.link, &sw, {-10.0, st.position.y}, 0.5,
                                          [&] { bool v = false; sw.read_input(3, 0, v); return v; }, at, error, &seen))
      << error;
  std::printf("GPIO home switch: found at %.4f mm (home position 5 mm)\n", seen.x);
  EXPECT_NEAR(seen.x, 5.0, 0.5 * 0.05);
}

TEST(GpioHomeSwitch, ASwitchThatNeverTripsIsAFaultInsideTheSearchDistance) {
  HomeRig rig(Wire::tcp, false, false);
  rig.board->start_servo(0.0);
  SwitchAt sw(*rig.board, false, 0.0);
  job::MachineState state;
  std::string error;
  EXPECT_FALSE(machine::home_axes(gpio_switch_config(), 1u, *rig.link, &sw, state, error, nullptr));
  EXPECT_EQ(error, "x: the switch never tripped within the search distance (60.000000 mm, GPIO input 3)");
  EXPECT_FALSE(state.homed[0]);
  EXPECT_NEAR(rig.board->status().position.x, 40.0 - 60.0, 1e-9);  // the whole distance, not past it
  EXPECT_EQ(rig.board->status().homed, 0);
}

TEST(GpioHomeSwitch, TheEStopStopsTheSearchUnhomed) {
  HomeRig rig(Wire::tcp, false, true);
  rig.board->start_servo(1.0);
  SwitchAt sw(*rig.board, true, 0.0, 0.2);  // the switch 40 mm off at 20 mm/s; the E-stop at 0.2 s
  job::MachineState state;
  state.homed[0] = true;
  std::string error;
  EXPECT_FALSE(machine::home_axes(gpio_switch_config(), 1u, *rig.link, &sw, state, error, nullptr));
  EXPECT_EQ(error, "x: E-stop: the jog stopped");
  EXPECT_FALSE(state.homed[0]);
  EXPECT_EQ(rig.board->status().homed, 0);
  EXPECT_LT(rig.board->status().position.x, 40.0 - 1.0);  // it had moved
  EXPECT_GT(rig.board->status().position.x, 30.0);        // and stopped
}

TEST(GpioHomeSwitch, RefusedWithoutItsInputLineOrOverCan) {
  config::Config c = gpio_switch_config();
  c.gpio.inputs.clear();
  HomeRig rig(Wire::tcp);
  rig.board->start_servo(0.0);
  SwitchAt sw(*rig.board, true, 37.0);
  job::MachineState state;
  std::string error;
  EXPECT_FALSE(machine::home_axes(c, 1u, *rig.link, &sw, state, error, nullptr));
  EXPECT_NE(error.find("home_input = 3: no [[gpio.input]] with that number"), std::string::npos) << error;
  c = gpio_switch_config();
  c.link.kind = config::Link::Kind::can;
  EXPECT_FALSE(machine::home_axes(c, 1u, *rig.link, &sw, state, error, nullptr));
  EXPECT_NE(error.find("a GPIO home switch needs the Modbus board"), std::string::npos) << error;
}

}  // namespace
}  // namespace kerf::test
