// The brute-force twin over a given region R (tests/support/band_twin.hpp),
// on tiny hand-made regions, and against the band checker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "band_checker.hpp"
#include "band_test_helpers.hpp"
#include "band_twin.hpp"

namespace kerf_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSlack = 1e-9;

TEST(BandTwin, StraightPolylineIsOnePiece) {
  const auto p = straight_points(5);
  const auto w = symmetric_widths(5, 0.1);
  const BandRegion r = ideal_region(p, w);
  std::vector<VPiece> pieces;
  EXPECT_EQ(twin_min_pieces(r, &pieces), 1);
  ASSERT_EQ(pieces.size(), 1u);
  const BandReport rep = check_band_fit(p, w, pieces, kSlack);
  EXPECT_TRUE(rep.ok) << rep.why;
  EXPECT_TRUE(twin_pair_valid(r, 0, 4));
}

TEST(BandTwin, RightAngleCornerNeedsTwoPieces) {
  const std::vector<VPoint> p{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};
  const auto w = symmetric_widths(5, 0.05);
  const BandRegion r = ideal_region(p, w);
  // The region's chains lie inside the band (so the twin's pieces must too).
  for (std::size_t k = 0; k + 1 < p.size(); ++k) {
    EXPECT_TRUE(segment_in_band(p, w, 0, 4, r.chain_left[k][0], r.chain_left[k][1], kSlack)) << k;
    EXPECT_TRUE(segment_in_band(p, w, 0, 4, r.chain_right[k][0], r.chain_right[k][1], kSlack)) << k;
  }
  std::vector<VPiece> pieces;
  EXPECT_EQ(twin_min_pieces(r, &pieces), 2);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].last, 2u);
  const BandReport rep = check_band_fit(p, w, pieces, kSlack);
  EXPECT_TRUE(rep.ok) << rep.why;
  EXPECT_FALSE(twin_pair_valid(r, 1, 3));
  EXPECT_FALSE(twin_pair_valid(r, 0, 4));
}

TEST(BandTwin, ZeroLengthGateSplitsTheLine) {
  const auto p = straight_points(3);
  BandRegion r = ideal_region(p, symmetric_widths(3, 0.1));
  r.gate_left[1] = r.gate_right[1] = p[1];
  r.chain_left[0].back() = r.chain_left[1].front() = p[1];
  r.chain_right[0].back() = r.chain_right[1].front() = p[1];
  EXPECT_FALSE(twin_pair_valid(r, 0, 2));
  EXPECT_TRUE(twin_pair_valid(r, 0, 1));
  EXPECT_EQ(twin_min_pieces(r), 2);
}

TEST(BandTwin, ChainDentRejectsTheLine) {
  const auto p = straight_points(3);
  const BandRegion plain = ideal_region(p, symmetric_widths(3, 0.5));
  VPiece pc;
  ASSERT_TRUE(twin_pair_valid(plain, 0, 2, &pc));

  // The left boundary dips to y = -0.1 at x = 0.5: the line crosses it, a
  // counter-clockwise arc bulging to the right passes below.
  BandRegion dent = plain;
  dent.chain_left[0] = {{0, 0.5}, {0.5, -0.1}, {1, 0.5}};
  ASSERT_TRUE(twin_pair_valid(dent, 0, 2, &pc));
  EXPECT_TRUE(pc.arc);
  EXPECT_EQ(pc.dir, 1);
  EXPECT_GT(pc.cy, 0.0);
  // It passes under the dent's tip (touching is allowed).
  const double r = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
  EXPECT_LE(pc.cy - std::sqrt(r * r - (0.5 - pc.cx) * (0.5 - pc.cx)), -0.1 + 1e-12);
  EXPECT_EQ(twin_min_pieces(dent), 1);

  // A dent down to -0.45 with the right boundary at -0.5 leaves no room for
  // an arc over both cells: two pieces, the first a deep arc.
  dent.chain_left[0] = {{0, 0.5}, {0.5, -0.45}, {1, 0.5}};
  EXPECT_FALSE(twin_pair_valid(dent, 0, 2));
  EXPECT_TRUE(twin_pair_valid(dent, 0, 1));
  EXPECT_EQ(twin_min_pieces(dent), 2);

  // Below the right boundary: no piece can leave p0.
  dent.chain_left[0] = {{0, 0.5}, {0.5, -0.6}, {1, 0.5}};
  EXPECT_EQ(twin_min_pieces(dent), -1);
}

TEST(BandTwin, MalformedRegionHasNoAnswer) {
  BandRegion r = ideal_region(straight_points(3), symmetric_widths(3, 0.1));
  r.chain_left.pop_back();
  EXPECT_EQ(twin_min_pieces(r), -1);
  EXPECT_FALSE(twin_pair_valid(r, 0, 1));
}

