// The exact valid-joint sets of fit/biarc/joints.hpp, the proven reach
// bound of fit/biarc/reach.hpp and the certified deviation of
// fit/biarc/deviation.hpp:
//  - the joint set agrees with the full single-joint test (BiarcCheck) on a
//    dense scan of J, on random pairs of random paths;
//  - a deliberately narrow valid interval, between all the joints the old
//    sampler tried, is found;
//  - the degenerate cases (J a line, one circle with both tangents, a joint
//    at an end point);
//  - the reach bound never rules out a pair with a valid joint, and the
//    default fit (with it) gives the every-pair count;
//  - the certified error is never below a dense sampling of the distance to
//    the polyline, and within the band.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "bridge/biarc_bridge.hpp"
#include "kerf/fit/biarc/deviation.hpp"
#include "kerf/fit/biarc/joints.hpp"
#include "kerf/fit/biarc/reach.hpp"
#include "kerf/fit/biarc/tangent.hpp"
#include "rng.hpp"

namespace {

using kerf::Vec2;
namespace fit = kerf::fit;
using kerf_test::CoreBiarcFitter;
using kerf_test::VPoint;

constexpr double kPi = 3.14159265358979323846;

// A region R over the points, tangents given or estimated.
struct Problem {
  std::vector<Vec2<double>> pts;
  std::vector<Vec2<double>> tan;
  std::vector<fit::BandWidth<double>> widths;
  std::vector<fit::BandVertex<double>> vertices;
  fit::BandRegion<double> region;

  Problem(std::vector<Vec2<double>> p, double tol, std::vector<Vec2<double>> t = {})
      : pts(std::move(p)), tan(std::move(t)), widths(pts.size(), {tol, tol}),
        vertices(pts.size()) {
    if (tan.empty()) {
      tan.resize(pts.size());
      fit::estimate_tangents<double>({pts.data(), pts.size()}, {tan.data(), tan.size()});
    }
    region = fit::BandRegion<double>(pts.data(), static_cast<std::uint32_t>(pts.size()),
                                     vertices.data());
    EXPECT_EQ(region.build(widths.data(), 1.0), kerf::Status::ok);
  }
  fit::BiarcJoints<double> joints(std::uint32_t i, std::uint32_t j) const {
    return fit::BiarcJoints<double>(region, i, j, tan[i], tan[j]);
  }
};

std::vector<Vec2<double>> random_path(kerf_test::Rng& rng, int n) {
  std::vector<Vec2<double>> p;
  double x = 0, y = 0, heading = rng.uniform(-1, 1);
  for (int k = 0; k < n; ++k) {
    p.push_back({x, y});
    heading += rng.uniform(-0.5, 0.5);
    const double step = rng.uniform(0.5, 1.5);
    x += step * std::cos(heading);
    y += step * std::sin(heading);
  }
  return p;
}

template <class Set>
bool in_set(const Set& set, double s, double margin) {
  for (int q = 0; q < set.size(); ++q)
    if (s > set[q].lo + margin && s < set[q].hi - margin) return true;
  return false;
}
template <class Set>
bool near_set(const Set& set, double s, double margin) {
  for (int q = 0; q < set.size(); ++q)
    if (s > set[q].lo - margin && s < set[q].hi + margin) return true;
  return false;
}
double measure(const fit::JointSet<double>& set) {
  double m = 0;
  for (int q = 0; q < set.size(); ++q) m += set[q].hi - set[q].lo;
  return m;
}

// --- the joint sets -------------------------------------------------------------

TEST(BiarcJointSet, AgreesWithTheSingleJointTestOnADenseScan) {
  kerf_test::Rng rng(31);
  int pairs = 0, valid_pairs = 0, inside = 0, outside = 0;
  for (int trial = 0; trial < 25; ++trial) {
    const Problem pr(random_path(rng, rng.integer(4, 9)), rng.uniform(0.05, 0.4));
    const auto n = static_cast<std::uint32_t>(pr.pts.size());
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const auto bj = pr.joints(i, j);
        fit::JointSet<double> set;
        ASSERT_TRUE(bj.compute(set));
        ++pairs;
        if (!set.empty()) ++valid_pairs;
        constexpr int kScan = 4000;
        for (int q = 1; q < kScan; ++q) {
          const double s = 2.0 * q / kScan;
          fit::Biarc<double> b;
          const bool ok = bj.circle().biarc(s, b) && bj.check().valid(b);
          // Away from the set's ends (a touch of the boundary), the set says
          // exactly which joints are valid.
          if (in_set(set, s, 1e-9)) {
            EXPECT_TRUE(ok) << "trial " << trial << " pair " << i << "," << j << " s " << s;
            ++inside;
          } else if (!near_set(set, s, 1e-9)) {
            EXPECT_FALSE(ok) << "trial " << trial << " pair " << i << "," << j << " s " << s;
            ++outside;
          }
        }
      }
    }
  }
  EXPECT_GT(valid_pairs, 20);
  EXPECT_LT(valid_pairs, pairs);
  EXPECT_GT(inside, 10000);
  EXPECT_GT(outside, 10000);
}

