// Gates and the piece / fit checks of the band referee (tests/support/band_checker.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "band_checker.hpp"
#include "band_test_helpers.hpp"

namespace kerf_test {
namespace {

constexpr double kSlack = 1e-9;

double dist(VPoint a, VPoint b) { return std::hypot(a.x - b.x, a.y - b.y); }

TEST(BandGate, RightAngleCornerBisects) {
  const std::vector<VPoint> p{{0, 0}, {1, 0}, {1, 1}};
  const BandGate g = band_gate(p, symmetric_widths(3, 0.1), 1);
  ASSERT_FALSE(g.cusp);
  const double h = 0.1 / std::sqrt(2.0);
  EXPECT_NEAR(g.left.x, 1 - h, 1e-15);  // inside of the left turn
  EXPECT_NEAR(g.left.y, h, 1e-15);
  EXPECT_NEAR(g.right.x, 1 + h, 1e-15);
  EXPECT_NEAR(g.right.y, -h, 1e-15);
  EXPECT_NEAR(g.fx, h / 0.1, 1e-15);  // forward: unit(u0 + u1)
  EXPECT_NEAR(g.fy, h / 0.1, 1e-15);
}

TEST(BandGate, EndsLieOnTheVertexDisc) {
  // The gate halves reach the circle of radius w_k around p_k + c_k n_k.
  const std::vector<VPoint> p{{0, 0}, {1, 0.3}, {1.4, 1.2}, {0.5, 1.5}};
  const BandWidths w{{0.0, 0.25, 0.1, 0.3}, {0.2, 0.05, 0.1, 0.0}};
  for (std::size_t k = 0; k < p.size(); ++k) {
    const BandGate g = band_gate(p, w, k);
    ASSERT_FALSE(g.cusp);
    const std::size_t e = k + 1 < p.size() ? k : k - 1;
    const double dx = p[e + 1].x - p[e].x, dy = p[e + 1].y - p[e].y, len = std::hypot(dx, dy);
    const double c = (w.left[k] - w.right[k]) / 2, ww = (w.left[k] + w.right[k]) / 2;
    const VPoint centre{p[k].x - c * dy / len, p[k].y + c * dx / len};
    EXPECT_NEAR(dist(g.left, centre), ww, 1e-14) << k;
    EXPECT_NEAR(dist(g.right, centre), ww, 1e-14) << k;
    // p_k lies on the gate, the forward normal is across it.
    EXPECT_NEAR(dist(g.left, p[k]) + dist(p[k], g.right), dist(g.left, g.right), 1e-14) << k;
    EXPECT_NEAR(g.fx * g.bx + g.fy * g.by, 0.0, 1e-15);
    if (k + 1 < p.size()) {
      EXPECT_GT((p[k + 1].x - p[k].x) * g.fx + (p[k + 1].y - p[k].y) * g.fy, 0);
    }
    // And the gate ends are in the band.
    EXPECT_LE(band_value(g.left, p, w, 0, p.size() - 1), 1e-14) << k;
    EXPECT_LE(band_value(g.right, p, w, 0, p.size() - 1), 1e-14) << k;
  }
}

TEST(BandGate, TurnBackIsACusp) {
  const std::vector<VPoint> p{{0, 0}, {2, 0}, {1, 1e-8}};
  EXPECT_TRUE(band_gate(p, symmetric_widths(3, 0.1), 1).cusp);
  const std::vector<VPoint> q{{0, 0}, {2, 0}, {1, 1e-5}};
  EXPECT_FALSE(band_gate(q, symmetric_widths(3, 0.1), 1).cusp);
}

TEST(CheckBandPiece, LineAndArcOnAStraightPolyline) {
  const auto p = straight_points(5);
  const auto w = symmetric_widths(5, 0.1);
  const BandReport line = check_band_piece(p, w, line_piece(p, 0, 4), kSlack);
  EXPECT_TRUE(line.ok) << line.why;
  EXPECT_NEAR(line.worst, -0.1, 1e-15);
  EXPECT_TRUE(check_band_piece(p, w, bulge_piece(p, 0, 4, 0.09), kSlack).ok);
  // Too high a bulge misses gate 2 (it ends at 0.1) ...
  const BandReport high = check_band_piece(p, w, bulge_piece(p, 0, 4, 0.11), kSlack);
  EXPECT_FALSE(high.ok);
  EXPECT_NE(high.why.find("gate 2"), std::string::npos) << high.why;
  // ... and between two gates it leaves the band.
  const BandReport out = check_band_piece(p, w, bulge_piece(p, 0, 1, 0.15), kSlack);
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.why.find("leaves the band"), std::string::npos) << out.why;
  EXPECT_GT(out.worst, 0.0);
}

TEST(CheckBandPiece, EndsMustBeTheInputPoints) {
  const auto p = straight_points(5);
  const auto w = symmetric_widths(5, 0.1);
  const BandReport r = check_band_piece(p, w, shifted(line_piece(p, 0, 4), 0, 0.05), kSlack);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.why.find("start"), std::string::npos) << r.why;
  VPiece wrong_end = line_piece(p, 0, 3);
  wrong_end.last = 4;
  EXPECT_FALSE(check_band_piece(p, w, wrong_end, kSlack).ok);
  EXPECT_TRUE(check_band_piece(p, w, shifted(line_piece(p, 0, 4), 1e-10, 0), kSlack).ok);
}