TEST(BandTwin, SampledCircleIsOneArcAndPassesTheChecker) {
  std::vector<VPoint> p;
  for (int k = 0; k < 9; ++k) p.push_back({5 * std::cos(k * kPi / 16), 5 * std::sin(k * kPi / 16)});
  const auto w = symmetric_widths(p.size(), 0.03);
  std::vector<VPiece> pieces;
  EXPECT_EQ(twin_min_pieces(ideal_region(p, w), &pieces), 1);
  const BandReport rep = check_band_fit(p, w, pieces, kSlack);
  EXPECT_TRUE(rep.ok) << rep.why;
  // The arc bulges 0.024 out of each chord: too much for a band of 0.001.
  EXPECT_GT(twin_min_pieces(ideal_region(p, symmetric_widths(p.size(), 0.001))), 1);
}

TEST(BandTwin, WavePiecesPassTheChecker) {
  std::vector<VPoint> p;
  for (int k = 0; k < 14; ++k) p.push_back({0.3 * k, 0.5 * std::sin(0.45 * k)});
  for (double tol : {0.01, 0.05, 0.2}) {
    const auto w = symmetric_widths(p.size(), tol);
    std::vector<VPiece> pieces;
    const int count = twin_min_pieces(ideal_region(p, w), &pieces);
    ASSERT_GT(count, 0) << tol;
    EXPECT_EQ(pieces.size(), static_cast<std::size_t>(count));
    const BandReport rep = check_band_fit(p, w, pieces, kSlack);
    EXPECT_TRUE(rep.ok) << tol << ": " << rep.why;
    for (const VPiece& pc : pieces) EXPECT_LE(band_piece_deviation(p, pc), tol * (1 + 1e-8));
  }
}

TEST(BandTwin, LeftWidthZeroAllowsOnlyRightBulges) {
  // L = 0: the left chain runs along the path itself. The line touches it
  // all along, which is allowed.
  const auto p = straight_points(5);
  const BandRegion r = ideal_region(p, asymmetric_widths(5, 0.0, 0.2));
  VPiece pc;
  ASSERT_TRUE(twin_pair_valid(r, 0, 4, &pc));
  EXPECT_FALSE(pc.arc);
  EXPECT_EQ(twin_min_pieces(r), 1);
  // A dip to y = -0.1 at x = 1. With L = 0 an arc p0 -> p2 must pass p1 on
  // its right, and then sags 0.025 below the edges (R = 0.005): two pieces.
  // With L = 0.05 a shallower arc passes p1 on its left: one piece.
  const std::vector<VPoint> dip{{0, 0}, {1, -0.1}, {2, 0}};
  EXPECT_EQ(twin_min_pieces(ideal_region(dip, asymmetric_widths(3, 0.0, 0.005))), 2);
  EXPECT_EQ(twin_min_pieces(ideal_region(dip, asymmetric_widths(3, 0.05, 0.005))), 1);
  // Zero gates everywhere: only the single edges remain.
  BandRegion flat = r;
  for (std::size_t k = 0; k < 5; ++k) flat.gate_right[k] = p[k];
  for (std::size_t k = 0; k < 4; ++k) flat.chain_right[k] = {p[k], p[k + 1]};
  EXPECT_FALSE(twin_pair_valid(flat, 0, 2));  // zero-length gate 1 cannot be stabbed
  EXPECT_EQ(twin_min_pieces(flat), 4);
}

// Random gentle polylines (turns under 70 degrees, widths under a third of
// the shortest edge, so the ideal gates do not cross): the ideal region with
// straight chains lies inside the band (each edge's band is convex and holds
// both gates' ends), so every piece the twin accepts must pass the checker.
TEST(BandTwin, RandomPolylinesTwinPiecesPassTheChecker) {
  unsigned state = 12345u;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  for (int trial = 0; trial < 24; ++trial) {
    const std::size_t n = 6 + static_cast<std::size_t>(trial % 7);
    std::vector<VPoint> p{{0, 0}};
    double heading = 0, shortest = 1e300;
    for (std::size_t k = 1; k < n; ++k) {
      heading += (uniform() - 0.5) * 2 * 1.2;
      const double len = 0.5 + uniform();
      shortest = std::min(shortest, len);
      p.push_back({p.back().x + len * std::cos(heading), p.back().y + len * std::sin(heading)});
    }
    const double tol = shortest * (0.02 + 0.3 * uniform());
    BandWidths w;
    if (trial % 3 == 0) {
      w = symmetric_widths(n, tol);
    } else if (trial % 3 == 1) {
      w = asymmetric_widths(n, tol * uniform(), tol * uniform());
    } else {
      std::vector<double> t;
      for (std::size_t k = 0; k < n; ++k) t.push_back(tol * (0.2 + 0.8 * uniform()));
      w = per_vertex_widths(t);
    }
    std::vector<VPiece> pieces;
    const int count = twin_min_pieces(ideal_region(p, w), &pieces);
    ASSERT_GT(count, 0) << trial;  // consecutive lines are always valid here
    EXPECT_LE(count, static_cast<int>(n) - 1);
    const BandReport rep = check_band_fit(p, w, pieces, kSlack);
    EXPECT_TRUE(rep.ok) << "trial " << trial << ": " << rep.why;
  }
}

}  // namespace
}  // namespace kerf_test
