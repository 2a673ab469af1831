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

TEST(MotionRamp, CornerRuleLimitsOnlyTurnsAboveTheAngle) {
  const double cos_limit = std::cos(10.0 * test::kPi / 180);
  const double a = 1e-3;
  const Vec2<double> east{1, 0};
  // 5 degrees: tangent-continuous by configuration
  EXPECT_TRUE(std::isinf(corner_step_limit(east, {std::cos(0.0873), std::sin(0.0873)}, cos_limit, a)));
  // 90 degrees: the velocity vector changes by sqrt(2) v, so v <= a T / sqrt(2)
  EXPECT_NEAR(corner_step_limit(east, {0.0, 1.0}, cos_limit, a), a / std::sqrt(2.0), 1e-15);
  // a reversal: v <= a T / 2
  EXPECT_NEAR(corner_step_limit(east, {-1.0, 0.0}, cos_limit, a), a / 2, 1e-15);
}

}  // namespace
}  // namespace kerf::motion
