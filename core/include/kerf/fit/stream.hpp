// Streaming fits in memory fixed at compile time: the vertex criterion here,
// the band criterion in fit/stream_band.hpp (the same engine).
//
// PointWindow<S, N> takes the points one by one and hands each piece to a
// sink as soon as it is decided. It keeps at most N points (the window) and,
// for each, the shortest-path label of the fewest-pieces search (fit/fit.hpp,
// fit/detail/min_count.hpp), built incrementally: a new point m gets
// d(m) = 1 + min d(i) over the starts i that reach it, and pred(m) = the
// nearest such i (the whole-input search's own rule). The feasibility test
// and the monotone guard are the whole-input fitter's (detail::Oracle).
//
// Which paths can still become the optimum: only through a *frontier* node,
// a point whose start is still alive at m (prefix_guard passes for every end
// seen so far, a necessary condition for reaching any later point), and m
// itself. Any complete path's last node inside the window is such a node,
// reached by a shortest path (else shorten it). So the candidates are the
// shortest paths to the frontier nodes, and every one of them shares the
// pieces from the root to the nodes' lowest common ancestor in the pred tree.
// Those pieces are *decided*: emitting them loses nothing, and afterwards
// every label stays exact (a node below the ancestor is reached through it).
//
// A *forced commit* happens when the window is full and the next point
// arrives before a decision. It commits the best prefix: the path to the
// frontier node at index >= root + H (H = floor((N - 1 - margin) / 2),
// margin = the criterion's kLag + kContext: forced_step()) with the fewest
// pieces, the newest on ties; the window is then relabelled from that node,
// exactly.
//
// Exactness (proven). With no forced commit the stream emits exactly the
// pieces of the whole-input fitter run at tol itself (fit_min_count with
// tie_break >= 1; `kerf fit --tie-break none`): label() gives each node the
// d and pred of min_count (pred = the nearest start among those one piece
// closer to the root that reach it; the guard drops only starts that reach
// nothing later, in both), a decided commit follows pred from a node every
// complete path passes, and piece() runs the fitter's choose_piece on the
// same numbers: scale_for() puts the points in the whole-input frame (a power
// of two: exact in double, the same Fixed operations in kerf::Fixed). Tested
// bit for bit on the test curves, the corpus's G-code polylines and random
// curves, in double and Fixed (tests/unit/test_stream_exact.cpp), and line
// for line through the CLI (tests/cli/stream_check.py).
//   The whole-input default (tie_break 1e-9) differs: among the fewest-pieces
// solutions it takes the one at the smallest tol that keeps the count, and
// that tol is set by the hardest stretch of the whole input (a bottleneck at
// the end shrinks every piece before it). A stream has emitted its first
// piece long before it sees that stretch, so no stream can match it.
//
// The bound (proof sketch). Let r_1 < ... < r_F be the forced cut points,
// r_0 = 0, r_{F+1} = n - 1, OPT(a, b) the fewest pieces from p_a to p_b.
//  (1) count = sum_k OPT(r_k, r_{k+1}). Decided commits keep the labels
//      exact (above); a forced commit relabels from r_k exactly; so each
//      block is fitted by the exact search restricted to it.
//  (2) F <= floor((n - 1) / H): every forced commit moves the root by >= H.
//  (3) count <= OPT + F (L - 1), L the longest piece (in index steps) of
//      an optimal solution P. Replace each piece a -> b of P that has a cut
//      strictly inside by its b - a one-step pieces (a step p_k -> p_{k+1}
//      is always valid): +(b - a - 1) <= L - 1 per cut at most, and the
//      result passes through every r_k, so by (1) it bounds the count.
//  (4) count <= OPT + F for inputs where a valid piece a -> b stays valid
//      when cut at an inner point (a -> r and r -> b valid): each cut then
//      costs one piece. Collinear points reach this exactly. Neither the
//      vertex nor the band criterion has that property in general (a piece
//      must start and end on input points, which the sub-arc of a valid
//      arc misses), which is why (3) is the general bound.
//  (5) Window and span. With no forced commit, count = OPT and the pieces
//      are the whole input's (above). No window length rules forced commits
//      out, and no rule that must commit when its window of W points is full
//      gives the fewest pieces on every input whose pieces are all far
//      shorter than W. Instance (tests/unit/test_stream_window_span.cpp,
//      vertex and band): the square wave x_k = k, y_k = 1 if k mod 5 >= 3
//      else 0, at tol 0.42 (band: both widths); no valid piece spans more
//      than 6 steps. Take W = 3 mod 10, A its first W + 1 points, B its
//      first W + 2. Every fewest-pieces fit of A starts 0 -> 3 and every one
//      of B 0 -> 4: exact, from the DAG of all valid pairs (the test: W = 63
//      and 103; a search: every such W from 13 to 1003). At W = 63 A's fit
//      cuts at 3, 9, 13, 19, ..., 63 and B's at 4, 8, 14, 18, ..., 64:
//      pieces of 6 and 4 steps across the low runs, two chains that never
//      meet. A window of W points, full when point W arrives, has read only
//      points A and B share and must emit its first piece: the same for
//      both, so one of them gets OPT + 1 pieces or more, though W = 63 is
//      over 10 L. (Any other W: take the next W' = 3 mod 10 above it.) kerf
//      loses one piece on one of the two (vertex: B; band: A), one forced
//      commit each, within (3); its reach there is 9, so a window past the
//      reach is no remedy either (the CLI too: tests/cli/stream_check.py).
//        Measured on smoother paths, L the longest piece of the whole-input
//      fit: a window of 3 L + 8 points gave the whole input's pieces, bit for
//      bit, on every path tested (test curves, corpus polylines, 24 random
//      curves; vertex: no forced commit at all; band: 47 forced commits on 3
//      paths, harmless), while 2 L + 8 forced 22 (vertex) and 225 (band)
//      commits, and gave other pieces on 2 and 6 paths (a random curve lost
//      a piece). A measurement, not a guarantee (the square wave). The
//      stream counts forced commits (StreamStats::forced); with none, the
//      result is the whole input's whatever the window. StreamStats::reach,
//      the longest a start stayed alive, bounds how far back the frontier
//      reaches (frontier nodes lie within reach of the newest point), not
//      how far back the candidates' paths part.
//
// No allocation, no exceptions, no OS header: all storage is members.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/fit/detail/fit_impl.hpp"

