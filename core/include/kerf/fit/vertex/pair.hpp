// The exact vertex criterion for one candidate piece p_i -> p_j: does a circle
// (or the line) through both end points pass within eps of every point in
// between, and which one passes closest?
//
// Derivation (see fit/detail/chord.hpp for phi). For an inner point p with
// v = p - mid, A = |v|^2 - h^2 and B = v.n, the power of p is linear in t:
//   |p - c(t)|^2 - r(t)^2 = A - 2 t B.
// The annulus condition (r - eps)^2 <= |p - c|^2 <= (r + eps)^2 reads
//   |A - eps^2 - 2 t B| <= 2 eps r(t),
// and multiplying by sin(phi) > 0 (r = h / sin(phi), t = h cot(phi)):
//   |(A - eps^2) sin(phi) - 2 h B cos(phi)| <= 2 eps h,
//   i.e. |R sin(phi - psi)| <= 2 eps h  with R cos(psi) = A - eps^2, R sin(psi) = 2 h B.
// So each inner point allows one arc of phi, centred on psi (mod pi), of half
// width asin(2 eps h / R); phi = 0 (the line) is allowed exactly when |B| <= eps.
//
// The annulus equals the true condition |d - r| <= eps whenever r >= eps. A
// circle with r < eps also accepts points with d <= eps - r near its centre;
// that needs h < eps (r >= h) and is added explicitly, so the test is exact.
//
// That is the circle. The piece is one of its two arcs, so each point must
// also lie in that arc's wedge or within eps of an end (constrain_wedge), and
// the arc must run the points in order (constrain_step): one half-plane in
// (cos phi, sin phi) each, for each arc in turn.
#pragma once

#include <cstdint>

#include "kerf/fit/detail/angle_set.hpp"
#include "kerf/fit/detail/chord.hpp"

namespace kerf::fit {

namespace detail {

// Sorts up to four intervals by lo and merges overlaps, in place.
template <class S>
std::size_t normalise(Interval<S>* v, std::size_t n) {
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t k = i; k > 0 && v[k].lo < v[k - 1].lo; --k) {
      const Interval<S> t = v[k];
      v[k] = v[k - 1];
      v[k - 1] = t;
    }
  std::size_t out = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (out > 0 && !(v[out - 1].hi < v[i].lo))
      v[out - 1].hi = max_of(v[out - 1].hi, v[i].hi);
    else
      v[out++] = v[i];
  }
  return out;
}

}  // namespace detail

// Narrows `set` to the phi at which p is within eps of the circle.
template <class S>
Status constrain(AngleSet<S>& set, const Chord<S>& chord, Vec2<S> p, S eps) {
  using M = Scalar<S>;
  const S h = chord.h;
  const typename Chord<S>::Terms t = chord.terms(p, eps);  // times k^2, see Chord::local
  const S a = t.a;
  const S b = t.b;
  const S r = M::sqrt(a * a + b * b);
  const S lim = t.lim;
  if (!(r > lim)) return Status::ok;  // every circle through a and b passes close enough
  const Vec2<S> psi{a / r, b / r};    // the direction (cos psi, sin psi)
  if (!(h < eps)) return set.intersect_arc(psi, lim / r);

  // Tiny circles (r < eps, i.e. sin(phi) > h / eps) also accept the point when
  // d <= eps - r, which is R sin(phi - psi) <= -2 eps h on phi in (0, pi).
  // Only chords shorter than 2 eps get here, so plain angles are fine.
  Interval<S> parts[4];
  std::size_t n = arc_parts(psi, lim / r, parts);
  const S pi = M::pi();
  const S half = M::asin(lim / r);
  const S ang = M::atan2(b, a);
  const S gamma = M::asin(h / eps);
  for (int m = -1; m <= 0; ++m) {
    const S lo = max_of(ang + pi + half + S(2) * pi * S(m), gamma);
    const S hi = min_of(ang + S(2) * pi - half + S(2) * pi * S(m), pi - gamma);
    if (!(hi < lo)) {
      parts[n++] = {pseudo_angle(Vec2<S>{M::cos(lo), M::sin(lo)}),
                    pseudo_angle(Vec2<S>{M::cos(hi), M::sin(hi)})};
    }
  }
  n = detail::normalise(parts, n);
  return set.intersect(parts, n);
}

// Narrows `set` to the directions d with c d.x + s d.y >= 0 (sin(phi) >= 0):
// one interval of phi, from the line up to the edge or from the edge on.
template <class S>
Status intersect_half_plane(AngleSet<S>& set, S c, S s) {
  if (c == S(0)) {
    if (!(s < S(0))) return Status::ok;
    const Interval<S> ends[2] = {{S(0), S(0)}, {S(2), S(2)}};  // only sin(phi) = 0
    return set.intersect(ends, 2);
  }
  const S q = pseudo_angle(Vec2<S>{s, -c});  // where the half-plane's edge meets phi
  const Interval<S> part = c > S(0) ? Interval<S>{S(0), q} : Interval<S>{q, S(2)};
  return set.intersect(&part, 1);
}

