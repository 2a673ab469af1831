// Differential tests of the band fitter against the independent referee in
// tests/support: on seeded random polylines (smooth, noisy, sharp, zig-zag,
// short edges) and every kind of width (symmetric, one-sided, asymmetric,
// per vertex),
//  - core's count equals the brute-force twin's over the same region R;
//  - each pair's validity agrees with the twin's (on the smallest cases);
//  - every output piece passes the band checker (certified band, gate order,
//    end tangents) against its own sub-polyline;
//  - R itself lies inside the band (every chain and gate segment, certified);
//  - with symmetric widths the count is >= the vertex criterion's minimum.
// KERF_SOAK_CASES=N runs N more seeds per family.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "band_checker.hpp"
#include "band_twin.hpp"
#include "bridge/band_bridge.hpp"
#include "rng.hpp"

namespace {

using kerf_test::BandWidths;
using kerf_test::CoreBandFitter;
using kerf_test::Rng;
using kerf_test::VPoint;

constexpr double kPi = 3.14159265358979323846;

struct Case {
  std::string name;
  std::vector<VPoint> pts;
  BandWidths widths;
  double tol = 0;
  bool symmetric = true;
};

std::string describe(const Case& c) {
  std::ostringstream s;
  s.precision(17);
  s << c.name << " tol " << c.tol << " points:";
  for (const VPoint& p : c.pts) s << " (" << p.x << "," << p.y << ")";
  s << " widths (left,right):";
  for (std::size_t k = 0; k < c.pts.size(); ++k) s << " (" << c.widths.left[k] << "," << c.widths.right[k] << ")";
  return s.str();
}

// A polyline of n points: a walk whose heading turns by up to max_turn per
// step, with steps between lo and hi.
std::vector<VPoint> walk(Rng& rng, int n, double max_turn, double lo, double hi) {
  std::vector<VPoint> p;
  double x = 0, y = 0, heading = rng.uniform(0, 2 * kPi);
  for (int k = 0; k < n; ++k) {
    p.push_back({x, y});
    heading += rng.uniform(-max_turn, max_turn);
    const double step = rng.uniform(lo, hi);
    x += step * std::cos(heading);
    y += step * std::sin(heading);
  }
  return p;
}

// Points on a circle arc or a sine, with noise of the given size.
std::vector<VPoint> curve(Rng& rng, int n, double noise) {
  std::vector<VPoint> p;
  const bool circle = rng.uniform() < 0.5;
  const double r = rng.uniform(5, 50);
  const double sweep = rng.uniform(0.3, 1.8) * kPi;
  for (int k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / (n - 1);
    VPoint q = circle ? VPoint{r * std::cos(sweep * t), r * std::sin(sweep * t)}
                      : VPoint{40 * t, 5 * std::sin(2 * kPi * 1.5 * t)};
    q.x += noise * rng.normal();
    q.y += noise * rng.normal();
    p.push_back(q);
  }
  return p;
}

Case make_case(const std::string& family, std::uint64_t seed) {
  Rng rng(seed * 7919 + family.size());
  Case c;
  c.name = family + " seed " + std::to_string(seed);
  const int n = rng.integer(3, 18);
  c.tol = rng.uniform(0.02, 0.5);
  if (family == "smooth") c.pts = walk(rng, n, 0.2, 0.5, 2.0);
  else if (family == "sharp") c.pts = walk(rng, n, 2.8, 0.3, 2.0);
  else if (family == "short") c.pts = walk(rng, n, 1.0, 0.01, 0.3);
  else if (family == "zigzag") {
    for (int k = 0; k < n; ++k) c.pts.push_back({0.7 * k, (k % 2 ? 1.0 : -1.0) * c.tol * rng.uniform(0.2, 1.5)});
  } else c.pts = curve(rng, n, rng.uniform() < 0.5 ? 0.0 : c.tol * 0.3);
  const std::size_t m = c.pts.size();
  switch (seed % 5) {
    case 0: c.widths = kerf_test::symmetric_widths(m, c.tol); break;
    case 1: c.widths = kerf_test::asymmetric_widths(m, 0.0, c.tol); c.symmetric = false; break;
    case 2: c.widths = kerf_test::asymmetric_widths(m, c.tol, 0.0); c.symmetric = false; break;
    case 3: c.widths = kerf_test::asymmetric_widths(m, 0.3 * c.tol, c.tol); c.symmetric = false; break;
    default: {
      std::vector<double> t;
      for (std::size_t k = 0; k < m; ++k) t.push_back(c.tol * rng.uniform(0.3, 1.0));
      c.widths = kerf_test::per_vertex_widths(t);
      c.symmetric = false;
    }
  }
  return c;
}


void check_case(const Case& c, bool pairwise) {
  SCOPED_TRACE(describe(c));
  CoreBandFitter core(c.pts, c.widths);
  const double slack = 1e-9 * kerf_test::scale_of(c.pts) + 1e-12;

  // R is inside the band.
  const kerf_test::BandRegion region = core.region();
  ASSERT_EQ(region.pts.size(), c.pts.size());
  const std::size_t n = c.pts.size();
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_TRUE(kerf_test::segment_in_band(c.pts, c.widths, 0, n - 1, region.gate_right[k],
                                           region.gate_left[k], slack))
        << "gate " << k;
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    for (const auto* chain : {&region.chain_left[k], &region.chain_right[k]}) {
      for (std::size_t t = 0; t + 1 < chain->size(); ++t)
        EXPECT_TRUE(kerf_test::segment_in_band(c.pts, c.widths, 0, n - 1, (*chain)[t],
                                               (*chain)[t + 1], slack))
            << "cell " << k << " chain segment " << t;
    }
  }

  // The count is the twin's.
  const auto count = core.count();
  ASSERT_TRUE(count.ok()) << kerf::to_string(count.status());
  const int twin = kerf_test::twin_min_pieces(region);
  EXPECT_EQ(static_cast<int>(count.value()), twin);

  if (pairwise) {
    for (std::uint32_t i = 0; i + 1 < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j)
        EXPECT_EQ(core.pair_valid(i, j), kerf_test::twin_pair_valid(region, i, j))
            << "pair " << i << " -> " << j;
  }

  // The fit's pieces pass the checker, and the count is the same.
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  EXPECT_EQ(fit.value().pieces, count.value());
  const auto report = kerf_test::check_band_fit(c.pts, c.widths, core.pieces(fit.value().pieces), slack);
  EXPECT_TRUE(report.ok) << report.why;

  if (c.symmetric) {  // every inner point is within tol of a band piece
    kerf_test::CoreFitter vertex(c.pts);
    const auto v = vertex.count(c.tol, kerf_test::Method::optimal);
    ASSERT_TRUE(v.ok());
    EXPECT_GE(count.value(), v.value());
  }
}

int soak_cases() {
  const char* env = std::getenv("KERF_SOAK_CASES");
  return env != nullptr ? std::atoi(env) : 0;
}

class BandDifferential : public ::testing::TestWithParam<const char*> {};

TEST_P(BandDifferential, CountsMatchTheTwinAndPiecesPassTheChecker) {
  const int cases = 10 + soak_cases();
  for (int seed = 0; seed < cases; ++seed) {
    const Case c = make_case(GetParam(), static_cast<std::uint64_t>(seed));
    check_case(c, seed < 4);
    if (HasFailure()) return;  // the first failing case is enough to debug
  }
}

INSTANTIATE_TEST_SUITE_P(Families, BandDifferential,
                         ::testing::Values("smooth", "sharp", "short", "zigzag", "curve"));

}  // namespace
