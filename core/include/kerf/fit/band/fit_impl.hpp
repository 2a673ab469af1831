// Definitions behind fit/band.hpp. Included by the translation unit that
// instantiates them for every scalar type (src/band.cpp).
#pragma once

#include "kerf/fit/band.hpp"
#include "kerf/fit/band/deviation.hpp"
#include "kerf/fit/band/pair.hpp"
#include "kerf/fit/band/region_impl.hpp"
#include "kerf/fit/band/start_region.hpp"
#include "kerf/fit/detail/chord.hpp"
#include "kerf/fit/detail/fit_impl.hpp"
#include "kerf/fit/detail/min_count.hpp"
#include "kerf/fit/detail/prefix_guard.hpp"

namespace kerf::fit {

namespace band_detail {

// The search's view of the band test. The hint word keeps, per orientation,
// the cell that emptied its last failed test (offset from i, plus one; 15
// bits each), and which orientation last succeeded (bit 30): a start usually
// keeps bending the same way, and the other orientation, or a start past its
// reach, usually fails again at the same cell, in O(1).
template <class S>
struct Oracle {
  const BandRegion<S>* region;
  const std::uint32_t* next_barrier;  // the first barrier after each vertex
  S guard_eps;                        // the longest half gate
  // Per orientation, the cells that bound the last successful test
  // (BandPair::run): one search's memory, so each search has its own.
  mutable std::uint32_t binding[2][2] = {{BandPair<S>::kNoCell, BandPair<S>::kNoCell},
                                         {BandPair<S>::kNoCell, BandPair<S>::kNoCell}};

  static constexpr std::uint32_t kMarkBits = 15;
  static constexpr std::uint32_t kMarkMask = (1u << kMarkBits) - 1;
  static constexpr std::uint32_t kPreferCw = 1u << 30;

  // Where orientation o's mark sits in the hint word (o is 0 or 1).
  static std::uint32_t shift(int o) { return static_cast<std::uint32_t>(o) * kMarkBits; }
  static std::uint32_t mark(std::uint32_t hint, int o) { return (hint >> shift(o)) & kMarkMask; }
  static std::uint32_t with_mark(std::uint32_t hint, int o, std::uint32_t m) {
    return (hint & ~(kMarkMask << shift(o))) | (m << shift(o));
  }
  static std::uint32_t pack(std::uint32_t i, std::uint32_t cell) {
    const std::uint32_t off = cell - i;
    return off < kMarkMask ? off + 1 : 0;
  }

  // Does the pair fail at its marked cell alone (mark m, 0: none)?
  static bool quick_fail(const BandPair<S>& pair, std::uint32_t i, std::uint32_t j, std::uint32_t m) {
    if (m == 0 || i + m - 1 >= j) return false;
    PsiRange<S> range;
    return !(pair.ends(range) && pair.cell(i + m - 1, range));
  }

  // The start regions (start_region.hpp; floating point): their "yes"
  // spares the pair test.
  mutable std::conditional_t<kFloating<S>, StartRegions<S>, NoStartRegion> regions = {};
  static constexpr std::uint32_t kFreshWithin = 4;

  // Does a start region admit i -> j in orientation o? One is started
  // for a start asked about one of its first few j, or (remember()) one
  // that the pair test has just found to reach j: a start that reaches j
  // usually reaches the next ones too (29 in a row on average in
  // tball-pocket's weld).
  bool quick_yes(std::uint32_t i, std::uint32_t j, int o) const {
    if constexpr (!kFloating<S>) {
      (void)i, (void)j, (void)o;
      return false;
    } else {
      if (next_barrier[i] < j) return false;
      const int orient = o == 0 ? 1 : -1;
      StartRegion<S>* q = regions.find(i, orient, j);
      if (q == nullptr) {
        if (j > i + kFreshWithin) return false;
        q = &regions.take(*region, i, orient);
      }
      return q->reach(*region, j) && q->admits(*region, j, binding[o]);
    }
  }