// Narrows `set` to the circles whose arc of E = e has p in its wedge (or p
// within eps of an end).
template <class S>
Status constrain_wedge(AngleSet<S>& set, const Chord<S>& chord, Vec2<S> p, S eps, int e) {
  const Wedge<S> w = wedge_of(chord, p, eps, e);
  if (w.exempt) return Status::ok;
  return intersect_half_plane(set, w.c, w.s);
}

// The step from p to the next point q must turn forward about the centre,
// by less than half a turn: E (p - c) x (q - p) >= 0, with c = mid + n h
// cot(phi), times sin(phi): E (cross(v, q - p) sin(phi) - h cross(n, q - p)
// cos(phi)) >= 0, v = p - mid. Points within eps of the arc may step back
// when the step is at most 2 eps (both can be near one point of the arc), so
// such a step is exempt. Without it an arc that runs the other way round a
// path that winds (or a major arc that a path's first step skips round) has
// every point within eps and still does not follow them.
template <class S>
Status constrain_step(AngleSet<S>& set, const Chord<S>& chord, Vec2<S> p, Vec2<S> q, S eps, int e) {
  const S k = min_of(chord.local(p, eps).k, chord.local(q, eps).k);
  const Vec2<S> v = (p - chord.mid) * k;
  const Vec2<S> step = (q - p) * k;
  const S ee = eps * k;
  if (!(step.norm2() > S(4) * ee * ee)) return Status::ok;
  const S c = -(chord.h * k) * chord.n.cross(step);
  const S s = v.cross(step);
  return e > 0 ? intersect_half_plane(set, c, s) : intersect_half_plane(set, -c, -s);
}

namespace detail {

// Point `at` (an inner point) near the arc, and its step from the point
// before it in order.
template <class S>
bool narrow(AngleSet<S>& set, const Chord<S>& chord, const Vec2<S>* pts, std::uint32_t at, S eps, int e) {
  return constrain(set, chord, pts[at], eps) == Status::ok && !set.empty() &&
         constrain_wedge(set, chord, pts[at], eps, e) == Status::ok && !set.empty() &&
         constrain_step(set, chord, pts[at - 1], pts[at], eps, e) == Status::ok && !set.empty();
}

// The circles whose arc of E = e passes within eps of every inner point;
// `first` is tried first, `failed` receives the point that emptied the set.
template <class S>
bool vertex_arc_set(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S eps, AngleSet<S>& set,
                    const Chord<S>& chord, int e, std::uint32_t first, std::uint32_t& failed) {
  set.reset();
  if (first > i && first < j && !narrow(set, chord, pts, first, eps, e)) {
    failed = first;
    return false;
  }
  // Coarse to fine (m/2, then quarters, eighths, ...): far-apart points
  // constrain phi most, so an infeasible pair usually fails within a few.
  const std::uint32_t m = j - i - 1;
  std::uint32_t top = 1;
  while (top < m) top *= 2;
  for (std::uint32_t step = top; step > 0; step /= 2) {
    const std::uint32_t start = step == top ? 0 : step;
    const std::uint32_t stride = step == top ? top : 2 * step;
    for (std::uint32_t k = start; k < m; k += stride) {
      const std::uint32_t at = i + 1 + (k + m / 2) % m;
      if (!narrow(set, chord, pts, at, eps, e)) {
        failed = at;
        return false;
      }
    }
  }
  // The last step, to p_j.
  if (constrain_step(set, chord, pts[j - 1], pts[j], eps, e) != Status::ok || set.empty()) {
    failed = j - 1;
    return false;
  }
  return true;
}

}  // namespace detail

// Narrows `set` to the circles through p_i and p_j one of whose two arcs
// from p_i to p_j passes within eps of every inner point (the distance to
// the arc, not to its circle: a point near the circle's other part is not
// near the piece). Stops as soon as the set is empty. Returns false when it
// is (or when storage ran out, which callers size so that it cannot); `dir`
// receives the E of the arc that passes (0 with no inner point).
//
// `hint`, if given, names an inner point to try first and receives the point
// that emptied the set: the same start usually fails on the same point for
// the next end point too, which makes a proof of infeasibility cost O(1).
template <class S>
bool vertex_pair_set(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S eps, AngleSet<S>& set,
                     std::uint32_t* hint = nullptr, int* dir = nullptr) {
  set.reset();
  if (dir != nullptr) *dir = 0;
  if (j <= i + 1) return true;
  if (closes_on_itself(pts[i], pts[j])) {
    set.intersect(nullptr, 0);  // a closed loop has no unique arc
    return false;
  }
  const Chord<S> chord(pts[i], pts[j]);
  const std::uint32_t first = hint != nullptr ? *hint : 0;
  // First the arc on the side of the hint (or the middle point).
  const std::uint32_t probe = first > i && first < j ? first : i + (j - i) / 2;
  int e = chord.offset(pts[probe]) > S(0) ? -1 : 1;
  std::uint32_t failed = 0;
  bool ok = detail::vertex_arc_set(pts, i, j, eps, set, chord, e, first, failed);
  // A point more than eps into the side this arc bulges to is farther than
  // eps from every arc of the other side (the chord's line separates them).
  if (!ok) {
    const S off = chord.offset(pts[failed]);
    const S into = e > 0 ? -off : off;
    if (!(into > eps + eps / S(64))) {
      e = -e;
      ok = detail::vertex_arc_set(pts, i, j, eps, set, chord, e, failed, failed);
    }
  }
  if (!ok) {
    if (hint != nullptr) *hint = failed;
    return false;
  }
  if (dir != nullptr) *dir = e;
  return true;
}