namespace kerf::fit {

struct StreamStats {
  std::uint64_t points = 0;  // accepted so far
  std::uint64_t pieces = 0;  // emitted so far
  std::uint32_t forced = 0;  // forced commits
  std::uint32_t peak = 0;    // the most points the window held at once
  std::uint32_t reach = 0;   // the longest span (index steps) a start stayed alive
};

namespace detail {

// Storage left unconstructed on purpose (each slot is written before it is
// read; Vec2 and Interval would zero themselves), so that a big capacity
// costs only the pages a window actually uses.
template <class T, std::size_t M>
struct Slots {
  union {
    T item[M];
  };
  Slots() {}
  operator T*() { return item; }
  operator const T*() const { return item; }
};

// The window and the decision rule, for any criterion. Criterion supplies
//   kLag      labels trail the newest point by this many points (a band
//             gate depends on the next point);
//   kContext  points kept before the root (a band gate depends on the
//             previous one);
//   prepare(pts, size), called when the points changed;
//   feasible(pts, i, j, hint), alive(pts, i, j), piece(pts, i, j) on local
//   indices, as the whole-input search's oracle.
// N: the capacity (compile time). The window actually used can be smaller
// (begin(window)), so one build serves several window lengths.
template <class S, std::size_t N, class Criterion>
class StreamEngine {
  static_assert(N >= 8 && N < 0x40000000u, "a window holds 8 .. 2^30 points");

 public:
  using Value = S;  // the scalar type
  static constexpr std::uint32_t kCapacity = static_cast<std::uint32_t>(N);
  // Points of the window that hold no start of the decision: the context
  // before the root and the newest points, not labelled yet.
  static constexpr std::uint32_t kMargin = Criterion::kLag + Criterion::kContext;
  static constexpr std::uint32_t kMinWindow = 4 + kMargin;

