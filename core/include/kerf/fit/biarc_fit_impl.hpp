// Definitions behind fit/biarc_fit.hpp. Included by the one translation unit
// per scalar type that instantiates them (src/biarc_double.cpp).
#pragma once

#include "kerf/fit/biarc_fit.hpp"
#include "kerf/fit/biarc_valid.hpp"

namespace kerf::fit {

namespace biarc_detail {

template <class S>
struct Pair {
  const BandRegion<S>& region;
  Span<const Vec2<S>> tangents;
  std::uint32_t samples;
  S widest;  // the largest width: R lies within it of the polyline

  S sample(std::uint32_t q) const { return S(2) * (S(q) + S(0.5)) / S(samples); }

  // Some valid joint of p_i -> p_j; its s through `found`. First the
  // samples; when none is valid, the valid joints may still form an interval
  // narrower than the samples' spacing (an S-curve fitted closely, J a line),
  // so around the two local minima of a cheap measure of how near the
  // biarcs come to the polyline (the joint and the arcs' middles), when the
  // measure could fall to about the band's width there, a scan 8 times
  // finer and a golden-section search on the measure look for one, each
  // probe tested exactly.
  bool any(std::uint32_t i, std::uint32_t j, S& found) const;
  bool refine(const BiarcCheck<S>& check, const JointCircle<S>& jc, std::uint32_t i,
              std::uint32_t j, S* near, S& found) const;
};

template <class S>
S point_deviation(Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, Vec2<S> x) {
  // Squared distances, one square root at the end.
  S best = (x - pts[i]).norm2();
  for (std::uint32_t k = i; k < j; ++k) {
    const Vec2<S> d = pts[k + 1] - pts[k];
    const Vec2<S> v = x - pts[k];
    const S t = d.dot(v);
    const S len2 = d.norm2();
    S d2;
    if (t <= S(0)) {
      d2 = v.norm2();
    } else if (t >= len2) {
      d2 = (x - pts[k + 1]).norm2();
    } else {
      const S c = d.cross(v);
      d2 = c * c / len2;
    }
    best = min_of(best, d2);
  }
  return Scalar<S>::sqrt(best);
}

// The cheap measure of how far the biarc at s strays (huge when it is not
// one).
template <class S>
S nearness(const JointCircle<S>& jc, Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, S s,
           Biarc<S>& b) {
  if (!(s > S(0) && s < S(2)) || !jc.biarc(s, b)) return S(1e300);
  S d = point_deviation(pts, i, j, b.first.b);
  d = max_of(d, point_deviation(pts, i, j, b.first.at(S(0.5))));
  return max_of(d, point_deviation(pts, i, j, b.second.at(S(0.5))));
}

template <class S>
bool Pair<S>::any(std::uint32_t i, std::uint32_t j, S& found) const {
  const BiarcCheck<S> check(region, i, j);
  if (!check.ends(tangents[i], tangents[j])) return false;
  const JointCircle<S> jc(region.point(i), tangents[i], region.point(j), tangents[j]);
  // The samples in bit-reversed order (the middle of each of J's arcs
  // first), tested in growing batches: a valid pair usually succeeds in
  // the first, and within a batch fit/biarc_valid.hpp builds each cell's
  // chains once for all.
  constexpr std::uint32_t kMax = kBiarcMaxSamples;  // (on the stack: ~7 KiB for doubles)
  Biarc<S> b[kMax];
  bool alive[kMax];
  std::uint32_t order[kMax];
  std::uint32_t m = 0;
  std::uint32_t bits = 0;
  while ((1u << bits) < samples) ++bits;
  for (std::uint32_t t = 0; t < (1u << bits); ++t) {
    std::uint32_t q = 0;
    for (std::uint32_t c = 0; c < bits; ++c) q |= ((t >> c) & 1u) << (bits - 1 - c);
    if (q < samples) order[m++] = q;
  }
  // The cheap measure first: a biarc whose joint or middles lie farther than
  // the widest width from the polyline is outside R (R lies in the band).
  // Cheaper still: a point farther than that from the box around p_i..p_j
  // (the measure then takes that distance, plus the width so it fails).
  const Span<const Vec2<S>> pts(&region.point(0), region.size());
  Vec2<S> lo = pts[i];
  Vec2<S> hi = pts[i];
  for (std::uint32_t k = i + 1; k <= j; ++k) {
    lo = {min_of(lo.x, pts[k].x), min_of(lo.y, pts[k].y)};
    hi = {max_of(hi.x, pts[k].x), max_of(hi.y, pts[k].y)};
  }
  auto outside = [&](Vec2<S> x) {
    const S dx = max_of(max_of(lo.x - x.x, x.x - hi.x), S(0));
    const S dy = max_of(max_of(lo.y - x.y, x.y - hi.y), S(0));
    return max_of(dx, dy);
  };
  S near[kMax];
  for (std::uint32_t from = 0, size = 4; from < m; from += size, size *= 4) {
    const std::uint32_t count = from + size < m ? size : m - from;
    for (std::uint32_t q = 0; q < count; ++q) {
      const std::uint32_t at = order[from + q];
      if (!jc.biarc(sample(at), b[q])) {
        near[at] = S(1e300);
      } else {
        const S off = max_of(outside(b[q].first.b),
                             max_of(outside(b[q].first.at(S(0.5))), outside(b[q].second.at(S(0.5)))));
        near[at] = off > widest ? off + widest : nearness(jc, pts, i, j, sample(at), b[q]);
      }
      alive[q] = near[at] <= widest;
    }
    if (check.filter(b, alive, count) == 0) continue;
    for (std::uint32_t q = 0; q < count; ++q) {
      if (alive[q]) {
        found = b[q].s;
        return true;
      }
    }
  }
  return refine(check, jc, i, j, near, found);
}

template <class S>
bool Pair<S>::refine(const BiarcCheck<S>& check, const JointCircle<S>& jc, std::uint32_t i,
                     std::uint32_t j, S* near, S& found) const {
  const Span<const Vec2<S>> pts(&region.point(0), region.size());
  Biarc<S> b;
  const std::uint32_t m = samples;
  // The two local minima that come nearest.
  std::uint32_t best[2] = {m, m};
  for (std::uint32_t q = 0; q < m; ++q) {
    const S l = near[q == 0 ? m - 1 : q - 1];
    const S r = near[q + 1 == m ? 0 : q + 1];
    if (near[q] > l || near[q] > r || !(near[q] < S(1e299))) continue;
    if (best[0] == m || near[q] < near[best[0]]) {
      best[1] = best[0];
      best[0] = q;
    } else if (best[1] == m || near[q] < near[best[1]]) {
      best[1] = q;
    }
  }
  const S w = widest;
  const S step = S(2) / S(m);
  const S g = S(0.6180339887498949);
  for (std::uint32_t c : best) {
    if (c == m) continue;
    // Worth a search only when the measure, falling at the rate it does
    // towards a neighbour, could come down to about the band's width.
    const S l = near[c == 0 ? m - 1 : c - 1];
    const S r = near[c + 1 == m ? 0 : c + 1];
    const S fall = max_of(Scalar<S>::abs(l - near[c]), Scalar<S>::abs(r - near[c]));
    if (near[c] - fall > w) continue;
    const S s0 = sample(c);
    // A finer scan between the neighbouring samples, then the search.
    for (int q = 1; q < 16; ++q) {
      const S x = s0 - step + step * S(q) / S(8);
      if (nearness(jc, pts, i, j, x, b) <= w && check.valid(b)) {
        found = x;
        return true;
      }
    }
    S lo = s0 - step;
    S hi = s0 + step;
    S x1 = hi - g * (hi - lo);
    S x2 = lo + g * (hi - lo);
    S f1 = nearness(jc, pts, i, j, x1, b);
    S f2 = nearness(jc, pts, i, j, x2, b);
    for (int it = 0; it < 40; ++it) {
      const bool left = f1 < f2;
      const S x = left ? x1 : x2;
      if ((left ? f1 : f2) <= w && jc.biarc(x, b) && check.valid(b)) {
        found = x;
        return true;
      }
      if (left) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = nearness(jc, pts, i, j, x1, b);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = nearness(jc, pts, i, j, x2, b);
      }
    }
  }
  return false;
}

template <class S>
S score(const Pair<S>& pr, Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, S s,
        Biarc<S>& b) {
  const BiarcCheck<S> check(pr.region, i, j);
  const JointCircle<S> jc(pts[i], pr.tangents[i], pts[j], pr.tangents[j]);
  if (!(s > S(0) && s < S(2)) || !jc.biarc(s, b) || !check.valid(b)) return S(1e300);
  // An arc of a radius far below the band's width is a corner to the
  // machine (and may be shorter than its resolution): where the band lets
  // the joint move, radii below the width cost more than any deviation.
  S tight = S(0);
  const ArcPart<S>* arcs[2] = {&b.first, &b.second};
  for (const ArcPart<S>* arc : arcs) {
    const S k = Scalar<S>::abs(arc->curvature());
    if (!arc->empty() && k * pr.widest > S(1)) tight = max_of(tight, pr.widest - S(1) / k);
  }
  return biarc_deviation(pts, i, j, b) + S(1000) * tight;
}

// The joint of p_i -> p_j (known valid at s0) with the smallest deviation
// (arcs tighter than the band's width penalised, see score()): the best of
// the samples, then a golden-section search between its neighbours (an
// invalid joint scores as infinite).
template <class S>
Biarc<S> best_joint(const Pair<S>& pr, Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j,
                    S s0) {
  Biarc<S> b;
  Biarc<S> best;
  S best_dev = score(pr, pts, i, j, s0, best);
  S best_s = s0;
  for (std::uint32_t q = 0; q < pr.samples; ++q) {
    const S dev = score(pr, pts, i, j, pr.sample(q), b);
    if (dev < best_dev) {
      best_dev = dev;
      best_s = b.s;
      best = b;
    }
  }
  const S step = S(2) / S(pr.samples);
  S lo = best_s - step;
  S hi = best_s + step;
  const S g = S(0.6180339887498949);
  S x1 = hi - g * (hi - lo);
  S x2 = lo + g * (hi - lo);
  S f1 = score(pr, pts, i, j, x1, b);
  S f2 = score(pr, pts, i, j, x2, b);
  for (int it = 0; it < 30; ++it) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = score(pr, pts, i, j, x1, b);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = score(pr, pts, i, j, x2, b);
    }
  }
  const S mid = f1 < f2 ? x1 : x2;
  if (score(pr, pts, i, j, mid, b) < best_dev) best = b;
  return best;
}

}  // namespace biarc_detail

