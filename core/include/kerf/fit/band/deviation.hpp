// How far a band piece strays from its polyline: the largest distance from
// a point of the arc (or line) p_i -> p_j to the polyline p_i..p_j.
//
// The piece crosses gate k at q_k (q_i = p_i, q_j = p_j); between q_k and
// q_{k+1} it lies in cell k, whose nearest polyline part is edge k (the
// gates are the corners' bisectors). So the piece's deviation is at most
// the largest, over k, of the distance to edge k along that stretch, and
// equals it unless a far part of the polyline folds back within tol. Along
// one stretch that distance is a smooth function between the points where
// the arc crosses the normals at p_k and p_{k+1} (where "nearest to the
// edge's inside" turns into "nearest to an end"); its maxima are at those
// crossings, at the stretch's ends, where the arc runs parallel to the edge,
// or where it is farthest from p_k or p_{k+1}. All of these are evaluated.
//
// Points on the arc are ordered by sigma, the angle between the start
// tangent and the chord to the point (half the angle turned so far), as a
// pseudo-angle: the arc is sigma in [0, psi], and nothing here needs the
// centre, which is far away on nearly straight arcs.
#pragma once

#include "kerf/fit/band/numeric.hpp"
#include "kerf/fit/band/region.hpp"
#include "kerf/geom/roots.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::fit {

template <class S>
class ArcProbe {
 public:
  // The arc from a to b with unit start tangent t and turning side m (the
  // unit normal of t towards the centre), or the line (d.y == 0), where d is
  // (cos psi, sin psi) up to scale in the chord frame (u, n).
  ArcProbe(Vec2<S> a, Vec2<S> b, Vec2<S> d, int orient) : a_(a), b_(b) {
    const Vec2<S> u = b - a;
    const S len = band_detail::length(u);
    u_ = u * (S(1) / len);
    n_ = u_.perp() * S(orient);
    const S dl = band_detail::length(d);
    d_ = d * (S(1) / dl);
    t_ = u_ * d_.x - n_ * d_.y;  // t = (cos psi, -sin psi) in the frame
    m_ = n_ * d_.x + u_ * d_.y;  // t rotated towards the bulge's far side
    h_ = len / S(2);
    psi_ = sigma(b);
  }
  bool line() const { return !(d_.y > S(0)); }

  // sigma of a point on the circle, as a pseudo-angle in [0, 2].
  S sigma(Vec2<S> x) const {
    const Vec2<S> v = x - a_;
    const S px = v.dot(t_);
    const S py = max_of(S(0), v.dot(m_));
    if (px == S(0) && py == S(0)) return S(0);
    return S(1) - px / (Scalar<S>::abs(px) + py);
  }
  bool on_arc(Vec2<S> x) const {
    const S s = sigma(x);
    return !(s > psi_);
  }

  // The points where the circle meets the line p + s g (s free); returns
  // how many (0..2) were written.
  int meet_line(Vec2<S> p, Vec2<S> g, Vec2<S> out[2]) const {
    // power * sin(psi) = d.y A - d.x Y with A = (x-a).(x-b), Y = 2h (x-mid).n
    const Vec2<S> mid = midpoint(a_, b_);
    const S qa = d_.y * g.norm2();
    const S qb = d_.y * g.dot(p * S(2) - a_ - b_) - d_.x * S(2) * h_ * g.dot(n_);
    const S qc = d_.y * (p - a_).dot(p - b_) - d_.x * S(2) * h_ * (p - mid).dot(n_);
    S t[2];
    const int k = quadratic_roots(qa, qb, qc, t);
    for (int r = 0; r < k; ++r) out[r] = p + g * t[r];
    return k;
  }

  // The points of the circle where its tangent is parallel to e (unit).
  int parallel_to(Vec2<S> e, Vec2<S> out[2]) const {
    if (line()) return 0;
    // The tangent has turned by theta = 2 sigma where it is parallel to e.
    const S ct = e.dot(t_);
    const S st = e.dot(m_);
    Vec2<S> half = (ct > S(-0.5)) ? Vec2<S>{S(1) + ct, st} : Vec2<S>{st, S(1) - ct};
    if (half.y < S(0)) half = -half;
    const S hl = band_detail::length(half);
    if (!(hl > S(0))) return 0;
    half = half * (S(1) / hl);
    // The chord from a at angle sigma has length 2 r sin(sigma) = 2 h sin(sigma) / sin(psi).
    const Vec2<S> other{-half.y, half.x};  // sigma + pi/2 (the opposite tangent)
    int k = 0;
    const Vec2<S> both[2] = {half, other};
    for (const Vec2<S>& c : both) {
      if (c.y < S(0)) continue;
      const S chord = S(2) * h_ * c.y / d_.y;
      out[k++] = a_ + (t_ * c.x + m_ * c.y) * chord;
    }
    return k;
  }

