#include <gtest/gtest.h>

#include <cmath>

#include "kerf/geom/circle.hpp"
#include "kerf/geom/segment.hpp"

namespace {

using kerf::Status;
using V = kerf::Vec2<double>;

TEST(CircleThrough, FindsTheCircleOfThreePointsOnIt) {
  const V c{3.0, -2.0};
  const double r = 7.5;
  auto at = [&](double a) { return V{c.x + r * std::cos(a), c.y + r * std::sin(a)}; };
  const auto res = kerf::circle_through(at(0.1), at(1.7), at(4.0));
  ASSERT_TRUE(res.ok());
  EXPECT_NEAR(res.value().centre.x, c.x, 1e-12);
  EXPECT_NEAR(res.value().centre.y, c.y, 1e-12);
  EXPECT_NEAR(res.value().radius, r, 1e-12);
}

TEST(CircleThrough, StaysAccurateFarFromTheOrigin) {
  const V o{1e6, -1e6};
  const auto res = kerf::circle_through(o + V{1, 0}, o + V{0, 1}, o + V{-1, 0});
  ASSERT_TRUE(res.ok());
  EXPECT_NEAR(res.value().centre.x, o.x, 1e-7);
  EXPECT_NEAR(res.value().centre.y, o.y, 1e-7);
  EXPECT_NEAR(res.value().radius, 1.0, 1e-9);
}

TEST(CircleThrough, ReportsCollinearAndCoincidentPoints) {
  EXPECT_EQ(kerf::circle_through(V{0, 0}, V{1, 1}, V{2, 2}).status(), Status::collinear);
  EXPECT_EQ(kerf::circle_through(V{0, 0}, V{1, 1}, V{-3, -3}).status(), Status::collinear);
  EXPECT_EQ(kerf::circle_through(V{0, 0}, V{0, 0}, V{2, 1}).status(), Status::degenerate);
  EXPECT_EQ(kerf::circle_through(V{0, 0}, V{2, 1}, V{2, 1}).status(), Status::degenerate);
}

TEST(Orientation, FollowsTheReportsDeterminant) {
  EXPECT_EQ(kerf::orientation(V{0, 0}, V{1, 0}, V{1, 1}), 1);
  EXPECT_EQ(kerf::orientation(V{0, 0}, V{1, 0}, V{1, -1}), -1);
  EXPECT_EQ(kerf::orientation(V{0, 0}, V{1, 0}, V{2, 0}), 0);
}

TEST(Distance, ToLineSegmentClampsToTheEnds) {
  EXPECT_DOUBLE_EQ(kerf::distance_to_line_segment(V{0, 0}, V{4, 0}, V{2, 3}), 3.0);
  EXPECT_DOUBLE_EQ(kerf::distance_to_line_segment(V{0, 0}, V{4, 0}, V{7, 4}), 5.0);
  EXPECT_DOUBLE_EQ(kerf::distance_to_line(V{0, 0}, V{4, 0}, V{7, 4}), 4.0);
}

TEST(Distance, ToArcUsesTheSweepInItsDirection) {
  // Quarter circle of radius 1 around the origin from (1,0) to (0,1).
  const auto ccw = kerf::Segment<double>::arc(V{1, 0}, V{0, 1}, V{0, 0}, +1);
  const auto cw = kerf::Segment<double>::arc(V{1, 0}, V{0, 1}, V{0, 0}, -1);
  const V inside{2 * std::cos(0.7), 2 * std::sin(0.7)};  // in the CCW quarter
  EXPECT_NEAR(kerf::distance_to_segment(ccw, inside), 1.0, 1e-12);
  // The CW arc is the other three quarters: nearest are its end points.
  EXPECT_NEAR(kerf::distance_to_segment(cw, inside),
              std::min(kerf::distance(inside, V{1, 0}), kerf::distance(inside, V{0, 1})), 1e-12);
  const V behind{-0.5, -0.5};
  EXPECT_NEAR(kerf::distance_to_segment(cw, behind), 1.0 - std::sqrt(0.5), 1e-12);
  EXPECT_GT(kerf::distance_to_segment(ccw, behind), 1.0);
}

TEST(Sweep, HandlesMajorArcsBothWays) {
  const V a{1, 0};
  const V b{0, -1};
  // CCW from a to b sweeps 270 degrees through (0,1) and (-1,0).
  EXPECT_TRUE(kerf::in_sweep(a, b, V{0, 1}, +1));
  EXPECT_TRUE(kerf::in_sweep(a, b, V{-1, 0}, +1));
  EXPECT_FALSE(kerf::in_sweep(a, b, V{1, -1}, +1));
  // CW from a to b is the quarter through (1,-1).
  EXPECT_TRUE(kerf::in_sweep(a, b, V{1, -1}, -1));
  EXPECT_FALSE(kerf::in_sweep(a, b, V{0, 1}, -1));
}

TEST(Distance, ToCircleStaysExactForHugeRadii) {
  // Centre 1e17 below the chord (-5,0)-(5,0): the circle rises 12.5 / t above
  // the chord's middle, so a point 0.5 above it is 0.5 - 12.5 / t from the
  // circle. At this radius one ulp is 16, so | |p - c| - r | would say 0.
  const double t = 1e17;
  const V c{0, -t};
  const V on{-5, 0};
  EXPECT_NEAR(kerf::distance_to_circle(c, on, V{0, 0.5}), 0.5 - 12.5 / t, 1e-12);
  EXPECT_NEAR(kerf::distance_to_circle(c, on, V{5, 0}), 0.0, 1e-12);
}

TEST(Segment, LineIsTheInfiniteRadiusLimit) {
  const auto line = kerf::Segment<double>::line(V{0, 0}, V{10, 0});
  EXPECT_FALSE(line.is_arc());
  EXPECT_EQ(line.dir, 0);
  // A huge arc through the same ends is within a hair of the line near its middle.
  const double big = 1e7;
  const auto arc = kerf::Segment<double>::arc(V{0, 0}, V{10, 0}, V{5, big}, +1);
  EXPECT_NEAR(kerf::distance_to_segment(arc, V{5, 0}), 0.0, 1e-5);
}

}  // namespace
