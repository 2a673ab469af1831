// The frame of a candidate piece from a to b, and how an arc's direction E is
// chosen once its centre is known.
//
// Every circle through a and b has its centre on the perpendicular bisector,
// c = mid + t n, with n the unit left normal of a->b and r^2 = h^2 + t^2
// (h = |ab| / 2). kerf parametrises that pencil by phi in [0, pi) with
// t = h cot(phi): phi = 0 is the line through a and b, phi = pi/2 the circle
// with ab as diameter, and equal steps in phi are equal steps in the tangent
// direction at a, which keeps nearly straight arcs well conditioned.
#pragma once

#include "kerf/geom/segment.hpp"

namespace kerf::fit {

template <class S>
struct Chord {
  Vec2<S> a{};
  Vec2<S> b{};
  Vec2<S> mid{};
  Vec2<S> n{};  // unit left normal of a -> b
  S h{};        // half the chord length

  Chord(Vec2<S> from, Vec2<S> to) : a(from), b(to), mid(midpoint(from, to)) {
    const Vec2<S> d = to - from;
    const S len = d.norm();
    h = len / S(2);
    n = len > S(0) ? d.perp() * (S(1) / len) : Vec2<S>{};
  }

  // The centre for the direction d = (cos phi, sin phi) up to scale, phi in (0, pi).
  Vec2<S> centre(Vec2<S> d) const { return mid + n * (h * d.x / d.y); }
  // Signed distance of p from the chord's line, > 0 on the left of a->b.
  S offset(Vec2<S> p) const { return (p - mid).dot(n); }
};

// The piece from a to b: a line, or the arc around `centre` that runs
// through the inner points. The arc bulges to the side of the inner point
// farthest from the chord. If every inner point is within tol of the chord
// (or there is none), it is the minor arc, which bulges away from the centre.
// Bulging to the right of a->b means turning counter-clockwise: E = +1.
template <class S>
Segment<S> make_segment(const Chord<S>& chord, const Vec2<S>* inner, unsigned count, bool line,
                        Vec2<S> centre, S tol) {
  if (line) return Segment<S>::line(chord.a, chord.b);
  S far = S(0);
  for (unsigned k = 0; k < count; ++k) {
    const S o = chord.offset(inner[k]);
    if (Scalar<S>::abs(o) > Scalar<S>::abs(far)) far = o;
  }
  const S t = chord.offset(centre);
  int bulge_left;  // +1 when the arc bulges to the left of a -> b
  if (Scalar<S>::abs(far) <= tol || t == S(0)) {
    bulge_left = (t > S(0)) ? -1 : (t < S(0) ? 1 : (far > S(0) ? 1 : -1));
  } else {
    bulge_left = far > S(0) ? 1 : -1;
  }
  return Segment<S>::arc(chord.a, chord.b, centre, -bulge_left);
}

}  // namespace kerf::fit
