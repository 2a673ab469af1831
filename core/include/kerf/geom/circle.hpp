// The circle through three points (ESGI'104 report, section 2.2).
#pragma once

#include "kerf/core/status.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf {

template <class S>
struct Circle {
  Vec2<S> centre{};
  S radius{};
};

// Intersects the perpendicular bisectors of p1p2 and p2p3, written relative to
// p1 so that large coordinates do not cancel. A (near-)collinear triple is
// reported as Status::collinear instead of dividing by a vanishing determinant;
// coincident points as Status::degenerate.
template <class S>
Result<Circle<S>> circle_through(Vec2<S> p1, Vec2<S> p2, Vec2<S> p3) {
  const Vec2<S> u = p2 - p1;
  const Vec2<S> v = p3 - p1;
  const S uu = u.norm2();
  const S vv = v.norm2();
  if (uu == S(0) || vv == S(0) || (p3 - p2).norm2() == S(0)) return Status::degenerate;
  const S det = S(2) * u.cross(v);
  // The determinant is |u||v|sin(angle) scaled by 2; below a few ulps of the
  // product the orientation is noise and the centre would be meaningless.
  const S scale = Scalar<S>::sqrt(uu * vv);
  if (Scalar<S>::abs(det) <= S(64) * Scalar<S>::epsilon() * scale) return Status::collinear;
  const Vec2<S> c{(v.y * uu - u.y * vv) / det, (u.x * vv - v.x * uu) / det};
  return Circle<S>{p1 + c, c.norm()};
}

// +1 when p1 -> p2 -> p3 turns counter-clockwise, -1 clockwise, 0 collinear.
// (The report's orientation determinant.)
template <class S>
int orientation(Vec2<S> p1, Vec2<S> p2, Vec2<S> p3) {
  const S d = (p2 - p1).cross(p3 - p2);
  return d > S(0) ? 1 : (d < S(0) ? -1 : 0);
}

}  // namespace kerf
