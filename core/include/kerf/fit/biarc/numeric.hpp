// Scale-aware arithmetic for the biarc fitter, in one place.
//
// The fitter scales its points into [-1, 1) by a power of two
// (fit/biarc/fit_impl.hpp). kerf::Fixed then has 2^-32 absolute
// resolution; a pair p_i -> p_j whose chord is a few hundredths long would
// square its lengths (curvatures, the quadratics of the one-segment test)
// down to a few significant bits. So each pair is solved in its own frame:
// origin p_i, lengths times the power of two that brings the pair's extent
// to about 1 (PairFrame). The shift and the power-of-two factor are exact
// in fixed point, so the frame is the same problem, not an approximation.
// For floating point everything here is the identity, bit for bit.
#pragma once

#include <type_traits>  // freestanding

#include "kerf/fit/band/numeric.hpp"
#include "kerf/fit/band/region.hpp"

namespace kerf::fit::biarc_detail {

template <class S>
inline constexpr bool kFloating = std::is_floating_point_v<S>;

// A pair's frame: x' = (x - origin) g. Identity in floating point.
template <class S>
struct PairFrame {
  Vec2<S> origin{};
  S g = S(1);

  // The frame of the pair i -> j of region r: g brings the largest offset
  // of p_i..p_j (plus the widest gate) from p_i to about 1, at most 2^10.
  static PairFrame of(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j) {
    PairFrame f;
    if constexpr (!kFloating<S>) {
      const Vec2<S> o = r.point(i);
      S m = S(0);
      for (std::uint32_t k = i; k <= j; ++k) {
        const Vec2<S> v = r.point(k) - o;
        const BandVertex<S>& w = r.vertex(k);
        const S reach = max_of(w.gate_left, w.gate_right);
        m = max_of(m, max_of(Scalar<S>::abs(v.x), Scalar<S>::abs(v.y)) + reach);
      }
      f.origin = o;
      f.g = m > S(0) ? band_detail::power_for(m, 10) : S(1);
    } else {
      (void)r;
      (void)i;
      (void)j;
    }
    return f;
  }

  Vec2<S> map(Vec2<S> x) const {
    if constexpr (kFloating<S>) return x;
    else return (x - origin) * g;
  }
  Vec2<S> unmap(Vec2<S> x) const {
    if constexpr (kFloating<S>) return x;
    else return x * (S(1) / g) + origin;
  }
  S length(S l) const { return l * g; }
  S unlength(S l) const { return l / g; }
};

// A point of J far beyond this (in the pair's frame) is no joint: the
// region lies within a few units of the origin there. Fixed point keeps
// room for its squares.
template <class S>
constexpr S far_joint() {
  if constexpr (kFloating<S>) return S(1e300);
  else return S(4096);
}

// How far a unit vector may stray from another (or from length 1) by
// rounding alone: 1e-10 in double; in fixed point 2^-20 (its unit vectors
// carry a few steps of 2^-32 each, and a chord a few thousand steps long
// turns its direction by that much).
template <class S>
constexpr S unit_slack(S floating) {
  if constexpr (kFloating<S>) return floating;
  else return S(1.0 / 1048576.0);
}

// A length `rel` of `scale` in floating point; in fixed point at least
// `steps` of the resolution (below that the product rounds to nothing).
template <class S>
S relative_reach(S scale, S rel, int steps) {
  if constexpr (kFloating<S>) {
    (void)steps;
    return scale * rel;
  } else {
    const S r = scale * rel;
    const S floor = Scalar<S>::epsilon() * S(steps);
    return r > floor ? r : floor;
  }
}

// 2 t x v / |v|^2, the curvature of the pencil (at the origin of v, along
// unit t) through the end of v, with v first brought to about 1.
template <class S>
S pencil_kappa(Vec2<S> t, Vec2<S> v) {
  if constexpr (kFloating<S>) {
    return S(2) * t.cross(v) / v.norm2();
  } else {
    const S m = max_of(Scalar<S>::abs(v.x), Scalar<S>::abs(v.y));
    if (!(m > S(0))) return Scalar<S>::infinity();
    const S f = Scalar<S>::normaliser(m);
    const Vec2<S> w = v * f;
    return S(2) * t.cross(w) / w.norm2() * f;
  }
}

// |a - b| <= reach along both axes (fixed point), or |a - b| <= reach.
template <class S>
bool near(Vec2<S> a, Vec2<S> b, S reach) {
  if constexpr (kFloating<S>) return (a - b).norm() <= reach;
  else return band_detail::within(a, b, reach);
}

}  // namespace kerf::fit::biarc_detail