  // The pair test has just found that i reaches j in orientation o: a
  // region for i, built up to j, unless one is kept.
  void remember(std::uint32_t i, std::uint32_t j, int o) const {
    if constexpr (!kFloating<S>) {
      (void)i, (void)j, (void)o;
    } else {
      const int orient = o == 0 ? 1 : -1;
      if (next_barrier[i] >= j && regions.find(i, orient, j) == nullptr)
        regions.take(*region, i, orient).reach(*region, j);
    }
  }

  static std::uint32_t succeeded(std::uint32_t hint, int o) {
    hint = with_mark(hint, o, 0);
    return o == 1 ? (hint | kPreferCw) : (hint & ~kPreferCw);
  }

  // Each orientation in the preferred order: the start regions first, then
  // for each its marked cell, then the whole test, on one BandPair (its
  // frame costs a square root).
  bool operator()(std::uint32_t i, std::uint32_t j, std::uint32_t& hint) const {
    if (closes_on_itself(region->point(i), region->point(j))) return false;
    const int first = (hint & kPreferCw) != 0 ? 1 : 0;  // 0: counter-clockwise
    for (int t = 0; t < 2; ++t) {
      const int o = t == 0 ? first : 1 - first;
      if (quick_yes(i, j, o)) {
        hint = succeeded(hint, o);
        return true;
      }
    }
    for (int t = 0; t < 2; ++t) {
      const int o = t == 0 ? first : 1 - first;
      BandPair<S> pair(*region, i, j, o == 0 ? 1 : -1);
      if (next_barrier[i] >= j) pair.set_clear_between();
      if (quick_fail(pair, i, j, mark(hint, o))) continue;
      PsiRange<S> range;
      std::uint32_t cell = i;
      if (pair.run(range, cell, binding[o])) {
        hint = succeeded(hint, o);
        remember(i, j, o);
        return true;
      }
      hint = with_mark(hint, o, pack(i, cell));
    }
    return false;
  }

