// Feed hold, resume, abort, the bounded queue and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "motion_helpers.hpp"

namespace kerf::motion {
namespace {

using namespace test;

struct Rig {
  std::vector<QueuedSegment<double>> slots;
  Interpolator<double> ip;
  explicit Rig(std::size_t capacity, const MotionConfig<double>& c = config(1e-3, 2000))
      : slots(capacity), ip(Span<QueuedSegment<double>>(slots.data(), slots.size())) {
    EXPECT_EQ(ip.configure(c), Status::ok);
  }
};

// Three 20 mm lines along x, sequences 10, 11, 12.
void push_lines(Interpolator<double>& ip) {
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(ip.push({Seg::line({20.0 * i, 0}, {20.0 * (i + 1), 0}), 100.0,
                       static_cast<std::uint32_t>(10 + i)}),
              Status::ok);
}

TEST(MotionControl, FeedHoldStopsWithinTheBrakingDistanceAndResumesWithoutGapOrRepeat) {
  Rig rig(8);
  Interpolator<double>& ip = rig.ip;
  push_lines(ip);
  Setpoint<double> p;
  for (int k = 0; k < 150; ++k) p = ip.step();  // cruising at 100 mm/s since 0.05 s
  ASSERT_NEAR(p.speed, 100.0, 1e-7);
  const double s_hold = p.s;
  const double v = p.speed;
  const double promised = ip.braking_distance();
  EXPECT_LE(promised, v * v / (2 * 2000.0) + v * 1e-3);
  ip.hold();
  double prev_step = p.s - (p.s - v * 1e-3);
  double prev_s = p.s;
  int periods = 0;
  do {
    p = ip.step();
    const double step = p.s - prev_s;
    ASSERT_GE(step, 0.0);
    ASSERT_LE(prev_step - step, 2000.0 * 1e-6 * (1 + 1e-9));
    prev_step = step;
    prev_s = p.s;
    ASSERT_LT(++periods, 1000);
  } while (p.state != MotionState::held);
  EXPECT_LE(p.s - s_hold, promised + 1e-12);
  const Setpoint<double> stopped = p;
  for (int k = 0; k < 50; ++k) {  // held: the same setpoint, period after period
    p = ip.step();
    ASSERT_EQ(p.state, MotionState::held);
    ASSERT_EQ(p.position, stopped.position);
    ASSERT_EQ(p.counts, stopped.counts);
  }
  ip.resume();
  p = ip.step();
  EXPECT_EQ(p.state, MotionState::running);
  // the first step after resume is one ramp step from rest: no gap, no repeat
  EXPECT_NEAR(p.s - stopped.s, 2000.0 * 1e-6, 1e-12);
  while (p.state != MotionState::done) p = ip.step();
  EXPECT_EQ(p.position, (V{60, 0}));
  EXPECT_EQ(ip.last_completed_sequence(), 12u);
  EXPECT_EQ(ip.completed_count(), 3u);
}

TEST(MotionControl, AbortStopsOnThePathAndDropsTheRest) {
  Rig rig(8);
  Interpolator<double>& ip = rig.ip;
  push_lines(ip);
  Setpoint<double> p;
  for (int k = 0; k < 250; ++k) p = ip.step();  // 22.5 mm: on the second line
  ASSERT_EQ(p.sequence, 11u);
  ip.abort();
  double prev = p.s;
  do {
    p = ip.step();
    ASSERT_GE(p.s, prev);
    prev = p.s;
  } while (p.state == MotionState::stopping);
  EXPECT_EQ(p.state, MotionState::done);
  EXPECT_EQ(ip.queued(), 0u);
  EXPECT_EQ(ip.last_completed_sequence(), 10u);  // the second line was not finished
  EXPECT_LT(p.s, 40.0);
  EXPECT_EQ(p.position.y, 0.0);
  // it stays put, and a new job can start where it stopped
  EXPECT_EQ(ip.step().position, p.position);
  EXPECT_EQ(ip.push({Seg::line(p.position, {0, 0}), 50.0, 99}), Status::ok);
  while (ip.step().state != MotionState::done) {
  }
  EXPECT_EQ(ip.last_setpoint().position, (V{0, 0}));
  EXPECT_EQ(ip.last_completed_sequence(), 99u);
}

// A sender that falls behind: the head stops exactly where the queue ends
// (done), and continues from there, with no jump, when more arrives. With
// the S-curve, a segment pushed while the head still catches up is taken too.
TEST(MotionControl, AStarvedQueueStopsAtItsEndAndContinuesWhenRefilled) {
  for (const double jerk : {0.0, 1e5}) {
    const auto c = config(1e-3, 2000, 1.0, 1000.0, jerk);
    std::vector<QueuedSegment<double>> slots(4);
    std::vector<double> window(Interpolator<double>::jerk_window_size(c));
    Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()),
                            Span<double>(window.data(), window.size()));
    ASSERT_EQ(ip.configure(c), Status::ok);
    ASSERT_EQ(ip.push({Seg::line({0, 0}, {5, 0}), 100.0, 1}), Status::ok);
    Setpoint<double> p = ip.step();
    double prev = p.s;
    int periods = 1;
    bool pushed_late = false;
    while (p.state != MotionState::done) {
      // with the S-curve, push while the plan is at the end but the head is not yet
      if (!pushed_late && jerk > 0 && p.s > 4.99) {
        ASSERT_EQ(ip.push({Seg::line({5, 0}, {5, 3}), 100.0, 2}), Status::ok);
        pushed_late = true;
      }
      p = ip.step();
      ASSERT_GE(p.s, prev);
      ASSERT_LE(p.s - prev, 0.1 + 1e-12);
      prev = p.s;
      ASSERT_LT(++periods, 5000);
    }
    EXPECT_EQ(pushed_late, jerk > 0);
    if (!pushed_late) {
      EXPECT_EQ(p.position, (V{5, 0}));  // stopped exactly at the end of what it had
      EXPECT_EQ(ip.last_completed_sequence(), 1u);
      EXPECT_EQ(ip.step().position, (V{5, 0}));
      ASSERT_EQ(ip.push({Seg::line({5, 0}, {5, 3}), 100.0, 2}), Status::ok);
      do {
        p = ip.step();
        ASSERT_GE(p.s, prev);
        ASSERT_LE(p.s - prev, 0.1 + 1e-12);
        prev = p.s;
      } while (p.state != MotionState::done);
    }
    EXPECT_EQ(p.position, (V{5, 3})) << "jerk " << jerk;
    EXPECT_NEAR(p.s, 8.0, 1e-12);
    EXPECT_EQ(ip.last_completed_sequence(), 2u);
  }
}

