// The band function, the certified band check and the certified deviation of
// the band referee (tests/support/band_checker.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "band_checker.hpp"
#include "band_test_helpers.hpp"

namespace kerf_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The band function by dense sampling of s on every edge (a plain reading of
// the definition): an upper bound of the true minimum.
double sampled_band(VPoint x, const std::vector<VPoint>& p, const BandWidths& w, int samples) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < p.size(); ++k) {
    const double dx = p[k + 1].x - p[k].x, dy = p[k + 1].y - p[k].y;
    const double len = std::hypot(dx, dy);
    const double nx = -dy / len, ny = dx / len;
    for (int i = 0; i <= samples; ++i) {
      const double s = static_cast<double>(i) / samples;
      const double c = (1 - s) * (w.left[k] - w.right[k]) / 2 + s * (w.left[k + 1] - w.right[k + 1]) / 2;
      const double ww = (1 - s) * (w.left[k] + w.right[k]) / 2 + s * (w.left[k + 1] + w.right[k + 1]) / 2;
      const double qx = p[k].x + s * dx + c * nx, qy = p[k].y + s * dy + c * ny;
      best = std::min(best, std::hypot(x.x - qx, x.y - qy) - ww);
    }
  }
  return best;
}

TEST(BandValue, StraightTubeIsDistanceMinusTol) {
  const auto p = straight_points(3);
  const auto w = symmetric_widths(3, 0.1);
  EXPECT_NEAR(band_value({0.5, 0.05}, p, w, 0, 2), -0.05, 1e-15);
  EXPECT_NEAR(band_value({1.5, -0.2}, p, w, 0, 2), 0.1, 1e-15);
  EXPECT_NEAR(band_value({2.1, 0.0}, p, w, 0, 2), 0.0, 1e-15);  // the round end cap
  EXPECT_NEAR(band_value({1.5, 0.0}, p, w, 0, 1), std::hypot(0.5, 0.0) - 0.1, 1e-15);
}

TEST(BandValue, LeftWidthZeroExcludesTheLeftSide) {
  const auto p = straight_points(3);
  const auto w = asymmetric_widths(3, 0.0, 0.2);
  EXPECT_NEAR(band_value({0.5, 0.0}, p, w, 0, 2), 0.0, 1e-15);
  EXPECT_NEAR(band_value({0.5, 0.01}, p, w, 0, 2), 0.01, 1e-15);
  EXPECT_NEAR(band_value({0.5, -0.15}, p, w, 0, 2), -0.05, 1e-15);
  EXPECT_NEAR(band_value({0.5, -0.25}, p, w, 0, 2), 0.05, 1e-15);
}

TEST(BandValue, TaperMatchesTheConeFormula) {
  // One edge (0,0)-(1,0), tol 0.1 -> 0.3: slope m = 0.2. Off the end caps the
  // minimum is beta sqrt(1 - m^2) - w0 - m alpha.
  const std::vector<VPoint> p{{0, 0}, {1, 0}};
  const auto w = per_vertex_widths({0.1, 0.3});
  const double m = 0.2;
  EXPECT_NEAR(band_value({0.5, 0.2}, p, w, 0, 1), 0.2 * std::sqrt(1 - m * m) - 0.1 - m * 0.5, 1e-15);
}

TEST(BandValue, AgreesWithDenseSampling) {
  const std::vector<VPoint> p{{0, 0}, {1, 0.2}, {1.5, 1}, {0.7, 1.6}, {0.9, 1.65}};
  const BandWidths w{{0.0, 0.3, 0.05, 0.2, 0.1}, {0.2, 0.0, 0.25, 0.05, 0.1}};
  const int samples = 20000;
  for (int i = 0; i < 400; ++i) {
    const VPoint x{-0.5 + 2.5 * std::fmod(i * 0.6180339887, 1.0), -0.5 + 2.5 * std::fmod(i * 0.7548776662, 1.0)};
    const double exact = band_value(x, p, w, 0, p.size() - 1);
    const double sampled = sampled_band(x, p, w, samples);
    // Sampling can only overshoot the minimum, by at most (|v| + |dw|) / samples.
    EXPECT_LE(exact, sampled + 1e-14) << i;
    EXPECT_GE(exact, sampled - 2.0 / samples) << i;
  }
}

