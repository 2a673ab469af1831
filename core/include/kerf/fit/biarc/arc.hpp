// Biarcs: two circular arcs (lines as their limit) joined with a common
// tangent, from p1 with tangent t1 to p2 with tangent t2 (Drysdale, Rote,
// Sturm, section 3.2).
//
// An arc is kept as start a, end b and unit start tangent t, never by its
// centre: its signed curvature is kappa = 2 t x (b - a) / |b - a|^2 (0 for a
// line), its end tangent is t reflected in the chord, and x lies on its
// circle iff kappa |x - a|^2 - 2 t x (x - a) = 0.
//
// The joint circle J (Proposition 3.1): an arc p1 -> m with tangent t1 ends
// with t1 reflected in the chord p1 m, and the arc m -> p2 that ends with t2
// starts with t2 reflected in the chord m p2; the two agree exactly when the
// chords' inscribed angle at m is (phi2 - phi1) / 2 - pi, so m lies on a
// circle (or line) through p1 and p2. kerf parametrises J with the Moebius
// map (complex numbers)  m(lambda) = p1 + lambda k (p2 - p1) / (1 + lambda k),
// lambda real, k = exp(i (phi1 - phi2) / 2) (J's tangent at p1 is k times
// the chord): lambda = 0 is p1, lambda = infinity is p2, and the two signs
// of lambda are J's two arcs. One formula covers a circle and the line
// (t1 == t2: k real, J is the line through p1 and p2; the point lambda =
// -1/k is then at infinity). The fitter uses s in [0, 2]: s in [0, 1] is
// lambda = s / (1 - s) (p1 -> p2 on one arc), s in [1, 2] is lambda = -(2 -
// s) / (s - 1) (p2 -> p1 on the other).
//
// The degenerate cases of section 3.2: a joint at an end point (s = 0, 1 or
// 2) leaves one arc of length zero, and the biarc is G1 only when the other
// arc alone matches both tangents; when a single circle through p1 and p2
// has both tangents, that circle is J and every joint splits the same arc.
#pragma once

#include "kerf/fit/biarc/numeric.hpp"
#include "kerf/fit/biarc/tangent.hpp"
#include "kerf/geom/complex.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::fit {

template <class S>
struct ArcPart {
  Vec2<S> a{};  // start
  Vec2<S> b{};  // end
  Vec2<S> t{};  // unit start tangent

  S curvature() const {
    const Vec2<S> c = b - a;
    return c.x == S(0) && c.y == S(0) ? S(0) : biarc_detail::pencil_kappa(t, c);
  }
  Vec2<S> end_tangent() const { return reflect_in_chord(t, a, b); }
  bool empty() const { return a == b; }

  // Where x (on the circle) lies along the arc: 0 at a, growing to the end;
  // comparable only with other points of the same circle. A pseudo-angle of
  // half the turn for an arc, the distance along t for a line.
  S position(Vec2<S> x) const {
    // Scaled (exactly, by a power of two; fixed point only): the result is
    // a ratio, and short offsets would keep few bits.
    const Vec2<S> v = (x - a) * unit_scale(x - a, x - a);
    const S k = curvature();
    const S px = v.dot(t);
    if (k == S(0)) return px;
    const S py = max_of(S(0), v.dot(t.perp()) * (k > S(0) ? S(1) : S(-1)));
    if (px == S(0) && py == S(0)) return S(0);
    return S(1) - px / (Scalar<S>::abs(px) + py);
  }

  // The point a fraction u in [0, 1] of the way (not by length: the chord's
  // direction from a turns evenly in u between t and the chord).
  Vec2<S> at(S u) const {
    // Homogeneous in the chord: computed on it scaled to about 1 (fixed
    // point; the factor is 1 in floating point), then scaled back.
    const S f = unit_scale(b - a, b - a);
    const Vec2<S> c = (b - a) * f;
    const S tc = t.cross(c);
    if (tc == S(0)) return a + (b - a) * u;
    const Vec2<S> v = t * ((S(1) - u) * c.norm()) + c * u;
    // chord length 2 sin(alpha) / |kappa| along v, with kappa = 2 tc / |c|^2
    return a + v * (t.cross(v) * c.norm2() / (tc * v.norm2()) / f);
  }

  // Straight to within what segment() keeps: a sagitta below 1e-12 of
  // the chord; in fixed point a turn below 2^-24 rad (it leaves its chord
  // by less than 2^-26 of the chord, a few steps of the scaled problem).
  bool nearly_straight() const {
    const S ak = Scalar<S>::abs(curvature());
    if constexpr (biarc_detail::kFloating<S>) {
      return ak * (b - a).norm() < S(1e-12);
    } else {
      return ak * band_detail::length(b - a) < S(1.0 / 16777216.0);
    }
  }

