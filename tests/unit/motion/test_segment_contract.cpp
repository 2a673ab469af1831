// The contract between the fit and the board (motion/segment_contract.hpp):
// the board's acceptance at its edges, prepare_segment agreeing with it, and
// emit_on_grid giving only segments the board runs after the link's rounding,
// close to the fitted piece.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kerf/core/fixed.hpp"
#include "kerf/motion/path_geometry.hpp"
#include "kerf/motion/segment_contract.hpp"

namespace kerf::motion {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr SegmentGrid kUm{1000, 2147483647};
constexpr double kQ = 0.001;

using D = Segment<double>;

// What a Modbus link does to a coordinate (hal/modbus register_map.hpp:
// nearbyint to integer micrometres, then back), written here on its own.
Vec2<double> link_round(Vec2<double> p) {
  return {std::nearbyint(p.x * 1000.0) / 1000.0, std::nearbyint(p.y * 1000.0) / 1000.0};
}
D through_link(const D& g, Vec2<double> from) {
  return g.is_arc() ? D::arc(from, link_round(g.end), link_round(g.centre), g.dir) : D::line(from, link_round(g.end));
}

double sweep_of(const D& g) {
  SegmentShape<double> s;
  EXPECT_EQ(segment_flaw(g, s), SegmentFlaw::none);
  return s.sweep;
}

// Distance from p to a line segment or arc (the arc's own extent).
double distance_to(const D& g, Vec2<double> p) {
  if (!g.is_arc()) {
    const Vec2<double> d = g.end - g.start;
    const double t = std::clamp(d.dot(p - g.start) / d.norm2(), 0.0, 1.0);
    return (g.start + d * t - p).norm();
  }
  const Vec2<double> a = g.start - g.centre, v = p - g.centre;
  double u = std::atan2(a.cross(v), a.dot(v)) * g.dir;
  if (u < 0) u += 2 * kPi;
  if (u <= sweep_of(g)) return std::fabs(v.norm() - a.norm());
  return std::min((p - g.start).norm(), (p - g.end).norm());
}

// The point at fraction t of an arc or line.
Vec2<double> point_on(const D& g, double t) {
  if (!g.is_arc()) return g.start + (g.end - g.start) * t;
  const Vec2<double> a = g.start - g.centre;
  const double phi = std::atan2(a.y, a.x) + g.dir * sweep_of(g) * t;
  return g.centre + Vec2<double>{std::cos(phi), std::sin(phi)} * a.norm();
}

D arc_by_sweep(Vec2<double> c, double r, double a0, double sweep, int dir) {
  const double a1 = a0 + dir * sweep;
  return D::arc(c + Vec2<double>{std::cos(a0), std::sin(a0)} * r, c + Vec2<double>{std::cos(a1), std::sin(a1)} * r,
                c, dir);
}

// ---- acceptance at the edges -------------------------------------------

TEST(SegmentContract, RefusesWhatTheBoardCannotRun) {
  SegmentShape<double> s;
  EXPECT_EQ(segment_flaw(D::line({1, 2}, {1, 2}), s), SegmentFlaw::zero_length);
  EXPECT_EQ(segment_flaw(D::arc({1, 0}, {1, 0}, {0, 0}, 1), s), SegmentFlaw::sweep_range);
  EXPECT_EQ(segment_flaw(D::arc({0, 0}, {1, 0}, {0, 0}, 1), s), SegmentFlaw::zero_radius);
  EXPECT_EQ(segment_flaw(D::line({0, 0}, {NAN, 0}), s), SegmentFlaw::not_finite);
  EXPECT_EQ(segment_flaw(D::arc({1, 0}, {0, 1}, {0, INFINITY}, 1), s), SegmentFlaw::not_finite);
}

TEST(SegmentContract, AcceptsTinySweepsAndNearlyFullCircles) {
  const D tiny = arc_by_sweep({0, 0}, 1.0, 0.3, 1e-9, 1);
  EXPECT_NEAR(sweep_of(tiny), 1e-9, 1e-12);
  const D nearly = arc_by_sweep({5, 5}, 10.0, 1.0, 2 * kPi - 1e-6, -1);
  EXPECT_NEAR(sweep_of(nearly), 2 * kPi - 1e-6, 1e-9);
  const D huge = arc_by_sweep({0, 1e7}, 1e7, -kPi / 2, 1e-7, 1);  // 10 km radius, 1 mm long
  EXPECT_NEAR(sweep_of(huge) * 1e7, 1.0, 1e-6);
}

TEST(SegmentContract, PrepareSegmentIsTheSameCheck) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int refused = 0;
  for (int i = 0; i < 20000; ++i) {
    // Coordinates on a coarse grid so that coinciding points happen often.
    auto pt = [&] { return Vec2<double>{std::round(u(rng) * 3) / 2, std::round(u(rng) * 3) / 2}; };
    const D g = i % 2 ? D::line(pt(), pt()) : D::arc(pt(), pt(), pt(), i % 4 ? 1 : -1);
    const bool ok = prepare_segment<double>({g, 1.0, 1}).ok();
    EXPECT_EQ(ok, segment_acceptable(g)) << i;
    refused += ok ? 0 : 1;
  }
  EXPECT_GT(refused, 1000);  // the edges were exercised
}

