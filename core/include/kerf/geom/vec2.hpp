// A point or vector in the cutting plane.
#pragma once

#include "kerf/core/scalar.hpp"

namespace kerf {

template <class S>
struct Vec2 {
  S x{};
  S y{};

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(S k) const { return {x * k, y * k}; }
  constexpr bool operator==(const Vec2& o) const { return x == o.x && y == o.y; }

  constexpr S dot(Vec2 o) const { return x * o.x + y * o.y; }
  // z of the 3-D cross product: > 0 when o lies counter-clockwise of *this.
  constexpr S cross(Vec2 o) const { return x * o.y - y * o.x; }
  constexpr S norm2() const { return x * x + y * y; }
  S norm() const { return Scalar<S>::sqrt(norm2()); }
  // Rotated a quarter turn counter-clockwise: the left normal of a direction.
  constexpr Vec2 perp() const { return {-y, x}; }
};

template <class S>
constexpr Vec2<S> midpoint(Vec2<S> a, Vec2<S> b) {
  return {(a.x + b.x) / S(2), (a.y + b.y) / S(2)};
}

template <class S>
S distance(Vec2<S> a, Vec2<S> b) {
  return (b - a).norm();
}

}  // namespace kerf