  // Straight, but its tangent does not point along the chord to b: the
  // limit of circles through infinity (or a line run backwards), which no
  // cut can follow and segment() would turn into a reversed line. Where
  // p_i, p_j and both tangents lie on one line, with p_j behind p_i, every
  // joint gives such a part.
  bool backward_line() const {
    const Vec2<S> c = b - a;
    const S along = t.dot(c);
    if (along > S(0) || empty()) return false;
    // Cheap first: more than 45 degrees off the backward chord is no line.
    return !(Scalar<S>::abs(t.cross(c)) > -along) && nearly_straight();
  }

  // The arc as a path segment: a line when nearly_straight(). In fixed
  // point a line also when its radius reaches max_radius (its centre would
  // not be representable where the caller takes it).
  Segment<S> segment(S max_radius = Scalar<S>::infinity()) const {
    const S k = curvature();
    if (nearly_straight()) return Segment<S>::line(a, b);
    if constexpr (biarc_detail::kFloating<S>) {
      (void)max_radius;
    } else {
      if (!(Scalar<S>::abs(k) * max_radius > S(1))) return Segment<S>::line(a, b);
    }
    return Segment<S>::arc(a, b, a + t.perp() * (S(1) / k), k > S(0) ? 1 : -1);
  }
};

template <class S>
struct Biarc {
  ArcPart<S> first{};
  ArcPart<S> second{};
  S s{};  // the joint on J
};

template <class S>
class JointCircle {
 public:
  JointCircle(Vec2<S> p1, Vec2<S> t1, Vec2<S> p2, Vec2<S> t2) : p1_(p1), p2_(p2), t1_(t1), t2_(t2) {
    // z = t1 conj(t2) = exp(i (phi1 - phi2)); k = its square root, Re k >= 0.
    const Vec2<S> z{t1.dot(t2), t2.cross(t1)};
    Vec2<S> h = z.x > S(-0.5) ? Vec2<S>{S(1) + z.x, z.y} : Vec2<S>{z.y, S(1) - z.x};
    if (h.x < S(0)) h = -h;
    k_ = unit_of(h);
  }

  bool line() const { return k_.y == S(0); }
  Vec2<S> k() const { return k_; }

  Vec2<S> point(S s) const {
    const Vec2<S> d = p2_ - p1_;
    if (!(s > S(0)) || !(s < S(2))) return p1_;
    if (s == S(1)) return p2_;
    const bool near_p1 = s < S(0.5) || s > S(1.5);
    if (near_p1) {  // m = p1 + d w / (1 + w), w = lambda k
      const S lambda = s < S(1) ? s / (S(1) - s) : -(S(2) - s) / (s - S(1));
      const Vec2<S> w = k_ * lambda;
      return p1_ + complex_mul<S>(d, complex_div<S>(w, {S(1) + w.x, w.y}));
    }
    // m = p2 - d mu / (mu + k), mu = 1 / lambda
    const S mu = s < S(1) ? (S(1) - s) / s : -(s - S(1)) / (S(2) - s);
    return p2_ - complex_mul<S>(d, complex_div<S>({mu, S(0)}, {mu + k_.x, k_.y}));
  }

  // The biarc with its joint at point(s). Returns false when it is not G1
  // (a joint at an end point without a single matching arc), not finite,
  // or has a part that is a backward line (ArcPart::backward_line).
  bool biarc(S s, Biarc<S>& out) const {
    const Vec2<S> m = point(s);
    out.s = s;
    const S scale = band_detail::length(p2_ - p1_);
    if (!Scalar<S>::is_finite(m.x) || !Scalar<S>::is_finite(m.y) ||
        !(Scalar<S>::abs(m.x) + Scalar<S>::abs(m.y) < biarc_detail::far_joint<S>()))
      return false;
    const S at_end = biarc_detail::relative_reach(scale, S(1e-12), 4);
    const bool at_p1 = biarc_detail::near(m, p1_, at_end);
    const bool at_p2 = biarc_detail::near(m, p2_, at_end);
    if (at_p1 || at_p2) {
      // One arc from p1 to p2; it must match both tangents.
      const ArcPart<S> whole{p1_, p2_, t1_};
      if (band_detail::length(whole.end_tangent() - t2_) > biarc_detail::unit_slack<S>(S(1e-9))) return false;
      out.first = at_p1 ? ArcPart<S>{p1_, p1_, t1_} : whole;
      out.second = at_p1 ? whole : ArcPart<S>{p2_, p2_, t2_};
      return !whole.backward_line();
    }
    out.first = {p1_, m, t1_};
    out.second = {m, p2_, out.first.end_tangent()};
    if (out.first.backward_line() || out.second.backward_line()) return false;
    // m is on J only up to rounding, which a joint very near an end point
    // magnifies: refuse a biarc whose end tangent strays from t2.
    return band_detail::length(out.second.end_tangent() - t2_) <= biarc_detail::unit_slack<S>(S(1e-10));
  }

 private:
  Vec2<S> p1_, p2_, t1_, t2_;
  Vec2<S> k_{};
};

}  // namespace kerf::fit