TEST(SegmentContract, FixedAcceptanceMatchesDouble) {
  using F = Segment<Fixed>;
  const F line = F::line({Fixed(1), Fixed(2)}, {Fixed(1), Fixed(2)});
  EXPECT_FALSE(segment_acceptable(line));
  const F one_count = F::line({Fixed(1), Fixed(2)}, {Fixed(1) + Fixed::ratio(1, 1000), Fixed(2)});
  EXPECT_TRUE(segment_acceptable(one_count));
  const F half = F::arc({Fixed(1), Fixed(0)}, {Fixed(-1), Fixed(0)}, {Fixed(0), Fixed(0)}, 1);
  SegmentShape<Fixed> s;
  ASSERT_EQ(segment_flaw(half, s), SegmentFlaw::none);
  EXPECT_NEAR(static_cast<double>(s.sweep.raw()) / 4294967296.0, kPi, 1e-6);
  const F closed = F::arc({Fixed(1), Fixed(0)}, {Fixed(1), Fixed(0)}, {Fixed(0), Fixed(0)}, -1);
  EXPECT_EQ(segment_flaw(closed, s), SegmentFlaw::sweep_range);
}

// ---- emission on the grid ----------------------------------------------

void expect_runs_on_board(const Emitted<double>& e, Vec2<double> from) {
  ASSERT_EQ(e.status, EmitStatus::ok);
  Vec2<double> at = from;
  for (int k = 0; k < e.count; ++k) {
    const D& g = e.segments[k];
    EXPECT_EQ(g.start, at) << "segment " << k << " does not start where the previous ended";
    EXPECT_TRUE(segment_acceptable(g)) << "segment " << k;
    const D linked = through_link(g, at);
    EXPECT_TRUE(segment_acceptable(linked)) << "segment " << k << " after the link";
    EXPECT_NEAR(linked.end.x, g.end.x, 1e-9);
    EXPECT_NEAR(linked.end.y, g.end.y, 1e-9);
    EXPECT_NEAR(linked.centre.x, g.centre.x, 1e-9);
    EXPECT_NEAR(linked.centre.y, g.centre.y, 1e-9);
    at = g.end;
  }
}

