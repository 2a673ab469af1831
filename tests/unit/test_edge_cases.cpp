// Edge cases of the fitter, each checked by the independent verifier (and,
// where it is small enough, against the brute-force twin), and tests of the
// verifier and the twin themselves: a broken checker must not pass silently.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bridge/fit_bridge.hpp"
#include "brute_twin.hpp"
#include "verifier.hpp"

namespace {

using kerf_test::CoreFitter;
using kerf_test::Method;
using kerf_test::VPiece;
using kerf_test::VPoint;

constexpr double kPi = 3.14159265358979323846;

// `count` points on a circle from angle a0 to a1 (radians, either direction).
std::vector<VPoint> arc_points(double cx, double cy, double r, double a0, double a1, int count) {
  std::vector<VPoint> p;
  for (int k = 0; k < count; ++k) {
    const double a = a0 + (a1 - a0) * k / (count - 1);
    p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return p;
}

// Fits with `m` at tol, checks the output with the verifier and returns it.
std::vector<VPiece> fit_verified(const std::vector<VPoint>& pts, double tol, Method m) {
  CoreFitter f(pts);
  const auto r = f.fit(tol, m);
  EXPECT_TRUE(r.ok()) << kerf::to_string(r.status());
  if (!r.ok()) return {};
  const auto pieces = f.pieces(r.value().pieces);
  const kerf_test::VerifyReport v = kerf_test::verify(pts, pieces, tol, m == Method::optimal ? kerf_test::Reach::arc : kerf_test::Reach::circle);
  EXPECT_TRUE(v.ok) << v.why;
  EXPECT_LE(r.value().max_error, tol);
  return pieces;
}

// ---------------------------------------------------------------------------
// The fitter

TEST(EdgeCases, FullCircleClosedGivesTwoPieces) {
  for (const double dir : {1.0, -1.0}) {
    SCOPED_TRACE(dir > 0 ? "counter-clockwise" : "clockwise");
    std::vector<VPoint> pts = arc_points(4, -2, 10, 0, dir * 2 * kPi, 37);
    pts.back() = pts.front();  // closed: exactly the first point again
    const double tol = 1e-3;
    EXPECT_EQ(kerf_test::twin_min_count(pts, tol).pieces, 2u);
    for (const Method m : kerf_test::kMethods) {
      SCOPED_TRACE(kerf_test::method_name(m));
      const auto pieces = fit_verified(pts, tol, m);
      ASSERT_EQ(pieces.size(), 2u);
      // Any split point will do, and a piece over a single step is a line.
      EXPECT_TRUE(pieces[0].arc || pieces[1].arc);
      for (const VPiece& p : pieces) {
        if (!p.arc) {
          EXPECT_EQ(p.last, p.first + 1);
          continue;
        }
        EXPECT_EQ(p.dir, static_cast<int>(dir));
        EXPECT_NEAR(p.cx, 4, 1e-6);
        EXPECT_NEAR(p.cy, -2, 1e-6);
      }
    }
  }
}

TEST(EdgeCases, OpenArcIsOneArcWithItsDirection) {
  // 120 degrees (a minor arc) and 300 degrees (a major one), both ways round.
  for (const double span : {120.0, 300.0}) {
    for (const double dir : {1.0, -1.0}) {
      SCOPED_TRACE(std::to_string(span) + (dir > 0 ? " degrees CCW" : " degrees CW"));
      const double a0 = 0.7;
      const auto pts = arc_points(3, -7, 50, a0, a0 + dir * span * kPi / 180, 30);
      for (const Method m : kerf_test::kMethods) {
        SCOPED_TRACE(kerf_test::method_name(m));
        const auto pieces = fit_verified(pts, 1e-4, m);
        ASSERT_EQ(pieces.size(), 1u);
        EXPECT_TRUE(pieces[0].arc);
        EXPECT_EQ(pieces[0].dir, static_cast<int>(dir));
        EXPECT_NEAR(pieces[0].cx, 3, 1e-3);
        EXPECT_NEAR(pieces[0].cy, -7, 1e-3);
        EXPECT_NEAR(std::hypot(pieces[0].sx - pieces[0].cx, pieces[0].sy - pieces[0].cy), 50, 1e-4);
      }
    }
  }
}

TEST(EdgeCases, StraightLineIsOneLinePiece) {
  std::vector<VPoint> exact;  // integer coordinates: exactly collinear
  for (int k = 0; k < 20; ++k) exact.push_back({3.0 * k - 5, 2.0 * k + 1});
  for (const Method m : kerf_test::kMethods) {
    SCOPED_TRACE(kerf_test::method_name(m));
    const auto pieces = fit_verified(exact, 1e-3, m);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_FALSE(pieces[0].arc);
    EXPECT_EQ(pieces[0].dir, 0);
  }
}

TEST(EdgeCases, StraightLineWithRoundingIsOneLinePiece) {
  // Coordinates that are not exact in binary: collinear only up to rounding.
  std::vector<VPoint> pts;
  for (int k = 0; k < 20; ++k) pts.push_back({0.1 * k + 1.3, 0.7 * k - 2.9});
  const auto pieces = fit_verified(pts, 1e-3, Method::optimal);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_FALSE(pieces[0].arc) << "a line of points came out as an arc around (" << pieces[0].cx
                              << ", " << pieces[0].cy << ")";
  // The report's rules build circles through (or from) three points, which
  // rounding can turn into huge arcs instead of the line; what they return
  // must still verify. (esgi_mean needs 2 pieces here: its mean centre is
  // thrown far off by the near-infinite centres of near-collinear points.)
  for (const Method m : {Method::esgi_max, Method::esgi_mean}) {
    SCOPED_TRACE(kerf_test::method_name(m));
    EXPECT_GE(fit_verified(pts, 1e-3, m).size(), 1u);
  }
}

TEST(EdgeCases, TwoPointsAreOneLine) {
  const std::vector<VPoint> pts{{1.5, -2}, {4, 7}};
  for (const Method m : kerf_test::kMethods) {
    SCOPED_TRACE(kerf_test::method_name(m));
    const auto pieces = fit_verified(pts, 0.01, m);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_FALSE(pieces[0].arc);
    EXPECT_EQ(pieces[0].first, 0u);
    EXPECT_EQ(pieces[0].last, 1u);
    EXPECT_EQ(pieces[0].dir, 0);
  }
}

TEST(EdgeCases, CollinearThenTurning) {
  // Ten points along the x axis, then a left quarter turn of radius 5
  // continuing tangentially: a line and an arc, both exact.
  std::vector<VPoint> pts;
  for (int k = 0; k < 10; ++k) pts.push_back({1.0 * k, 0});
  for (int k = 1; k <= 10; ++k) {
    const double a = -kPi / 2 + (kPi / 2) * k / 10;
    pts.push_back({9 + 5 * std::cos(a), 5 + 5 * std::sin(a)});
  }
  const double tol = 1e-3;
  EXPECT_EQ(kerf_test::twin_min_count(pts, tol).pieces, 2u);
  CoreFitter f(pts);
  const auto count = f.count(tol, Method::optimal);
  ASSERT_TRUE(count.ok());
  EXPECT_EQ(count.value(), 2u);
  // The only 2-piece solution with zero error splits at the tangent point.
  const auto pieces = fit_verified(pts, tol, Method::optimal);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_FALSE(pieces[0].arc);
  EXPECT_EQ(pieces[0].last, 9u);
  EXPECT_TRUE(pieces[1].arc);
  EXPECT_EQ(pieces[1].dir, 1);  // a left turn: counter-clockwise
  EXPECT_NEAR(pieces[1].cx, 9, 1e-6);
  EXPECT_NEAR(pieces[1].cy, 5, 1e-6);
  for (const Method m : {Method::esgi_max, Method::esgi_mean}) {
    SCOPED_TRACE(kerf_test::method_name(m));
    EXPECT_GE(fit_verified(pts, tol, m).size(), 2u);
  }
}

TEST(EdgeCases, HugeToleranceIsOnePiece) {
  const std::vector<VPoint> pts{{0, 0}, {1, 3}, {2, -1}, {3, 2}, {4, -3}, {5, 0}};
  for (const Method m : kerf_test::kMethods) {
    SCOPED_TRACE(kerf_test::method_name(m));
    EXPECT_EQ(fit_verified(pts, 100, m).size(), 1u);
  }
}

TEST(EdgeCases, ChordsShorterThanTwiceTheTolerance) {
  // Clusters of points closer together than the tolerance: circles through
  // the end points with r < tol accept points near their centre too.
  for (unsigned seed = 1; seed <= 12; ++seed) {
    std::vector<VPoint> pts;
    unsigned s = seed * 2654435761u;
    auto next = [&s]() {
      s = s * 1664525u + 1013904223u;
      return static_cast<double>(s >> 8) / 16777216.0;
    };
    double x = 0, y = 0;
    for (int k = 0; k < 16; ++k) {
      pts.push_back({x, y});
      x += next() * 0.06 - 0.02;  // a drift along x, jitter in both
      y += next() * 0.04 - 0.02;
    }
    for (const double tol : {0.005, 0.02, 0.05}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", tol " + std::to_string(tol));
      const auto twin = kerf_test::twin_min_count(pts, tol);
      CoreFitter f(pts);
      const auto c = f.count(tol, Method::optimal);
      ASSERT_TRUE(c.ok());
      EXPECT_EQ(c.value(), twin.pieces);
      for (const Method m : kerf_test::kMethods) fit_verified(pts, tol, m);
    }
  }
}

// ---------------------------------------------------------------------------
// The verifier: accepts the right thing, rejects each kind of wrong one.

// A quarter of the unit circle, counter-clockwise from (1, 0) to (0, 1).
std::vector<VPoint> quarter() {
  return {{1, 0}, {std::cos(kPi / 4), std::sin(kPi / 4)}, {0, 1}};
}
VPiece quarter_arc() {
  VPiece p;
  p.arc = true;
  p.first = 0;
  p.last = 2;
  p.sx = 1;
  p.sy = 0;
  p.ex = 0;
  p.ey = 1;
  p.cx = 0;
  p.cy = 0;
  p.dir = 1;
  return p;
}
VPiece line(const std::vector<VPoint>& pts, std::size_t i, std::size_t j) {
  return kerf_test::line_piece(pts, i, j);
}

TEST(Verifier, AcceptsAGoodArc) {
  const kerf_test::VerifyReport r = kerf_test::verify(quarter(), {quarter_arc()}, 1e-9);
  EXPECT_TRUE(r.ok) << r.why;
}

TEST(Verifier, RejectsAnInnerPointOutOfTolerance) {
  auto pts = quarter();
  pts[1] = {0.75, 0.75};  // 0.0607 outside the unit circle
  EXPECT_FALSE(kerf_test::verify(pts, {quarter_arc()}, 0.05).ok);
  EXPECT_TRUE(kerf_test::verify(pts, {quarter_arc()}, 0.07).ok);
  // The same for a line.
  const std::vector<VPoint> bent{{0, 0}, {1, 0.2}, {2, 0}};
  EXPECT_FALSE(kerf_test::verify(bent, {line(bent, 0, 2)}, 0.1).ok);
  EXPECT_TRUE(kerf_test::verify(bent, {line(bent, 0, 2)}, 0.25).ok);
}

TEST(Verifier, RejectsTheWrongDirection) {
  VPiece p = quarter_arc();
  p.dir = -1;  // clockwise from (1, 0) to (0, 1) is the other 270 degrees
  const kerf_test::VerifyReport r = kerf_test::verify(quarter(), {p}, 1e-6);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.why.find("direction"), std::string::npos) << r.why;
  p.dir = 0;
  EXPECT_FALSE(kerf_test::verify(quarter(), {p}, 1e-6).ok);
  // A major arc: 270 degrees counter-clockwise through (-1, 0).
  const std::vector<VPoint> major{{1, 0}, {-1, 0}, {0, -1}};
  VPiece q = quarter_arc();
  q.ex = 0;
  q.ey = -1;
  EXPECT_TRUE(kerf_test::verify(major, {q}, 1e-6).ok);
  q.dir = -1;
  EXPECT_FALSE(kerf_test::verify(major, {q}, 1e-6).ok);
}

