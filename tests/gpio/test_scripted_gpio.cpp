// sim::ScriptedGpio: the arc model, scripted inputs, the torch timeline.
#include "kerf/sim/scripted_gpio.hpp"

#include <gtest/gtest.h>

namespace kerf::sim {
namespace {

hal::GpioInputs read_at(ScriptedGpio& g, double t) {
  hal::GpioInputs in;
  EXPECT_TRUE(g.read(t, in)) << g.last_error();
  return in;
}

TEST(ScriptedGpio, ArcOkFollowsTheTorchAfterTheDelay) {
  ScriptedGpio g(ScriptedGpioOptions{0, 0.25, 0.1});
  EXPECT_FALSE(read_at(g, 1.0).arc_ok);
  ASSERT_TRUE(g.set_torch(true));  // at 1.0, the last read
  EXPECT_FALSE(read_at(g, 1.0).arc_ok);
  EXPECT_FALSE(read_at(g, 1.125).arc_ok);
  EXPECT_TRUE(read_at(g, 1.25).arc_ok);
  EXPECT_TRUE(read_at(g, 2.0).arc_ok);
  ASSERT_TRUE(g.set_torch(false));
  EXPECT_FALSE(read_at(g, 2.0).arc_ok);  // drops at once with the torch
}

TEST(ScriptedGpio, DefaultArcDelayIsFiftyMilliseconds) {
  ScriptedGpio g;
  read_at(g, 0.0);
  g.set_torch(true);
  EXPECT_FALSE(read_at(g, 0.04).arc_ok);
  EXPECT_TRUE(read_at(g, 0.06).arc_ok);
}

TEST(ScriptedGpio, NoArcDeniesOnlyTheNextTorchOn) {
  ScriptedGpio g(ScriptedGpioOptions{0, 0.25, 0.1});
  ASSERT_TRUE(g.no_arc_at(0.5));
  read_at(g, 0.5);
  g.set_torch(true);
  EXPECT_FALSE(read_at(g, 1.0).arc_ok);
  EXPECT_FALSE(read_at(g, 5.0).arc_ok);
  g.set_torch(false);
  read_at(g, 6.0);
  g.set_torch(true);  // the retry strikes
  EXPECT_TRUE(read_at(g, 6.25).arc_ok);
}

TEST(ScriptedGpio, ArcLostDropsArcOkWhileTheTorchStaysOn) {
  ScriptedGpio g(ScriptedGpioOptions{0, 0.25, 0.1});
  ASSERT_TRUE(g.arc_lost_at(2.0));
  read_at(g, 1.0);
  g.set_torch(true);
  EXPECT_TRUE(read_at(g, 1.5).arc_ok);
  EXPECT_TRUE(read_at(g, 1.999).arc_ok);
  EXPECT_FALSE(read_at(g, 2.0).arc_ok);
  EXPECT_TRUE(g.torch());
  EXPECT_FALSE(read_at(g, 3.0).arc_ok);
  g.set_torch(false);
  read_at(g, 4.0);
  g.set_torch(true);  // relit: the loss was of that one arc
  EXPECT_TRUE(read_at(g, 4.25).arc_ok);
}

TEST(ScriptedGpio, ArcLostWhileTheTorchIsOffChangesNothing) {
  ScriptedGpio g(ScriptedGpioOptions{0, 0.25, 0.1});
  ASSERT_TRUE(g.arc_lost_at(0.5));
  read_at(g, 1.0);
  g.set_torch(true);
  EXPECT_TRUE(read_at(g, 1.25).arc_ok);
}

TEST(ScriptedGpio, EstopAndLimitsAreLevels) {
  ScriptedGpio g(ScriptedGpioOptions{3, 0.05, 0.1});
  ASSERT_TRUE(g.estop_at(1.0, true));
  ASSERT_TRUE(g.estop_at(2.0, false));
  ASSERT_TRUE(g.limit_at(1.5, 2, true));
  EXPECT_FALSE(g.limit_at(1.5, 3, true));  // only 3 limit lines
  hal::GpioInputs in = read_at(g, 0.5);
  EXPECT_EQ(in.limit_count, 3);
  EXPECT_FALSE(in.estop);
  EXPECT_FALSE(in.any_limit());
  in = read_at(g, 1.0);
  EXPECT_TRUE(in.estop);
  EXPECT_FALSE(in.any_limit());
  in = read_at(g, 1.75);
  EXPECT_TRUE(in.estop);
  EXPECT_TRUE(in.limit[2]);
  EXPECT_FALSE(in.limit[0]);
  in = read_at(g, 2.0);
  EXPECT_FALSE(in.estop);
  EXPECT_TRUE(in.any_limit());
}

TEST(ScriptedGpio, PressesLastTheirDuration) {
  ScriptedGpio g(ScriptedGpioOptions{0, 0.05, 0.25});
  ASSERT_TRUE(g.hold_at(3.0));              // the default 0.25 s
  ASSERT_TRUE(g.cycle_start_at(4.0, 0.5));  // an explicit 0.5 s
  EXPECT_FALSE(read_at(g, 2.9).hold);
  EXPECT_TRUE(read_at(g, 3.0).hold);
  EXPECT_TRUE(read_at(g, 3.125).hold);
  EXPECT_FALSE(read_at(g, 3.25).hold);
  EXPECT_FALSE(read_at(g, 3.9).cycle_start);
  EXPECT_TRUE(read_at(g, 4.375).cycle_start);
  EXPECT_FALSE(read_at(g, 4.5).cycle_start);
}

TEST(ScriptedGpio, ResetIsAPressFromTheScriptOrTheCommandLine) {
  ScriptedGpio g(ScriptedGpioOptions{0, 0.05, 0.25});
  EXPECT_FALSE(g.has_reset());
  std::vector<GpioEvent> ev;
  std::string error;
  ASSERT_TRUE(parse_gpio_script("1.5 reset 0.5\n", "s", 0, ev, error)) << error;
  ASSERT_TRUE(parse_gpio_fault("reset@3", 0, ev, error)) << error;
  ASSERT_TRUE(g.add(ev, error)) << error;
  EXPECT_TRUE(g.has_reset());
  EXPECT_FALSE(read_at(g, 1.4).reset);
  EXPECT_TRUE(read_at(g, 1.9).reset);
  EXPECT_FALSE(read_at(g, 2.0).reset);
  EXPECT_TRUE(read_at(g, 3.2).reset);  // the default 0.25 s press
  EXPECT_FALSE(read_at(g, 3.25).reset);
}

TEST(ScriptedGpio, CountsWatchdogEdgesAtTheLastReadTime) {
  ScriptedGpio g;
  read_at(g, 0.5);
  g.set_watchdog(true);
  g.set_watchdog(true);  // no edge
  read_at(g, 0.75);
  g.set_watchdog(false);
  EXPECT_EQ(g.watchdog_changes(), 2u);
  EXPECT_EQ(g.watchdog_last_change_s(), 0.75);
}

TEST(ScriptedGpio, EventsAddedOutOfOrderApplyInTimeOrder) {
  ScriptedGpio g;
  ASSERT_TRUE(g.estop_at(2.0, false));
  ASSERT_TRUE(g.estop_at(1.0, true));
  EXPECT_TRUE(read_at(g, 1.5).estop);
  EXPECT_FALSE(read_at(g, 2.5).estop);
  // In the past already: applies at the next read.
  ASSERT_TRUE(g.estop_at(0.1, true));
  EXPECT_TRUE(read_at(g, 2.6).estop);
}

TEST(ScriptedGpio, ScriptEventsFeedTheModel) {
  std::vector<GpioEvent> ev;
  std::string error;
  ASSERT_TRUE(parse_gpio_script("0 no-arc\n1.25 estop on\n2.0 limit 0 on\n", "t", 1, ev, error))
      << error;
  ScriptedGpio g(ScriptedGpioOptions{1, 0.05, 0.1});
  ASSERT_TRUE(g.add(ev, error)) << error;
  read_at(g, 0.0);
  g.set_torch(true);
  hal::GpioInputs in = read_at(g, 1.0);
  EXPECT_FALSE(in.arc_ok);
  EXPECT_FALSE(in.estop);
  in = read_at(g, 2.0);
  EXPECT_TRUE(in.estop);
  EXPECT_TRUE(in.limit[0]);
  // A script for more limit lines than the model has is refused.
  ScriptedGpio none;
  EXPECT_FALSE(none.add(ev, error));
  EXPECT_EQ(error, "sim gpio: limit 0 out of range (0 limit lines)");
}

TEST(ScriptedGpio, RecordsTheTorchTimelineAtTheLastReadTime) {
  ScriptedGpio g;
  g.set_torch(false);  // no change, not recorded
  read_at(g, 0.5);
  g.set_torch(true);
  read_at(g, 0.75);
  g.set_torch(true);  // still on: not recorded
  read_at(g, 1.5);
  g.set_torch(false);
  read_at(g, 2.0);
  g.set_torch(true);
  const std::vector<TorchChange> want{{0.5, true}, {1.5, false}, {2.0, true}};
  EXPECT_EQ(g.torch_timeline(), want);
}

TEST(ScriptedGpio, InjectedFaults) {
  ScriptedGpio g;
  g.fail_reads_from(1.0);
  g.fail_torch_from(2.0);
  hal::GpioInputs in;
  EXPECT_TRUE(g.read(0.5, in));
  EXPECT_FALSE(g.read(1.0, in));
  EXPECT_NE(std::string(g.last_error()).find("read failed"), std::string::npos);
  EXPECT_TRUE(g.set_torch(true));  // the last read was at 1.0
  EXPECT_FALSE(g.read(2.0, in));
  EXPECT_FALSE(g.set_torch(false));
  EXPECT_NE(std::string(g.last_error()).find("torch write failed"), std::string::npos);
  EXPECT_TRUE(g.torch());  // the failed write changed nothing
}

}  // namespace
}  // namespace kerf::sim