template <class S>
S biarc_deviation(Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, const Biarc<S>& b) {
  // Samples per arc grow with the span, so that each cell sees several.
  const std::uint32_t m = 8 + 4 * (j - i);
  S worst = S(0);
  const ArcPart<S>* arcs[2] = {&b.first, &b.second};
  for (const ArcPart<S>* arc : arcs) {
    if (arc->empty()) continue;
    for (std::uint32_t q = 0; q <= m; ++q)
      worst = max_of(worst, biarc_detail::point_deviation(pts, i, j, arc->at(S(q) / S(m))));
  }
  return worst;
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
        Scalar<S>::abs(t.norm() - S(1)) > S(1e-9))
      return Status::invalid_argument;
  }
  if (ws.words.size() < biarc_workspace_words(n) || ws.vertices.size() < n)
    return Status::capacity_exceeded;
  const auto count = static_cast<std::uint32_t>(n);
  BandRegion<S> region(pts.data(), count, ws.vertices.data());
  if (const Status s = region.build(widths.data(), S(1)); s != Status::ok) return s;

  // Breadth-first over the DAG in index order: dist[j] the fewest biarcs to
  // p_j, prev[j] the start of the last one.
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::uint32_t* dist = ws.words.data();
  std::uint32_t* prev = dist + n;
  for (std::size_t k = 0; k < n; ++k) dist[k] = prev[k] = kNone;
  dist[0] = 0;
  const biarc_detail::Pair<S> pair{region, tangents, opts.samples, widest};
  for (std::uint32_t i = 0; i + 1 < count; ++i) {
    if (dist[i] == kNone) continue;
    std::uint32_t misses = 0;
    std::uint32_t reach = 0;
    for (std::uint32_t j = i + 1; j < count; ++j) {
      const bool reached = dist[j] != kNone && dist[j] <= dist[i] + 1;
      S s{};
      if (reached) {
        // (not tested: neither a hit nor a miss)
      } else if (pair.any(i, j, s)) {
        dist[j] = dist[i] + 1;
        prev[j] = i;
        misses = 0;
        reach = j - i;
      } else if (!opts.exact && ++misses >= opts.slack + reach) {
        break;
      }
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
    S s{};
    if (!pair.any(i, j, s)) return Status::infeasible;  // cannot happen: it was found valid
    const Biarc<S> b = biarc_detail::best_joint(pair, pts, i, j, s);
    BiarcPiece<S>& piece = out[p];
    piece.first = i;
    piece.last = j;
    piece.arc[0] = b.first.segment();
    piece.arc[1] = b.second.segment();
    piece.joint = b.first.b;
    piece.tangent[0] = tangents[i];
    piece.tangent[1] = b.second.t;
    piece.tangent[2] = b.second.end_tangent();
    piece.error = biarc_deviation(pts, i, j, b);
    fit.max_error = max_of(fit.max_error, piece.error);
    j = i;
  }
  return fit;
}

}  // namespace kerf::fit
