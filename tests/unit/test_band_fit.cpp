// The band fitter on the report's parabola, on degenerate polylines and on
// bad input. Every fit is checked by the independent band checker
// (tests/support/band_checker.hpp) against its own widths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "band_checker.hpp"
#include "bridge/band_bridge.hpp"
#include "rng.hpp"

namespace {

using kerf_test::BandWidths;
using kerf_test::CoreBandFitter;
using kerf_test::VPoint;

constexpr double kPi = 3.14159265358979323846;

std::vector<VPoint> load(const std::string& name) {
  std::ifstream in(std::string(KERF_TEST_DATA_DIR) + "/curves/" + name);
  std::vector<VPoint> p;
  double x = 0, y = 0;
  while (in >> x >> y) p.push_back({x, y});
  return p;
}

double slack_for(const std::vector<VPoint>& p) { return 1e-9 * kerf_test::scale_of(p) + 1e-12; }

// Fits at the widths and checks the result with the referee; returns the count.
std::uint32_t checked_fit(const std::vector<VPoint>& p, const BandWidths& w) {
  CoreBandFitter core(p, w);
  const auto fit = core.fit();
  EXPECT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  if (!fit.ok()) return 0;
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
  return fit.value().pieces;
}

TEST(BandReference, ParabolaCountsAreTheReportsAndPassTheChecker) {
  const auto p = load("parabola.txt");
  ASSERT_EQ(p.size(), 200u);
  EXPECT_EQ(checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.0183)), 5u);
  EXPECT_EQ(checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.0085)), 7u);
  EXPECT_EQ(checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.05)), 4u);
  EXPECT_EQ(checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.1)), 3u);
}

// Found by fuzzing (tests/fuzz/corpus/fit_band/sharp_turn_one_sided): a turn
// of 176 degrees with widths 0.30 left and 1.17 right. The pair 1..3 took a
// short arc near the chord p1 p3, 1500 away from p2, because the circle (on
// its far side) crossed gate 2; `kerf fit` printed it with max error 57.
TEST(BandReference, SharpTurnWithUnequalWidthsKeepsTheArcInTheBand) {
  const std::vector<VPoint> p{{-428, -987}, {-431, -956}, {-243, 586}, {-545, -943}};
  const auto w = kerf_test::asymmetric_widths(p.size(), 0.30046648963304434, 1.1682835103669555);
  CoreBandFitter core(p, w);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  EXPECT_LE(fit.value().pieces, 3u);
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
  EXPECT_LE(fit.value().max_error, 1.1682835103669555 * (1 + 1e-9));
}

// Found by fuzzing (tests/fuzz/corpus/fit_band/sharp_turn_arc_out_of_band):
// a 140-degree turn at the first inner vertex, tol 1.77 on edges of 1e3 to
// 7e4. The tie-break's smallest scale (1e-12) left gates below the
// coordinates' resolution; their ends fell a rounding step beside p1 and p3,
// and the pair 1..3 passed with a 256-degree arc 44966 out of the band (two
// pieces instead of three).
TEST(BandReference, SharpTurnAtTheFirstVertexKeepsThreeLines) {
  const std::vector<VPoint> p{{7872, -68096}, {8640, -68928}, {-60608, -60608}, {9920, 9920}};
  const auto w = kerf_test::symmetric_widths(p.size(), 1.7734375);
  CoreBandFitter core(p, w);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  EXPECT_EQ(fit.value().pieces, 3u);
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
  EXPECT_LE(fit.value().max_error, 1.7734375);
}

// Found by fuzzing (tests/fuzz/corpus/fit_band/one_sided_sub_ulp_width): a
// right width of 2e-13 at coordinates of 1.4e4, below their resolution. The
// chain's end sat a rounding step beside p3, the segment test lost its
// binding point there, and 1..3 took an arc 1109 from the path in a 62 band.
// The fit must be the one of a right width of 0.
TEST(BandReference, OneSidedWidthBelowTheResolutionFitsLikeZero) {
  const std::vector<VPoint> p{{14624, 1184}, {14528, 1600}, {14384, 1648}, {-272, 1392}, {-3520, -14448}};
  const double left = 61.999999999999787;
  const auto w = kerf_test::asymmetric_widths(p.size(), left, 2.1338822635968979e-13);
  CoreBandFitter core(p, w);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
  EXPECT_LE(fit.value().max_error, left);
  CoreBandFitter zero(p, kerf_test::asymmetric_widths(p.size(), left, 0.0));
  const auto z = zero.fit();
  ASSERT_TRUE(z.ok());
  EXPECT_EQ(fit.value().pieces, z.value().pieces);
  EXPECT_NEAR(fit.value().max_error, z.value().max_error, 1e-9 * left);
}

