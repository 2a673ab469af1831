// Definitions behind fit/biarc.hpp. Included by the translation unit that
// instantiates them for every scalar type (src/biarc.cpp).
#pragma once

#include <type_traits>  // freestanding

#include "kerf/fit/biarc.hpp"
#include "kerf/fit/biarc/deviation.hpp"
#include "kerf/fit/biarc/joints.hpp"
#include "kerf/fit/biarc/reach.hpp"
#include "kerf/fit/detail/fit_impl.hpp"

namespace kerf::fit {

namespace biarc_detail {

// The power of two the fitter scales the points by (fixed point: into
// [-1, 1), like the band and vertex fitters; floating point: 1).
template <class S>
S problem_factor(Span<const Vec2<S>> pts) {
  if constexpr (kFloating<S>) {
    (void)pts;
    return S(1);
  } else {
    return detail::scale_factor(pts);
  }
}

// x (a point or a length) of the scaled problem in the input's units.
template <class T, class S>
T unscale(T x, S factor) {
  if constexpr (kFloating<S>) {
    (void)factor;
    return x;
  } else {
    return x * (S(1) / factor);
  }
}

// The largest radius (in the pair's frame) whose centre stays within
// 2^30 in the input's units: beyond it a fixed-point arc is output as its
// chord (ArcPart::segment). No limit in floating point.
template <class S>
S max_radius(const PairFrame<S>& fr, S factor) {
  if constexpr (kFloating<S>) {
    (void)fr;
    (void)factor;
    return Scalar<S>::infinity();
  } else {
    return S(1L << 29) * fr.g * factor;
  }
}

// The caller's joint sets (BiarcOptions::joints); floating point only (the
// fitter refuses them in fixed point before it gets here).
template <class S>
bool given_joints(BiarcJointsFn joints, const BandRegion<S>& r, std::uint32_t i, std::uint32_t j,
                  Vec2<S> ti, Vec2<S> tj, JointSet<S>& set) {
  if constexpr (std::is_same_v<S, double>) {
    return joints(r, i, j, ti, tj, set);
  } else {
    (void)joints;
    (void)r;
    (void)i;
    (void)j;
    (void)ti;
    (void)tj;
    set.clear();
    return false;
  }
}

// pts in the scaled problem, x in the pair's frame f.
template <class S>
S point_deviation(Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, Vec2<S> x,
                  const PairFrame<S>& f) {
  // Squared distances, one square root at the end.
  S best = (x - f.map(pts[i])).norm2();
  for (std::uint32_t k = i; k < j; ++k) {
    const Vec2<S> pk = f.map(pts[k]);
    const Vec2<S> pk1 = f.map(pts[k + 1]);
    const Vec2<S> d = pk1 - pk;
    const Vec2<S> v = x - pk;
    const S t = d.dot(v);
    const S len2 = d.norm2();
    S d2;
    if (t <= S(0)) {
      d2 = v.norm2();
    } else if (t >= len2) {
      d2 = (x - pk1).norm2();
    } else {
      const S c = d.cross(v);
      d2 = c * c / len2;
    }
    best = min_of(best, d2);
  }
  return Scalar<S>::sqrt(best);
}

// The sampled deviation of b (in frame f) from the polyline p_i..p_j, in
// the frame's units.
template <class S>
S sampled_deviation(Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, const Biarc<S>& b,
                    const PairFrame<S>& f) {
  // Samples per arc grow with the span, so that each cell sees several, up
  // to 32 cells' worth: each costs O(j - i), and this only ranks joints (the
  // reported error is certified, fit/biarc/deviation.hpp).
  const std::uint32_t span = j - i < 32 ? j - i : 32;
  const std::uint32_t m = 8 + 4 * span;
  S worst = S(0);
  const ArcPart<S>* arcs[2] = {&b.first, &b.second};
  for (const ArcPart<S>* arc : arcs) {
    if (arc->empty()) continue;
    for (std::uint32_t q = 0; q <= m; ++q)
      worst = max_of(worst, point_deviation(pts, i, j, arc->at(S(q) / S(m)), f));
  }
  return worst;
}

// The deviation used to choose a joint (sampled: the certified one of
// fit/biarc/deviation.hpp is computed for the result), plus a penalty: an
// arc of a radius far below the band's width is a corner to the machine
// (and may be shorter than its resolution), so where the band lets the
// joint move, radii below the width cost more than any deviation.
// Everything in the pair's frame f (widest too).
template <class S>
S score(const JointCircle<S>& jc, Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, S s,
        S widest, Biarc<S>& b, const PairFrame<S>& f) {
  if (!jc.biarc(s, b)) return Scalar<S>::infinity();
  S tight = S(0);
  const ArcPart<S>* arcs[2] = {&b.first, &b.second};
  for (const ArcPart<S>* arc : arcs) {
    const S k = Scalar<S>::abs(arc->curvature());
    if (!arc->empty() && k * widest > S(1)) tight = max_of(tight, widest - S(1) / k);
  }
  return sampled_deviation(pts, i, j, b, f) + S(1000) * tight;
}

// The joint of p_i -> p_j with the smallest score, inside the proven-valid
// set: `samples` joints spread over each of its intervals, then a
// golden-section search between the best one's neighbours (kept inside its
// interval). Validity is exact already; the chosen joint is tested once
// more in full, and the verified joint s0 stands in should rounding fail it.
template <class S>
Biarc<S> best_joint(const BiarcJoints<S>& bj, const JointSet<S>& set, Span<const Vec2<S>> pts,
                    std::uint32_t i, std::uint32_t j, std::uint32_t samples, S widest, S s0) {
  const JointCircle<S>& jc = bj.circle();
  const PairFrame<S>& fr = bj.check().frame();
  widest = fr.length(widest);
  Biarc<S> b;
  Biarc<S> best;
  S best_score = score(jc, pts, i, j, s0, widest, best, fr);
  for (int q = 0; q < set.size(); ++q) {
    const S lo = set[q].lo;
    const S hi = set[q].hi;
    const S step = (hi - lo) / S(samples);
    S at = lo + step / S(2);
    S at_score = Scalar<S>::infinity();
    for (std::uint32_t c = 0; c < samples; ++c) {
      const S x = lo + step * (S(c) + S(0.5));
      const S f = score(jc, pts, i, j, x, widest, b, fr);
      if (f < at_score) {
        at_score = f;
        at = x;
      }
    }
    S a = max_of(lo, at - step);
    S z = min_of(hi, at + step);
    const S g = S(0.6180339887498949);
    S x1 = z - g * (z - a);
    S x2 = a + g * (z - a);
    S f1 = score(jc, pts, i, j, x1, widest, b, fr);
    S f2 = score(jc, pts, i, j, x2, widest, b, fr);
    for (int it = 0; it < 30; ++it) {
      if (f1 < f2) {
        z = x2;
        x2 = x1;
        f2 = f1;
        x1 = z - g * (z - a);
        f1 = score(jc, pts, i, j, x1, widest, b, fr);
      } else {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + g * (z - a);
        f2 = score(jc, pts, i, j, x2, widest, b, fr);
      }
    }
    const S xs[2] = {at, f1 < f2 ? x1 : x2};
    for (const S x : xs) {
      if (!(x > lo && x < hi)) continue;
      const S f = score(jc, pts, i, j, x, widest, b, fr);
      if (f < best_score && bj.check().valid(b)) {
        best_score = f;
        best = b;
      }
    }
  }
  return best;
}

}  // namespace biarc_detail

template <class S>
S biarc_deviation(Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, const Biarc<S>& b) {
  return biarc_detail::sampled_deviation(pts, i, j, b, biarc_detail::PairFrame<S>{});
}

template <class S>
Result<Fit<S>> fit_biarc_min_count(Span<const Vec2<S>> pts, Span<const Vec2<S>> tangents,
                                   Span<const BandWidth<S>> widths, BiarcOptions opts,
                                   BiarcWorkspace<S> ws, Span<BiarcPiece<S>> out) {
  std::size_t where = 0;
  if (const Status s = validate_points(pts, where); s != Status::ok) return s;
  const std::size_t n = pts.size();
  if (tangents.size() != n || widths.size() != n || opts.samples == 0 ||
      opts.samples > kBiarcMaxSamples)
    return Status::invalid_argument;
  S widest = S(0);
  for (std::size_t k = 0; k < n; ++k) {
    const BandWidth<S>& w = widths[k];
    if (!Scalar<S>::is_finite(w.left) || !Scalar<S>::is_finite(w.right) || !(w.left > S(0)) ||
        !(w.right > S(0)))
      return Status::invalid_argument;
    widest = max_of(widest, max_of(w.left, w.right));
    const Vec2<S> t = tangents[k];
    if (!Scalar<S>::is_finite(t.x) || !Scalar<S>::is_finite(t.y) ||
        Scalar<S>::abs(t.norm() - S(1)) > biarc_detail::unit_slack<S>(S(1e-9)))
      return Status::invalid_argument;
  }
  // The caller's joint sets (the tests' referee) run in floating point only.
  if (!std::is_same_v<S, double> && opts.joints != nullptr) return Status::invalid_argument;
  if (ws.words.size() < biarc_workspace_words(n) || ws.vertices.size() < n || ws.points.size() < n)
    return Status::capacity_exceeded;
  const auto count = static_cast<std::uint32_t>(n);
  // Fixed point solves the problem scaled by a power of two into [-1, 1)
  // (exact); floating point keeps the input's scale (factor 1).
  const S factor = biarc_detail::problem_factor(pts);
  for (std::size_t k = 0; k < n; ++k) ws.points[k] = pts[k] * factor;
  const Span<const Vec2<S>> scaled(ws.points.data(), n);
  BandRegion<S> region(scaled.data(), count, ws.vertices.data());
  if (const Status s = region.build(widths.data(), factor); s != Status::ok) return s;

  // Breadth-first over the DAG in index order: dist[j] the fewest biarcs to
  // p_j, prev[j] the start of the last one.
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::uint32_t* dist = ws.words.data();
  std::uint32_t* prev = dist + n;
  std::uint32_t* back = prev + n;  // B_j of fit/biarc/reach.hpp
  std::uint32_t* back_min = back + n;  // min of B over j..n-1
  for (std::size_t k = 0; k < n; ++k) dist[k] = prev[k] = kNone;
  dist[0] = 0;
  if (!opts.exact) {
    for (std::uint32_t k = 0; k < count; ++k) back[k] = backward_reach(region, k, tangents[k]);
    back_min[n - 1] = back[n - 1];
    for (std::uint32_t k = count - 1; k-- > 0;) back_min[k] = back[k] < back_min[k + 1] ? back[k] : back_min[k + 1];
  }
  JointSet<S> set;
  Biarc<S> b;
  bool overflow = false;
  for (std::uint32_t i = 0; i + 1 < count; ++i) {
    if (dist[i] == kNone) continue;
    // F_i of fit/biarc/reach.hpp, extended only as far as a j needs it.
    KappaMeet<S> meet;
    std::uint32_t fwd = i;
    bool fwd_final = false;
    auto reaches = [&](std::uint32_t need) {  // F_i >= need?
      while (fwd < need && !fwd_final) {
        const std::uint32_t k = fwd + 1;
        if (meet.meet(pencil_range(region.point(i), tangents[i], region.gate_end(k, -1),
                                   region.gate_end(k, 1)))) {
          fwd = k;
        } else {
          fwd_final = true;
        }
      }
      return fwd >= need;
    };
    // Nothing through p_i can shorten the path to the last point.
    if (dist[n - 1] != kNone && dist[n - 1] <= dist[i] + 1) continue;
    // The last point first: if p_i reaches it, no other end of p_i can
    // lead to a shorter path (a long straight or circular run ends here).
    auto test = [&](std::uint32_t j) {
      if (!opts.exact && back[j] > i + 1 && !reaches(back[j] - 1)) return false;
      const BiarcJoints<S> bj(region, i, j, tangents[i], tangents[j]);
      S s{};
      if (opts.joints != nullptr) {
        if (!biarc_detail::given_joints(opts.joints, region, i, j, tangents[i], tangents[j], set)) {
          overflow = true;
          return false;
        }
        return bj.verified(set, s, b);
      }
      // A valid joint among a few likely ones proves the pair; otherwise
      // the exact set decides (so no valid pair is missed).
      bool valid = bj.quick_yes(s);
      if (!valid) {
        if (!bj.compute(set)) {
          overflow = true;
          return false;
        }
        valid = bj.verified(set, s, b);
      }
      return valid;
    };
    if (test(count - 1)) {
      dist[n - 1] = dist[i] + 1;
      prev[n - 1] = i;
      continue;
    }
    if (overflow) return Status::capacity_exceeded;
    for (std::uint32_t j = i + 1; j + 1 < count; ++j) {
      // No biarc from p_i reaches any p_j' with j' >= j (B_j' - 1 > F_i).
      if (!opts.exact && back_min[j] > i + 1 && !reaches(back_min[j] - 1)) break;
      const bool reached = dist[j] != kNone && dist[j] <= dist[i] + 1;
      if (!reached && test(j)) {
        dist[j] = dist[i] + 1;
        prev[j] = i;
      }
      if (overflow) return Status::capacity_exceeded;
      if (region.vertex(j).barrier) break;  // nothing passes through it
    }
  }
  if (dist[n - 1] == kNone) return Status::infeasible;
  const std::uint32_t pieces = dist[n - 1];
  if (out.size() < pieces) return Status::capacity_exceeded;

  Fit<S> fit{};
  fit.pieces = pieces;
  fit.tol = widest;
  std::uint32_t j = count - 1;
  for (std::uint32_t p = pieces; p-- > 0;) {
    const std::uint32_t i = prev[j];
    const BiarcJoints<S> bj(region, i, j, tangents[i], tangents[j]);
    S s{};
    const bool got = opts.joints != nullptr
                         ? biarc_detail::given_joints(opts.joints, region, i, j, tangents[i], tangents[j], set)
                         : bj.compute(set);
    if (!got) return Status::capacity_exceeded;
    // The pair was found valid: by a joint of its set or by a quick joint.
    // (Both agree but for rounding, seen only when p_i and p_j nearly
    // coincide, as where a closed path meets its start.)
    if (!bj.verified(set, s, b) && !bj.quick_yes(s)) return Status::infeasible;
    const Biarc<S> best = biarc_detail::best_joint(bj, set, scaled, i, j, opts.samples, widest * factor, s);
    // Back from the pair's frame and the scaled problem to the input.
    const biarc_detail::PairFrame<S>& fr = bj.check().frame();
    auto to_input = [&](Vec2<S> x) { return biarc_detail::unscale(fr.unmap(x), factor); };
    const S max_radius = biarc_detail::max_radius(fr, factor);
    BiarcPiece<S>& piece = out[p];
    piece.first = i;
    piece.last = j;
    piece.joint = to_input(best.first.b);
    for (int a = 0; a < 2; ++a) {
      Segment<S> g = (a == 0 ? best.first : best.second).segment(max_radius);
      g.start = a == 0 ? pts[i] : piece.joint;
      g.end = a == 0 ? piece.joint : pts[j];
      if (g.is_arc()) g.centre = to_input(g.centre);
      piece.arc[a] = g;
    }
    piece.tangent[0] = tangents[i];
    piece.tangent[1] = best.second.t;
    piece.tangent[2] = best.second.end_tangent();
    piece.error = biarc_detail::unscale(biarc_certified_deviation(region, i, j, best, fr), factor);
    fit.max_error = max_of(fit.max_error, piece.error);
    j = i;
  }
  return fit;
}

}  // namespace kerf::fit
