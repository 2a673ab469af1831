// The biarc fitter (Drysdale, Rote, Sturm, section 3): tangent estimation,
// the joint circle and its degenerate cases, fits checked by the independent
// biarc checker (tests/support/biarc_checker.hpp: tangent continuity, the
// certified band, the gate rules), and the brute-force twin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "biarc_checker.hpp"
#include "biarc_twin.hpp"
#include "bridge/biarc_bridge.hpp"
#include "kerf/fit/biarc/arc.hpp"
#include "kerf/fit/biarc/tangent.hpp"
#include "rng.hpp"

namespace {

using kerf::Vec2;
using kerf_test::CoreBiarcFitter;
using kerf_test::VBiarc;
using kerf_test::VPoint;

constexpr double kPi = 3.14159265358979323846;

double slack_for(const std::vector<VPoint>& p) { return 1e-9 * kerf_test::scale_of(p) + 1e-12; }

std::vector<VPoint> circle_points(std::size_t n, double r, double from, double to, double cx = 0,
                                  double cy = 0) {
  std::vector<VPoint> p;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = from + (to - from) * static_cast<double>(k) / static_cast<double>(n - 1);
    p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return p;
}

// Fits, checks with the referee, returns the count (0 on failure).
std::uint32_t checked_fit(const std::vector<VPoint>& p, const std::vector<VPoint>& tangents,
                          double tol, std::vector<VBiarc>* out = nullptr) {
  CoreBiarcFitter core(p, tangents, tol);
  const auto fit = core.fit();
  // The reach bound (fit/biarc/reach.hpp) skips only pairs it proves
  // invalid: testing every pair gives the same count.
  const auto exact = core.fit({16, true});
  EXPECT_TRUE(exact.ok());
  if (exact.ok() && fit.ok()) {
    EXPECT_EQ(exact.value().pieces, fit.value().pieces);
  }
  EXPECT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  if (!fit.ok()) return 0;
  const auto biarcs = core.biarcs(fit.value().pieces);
  const auto rep = kerf_test::check_biarc_fit(p, core.tangents(),
                                              kerf_test::symmetric_widths(p.size(), tol), biarcs,
                                              slack_for(p));
  EXPECT_TRUE(rep.ok) << rep.why;
  if (out != nullptr) *out = biarcs;
  return fit.value().pieces;
}

double angle_of(Vec2<double> a, Vec2<double> b) {
  return std::atan2(std::abs(a.cross(b)), a.dot(b));
}

// --- tangents ---------------------------------------------------------------

TEST(BiarcTangents, ExactOnSampledCirclesAtAnySpacing) {
  kerf_test::Rng rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const double r = rng.uniform(0.1, 1000);
    const double cx = rng.uniform(-100, 100), cy = rng.uniform(-100, 100);
    std::vector<double> angles{rng.uniform(0, 2 * kPi)};
    const int n = rng.integer(3, 40);
    for (int k = 1; k < n; ++k) angles.push_back(angles.back() + rng.uniform(0.01, 0.3));
    std::vector<Vec2<double>> pts, t(static_cast<std::size_t>(n));
    for (double a : angles) pts.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    kerf::fit::estimate_tangents<double>({pts.data(), pts.size()}, {t.data(), t.size()});
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const Vec2<double> exact{-std::sin(angles[k]), std::cos(angles[k])};
      EXPECT_LT(angle_of(t[k], exact), 1e-10 * (1 + r / 100)) << "trial " << trial << " k " << k;
      EXPECT_GT(t[k].dot(exact), 0.0);
    }
  }
}

TEST(BiarcTangents, SecondOrderOnASmoothCurve) {
  // y = sin(x): halving the spacing divides the largest error by about 4.
  auto worst = [](double h) {
    std::vector<Vec2<double>> pts;
    for (double x = 0; x <= 3.0 + 1e-12; x += h) pts.push_back({x, std::sin(x)});
    std::vector<Vec2<double>> t(pts.size());
    kerf::fit::estimate_tangents<double>({pts.data(), pts.size()}, {t.data(), t.size()});
    double w = 0;
    for (std::size_t k = 1; k + 1 < pts.size(); ++k)
      w = std::max(w, angle_of(t[k], kerf::fit::unit_of(Vec2<double>{1, std::cos(pts[k].x)})));
    return w;
  };
  const double e1 = worst(0.1), e2 = worst(0.05);
  EXPECT_LT(e1, 2e-3);
  EXPECT_GT(e1 / e2, 3.5);
  EXPECT_LT(e1 / e2, 4.5);
}

