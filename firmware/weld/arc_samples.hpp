// The sample points of an arc that write_piece measures against the input
// (weld/weld_plan.cpp), without a sincos per point.
#pragma once

#include <cmath>
#include <cstddef>

#include "kerf/geom/vec2.hpp"

namespace kerf::weld::detail {

// The points c + r (cos a_k, sin a_k), a_k = a0 + turn * (k / n), of an arc
// cut into n equal steps (0 <= k < n <= kMaxSteps), as write_piece walks it.
// For k = 16 i + j, the unit vector of a_k is that of a0 + turn * (16 i / n)
// (the same angle, so the same point, as a sincos per point gives at every
// 16th point) turned by that of turn * (j / n): one complex product, with a
// sincos per 16 points and one per step below 16, made at construction.
// The product is within 2e-15 of the exact unit vector: the angle's own
// rounding is up to 9e-16 (|a_k| < 3 pi), and a sincos per point was off
// by up to 1.6e-15 (tests/weld/test_arc_samples.cpp; 5M random points: 1.5e-15
// here): a few ulps of the coordinates, far below the tolerances.
class ArcSamples {
 public:
  static constexpr std::size_t kMaxSteps = 512;

  ArcSamples(Vec2<double> centre, double r, double a0, double turn, std::size_t n) : c_(centre), r_(r) {
    const double steps = static_cast<double>(n);
    for (std::size_t i = 0; i * kBlock < n; ++i)
      coarse_[i] = polar(a0 + turn * (static_cast<double>(i * kBlock) / steps));
    for (std::size_t j = 1; j < kBlock && j < n; ++j) fine_[j] = polar(turn * (static_cast<double>(j) / steps));
  }

  // Point k.
  Vec2<double> at(std::size_t k) const {
    const Vec2<double> u = unit(k);
    return {c_.x + r_ * u.x, c_.y + r_ * u.y};
  }

  // The unit vector of a_k.
  Vec2<double> unit(std::size_t k) const {
    const Vec2<double> u = coarse_[k / kBlock];
    if (k % kBlock == 0) return u;
    const Vec2<double> v = fine_[k % kBlock];
    return {u.x * v.x - u.y * v.y, u.y * v.x + u.x * v.y};
  }

 private:
  static constexpr std::size_t kBlock = 16;
  static Vec2<double> polar(double a) { return {std::cos(a), std::sin(a)}; }

  Vec2<double> c_;
  double r_;
  Vec2<double> coarse_[kMaxSteps / kBlock];
  Vec2<double> fine_[kBlock];
};

}  // namespace kerf::weld::detail
