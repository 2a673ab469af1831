// Safety on the simulated machine: the latched E-stop with its reset and
// watchdog output, and the following-error fault when an axis stalls, on the
// Modbus board and on the CAN drives.
#include <gtest/gtest.h>

#include <cmath>

#include "machine/machine_run.hpp"
#include "fake_gpio.hpp"
#include "simulated/can_sim_machine.hpp"
#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"

namespace kerf::test {
namespace {

using control::State;

// An L of two lines, then a half circle of radius 10 (from (60,0) to (80,0)
// about (70,0)) and a line: the second path pierces at about 2.1 s, its arc
// runs until about 2.75 s.
control::Job l_then_arc() {
  auto seg = [](Vec2<double> end, SegmentKind kind = SegmentKind::line, Vec2<double> c = {}, int dir = 0) {
    hal::SegmentCommand s;
    s.kind = kind;
    s.end = end;
    s.centre = c;
    s.dir = static_cast<std::int8_t>(dir);
    s.feed = 50.0;
    return s;
  };
  control::Job job;
  control::CutPath a;
  a.start = {0, 0};
  a.segments = {seg({40, 0}), seg({40, 30})};
  control::CutPath b;
  b.start = {60, 0};
  b.segments = {seg({80, 0}, SegmentKind::arc, {70, 0}, 1), seg({100, 0})};
  job.paths = {a, b};
  return job;
}

control::ControllerConfig cut_config(bool reset_line) {
  control::ControllerConfig c;
  c.pierce_delay_s = 0.1;
  c.arc_ok_timeout_s = 0.5;
  c.rapid_feed_mm_s = 200.0;
  c.wait_for_reset = reset_line;
  c.ferror.max_speed_mm_s = 200.0;
  return c;
}

void press_reset(FakeGpio& g, double t) {
  g.at(t, [](FakeGpio& x) { x.inputs.reset = true; });
  g.at(t + 0.1, [](FakeGpio& x) { x.inputs.reset = false; });
}

// The last trace sample's position equals the one at time t: nothing moved since.
bool still_since(const simulated::SimMachineResult& r, double t) {
  for (const auto& s : r.trace)
    if (s.t_s >= t && distance(s.pos, r.trace.back().pos) > 0.0) return false;
  return true;
}

TEST(SafetyLatch, EStopReleasedWithoutResetStaysStopped) {
  FakeGpio gpio;
  gpio.at(2.4, [](FakeGpio& g) { g.inputs.estop = true; });
  gpio.at(2.6, [](FakeGpio& g) { g.inputs.estop = false; });
  simulated::SimMachineConfig m;
  m.max_sim_s = 4.0;  // it would wait for a reset for ever
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(true), m, gpio, nullptr, {});
  EXPECT_EQ(r.setup_error, "the job did not finish within the simulation's time limit");
  EXPECT_EQ(r.run.state, State::estop);
  EXPECT_EQ(r.run.reason, "E-stop");
  EXPECT_EQ(r.run.last_completed, 1);
  EXPECT_FALSE(gpio.torch());
  EXPECT_TRUE(still_since(r, 2.7)) << "moved after the E-stop was released without a reset";
  EXPECT_EQ(r.run.resets, 1u);  // the start-up one only
  ASSERT_FALSE(gpio.watchdog_changes.empty());
  EXPECT_LE(gpio.watchdog_changes.back(), 2.4 + 1e-9) << "the watchdog kept toggling after the E-stop";
}

TEST(SafetyLatch, ResetWhileTheEStopIsAssertedIsRefused) {
  FakeGpio gpio;
  gpio.at(2.4, [](FakeGpio& g) { g.inputs.estop = true; });
  press_reset(gpio, 3.0);
  simulated::SimMachineConfig m;
  m.max_sim_s = 3.5;
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(true), m, gpio, nullptr, {});
  EXPECT_EQ(r.run.state, State::estop);
  EXPECT_EQ(r.run.reset_refused, "reset refused: the E-stop is still asserted");
  EXPECT_EQ(r.run.resets, 1u);
  EXPECT_TRUE(still_since(r, 2.7));
  EXPECT_LE(gpio.watchdog_changes.back(), 2.4 + 1e-9);
}

TEST(SafetyLatch, ReleaseThenResetGoesBackToReadyAndFinishesTheJob) {
  FakeGpio gpio;
  gpio.at(2.4, [](FakeGpio& g) { g.inputs.estop = true; });
  gpio.at(2.6, [](FakeGpio& g) { g.inputs.estop = false; });
  press_reset(gpio, 3.0);
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(true), {}, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.run.reset_refused, "");
  EXPECT_EQ(r.run.resets, 2u);
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1, 2, 3}));  // the arc finished after the reset, once
  EXPECT_EQ(r.run.pierces, 3u);  // re-pierced where the E-stop cut off the arc
  EXPECT_TRUE(still_since(r, 2.7) == false);
  // Stopped from the E-stop until the reset, pumping again after it.
  for (double t : gpio.watchdog_changes) EXPECT_FALSE(t > 2.4 + 1e-9 && t < 3.0) << t;
  EXPECT_GT(gpio.watchdog_changes.back(), 3.0);
}