TEST(BiarcTangents, CollinearPointsGiveTheLine) {
  std::vector<Vec2<double>> pts{{0, 0}, {1, 1}, {3, 3}, {3.5, 3.5}};
  std::vector<Vec2<double>> t(4);
  kerf::fit::estimate_tangents<double>({pts.data(), 4}, {t.data(), 4});
  for (const auto& v : t) EXPECT_LT(angle_of(v, {1, 1}), 1e-15);
}

// --- the joint circle ---------------------------------------------------------

TEST(BiarcJointCircle, EveryJointGivesAG1BiarcWithBothTangents) {
  kerf_test::Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const VPoint p{rng.uniform(-5, 5), rng.uniform(-5, 5)};
    const VPoint q{rng.uniform(-5, 5), rng.uniform(-5, 5)};
    const double a1 = rng.uniform(0, 2 * kPi), a2 = rng.uniform(0, 2 * kPi);
    const Vec2<double> t1{std::cos(a1), std::sin(a1)}, t2{std::cos(a2), std::sin(a2)};
    const kerf::fit::JointCircle<double> jc({p.x, p.y}, t1, {q.x, q.y}, t2);
    const std::vector<VPoint> pts{p, q};
    const std::vector<VPoint> tan{{t1.x, t1.y}, {t2.x, t2.y}};
    for (double s = 0.05; s < 2; s += 0.1) {
      kerf::fit::Biarc<double> b;
      if (!jc.biarc(s, b)) continue;  // only a joint a rounding step from an end
      const VBiarc v{kerf_test::to_vpiece(b.first.segment(), 0, 1),
                     kerf_test::to_vpiece(b.second.segment(), 0, 1)};
      EXPECT_LT(kerf_test::angle_between(kerf_test::piece_tangent(v.a1, false), tan[0]), 1e-9);
      EXPECT_LT(kerf_test::angle_between(kerf_test::piece_tangent(v.a1, true),
                                         kerf_test::piece_tangent(v.a2, false)), 1e-9);
      EXPECT_LT(kerf_test::angle_between(kerf_test::piece_tangent(v.a2, true), tan[1]), 1e-9)
          << "trial " << trial << " s " << s;
    }
  }
}

TEST(BiarcJointCircle, EqualTangentsMakeItALine) {
  const Vec2<double> t{0.6, 0.8};
  const kerf::fit::JointCircle<double> jc({0, 0}, t, {4, 1}, t);
  EXPECT_TRUE(jc.line());
  for (double s : {0.2, 0.5, 0.9, 1.3, 1.7}) {
    const Vec2<double> m = jc.point(s);
    EXPECT_NEAR(m.cross({4, 1}), 0.0, 1e-12) << s;  // on the line through both points
    kerf::fit::Biarc<double> b;
    ASSERT_TRUE(jc.biarc(s, b));
    EXPECT_LT((b.second.end_tangent() - t).norm(), 1e-12);
  }
  // The joint half way: the S-shaped biarc is point-symmetric.
  kerf::fit::Biarc<double> b;
  ASSERT_TRUE(jc.biarc(0.5, b));
  EXPECT_NEAR(b.first.curvature(), -b.second.curvature(), 1e-12);
}

TEST(BiarcJointCircle, OneCircleWithBothTangentsIsJ) {
  // p and q on the unit circle with its tangents: J is that circle, and every
  // joint splits the same arc.
  const kerf::fit::JointCircle<double> jc({1, 0}, {0, 1}, {0, 1}, {-1, 0});
  for (double s = 0.05; s < 2; s += 0.1) {
    const Vec2<double> m = jc.point(s);
    EXPECT_NEAR(m.norm(), 1.0, 1e-12);
    kerf::fit::Biarc<double> b;
    ASSERT_TRUE(jc.biarc(s, b));
    EXPECT_NEAR(b.first.curvature(), 1.0, 1e-9);
    EXPECT_NEAR(b.second.curvature(), 1.0, 1e-9);
  }
}

TEST(BiarcJointCircle, AJointAtAnEndPointIsG1OnlyForOneMatchingArc) {
  kerf::fit::Biarc<double> b;
  // One circle has both tangents: the joint may sit on either end; the other
  // arc is then the whole quarter circle.
  const kerf::fit::JointCircle<double> one({1, 0}, {0, 1}, {0, 1}, {-1, 0});
  for (double s : {0.0, 1.0, 2.0}) {
    ASSERT_TRUE(one.biarc(s, b)) << s;
    EXPECT_TRUE(b.first.empty() || b.second.empty());
    const kerf::fit::ArcPart<double>& whole = b.first.empty() ? b.second : b.first;
    EXPECT_NEAR(whole.curvature(), 1.0, 1e-12);
  }
  // Generic tangents: a joint on an end point leaves a corner there.
  const kerf::fit::JointCircle<double> generic({0, 0}, {1, 0}, {4, 1}, {0, 1});
  for (double s : {0.0, 1.0, 2.0}) EXPECT_FALSE(generic.biarc(s, b)) << s;
  EXPECT_TRUE(generic.biarc(0.5, b));
}