TEST(ArcInBand, LineAlongAStraightPolylinePasses) {
  const auto p = straight_points(5);
  const auto w = symmetric_widths(5, 0.1);
  double worst = 0;
  EXPECT_TRUE(arc_in_band(p, w, line_piece(p, 0, 4), 1e-9 * 4, &worst));
  EXPECT_NEAR(worst, -0.1, 1e-15);
}

TEST(ArcInBand, OffsetLinePassesInsideAndFailsOutside) {
  const auto p = straight_points(5);
  const double tol = 0.1, slack = 4e-9;
  const auto w = symmetric_widths(5, tol);
  double worst = 0;
  EXPECT_TRUE(arc_in_band(p, w, shifted(line_piece(p, 0, 4), 0, 0.99 * tol), slack, &worst));
  EXPECT_NEAR(worst, -0.01 * tol, 1e-15);
  // On the boundary itself: the chord bound proves it without endless splitting.
  EXPECT_TRUE(arc_in_band(p, w, shifted(line_piece(p, 0, 4), 0, -tol), slack, &worst));
  EXPECT_FALSE(arc_in_band(p, w, shifted(line_piece(p, 0, 4), 0, 1.01 * tol), slack, &worst));
  EXPECT_NEAR(worst, 0.01 * tol, 1e-15);
  EXPECT_FALSE(arc_in_band(p, w, shifted(line_piece(p, 0, 4), 0, -1.01 * tol), slack, &worst));
}

TEST(ArcInBand, ArcThroughSampledCircleNeedsTheSagitta) {
  // p_k on a circle of radius 10, 30 degrees apart: the arc bulges out of
  // each chord by the sagitta r (1 - cos 15 deg).
  const double r = 10, step = kPi / 6;
  std::vector<VPoint> p;
  for (int k = 0; k < 3; ++k) p.push_back({r * std::cos(k * step), r * std::sin(k * step)});
  VPiece arc = line_piece(p, 0, 2);
  arc.arc = true;
  arc.dir = 1;
  const double sag = r * (1 - std::cos(step / 2));
  double worst = 0;
  EXPECT_TRUE(arc_in_band(p, symmetric_widths(3, 1.01 * sag), arc, 1e-8, &worst));
  EXPECT_LE(worst, 0.0);
  EXPECT_FALSE(arc_in_band(p, symmetric_widths(3, 0.99 * sag), arc, 1e-8, &worst));
  EXPECT_NEAR(worst, 0.01 * sag, 1e-12);
  // Only the outside needs width: no left width (the inside of a CCW turn).
  EXPECT_TRUE(arc_in_band(p, asymmetric_widths(3, 0.0, 1.01 * sag), arc, 1e-8));
  EXPECT_FALSE(arc_in_band(p, asymmetric_widths(3, 1.01 * sag, 0.0), arc, 1e-8));
}

TEST(ArcInBand, AsymmetricRightOnlyBand) {
  const auto p = straight_points(6, 2.0);  // chord 10
  const double tol = 0.2, slack = 1e-8;
  const auto w = asymmetric_widths(6, 0.0, tol);
  EXPECT_TRUE(arc_in_band(p, w, bulge_piece(p, 0, 5, -0.9 * tol), slack));
  EXPECT_FALSE(arc_in_band(p, w, bulge_piece(p, 0, 5, 0.01 * tol), slack));
  EXPECT_FALSE(arc_in_band(p, w, bulge_piece(p, 0, 5, -1.05 * tol), slack));
  // The mirror image with the left width only.
  const auto wl = asymmetric_widths(6, tol, 0.0);
  EXPECT_TRUE(arc_in_band(p, wl, bulge_piece(p, 0, 5, 0.9 * tol), slack));
  EXPECT_FALSE(arc_in_band(p, wl, bulge_piece(p, 0, 5, -0.01 * tol), slack));
}