TEST(SafetyLatch, EStopHeldAtStartUpWithAResetLineWaitsThenRuns) {
  FakeGpio gpio;
  gpio.inputs.estop = true;  // from power-up: the start-up reset is refused
  gpio.at(0.5, [](FakeGpio& g) { g.inputs.estop = false; });
  press_reset(gpio, 1.0);
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(true), {}, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.run.reset_refused, "reset refused: the E-stop is still asserted");
  ASSERT_FALSE(gpio.changes.empty());
  EXPECT_GT(gpio.changes.front().t, 1.0) << "the torch came on before the reset";
  EXPECT_TRUE(gpio.watchdog_changes.empty() || gpio.watchdog_changes.front() >= 1.0);
}

TEST(SafetyLatch, WatchdogTogglesEveryCycleWhileAllIsWell) {
  FakeGpio gpio;
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(false), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  ASSERT_GT(gpio.watchdog_changes.size(), 100u);
  for (std::size_t i = 1; i < gpio.watchdog_changes.size(); ++i)
    ASSERT_NEAR(gpio.watchdog_changes[i] - gpio.watchdog_changes[i - 1], 0.002, 1e-9) << i;
  EXPECT_EQ(r.run.watchdog_toggles, gpio.watchdog_changes.size());
}

// The x axis stalls at 2.4 s, on the arc: the following error must trip
// within a cycle of crossing the limit, with the torch off in that cycle.
void expect_following_error_fault(const control::RunReport& run, const FakeGpio& gpio, double stall_t) {
  EXPECT_EQ(run.state, State::fault);
  EXPECT_EQ(run.reason.rfind("following error ", 0), 0u) << run.reason;
  EXPECT_NE(run.reason.find("on axis x"), std::string::npos) << run.reason;
  EXPECT_GT(run.ferror_at_fault_mm, run.ferror_limit_mm);
  // The gap grows at most at the feed (50 mm/s): over the limit by at most one 2 ms cycle's travel.
  EXPECT_LE(run.ferror_at_fault_mm, run.ferror_limit_mm + 50.0 * 0.002 + 1e-6);
  // The limit at the feed: between min_ferror and ferror.
  EXPECT_GE(run.ferror_limit_mm, 0.25);
  EXPECT_LE(run.ferror_limit_mm, 1.0);
  EXPECT_GT(run.reason_t_s, stall_t);
  EXPECT_LT(run.reason_t_s, stall_t + 0.1);
  ASSERT_FALSE(gpio.changes.empty());
  EXPECT_FALSE(gpio.changes.back().on);
  EXPECT_DOUBLE_EQ(gpio.changes.back().t, run.reason_t_s) << "the torch went off in a later cycle";
  EXPECT_EQ(run.last_completed, 1);
  ASSERT_TRUE(run.has_cut_to);
  EXPECT_EQ(run.cut_to.segment, 2u);  // progress kept on the arc
  EXPECT_LT(std::abs(distance(run.cut_to.at, Vec2<double>{70, 0}) - 10.0), 2e-3);
  ASSERT_FALSE(gpio.watchdog_changes.empty());
  EXPECT_LE(gpio.watchdog_changes.back(), run.reason_t_s + 0.002 + 1e-9) << "the watchdog kept toggling";
  ::testing::Test::RecordProperty("ferror_at_fault_mm", std::to_string(run.ferror_at_fault_mm));
  ::testing::Test::RecordProperty("ferror_limit_mm", std::to_string(run.ferror_limit_mm));
  ::testing::Test::RecordProperty("fault_t_s", std::to_string(run.reason_t_s));
  std::printf("following error %.4f mm at t=%.3f s (limit %.4f mm); torch off at t=%.3f s; max before %.4f mm\n",
              run.ferror_at_fault_mm, run.reason_t_s, run.ferror_limit_mm, gpio.changes.back().t,
              run.max_ferror_mm);
}

TEST(FollowingError, StalledAxisMidArcFaultsOnTheModbusBoard) {
  FakeGpio gpio;
  simulated::SimMachineConfig m;
  m.faults = {{simulated::BoardFaultKind::stall, 2.4, 0.0}};
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(false), m, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  expect_following_error_fault(r.run, gpio, 2.4);
  EXPECT_EQ(r.board.state, hal::BoardState::fault);  // aborted: braked on the path
}