TEST(BiarcJointCircle, BothTangentsAlongTheChordBackwardsGiveNoBiarc) {
  // p2 straight behind p1, both tangents pointing ahead along the line
  // through them: J is that line, and every joint leaves one part a line
  // run backwards (a circle through infinity), which no cut can follow.
  kerf::fit::Biarc<double> b;
  const kerf::fit::JointCircle<double> back({0, 68}, {0, 1}, {0, -608}, {0, 1});
  for (double s = 0.0; s <= 2.0; s += 0.0625) EXPECT_FALSE(back.biarc(s, b)) << s;
  // p2 ahead instead: a joint between them gives the straight line itself.
  const kerf::fit::JointCircle<double> ahead({0, 68}, {0, 1}, {0, 608}, {0, 1});
  for (double s = 0.0625; s < 1.0; s += 0.0625) {
    ASSERT_TRUE(ahead.biarc(s, b)) << s;
    EXPECT_FALSE(b.first.backward_line() || b.second.backward_line()) << s;
  }
}

// --- fits ---------------------------------------------------------------------

TEST(BiarcFit, SampledCircleArcIsOneBiarc) {
  // 100 points on radius 10: the chords' sagitta is 0.0023, inside both tols.
  for (double tol : {5e-3, 2e-2}) {
    const auto p = circle_points(100, 10, 0.2, 4.5);
    EXPECT_EQ(checked_fit(p, {}, tol), 1u) << tol;
  }
}

TEST(BiarcFit, NearlyClosedCircleIsOneArc) {
  // A closed polyline on a circle whose last point stops 1e-9 short of the
  // first: one circle (this one) passes both ends with both tangents, so J
  // is that circle and one biarc, the near-full circle, is valid; it never
  // reaches the start gate. (The former sampling fitter returned 2 here: the
  // pair 0 -> 100 is badly conditioned, |p_100 - p_0| = 1e-9, and its
  // samples missed.)
  auto p = circle_points(101, 5, 0, 2 * kPi);  // sagitta 0.0025
  p.pop_back();
  p.push_back({5, -1e-9});
  std::vector<VBiarc> b;
  ASSERT_EQ(checked_fit(p, {}, 5e-3, &b), 1u);
  for (const kerf_test::VPiece* a : {&b[0].a1, &b[0].a2}) {
    EXPECT_EQ(a->dir, 1);
    EXPECT_NEAR(std::hypot(a->sx - a->cx, a->sy - a->cy), 5.0, 0.01);
  }
}

TEST(BiarcFit, SCurveWithGivenTangentsIsOneBiarc) {
  // Two quarter circles of radius 5 turning opposite ways, joined with a
  // common tangent: exactly a biarc with equal end tangents (J is a line).
  std::vector<VPoint> p, t;
  for (int k = 0; k <= 40; ++k) {
    const double a = kPi / 2 * k / 40;  // first: centre (0, 5), clockwise from (0, 0)
    p.push_back({5 * std::sin(a), 5 - 5 * std::cos(a)});
    t.push_back({std::cos(a), std::sin(a)});
  }
  for (int k = 1; k <= 40; ++k) {
    const double a = kPi / 2 * (1 - k / 40.0);  // second: centre (10, 5)
    p.push_back({10 - 5 * std::sin(a), 5 + 5 * std::cos(a)});
    t.push_back({std::cos(a), std::sin(a)});
  }
  std::vector<VBiarc> b;
  ASSERT_EQ(checked_fit(p, t, 5e-3, &b), 1u);  // sagitta 0.0010
  // The joint is the inflection point (5, 5).
  EXPECT_NEAR(b[0].a1.ex, 5.0, 0.05);
  EXPECT_NEAR(b[0].a1.ey, 5.0, 0.05);
  EXPECT_EQ(b[0].a1.dir, -b[0].a2.dir);
}