TEST(Verifier, RejectsPiecesThatAreNotContiguous) {
  const std::vector<VPoint> pts{{0, 0}, {1, 0}, {2, 1}, {3, 1}};
  EXPECT_TRUE(kerf_test::verify(pts, {line(pts, 0, 1), line(pts, 1, 2), line(pts, 2, 3)}, 0.1).ok);
  EXPECT_FALSE(kerf_test::verify(pts, {line(pts, 0, 1), line(pts, 2, 3)}, 0.1).ok);   // a gap
  EXPECT_FALSE(kerf_test::verify(pts, {line(pts, 0, 2), line(pts, 1, 3)}, 1.0).ok);   // overlap
  EXPECT_FALSE(kerf_test::verify(pts, {line(pts, 1, 2), line(pts, 2, 3)}, 0.1).ok);   // late start
  EXPECT_FALSE(kerf_test::verify(pts, {line(pts, 0, 1), line(pts, 1, 2)}, 0.1).ok);   // stops short
  EXPECT_FALSE(kerf_test::verify(pts, {}, 0.1).ok);
  VPiece back = line(pts, 0, 3);
  back.first = 3;
  back.last = 0;
  EXPECT_FALSE(kerf_test::verify(pts, {back}, 10).ok);  // first > last
}

TEST(Verifier, RejectsEndPointsAndRadiiThatDoNotMatch) {
  VPiece p = quarter_arc();
  p.sx = 1 + 1e-6;  // not the input point
  EXPECT_FALSE(kerf_test::verify(quarter(), {p}, 1e-3).ok);
  p = quarter_arc();
  p.ey = 1.001;  // not the input point, and off the circle
  EXPECT_FALSE(kerf_test::verify(quarter(), {p}, 1e-2).ok);
  p = quarter_arc();
  p.cx = 1e-3;  // start and end no longer equally far from the centre
  EXPECT_FALSE(kerf_test::verify(quarter(), {p}, 1e-2).ok);
  VPiece l = line(quarter(), 0, 2);
  l.dir = 1;  // a line has no direction
  EXPECT_FALSE(kerf_test::verify(quarter(), {l}, 1).ok);
  const std::vector<VPoint> loop{{0, 0}, {1, 1}, {0, 0}};
  EXPECT_FALSE(kerf_test::verify(loop, {line(loop, 0, 2)}, 10).ok);  // a closed loop
}

