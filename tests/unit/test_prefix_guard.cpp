// The guard must be a necessary condition: whenever p_i -> p_j is feasible,
// the guard holds at (i, j') for every j' in (i, j]. Otherwise the search
// would give up on a start too early and miss the true minimum.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kerf/fit/detail/prefix_guard.hpp"
#include "kerf/fit/vertex/pair.hpp"

namespace {

using V = kerf::Vec2<double>;

std::vector<V> noisy_curve(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, 0.01);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  const double bend = u(rng);
  std::vector<V> p;
  for (int k = 0; k < n; ++k) {
    const double t = 0.1 * k;
    p.push_back({t + noise(rng), bend * std::sin(t) + 0.3 * t * t / bend + noise(rng)});
  }
  return p;
}

TEST(PrefixGuard, HoldsUpToEveryFeasibleEnd) {
  std::vector<kerf::fit::Interval<double>> x(512), y(512);
  kerf::fit::AngleSet<double> set({x.data(), x.size()}, {y.data(), y.size()});
  int feasible = 0;
  for (unsigned seed = 0; seed < 20; ++seed) {
    const auto p = noisy_curve(seed, 70);
    for (const double eps : {0.005, 0.02, 0.1}) {
      for (std::uint32_t i = 0; i + 1 < p.size(); ++i) {
        std::uint32_t first_fail = 0;
        for (std::uint32_t j = i + 1; j < p.size(); ++j) {
          if (first_fail == 0 && !kerf::fit::prefix_guard(p.data(), i, j, eps)) first_fail = j;
          if (kerf::fit::vertex_pair_set(p.data(), i, j, eps, set)) {
            ++feasible;
            ASSERT_EQ(first_fail, 0u) << "seed " << seed << " eps " << eps << ": guard failed at "
                                      << first_fail << " but " << i << "->" << j << " is feasible";
          }
        }
      }
    }
  }
  EXPECT_GT(feasible, 1000);
}

TEST(PrefixGuard, FailsForPointsNoCircleCanFollow) {
  // A zig-zag far larger than eps: no circle through p0 is near all three.
  const V three[3] = {{1, 1}, {2, -1}, {3, 1}};
  EXPECT_FALSE(kerf::fit::circle_through_near_three(V{0, 0}, three, 0.01));
  // Points on a circle through the origin always pass.
  const V on[3] = {{1, 1}, {2, 0}, {1, -1}};
  EXPECT_TRUE(kerf::fit::circle_through_near_three(V{0, 0}, on, 1e-9));
}

// The square-root-free slack and the squared test of which constraints bind
// (prefix_guard.hpp) must keep it necessary: three points within eps of one
// circle (or line) through the origin pass, for radii from below 3 eps (the
// short cut) to nearly straight, with the points pushed out to 0.999 eps.
TEST(PrefixGuard, PassesPointsNearOneCircleThroughTheOrigin) {
  std::mt19937 rng(2511);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pi = std::acos(-1.0);
  int checked = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double eps = std::pow(10.0, -4 + 3 * unit(rng));
    const double radius = eps * std::pow(10.0, 7 * unit(rng));
    const double phi = 2 * pi * unit(rng);
    const V centre{radius * std::cos(phi), radius * std::sin(phi)};  // the circle passes through 0
    V three[3];
    for (V& q : three) {
      const double a = phi + pi + (unit(rng) - 0.5) * std::min(pi, 50 * eps / radius + 0.5);
      const double push = (2 * unit(rng) - 1) * 0.999 * eps;
      const V on{centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
      const double n = std::hypot(on.x - centre.x, on.y - centre.y);
      q = {on.x + push * (on.x - centre.x) / n, on.y + push * (on.y - centre.y) / n};
    }
    ++checked;
    ASSERT_TRUE(kerf::fit::circle_through_near_three(V{0, 0}, three, eps))
        << "trial " << trial << " eps " << eps << " radius " << radius;
  }
  EXPECT_EQ(checked, 20000);
}

}  // namespace
