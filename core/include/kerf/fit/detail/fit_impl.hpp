// Definitions behind fit/fit.hpp (and the search the band fitter shares).
// Included by src/fit.cpp, which instantiates them, and by the fitters that
// build on it.
#pragma once

#include "kerf/core/scale.hpp"
#include "kerf/fit/detail/min_count.hpp"
#include "kerf/fit/detail/prefix_guard.hpp"
#include "kerf/fit/esgi/rules.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/fit/vertex/pair.hpp"

namespace kerf::fit {

namespace detail {

template <class S>
struct Oracle {
  const Vec2<S>* pts;
  S eps;
  Method method;
  AngleSet<S>* set;

  bool operator()(std::uint32_t i, std::uint32_t j, std::uint32_t& hint) {
    if (method == Method::optimal) {
      // A start whose last exact test failed is probably past its reach: go
      // straight to the exact test, which tries the point that failed first.
      if (hint == 0 && vertex_pair_witness(pts, i, j, eps).norm2() != S(0)) return true;
      const bool ok = vertex_pair_set(pts, i, j, eps, *set, &hint);
      if (ok) hint = 0;
      return ok;
    }
    const EsgiRule rule = method == Method::esgi_max ? EsgiRule::max : EsgiRule::mean;
    return !(esgi_arc(rule, pts, i, j, eps, eps, eps).error > eps);
  }
  bool alive(std::uint32_t i, std::uint32_t j) const { return prefix_guard(pts, i, j, eps); }
};

// The problem as the search sees it: the points scaled by a power of two
// (exact) and the tolerance scaled alike.
template <class S>
struct Scaled {
  Span<const Vec2<S>> pts;
  S factor;
};

// The power of two the points are scaled by: their largest coordinate to
// about 1.
template <class S>
S scale_factor(Span<const Vec2<S>> pts) {
  S big = S(0);
  for (const Vec2<S>& p : pts) big = max_of(big, max_of(Scalar<S>::abs(p.x), Scalar<S>::abs(p.y)));
  return power_of_two_scale(big);
}

template <class S>
Scaled<S> scale_into(Span<const Vec2<S>> pts, Span<Vec2<S>> out) {
  const S f = scale_factor(pts);
  for (std::size_t k = 0; k < pts.size(); ++k) out[k] = pts[k] * f;
  return {Span<const Vec2<S>>(out.data(), pts.size()), f};
}

template <class S>
AngleSet<S> make_set(Workspace<S> ws) {
  const std::size_t half = ws.intervals.size() / 2;
  return AngleSet<S>(ws.intervals.subspan(0, half), ws.intervals.subspan(half, half));
}

template <class S>
bool storage_ok(std::size_t n, Workspace<S> ws) {
  return ws.words.size() >= min_count_words(n) && ws.intervals.size() >= workspace_intervals(n) &&
         ws.points.size() >= workspace_points(n);
}

// Pieces needed at eps, or 0 when more than `budget`; pred is left in ws.
template <class S>
Result<std::uint32_t> count_at(Span<const Vec2<S>> pts, S eps, Method method, Workspace<S> ws,
                               std::uint32_t budget, std::uint32_t*& pred,
                               const std::uint32_t* layer_of = nullptr) {
  AngleSet<S> set = make_set(ws);
  Oracle<S> oracle{pts.data(), eps, method, &set};
  const auto n = static_cast<std::uint32_t>(pts.size());
  const Result<MinCount> r = min_count(n, oracle, ws.words, budget, pred, layer_of);
  if (!r.ok()) return r.status();
  return r.value().pieces;
}

template <class S>
S bbox_diagonal(Span<const Vec2<S>> pts) {
  Vec2<S> lo = pts[0];
  Vec2<S> hi = pts[0];
  for (const Vec2<S>& p : pts) {
    lo = {min_of(lo.x, p.x), min_of(lo.y, p.y)};
    hi = {max_of(hi.x, p.x), max_of(hi.y, p.y)};
  }
  return (hi - lo).norm();
}

inline void copy_words(const std::uint32_t* from, std::uint32_t* to, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) to[k] = from[k];
}

// Smallest eps in [floor, hi] (to `rel` relative) at which `pieces` suffice,
// given that they suffice at hi. Returns hi, the tightest known feasible eps;
// hi itself when rel >= 1. `seeded`: the search at hi, with exactly
// `pieces`, has just run, so its layers bound every later search
// (min_count's layer_of), kept in the workspace's sixth n words if it has
// them.
template <class S>
Result<S> bisect_tol(Span<const Vec2<S>> pts, std::uint32_t pieces, Method method, Workspace<S> ws,
                     S hi, S rel, bool seeded = false) {
  if (!(rel < S(1))) return hi;
  std::uint32_t* pred = nullptr;
  const std::size_t n = pts.size();
  std::uint32_t* layers = seeded && ws.words.size() >= 6 * n ? ws.words.data() + 5 * n : nullptr;
  if (layers != nullptr) copy_words(ws.words.data(), layers, n);
  S lo = bbox_diagonal(pts) * S(1e-12);
  {
    const Result<std::uint32_t> c = count_at(pts, lo, method, ws, pieces, pred, layers);
    if (!c.ok()) return c.status();
    if (c.value() != 0) return lo;  // exact data: any positive tol is enough
  }
  for (int it = 0; it < 200 && hi - lo > hi * rel; ++it) {
    const S mid = lo + (hi - lo) / S(2);
    const Result<std::uint32_t> c = count_at(pts, mid, method, ws, pieces, pred, layers);
    if (!c.ok()) return c.status();
    if (c.value() != 0) {
      hi = mid;
      if (layers != nullptr) copy_words(ws.words.data(), layers, n);
    } else {
      lo = mid;
    }
  }
  return hi;
}

// The circle (or line) of one piece of the final path.
template <class S>
PieceFit<S> choose_piece(const Vec2<S>* p, std::uint32_t i, std::uint32_t j, S eps, Method method,
                        AngleSet<S>& set) {
  if (method == Method::optimal) return best_vertex_pair(p, i, j, eps, set);
  const EsgiRule rule = method == Method::esgi_max ? EsgiRule::max : EsgiRule::mean;
  return esgi_arc(rule, p, i, j, Scalar<S>::infinity(), S(-1), eps);
}

// Runs the search at eps within `pieces` and writes the path's pieces, in
// the caller's units (original points, centre and errors divided by factor).
template <class S>
Result<Fit<S>> build(Span<const Vec2<S>> original, Scaled<S> sc, S eps, std::uint32_t pieces,
                     Method method, Workspace<S> ws, Span<Piece<S>> out) {
  std::uint32_t* pred = nullptr;
  const Result<std::uint32_t> c = count_at(sc.pts, eps, method, ws, pieces, pred);
  if (!c.ok()) return c.status();
  if (c.value() == 0) return Status::infeasible;
  const std::uint32_t count = c.value();
  if (out.size() < count) return Status::capacity_exceeded;

  AngleSet<S> set = make_set(ws);
  const Vec2<S>* p = sc.pts.data();
  const S unscale = S(1) / sc.factor;
  Fit<S> fit{count, S(0), eps * unscale};
  std::uint32_t j = static_cast<std::uint32_t>(sc.pts.size()) - 1;
  for (std::uint32_t k = count; k-- > 0;) {
    const std::uint32_t i = pred[j];
    const PieceFit<S> f = choose_piece(p, i, j, eps, method, set);
    const Chord<S> chord(p[i], p[j]);
    const Vec2<S> centre = f.line ? Vec2<S>{} : chord.centre(f.direction);
    Segment<S> seg = make_segment(chord, p + i + 1, j - i - 1, f.line, centre, eps, f.dir);
    seg.start = original[i];
    seg.end = original[j];
    seg.centre = seg.centre * unscale;
    out[k] = Piece<S>{i, j, seg, f.error * unscale};
    fit.max_error = max_of(fit.max_error, f.error * unscale);
    j = i;
  }
  return fit;
}

template <class S>
bool tol_ok(S tol) {
  return Scalar<S>::is_finite(tol) && tol > S(0);
}

template <class S>
Status check_inputs(Span<const Vec2<S>> pts, Workspace<S> ws) {
  std::size_t where = 0;
  if (const Status s = validate_points(pts, where); s != Status::ok) return s;
  if (!storage_ok(pts.size(), ws)) return Status::capacity_exceeded;
  return Status::ok;
}

}  // namespace detail

