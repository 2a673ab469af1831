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

  // p - mid and h, both times k, a power of two that brings the larger of them
  // (and of `eps`) near 1. Every test below is homogeneous in the lengths, so
  // it runs on these: for a short chord far from the origin kerf::Fixed would
  // otherwise square values of 1e-5 and less at its absolute resolution of
  // 2^-32 and lose them (an airfoil's nose); a double is left as it is.
  struct Local {
    Vec2<S> v;
    S h;
    S k;
  };
  Local local(Vec2<S> p, S eps = S(0)) const {
    const Vec2<S> v = p - mid;
    const S m = max_of(max_of(Scalar<S>::abs(v.x), Scalar<S>::abs(v.y)), max_of(h, eps));
    const S k = Scalar<S>::local_scale(m);
    return {v * k, h * k, k};
  }

  // The annulus test of p at eps, |A s - B c| <= L for the direction (c, s),
  // with A = |v|^2 - h^2 - eps^2, B = 2 h v.n and L = 2 eps h, all times k^2.
  struct Terms {
    S a;
    S b;
    S lim;
  };
  Terms terms(Vec2<S> p, S eps) const {
    const Local l = local(p, eps);
    const S e = eps * l.k;
    return {l.v.norm2() - l.h * l.h - e * e, S(2) * l.h * l.v.dot(n), S(2) * e * l.h};
  }

  // The power of p with respect to the circle of unit direction d = (cos phi,
  // sin phi), sin phi >= 0, times sin phi:  P = A sin(phi) - 2 h B cos(phi)
  // with A = |p - mid|^2 - h^2 and B = offset(p). It is small and well
  // conditioned for every phi, the line included, unlike |p - c|^2 - r^2.
  // On local terms (times k^2).
  static S power(Vec2<S> d, const Local& l, Vec2<S> n) {
    return (l.v.norm2() - l.h * l.h) * d.y - S(2) * l.h * l.v.dot(n) * d.x;
  }

  // Exact distance from p to that circle (to the line for sin phi = 0), free
  // of the cancellation in | |p - c| - r | when r is huge:
  //   s (d^2 - r^2) = P, s r = h, s d = sqrt(h^2 + s P), so
  //   |d - r| = |P| / (h + sqrt(h^2 + s P)).
  S distance(Vec2<S> d, Vec2<S> p) const {
    const Local l = local(p);
    const S pw = power(d, l, n);
    const S root = l.h * l.h + d.y * pw;
    return Scalar<S>::abs(pw) / (l.h + Scalar<S>::sqrt(root > S(0) ? root : S(0))) / l.k;
  }

  // The unit direction of the circle through a, b and p, or (0, 0) when p is
  // a or b. Collinear p gives the line, (1, 0).
  Vec2<S> direction_through(Vec2<S> p) const {
    const Local l = local(p);
    Vec2<S> d{l.v.norm2() - l.h * l.h, S(2) * l.h * l.v.dot(n)};
    const S len = d.norm();
    if (!(len > S(0))) return {};
    d = d * (S(1) / len);
    return (d.y < S(0) || (d.y == S(0) && d.x < S(0))) ? -d : d;
  }
};

// The arc's wedge (the angle at the centre that the arc spans). Of the two
// arcs from a to b on the circle of direction d = (cos phi, sin phi), the one
// of E = +1 bulges to the right of a -> b (counter-clockwise, half-sweep phi)
// and the one of E = -1 to the left (clockwise, half-sweep pi - phi). With
// p = mid + x u + y n (u along a -> b), p lies in the wedge of the arc of E iff
//   E ((h - |x|) cos phi - y sin phi) >= 0,
// a half-plane in (cos phi, sin phi). Why: p is on the arc's side of the ray
// from the centre through a iff (h + x) cos phi - y sin phi >= 0 (the cross
// product (a - c) x (p - c) times sin(phi) / h), through b iff (h - x) cos phi
// - y sin phi >= 0; a minor arc's wedge (cos phi >= 0) is both, a major one's
// either, and in both cases the one that binds is the end on p's side of the
// bisector. At phi = 0 the arc of E = +1 is the segment ab (|x| <= h); the
// arc of E = -1 there is the rest of the line. A point within eps of a or b
// is within eps of every arc from a to b: it is exempt.
template <class S>
struct Wedge {
  S c;      // p is in the wedge iff c cos(phi) + s sin(phi) >= 0
  S s;
  bool exempt;
  S end2;   // the squared distance to the nearer end, on local terms
  S k;      // the local scale (Chord::local)
};