// Found by fuzzing (tests/fuzz/corpus/fit_band/near_cusp_one_sided_sub_ulp_width):
// the same widths, and a turn of 179.4 degrees at p9. Its gate runs almost
// along the edges, so the sub-resolution right width gives a half gate of
// many ulps: the chain's end is a hair from p9, not a rounding step. The
// binding point near t = 1 was lost again, and 7..9 took an arc 1408 out.
TEST(BandReference, NearCuspWithASubResolutionWidthKeepsTheArcInTheBand) {
  const std::vector<VPoint> p{
      {-80, -224},    {-176, -144},   {-128, 128},   {-176, -80},    {14624, 880},
      {14384, 688},   {14144, 960},   {1888, 1760},  {1888, 1888},   {-1296, 1888},
      {-352, 1872},   {1888, -1296},  {1632, -1808}, {1376, -2320},  {1120, -2832},
      {880, -3344},   {1888, 1888},   {1888, 1616},  {2048, 1568},   {2224, 1696},
      {-7584, 640},   {1888, 1888},   {1888, -6432}, {1712, -6528},  {1488, -6080},
      {-8720, -15088}};
  const double left = 61.999999999999787;
  const auto w = kerf_test::asymmetric_widths(p.size(), left, 2.1338822635968979e-13);
  CoreBandFitter core(p, w);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
  EXPECT_LE(fit.value().max_error, left);
}

// A closed circle (90 points rounded to 1e-5) at the tol kerf weld's coarse
// tie-break lands on: the fit is 0..67 (268 degrees) and 67..90. The gate
// line at 180 degrees meets that circle again next to p_0, where the arc's
// order parameter is noise; the deviation took that crossing and reported
// the diameter (1.9988) for an arc inside the band.
TEST(BandReference, ArcPastAHalfTurnReportsItsTrueDeviation) {
  std::vector<VPoint> p{{1, 0}};
  for (int k = 1; k <= 90; ++k) {
    const double a = 2 * M_PI * k / 90;
    p.push_back({std::round(std::cos(a) * 1e5) / 1e5, std::round(std::sin(a) * 1e5) / 1e5});
  }
  const double tol = 0.000964;
  const auto w = kerf_test::symmetric_widths(p.size(), tol);
  CoreBandFitter core(p, w);
  const auto fit = core.fit(0.1);
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  ASSERT_EQ(fit.value().pieces, 2u);
  bool long_arc = false;
  for (std::uint32_t k = 0; k < 2; ++k) {
    long_arc = long_arc || core.piece(k).last - core.piece(k).first > 45;
    EXPECT_LE(core.piece(k).error, tol) << "piece " << k;
  }
  EXPECT_TRUE(long_arc) << "the case needs a piece of more than a half turn";
  EXPECT_LE(fit.value().max_error, tol);
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
}

TEST(BandReference, MinErrorIsTheSmallestBandForTheBudget) {
  const auto p = load("parabola.txt");
  CoreBandFitter core(p, kerf_test::symmetric_widths(p.size(), 1.0));
  const auto fit = core.budget(5);
  ASSERT_TRUE(fit.ok());
  const double tol = fit.value().tol;
  EXPECT_LT(tol, 0.0183);
  EXPECT_LE(fit.value().max_error, tol * (1 + 1e-9));
  const auto w = kerf_test::symmetric_widths(p.size(), tol);
  const auto report = kerf_test::check_band_fit(p, w, core.pieces(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(report.ok) << report.why;
  // Just below it, five pieces are no longer enough.
  CoreBandFitter tighter(p, kerf_test::symmetric_widths(p.size(), tol * (1 - 1e-6)));
  EXPECT_GT(tighter.count().value(), 5u);
}

TEST(BandReference, ReportedErrorsMatchTheCheckersDeviation) {
  const auto p = load("parabola.txt");
  CoreBandFitter core(p, kerf_test::symmetric_widths(p.size(), 0.0183));
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok());
  for (std::uint32_t k = 0; k < fit.value().pieces; ++k) {
    const double mine = core.piece(k).error;
    const double ref = kerf_test::band_piece_deviation(p, core.pieces(fit.value().pieces)[k]);
    EXPECT_NEAR(mine, ref, 1e-9 * 500) << "piece " << k;
    EXPECT_LE(mine, 0.0183);
  }
}

// The one-sided case: with no width on the left, no point of any
// piece lies left of the path (the band function is > 0 there).
TEST(BandAsymmetric, RightOnlyBandKeepsEveryArcOnTheRight) {
  for (const char* name : {"parabola.txt", "sine.txt", "ellipse.txt"}) {
    SCOPED_TRACE(name);
    const auto p = load(name);
    checked_fit(p, kerf_test::asymmetric_widths(p.size(), 0.0, 0.05));
    checked_fit(p, kerf_test::asymmetric_widths(p.size(), 0.05, 0.0));
    checked_fit(p, kerf_test::asymmetric_widths(p.size(), 0.01, 0.05));
  }
}

TEST(BandPerVertex, TaperedWidthsPassTheChecker) {
  kerf_test::Rng rng(7);
  const auto p = load("sine.txt");
  std::vector<double> t;
  for (std::size_t k = 0; k < p.size(); ++k) t.push_back(rng.uniform(0.005, 0.05));
  checked_fit(p, kerf_test::per_vertex_widths(t));
}

TEST(BandDegenerate, CollinearRunIsOneLine) {
  std::vector<VPoint> p;
  for (int k = 0; k < 20; ++k) p.push_back({0.5 * k, 0.25 * k});
  CoreBandFitter core(p, kerf_test::symmetric_widths(p.size(), 1e-6));
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(fit.value().pieces, 1u);
  EXPECT_FALSE(core.piece(0).segment.is_arc());
}

TEST(BandDegenerate, CuspForcesABreakAndStaysInTheBand) {
  // Out along the x axis and straight back, slightly above.
  const std::vector<VPoint> p{{0, 0}, {1, 0}, {2, 0}, {1, 1e-3}, {0, 2e-3}};
  const auto w = kerf_test::symmetric_widths(p.size(), 0.05);
  CoreBandFitter core(p, w);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok());
  ASSERT_EQ(fit.value().pieces, 2u);
  EXPECT_EQ(core.piece(0).last, 2u);  // no piece runs through the turn-back
  checked_fit(p, w);
}