// A wide band on a sine: the set fragments past its capacity while the
// segments are removed, and compute() falls back to windows of J. The
// result still agrees with the single-joint test.
TEST(BiarcJointSet, WindowsWhenTheSetFragmentsAgreeToo) {
  std::vector<Vec2<double>> p;
  for (int k = 0; k < 120; ++k) p.push_back({0.5 * k, 50 * std::sin(2 * kPi * 0.5 * k / 200)});
  const Problem pr(p, 1.0);
  int windowed = 0, checked = 0;
  for (std::uint32_t i = 0; i < 120; i += 5) {
    for (std::uint32_t j = i + 1; j < 120; j += 3) {
      // Room for 16 intervals only, so that the windows are needed.
      const fit::BiarcJoints<double, 16> bj(pr.region, i, j, pr.tan[i], pr.tan[j]);
      fit::JointSet<double, 16> set;
      ASSERT_TRUE(bj.compute(set));
      if (bj.windows() == 0) continue;
      ++windowed;
      for (int q = 1; q < 2000; ++q) {
        const double s = 2.0 * q / 2000;
        fit::Biarc<double> b;
        const bool ok = bj.circle().biarc(s, b) && bj.check().valid(b);
        if (in_set(set, s, 1e-9)) {
          EXPECT_TRUE(ok) << i << "," << j << " s " << s;
        } else if (!near_set(set, s, 1e-9)) {
          EXPECT_FALSE(ok) << i << "," << j << " s " << s;
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(windowed, 0);
  EXPECT_GT(checked, 0);
}

// Points on an exact biarc (two arcs with a common tangent at a known joint),
// with their exact tangents, in a tight band: the valid joints are a narrow
// interval of J around the true joint. It is narrower than the spacing of
// the 64 joints the old fitter sampled on J (s = (q + 1/2) / 32), and none
// of them lies in it; the exact set still has it, and the fit is 1 biarc.
// (The old fitter, main at da828cb, also missed it in its finer search
// near the closest samples and returned 2 biarcs, points 0..15..400.)
TEST(BiarcJointSet, FindsAValidIntervalNarrowerThanAnySampling) {
  // First arc: radius 4 about (0, 4), from (0, 0) anticlockwise through 80
  // degrees; second: radius 1, turning clockwise through 120 degrees.
  std::vector<Vec2<double>> p, t;
  const double a1 = 80.0 * kPi / 180;
  for (int k = 0; k <= 200; ++k) {
    const double a = a1 * k / 200;
    p.push_back({4 * std::sin(a), 4 - 4 * std::cos(a)});
    t.push_back({std::cos(a), std::sin(a)});
  }
  const Vec2<double> joint = p.back();
  const Vec2<double> tj = t.back();
  const Vec2<double> c2 = joint - tj.perp() * 1.0;  // centre of the clockwise arc
  for (int k = 1; k <= 200; ++k) {
    const double a = 120.0 * kPi / 180 * k / 200;  // turned so far, clockwise
    const Vec2<double> r0 = (joint - c2);
    const Vec2<double> r{r0.x * std::cos(a) + r0.y * std::sin(a), -r0.x * std::sin(a) + r0.y * std::cos(a)};
    p.push_back(c2 + r);
    t.push_back({tj.x * std::cos(a) + tj.y * std::sin(a), -tj.x * std::sin(a) + tj.y * std::cos(a)});
  }
  const double tol = 1e-4;  // the chords' sagitta is below 2.5e-5
  const Problem pr(p, tol, t);
  const auto n = static_cast<std::uint32_t>(p.size());
  const auto bj = pr.joints(0, n - 1);
  fit::JointSet<double> set;
  ASSERT_TRUE(bj.compute(set));
  ASSERT_FALSE(set.empty());
  const double width = measure(set);
  EXPECT_LT(width, 2.0 / 64) << "narrower than the old samples' spacing";
  for (int q = 0; q < 64; ++q) EXPECT_FALSE(in_set(set, 2.0 * (q + 0.5) / 64, 0)) << q;
  // The true joint lies in the set.
  bool has_joint = false;
  for (int q = 0; q < set.size(); ++q) {
    fit::Biarc<double> b;
    const double mid = (set[q].lo + set[q].hi) / 2;
    ASSERT_TRUE(bj.circle().biarc(mid, b));
    if ((b.first.b - joint).norm() < 50 * tol) has_joint = true;
  }
  EXPECT_TRUE(has_joint);

  std::vector<VPoint> vp, vt;
  for (const auto& q : p) vp.push_back({q.x, q.y});
  for (const auto& q : t) vt.push_back({q.x, q.y});
  CoreBiarcFitter core(vp, vt, tol);
  const auto f = core.fit();
  ASSERT_TRUE(f.ok()) << kerf::to_string(f.status());
  EXPECT_EQ(f.value().pieces, 1u);
  EXPECT_LE(f.value().max_error, tol);
}

TEST(BiarcJointSet, JointCircleALine) {
  // An S of two quarter circles with equal end tangents: J is the line
  // through both ends, and its point at infinity splits the set's domain.
  std::vector<Vec2<double>> p, t;
  for (int k = 0; k <= 20; ++k) {
    const double a = kPi / 2 * k / 20;
    p.push_back({5 * std::sin(a), 5 - 5 * std::cos(a)});
    t.push_back({std::cos(a), std::sin(a)});
  }
  for (int k = 1; k <= 20; ++k) {
    const double a = kPi / 2 * (1 - k / 20.0);
    p.push_back({10 - 5 * std::sin(a), 5 + 5 * std::cos(a)});
    t.push_back({std::cos(a), std::sin(a)});
  }
  t.front() = t.back() = {1, 0};
  const Problem pr(p, 0.02, t);
  const auto bj = pr.joints(0, static_cast<std::uint32_t>(p.size() - 1));
  ASSERT_TRUE(bj.circle().line());
  fit::JointSet<double> set;
  ASSERT_TRUE(bj.compute(set));
  ASSERT_FALSE(set.empty());
  // The valid joints sit about the inflection (5, 5), half way: s near 0.5.
  for (int q = 0; q < set.size(); ++q) {
    EXPECT_GT(set[q].lo, 0.4);
    EXPECT_LT(set[q].hi, 0.6);
  }
  double s{};
  fit::Biarc<double> b;
  ASSERT_TRUE(bj.verified(set, s, b));
  EXPECT_NEAR(b.first.b.x, 5.0, 0.3);
  EXPECT_NEAR(b.first.b.y, 5.0, 0.3);
}

TEST(BiarcJointSet, OneCircleWithBothTangentsValidAlongTheWholeArc) {
  // Points on a circle with its tangents: J is that circle, and every joint
  // on the arc p_0 -> p_last splits the same arc, which is valid; joints on
  // the other side would pass p_last first, so none of them is.
  std::vector<Vec2<double>> p, t;
  for (int k = 0; k <= 40; ++k) {
    const double a = 1.5 * k / 40;
    p.push_back({3 * std::cos(a), 3 * std::sin(a)});
    t.push_back({-std::sin(a), std::cos(a)});
  }
  const Problem pr(p, 0.01, t);
  const auto bj = pr.joints(0, 40);
  fit::JointSet<double> set;
  ASSERT_TRUE(bj.compute(set));
  ASSERT_EQ(set.size(), 1);
  const bool first_side = set[0].hi <= 1.0;
  // Nearly the whole side: only joints within rounding of the ends are out.
  EXPECT_GT(measure(set), 0.99);
  EXPECT_TRUE(first_side ? set[0].hi <= 1.0 : set[0].lo >= 1.0);
  fit::Biarc<double> b;
  for (double f : {0.01, 0.5, 0.99}) {
    const double s = set[0].lo + f * (set[0].hi - set[0].lo);
    ASSERT_TRUE(bj.circle().biarc(s, b));
    EXPECT_NEAR(b.first.curvature(), 1.0 / 3, 1e-9);
    EXPECT_NEAR(b.second.curvature(), 1.0 / 3, 1e-9);
  }
}

TEST(BiarcJointSet, AJointAtAnEndPointIsNeverInTheSet) {
  // Generic tangents: a joint at p_i or p_j leaves a corner, so the set is
  // open at s = 0, 1 and 2; the biarcs near them are tested like any other.
  kerf_test::Rng rng(5);
  int checked = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Problem pr(random_path(rng, 6), 0.3);
    for (std::uint32_t j = 1; j < 6; ++j) {
      const auto bj = pr.joints(0, j);
      fit::JointSet<double> set;
      ASSERT_TRUE(bj.compute(set));
      for (double s : {0.0, 1.0, 2.0}) EXPECT_FALSE(in_set(set, s, 0)) << s;
      for (int q = 0; q < set.size(); ++q) {
        EXPECT_GE(set[q].lo, 0.0);
        EXPECT_LE(set[q].hi, 2.0);
        EXPECT_FALSE(set[q].lo < 1.0 && set[q].hi > 1.0);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

// --- the reach bound ---------------------------------------------------------------

TEST(BiarcReach, NeverRulesOutAValidPair) {
  kerf_test::Rng rng(77);
  int valid = 0, ruled_out = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec2<double>> p;
    const double f = rng.uniform(0.3, 1.5);
    for (int k = 0; k < 40; ++k) p.push_back({0.15 * k, std::sin(f * 0.15 * k)});
    const Problem pr(p, rng.uniform(0.005, 0.1));
    const auto n = static_cast<std::uint32_t>(p.size());
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      const std::uint32_t fwd = fit::forward_reach(pr.region, i, pr.tan[i], n - 1);
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const std::uint32_t back = fit::backward_reach(pr.region, j, pr.tan[j]);
        fit::JointSet<double> set;
        const auto bj = pr.joints(i, j);
        ASSERT_TRUE(bj.compute(set));
        double s{};
        fit::Biarc<double> b;
        const bool ok = bj.verified(set, s, b);
        if (ok) {
          ++valid;
          EXPECT_LE(back, fwd + 1) << "trial " << trial << " pair " << i << "," << j;
        }
        if (back > fwd + 1) ++ruled_out;
      }
    }
  }
  EXPECT_GT(valid, 500);
  EXPECT_GT(ruled_out, 2000);  // the bound does prune
}

TEST(BiarcReach, DefaultFitGivesTheEveryPairCount) {
  kerf_test::Rng rng(91);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<VPoint> p;
    const double f = rng.uniform(0.3, 2.0);
    for (int k = 0; k < 80; ++k) p.push_back({0.1 * k, 0.7 * std::sin(f * 0.1 * k)});
    CoreBiarcFitter core(p, {}, rng.uniform(0.002, 0.05));
    const auto fast = core.fit();
    const auto every = core.fit({16, true});
    ASSERT_TRUE(fast.ok());
    ASSERT_TRUE(every.ok());
    EXPECT_EQ(fast.value().pieces, every.value().pieces) << trial;
  }
}

// --- the certified error ------------------------------------------------------------

// The point a fraction u of the way along a segment (by angle for an arc).
Vec2<double> point_on(const kerf::Segment<double>& seg, double u) {
  if (!seg.is_arc()) return seg.start + (seg.end - seg.start) * u;
  const Vec2<double> a = seg.start - seg.centre, b = seg.end - seg.centre;
  double sweep = std::atan2(a.cross(b), a.dot(b));  // (-pi, pi]
  if (seg.dir > 0 && sweep < 0) sweep += 2 * kPi;
  if (seg.dir < 0 && sweep > 0) sweep -= 2 * kPi;
  const double ang = u * sweep;
  return seg.centre + Vec2<double>{a.x * std::cos(ang) - a.y * std::sin(ang),
                                   a.x * std::sin(ang) + a.y * std::cos(ang)};
}

double sampled_deviation(const std::vector<VPoint>& p, const fit::BiarcPiece<double>& pc) {
  double worst = 0;
  for (const auto& seg : pc.arc) {
    for (int q = 0; q <= 2000; ++q) {
      const Vec2<double> x = point_on(seg, q / 2000.0);
      double best = 1e300;
      for (std::size_t k = pc.first; k < pc.last; ++k) {
        const Vec2<double> a{p[k].x, p[k].y}, c{p[k + 1].x, p[k + 1].y};
        best = std::min(best, kerf::distance_to_line_segment(a, c, x));
      }
      worst = std::max(worst, best);
    }
  }
  return worst;
}

TEST(BiarcCertifiedError, BoundsTheSampledDeviationAndStaysInTheBand) {
  kerf_test::Rng rng(13);
  int pieces = 0;
  for (int trial = 0; trial < 16; ++trial) {
    std::vector<VPoint> p;
    if (trial % 2 == 0) {
      const double f = rng.uniform(0.5, 2.0);
      for (int k = 0; k < 60; ++k) p.push_back({0.1 * k, std::sin(f * 0.1 * k)});
    } else {
      for (const auto& q : random_path(rng, 12)) p.push_back({q.x, q.y});
    }
    const double tol = trial % 2 == 0 ? rng.uniform(0.002, 0.03) : rng.uniform(0.05, 0.3);
    CoreBiarcFitter core(p, {}, tol);
    const auto f = core.fit();
    ASSERT_TRUE(f.ok()) << trial;
    double worst = 0;
    for (std::uint32_t k = 0; k < f.value().pieces; ++k) {
      const auto& pc = core.piece(k);
      const double sampled = sampled_deviation(p, pc);
      EXPECT_GE(pc.error, sampled * (1 - 1e-12)) << "trial " << trial << " piece " << k;
      // Tight on these curves: the bound is the distance to the cell's edge.
      EXPECT_LE(pc.error, sampled + 0.02 * tol) << "trial " << trial << " piece " << k;
      worst = std::max(worst, pc.error);
      ++pieces;
    }
    EXPECT_EQ(f.value().max_error, worst);
    EXPECT_LE(f.value().max_error, tol * (1 + 1e-9)) << trial;
  }
  EXPECT_GT(pieces, 40);
}

TEST(BiarcCertifiedError, StraightPartsAreCertifiedToo) {
  // Collinear points: two lines on the polyline, error 0 (to rounding); a
  // bent line with a long straight run: within the band.
  std::vector<VPoint> p;
  for (int k = 0; k < 50; ++k) p.push_back({0.3 * k, 0.1 * k});
  CoreBiarcFitter line(p, {}, 0.01);
  const auto f = line.fit();
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.value().pieces, 1u);
  EXPECT_LE(f.value().max_error, 1e-9);
  for (int k = 1; k < 30; ++k) p.push_back({p[49].x + 0.2 * k, p[49].y + 0.01 * k * k});
  CoreBiarcFitter bent(p, {}, 0.02);
  const auto g = bent.fit();
  ASSERT_TRUE(g.ok());
  for (std::uint32_t k = 0; k < g.value().pieces; ++k)
    EXPECT_GE(bent.piece(k).error, sampled_deviation(p, bent.piece(k)) * (1 - 1e-12)) << k;
  EXPECT_LE(g.value().max_error, 0.02 * (1 + 1e-9));
}

TEST(BiarcCertifiedError, ArcPastAHalfTurnIsBoundedByItsOwnCells) {
  // 100 points on 350 degrees of a circle of radius 100 at tol 0.05: one
  // biarc whose first arc turns about 349 degrees. Each gate's line (a
  // radius) meets that arc a second time across the circle; taking that
  // crossing as a cell boundary bounded a stretch by a far edge and reported
  // the diameter (199.9). The true deviation is the chords' sagitta, 0.0466.
  std::vector<VPoint> p;
  for (int k = 0; k < 100; ++k) {
    const double a = k * (350.0 / 99.0) * kPi / 180.0;
    p.push_back({100 * std::cos(a), 100 * std::sin(a)});
  }
  CoreBiarcFitter core(p, {}, 0.05);
  const auto f = core.fit();
  ASSERT_TRUE(f.ok());
  ASSERT_EQ(f.value().pieces, 1u);
  const double sampled = sampled_deviation(p, core.piece(0));
  EXPECT_GE(core.piece(0).error, sampled * (1 - 1e-12));
  EXPECT_LE(core.piece(0).error, sampled + 0.02 * 0.05);
  EXPECT_LE(f.value().max_error, 0.05);
}

}  // namespace