template <class S>
Wedge<S> wedge_of(const Chord<S>& chord, Vec2<S> p, S eps, int e) {
  const typename Chord<S>::Local l = chord.local(p, eps);
  const Vec2<S> u{chord.n.y, -chord.n.x};
  const S x = Scalar<S>::abs(l.v.dot(u));
  const S y = l.v.dot(chord.n);
  const S gap = x - l.h;
  const S ee = eps * l.k;
  const S end2 = gap * gap + y * y;
  const S c = e > 0 ? l.h - x : x - l.h;
  const S s = e > 0 ? -y : y;
  return {c, s, !(end2 > ee * ee), end2, l.k};
}

// Distance of p to the arc of E = e on the circle of direction d (for d =
// (1, 0) and e = +1: the segment): to the circle inside the arc's wedge, else
// to the nearer end.
template <class S>
S arc_distance(const Chord<S>& chord, Vec2<S> d, int e, Vec2<S> p) {
  const Wedge<S> w = wedge_of(chord, p, S(0), e);
  if (w.exempt || !(w.c * d.x + w.s * d.y < S(0))) return chord.distance(d, p);
  return Scalar<S>::sqrt(w.end2) / w.k;
}

// Does the step from p to q turn forward about the centre of direction d,
// for the arc of E = e (fit/vertex/pair.hpp, constrain_step)? Steps of at
// most 2 eps are exempt.
template <class S>
bool steps_forward(const Chord<S>& chord, Vec2<S> p, Vec2<S> q, S eps, int e, Vec2<S> d) {
  const S k = min_of(chord.local(p, eps).k, chord.local(q, eps).k);
  const Vec2<S> step = (q - p) * k;
  const S ee = eps * k;
  if (!(step.norm2() > S(4) * ee * ee)) return true;
  const S c = -(chord.h * k) * chord.n.cross(step);
  const S s = ((p - chord.mid) * k).cross(step);
  return !(S(e) * (c * d.x + s * d.y) < S(0));
}

// The circle (or line) chosen for one piece, as every fitting rule reports it.
template <class S>
struct PieceFit {
  bool line = true;
  Vec2<S> direction{S(1), S(0)};  // unit (cos phi, sin phi); (1, 0) is the line
  S error{};                      // the largest distance of an inner point
  int dir = 0;  // the arc's E (+1 CCW, -1 CW) when the rule chose it; 0: make_segment's rule
};

// True when a and b are too close for their chord to define a pencil of
// circles: its direction would be rounding noise. Such a pair is a closed
// loop, which no single arc can represent.
template <class S>
bool closes_on_itself(Vec2<S> a, Vec2<S> b) {
  const S scale = max_of(max_of(Scalar<S>::abs(a.x), Scalar<S>::abs(a.y)),
                         max_of(Scalar<S>::abs(b.x), Scalar<S>::abs(b.y)));
  const S gap = max_of(Scalar<S>::abs(b.x - a.x), Scalar<S>::abs(b.y - a.y));
  return !(gap > scale * S(1024) * Scalar<S>::epsilon());
}

// The piece from a to b: a line, or the arc around `centre` that runs
// through the inner points. The arc bulges to the side of the inner point
// farthest from the chord. If every inner point is within tol of the chord
// (or there is none), it is the minor arc, which bulges away from the centre.
// Bulging to the right of a->b means turning counter-clockwise: E = +1.
// `dir`, when not 0, is the E that the rule chose (the vertex criterion's
// exact arc test knows which of the circle's two arcs passes the points).
template <class S>
Segment<S> make_segment(const Chord<S>& chord, const Vec2<S>* inner, unsigned count, bool line,
                        Vec2<S> centre, S tol, int dir = 0) {
  if (line) return Segment<S>::line(chord.a, chord.b);
  if (dir != 0) return Segment<S>::arc(chord.a, chord.b, centre, dir);
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
