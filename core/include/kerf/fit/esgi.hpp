// The ESGI'104 report's two "best arc" rules (section 2.3), kept to reproduce
// the report and as baselines. Both put the arc through p_i and p_j.
//   esgi-max:  through one inner point too, the one whose circle has the
//              smallest largest distance to the inner points.
//   esgi-mean: centre on the bisector at the mean of the signed distances
//              d_k from the chord midpoint to the centres of the circles
//              through p_i, p_k, p_j. An inner point on the chord's line has
//              no such circle (d_k is infinite) and is left out of the mean;
//              if every inner point is, the piece is the line.
// A rule's piece is feasible when its largest inner distance is <= eps.
#pragma once

#include <cstdint>

#include "kerf/geom/circle.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::fit {

enum class EsgiRule : std::uint8_t { max, mean };

template <class S>
struct EsgiArc {
  bool line = true;
  Vec2<S> centre{};
  S error{};
};

namespace detail {

// Largest distance from the inner points to the circle (or to the line if
// `line`), stopping early once it exceeds `stop`.
template <class S>
S inner_error(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, bool line, Vec2<S> c, S stop) {
  const S r = line ? S(0) : (pts[i] - c).norm();
  S worst = S(0);
  for (std::uint32_t k = i + 1; k < j && !(worst > stop); ++k) {
    const S d = line ? distance_to_line(pts[i], pts[j], pts[k]) : distance_to_circle(c, r, pts[k]);
    worst = max_of(worst, d);
  }
  return worst;
}

template <class S>
EsgiArc<S> esgi_max(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S stop, S good_enough) {
  EsgiArc<S> best;
  best.error = Scalar<S>::infinity();
  for (std::uint32_t k = i + 1; k < j && !(best.error <= good_enough); ++k) {
    const Result<Circle<S>> c = circle_through(pts[i], pts[k], pts[j]);
    const bool line = !c.ok();
    const S e = inner_error(pts, i, j, line, c.value().centre, min_of(best.error, stop));
    if (e < best.error) best = {line, c.value().centre, e};
  }
  return best;
}

template <class S>
EsgiArc<S> esgi_mean(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S stop) {
  // The report's notation: x01 = x0 - x_{n+1}, y10 = y_{n+1} - y0, w = |chord|.
  const Vec2<S> a = pts[i];
  const Vec2<S> b = pts[j];
  const Vec2<S> m = midpoint(a, b);
  const S x01 = a.x - b.x;
  const S y10 = b.y - a.y;
  const S w2 = x01 * x01 + y10 * y10;
  const S w = Scalar<S>::sqrt(w2);
  S sum = S(0);
  std::uint32_t count = 0;
  for (std::uint32_t k = i + 1; k < j; ++k) {
    const Vec2<S> v = pts[k] - m;
    const S den = S(2) * (v.x * y10 + v.y * x01);
    if (den == S(0)) continue;
    sum = sum + (v.norm2() - w2 / S(4)) * w / den;
    ++count;
  }
  EsgiArc<S> arc;
  if (count > 0) {
    const S d = sum / S(static_cast<long>(count));
    arc.line = false;
    arc.centre = m + Vec2<S>{y10, x01} * (d / w);
  }
  arc.error = inner_error(pts, i, j, arc.line, arc.centre, stop);
  return arc;
}

}  // namespace detail

// The rule's piece for p_i -> p_j. A feasibility test passes stop =
// good_enough = eps: it gives up on a candidate once its error exceeds eps and
// settles for the first one within eps. For the rule's own choice pass
// stop = infinity and good_enough = -1.
template <class S>
EsgiArc<S> esgi_arc(EsgiRule rule, const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S stop,
                    S good_enough) {
  if (j <= i + 1 || pts[i] == pts[j]) {
    EsgiArc<S> line;
    line.error = pts[i] == pts[j] && j > i + 1 ? Scalar<S>::infinity() : S(0);
    return line;
  }
  return rule == EsgiRule::max ? detail::esgi_max(pts, i, j, stop, good_enough)
                               : detail::esgi_mean(pts, i, j, stop);
}

}  // namespace kerf::fit
