// One suite, two scalar types: geometry, the vertex fitter and the
// interpolator run in double and in kerf::Fixed. The fixed-point fitter must
// find the same piece counts as double on every test curve, and its pieces
// must verify in double within tol plus the fixed-point quantization.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kerf/geom/circle.hpp"
#include "kerf/geom/segment.hpp"
#include "job/check_fit.hpp"
#include "kerf/motion/interpolator.hpp"
#include "typed_core_helpers.hpp"

namespace {

using kerf::Fixed;
using kerf::Status;
using kerf::fit::Method;
using kerf::test::from_d;
using kerf::test::to_d;
using VD = kerf::Vec2<double>;

template <class S>
class TypedCore : public ::testing::Test {};
using Scalars = ::testing::Types<double, Fixed>;
TYPED_TEST_SUITE(TypedCore, Scalars);

// How far a scalar type may stray from the exact figure at magnitude m:
// double's rounding, or the fixed type's steps (documented in fixed.hpp).
template <class S>
double slack(double m) {
  if constexpr (__is_same(S, Fixed)) return 64 * kerf::fixed_quantum * std::max(1.0, m);
  else return 1e-12 * std::max(1.0, m);
}

TYPED_TEST(TypedCore, CircleThroughThreePoints) {
  using S = TypeParam;
  const VD c{3.0, -2.0};
  const double r = 7.5;
  auto at = [&](double a) { return from_d<S>(VD{c.x + r * std::cos(a), c.y + r * std::sin(a)}); };
  const auto res = kerf::circle_through(at(0.1), at(1.7), at(4.0));
  ASSERT_TRUE(res.ok());
  EXPECT_NEAR(to_d(res.value().centre.x), c.x, slack<S>(100));
  EXPECT_NEAR(to_d(res.value().centre.y), c.y, slack<S>(100));
  EXPECT_NEAR(to_d(res.value().radius), r, slack<S>(100));
  const auto flat = kerf::circle_through(from_d<S>(VD{0, 0}), from_d<S>(VD{1, 1}), from_d<S>(VD{2, 2}));
  EXPECT_EQ(flat.status(), Status::collinear);
}

TYPED_TEST(TypedCore, DistancesToLinesArcsAndCircles) {
  using S = TypeParam;
  const auto a = from_d<S>(VD{0, 0}), b = from_d<S>(VD{10, 0}), p = from_d<S>(VD{4, 3});
  EXPECT_NEAR(to_d(kerf::distance_to_line_segment(a, b, p)), 3.0, slack<S>(10));
  EXPECT_NEAR(to_d(kerf::distance_to_line_segment(a, b, from_d<S>(VD{13, 4}))), 5.0, slack<S>(10));
  const auto centre = from_d<S>(VD{100, 100});
  const auto on = from_d<S>(VD{200, 100});
  EXPECT_NEAR(to_d(kerf::distance_to_circle(centre, on, from_d<S>(VD{100, 250}))), 50.0,
              slack<S>(1e4));
  const auto arc = kerf::Segment<S>::arc(on, from_d<S>(VD{100, 200}), centre, 1);
  EXPECT_NEAR(to_d(kerf::distance_to_segment(arc, from_d<S>(VD{100 + 60, 100 + 80}))), 0.0,
              slack<S>(1e4));
  // the opposite side of the circle is outside the quarter arc: nearest end
  EXPECT_NEAR(to_d(kerf::distance_to_segment(arc, from_d<S>(VD{0, 100}))), std::hypot(100.0, 100.0),
              slack<S>(1e4));
}

struct FitCase {
  const char* curve;
  double tol;
};
constexpr FitCase fit_cases[] = {
    {"parabola.txt", 0.0183}, {"parabola.txt", 0.0085}, {"parabola.txt", 0.05},
    {"parabola.txt", 0.1},    {"circle.txt", 0.01},     {"ellipse.txt", 0.05},
    {"ellipse.txt", 0.2},     {"sine.txt", 0.05},       {"spiral.txt", 0.1},
};

template <class S>
kerf::Result<kerf::fit::Fit<S>> fit_curve(const std::vector<VD>& pd, double tol, Method m,
                                          kerf::test::FitBuffers<S>& buf) {
  std::vector<kerf::Vec2<S>> p;
  for (const VD& v : pd) p.push_back(from_d<S>(v));
  return kerf::fit::fit_min_count<S>({p.data(), p.size()}, from_d<S>(tol), m, buf.ws(), buf.out());
}

// Every inner point of every piece, measured in double against the piece as
// drawn (the swept arc or the line segment).
template <class S>
double worst_excess(const std::vector<VD>& pd, const kerf::test::FitBuffers<S>& buf,
                    std::uint32_t pieces, double tol) {
  double worst = -tol;
  std::uint32_t expect_first = 0;
  for (std::uint32_t k = 0; k < pieces; ++k) {
    const auto& piece = buf.pieces[k];
    EXPECT_EQ(piece.first, expect_first);
    expect_first = piece.last;
    const kerf::Segment<double> seg = to_d(piece.segment);
    for (std::uint32_t i = piece.first; i <= piece.last; ++i)
      worst = std::max(worst, kerf::distance_to_segment(seg, pd[i]) - tol);
  }
  EXPECT_EQ(expect_first, pd.size() - 1);
  return worst;
}

template <class S>
void expect_counts_match_double(Method m, const FitCase& c) {
  const std::vector<VD> pd = kerf::test::load_curve(c.curve);
  ASSERT_GT(pd.size(), 2u) << c.curve;
  kerf::test::FitBuffers<double> ref(pd.size());
  kerf::test::FitBuffers<S> buf(pd.size());
  const auto want = fit_curve<double>(pd, c.tol, m, ref);
  const auto got = fit_curve<S>(pd, c.tol, m, buf);
  ASSERT_TRUE(want.ok() && got.ok()) << c.curve << " " << c.tol;
  EXPECT_EQ(got.value().pieces, want.value().pieces)
      << c.curve << " tol " << c.tol << " method " << static_cast<int>(m);
  double big = 0;
  for (const VD& v : pd) big = std::max({big, std::abs(v.x), std::abs(v.y)});
  EXPECT_LE(worst_excess(pd, buf, got.value().pieces, c.tol), slack<S>(big) + 1e-9 * c.tol)
      << c.curve << " tol " << c.tol << " method " << static_cast<int>(m);
}

TYPED_TEST(TypedCore, VertexFitCountsMatchDoubleAndVerifyInDouble) {
  for (const FitCase& c : fit_cases) expect_counts_match_double<TypeParam>(Method::optimal, c);
}

// The ESGI rules try every inner point of every pair: on the parabola only,
// so the suite stays quick under the sanitizers. The host runs them, the
// cross presets do not (tests/unit/CMakeLists.txt): their Fixed operations
// are the optimal fit's, above, and they cost 10 times as much.
TYPED_TEST(TypedCore, EsgiRuleCountsMatchDoubleAndVerifyInDouble) {
  for (const Method m : {Method::esgi_max, Method::esgi_mean})
    for (const FitCase& c : fit_cases)
      if (std::string(c.curve) == "parabola.txt") expect_counts_match_double<TypeParam>(m, c);
}

// An airfoil's nose: short chords (0.05 mm) at 300 mm from the trailing edge.
// Fixed once squared their terms at its absolute resolution, accepted pieces
// that missed points by 7 tol and failed the fit's own check (issue 25).
TYPED_TEST(TypedCore, AirfoilVertexCountsMatchDoubleAndVerifyInDouble) {
  using S = TypeParam;
  for (const char* code : {"2412", "0012"}) {
    const std::vector<VD> pd = kerf::test::naca4(code);
    ASSERT_EQ(pd.size(), 250u);
    for (const double tol : {0.05, 0.02, 0.01, 0.005}) {
      kerf::test::FitBuffers<double> ref(pd.size());
      kerf::test::FitBuffers<S> buf(pd.size());
      const auto want = fit_curve<double>(pd, tol, Method::optimal, ref);
      const auto got = fit_curve<S>(pd, tol, Method::optimal, buf);
      ASSERT_TRUE(want.ok() && got.ok()) << code << " tol " << tol;
      EXPECT_EQ(got.value().pieces, want.value().pieces) << code << " tol " << tol;
      EXPECT_LE(worst_excess(pd, buf, got.value().pieces, tol), slack<S>(512) + 1e-9 * tol)
          << code << " tol " << tol;
    }
  }
}

// Points near a piece's circle but on its other arc, from
// tests/data/gcode/cncjs_tball-pocket.gcode (issue 25). The zigzag: the
// circle through its ends passes within tol of the two inner points, on the
// arc the piece does not run. The hook: a long step, then a short one back
// past the end; only the major arc through all three has them in its sweep,
// and its first step skips 343 degrees round: two pieces. The vertex fit
// measured to the circle and failed kerf's own check on both.
TYPED_TEST(TypedCore, VertexFitMeasuresToTheArcNotToItsCircle) {
  using S = TypeParam;
  struct ArcCase {
    const char* name;
    std::vector<VD> pts;
    std::uint32_t pieces;
  };
  const ArcCase cases[] = {
      {"zigzag", {{79.5450, -52.2490}, {79.4614, -52.3628}, {80.4832, -53.1169}, {80.3877, -53.2457}}, 2},
      {"hook", {{116.1360, -95.0597}, {102.4685, -109.4526}, {102.7496, -109.2324}}, 2},
  };
  for (const ArcCase& c : cases) {
    for (const double tol : {0.01, 0.025, 0.05, 0.1}) {
      kerf::test::FitBuffers<S> buf(c.pts.size());
      const auto got = fit_curve<S>(c.pts, tol, Method::optimal, buf);
      ASSERT_TRUE(got.ok()) << c.name << " tol " << tol;
      EXPECT_EQ(got.value().pieces, c.pieces) << c.name << " tol " << tol;
      EXPECT_LE(worst_excess(c.pts, buf, got.value().pieces, tol), slack<S>(128) + 1e-9 * tol)
          << c.name << " tol " << tol;
      std::vector<kerf::fit::Piece<double>> pd;
      for (std::uint32_t k = 0; k < got.value().pieces; ++k) {
        const auto& pc = buf.pieces[k];
        kerf::Segment<double> seg = to_d(pc.segment);
        seg.start = c.pts[pc.first];  // exactly on the input points, as kerf fit writes them
        seg.end = c.pts[pc.last];
        pd.push_back({pc.first, pc.last, seg, to_d(pc.error)});
      }
      EXPECT_EQ(kerf::job::check_fit({c.pts.data(), c.pts.size()}, {pd.data(), pd.size()},
                                     tol + slack<S>(128)),
                "")
          << c.name << " tol " << tol;
    }
  }
}

TYPED_TEST(TypedCore, InterpolatorRunsAPathToItsEndWithinTheFeed) {
  using S = TypeParam;
  using namespace kerf::motion;
  std::vector<QueuedSegment<S>> slots(8);
  Interpolator<S> ip({slots.data(), slots.size()});
  MotionConfig<S> cfg;
  cfg.period = from_d<S>(0.001);
  cfg.accel = from_d<S>(2000.0);
  cfg.corner_angle = from_d<S>(0.05);
  cfg.counts_per_mm = {from_d<S>(1000.0), from_d<S>(1000.0)};
  ASSERT_EQ(ip.configure(cfg), Status::ok);
  const auto p0 = from_d<S>(VD{0, 0}), p1 = from_d<S>(VD{50, 0}), p2 = from_d<S>(VD{70, 20});
  const auto c = from_d<S>(VD{50, 20});
  ASSERT_EQ(ip.push({kerf::Segment<S>::line(p0, p1), from_d<S>(100.0), 1}), Status::ok);
  ASSERT_EQ(ip.push({kerf::Segment<S>::arc(p1, p2, c, 1), from_d<S>(100.0), 2}), Status::ok);
  const double length = 50.0 + 20.0 * 3.14159265358979 / 2;
  double max_speed = 0, last_s = 0;
  int steps = 0;
  for (; steps < 100000 && ip.state() != MotionState::done; ++steps) {
    const auto sp = ip.step();
    max_speed = std::max(max_speed, to_d(sp.speed));
    EXPECT_GE(to_d(sp.s), last_s - slack<S>(100));  // never backwards
    last_s = to_d(sp.s);
    // on the path: the line y = 0, or the circle of radius 20 around c
    const VD at = to_d(sp.position);
    const double off = at.x <= 50.0 ? std::abs(at.y) : std::abs(std::hypot(at.x - 50, at.y - 20) - 20);
    EXPECT_LT(off, 1e-6) << steps;
  }
  EXPECT_EQ(ip.state(), MotionState::done);
  EXPECT_LT(steps, 2000);  // ~0.81 s at 100 mm/s plus the ramps
  EXPECT_NEAR(last_s, length, 1e-6);
  EXPECT_LE(max_speed, 100.0 + 1e-6);
  EXPECT_GT(max_speed, 99.0);
  EXPECT_NEAR(to_d(ip.last_setpoint().position.x), 70.0, 1e-6);
  EXPECT_NEAR(to_d(ip.last_setpoint().position.y), 20.0, 1e-6);
  EXPECT_EQ(ip.last_setpoint().counts.x, 70000);
  EXPECT_EQ(ip.last_setpoint().counts.y, 20000);
}

}  // namespace
