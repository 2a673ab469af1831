// Complex numbers as plane vectors (x + i y): the joint circle of a biarc is
// a Moebius map of the chord (fit/biarc/arc.hpp), and its rotations and
// quotients are products and quotients of complex numbers.
#pragma once

#include "kerf/geom/vec2.hpp"

namespace kerf {

template <class S>
constexpr Vec2<S> complex_mul(Vec2<S> a, Vec2<S> b) {
  return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x};
}

// a / b as a conj(b) / |b|^2 (b != 0).
template <class S>
constexpr Vec2<S> complex_div(Vec2<S> a, Vec2<S> b) {
  const S q = b.norm2();
  return Vec2<S>{a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y} * (S(1) / q);
}

}  // namespace kerf