// The piece that stopped tball-pocket at --tol 0.025: an arc of radius
// 0.2 um from the fit; on the link its start, end and centre all became
// (79.096, -52.418).
TEST(SegmentContract, SubMicrometreArcFromTballPocket) {
  const D fitted = D::arc({79.0959, -52.4182}, {79.0962, -52.4179}, {79.096050996, -52.418050996}, -1);
  ASSERT_TRUE(segment_acceptable(fitted));
  const Vec2<double> from = link_round(fitted.start);
  EXPECT_FALSE(segment_acceptable(through_link(fitted, from)));  // the bug, as it was
  const Emitted<double> e = emit_on_grid(from, fitted, kUm);
  expect_runs_on_board(e, from);
  ASSERT_EQ(e.count, 0);  // both ends round to (79.096, -52.418): merged into the next piece
}

TEST(SegmentContract, LineShorterThanTheGridMerges) {
  const Vec2<double> from{35.931, -24.278};
  const Emitted<double> e = emit_on_grid(from, D::line({35.9309, -24.2775}, {35.9309, -24.2778}), kUm);
  expect_runs_on_board(e, from);
  EXPECT_EQ(e.count, 0);
  const Emitted<double> f = emit_on_grid(from, D::line({35.9309, -24.2778}, {35.9309, -24.2792}), kUm);
  expect_runs_on_board(f, from);
  ASSERT_EQ(f.count, 1);
  EXPECT_EQ(f.segments[0].end, (Vec2<double>{35.931, -24.279}));
}

TEST(SegmentContract, NearlyFullCircleIsSplitNotLost) {
  // 10 mm radius, counter-clockwise from 0.4 um above the x axis round to
  // 0.1 um below it: both ends round to (10, 0), and as one arc on the grid
  // its sweep would be 0 (refused) instead of nearly 2 pi.
  const D fitted = D::arc({std::sqrt(100 - 0.0004 * 0.0004), 0.0004}, {std::sqrt(100 - 0.0001 * 0.0001), -0.0001},
                          {0, 0}, 1);
  EXPECT_NEAR(sweep_of(fitted), 2 * kPi - 5e-5, 1e-9);
  const Vec2<double> from = link_round(fitted.start);
  EXPECT_FALSE(segment_acceptable(through_link(fitted, from)));
  const Emitted<double> e = emit_on_grid(from, fitted, kUm);
  expect_runs_on_board(e, from);
  ASSERT_EQ(e.count, 2);
  double sweep = 0;
  for (int k = 0; k < e.count; ++k) {
    ASSERT_TRUE(e.segments[k].is_arc());
    sweep += sweep_of(e.segments[k]);
  }
  EXPECT_NEAR(sweep, 2 * kPi, 1e-3);
}

TEST(SegmentContract, ArcWithACentreBeyondTheGridBecomesItsChord) {
  // 3000 km radius, 20 mm long: the centre does not fit 32-bit micrometres.
  const D fitted = arc_by_sweep({0, 3e9}, 3e9, -kPi / 2, 20.0 / 3e9, 1);
  const Vec2<double> from = link_round(fitted.start);
  const Emitted<double> e = emit_on_grid(from, fitted, kUm);
  expect_runs_on_board(e, from);
  ASSERT_EQ(e.count, 1);
  EXPECT_FALSE(e.segments[0].is_arc());
  EXPECT_EQ(e.lines_for_arcs, 1);
}

TEST(SegmentContract, EndsBeyondTheGridAreRefused) {
  const Emitted<double> e = emit_on_grid<double>({0, 0}, D::line({0, 0}, {3e6, 0}), kUm);
  EXPECT_EQ(e.status, EmitStatus::off_grid);
  const Emitted<double> f = emit_on_grid<double>({0, 0}, D::line({0, 0}, {0, 0}), kUm);
  EXPECT_EQ(f.status, EmitStatus::refused);
}

