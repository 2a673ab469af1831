// The safety pieces on their own: the E-stop latch (LinuxCNC's estop_latch
// rules) and the following-error limit (LinuxCNC's FERROR/MIN_FERROR ramp).
#include <gtest/gtest.h>

#include "control/following_error.hpp"
#include "control/safety_latch.hpp"

namespace kerf::control {
namespace {

constexpr const char* kEStop = "the E-stop is still asserted";

TEST(SafetyLatchUnit, StartsLatchedAndNeedsAnEdge) {
  SafetyLatch l;  // no start-up reset
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(l.cycle(nullptr, true)) << "a reset line held from power-up is no edge";
  EXPECT_FALSE(l.ok());
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(l.cycle(nullptr, false));
  EXPECT_FALSE(l.ok());
  EXPECT_TRUE(l.cycle(nullptr, true));  // the rising edge
  EXPECT_TRUE(l.ok());
}

TEST(SafetyLatchUnit, EStopReleaseNoResetStaysLatched) {
  SafetyLatch l(true);
  EXPECT_TRUE(l.cycle(nullptr, false));
  l.cycle(kEStop, false);
  EXPECT_FALSE(l.ok());
  for (int i = 0; i < 100; ++i) l.cycle(nullptr, false);
  EXPECT_FALSE(l.ok());
  EXPECT_EQ(l.refused(), "");
}

TEST(SafetyLatchUnit, ResetWhileAssertedIsRefusedThenAcceptedOnceClear) {
  SafetyLatch l(true);
  l.cycle(nullptr, false);
  l.cycle(kEStop, false);
  EXPECT_FALSE(l.cycle(kEStop, true));
  EXPECT_FALSE(l.ok());
  EXPECT_EQ(l.refused(), "reset refused: the E-stop is still asserted");
  EXPECT_EQ(l.refusals(), 1u);
  l.cycle(kEStop, true);  // held: no second edge, no second refusal
  EXPECT_EQ(l.refusals(), 1u);
  l.cycle(nullptr, true);  // released, the button still held: no edge
  EXPECT_FALSE(l.ok());
  l.cycle(nullptr, false);
  EXPECT_TRUE(l.cycle(nullptr, true));
  EXPECT_TRUE(l.ok());
}

TEST(SafetyLatchUnit, StartUpResetWithTheEStopAssertedIsRefused) {
  SafetyLatch l(true);
  EXPECT_FALSE(l.cycle(kEStop, false));
  EXPECT_FALSE(l.ok());
  EXPECT_EQ(l.refusals(), 1u);
  EXPECT_FALSE(l.cycle(nullptr, false)) << "the start-up reset is one edge, not a standing permission";
}

TEST(SafetyLatchUnit, WatchdogTogglesOnlyWhileOk) {
  SafetyLatch l(true);
  bool last = l.watchdog();
  for (int i = 0; i < 10; ++i) {
    l.cycle(nullptr, false);
    EXPECT_NE(l.watchdog(), last) << i;
    last = l.watchdog();
  }
  l.trip();  // a fault
  for (int i = 0; i < 10; ++i) {
    l.cycle(nullptr, false);
    EXPECT_EQ(l.watchdog(), last) << i;
  }
  EXPECT_EQ(l.toggles(), 10u);
}

TEST(FerrorLimit, RampsFromMinAtRestToFerrorAtFullSpeed) {
  const FerrorLimits l{1.0, 0.25, 200.0};
  EXPECT_DOUBLE_EQ(ferror_limit(l, 0.0), 0.25);
  EXPECT_DOUBLE_EQ(ferror_limit(l, 100.0), 0.625);
  EXPECT_DOUBLE_EQ(ferror_limit(l, 200.0), 1.0);
  EXPECT_DOUBLE_EQ(ferror_limit(l, 400.0), 1.0);  // never above ferror
  EXPECT_DOUBLE_EQ(ferror_limit(l, -100.0), 0.625);
}

TEST(FerrorCheck, JudgesEachAxisAtItsOwnSpeed) {
  FollowingError f({1.0, 0.25, 200.0});
  EXPECT_FALSE(f.check({0, 0}, {0, 0}, 0.0).over);
  // x at 100 mm/s (limit 0.625), 0.6 behind: fine; y at rest, 0.3 off: over.
  const FerrorVerdict v = f.check({0.2, 0.0}, {-0.4, 0.3}, 0.002);
  EXPECT_TRUE(v.over);
  EXPECT_EQ(v.axis, 1);
  EXPECT_DOUBLE_EQ(v.limit_mm, 0.25);
  EXPECT_NEAR(v.error_mm, 0.3, 1e-12);
  EXPECT_NEAR(f.max_error_mm(), 0.6, 1e-12);
}

TEST(FerrorCheck, ARepeatedStatusKeepsTheSpeed) {
  FollowingError f({1.0, 0.25, 200.0});
  f.check({0, 0}, {0, 0}, 0.0);
  f.check({0.4, 0}, {0.0, 0}, 0.002);  // 200 mm/s, 0.4 behind: within 1.0
  const FerrorVerdict v = f.check({0.4, 0}, {0.0, 0}, 0.004);  // the same status again
  EXPECT_FALSE(v.over) << v.limit_mm;
  EXPECT_DOUBLE_EQ(v.limit_mm, 1.0);
  // Held no longer than kSpeedHoldS: at rest the limit is min_ferror again.
  EXPECT_TRUE(f.check({0.4, 0}, {0.0, 0}, 0.004 + kSpeedHoldS + 0.001).over);
}

}  // namespace
}  // namespace kerf::control