  StreamEngine() = default;
  // The criterion may point into its own storage.
  StreamEngine(const StreamEngine&) = delete;
  StreamEngine& operator=(const StreamEngine&) = delete;

  // Adds the next point; the sink is called as sink(piece, forced_end) for
  // each piece decided, forced_end marking the last piece of a forced
  // commit (its end is a cut r_k). degenerate: p equals the previous point;
  // invalid_argument: p not finite; capacity_exceeded: 2^32 points.
  // invalid_argument also for |x| or |y| above the extent (scale_for).
  template <class Sink>
  Status push(Vec2<S> p, Sink& sink) {
    if (!Scalar<S>::is_finite(p.x) || !Scalar<S>::is_finite(p.y)) return Status::invalid_argument;
    if (extent_ > S(0) && (extent_ < Scalar<S>::abs(p.x) || extent_ < Scalar<S>::abs(p.y)))
      return Status::invalid_argument;
    if (size_ > 0 && orig_[size_ - 1] == p) return Status::degenerate;
    if (base_ + size_ >= 0xFFFFFFFFu) return Status::capacity_exceeded;
    if (size_ >= window_) force(sink);
    const std::uint32_t m = size_++;
    orig_[m] = p;
    pts_[m] = p * scale_;
    ++stats_.points;
    if (size_ > stats_.peak) stats_.peak = size_;
    if (m == 0) {
      root_ = 0;
      labeled_ = 1;
      dist_[0] = 0;
      pred_[0] = 0;
      live_[0] = 1;
      hint_[0] = 0;
      return Status::ok;
    }
    crit_.prepare(pts_, size_);
    while (labeled_ + Criterion::kLag < size_) label(labeled_++);
    decide(sink);
    return Status::ok;
  }

  // Ends the stream: emits the rest of the path to the last point.
  // invalid_argument if fewer than two points came.
  template <class Sink>
  Status finish(Sink& sink) {
    if (stats_.points < 2) return Status::invalid_argument;
    if (size_ > root_ + 1) {
      crit_.prepare(pts_, size_);
      while (labeled_ < size_) label(labeled_++);
      commit(size_ - 1, false, sink);
    }
    return Status::ok;
  }

  const StreamStats& stats() const { return stats_; }
  std::uint32_t window() const { return window_; }
  // H of the bound: a forced commit moves the root on by at least this.
  std::uint32_t forced_step() const { return (window_ - 1 - kMargin) / 2; }

  // Fits in the whole-input fitters' frame: the points scaled by the power
  // of two (Scalar<S>::normaliser) that brings `extent`, the largest |x| or
  // |y| the stream will hold, into [0.5, 1). Those fitters take it from the
  // largest coordinate of their input; given an extent in the same octave,
  // the stream computes what they compute (the same operations on the same
  // scaled numbers), which matters in kerf::Fixed. Points beyond the extent
  // are refused. Call after start(), before the first point; in double the
  // scale changes nothing but the refusal (powers of two are exact).
  Status scale_for(S extent) {
    if (!Scalar<S>::is_finite(extent) || !(extent > S(0)) || stats_.points > 0)
      return Status::invalid_argument;
    extent_ = extent;
    scale_ = Scalar<S>::normaliser(extent);
    unscale_ = S(1) / scale_;
    crit_.rescale(scale_);
    return Status::ok;
  }

 protected:
  Status begin(std::uint32_t window) {
    if (window < kMinWindow || window > kCapacity) return Status::invalid_argument;
    window_ = window;
    extent_ = S(0);
    scale_ = S(1);
    unscale_ = S(1);
    size_ = 0;
    root_ = 0;
    labeled_ = 0;
    base_ = 0;
    stats_ = StreamStats{};
    return Status::ok;
  }

  Criterion crit_;

