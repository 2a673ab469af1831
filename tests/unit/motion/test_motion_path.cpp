// The interpolator on whole paths: cruise speed, setpoints on the path, no
// drift, limits, never overshooting or going back.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "motion_helpers.hpp"

namespace kerf::motion {
namespace {

using namespace test;

// Tangent-continuous: line, left arc, right arc, line, long gentle arc.
std::vector<Seg> smooth_path() {
  std::vector<Seg> p;
  p.push_back(line_from({1, 2}, 0.0, 30));
  p.push_back(arc_from(p.back().end, 0.0, 10, kPi / 2));
  p.push_back(arc_from(p.back().end, kPi / 2, 5, -2 * kPi / 3));
  const double h = kPi / 2 - 2 * kPi / 3;
  p.push_back(line_from(p.back().end, h, 20));
  p.push_back(arc_from(p.back().end, h, 50, kPi / 6));
  return p;
}

// Every check that holds for any path: on the path at s, counts rounded from
// the position, s never decreasing or past the end, the end reached exactly,
// and the acceleration along the path within the limit.
void expect_valid_run(const std::vector<Seg>& path, const std::vector<Setpoint<double>>& sp,
                      const MotionConfig<double>& c) {
  ASSERT_FALSE(sp.empty());
  const double total = path_length(path);
  double prev = 0;
  for (const auto& p : sp) {
    const V want = path_point(path, p.s);
    ASSERT_LE(std::hypot(p.position.x - want.x, p.position.y - want.y), 1e-9) << "s " << p.s;
    ASSERT_EQ(p.counts, to_counts(p.position, c.counts_per_mm));
    ASSERT_GE(p.s, prev);
    ASSERT_LE(p.s, total + 1e-9);
    prev = p.s;
  }
  EXPECT_EQ(sp.back().position, path.back().end);
  EXPECT_NEAR(sp.back().s, total, 1e-9);
  const std::vector<double> steps = step_lengths(sp);
  const double limit = c.accel * c.period * c.period;
  double prev_step = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    ASSERT_LE(std::fabs(steps[k] - prev_step), limit * (1 + 1e-9) + 1e-14) << "period " << k;
    prev_step = steps[k];
  }
}

TEST(MotionPath, CruisesAtTheFeedAcrossTangentJointsAndStaysOnThePath) {
  const std::vector<Seg> path = smooth_path();
  // v^2 / r = 1280 mm/s^2 on the r = 5 arc: below the arcs' cap, 0.85 accel
  const double feed = 80, accel = 2000, period = 1e-3;
  const auto c = config(period, accel);
  const auto sp = run_path(path, feed, c);
  expect_valid_run(path, sp, c);
  for (std::size_t k = 2; k < sp.size(); ++k) {  // in the plane too
    const V d2 = sp[k].position - sp[k - 1].position * 2.0 + sp[k - 2].position;
    ASSERT_LE(d2.norm() / (period * period), accel * (1 + 1e-6)) << "period " << k;
  }
  const double ramp = feed * feed / (2 * accel) + 3 * feed * period;
  // the end of the queue is braked for with the normal part's share left (it
  // may become a joint of any turn when more is pushed)
  const double end_ramp = feed * feed / (2 * accel * std::sqrt(1 - kShare * kShare)) + 3 * feed * period;
  const double total = path_length(path);
  int cruise = 0, joints = 0;
  for (std::size_t k = 1; k < sp.size(); ++k) {
    if (sp[k - 1].s < ramp || sp[k].s > total - end_ramp) continue;
    const double v = (sp[k].s - sp[k - 1].s) / period;
    ASSERT_LE(std::fabs(v - feed) / feed, 1e-9) << "period " << k;
    ++cruise;
    if (sp[k].segment != sp[k - 1].segment) ++joints;
  }
  EXPECT_GT(cruise, 900);
  EXPECT_EQ(joints, 4);  // every joint is crossed at full speed
}

// At 100 mm/s the r = 5 arc would ask for 2000 mm/s^2 in the plane: the
// speed there is capped at sqrt(0.85 accel r), ramped into and out of, and
// the plane acceleration stays within the limit everywhere.
TEST(MotionPath, CapsTheSpeedOnTightArcsAndKeepsThePlaneAccelerationWithinTheLimit) {
  const std::vector<Seg> path = smooth_path();
  const double feed = 100, accel = 2000, period = 1e-3;
  const auto c = config(period, accel);
  const auto sp = run_path(path, feed, c);
  expect_valid_run(path, sp, c);
  const double cap = std::sqrt(kShare * accel * 5);
  double slowest_on_arc = feed;
  for (std::size_t k = 2; k < sp.size(); ++k) {
    const V d2 = sp[k].position - sp[k - 1].position * 2.0 + sp[k - 2].position;
    ASSERT_LE(d2.norm() / (period * period), accel * (1 + 1e-6)) << "period " << k;
    if (sp[k].segment == 2 && sp[k - 1].segment == 2) {
      EXPECT_LE(sp[k].speed, cap * (1 + 1e-9));
      slowest_on_arc = std::min(slowest_on_arc, sp[k].speed);
    }
  }
  EXPECT_GT(slowest_on_arc, 0.99 * cap);  // held at the cap, not below it
}

TEST(MotionPath, OverrideScalesTheCruiseSpeed) {
  const std::vector<Seg> path = smooth_path();
  const auto c = config(1e-3, 2000);
  std::vector<QueuedSegment<double>> slots(8);
  Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()));
  ASSERT_EQ(ip.configure(c), Status::ok);
  for (std::size_t i = 0; i < path.size(); ++i)
    ASSERT_EQ(ip.push({path[i], 50.0, static_cast<std::uint32_t>(i)}), Status::ok);
  EXPECT_EQ(ip.set_override(9.99), Status::invalid_argument);
  EXPECT_EQ(ip.set_override(200.01), Status::invalid_argument);
  EXPECT_EQ(ip.set_override(10), Status::ok);
  ASSERT_EQ(ip.set_override(200), Status::ok);
  Setpoint<double> p;
  for (int k = 0; k < 200; ++k) p = ip.step();
  EXPECT_NEAR(p.speed, 100.0, 100.0 * 1e-9);
  ASSERT_EQ(ip.set_override(10), Status::ok);
  for (int k = 0; k < 200; ++k) p = ip.step();
  EXPECT_NEAR(p.speed, 5.0, 5.0 * 1e-9);
}