TEST(BiarcFit, SineWaveWithEstimatedTangentsPassesTheChecker) {
  std::vector<VPoint> p;
  for (int k = 0; k <= 120; ++k) p.push_back({0.1 * k, std::sin(0.1 * k)});
  CoreBiarcFitter core(p, {}, 0.005);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok());
  // Two periods need a biarc per half-wave at least (each arc turns one way).
  EXPECT_GE(fit.value().pieces, 2u);
  EXPECT_LE(fit.value().max_error, 0.005 * (1 + 1e-9));
  const auto rep = kerf_test::check_biarc_fit(p, core.tangents(),
                                              kerf_test::symmetric_widths(p.size(), 0.005),
                                              core.biarcs(fit.value().pieces), slack_for(p));
  EXPECT_TRUE(rep.ok) << rep.why;
}

TEST(BiarcFit, CollinearPointsAreOneBiarcOfLines) {
  std::vector<VPoint> p;
  for (int k = 0; k < 10; ++k) p.push_back({1.0 * k, 0.5 * k});
  std::vector<VBiarc> b;
  ASSERT_EQ(checked_fit(p, {}, 0.01, &b), 1u);
  EXPECT_FALSE(b[0].a1.arc);
  EXPECT_FALSE(b[0].a2.arc);
}

TEST(BiarcFit, RefusesBadInput) {
  const auto p = circle_points(10, 1, 0, 1);
  CoreBiarcFitter zero(p, {}, 0.0);
  EXPECT_EQ(zero.fit().status(), kerf::Status::invalid_argument);
  std::vector<VPoint> t(p.size(), {2, 0});  // not unit
  CoreBiarcFitter long_tangent(p, t, 0.1);
  EXPECT_EQ(long_tangent.fit().status(), kerf::Status::invalid_argument);
}

TEST(BiarcFit, TangentsAgainstThePathAreInfeasible) {
  const auto p = circle_points(10, 1, 0, 1);
  std::vector<VPoint> t;
  for (const VPoint& q : p) t.push_back({q.y, -q.x});  // the circle's tangent, backwards
  CoreBiarcFitter core(p, t, 0.01);
  EXPECT_EQ(core.fit().status(), kerf::Status::infeasible);
}

// --- the twin -----------------------------------------------------------------

// Random smooth-ish polylines: kerf's count is never above the twin's, and
// both fits pass the checker.
TEST(BiarcTwin, KerfNeverNeedsMoreThanTheTwin) {
  kerf_test::Rng rng(2024);
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = rng.integer(4, 12);
    std::vector<VPoint> p;
    double x = 0, y = 0, heading = rng.uniform(-1, 1);
    for (int k = 0; k < n; ++k) {
      p.push_back({x, y});
      heading += rng.uniform(-0.5, 0.5);
      const double step = rng.uniform(0.5, 1.5);
      x += step * std::cos(heading);
      y += step * std::sin(heading);
    }
    const double tol = rng.uniform(0.02, 0.3);
    CoreBiarcFitter core(p, {}, tol);
    const auto fit = core.fit();  // the default: the proven reach bound skips far pairs
    const auto every = core.fit({16, true});  // every pair
    ASSERT_EQ(fit.ok(), every.ok()) << "trial " << trial;
    if (fit.ok()) {
      EXPECT_EQ(fit.value().pieces, every.value().pieces) << "trial " << trial;
    }
    const auto widths = kerf_test::symmetric_widths(p.size(), tol);
    kerf_test::CoreBandFitter band(p, widths);
    const kerf_test::BandRegion region = band.region();
    const auto tangents = core.tangents();
    const kerf_test::BiarcTwin twin{region, tangents, widths, 720};
    std::vector<VBiarc> twin_fit;
    const int want = twin.min_biarcs(&twin_fit);
    if (want > 0) {
      const auto rep = kerf_test::check_biarc_fit(p, tangents, widths, twin_fit, slack_for(p), 1e-7);
      EXPECT_TRUE(rep.ok) << "twin, trial " << trial << ": " << rep.why;
      ASSERT_TRUE(fit.ok()) << "trial " << trial << ": " << kerf::to_string(fit.status());
      EXPECT_LE(fit.value().pieces, static_cast<std::uint32_t>(want)) << "trial " << trial;
      if (fit.value().pieces > static_cast<std::uint32_t>(want)) {
        for (const VPoint& q : p) std::printf("P %.17g %.17g\n", q.x, q.y);
        std::printf("TOL %.17g\n", tol);
        for (const VBiarc& b : twin_fit) std::printf("B %zu %zu %.17g %.17g\n", b.a1.first, b.a1.last, b.a1.ex, b.a1.ey);
      }
      ++compared;
    }
    if (fit.ok()) {
      const auto rep = kerf_test::check_biarc_fit(p, tangents, widths,
                                                  core.biarcs(fit.value().pieces), slack_for(p));
      EXPECT_TRUE(rep.ok) << "kerf, trial " << trial << ": " << rep.why;
    }
  }
  EXPECT_GE(compared, 40);
}

