// The exact pair test against the definition: for many circles through the
// two end points, "p is within eps of the circle" must agree with the set.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kerf/fit/vertex/pair.hpp"

namespace {

using kerf::fit::AngleSet;
using kerf::fit::Chord;
using kerf::fit::Interval;
using V = kerf::Vec2<double>;

bool member(const AngleSet<double>& set, double q) {
  for (std::size_t s = 0; s < set.size(); ++s)
    if (set[s].lo <= q && q <= set[s].hi) return true;
  return false;
}

// Checks one (chord, point, eps) at 2000 circles of the pencil.
void check_against_definition(V a, V b, V p, double eps, unsigned seed) {
  std::vector<Interval<double>> x(16), y(16);
  AngleSet<double> set({x.data(), x.size()}, {y.data(), y.size()});
  const Chord<double> chord(a, b);
  ASSERT_EQ(kerf::fit::constrain(set, chord, p, eps), kerf::Status::ok);
  for (int k = 1; k < 2000; ++k) {
    const double phi = M_PI * k / 2000.0;
    const V dir{std::cos(phi), std::sin(phi)};
    const V c = chord.centre(dir);
    const double r = chord.h / std::sin(phi);
    const double d = std::fabs(std::hypot(p.x - c.x, p.y - c.y) - r);
    if (std::fabs(d - eps) < 1e-9 * (1 + r)) continue;  // too close to call in doubles
    EXPECT_EQ(member(set, kerf::fit::pseudo_angle(dir)), d <= eps)
        << "seed " << seed << " phi " << phi << " d " << d << " eps " << eps;
  }
  // phi = 0 is the line through a and b.
  const double line = std::fabs(chord.offset(p));
  if (std::fabs(line - eps) > 1e-9) {
    EXPECT_EQ(set.contains_line(), line <= eps) << "seed " << seed;
  }
}

TEST(VertexPair, ConstraintMatchesTheDefinitionOnRandomCases) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  for (unsigned seed = 0; seed < 300; ++seed) {
    const V a{u(rng), u(rng)};
    const V b{u(rng), u(rng)};
    const V p{u(rng), u(rng)};
    const double eps = std::fabs(u(rng)) * 0.3 + 1e-3;
    check_against_definition(a, b, p, eps, seed);
  }
}

TEST(VertexPair, ConstraintIsExactForCirclesSmallerThanTheTolerance) {
  // Chord shorter than 2 eps: circles of radius < eps exist, and a point near
  // their centre is within eps of them although outside the annulus rule.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (unsigned seed = 0; seed < 300; ++seed) {
    const V a{u(rng) * 0.2, u(rng) * 0.2};
    const V b{a.x + u(rng) * 0.3, a.y + u(rng) * 0.3};
    const V p{u(rng) * 0.6, u(rng) * 0.6};
    check_against_definition(a, b, p, 0.4, seed);
  }
}

TEST(VertexPair, BestPairIsTheLineForCollinearPoints) {
  const std::vector<V> pts{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  std::vector<Interval<double>> x(32), y(32);
  AngleSet<double> set({x.data(), x.size()}, {y.data(), y.size()});
  const auto fit = kerf::fit::best_vertex_pair(pts.data(), 0, 3, 0.1, set);
  EXPECT_TRUE(fit.line);
  EXPECT_EQ(fit.error, 0.0);
}

TEST(VertexPair, BestPairRecoversTheCircleOfPointsOnIt) {
  std::vector<V> pts;
  for (int k = 0; k <= 20; ++k) {
    const double a = 0.05 * k;
    pts.push_back({2 + 5 * std::cos(a), -1 + 5 * std::sin(a)});
  }
  std::vector<Interval<double>> x(128), y(128);
  AngleSet<double> set({x.data(), x.size()}, {y.data(), y.size()});
  ASSERT_TRUE(kerf::fit::vertex_pair_set(pts.data(), 0, 20, 1e-3, set));
  const auto fit = kerf::fit::best_vertex_pair(pts.data(), 0, 20, 1e-3, set);
  ASSERT_FALSE(fit.line);
  const V centre = Chord<double>(pts[0], pts[20]).centre(fit.direction);
  EXPECT_NEAR(centre.x, 2, 1e-6);
  EXPECT_NEAR(centre.y, -1, 1e-6);
  EXPECT_LT(fit.error, 1e-9);
}

TEST(VertexPair, ClosedLoopIsNotOnePiece) {
  const std::vector<V> pts{{0, 0}, {1, 0}, {1, 1}, {0, 0}};
  std::vector<Interval<double>> x(32), y(32);
  AngleSet<double> set({x.data(), x.size()}, {y.data(), y.size()});
  EXPECT_FALSE(kerf::fit::vertex_pair_set(pts.data(), 0, 3, 10.0, set));
  EXPECT_EQ(kerf::fit::vertex_pair_witness(pts.data(), 0, 3, 10.0).norm2(), 0.0);
}

TEST(VertexPair, WitnessNeverAcceptsWhatTheExactTestRejects) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.02);
  std::vector<V> pts;
  for (int k = 0; k < 60; ++k) pts.push_back({k * 0.5, 3 * std::sin(k * 0.1) + noise(rng)});
  std::vector<Interval<double>> x(256), y(256);
  AngleSet<double> set({x.data(), x.size()}, {y.data(), y.size()});
  int witnessed = 0;
  for (std::uint32_t i = 0; i < 60; ++i)
    for (std::uint32_t j = i + 1; j < 60; ++j)
      if (kerf::fit::vertex_pair_witness(pts.data(), i, j, 0.05).norm2() != 0.0) {
        ++witnessed;
        EXPECT_TRUE(kerf::fit::vertex_pair_set(pts.data(), i, j, 0.05, set)) << i << "->" << j;
      }
  EXPECT_GT(witnessed, 100);
}

}  // namespace