template <class S>
Status validate_points(Span<const Vec2<S>> pts, std::size_t& where) {
  for (std::size_t k = 0; k < pts.size(); ++k) {
    where = k;
    if (!Scalar<S>::is_finite(pts[k].x) || !Scalar<S>::is_finite(pts[k].y))
      return Status::invalid_argument;
    if (k > 0 && pts[k] == pts[k - 1]) return Status::degenerate;
  }
  where = pts.size();
  return pts.size() < 2 ? Status::invalid_argument : Status::ok;
}

template <class S>
Result<std::uint32_t> count_min(Span<const Vec2<S>> pts, S tol, Method method, Workspace<S> ws) {
  if (const Status s = detail::check_inputs(pts, ws); s != Status::ok) return s;
  if (!detail::tol_ok(tol)) return Status::invalid_argument;
  const detail::Scaled<S> sc = detail::scale_into(pts, ws.points);
  std::uint32_t* pred = nullptr;
  return detail::count_at(sc.pts, tol * sc.factor, method, ws,
                          static_cast<std::uint32_t>(pts.size()), pred);
}

template <class S>
Result<Fit<S>> fit_min_count(Span<const Vec2<S>> pts, S tol, Method method, Workspace<S> ws,
                             Span<Piece<S>> out) {
  return fit_min_count(pts, tol, method, ws, out, S(1e-9));
}

