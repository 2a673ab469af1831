// The band pair test's quick pass (fit/band/pair.hpp): is a whole slab, the
// points within `thickness` of a segment, outside the disc of a candidate
// arc? A chain of the region lies in such a slab around the segment between
// its ends (BandChainSlot::thickness), and most cells of a piece that fits
// lie well clear of it: one quadratic over the segment then stands for every
// point and segment of the chain.
//
// The arc runs from a to b; n is the chord's normal (b - a).perp() times
// the orientation, and d = (cos psi, sin psi) times any length <= 1 (as
// fit/detail/angle_set.hpp's direction_of gives). With A = (q - a).(q - b) and
// Y = (q - a).n, the power P = d.y A - d.x Y equals |d| sin(psi) times
// |q - c|^2 - R^2 (c, R the circle's centre and radius), and
// R sin(psi) = |b - a| / 2. A point q of the segment at least R + t from c
// puts every point within t of q outside the disc, and that holds when
//   P(q) >= |d| |b - a| t + d.y t^2,
// of which |b - a| t + d.y t^2 is an upper bound. Floating point only.
#pragma once

#include "kerf/geom/vec2.hpp"

namespace kerf::fit::band_detail {

template <class S>
class SlabTest {
 public:
  // chord = |b - a|.
  SlabTest(Vec2<S> a, Vec2<S> b, Vec2<S> n, S chord, Vec2<S> s0, Vec2<S> s1, S thickness)
      : thickness_(thickness), chord_(chord) {
    const Vec2<S> ds = s1 - s0;
    const Vec2<S> qa = s0 - a;
    const Vec2<S> qb = s0 - b;
    area0_ = qa.dot(qb);
    offset0_ = qa.dot(n);
    vd_ = ds.dot(qa + qb);  // twice ds.(s0 - mid): A(s0 + x ds) = area0 + x vd + x^2 dd
    dd_ = ds.norm2();
    dn_ = ds.dot(n);
  }

  // Is the whole slab outside the disc of direction d (with the margin)?
  bool clear_at(Vec2<S> d) const {
    const S margin = thickness_ * (chord_ + d.y * thickness_);
    return at_least(d.y * area0_ - d.x * offset0_, d.y * vd_ - d.x * dn_, d.y * dd_, margin);
  }

 private:
  // Is p0 + c1 x + c2 x^2 >= m for every x in [0, 1]? (False on NaN.)
  static bool at_least(S p0, S c1, S c2, S m) {
    if (!(p0 >= m) || !(p0 + c1 + c2 >= m)) return false;
    if (c2 > S(0) && c1 < S(0) && -c1 < S(2) * c2) return S(4) * c2 * (p0 - m) >= c1 * c1;
    return true;
  }

  S thickness_;
  S chord_;
  S area0_{}, offset0_{}, vd_{}, dd_{}, dn_{};
};

}  // namespace kerf::fit::band_detail
