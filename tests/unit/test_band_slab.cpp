// The pair test's quick pass (fit/band/slab.hpp) must be sound: when it
// says a slab is clear of an arc's disc, every point within the slab's
// thickness of its segment lies outside that disc. Checked on random arcs
// and slabs placed across their circles, sampling each slab to its edge,
// against the circle's centre and radius computed apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "kerf/fit/detail/angle_set.hpp"
#include "kerf/fit/band/slab.hpp"

namespace {

using VD = kerf::Vec2<double>;
using kerf::fit::band_detail::SlabTest;

class Random {
 public:
  double uniform(double lo, double hi) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * static_cast<double>(state_ >> 11) / 9007199254740992.0;
  }

 private:
  std::uint64_t state_ = 0x9e3779b97f4a7c15ull;
};

struct Arc {
  VD a, b, n;
  double chord;
  int orient;
};

Arc random_arc(Random& rng) {
  Arc arc;
  arc.a = {rng.uniform(-10, 10), rng.uniform(-10, 10)};
  arc.b = {rng.uniform(-10, 10), rng.uniform(-10, 10)};
  arc.orient = rng.uniform(0, 1) < 0.5 ? 1 : -1;
  arc.n = (arc.b - arc.a).perp() * static_cast<double>(arc.orient);
  arc.chord = std::sqrt((arc.b - arc.a).norm2());
  return arc;
}

TEST(BandSlab, AClearSlabHasNoPointInsideTheDisc) {
  Random rng;
  int clear = 0, not_clear = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Arc arc = random_arc(rng);
    const VD d = kerf::fit::direction_of(rng.uniform(0.01, 1.99));
    // The circle through a and b for d: centre mid + n d.x / (2 d.y).
    const VD c = (arc.a + arc.b) * 0.5 + arc.n * (d.x / (2 * d.y));
    const double r = std::sqrt((arc.a - c).norm2());
    // A slab across the circle: its ends a little inside or outside it.
    const double angle = rng.uniform(0, 6.283185307179586);
    const double turn = rng.uniform(-0.3, 0.3);
    const double scale = rng.uniform(0.01, 1.0);
    const VD s0 = c + VD{std::cos(angle), std::sin(angle)} * (r + scale * rng.uniform(-0.2, 1.0));
    const VD s1 = c + VD{std::cos(angle + turn), std::sin(angle + turn)} * (r + scale * rng.uniform(-0.2, 1.0));
    const double thickness = scale * rng.uniform(0, 0.5);
    const SlabTest<double> slab(arc.a, arc.b, arc.n, arc.chord, s0, s1, thickness);
    if (!slab.clear_at(d)) {
      ++not_clear;
      continue;
    }
    ++clear;
    for (int k = 0; k <= 32; ++k) {
      const double x = k / 32.0;
      const double towards = rng.uniform(0, 6.283185307179586);
      // On the slab's edge: the points the margin is there for.
      const VD q = s0 + (s1 - s0) * x + VD{std::cos(towards), std::sin(towards)} * thickness;
      const double from_centre = std::sqrt((q - c).norm2());
      ASSERT_GE(from_centre, r * (1 - 1e-9)) << "trial " << trial << " point " << k << ": inside the disc by "
                                             << r - from_centre << " (thickness " << thickness << ")";
    }
  }
  // Both verdicts were reached often: the check had clear slabs to sample.
  EXPECT_GT(clear, 2000);
  EXPECT_GT(not_clear, 2000);
}

TEST(BandSlab, TheLineCaseIsTheHalfPlaneOnTheBulgeSide) {
  // psi = 0: the "disc" is the half-plane left of a -> b times the
  // orientation (Y > 0); outside is Y <= 0.
  Random rng;
  int clear = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const Arc arc = random_arc(rng);
    const VD unit_n = arc.n * (1 / arc.chord);
    const VD along = (arc.b - arc.a) * (1 / arc.chord);
    const VD s0 = arc.a + along * rng.uniform(-5, 5) + unit_n * rng.uniform(-1, 0.2);
    const VD s1 = arc.a + along * rng.uniform(-5, 5) + unit_n * rng.uniform(-1, 0.2);
    const double thickness = rng.uniform(0, 0.4);
    const SlabTest<double> slab(arc.a, arc.b, arc.n, arc.chord, s0, s1, thickness);
    if (!slab.clear_at(kerf::fit::direction_of(0.0))) continue;
    ++clear;
    for (int k = 0; k <= 8; ++k) {
      const VD q = s0 + (s1 - s0) * (k / 8.0) + unit_n * thickness;  // the edge nearest the line
      ASSERT_LE((q - arc.a).dot(unit_n), 1e-12) << "trial " << trial << " point " << k;
    }
  }
  EXPECT_GT(clear, 500);
}

}  // namespace