template <class S>
Result<Fit<S>> fit_min_count(Span<const Vec2<S>> pts, S tol, Method method, Workspace<S> ws,
                             Span<Piece<S>> out, S tie_break) {
  if (const Status s = detail::check_inputs(pts, ws); s != Status::ok) return s;
  if (!detail::tol_ok(tol)) return Status::invalid_argument;
  const detail::Scaled<S> sc = detail::scale_into(pts, ws.points);
  const auto n = static_cast<std::uint32_t>(pts.size());
  if (!(tie_break < S(1))) {  // no tie-break: build's own search is the count
    Result<Fit<S>> fit = detail::build(pts, sc, tol * sc.factor, n, method, ws, out);
    if (fit.ok()) fit.value().tol = tol;
    return fit;
  }
  std::uint32_t* pred = nullptr;
  const Result<std::uint32_t> count = detail::count_at(sc.pts, tol * sc.factor, method, ws, n, pred);
  if (!count.ok()) return count.status();
  // The tie-break: the smallest tol that still allows this count.
  const Result<S> best = detail::bisect_tol(sc.pts, count.value(), method, ws, tol * sc.factor, tie_break, true);
  if (!best.ok()) return best.status();
  Result<Fit<S>> fit = detail::build(pts, sc, best.value(), count.value(), method, ws, out);
  // At the tie-break's tol the verdicts sit on their boundary, where rounding
  // (kerf::Fixed far from the origin) may undo the count the bisection saw:
  // then the fit at tol itself, whose count was just found.
  if (!fit.ok() && fit.status() == Status::infeasible)
    fit = detail::build(pts, sc, tol * sc.factor, count.value(), method, ws, out);
  if (fit.ok()) fit.value().tol = tol;
  return fit;
}

template <class S>
Result<Fit<S>> fit_min_error(Span<const Vec2<S>> pts, std::uint32_t pieces, Method method,
                             Workspace<S> ws, Span<Piece<S>> out) {
  if (const Status s = detail::check_inputs(pts, ws); s != Status::ok) return s;
  if (pieces == 0) return Status::invalid_argument;
  const detail::Scaled<S> sc = detail::scale_into(pts, ws.points);
  // Any positive tol works for n - 1 pieces; the bounding box's diagonal
  // lets one piece (or two, for a closed loop) through.
  const S hi = detail::bbox_diagonal(sc.pts) * S(2);
  std::uint32_t* pred = nullptr;
  const Result<std::uint32_t> c = detail::count_at(sc.pts, hi, method, ws, pieces, pred);
  if (!c.ok()) return c.status();
  if (c.value() == 0) return Status::infeasible;
  const Result<S> best = detail::bisect_tol(sc.pts, pieces, method, ws, hi, S(1e-9));
  if (!best.ok()) return best.status();
  return detail::build(pts, sc, best.value(), pieces, method, ws, out);
}

}  // namespace kerf::fit