TEST(BandDegenerate, NearZeroEdgesGiveAValidFit) {
  std::vector<VPoint> p;
  kerf_test::Rng rng(3);
  for (int k = 0; k < 30; ++k) {
    p.push_back({0.3 * k, std::sin(0.3 * k)});
    p.push_back({0.3 * k + 1e-9 * rng.uniform(1, 2), std::sin(0.3 * k) + 1e-9});
  }
  checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.01));
}

TEST(BandDegenerate, ClosedPolylineTakesTwoArcs) {
  std::vector<VPoint> p;
  for (int k = 0; k <= 72; ++k) p.push_back({50 * std::cos(2 * kPi * k / 72), 50 * std::sin(2 * kPi * k / 72)});
  p.back() = p.front();  // exactly closed
  EXPECT_EQ(checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.1)), 2u);
}

TEST(BandDegenerate, ZigZagAtTheToleranceScale) {
  // +-a about the x axis, ends on it: one line when the band is a little
  // wider than a, several when it is narrower.
  const double a = 0.01;
  std::vector<VPoint> p{{0, 0}};
  for (int k = 1; k < 39; ++k) p.push_back({0.2 * k, (k % 2 ? a : -a)});
  p.push_back({7.8, 0});
  EXPECT_EQ(checked_fit(p, kerf_test::symmetric_widths(p.size(), 1.05 * a)), 1u);
  EXPECT_GT(checked_fit(p, kerf_test::symmetric_widths(p.size(), 0.5 * a)), 1u);
}

TEST(BandBadInput, IsRefusedWithAStatus) {
  using kerf::Status;
  const std::vector<VPoint> p{{0, 0}, {1, 1}, {2, 0}};
  auto count = [](const std::vector<VPoint>& pts, BandWidths w) { return CoreBandFitter(pts, w).count().status(); };
  EXPECT_EQ(count(p, kerf_test::symmetric_widths(3, 0.0)), Status::invalid_argument);
  EXPECT_EQ(count(p, kerf_test::symmetric_widths(3, -1.0)), Status::invalid_argument);
  EXPECT_EQ(count(p, kerf_test::symmetric_widths(3, std::nan(""))), Status::invalid_argument);
  EXPECT_EQ(count(p, kerf_test::symmetric_widths(3, HUGE_VAL)), Status::invalid_argument);
  EXPECT_EQ(count(p, kerf_test::asymmetric_widths(3, 0.0, 0.0)), Status::invalid_argument);
  EXPECT_EQ(count({{0, 0}}, kerf_test::symmetric_widths(1, 0.1)), Status::invalid_argument);
  EXPECT_EQ(count({{0, 0}, {0, 0}, {1, 0}}, kerf_test::symmetric_widths(3, 0.1)), Status::degenerate);
  EXPECT_EQ(count({{0, 0}, {std::nan(""), 0}}, kerf_test::symmetric_widths(2, 0.1)),
            Status::invalid_argument);
  CoreBandFitter ok(p, kerf_test::symmetric_widths(3, 0.1));
  EXPECT_EQ(ok.budget(0).status(), Status::invalid_argument);
}

}  // namespace