// A path that runs up, jumps back below its start and runs up over itself
// again (the fuzzer's fit_biarc finding): p3 and p8 lie on x = 0 with both
// estimated tangents straight up, p8 behind p3. The fitter used to accept
// 3 -> 8 with a joint above p3, its second part a line run downwards with
// the tangent up: the CLI saw a corner at the joint and an end tangent
// against t_8. No G1 chain exists here (it would need two U-turns of
// radius <= 16 in one biarc), so the answer is a refusal.
TEST(BiarcFit, APathOverItselfGetsNoBackwardLine) {
  const std::vector<VPoint> p{{0, -204}, {0, -136}, {0, -68}, {0, 0},      {0, 16},    {4, 84},
                              {-4, -864}, {0, -784}, {0, -716}, {0, -648}, {0, -580}, {12, -460}};
  CoreBiarcFitter core(p, {}, 16);
  const auto fit = core.fit();
  if (fit.ok()) {
    const auto rep = kerf_test::check_biarc_fit(p, core.tangents(), kerf_test::symmetric_widths(p.size(), 16),
                                                core.biarcs(fit.value().pieces), slack_for(p));
    EXPECT_TRUE(rep.ok) << rep.why;
  }
  EXPECT_EQ(fit.status(), kerf::Status::infeasible);
}

// A path that runs up, jumps back to its first point and runs up again:
// the band of the jump covers the first run, so R (cells 0..10) runs back
// over itself. The biarc 0 -> 10 used to go straight up inside it, never
// reaching points 2..8 (392 away): R held it, but the CLI's own check saw
// a point farther than tol. Every gate between p_i and p_j must be crossed;
// no G1 chain then exists (two U-turns of radius <= 16 in one biarc).
TEST(BiarcFit, ABiarcMayNotSkipWhereThePathRunsOverItself) {
  const std::vector<VPoint> p{{0, 0},    {4, 24},  {8, 140},  {16, 188},  {20, 192}, {28, 276},
                              {24, 300}, {16, 356}, {12, 464}, {0, 0},     {-8, 72},  {-8, 168},
                              {-16, 224}, {-16, 272}, {24, 328}, {32, 420}, {28, 544}};
  CoreBiarcFitter core(p, {}, 16);
  const auto fit = core.fit();
  for (std::uint32_t k = 0; fit.ok() && k < fit.value().pieces; ++k) {
    const kerf::fit::BiarcPiece<double>& b = core.piece(k);
    for (std::uint32_t q = b.first; q <= b.last; ++q) {
      const kerf::Vec2<double> x{p[q].x, p[q].y};
      EXPECT_LE(std::fmin(kerf::distance_to_segment(b.arc[0], x), kerf::distance_to_segment(b.arc[1], x)),
                16 + slack_for(p))
          << "point " << q << " of biarc " << k;
    }
  }
  EXPECT_EQ(fit.status(), kerf::Status::infeasible);
}

// A hairpin of short edges (the fuzzer's fit_biarc finding): the path
// climbs to p2, turns round p3 (4 away) and runs back down past p2. The
// ideal gate at p2 (16 each side) reaches into the band of the return leg,
// and the biarc 2 -> 4, going down that leg, crosses it there. kerf's
// region narrows the widths at p2 until its cells are convex; its gate is
// the one the biarc may touch only at p2, and the referee checks the gate
// rules at the region's gates (the region no wider than the band).
TEST(BiarcFit, AHairpinsReturnLegMayCrossTheIdealGate) {
  const std::vector<VPoint> p{{8, 140}, {16, 188}, {20, 192}, {28, 104}, {-24, -12}};
  CoreBiarcFitter core(p, {}, 16);
  const auto fit = core.fit();
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  const auto biarcs = core.biarcs(fit.value().pieces);
  const auto widths = kerf_test::symmetric_widths(p.size(), 16);
  const kerf_test::BandWidths region = core.region_widths();
  EXPECT_LT(region.right[1], 16.0);  // narrowed at the hairpin
  const auto rep = kerf_test::check_biarc_fit(p, core.tangents(), widths, biarcs, slack_for(p), 1e-9, &region);
  EXPECT_TRUE(rep.ok) << rep.why;
  const auto ideal = kerf_test::check_biarc_fit(p, core.tangents(), widths, biarcs, slack_for(p));
  EXPECT_FALSE(ideal.ok);
  EXPECT_NE(ideal.why.find("meets gate"), std::string::npos) << ideal.why;
}

}  // namespace

