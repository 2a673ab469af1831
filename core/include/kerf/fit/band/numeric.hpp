// Scale-aware arithmetic for the band fitter, in one place.
//
// The fitter scales its points into [0.5, 1), so the band's widths and the
// short chords of R's corners are small numbers there (a 0.01 mm band on a
// 100 mm part is ~1e-4). kerf::Fixed has an absolute resolution of 2^-32:
// the square of such a width keeps only a few dozen steps, and the square
// root of it (a vector's length, a gate's half length) is then off by
// percents. These helpers move the operands to [0.5, 1) by a power of two
// first (exact), so the result keeps 32 significant bits whatever its size.
// For floating point they are the plain expressions, bit for bit.
#pragma once

#include <type_traits>  // freestanding

#include "kerf/geom/segment.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::fit::band_detail {

template <class S>
inline constexpr bool kFloating = std::is_floating_point_v<S>;

// |v|.
template <class S>
S length(Vec2<S> v) {
  if constexpr (kFloating<S>) {
    return v.norm();
  } else {
    const S m = max_of(Scalar<S>::abs(v.x), Scalar<S>::abs(v.y));
    if (!(m > S(0))) return S(0);
    const S f = Scalar<S>::normaliser(m);
    return (v * f).norm() / f;
  }
}

// sqrt(max(0, w^2 - c^2 s^2)): a gate's half length without the offset
// (band_region.hpp).
template <class S>
S gate_root(S w, S c, S s) {
  if constexpr (kFloating<S>) {
    const S d = w * w - c * c * s * s;
    return Scalar<S>::sqrt(d > S(0) ? d : S(0));
  } else {
    const S m = max_of(Scalar<S>::abs(w), Scalar<S>::abs(c));
    if (!(m > S(0))) return S(0);
    const S f = Scalar<S>::normaliser(m);
    const S sw = w * f;
    const S sc = c * f * s;
    const S d = sw * sw - sc * sc;
    return Scalar<S>::sqrt(d > S(0) ? d : S(0)) / f;
  }
}

// The power of two that brings m (> 0) into [0.5, 1), at most 2^limit.
template <class S>
S power_for(S m, int limit) {
  const S f = Scalar<S>::normaliser(m);
  const S cap = S(1L << limit);
  return f < cap ? f : cap;
}

// The factor a pair's frame is scaled by (see fit/band/pair.hpp): 1 in
// floating point; in fixed point the power of two that makes the chord u
// about 1, so that the pair's areas and offsets keep their bits. At most
// 2^10: points of a pair lie within 2 of each other in the scaled problem,
// and their products must stay far below the range (2^31).
template <class S>
S frame_factor(Vec2<S> u) {
  if constexpr (kFloating<S>) {
    return S(1);
  } else {
    const S m = max_of(Scalar<S>::abs(u.x), Scalar<S>::abs(u.y));
    return m > S(0) ? power_for(m, 10) : S(1);
  }
}

// Multiplies v[0..count) by one power of two that brings the largest into
// [0.5, 1): a comparison of products of them (homogeneous, all of one
// degree) keeps its answer, and fixed point keeps the bits that products of
// small terms (the fourth and eighth powers of the pair test) would lose.
// Nothing to do in floating point.
template <class S>
void balance(S* v, int count) {
  if constexpr (!kFloating<S>) {
    S m = S(0);
    for (int k = 0; k < count; ++k) m = max_of(m, Scalar<S>::abs(v[k]));
    if (!(m > S(0)) || !Scalar<S>::is_finite(m)) return;
    const S g = power_for(m, 30);
    for (int k = 0; k < count; ++k) v[k] = v[k] * g;
  } else {
    (void)v;
    (void)count;
  }
}

// The lower end of the scales bisect_scale tries, below hi; `widest` is the
// widest width at scale 1 in the scaled problem. Floating point: 1e-12 of
// hi. Fixed point: 2^-20 of hi (R narrows a width to 0 below that anyway,
// band_region.hpp), but no scale at which the widest width is below 2^-24
// (256 steps). Narrower, the gates are a few steps long and the pair test
// passes pieces far outside the band: on the calibration G-code, a floor of
// 2^-30 gave 24 pieces instead of 25, one 16 mm out; 2^-27 and 2^-24 match
// double on every test curve and G-code polyline. (A floor of 2^-16 was too
// high: it stopped the parabola's tie-break at 0.01 at 0.78 of the band,
// where double goes on to 0.64 and other piece boundaries.)
template <class S>
S smallest_scale(S hi, S widest) {
  if constexpr (kFloating<S>) {
    (void)widest;
    return hi * S(1e-12);
  } else {
    const S floor = (S(1) / S(1L << 24)) / widest;
    const S lo = max_of(hi / S(1048576), floor);
    return lo < hi ? lo : hi / S(2);
  }
}

// How far a point computed next to a or b (p + b g with g below the
// coordinates' resolution: a gate end, a corner's chord, a tangent point of
// a sub-ulp width) can lie from it by rounding alone: 16 ulps of the larger
// coordinate in floating point, 4 steps in fixed point (absolute). The pair
// test takes such a point as a or b itself (fit/band/pair.hpp).
template <class S>
S rounding_reach(Vec2<S> a, Vec2<S> b) {
  if constexpr (kFloating<S>) {
    const S big = max_of(max_of(Scalar<S>::abs(a.x), Scalar<S>::abs(a.y)),
                         max_of(Scalar<S>::abs(b.x), Scalar<S>::abs(b.y)));
    return S(16) * Scalar<S>::epsilon() * big;
  } else {
    (void)a;
    (void)b;
    return S(4) * Scalar<S>::epsilon();
  }
}

// How close to a or b (along each axis) the end of a chain segment d
// (= q2 - q1) may lie before the pair test takes it as a or b itself:
// 2^-26 of the segment, about sqrt(epsilon). There the circle through a, b
// and a point of the segment is extreme within that fraction of the end,
// at a double root of the segment test's quadratic, which rounding moves
// by about sqrt(epsilon): past the end, where it was dropped. The end's
// limit condition (band_pair.hpp) is then the binding one, to within that
// fraction of the segment's angle.
template <class S>
S segment_end_reach(Vec2<S> d) {
  const S m = max_of(Scalar<S>::abs(d.x), Scalar<S>::abs(d.y));
  return m / S(67108864);  // 2^26: exact in fixed point too
}

// Are p and q within `reach` of each other along both axes?
template <class S>
bool within(Vec2<S> p, Vec2<S> q, S reach) {
  return Scalar<S>::abs(p.x - q.x) <= reach && Scalar<S>::abs(p.y - q.y) <= reach;
}

// Distance from x to the segment p0 -> p1 (geom/segment.hpp's
// distance_to_line_segment). In fixed point its squared lengths would
// quantize a distance below 2^-16 to sqrt of a step, 2^-16 itself (the
// reported error of band pieces was exactly that): lengths go through
// length(), and the offset is taken against the unit direction.
template <class S>
S distance_to_edge(Vec2<S> p0, Vec2<S> p1, Vec2<S> x) {
  if constexpr (kFloating<S>) {
    return distance_to_line_segment(p0, p1, x);
  } else {
    const Vec2<S> d = p1 - p0;
    const S len = length(d);
    if (len == S(0)) return length(x - p0);
    const Vec2<S> e = d * (S(1) / len);
    const S t = e.dot(x - p0);
    if (t <= S(0)) return length(x - p0);
    if (t >= len) return length(x - p1);
    return Scalar<S>::abs(e.cross(x - p0));
  }
}

}  // namespace kerf::fit::band_detail