// Square corners, a slower segment, and an end made of pieces far shorter
// than the braking distance.
TEST(MotionPath, SlowsForCornersFeedDropsAndShortEndPiecesWithinTheLimit) {
  std::vector<Seg> path;
  std::vector<double> feeds;
  V at{0, 0};
  for (int side = 0; side < 4; ++side) {
    path.push_back(line_from(at, side * kPi / 2, 10));
    feeds.push_back(side == 2 ? 30.0 : 100.0);
    at = path.back().end;
  }
  for (int i = 0; i < 40; ++i) {
    path.push_back(line_from(at, 0.0, 0.02));
    feeds.push_back(100.0);
    at = path.back().end;
  }
  const auto c = config(1e-3, 2000, 5.0);
  const auto sp = run_path(path, feeds, c, 8);
  expect_valid_run(path, sp, c);
  const double corner_speed = c.accel * c.period / std::sqrt(2.0);
  for (int corner = 1; corner <= 4; ++corner) {
    const double s_corner = 10.0 * corner;
    for (std::size_t k = 1; k < sp.size(); ++k) {
      // the steps that cross or leave the corner (the one before may end a
      // hair short of it at full ramp speed: the plane check below covers it)
      if (sp[k - 1].s <= s_corner + 1e-12 && sp[k].s > s_corner + 1e-12) {
        EXPECT_LE(sp[k].speed, corner_speed * (1 + 1e-9)) << "corner " << corner;
      }
    }
  }
  // In the plane, the velocity vector changes by at most accel * period along
  // the path plus accel * period at a corner.
  for (std::size_t k = 2; k < sp.size(); ++k) {
    const V v0 = (sp[k - 1].position - sp[k - 2].position) * (1 / c.period);
    const V v1 = (sp[k].position - sp[k - 1].position) * (1 / c.period);
    ASSERT_LE((v1 - v0).norm(), 2 * c.accel * c.period * (1 + 1e-9)) << "period " << k;
  }
  for (std::size_t k = 1; k < sp.size(); ++k) {
    if (sp[k - 1].s >= 20.0 && sp[k].s <= 30.0) {
      ASSERT_LE(sp[k].speed, 30.0 * (1 + 1e-9));
    }
  }
}

TEST(MotionPath, NoDriftAfterAMillionShortSegments) {
  // 1e6 collinear pieces of 0.01 mm along (3, 4) / 5, odd counts per mm.
  const std::size_t n = 1000000;
  const V dir{0.6, 0.8};
  const V origin{-1234.5678, 987.654321};
  const double piece = 0.01, cpm = 1237.3;
  auto c = config(1e-3, 5000, 1.0, cpm);
  std::vector<QueuedSegment<double>> slots(1024);
  Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()));
  ASSERT_EQ(ip.configure(c), Status::ok);
  std::size_t next = 0;
  Setpoint<double> p;
  std::size_t periods = 0;
  do {
    while (next < n && ip.free_slots() > 0) {
      const Seg g = Seg::line(origin + dir * (piece * static_cast<double>(next)),
                              origin + dir * (piece * static_cast<double>(next + 1)));
      ASSERT_EQ(ip.push({g, 200.0, static_cast<std::uint32_t>(next)}), Status::ok);
      ++next;
    }
    p = ip.step();
    ++periods;
    if (periods % 997 == 0) {
      ASSERT_EQ(p.counts, to_counts(p.position, c.counts_per_mm));
    }
  } while (p.state != MotionState::done);
  const V end = origin + dir * (piece * static_cast<double>(n));
  EXPECT_LE(std::fabs(static_cast<double>(p.counts.x) - end.x * cpm), 0.5);
  EXPECT_LE(std::fabs(static_cast<double>(p.counts.y) - end.y * cpm), 0.5);
  EXPECT_EQ(ip.completed_count(), n);
  EXPECT_EQ(ip.last_completed_sequence(), n - 1);
  EXPECT_NEAR(p.s, piece * static_cast<double>(n), 1e-6);
  // full speed most of the way: the queue holds more than the braking distance
  EXPECT_LT(periods, static_cast<std::size_t>(10000.0 / 200.0 / 1e-3 * 1.01));
}

}  // namespace
}  // namespace kerf::motion
