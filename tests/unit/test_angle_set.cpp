#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kerf/fit/detail/angle_set.hpp"

namespace {

using kerf::fit::AngleSet;
using kerf::fit::Interval;
using V = kerf::Vec2<double>;

TEST(PseudoAngle, IsIncreasingInTheTrueAngleModPi) {
  double prev = -1;
  for (int k = 0; k < 10000; ++k) {
    const double a = M_PI * k / 10000.0;
    const double q = kerf::fit::pseudo_angle(V{std::cos(a), std::sin(a)});
    EXPECT_GT(q, prev) << "at angle " << a;
    prev = q;
    // Opposite directions are the same point of the projective circle.
    if (k > 0) {
      EXPECT_DOUBLE_EQ(kerf::fit::pseudo_angle(V{-std::cos(a), -std::sin(a)}), q);
    }
  }
  EXPECT_LT(prev, 2.0);
}

TEST(PseudoAngle, DirectionOfInvertsIt) {
  for (int k = 0; k <= 200; ++k) {
    const double q = 2.0 * k / 200.0;
    const V d = kerf::fit::direction_of(q);
    if (k == 200) continue;  // q = 2 is the line again
    EXPECT_NEAR(kerf::fit::pseudo_angle(d), q, 1e-15);
  }
}

TEST(AngleSet, IntersectionCanSplitIntoTwoPieces) {
  std::vector<Interval<double>> a(8), b(8);
  AngleSet<double> set({a.data(), a.size()}, {b.data(), b.size()});
  const Interval<double> wide[2] = {{0.0, 1.5}, {1.7, 2.0}};  // everything but (1.5, 1.7)
  ASSERT_EQ(set.intersect(wide, 2), kerf::Status::ok);
  const Interval<double> mid[1] = {{1.0, 1.9}};
  ASSERT_EQ(set.intersect(mid, 1), kerf::Status::ok);
  ASSERT_EQ(set.size(), 2u);
  EXPECT_DOUBLE_EQ(set[0].lo, 1.0);
  EXPECT_DOUBLE_EQ(set[0].hi, 1.5);
  EXPECT_DOUBLE_EQ(set[1].lo, 1.7);
  EXPECT_DOUBLE_EQ(set[1].hi, 1.9);
  EXPECT_FALSE(set.contains_line());
  const Interval<double> none[1] = {{1.55, 1.65}};
  ASSERT_EQ(set.intersect(none, 1), kerf::Status::ok);
  EXPECT_TRUE(set.empty());
}

TEST(AngleSet, ArcAroundTheLineWrapsAndContainsIt) {
  std::vector<Interval<double>> a(4), b(4);
  AngleSet<double> set({a.data(), a.size()}, {b.data(), b.size()});
  ASSERT_EQ(set.intersect_arc(V{1, 0}, 0.1), kerf::Status::ok);  // +-asin(0.1) around phi = 0
  EXPECT_EQ(set.size(), 2u);
  EXPECT_TRUE(set.contains_line());
  // Its members are exactly the directions within asin(0.1) of the x axis.
  for (int k = 0; k < 3600; ++k) {
    const double ang = M_PI * k / 3600.0;
    const double q = kerf::fit::pseudo_angle(V{std::cos(ang), std::sin(ang)});
    bool in = false;
    for (std::size_t s = 0; s < set.size(); ++s) in = in || (set[s].lo <= q && q <= set[s].hi);
    const bool expect = std::fabs(std::sin(ang)) <= 0.1;
    if (std::fabs(std::fabs(std::sin(ang)) - 0.1) > 1e-9) {
      EXPECT_EQ(in, expect) << ang;
    }
  }
}

TEST(AngleSet, ReportsCapacityInsteadOfTruncating) {
  Interval<double> a[1], b[1];
  AngleSet<double> set({a, 1}, {b, 1});
  const Interval<double> two[2] = {{0.1, 0.2}, {0.5, 0.6}};
  EXPECT_EQ(set.intersect(two, 2), kerf::Status::capacity_exceeded);
}

}  // namespace