TEST(CheckBandPiece, SkippingAGateFails) {
  // A hairpin: the chord p0 -> p2 stays within tol = 2 of both edges but
  // passes nowhere near gate 1 at (10, 0).
  const std::vector<VPoint> p{{0, 0}, {10, 0}, {0, 3.5}};
  const auto w = symmetric_widths(3, 2.0);
  const VPiece chord = line_piece(p, 0, 2);
  EXPECT_TRUE(arc_in_band(p, w, chord, kSlack));
  const BandReport r = check_band_piece(p, w, chord, kSlack);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.why.find("does not cut gate 1"), std::string::npos) << r.why;
  // Two pieces through the corner are fine.
  EXPECT_TRUE(check_band_fit(p, w, {line_piece(p, 0, 1), line_piece(p, 1, 2)}, kSlack).ok);
}

TEST(CheckBandPiece, TurningBackFails) {
  // More than a half circle from p0 to p2: it leaves p0 backwards, inside a wide band.
  const auto p = straight_points(3);
  const auto w = symmetric_widths(3, 1.5);
  const VPiece loop = bulge_piece(p, 0, 2, 1.2);
  EXPECT_TRUE(arc_in_band(p, w, loop, kSlack));
  const BandReport r = check_band_piece(p, w, loop, kSlack);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.why.find("start tangent"), std::string::npos) << r.why;
  EXPECT_TRUE(check_band_piece(p, w, bulge_piece(p, 0, 2, 0.8), kSlack).ok);
}

TEST(CheckBandPiece, GatesOutOfOrderFail) {
  // A U turn with long gates (w = 3): gate 1 (line x + y = 1) and gate 2
  // cross each other, and the chord p0 -> p3 (x = 0) meets gate 2 at y = 0.38
  // before gate 1 at y = 1.
  const std::vector<VPoint> p{{0, 0}, {1, 0}, {1, 1}, {0, 1.5}};
  const auto w = symmetric_widths(4, 3.0);
  const VPiece chord = line_piece(p, 0, 3);
  EXPECT_TRUE(arc_in_band(p, w, chord, kSlack));
  const BandReport r = check_band_piece(p, w, chord, kSlack);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.why.find("cuts gate 2"), std::string::npos) << r.why;
}

TEST(CheckBandPiece, CuspInsideAPieceFails) {
  const std::vector<VPoint> p{{0, 0}, {2, 0}, {1, 1e-9}};
  const auto w = symmetric_widths(3, 0.1);
  const BandReport r = check_band_piece(p, w, line_piece(p, 0, 2), kSlack);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.why.find("cusp"), std::string::npos) << r.why;
  // Ending at the cusp and starting from it again is allowed.
  const BandReport two = check_band_fit(p, w, {line_piece(p, 0, 1), line_piece(p, 1, 2)}, kSlack);
  EXPECT_TRUE(two.ok) << two.why;
}

TEST(CheckBandFit, PiecesMustRunContiguously) {
  const auto p = straight_points(5);
  const auto w = symmetric_widths(5, 0.1);
  EXPECT_TRUE(check_band_fit(p, w, {line_piece(p, 0, 2), line_piece(p, 2, 4)}, kSlack).ok);
  const BandReport gap = check_band_fit(p, w, {line_piece(p, 0, 1), line_piece(p, 2, 4)}, kSlack);
  EXPECT_FALSE(gap.ok);
  EXPECT_NE(gap.why.find("not contiguous"), std::string::npos) << gap.why;
  EXPECT_FALSE(check_band_fit(p, w, {line_piece(p, 0, 3)}, kSlack).ok);
  EXPECT_FALSE(check_band_fit(p, w, {}, kSlack).ok);
}

}  // namespace
}  // namespace kerf_test