TEST(ArcInBand, PerVertexTaper) {
  const auto p = straight_points(3, 5.0);
  const double slack = 1e-8;
  // Wide in the middle: a bulge of 0.3 fits under widths 0.1 / 0.5 / 0.1 ...
  EXPECT_TRUE(arc_in_band(p, per_vertex_widths({0.1, 0.5, 0.1}), bulge_piece(p, 0, 2, 0.3), slack));
  EXPECT_TRUE(arc_in_band(p, per_vertex_widths({0.1, 0.5, 0.1}), bulge_piece(p, 0, 2, -0.3), slack));
  // ... but not under a constant 0.1, nor when the taper is the other way round.
  EXPECT_FALSE(arc_in_band(p, symmetric_widths(3, 0.1), bulge_piece(p, 0, 2, 0.3), slack));
  EXPECT_FALSE(arc_in_band(p, per_vertex_widths({0.5, 0.1, 0.5}), bulge_piece(p, 0, 2, 0.3), slack));
  // A bulge of 0.45 pokes out of the linear taper near x = 2.5 (0.34 > 0.3).
  EXPECT_FALSE(arc_in_band(p, per_vertex_widths({0.1, 0.5, 0.1}), bulge_piece(p, 0, 2, 0.45), slack));
}

TEST(ArcInBand, HugeRadiusArcIsAsGoodAsTheLine) {
  // Radius 1e9 over a chord of 4: sagitta 2e-9, far below the slack of the test.
  const auto p = straight_points(5);
  const auto w = symmetric_widths(5, 0.1);
  const VPiece nearly_line = bulge_piece(p, 0, 4, 2e-9);
  EXPECT_GT(std::hypot(nearly_line.cx - 2, nearly_line.cy), 9e8);
  double worst = 0;
  EXPECT_TRUE(arc_in_band(p, w, nearly_line, 4e-9, &worst));
  EXPECT_NEAR(worst, -0.1, 1e-8);
}

TEST(ArcInBand, FarFromTheOriginKeepsItsAccuracy) {
  // The same cases a million units away: the slack (1e-9 of the scale) still
  // separates 0.99 tol from 1.01 tol, and the sampled circle still needs its sagitta.
  const double ox = 1e6, oy = -2e6, tol = 0.1, slack = 4e-9;
  std::vector<VPoint> p = straight_points(5);
  for (VPoint& q : p) q = {q.x + ox, q.y + oy};
  const auto w = symmetric_widths(5, tol);
  EXPECT_TRUE(arc_in_band(p, w, shifted(line_piece(p, 0, 4), 0, 0.99 * tol), slack));
  EXPECT_FALSE(arc_in_band(p, w, shifted(line_piece(p, 0, 4), 0, 1.01 * tol), slack));
  EXPECT_TRUE(arc_in_band(p, w, bulge_piece(p, 0, 4, -0.99 * tol), slack));
  EXPECT_FALSE(arc_in_band(p, w, bulge_piece(p, 0, 4, -1.01 * tol), slack));

  const double r = 10, step = kPi / 6;
  std::vector<VPoint> c;
  for (int k = 0; k < 3; ++k) c.push_back({ox + r * std::cos(k * step), oy + r * std::sin(k * step)});
  VPiece arc = line_piece(c, 0, 2);
  arc.arc = true;
  arc.cx = ox;
  arc.cy = oy;
  arc.dir = 1;
  const double sag = r * (1 - std::cos(step / 2));
  EXPECT_TRUE(arc_in_band(c, symmetric_widths(3, 1.01 * sag), arc, 1e-8));
  EXPECT_FALSE(arc_in_band(c, symmetric_widths(3, 0.99 * sag), arc, 1e-8));
  const double dev = band_piece_deviation(c, arc);
  EXPECT_GE(dev, sag * (1 - 1e-9));
  EXPECT_LE(dev, sag * (1 + 1e-8));
}

TEST(SegmentInBand, ProvesAndRefutesSegments) {
  const std::vector<VPoint> p{{0, 0}, {2, 0}, {2, 2}};
  const auto w = symmetric_widths(3, 0.1);
  EXPECT_TRUE(segment_in_band(p, w, 0, 2, {0, 0.09}, {1.91, 0.09}, 1e-9));
  EXPECT_TRUE(segment_in_band(p, w, 0, 2, {1.95, 0.05}, {1.95, 1.5}, 1e-9));
  // Cutting the corner leaves the band; against edge 0 alone so does going up.
  EXPECT_FALSE(segment_in_band(p, w, 0, 2, {1.5, 0}, {2, 0.5}, 1e-9));
  EXPECT_FALSE(segment_in_band(p, w, 0, 1, {1.95, 0.05}, {1.95, 1.5}, 1e-9));
}