TEST(SegmentContract, FixedEmitsOnTheSameGrid) {
  using F = Segment<Fixed>;
  const Vec2<Fixed> from{Fixed::ratio(79096, 1000), Fixed::ratio(-52418, 1000)};
  const F tiny = F::arc({Fixed::ratio(790959, 10000), Fixed::ratio(-524182, 10000)},
                        {Fixed::ratio(790962, 10000), Fixed::ratio(-524179, 10000)},
                        {Fixed::ratio(79096051, 1000000), Fixed::ratio(-52418051, 1000000)}, -1);
  const Emitted<Fixed> e = emit_on_grid(from, tiny, kUm);
  ASSERT_EQ(e.status, EmitStatus::ok);
  EXPECT_EQ(e.count, 0);
  const F quarter = F::arc(from, {Fixed::ratio(89096, 1000), Fixed::ratio(-42418, 1000)},
                           {Fixed::ratio(79096, 1000), Fixed::ratio(-42418, 1000)}, 1);
  const Emitted<Fixed> q = emit_on_grid(from, quarter, kUm);
  ASSERT_EQ(q.status, EmitStatus::ok);
  ASSERT_EQ(q.count, 1);
  EXPECT_TRUE(q.segments[0].is_arc());
  EXPECT_TRUE(segment_acceptable(q.segments[0]));
}

// Random chains of pieces from 0.1 um to 10 m radius, sweeps from 1e-7 to
// nearly 2 pi: every emitted segment runs after the link, chains stay
// joined, and the emitted path stays within a few grid steps of the fit.
TEST(SegmentContract, RandomChainsRunAndStayClose) {
  std::mt19937_64 rng(2121);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0, worst_r = 0;
  int emitted = 0, merged = 0, chords = 0;
  for (int chain = 0; chain < 400; ++chain) {
    Vec2<double> end{u(rng) * 200 - 100, u(rng) * 200 - 100};
    Vec2<double> from = link_round(end);
    double heading = u(rng) * 2 * kPi;
    for (int i = 0; i < 40; ++i) {
      const double len = std::pow(10.0, -4.5 + 6.0 * u(rng));  // 0.03 um .. 30 mm
      D fitted;
      if (u(rng) < 0.3) {
        fitted = D::line(end, end + Vec2<double>{std::cos(heading), std::sin(heading)} * len);
      } else {
        const double r = std::pow(10.0, -4.0 + 8.0 * u(rng));  // 0.1 um .. 10 km
        const double sweep = std::min(len / r, 2 * kPi - 1e-7 - 1e-3 * u(rng));
        const int dir = u(rng) < 0.5 ? 1 : -1;
        const Vec2<double> c = end + Vec2<double>{-std::sin(heading), std::cos(heading)} * (r * dir);
        fitted = arc_by_sweep(c, r, std::atan2(end.y - c.y, end.x - c.x), sweep, dir);
        fitted.start = end;
        heading += dir * sweep;
      }
      if (!segment_acceptable(fitted)) continue;
      const Emitted<double> e = emit_on_grid(from, fitted, kUm);
      expect_runs_on_board(e, from);
      if (::testing::Test::HasFailure()) return;
      emitted += e.count;
      merged += e.count == 0 ? 1 : 0;
      chords += e.lines_for_arcs;
      // Every point of the fitted piece lies near the emitted segments (or
      // near `from` when the piece merged).
      for (int s = 0; s <= 32; ++s) {
        const Vec2<double> p = point_on(fitted, s / 32.0);
        double d = (p - from).norm();
        for (int k = 0; k < e.count; ++k) d = std::min(d, distance_to(e.segments[k], p));
        if (d > worst) {
          worst = d;
          worst_r = fitted.is_arc() ? fitted.radius() : 0;
        }
      }
      if (e.count > 0) from = e.segments[e.count - 1].end;
      end = fitted.end;
    }
  }
  std::printf("emitted %d segments, %d pieces merged, %d arcs as chords; worst deviation %.3g mm (radius %.3g)\n",
              emitted, merged, chords, worst, worst_r);
  EXPECT_GT(merged, 0);
  EXPECT_GT(chords, 0);
  EXPECT_LE(worst, 3 * kQ);
}

}  // namespace
}  // namespace kerf::motion