TEST(MotionControl, AFullQueueRefusesAndKeepsWhatItHas) {
  Rig rig(2);
  Interpolator<double>& ip = rig.ip;
  EXPECT_EQ(ip.state(), MotionState::idle);
  ASSERT_EQ(ip.push({Seg::line({0, 0}, {1, 0}), 10.0, 1}), Status::ok);
  ASSERT_EQ(ip.push({Seg::line({1, 0}, {2, 0}), 10.0, 2}), Status::ok);
  EXPECT_EQ(ip.push({Seg::line({2, 0}, {3, 0}), 10.0, 3}), Status::capacity_exceeded);
  EXPECT_EQ(ip.queued(), 2u);
  Setpoint<double> p;
  do p = ip.step();
  while (p.state != MotionState::done);
  EXPECT_EQ(p.position, (V{2, 0}));  // the refused segment was not kept
  EXPECT_EQ(ip.last_completed_sequence(), 2u);
}

TEST(MotionControl, RejectsBadSegmentsAndLimits) {
  Rig rig(4);
  Interpolator<double>& ip = rig.ip;
  EXPECT_EQ(ip.push({Seg::line({0, 0}, {0, 0}), 10.0, 1}), Status::invalid_argument);
  EXPECT_EQ(ip.push({Seg::line({0, 0}, {1, 0}), 0.0, 1}), Status::invalid_argument);
  EXPECT_EQ(ip.push({Seg::line({0, 0}, {1, NAN}), 10.0, 1}), Status::invalid_argument);
  ASSERT_EQ(ip.push({Seg::line({0, 0}, {1, 0}), 10.0, 1}), Status::ok);
  EXPECT_EQ(ip.push({Seg::line({1.001, 0}, {2, 0}), 10.0, 2}), Status::invalid_argument);  // gap
  EXPECT_EQ(ip.queued(), 1u);

  MotionConfig<double> c = config(1e-3, 2000);
  c.jerk = 1e5;  // an S-curve needs a window of ceil(2 * 2000 / (1e5 * 1e-3)) = 40 values
  EXPECT_EQ(Interpolator<double>::jerk_window_size(c), 40u);
  EXPECT_EQ(ip.configure(c), Status::capacity_exceeded);
  c.jerk = -1;
  EXPECT_EQ(ip.configure(c), Status::invalid_argument);
  c = config(0.0, 2000);
  EXPECT_EQ(ip.configure(c), Status::invalid_argument);
  c = config(1e-3, -1);
  EXPECT_EQ(ip.configure(c), Status::invalid_argument);
  c = config(1e-3, 2000, 1.0, 0.0);
  EXPECT_EQ(ip.configure(c), Status::invalid_argument);
}

}  // namespace
}  // namespace kerf::motion