 private:
  // d and pred of node v, the next one to label; drops starts whose guard
  // fails at v.
  void label(std::uint32_t v) {
    std::uint32_t best_d = dist_[v - 1] + 1;
    std::uint32_t best_i = v - 1;  // one step is always a valid piece
    for (std::uint32_t i = v - 1; i-- > root_;) {
      if (live_[i] == 0) continue;
      if (dist_[i] + 1 < best_d && crit_.feasible(pts_, i, v, hint_[i])) {
        best_d = dist_[i] + 1;
        best_i = i;
        continue;
      }
      // The guard is the search's cost: like min_count, ask it after a failed
      // test, and otherwise at every kGuardEvery-th end. Checking it at fewer
      // ends only keeps a start alive longer, which is still sound.
      if ((dist_[i] + 1 < best_d || (v - i) % kGuardEvery == 0) && !crit_.alive(pts_, i, v))
        live_[i] = 0;
    }
    dist_[v] = best_d;
    pred_[v] = best_i;
    live_[v] = 1;
    hint_[v] = 0;
    for (std::uint32_t i = root_; i < v; ++i) {  // the oldest live start
      if (live_[i] == 0) continue;
      if (v - i > stats_.reach) stats_.reach = v - i;
      break;
    }
  }

  // Labels every node again from the root, after a forced commit.
  // Liveness does not depend on the root, so it is kept.
  void relabel() {
    crit_.prepare(pts_, size_);
    for (std::uint32_t v = root_ + 1; v < labeled_; ++v) {
      std::uint32_t best_d = dist_[v - 1] + 1;
      std::uint32_t best_i = v - 1;
      for (std::uint32_t i = v - 1; i-- > root_;) {
        std::uint32_t hint = 0;
        if (dist_[i] + 1 < best_d && crit_.alive(pts_, i, v) && crit_.feasible(pts_, i, v, hint)) {
          best_d = dist_[i] + 1;
          best_i = i;
        }
      }
      dist_[v] = best_d;
      pred_[v] = best_i;
    }
    for (std::uint32_t v = root_; v < labeled_; ++v) hint_[v] = 0;
  }

  // Emits the pieces every candidate shares: root -> lowest common
  // ancestor of the frontier in the pred tree.
  template <class Sink>
  void decide(Sink& sink) {
    std::uint32_t total = 0;
    for (std::uint32_t v = root_; v < labeled_; ++v) {
      cnt_[v] = 0;
      total += live_[v];
    }
    for (std::uint32_t v = labeled_; v-- > root_ + 1;) {
      cnt_[v] += live_[v];
      if (cnt_[v] > 0) cnt_[pred_[v]] += cnt_[v];
    }
    for (std::uint32_t v = labeled_; v-- > root_ + 1;) {
      if (cnt_[v] == total) {
        commit(v, false, sink);
        return;
      }
    }
  }

  template <class Sink>
  void force(Sink& sink) {
    // The cut lies H past the root, and past the context too, so that the
    // commit frees a point (near the stream's start the root is below it).
    const std::uint32_t from = root_ + forced_step() > Criterion::kContext + 1
                                   ? root_ + forced_step()
                                   : Criterion::kContext + 1;
    std::uint32_t best = labeled_ - 1;  // the newest labelled point is always on the frontier
    for (std::uint32_t v = labeled_ - 1; v-- > from;)
      if (live_[v] != 0 && dist_[v] < dist_[best]) best = v;
    ++stats_.forced;
    commit(best, true, sink);
    relabel();
  }

  // Emits root -> r along pred and makes r the root.
  template <class Sink>
  void commit(std::uint32_t r, bool forced, Sink& sink) {
    std::uint32_t k = 0;
    for (std::uint32_t v = r; v != root_; v = pred_[v]) path_[k++] = v;
    std::uint32_t i = root_;
    while (k-- > 0) {
      const std::uint32_t j = path_[k];
      Piece<S> piece = crit_.piece(pts_, i, j);
      piece.segment.start = orig_[i];  // as the whole-input fitters write them
      piece.segment.end = orig_[j];
      piece.segment.centre = piece.segment.centre * unscale_;
      piece.error = piece.error * unscale_;
      piece.first = static_cast<std::uint32_t>(base_ + i);
      piece.last = static_cast<std::uint32_t>(base_ + j);
      sink(piece, forced && k == 0);
      ++stats_.pieces;
      i = j;
    }
    shift(r);
  }

