// The ESGI'104 report's two "best arc" rules (section 2.3), kept to reproduce
// the report and as baselines. Both put the arc through p_i and p_j.
//   esgi-max:  through one inner point too, the one whose circle has the
//              smallest largest distance to the inner points.
//   esgi-mean: centre on the bisector at the mean of the signed distances
//              d_k from the chord midpoint to the centres of the circles
//              through p_i, p_k, p_j. An inner point on the chord's line
//              (to within rounding) has no such circle (d_k is infinite) and
//              is left out of the mean; if every inner point is, the piece
//              is the line.
// A rule's piece is feasible when its largest inner distance is <= eps, the
// distance to the arc (the better of the circle's two; fit/detail/chord.hpp).
// Distances are measured in the chord frame (fit/detail/chord.hpp), which stays
// exact for the enormous radii of nearly straight runs.
#pragma once

#include <cstdint>

#include "kerf/fit/detail/chord.hpp"

namespace kerf::fit {

enum class EsgiRule : std::uint8_t { max, mean };

namespace detail {

// Largest distance from the inner points to the arc on the circle of
// direction d (the better of its two arcs that runs them in order, steps of
// at most 2 eps exempt; for the line, the segment), stopping early once it
// exceeds `stop`; infinite when neither arc runs them in order.
template <class S>
struct ArcError {
  S error;
  int dir;
};

template <class S>
ArcError<S> inner_error(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, const Chord<S>& chord,
                        Vec2<S> d, S stop, S eps) {
  ArcError<S> best{Scalar<S>::infinity(), 1};
  for (int e = 1; e >= -1; e -= 2) {
    if (e < 0 && !(d.y > S(0))) break;  // the line: only the segment (E = +1 at phi = 0)
    bool forward = true;  // the arc runs the points in order
    for (std::uint32_t k = i; k < j && forward; ++k)
      forward = steps_forward(chord, pts[k], pts[k + 1], eps, e, d);
    if (!forward) continue;
    const S limit = min_of(stop, best.error);
    S worst = S(0);
    for (std::uint32_t k = i + 1; k < j && !(worst > limit); ++k)
      worst = max_of(worst, arc_distance(chord, d, e, pts[k]));
    if (worst < best.error) best = {worst, e};
  }
  return best;
}

template <class S>
PieceFit<S> esgi_max(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, const Chord<S>& chord,
                    S stop, S good_enough, S eps) {
  PieceFit<S> best;
  best.error = Scalar<S>::infinity();
  for (std::uint32_t k = i + 1; k < j && !(best.error <= good_enough); ++k) {
    const Vec2<S> d = chord.direction_through(pts[k]);
    if (d.norm2() == S(0)) continue;  // p_k repeats an end point: no circle
    const ArcError<S> e = inner_error(pts, i, j, chord, d, min_of(best.error, stop), eps);
    if (e.error < best.error) best = {!(d.y > S(0)), d, e.error, e.dir};
  }
  return best;
}

template <class S>
PieceFit<S> esgi_mean(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, const Chord<S>& chord,
                     S stop, S eps) {
  // The report's d_k is the signed offset t of the centre along the bisector,
  // t = A / (2B) in fit/detail/chord.hpp's terms (its normal points the other way,
  // which flips every d_k and the mean together).
  S sum = S(0);
  std::uint32_t count = 0;
  for (std::uint32_t k = i + 1; k < j; ++k) {
    const Vec2<S> v = pts[k] - chord.mid;
    const S b = v.dot(chord.n);
    // b carries a rounding error of a few ulps of |v|; below that the sign
    // and size of d_k are noise, which would swamp the mean.
    if (!(Scalar<S>::abs(b) > S(16) * Scalar<S>::epsilon() * (v.norm() + chord.h))) continue;
    sum = sum + (v.norm2() - chord.h * chord.h) / (S(2) * b);
    ++count;
  }
  PieceFit<S> arc;
  if (count > 0 && Scalar<S>::is_finite(sum)) {
    const Vec2<S> d{sum / S(static_cast<long>(count)), chord.h};  // (t, h) ~ (cos, sin)
    arc.direction = d * (S(1) / d.norm());
    arc.line = !(arc.direction.y > S(0));
  }
  const ArcError<S> e = inner_error(pts, i, j, chord, arc.direction, stop, eps);
  arc.error = e.error;
  arc.dir = e.dir;
  return arc;
}

}  // namespace detail

// The rule's piece for p_i -> p_j (eps: the tol, which exempts steps of at
// most 2 eps from running forward). A feasibility test passes stop =
// good_enough = eps: it gives up on a candidate once its error exceeds eps and
// settles for the first one within eps. For the rule's own choice pass
// stop = infinity and good_enough = -1.
template <class S>
PieceFit<S> esgi_arc(EsgiRule rule, const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S stop,
                    S good_enough, S eps) {
  PieceFit<S> arc;
  if (j <= i + 1) return arc;  // two consecutive points: the line, exactly
  if (closes_on_itself(pts[i], pts[j])) {
    arc.error = Scalar<S>::infinity();
    return arc;
  }
  const Chord<S> chord(pts[i], pts[j]);
  return rule == EsgiRule::max ? detail::esgi_max(pts, i, j, chord, stop, good_enough, eps)
                               : detail::esgi_mean(pts, i, j, chord, stop, eps);
}

}  // namespace kerf::fit
