// Unit tangents at the points of a polyline, for the biarc fitter
// (fit/biarc.hpp), when the input does not give them.
//
// The method: the tangent at p_k of the circle through p_{k-1}, p_k, p_{k+1}.
// With a = p_k - p_{k-1}, b = p_{k+1} - p_k it is the direction of
//   |b|^2 a + |a|^2 b
// (the two chords make angles alpha, beta with the tangent, |a| = 2r sin
// alpha, |b| = 2r sin beta, and these weights cancel the normal parts). It
// needs no square root besides the final normalisation, it is the chord
// direction for collinear points, and it is exact (to rounding) for points
// sampled on a circle at any spacing: that is the accuracy
// tests/unit/biarc_tangent_test.cpp measures (below 1e-12 rad on sampled
// circles, and second order in the spacing on smooth curves). The end
// tangents come from the circle through the first (last) three points: the
// tangent at p_1 reflected in the chord p_0 p_1. Two points: the chord.
#pragma once

#include <type_traits>  // freestanding

#include "kerf/core/scale.hpp"
#include "kerf/core/span.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::fit {

// The power of two that brings the largest coordinate of u and v into
// [0.5, 1) in fixed point (its squares of short vectors would keep only a
// few bits; the factor is exact), 1 in floating point.
template <class S>
S unit_scale(Vec2<S> u, Vec2<S> v) {
  if constexpr (std::is_floating_point_v<S>) {
    (void)u;
    (void)v;
    return S(1);
  } else {
    const S m = max_of(max_of(Scalar<S>::abs(u.x), Scalar<S>::abs(u.y)),
                       max_of(Scalar<S>::abs(v.x), Scalar<S>::abs(v.y)));
    if (!Scalar<S>::is_finite(m)) return S(1);
    const S f = power_of_two_scale(m);
    return Scalar<S>::is_finite(f) ? f : S(1);  // m below 2^-31: no factor in range
  }
}

template <class S>
Vec2<S> unit_of(Vec2<S> v) {
  v = v * unit_scale(v, v);
  const S len = v.norm();
  return len > S(0) ? v * (S(1) / len) : Vec2<S>{};
}

// The end tangent of the arc that starts at a with unit tangent t and ends
// at b: t reflected in the chord.
template <class S>
Vec2<S> reflect_in_chord(Vec2<S> t, Vec2<S> a, Vec2<S> b) {
  const Vec2<S> c = unit_of(b - a);
  return c * (S(2) * t.dot(c)) - t;
}

// The tangent at b of the circle through a, b, c (unit; the chord for
// collinear points).
template <class S>
Vec2<S> three_point_tangent(Vec2<S> a, Vec2<S> b, Vec2<S> c) {
  const S f = unit_scale(b - a, c - b);
  const Vec2<S> u = (b - a) * f;
  const Vec2<S> v = (c - b) * f;
  return unit_of(u * v.norm2() + v * u.norm2());
}

// out[k] for every point; pts has n >= 2 points, consecutive ones distinct.
template <class S>
void estimate_tangents(Span<const Vec2<S>> pts, Span<Vec2<S>> out) {
  const std::size_t n = pts.size();
  if (n < 2 || out.size() < n) return;
  if (n == 2) {
    out[0] = out[1] = unit_of(pts[1] - pts[0]);
    return;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) out[k] = three_point_tangent(pts[k - 1], pts[k], pts[k + 1]);
  // The circle's tangent at p_0 is its tangent at p_1 reflected in the chord
  // (a reflection in a line does not care which way the arc runs).
  out[0] = reflect_in_chord(out[1], pts[0], pts[1]);
  out[n - 1] = reflect_in_chord(out[n - 2], pts[n - 2], pts[n - 1]);
}

}  // namespace kerf::fit