  // Drops the points before r (keeping kContext of them).
  void shift(std::uint32_t r) {
    const std::uint32_t from = r >= Criterion::kContext ? r - Criterion::kContext : 0;
    for (std::uint32_t v = from; v < size_; ++v) {
      const std::uint32_t w = v - from;
      pts_[w] = pts_[v];
      orig_[w] = orig_[v];
      dist_[w] = dist_[v];
      pred_[w] = pred_[v] >= from ? pred_[v] - from : 0;  // below: a dead non-descendant
      live_[w] = v < r ? 0 : live_[v];  // the context is no start
      hint_[w] = hint_[v];
    }
    size_ -= from;
    labeled_ -= from;
    root_ = r - from;
    base_ += from;
  }

  static constexpr std::uint32_t kGuardEvery = 8;

  std::uint32_t window_ = kCapacity;
  std::uint32_t size_ = 0;     // points held
  std::uint32_t root_ = 0;     // local index of the root
  std::uint32_t labeled_ = 0;  // nodes [0, labeled_) have labels
  std::uint64_t base_ = 0;     // stream index of local 0
  StreamStats stats_{};
  S extent_{};  // 0: none
  S scale_ = S(1);
  S unscale_ = S(1);
  Slots<Vec2<S>, N> pts_;   // scaled
  Slots<Vec2<S>, N> orig_;  // as pushed
  Slots<std::uint32_t, N> dist_;
  Slots<std::uint32_t, N> pred_;
  Slots<std::uint32_t, N> hint_;
  Slots<std::uint32_t, N> cnt_;
  Slots<std::uint32_t, N> path_;
  Slots<std::uint8_t, N> live_;
};

// The vertex criterion (fit/fit.hpp): the whole-input fitter's oracle and
// piece choice; a pair depends only on the points between its ends.
template <class S, std::size_t N>
struct VertexCriterion {
  static constexpr std::uint32_t kLag = 0;
  static constexpr std::uint32_t kContext = 0;
  static constexpr std::size_t kSetHalf = 3 * N + 8;  // fit.hpp's workspace_intervals / 2

  S tol{};
  S eps{};  // tol in the scaled frame
  Method method = Method::optimal;
  Slots<Interval<S>, 2 * kSetHalf> sets;

  AngleSet<S> set() {
    return AngleSet<S>(Span<Interval<S>>(sets.item, kSetHalf),
                       Span<Interval<S>>(sets.item + kSetHalf, kSetHalf));
  }
  void rescale(S factor) { eps = tol * factor; }
  void prepare(const Vec2<S>*, std::uint32_t) {}
  bool feasible(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, std::uint32_t& hint) {
    AngleSet<S> s = set();
    return Oracle<S>{pts, eps, method, &s}(i, j, hint);
  }
  bool alive(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j) {
    return prefix_guard(pts, i, j, eps);
  }
  Piece<S> piece(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j) {
    AngleSet<S> s = set();
    const PieceFit<S> f = choose_piece(pts, i, j, eps, method, s);
    const Chord<S> chord(pts[i], pts[j]);
    const Vec2<S> centre = f.line ? Vec2<S>{} : chord.centre(f.direction);
    return Piece<S>{i, j, make_segment(chord, pts + i + 1, j - i - 1, f.line, centre, eps, f.dir), f.error};
  }
};

}  // namespace detail

// The vertex criterion, streamed.
template <class S, std::size_t N>
class PointWindow : public detail::StreamEngine<S, N, detail::VertexCriterion<S, N>> {
 public:
  // Starts a new stream. invalid_argument: tol not finite and > 0, or a
  // window outside [4, N].
  Status start(S tol, Method method, std::uint32_t window = static_cast<std::uint32_t>(N)) {
    if (!detail::tol_ok(tol)) return Status::invalid_argument;
    this->crit_.tol = tol;
    this->crit_.eps = tol;
    this->crit_.method = method;
    return this->begin(window);
  }
};

// A compiled instance (src/stream_double.cpp), so that the core's symbol
// scan covers the streaming code: the pieces of a stream fit, 0 on an error.
std::uint64_t stream_count_window64(PointWindow<double, 64>& w, Span<const Vec2<double>> pts,
                                    double tol);

}  // namespace kerf::fit