  // The point of the circle farthest from p, when the radius is moderate.
  bool farthest_from(Vec2<S> p, Vec2<S>& out) const {
    if (line() || d_.y < S(1e-6)) return false;  // nearly straight: never on the arc
    const S r = h_ / d_.y;
    const Vec2<S> c = a_ + m_ * r;
    const Vec2<S> v = c - p;
    const S len = band_detail::length(v);
    if (!(len > S(0))) return false;
    out = c + v * (r / len);
    return true;
  }

 private:
  Vec2<S> a_, b_, u_, n_, d_, t_, m_;
  S h_{};
  S psi_{};
};

namespace band_detail {

// Whether x, a point on gate e0 e1's line, lies on the gate segment (within
// 1/64 of its length). Inside R an arc passes from cell to cell only through
// gate segments; a gate line's other crossing lies off the segment (an arc of
// more than a half turn meets the line again) and bounds no cell.
template <class S>
bool on_gate_segment(Vec2<S> e0, Vec2<S> e1, Vec2<S> x) {
  const S f = frame_factor(e1 - e0);
  const Vec2<S> ge = (e1 - e0) * f;
  const S gl2 = ge.norm2();
  if (!(gl2 > S(0))) return true;
  const S t = ((x - e0) * f).dot(ge);
  const S slack = gl2 / S(64);
  return !(t < -slack) && !(t > gl2 + slack);
}

}  // namespace band_detail

// The largest distance from the stretch [from, to] of `arc` to the segment
// p0 p1 (see the top of this file for why these candidates suffice).
template <class S>
S stretch_to_edge(const ArcProbe<S>& arc, Vec2<S> from, Vec2<S> to, Vec2<S> p0, Vec2<S> p1) {
  const S lo = arc.sigma(from);
  const S hi = arc.sigma(to);
  S worst = max_of(band_detail::distance_to_edge(p0, p1, from), band_detail::distance_to_edge(p0, p1, to));
  if (arc.line()) return worst;  // a line's distance to a segment is convex
  auto consider = [&](Vec2<S> x) {
    const S s = arc.sigma(x);
    if (!(s < lo) && !(s > hi)) worst = max_of(worst, band_detail::distance_to_edge(p0, p1, x));
  };
  const Vec2<S> e = (p1 - p0) * (S(1) / band_detail::length(p1 - p0));
  Vec2<S> pts[2];
  const Vec2<S> ends[2] = {p0, p1};
  for (const Vec2<S>& base : ends) {
    const int m = arc.meet_line(base, e.perp(), pts);
    for (int t = 0; t < m; ++t) consider(pts[t]);
    Vec2<S> far{};
    if (arc.farthest_from(base, far)) consider(far);
  }
  const int m = arc.parallel_to(e, pts);
  for (int t = 0; t < m; ++t) consider(pts[t]);
  return worst;
}

// The deviation of the piece p_i -> p_j of region R with direction d and
// orientation orient (see fit/band/pair.hpp), in R's units.
template <class S>
S band_deviation(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j, Vec2<S> d, int orient) {
  const ArcProbe<S> arc(r.point(i), r.point(j), d, orient);
  S worst = S(0);
  Vec2<S> from = r.point(i);
  for (std::uint32_t k = i; k < j; ++k) {
    const Vec2<S> p0 = r.point(k);
    const Vec2<S> p1 = r.point(k + 1);
    Vec2<S> to = p1;
    if (k + 1 < j) {  // where the arc crosses gate k + 1
      Vec2<S> hits[2];
      const int m = arc.meet_line(p1, r.vertex(k + 1).b, hits);
      const S s_from = arc.sigma(from);
      // A valid piece meets the gate segment itself exactly once; the gate
      // line's other crossing lies off the segment and, on an arc of more
      // than a half turn, can sit next to p_i, where sigma is noise (0 or a
      // full turn). So a crossing on the segment wins over one off it.
      const Vec2<S> e0 = r.gate_end(k + 1, orient);
      const Vec2<S> e1 = r.gate_end(k + 1, -orient);
      auto on_gate = [&](Vec2<S> x) { return band_detail::on_gate_segment(e0, e1, x); };
      bool found = false;
      bool found_on_gate = false;
      for (int t = 0; t < m; ++t) {
        const S s = arc.sigma(hits[t]);
        if (!arc.on_arc(hits[t]) || s < s_from) continue;
        const bool g = on_gate(hits[t]);
        if (!found || (g && !found_on_gate) || (g == found_on_gate && s < arc.sigma(to))) {
          to = hits[t];
          found = true;
          found_on_gate = g;
        }
      }
    }
    worst = max_of(worst, stretch_to_edge(arc, from, to, p0, p1));
    from = to;
  }
  return worst;
}

}  // namespace kerf::fit
