// The ramp arithmetic (ramp/lookahead.hpp) against a brute-force sum.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "motion_helpers.hpp"

namespace kerf::motion {
namespace {

// Sum of x, x - a, x - 2a, ... while the term is > w, term by term.
double brute_braking_length(double x, double w, double a) {
  double sum = 0;
  for (int i = 0; x - i * a > w; ++i) sum += x - i * a;  // no running subtraction: no drift
  return sum;
}

TEST(MotionRamp, BrakingLengthMatchesTheTermByTermSum) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const double a = 1e-3 * (0.1 + u(rng));
    const double w = i % 3 == 0 ? 0.0 : 0.3 * u(rng);
    const double x = w + 0.5 * u(rng);
    const double want = brute_braking_length(x, w, a);
    EXPECT_NEAR(braking_length(x, w, a), want, 1e-12 * (1 + want)) << x << " " << w << " " << a;
  }
  EXPECT_EQ(braking_length(0.5, 0.5, 0.01), 0.0);
  EXPECT_EQ(braking_length(0.25, 0.0, 0.25), 0.25);  // one term: x is an exact multiple of a
}

TEST(MotionRamp, MaxStepBeforeIsTheLargestStepThatCanStillBrakeInTime) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const double a = 1e-3 * (0.1 + u(rng));
    const double w = i % 2 == 0 ? 0.0 : 0.2 * u(rng);
    const double d = 10.0 * u(rng) * u(rng);
    const double x = max_step_before(d, w, a);
    ASSERT_GE(x, w);
    // it can brake in time...
    EXPECT_LE(brute_braking_length(x, w, a), d * (1 + 1e-12) + 1e-15) << d << " " << w << " " << a;
    // ...and any noticeably larger step could not
    if (d > w) {
      const double more = x * (1 + 1e-9) + 1e-15;
      EXPECT_GT(brute_braking_length(more, w, a), d) << d << " " << w << " " << a;
    }
  }
}

TEST(MotionRamp, JointRuleKeepsTheChordChangeWithinTheShareOfTheLimit) {
  const double a = 1e-3;
  const Vec2<double> east{1, 0};
  const double k = kShare * a;
  // 90 degrees between lines: the chord turns by 2 sin(45 deg) = sqrt(2), so v <= k / sqrt(2)
  const double s90 = turn_chord(east, {0.0, 1.0});
  EXPECT_NEAR(s90, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(joint_step_limit(s90, 0.0, 0.0, a, 0.0), k / std::sqrt(2.0), 1e-15);
  // a reversal: v <= k / 2
  EXPECT_NEAR(joint_step_limit(turn_chord(east, {-1.0, 0.0}), 0.0, 0.0, a, 0.0), k / 2, 1e-15);
  // no turn, no curvature: no limit; a line into an arc: x^2 kappa <= k
  EXPECT_TRUE(std::isinf(joint_step_limit(turn_chord(east, east), 0.0, 0.0, a, 0.0)));
  const double w = joint_step_limit(0.0, 0.0, 0.5, a, 0.0);
  EXPECT_NEAR(w * w * 0.5, k, 1e-15);
  // a turn and a curvature: x (s + x kappa) = k exactly
  const double x = joint_step_limit(0.1, 2.0, -1.0, a, 0.0);
  EXPECT_NEAR(x * (0.1 + x * 2.0), k, 1e-18);
  // with jerk, the curvature step (3 here) at b / 2 may be the tighter one
  const double b = 1e-7;
  const double xj = joint_step_limit(0.1, 2.0, -1.0, a, b);
  EXPECT_NEAR(xj * xj * 3.0, b / 2, 1e-20);
}

TEST(MotionRamp, CurveCapAndTangentialShare) {
  const double a = 1e-3;
  const double cap = curve_step_cap(1.0, a, 0.0);
  EXPECT_NEAR(cap * cap, kShare * a, 1e-18);
  EXPECT_TRUE(std::isinf(curve_step_cap(0.0, a, 0.0)));
  const double b = 1e-6;  // x^3 kappa^2 <= b / 2 is the tighter cap on a tight curve
  const double capj = curve_step_cap(4.0, a, b);
  EXPECT_NEAR(capj * capj * capj * 16.0, b / 2, 1e-15 * b);
  EXPECT_NEAR(tangential_step(0.0, a), a, 1e-18);
  EXPECT_NEAR(tangential_step(0.6 * a, a), 0.8 * a, 1e-15);
  // the normal part is clamped to the share: something is always left for braking
  EXPECT_NEAR(tangential_step(2 * a, a), std::sqrt(1 - kShare * kShare) * a, 1e-15);
}

}  // namespace
}  // namespace kerf::motion
