// weld's arc samples (firmware/weld/arc_samples.hpp): a sincos per 16
// points and a complex product, against the exact points of the same angles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "weld/arc_samples.hpp"

namespace {

using kerf::weld::detail::ArcSamples;
using P = kerf::Vec2<double>;

constexpr double kPi = 3.14159265358979323846;

// Random arcs as write_piece makes them (start angle in [-pi, pi], a turn of
// up to a full circle either way, 8 to 512 steps), every point asked for in
// a random order, some twice (at() is const: the same answer): each unit vector is within 2e-15 of the exact
// one of a0 + turn * k / n (in long double), and every 16th is the sincos of
// that angle rounded as one sincos per point would round it, bit for bit.
TEST(ArcSamples, WithinTwoE15OfTheExactPointsOnRandomArcs) {
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> angle(-kPi, kPi), part(1e-6, 1.0), coord(-500.0, 500.0);
  std::uniform_int_distribution<std::size_t> steps(8, ArcSamples::kMaxSteps);
  double worst = 0;
  for (int arc = 0; arc < 400; ++arc) {
    const double a0 = angle(rng);
    const double turn = (arc % 2 == 0 ? 1 : -1) * 2 * kPi * part(rng);
    const std::size_t n = steps(rng);
    const P c{coord(rng), coord(rng)};
    const double r = 1000 * part(rng);
    ArcSamples s(c, r, a0, turn, n);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), rng);
    order.insert(order.end(), order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n / 3));
    for (std::size_t k : order) {
      const P u = s.unit(k);
      using L = long double;
      const L exact = static_cast<L>(a0) + static_cast<L>(turn) * static_cast<L>(k) / static_cast<L>(n);
      const double err = static_cast<double>(std::max(std::fabs(static_cast<L>(u.x) - std::cos(exact)),
                                                      std::fabs(static_cast<L>(u.y) - std::sin(exact))));
      worst = std::max(worst, err);
      ASSERT_LE(err, 2e-15) << "arc " << arc << " point " << k << " of " << n;
      const P q = s.at(k);
      ASSERT_EQ(q.x, c.x + r * u.x);
      ASSERT_EQ(q.y, c.y + r * u.y);
      if (k % 16 == 0) {
        const double a = a0 + turn * (static_cast<double>(k) / static_cast<double>(n));
        ASSERT_EQ(u.x, std::cos(a)) << k;
        ASSERT_EQ(u.y, std::sin(a)) << k;
      }
    }
  }
  EXPECT_GT(worst, 0.0);  // the products do round: the bound is not met trivially
}

}  // namespace