TEST(FollowingError, StalledAxisMidArcFaultsOnTheCanDrives) {
  FakeGpio gpio;
  simulated::CanMachineConfig m;
  m.faults = {{simulated::CanFaultKind::stall, 2.4}};
  const auto r = simulated::run_can_sim_machine(l_then_arc(), cut_config(false), m, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  expect_following_error_fault(r.run, gpio, 2.4);
}

TEST(FollowingError, NoFaultWithoutAStallOnEitherLink) {
  FakeGpio a, b;
  const auto modbus = simulated::run_sim_machine(l_then_arc(), cut_config(false), {}, a, nullptr, {});
  EXPECT_EQ(modbus.run.state, State::done) << modbus.run.reason;
  EXPECT_GT(modbus.run.max_ferror_mm, 0.0);  // the plant lags: the check sees a gap
  const auto can = simulated::run_can_sim_machine(l_then_arc(), cut_config(false), {}, b, nullptr, {});
  EXPECT_EQ(can.run.state, State::done) << can.run.reason;
  EXPECT_GT(can.run.max_ferror_mm, 0.0);
  std::printf("largest following error without a stall: modbus %.4f mm, can %.4f mm\n", modbus.run.max_ferror_mm,
              can.run.max_ferror_mm);
}

// `kerf run`'s loop (machine::run_on_machine) on the simulated board, in real time.
// (A run that nothing could reset is refused before any device opens: the
// CLI row run_no_reset, tests/cli/bad_input.tsv.)
TEST(KerfRunLatch, StartUpResetWithTheEStopAssertedIsRefusedAndSaysSo) {
  FakeGpio gpio;
  gpio.inputs.estop = true;
  std::string error;
  auto plant = simulated::make_modbus_plant(simulated::SimMachineConfig{}, 0.5, error);
  ASSERT_TRUE(plant) << error;
  config::Config cfg = config::defaults();
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const int rc = machine::run_on_machine(l_then_arc(), cfg, plant->link(), gpio, nullptr, {}, false, "", true);
  const std::string err = ::testing::internal::GetCapturedStderr();
  ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(rc, 1);
  EXPECT_NE(err.find("kerf: run: reset refused: the E-stop is still asserted"), std::string::npos) << err;
  EXPECT_NE(err.find(": E-stop\n"), std::string::npos) << err;
  EXPECT_TRUE(gpio.changes.empty()) << "the torch came on";
  EXPECT_TRUE(gpio.watchdog_changes.empty()) << "the watchdog pumped while latched";
}

// [cut] vad reaches the board (80 % here, not the 0.9 default): its thc_lock
// is on exactly while the speed is below 80 % of the 50 mm/s feed. The
// controller's gpio.thc_lock follows it while the torch is on, off otherwise.
TEST(ThcLockOutput, FollowsTheBoardWhileTheTorchIsOn) {
  FakeGpio gpio;
  simulated::SimMachineConfig m;
  m.motion.vad = 0.8;
  const auto r = simulated::run_sim_machine(l_then_arc(), cut_config(false), m, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  const double period = r.trace[2].t_s - r.trace[1].t_s;
  int checked = 0, between = 0;  // between: 40..45 mm/s, where 0.9 would differ
  for (std::size_t k = 1; k < r.trace.size(); ++k) {
    if (r.trace[k].seq == 0 || !r.trace[k].torch) continue;
    const double v = distance(r.trace[k].pos, r.trace[k - 1].pos) / period;
    if (std::fabs(v - 40.0) < 0.05) continue;  // the rounding of the step decides
    EXPECT_EQ(r.trace[k].thc_lock, v < 40.0) << "sample " << k << " at " << v << " mm/s";
    ++checked;
    if (v > 40.0 && v < 45.0) ++between;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(between, 0);

  auto torch_at = [&](double t) {
    bool on = false;
    for (const auto& c : gpio.changes)
      if (c.t <= t) on = c.on;
    return on;
  };
  const double window = 0.006;  // a controller cycle (2 ms) and the poll behind it
  ASSERT_GE(gpio.thc_lock_changes.size(), 4u);
  EXPECT_FALSE(gpio.thc_lock) << "left on after the job";
  for (const auto& c : gpio.thc_lock_changes) {
    EXPECT_TRUE(!c.on || torch_at(c.t)) << "thc_lock on with the torch off at " << c.t;
    if (!torch_at(c.t)) continue;  // off with the torch
    bool seen = false;
    for (const auto& s : r.trace)
      if (s.t_s >= c.t - window && s.t_s <= c.t && s.thc_lock == c.on) seen = true;
    EXPECT_TRUE(seen) << "gpio.thc_lock " << c.on << " at " << c.t << " without the board's";
  }
  // Every edge of the board's flag while the torch is on reaches the output.
  int edges = 0;
  for (std::size_t k = 1; k < r.trace.size(); ++k) {
    const double t = r.trace[k].t_s;
    if (r.trace[k].thc_lock == r.trace[k - 1].thc_lock || !torch_at(t - window) || !torch_at(t + window)) continue;
    ++edges;
    bool followed = false;
    for (const auto& c : gpio.thc_lock_changes)
      if (c.on == r.trace[k].thc_lock && c.t >= t - 1e-9 && c.t <= t + window) followed = true;
    EXPECT_TRUE(followed) << "the board's thc_lock went " << r.trace[k].thc_lock << " at " << t;
  }
  EXPECT_GE(edges, 4);
}

}  // namespace
}  // namespace kerf::test
