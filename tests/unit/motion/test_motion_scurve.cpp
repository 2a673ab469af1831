// S-curve ramps (jerk > 0): the jerk and acceleration limits measured from
// the setpoints, with the path, cruise and end guarantees of the trapezoid.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "motion_helpers.hpp"

namespace kerf::motion {
namespace {

using namespace test;

// Largest |second| and |third| differences of s (with rest before and after),
// as acceleration and jerk.
struct Measured {
  double accel = 0;
  double jerk = 0;
};
Measured measure(const std::vector<Setpoint<double>>& sp, double period) {
  std::vector<double> s(3, 0.0);
  for (const auto& p : sp) s.push_back(p.s);
  for (int i = 0; i < 3; ++i) s.push_back(sp.back().s);
  Measured m;
  for (std::size_t k = 3; k < s.size(); ++k) {
    const double d2 = s[k] - 2 * s[k - 1] + s[k - 2];
    const double d3 = s[k] - 3 * s[k - 1] + 3 * s[k - 2] - s[k - 3];
    m.accel = std::max(m.accel, std::fabs(d2) / (period * period));
    m.jerk = std::max(m.jerk, std::fabs(d3) / (period * period * period));
  }
  return m;
}

std::vector<Seg> mixed_path() {
  std::vector<Seg> p;
  p.push_back(line_from({0, 0}, 0.0, 25));
  p.push_back(arc_from(p.back().end, 0.0, 8, kPi / 2));
  p.push_back(line_from(p.back().end, kPi / 2, 0.4));  // shorter than the braking distance
  p.push_back(line_from(p.back().end, kPi, 15));       // a 90 degree corner
  for (int i = 0; i < 30; ++i) p.push_back(line_from(p.back().end, kPi, 0.03));
  return p;
}

TEST(MotionSCurve, KeepsJerkAndAccelerationLimitsAndTheTrapezoidsGuarantees) {
  const std::vector<Seg> path = mixed_path();
  const double feed = 80, accel = 1500, jerk = 60000, period = 1e-3;
  const auto c = config(period, accel, 1.0, 1000.0, jerk);
  const auto sp = run_path(path, feed, c, 16);
  ASSERT_FALSE(sp.empty());
  const Measured m = measure(sp, period);
  EXPECT_LE(m.accel, accel * (1 + 1e-6));
  EXPECT_LE(m.jerk, jerk * (1 + 1e-6));
  EXPECT_GT(m.jerk, jerk * 0.5);  // the measure sees the ramps at all
  double prev = 0;
  for (const auto& p : sp) {
    const V want = path_point(path, p.s);
    ASSERT_LE(std::hypot(p.position.x - want.x, p.position.y - want.y), 1e-9) << p.s;
    ASSERT_GE(p.s, prev);
    prev = p.s;
  }
  EXPECT_EQ(sp.back().position, path.back().end);
  int cruise = 0;
  for (std::size_t k = 1; k < sp.size(); ++k)
    cruise += std::fabs((sp[k].s - sp[k - 1].s) / period - feed) <= 1e-9 * feed ? 1 : 0;
  EXPECT_GT(cruise, 100);  // the first line is cruised at exactly the feed
}

TEST(MotionSCurve, KeepsToTheCornerSpeedAtSquareCorners) {
  std::vector<Seg> path;
  V at{0, 0};
  for (int side = 0; side < 4; ++side) {
    path.push_back(line_from(at, side * kPi / 2, 10));
    at = path.back().end;
  }
  const auto c = config(1e-3, 500, 1.0, 200.0, 10000);  // a window of 100 periods
  const auto sp = run_path(path, 20.0, c, 8);
  ASSERT_FALSE(sp.empty());
  EXPECT_EQ(sp.back().position, path.back().end);
  const double corner_speed = c.accel * c.period / std::sqrt(2.0);
  for (int corner = 1; corner <= 3; ++corner) {
    const double s_corner = 10.0 * corner;
    for (std::size_t k = 1; k < sp.size(); ++k) {
      if (sp[k - 1].s <= s_corner + 1e-12 && sp[k].s > s_corner + 1e-12) {
        EXPECT_LE(sp[k].speed, corner_speed * (1 + 1e-9)) << "corner " << corner;
      }
    }
  }
  for (std::size_t k = 2; k < sp.size(); ++k) {
    const V v0 = (sp[k - 1].position - sp[k - 2].position) * (1 / c.period);
    const V v1 = (sp[k].position - sp[k - 1].position) * (1 / c.period);
    ASSERT_LE((v1 - v0).norm(), 2 * c.accel * c.period * (1 + 1e-9)) << "period " << k;
  }
  const Measured m = measure(sp, c.period);
  EXPECT_LE(m.jerk, c.jerk * (1 + 1e-6));
}

TEST(MotionSCurve, FeedHoldStopsWithinTheBrakingDistance) {
  const auto c = config(1e-3, 1500, 1.0, 1000.0, 60000);
  std::vector<QueuedSegment<double>> slots(4);
  std::vector<double> window(Interpolator<double>::jerk_window_size(c));
  Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()),
                          Span<double>(window.data(), window.size()));
  ASSERT_EQ(ip.configure(c), Status::ok);
  ASSERT_EQ(ip.push({Seg::line({0, 0}, {100, 0}), 80.0, 1}), Status::ok);
  Setpoint<double> p;
  for (int k = 0; k < 300; ++k) p = ip.step();
  ASSERT_NEAR(p.speed, 80.0, 1e-7);
  const double promised = ip.braking_distance();
  const double s_hold = p.s;
  ip.hold();
  std::vector<Setpoint<double>> sp;
  do {
    sp.push_back(ip.step());
    ASSERT_LT(sp.size(), 2000u);
  } while (sp.back().state != MotionState::held);
  EXPECT_LE(sp.back().s - s_hold, promised + 1e-12);
  EXPECT_GT(sp.back().s - s_hold, 0.5 * promised);
  ip.resume();
  const Setpoint<double> first = ip.step();
  EXPECT_GT(first.s, sp.back().s);  // moves at once: no repeated setpoint
  EXPECT_LT(first.s - sp.back().s, 1e-3 * 80.0);
}

}  // namespace
}  // namespace kerf::motion