// ---------------------------------------------------------------------------
// The twin, on cases small enough to decide by hand.

TEST(Twin, HandCheckedCounts) {
  // Three points: the circle through them.
  EXPECT_EQ(kerf_test::twin_min_count({{0, 0}, {1, 1}, {2, 0}}, 1e-6).pieces, 1u);
  // No circle through (0,0) and (3,0) comes near both (1,1) and (2,-1): the
  // one through (1,1) has centre (1.5,-0.5) and passes x = 2 at y = -2.
  const std::vector<VPoint> z{{0, 0}, {1, 1}, {2, -1}, {3, 0}};
  EXPECT_FALSE(kerf_test::twin_pair(z, 0, 3, 0.1).feasible);
  // A circle comes within 0.8 of both, but an arc lies on one side of the
  // chord's line and they are 1 from it on either side: only the segment,
  // at 1, reaches both.
  EXPECT_FALSE(kerf_test::twin_pair(z, 0, 3, 0.8).feasible);
  EXPECT_TRUE(kerf_test::twin_pair(z, 0, 3, 1.0).feasible);
  EXPECT_EQ(kerf_test::twin_min_count(z, 0.1).pieces, 2u);
  // A closed loop with inner points is never one piece.
  const std::vector<VPoint> loop{{0, 0}, {1, 0}, {1, 1}, {0, 0}};
  EXPECT_FALSE(kerf_test::twin_pair(loop, 0, 3, 100).feasible);
  EXPECT_EQ(kerf_test::twin_min_count(loop, 100).pieces, 2u);
  // Collinear points: the line.
  const auto l = kerf_test::twin_pair({{0, 0}, {1, 1}, {2, 2}, {3, 3}}, 0, 3, 1e-9);
  EXPECT_TRUE(l.feasible);
  EXPECT_TRUE(l.line);
}

TEST(Twin, ExactBoundaryIsFeasible) {
  // Inner points exactly tol either side of the line through the end points.
  // By symmetry a circle through the end points is as far from them as from
  // (1, +-0.25), and bending towards one moves it farther from the other:
  // the line is the best piece, feasible at 0.25 and not below.
  const std::vector<VPoint> pts{{0, 0}, {1, 0.25}, {2, -0.25}, {3, 0}};
  EXPECT_TRUE(kerf_test::twin_pair(pts, 0, 3, 0.25).feasible);
  EXPECT_FALSE(kerf_test::twin_pair(pts, 0, 3, 0.2499).feasible);
  CoreFitter f(pts);
  const auto at = f.count(0.25, Method::optimal);
  const auto below = f.count(0.2499, Method::optimal);
  ASSERT_TRUE(at.ok());
  ASSERT_TRUE(below.ok());
  EXPECT_EQ(at.value(), 1u);
  EXPECT_EQ(below.value(), 2u);
}

}  // namespace
