// The plane limit at a sharp corner, in double and in kerf::Fixed: every pair
// of consecutive chords, the one that crosses the joint included, changes by
// at most accel * T^2 (the second difference of the setpoints, checked here
// independently of ramp/plane_limits.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kerf/core/fixed.hpp"
#include "kerf/motion/interpolator.hpp"

namespace kerf::motion {
namespace {

double as_double(double v) { return v; }
double as_double(Fixed v) { return static_cast<double>(v.raw()) / static_cast<double>(Fixed::one_raw); }

template <class S>
class MotionCornerTest : public ::testing::Test {};

using Scalars = ::testing::Types<double, Fixed>;
TYPED_TEST_SUITE(MotionCornerTest, Scalars);

// The largest |p[n+1] - 2 p[n] + p[n-1]| (mm) of a step: 2 mm along +x, a
// 90 degree left turn, `middle` along +y, a right turn, 1 mm along +x; 20
// mm/s, accel 1500, 1 ms, from rest to rest. The head runs at the corner
// speed between the two joints, so `middle` sets where its steps cross the
// second one.
template <class S>
double max_second_difference(S middle) {
  std::vector<QueuedSegment<S>> slots(8);
  Interpolator<S> ip{Span<QueuedSegment<S>>(slots.data(), slots.size())};
  MotionConfig<S> c;
  c.period = S(1) / S(1000);
  c.accel = S(1500);
  c.corner_angle = S(0);
  c.counts_per_mm = {S(1000), S(1000)};
  EXPECT_EQ(ip.configure(c), Status::ok);
  const Vec2<S> p0{S(0), S(0)};
  const Vec2<S> p1{S(2), S(0)};
  const Vec2<S> p2 = p1 + Vec2<S>{S(0), middle};
  const Vec2<S> p3 = p2 + Vec2<S>{S(1), S(0)};
  EXPECT_EQ(ip.push({Segment<S>::line(p0, p1), S(20), 1}), Status::ok);
  EXPECT_EQ(ip.push({Segment<S>::line(p1, p2), S(20), 2}), Status::ok);
  EXPECT_EQ(ip.push({Segment<S>::line(p2, p3), S(20), 3}), Status::ok);
  std::vector<double> x{0, 0}, y{0, 0};  // at rest before the start
  for (int n = 0; n < 100000; ++n) {
    const Setpoint<S> p = ip.step();
    x.push_back(as_double(p.position.x));
    y.push_back(as_double(p.position.y));
    if (p.state == MotionState::done) break;
  }
  EXPECT_NEAR(x.back(), 3.0, 1e-9);
  EXPECT_NEAR(y.back(), as_double(middle), 1e-9);
  x.push_back(x.back());  // and at rest after the end
  y.push_back(y.back());
  double worst = 0;
  for (std::size_t n = 1; n + 1 < x.size(); ++n)
    worst = std::fmax(worst, std::hypot(x[n + 1] - 2 * x[n] + x[n - 1], y[n + 1] - 2 * y[n] + y[n - 1]));
  return worst;
}

TYPED_TEST(MotionCornerTest, TheStepsAroundARightAngleStayWithinTheAcceleration) {
  using S = TypeParam;
  const double limit = 1500 * 1e-6;  // accel T^2, mm
  // Middles 0.05 um apart cover every phase of the corner steps (0.9 um)
  // against the second joint: some steps cross it near their end.
  for (int i = 0; i < 24; ++i) {
    const double worst = max_second_difference<S>(S(3) / S(1000) + S(i) / S(20000));
    EXPECT_LE(worst, limit + 1e-9) << "middle 3 um + " << i * 0.05 << " um";
  }
}

}  // namespace
}  // namespace kerf::motion