  // False only when no j' >= j can be reached from i (min_count's guard;
  // it changes what the search costs, never what it finds). A piece i -> j'
  // crosses the gate of every point between, within guard_eps of it, and
  // ends on p_j', so one circle through p_i passes within guard_eps of every
  // point of (i, j]: any three of them make a necessary condition
  // (fit/detail/prefix_guard.hpp). The thirds of (i, j] and j first, then
  // five more spreads, in eighths of the span: a start kept alive costs a
  // failed test at every later j, and with them tball-engrave's weld fails
  // 8011 tests instead of 17365 (more spreads cost more than they save).
  bool alive(std::uint32_t i, std::uint32_t j) const {
    if (next_barrier[i] < j) return false;
    const Vec2<S>* pts = &region->point(0);
    if (!prefix_guard(pts, i, j, guard_eps)) return false;
    if (j < i + 5) return true;
    static constexpr std::uint32_t kEighths[5][3] = {{2, 4, 6}, {4, 6, 8}, {1, 4, 8}, {1, 2, 3}, {5, 7, 8}};
    const std::uint32_t span = j - i;
    for (const auto& e : kEighths) {
      const Vec2<S> three[3] = {pts[i + e[0] * span / 8], pts[i + e[1] * span / 8], pts[i + e[2] * span / 8]};
      if (!circle_through_near_three(pts[i], three, guard_eps)) return false;
    }
    return true;
  }
};

// The problem as the search sees it: points scaled by a power of two (exact)
// and the widths' scale to match.
template <class S>
struct Problem {
  Span<const Vec2<S>> pts;  // scaled
  const BandWidth<S>* widths;
  S factor;
  BandWorkspace<S> ws;
};

template <class S>
BandRegion<S> build_region(const Problem<S>& pb, S scale) {
  const auto n = static_cast<std::uint32_t>(pb.pts.size());
  BandRegion<S> region(pb.pts.data(), n, pb.ws.vertices.data());
  region.build(pb.widths, scale * pb.factor);
  region.cache_chains(pb.ws.chains);
  return region;
}

// Pieces needed in `region`, or 0 when more than budget.
template <class S>
Result<std::uint32_t> count_in(const Problem<S>& pb, const BandRegion<S>& region,
                               std::uint32_t budget, std::uint32_t*& pred,
                               const std::uint32_t* layer_of = nullptr) {
  const auto n = static_cast<std::uint32_t>(pb.pts.size());
  std::uint32_t* next_barrier = pb.ws.words.data() + 5 * static_cast<std::size_t>(n);
  S longest = S(0);
  next_barrier[n - 1] = n;
  for (std::uint32_t k = n - 1; k-- > 0;) {
    next_barrier[k] = region.vertex(k + 1).barrier ? k + 1 : next_barrier[k + 1];
    longest = max_of(longest, max_of(region.vertex(k).gate_left, region.vertex(k).gate_right));
  }
  longest = max_of(longest, max_of(region.vertex(n - 1).gate_left, region.vertex(n - 1).gate_right));
  const Oracle<S> oracle{&region, next_barrier, longest};
  const Result<MinCount> r =
      min_count(n, oracle, pb.ws.words.subspan(0, 5 * static_cast<std::size_t>(n)), budget, pred, layer_of);
  if (!r.ok()) return r.status();
  return r.value().pieces;
}

// Pieces needed with the widths times `scale`, or 0 when more than budget.
template <class S>
Result<std::uint32_t> count_at(const Problem<S>& pb, S scale, std::uint32_t budget,
                               std::uint32_t*& pred, const std::uint32_t* layer_of = nullptr) {
  return count_in(pb, build_region(pb, scale), budget, pred, layer_of);
}

// The widest width at scale 1, in the scaled problem.
template <class S>
S widest_scaled(const Problem<S>& pb) {
  S w = S(0);
  for (std::size_t k = 0; k < pb.pts.size(); ++k)
    w = max_of(w, max_of(pb.widths[k].left, pb.widths[k].right));
  return w * pb.factor;
}

// Smallest scale in (0, hi] (to `rel` relative) at which `pieces` suffice,
// given that they suffice at hi. `seeded`: the search at hi, with exactly
// `pieces`, has just run, so its layers bound every later search
// (min_count's layer_of), kept in the workspace's seventh n words if it has
// them.
template <class S>
Result<S> bisect_scale(const Problem<S>& pb, std::uint32_t pieces, S hi, S rel, bool seeded = false) {
  std::uint32_t* pred = nullptr;
  const std::size_t n = pb.pts.size();
  std::uint32_t* layers = seeded && pb.ws.words.size() >= 7 * n ? pb.ws.words.data() + 6 * n : nullptr;
  if (layers != nullptr) detail::copy_words(pb.ws.words.data(), layers, n);
  S lo = smallest_scale(hi, widest_scaled(pb));
  {
    const Result<std::uint32_t> c = count_at(pb, lo, pieces, pred, layers);
    if (!c.ok()) return c.status();
    if (c.value() != 0) return lo;  // exact data: any positive width is enough
  }
  for (int it = 0; it < 200 && hi - lo > hi * rel; ++it) {
    const S mid = lo + (hi - lo) / S(2);
    const Result<std::uint32_t> c = count_at(pb, mid, pieces, pred, layers);
    if (!c.ok()) return c.status();
    if (c.value() != 0) {
      hi = mid;
      if (layers != nullptr) detail::copy_words(pb.ws.words.data(), layers, n);
    } else {
      lo = mid;
    }
  }
  return hi;
}

template <class S>
S widest(Span<const BandWidth<S>> widths) {
  S w = S(0);
  for (const BandWidth<S>& b : widths) w = max_of(w, max_of(b.left, b.right));
  return w;
}

// The arc (or line) chosen for a valid piece: the line when it is valid,
// else the middle of the valid range of the orientation that has one.
template <class S>
struct Choice {
  bool line = true;
  int orient = 1;
  Vec2<S> direction{S(1), S(0)};
};

template <class S>
bool choose(const BandRegion<S>& region, std::uint32_t i, std::uint32_t j, Choice<S>& out) {
  PsiRange<S> ranges[2];
  bool ok[2];
  const int orients[2] = {1, -1};
  for (int o = 0; o < 2; ++o) {
    std::uint32_t cell = 0;
    ok[o] = BandPair<S>(region, i, j, orients[o]).run(ranges[o], cell);
    if (ok[o] && !(ranges[o].lo > S(0))) {
      out = Choice<S>{};
      return true;
    }
  }
  for (int o = 0; o < 2; ++o) {
    if (!ok[o]) continue;
    out.line = false;
    out.orient = orients[o];
    out.direction = direction_of((ranges[o].lo + ranges[o].hi) / S(2));
    return true;
  }
  return false;
}

template <class S>
Segment<S> make_band_segment(const BandRegion<S>& region, std::uint32_t i, std::uint32_t j,
                             const Choice<S>& c) {
  const Vec2<S> a = region.point(i);
  const Vec2<S> b = region.point(j);
  if (c.line) return Segment<S>::line(a, b);
  const BandPair<S> pair(region, i, j, c.orient);
  const S q = pseudo_angle(c.direction);
  return Segment<S>::arc(a, b, pair.centre(q), c.orient);
}

// Runs the search at `scale` within `pieces` and writes the path's pieces in
// the caller's units.
template <class S>
Result<Fit<S>> build(Span<const Vec2<S>> original, const Problem<S>& pb, S scale,
                     std::uint32_t pieces, Span<Piece<S>> out) {
  std::uint32_t* pred = nullptr;
  const BandRegion<S> region = build_region(pb, scale);
  const Result<std::uint32_t> c = count_in(pb, region, pieces, pred);
  if (!c.ok()) return c.status();
  if (c.value() == 0) return Status::infeasible;
  const std::uint32_t count = c.value();
  if (out.size() < count) return Status::capacity_exceeded;
  const S unscale = S(1) / pb.factor;
  Fit<S> fit{count, S(0), widest(Span<const BandWidth<S>>(pb.widths, pb.pts.size())) * scale};
  std::uint32_t j = static_cast<std::uint32_t>(pb.pts.size()) - 1;
  for (std::uint32_t k = count; k-- > 0;) {
    const std::uint32_t i = pred[j];
    Choice<S> choice;
    if (!choose(region, i, j, choice)) return Status::infeasible;  // cannot happen: i reached j
    Segment<S> seg = make_band_segment(region, i, j, choice);
    const S error = band_deviation(region, i, j, choice.direction, choice.orient) * unscale;
    seg.start = original[i];
    seg.end = original[j];
    seg.centre = seg.centre * unscale;
    out[k] = Piece<S>{i, j, seg, error};
    fit.max_error = max_of(fit.max_error, error);
    j = i;
  }
  return fit;
}

template <class S>
Status check_band_inputs(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                         BandWorkspace<S> ws) {
  std::size_t where = 0;
  if (const Status s = validate_points(pts, where); s != Status::ok) return s;
  const std::size_t n = pts.size();
  if (widths.size() != n) return Status::invalid_argument;
  for (const BandWidth<S>& w : widths) {
    if (!Scalar<S>::is_finite(w.left) || !Scalar<S>::is_finite(w.right)) return Status::invalid_argument;
    if (w.left < S(0) || w.right < S(0) || !(w.left + w.right > S(0))) return Status::invalid_argument;
  }
  if (ws.words.size() < 6 * n || ws.points.size() < n || ws.vertices.size() < n)
    return Status::capacity_exceeded;
  return Status::ok;
}

template <class S>
Problem<S> problem(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths, BandWorkspace<S> ws) {
  const detail::Scaled<S> sc = detail::scale_into(pts, ws.points);
  return Problem<S>{sc.pts, widths.data(), sc.factor, ws};
}

}  // namespace band_detail

template <class S>
Result<std::uint32_t> count_band_min(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                     BandWorkspace<S> ws) {
  if (const Status s = band_detail::check_band_inputs(pts, widths, ws); s != Status::ok) return s;
  const band_detail::Problem<S> pb = band_detail::problem(pts, widths, ws);
  std::uint32_t* pred = nullptr;
  return band_detail::count_at(pb, S(1), static_cast<std::uint32_t>(pts.size()), pred);
}

template <class S>
Result<Fit<S>> fit_band_min_count(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  BandWorkspace<S> ws, Span<Piece<S>> out) {
  // To 1e-6: each step is a whole search; finer would change no cut.
  return fit_band_min_count(pts, widths, ws, out, S(1e-6));
}

template <class S>
Result<Fit<S>> fit_band_min_count(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  BandWorkspace<S> ws, Span<Piece<S>> out, S tie_break) {
  if (const Status s = band_detail::check_band_inputs(pts, widths, ws); s != Status::ok) return s;
  const band_detail::Problem<S> pb = band_detail::problem(pts, widths, ws);
  const auto n = static_cast<std::uint32_t>(pts.size());
  if (!(tie_break < S(1))) {  // no tie-break: build's own search is the count
    Result<Fit<S>> fit = band_detail::build(pts, pb, S(1), n, out);
    if (fit.ok()) fit.value().tol = band_detail::widest(widths);
    return fit;
  }
  std::uint32_t* pred = nullptr;
  const Result<std::uint32_t> count = band_detail::count_at(pb, S(1), n, pred);
  if (!count.ok()) return count.status();
  // The tie-break: the smallest band that still allows this count.
  const Result<S> best = band_detail::bisect_scale(pb, count.value(), S(1), tie_break, true);
  if (!best.ok()) return best.status();
  Result<Fit<S>> fit = band_detail::build(pts, pb, best.value(), count.value(), out);
  if (fit.ok()) fit.value().tol = band_detail::widest(widths);  // as asked
  return fit;
}

template <class S>
Result<Fit<S>> fit_band_min_error(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  std::uint32_t pieces, BandWorkspace<S> ws, Span<Piece<S>> out) {
  if (const Status s = band_detail::check_band_inputs(pts, widths, ws); s != Status::ok) return s;
  if (pieces == 0) return Status::invalid_argument;
  const band_detail::Problem<S> pb = band_detail::problem(pts, widths, ws);
  std::uint32_t* pred = nullptr;
  S hi = S(1);
  for (int grow = 0;; ++grow) {  // widen until the budget is met
    const Result<std::uint32_t> c = band_detail::count_at(pb, hi, pieces, pred);
    if (!c.ok()) return c.status();
    if (c.value() != 0) break;
    if (grow == 40) return Status::infeasible;
    hi = hi * S(2);
  }
  const Result<S> best = band_detail::bisect_scale(pb, pieces, hi, S(1e-9));
  if (!best.ok()) return best.status();
  return band_detail::build(pts, pb, best.value(), pieces, out);
}

template <class S>
Result<BandRegion<S>> band_region(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  BandWorkspace<S> ws) {
  if (const Status s = band_detail::check_band_inputs(pts, widths, ws); s != Status::ok) return s;
  BandRegion<S> region(pts.data(), static_cast<std::uint32_t>(pts.size()), ws.vertices.data());
  if (const Status s = region.build(widths.data(), S(1)); s != Status::ok) return s;
  return region;
}

template <class S>
bool band_pair_valid(const BandRegion<S>& region, std::uint32_t i, std::uint32_t j,
                     Segment<S>* chosen) {
  if (!(i < j && j < region.size())) return false;
  if (closes_on_itself(region.point(i), region.point(j))) return false;
  band_detail::Choice<S> c;
  if (!band_detail::choose(region, i, j, c)) return false;
  if (chosen != nullptr) *chosen = band_detail::make_band_segment(region, i, j, c);
  return true;
}

}  // namespace kerf::fit