TEST(Deviation, ZeroAlongTheLineAndSagittaForTheArc) {
  const auto p = straight_points(5);
  EXPECT_LE(band_piece_deviation(p, line_piece(p, 0, 4)), 1e-11);
  const double off = band_piece_deviation(p, shifted(line_piece(p, 0, 4), 0, 0.25));
  EXPECT_GE(off, 0.25);
  EXPECT_LE(off, 0.25 * (1 + 2e-9));

  const double r = 10, step = kPi / 12;
  std::vector<VPoint> c;
  for (int k = 0; k < 7; ++k) c.push_back({r * std::cos(k * step), r * std::sin(k * step)});
  VPiece arc = line_piece(c, 0, 6);
  arc.arc = true;
  arc.dir = 1;
  const double sag = r * (1 - std::cos(step / 2));
  const double dev = band_piece_deviation(c, arc);
  EXPECT_GE(dev, sag * (1 - 1e-12));  // an upper bound of the true maximum
  EXPECT_LE(dev, sag * (1 + 2e-9));
}

TEST(Deviation, LineCuttingACorner) {
  const std::vector<VPoint> p{{0, 0}, {1, 1}, {2, 0}};
  const double dev = band_piece_deviation(p, line_piece(p, 0, 2));
  EXPECT_GE(dev, std::sqrt(0.5) * (1 - 1e-15));
  EXPECT_LE(dev, std::sqrt(0.5) * (1 + 2e-9));
}

// Points of an arc piece the plain way: centre, radius and polar angle.
std::vector<VPoint> plain_arc_samples(const VPiece& pc, int count) {
  const double r = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
  const double a0 = std::atan2(pc.sy - pc.cy, pc.sx - pc.cx);
  const double a1 = std::atan2(pc.ey - pc.cy, pc.ex - pc.cx);
  double sweep = std::fmod(pc.dir * (a1 - a0), 2 * kPi);
  if (sweep < 0) sweep += 2 * kPi;
  std::vector<VPoint> out;
  for (int i = 0; i <= count; ++i) {
    const double a = a0 + pc.dir * sweep * i / count;
    out.push_back({pc.cx + r * std::cos(a), pc.cy + r * std::sin(a)});
  }
  return out;
}

// Random arcs over random polylines, against dense plain sampling: the
// certified answers must bound the samples, and be close to them.
TEST(ArcInBand, AgreesWithDenseSamplingOnRandomArcs) {
  unsigned state = 777u;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  const int count = 20000;
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<VPoint> p{{0, 0}};
    for (int k = 1; k < 6; ++k) p.push_back({p.back().x + 0.5 + uniform(), p.back().y + uniform() - 0.5});
    const BandWidths w{{0.05 + 0.2 * uniform(), 0.1, 0.05 + 0.2 * uniform(), 0.15, 0.1, 0.05},
                       {0.1, 0.05 + 0.2 * uniform(), 0.2, 0.05 + 0.1 * uniform(), 0.1, 0.12}};
    const VPiece pc = bulge_piece(p, 0, 5, (uniform() - 0.5) * 0.8);
    const std::vector<VPoint> xs = plain_arc_samples(pc, count);
    double len = 0, worst_band = -1e300, worst_dist = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (i > 0) len += std::hypot(xs[i].x - xs[i - 1].x, xs[i].y - xs[i - 1].y);
      worst_band = std::max(worst_band, band_value(xs[i], p, w, 0, 5));
      worst_dist = std::max(worst_dist, band_value(xs[i], p, symmetric_widths(6, 0.0), 0, 5));
    }
    const double spacing = len / count;
    // The deviation bounds every sample and is within the spacing of them.
    const double dev = band_piece_deviation(p, pc);
    EXPECT_GE(dev, worst_dist - 1e-12) << trial;
    EXPECT_LE(dev, worst_dist + spacing) << trial;
    // The band check: a sample outside means no; a clear margin means yes.
    for (double slack : {worst_band - 2 * spacing, worst_band + 2 * spacing}) {
      const bool inside = arc_in_band(p, w, pc, slack);
      EXPECT_EQ(inside, slack > worst_band) << trial << " slack " << slack;
    }
  }
}

}  // namespace
}  // namespace kerf_test