// A cheap sufficient test: the circle through p_i, the middle point and p_j
// (the line if they are collinear), checked with the annulus rule in the
// chord frame, which stays exact for huge radii, and its arc through the
// middle point with the wedge and the steps. Returns its direction, or (0, 0) when it does
// not fit; `dir` receives the arc's E (+1 for the line: the segment).
template <class S>
Vec2<S> vertex_pair_witness(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S eps,
                            int* dir = nullptr) {
  if (dir != nullptr) *dir = 1;
  if (j == i + 1) return {S(1), S(0)};
  if (closes_on_itself(pts[i], pts[j])) return {};
  const Chord<S> chord(pts[i], pts[j]);
  const Vec2<S> middle = pts[(i + j + 1) / 2];
  const Vec2<S> d = chord.direction_through(middle);
  if (d.norm2() == S(0)) return {};
  const int e = d.y > S(0) && chord.offset(middle) > S(0) ? -1 : 1;
  // |(A - eps^2) s - 2 h B c| <= 2 eps h is the annulus (r - eps)^2 <= |p - c|^2
  // <= (r + eps)^2 times s, a sufficient form of "within eps" for any radius.
  for (std::uint32_t k = i + 1; k < j; ++k) {
    const typename Chord<S>::Terms t = chord.terms(pts[k], eps);
    if (Scalar<S>::abs(t.a * d.y - t.b * d.x) > t.lim) return {};
    const Wedge<S> w = wedge_of(chord, pts[k], eps, e);
    if (!w.exempt && w.c * d.x + w.s * d.y < S(0)) return {};
  }
  for (std::uint32_t k = i; k < j; ++k)
    if (!steps_forward(chord, pts[k], pts[k + 1], eps, e, d)) return {};
  if (dir != nullptr) *dir = e;
  return d;
}

// Largest distance of the inner points to that arc.
template <class S>
S pair_error(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, const Chord<S>& chord, Vec2<S> d,
             int e) {
  S err = S(0);
  for (std::uint32_t k = i + 1; k < j; ++k) err = max_of(err, arc_distance(chord, d, e, pts[k]));
  return err;
}

// The widest interval of a non-empty set.
template <class S>
const Interval<S>& widest(const AngleSet<S>& set) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < set.size(); ++k)
    if (set[k].hi - set[k].lo > set[best].hi - set[best].lo) best = k;
  return set[best];
}

// The segment when it is within eps: that never raises the fit's largest
// error, and a machine runs it without an enormous centre. Otherwise the arc
// with the smallest largest distance, found by bisecting eps' in [0, eps] on
// the exact test (to 1e-12 relative). Precondition: the pair is feasible at eps.
template <class S>
PieceFit<S> best_vertex_pair(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S eps,
                            AngleSet<S>& set) {
  PieceFit<S> best;
  const Chord<S> chord(pts[i], pts[j]);
  best.error = pair_error(pts, i, j, chord, best.direction, 1);
  if (!(best.error > eps)) return best;
  S lo = S(0);
  S hi = eps;
  bool found = vertex_pair_set(pts, i, j, hi, set);
  for (int it = 0; found && it < 200 && hi - lo > hi * S(1e-12); ++it) {
    const S mid = (lo + hi) / S(2);
    if (vertex_pair_set(pts, i, j, mid, set)) hi = mid; else lo = mid;
  }
  auto consider = [&](Vec2<S> d, int e) {
    if (!(d.y > S(0)) || e == 0) return;
    const S err = pair_error(pts, i, j, chord, d, e);
    if (err < best.error) best = {false, d, err, e};
  };
  int e = 0;
  if (found && vertex_pair_set(pts, i, j, hi, set, nullptr, &e)) {
    const Interval<S>& part = widest(set);
    const Vec2<S> d = direction_of((part.lo + part.hi) / S(2));
    consider(d * (S(1) / d.norm()), e);
  }
  // The search accepted the pair through its witness or the exact set; if
  // rounding at the boundary made the bisection find nothing, the witness
  // still gives an arc within eps.
  const Vec2<S> w = vertex_pair_witness(pts, i, j, eps, &e);
  consider(w, e);
  return best;
}

}  // namespace kerf::fit
