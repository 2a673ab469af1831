// How far a biarc from p_i can possibly reach: a proven bound that lets the
// fitter skip far pairs without testing them (it replaces an earlier
// "stop after 16 + reach failures" heuristic, which was not proven).
//
// R is a chain of cells joined at the gates, so a biarc p_i -> p_j with
// its joint in cell c (i <= c < j) has a first arc from p_i that crosses
// every gate g_{i+1}..g_c, and a second arc that crosses g_{c+1}..g_{j-1}.
// An arc from p_i is a circle of the pencil tangent to t_i at p_i, one per
// curvature kappa, and it meets gate g_k only if kappa lies in the range of
// kappa(x) = 2 t_i x (x - p_i) / |x - p_i|^2 over g_k's points (an interval:
// its ends' values and, where the gate's line touches a pencil circle
// inside the gate, that circle's). So
//   F_i = the last k such that the ranges of g_{i+1}..g_k still share a kappa
// bounds the cell of the joint from above (c <= F_i), and likewise
//   B_j = the first k such that the ranges of the pencil at p_j (along -t_j)
//         over g_k..g_{j-1} share one
// from below (c + 1 >= B_j). A valid biarc p_i -> p_j needs B_j <= F_i + 1.
// This is the forward part of the circular visibility region W_i of the
// paper's Lemma 3.3 (an interval of curvatures that shrinks gate by gate),
// relaxed to "meets the gate" instead of "reaches it inside R": a superset,
// so the bound is safe, and cheap.
#pragma once

#include <cstdint>

#include "kerf/fit/band/region.hpp"
#include "kerf/fit/biarc/numeric.hpp"

namespace kerf::fit {

template <class S>
struct KappaRange {
  S lo{};
  S hi{};
  bool all = false;  // unbounded: the gate passes through p
};

// The range of pencil curvatures (pencil at p along unit t) over the
// segment q1 q2, widened by a relative margin so that rounding never makes
// it narrower than the truth.
template <class S>
KappaRange<S> pencil_range(Vec2<S> p, Vec2<S> t, Vec2<S> q1, Vec2<S> q2) {
  KappaRange<S> r;
  const Vec2<S> e = q2 - q1;
  const S len = band_detail::length(e);
  auto kappa = [&](Vec2<S> x) { return biarc_detail::pencil_kappa(t, x - p); };
  const Vec2<S> v1 = q1 - p;
  const Vec2<S> v2 = q2 - p;
  const S len1 = band_detail::length(v1);
  const S len2 = band_detail::length(v2);
  const S scale = max_of(len1, len2);
  if (!(scale > S(0))) {
    r.all = true;
    return r;
  }
  if (len > S(0)) {
    const Vec2<S> u = e * (S(1) / len);
    const Vec2<S> n = u.perp();
    const S a = n.dot(p - q1);
    const S along = u.dot(p - q1);
    // The segment passes through (or within rounding of) p: kappa unbounded.
    const S near = biarc_detail::relative_reach(scale, S(1e-9), 4);
    if (Scalar<S>::abs(a) <= near && along >= -near && along <= len + near) {
      r.all = true;
      return r;
    }
  } else if (len1 <= biarc_detail::relative_reach(scale, S(1e-9), 4)) {
    r.all = true;
    return r;
  }
  r.lo = r.hi = kappa(q1);
  const S k2 = kappa(q2);
  r.lo = min_of(r.lo, k2);
  r.hi = max_of(r.hi, k2);
  if (len > S(0)) {
    const Vec2<S> u = e * (S(1) / len);
    const Vec2<S> n = u.perp();
    const S a = n.dot(p - q1);
    const S b = n.dot(t.perp());
    if (a != S(0)) {
      const S signs[2] = {S(1), S(-1)};
      for (const S sign : signs) {
        const S k = (sign - b) / a;
        if (k == S(0)) continue;
        const Vec2<S> c = p + t.perp() * (S(1) / k);  // the circle's centre
        const S at = u.dot(c - q1);                    // its touching point along the gate
        if (at >= S(0) && at <= len) {
          r.lo = min_of(r.lo, k);
          r.hi = max_of(r.hi, k);
        }
      }
    }
  }
  // Rounding: widen by a little of the range and of the curvature scale
  // 1 / scale (both relative, no absolute tolerance).
  // Fixed point: 2^-20 instead of 1e-9, and of 1 / the nearer end too (a
  // curvature through a point at distance l carries ~2^-31 / l).
  const S big = max_of(Scalar<S>::abs(r.lo), Scalar<S>::abs(r.hi));
  S pad;
  if constexpr (biarc_detail::kFloating<S>) {
    pad = (r.hi - r.lo) * S(1e-6) + S(1e-9) * (big + S(1) / scale);
  } else {
    const S nearer = min_of(len1, len2);
    const S inv = nearer > S(0) ? S(1) / nearer : S(1) / scale;
    pad = (r.hi - r.lo) * S(1e-6) + (big + inv) / S(1048576);
  }
  r.lo = r.lo - pad;
  r.hi = r.hi + pad;
  return r;
}

// The running intersection of pencil ranges.
template <class S>
struct KappaMeet {
  S lo{};
  S hi{};
  bool bounded = false;
  // Intersects with r; false once empty.
  bool meet(const KappaRange<S>& r) {
    if (r.all) return true;
    if (!bounded) {
      lo = r.lo;
      hi = r.hi;
      bounded = true;
      return true;
    }
    lo = max_of(lo, r.lo);
    hi = min_of(hi, r.hi);
    return !(lo > hi);
  }
};

// F_i (see above), looking no further than `limit` (inclusive).
template <class S>
std::uint32_t forward_reach(const BandRegion<S>& r, std::uint32_t i, Vec2<S> ti,
                            std::uint32_t limit) {
  KappaMeet<S> m;
  for (std::uint32_t k = i + 1; k <= limit; ++k) {
    if (!m.meet(pencil_range(r.point(i), ti, r.gate_end(k, -1), r.gate_end(k, 1)))) return k - 1;
  }
  return limit;
}

// B_j (see above).
template <class S>
std::uint32_t backward_reach(const BandRegion<S>& r, std::uint32_t j, Vec2<S> tj) {
  KappaMeet<S> m;
  for (std::uint32_t k = j; k-- > 0;) {
    if (!m.meet(pencil_range(r.point(j), -tj, r.gate_end(k, -1), r.gate_end(k, 1)))) return k + 1;
  }
  return 0;
}

}  // namespace kerf::fit
