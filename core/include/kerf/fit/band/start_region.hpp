// The circles through one start p_i that every cell from i on allows, kept
// as the end point j grows: the paper's incremental regions of centres
// (Drysdale, Rote, Sturm, Lemmas 2.5 and 2.10), here only as a quick "yes"
// in front of the per-pair test (fit/band/pair.hpp). The search asks a
// start about j, j + 1, ... in turn; the pair test visits every cell
// between each time (O(L^2) cells for a piece of L points), this region
// adds each cell once. The chart below is the centre plane seen
// projectively, so that lines (centres at infinity) are points in it too.
//
// Chart. With f the forward normal of gate i (unit), e = f.perp() and
// r = q - p_i, the circles (and lines) through p_i that leave it within 90
// degrees of f are the zero sets of
//     F(q) = lambda |r|^2 - 2 (e + tau f).r,
// one point (tau, lambda) each: the centre is p_i + (e + tau f) / lambda,
// lambda = 0 the line. Followed from p_i with tangent R(grad F) (R the
// quarter turn), the arc is counter-clockwise when lambda > 0, so an
// orientation o is the half plane o lambda >= 0, and q lies outside the
// disc when o F(q) >= 0. Every condition of the pair test is then a half
// plane in (tau, lambda), and the region a convex polygon:
//  - a chain point q on the bulge side (side -o) outside the disc; a chain
//    segment q1 -> q2 outside it when both ends are, each by
//    |lambda| |q2 - q1|^2 / 4 (o F along the segment is convex, with
//    leading term |lambda| |q2 - q1|^2 t^2): a sufficient condition;
//  - gate k's end on side +o inside the disc;
//  - for the pair with p_j: F(p_j) = 0, a line through the polygon, and
//    the arc reaching p_j forwards through gate j, g.R(grad F(p_j)) >= 0.
// The pair test's other conditions are checked here as they are there: no
// gate wholly beyond the chord, no barrier between (the caller's).
//
// A "yes" must never be a pair the pair test refuses: the polygon is kept
// inside the conditions by a margin far above its rounding (each half
// plane is moved in by 2^-30 of its terms at the box's extent), and the box
// itself is bounded (tangents within 86 degrees of f, radii above 1/64 of
// the first edge), which only drops arcs. A "no" says nothing: the caller
// runs the pair test. Floating point only.
#pragma once

#include <cstdint>
#include <type_traits>  // freestanding

#include "kerf/fit/band/numeric.hpp"
#include "kerf/fit/band/pair.hpp"
#include "kerf/fit/band/region.hpp"

namespace kerf::fit::band_detail {

template <class S>
class StartRegion {
 public:
  // Edges the polygon keeps; past that it is cut down by chords (16: the
  // search keeps four regions on the stack, within the 4 KiB that the
  // Cortex-M build allows a function).
  static constexpr int kMaxEdges = 16;

  std::uint32_t start() const { return start_; }
  std::uint32_t level() const { return level_; }

  // Starts over at start i (i + 1 < the region's size) in orientation
  // `orient`: the box alone, no cell yet.
  void reset(const BandRegion<S>& r, std::uint32_t i, int orient) {
    start_ = i;
    orient_ = orient;
    level_ = i;
    a_ = r.point(i);
    f_ = r.forward(i, false);
    e_ = f_.perp();
    const S first = length(r.point(i + 1) - a_);
    tau_max_ = S(16);
    lambda_max_ = first > S(0) ? S(64) * S(17) / first : S(0);  // 17 > |e + tau f| in the box
    count_ = first > S(0) ? 4 : 0;
    const S lo = orient > 0 ? S(0) : -lambda_max_;
    const S hi = orient > 0 ? lambda_max_ : S(0);
    // Counter-clockwise in (tau, lambda); edge t runs from vertex t to t + 1.
    set_vertex(0, -tau_max_, lo, {S(0), S(1), -lo});
    set_vertex(1, tau_max_, lo, {-S(1), S(0), tau_max_});
    set_vertex(2, tau_max_, hi, {S(0), -S(1), hi});
    set_vertex(3, -tau_max_, hi, {S(1), S(0), tau_max_});
  }

  // Adds the cells up to j - 1: their bulge-side chains, and gates up to
  // j - 1. False once the region is empty or gave up.
  bool reach(const BandRegion<S>& r, std::uint32_t j) {
    while (level_ < j && count_ > 0) add_cell(r, level_++);
    return count_ > 0;
  }

  // Does some arc from p_i to p_j of this orientation pass the pair test
  // (with margin)? Call after reach(r, j). No barrier may lie between.
  // `binding`, if given, receives after a yes the cells whose conditions
  // bound the arcs found (kNoCell: the box, a chord or the ends), as the
  // pair test's run() gives them: the search visits them first in its
  // next pair test.
  bool admits(const BandRegion<S>& r, std::uint32_t j, std::uint32_t* binding = nullptr) const {
    if (count_ == 0 || level_ != j) return false;
    const Vec2<S> rb = r.point(j) - a_;
    const S ab = rb.norm2();
    if (!(ab > S(0))) return false;
    // On F(p_j) = 0: lambda = -(tau bb + cb) / ab, bb = -2 f.rb, cb = -2 e.rb.
    const S bb_ab = S(-2) * f_.dot(rb) / ab;
    const S cb_ab = S(-2) * e_.dot(rb) / ab;
    S lo = -tau_max_;
    S hi = tau_max_;
    std::uint32_t lo_cell = kNoCell;
    std::uint32_t hi_cell = kNoCell;
    auto bound = [&](const Plane& h) {
      // h.a tau + h.b lambda + h.c >= 0 along the line.
      const S k = h.a - h.b * bb_ab;
      const S c = h.c - h.b * cb_ab;
      // -c / k, divided only where it tightens the interval.
      if (k > S(0)) {
        if (-c > lo * k) lo = -c / k, lo_cell = h.cell;
      } else if (k < S(0)) {
        if (-c > hi * k) hi = -c / k, hi_cell = h.cell;
      } else if (c < S(0)) {
        hi = lo - S(1);
      }
    };
    for (int t = 0; t < count_; ++t) bound(edge_[t]);
    // Forwards through gate j: lambda g x rb - g x e - tau g x f >= 0,
    // written with cross(v, g) = v.x g.y - v.y g.x.
    const Vec2<S> g = r.forward(j, true);
    bound(with_margin({-f_.cross(g), rb.cross(g), -e_.cross(g)}));
    if (!(hi - lo > kMargin * (Scalar<S>::abs(lo) + Scalar<S>::abs(hi) + S(1)))) return false;
    if (!no_gate_beyond_chord(r, j)) return false;
    if (binding != nullptr) {
      binding[0] = lo_cell;
      binding[1] = hi_cell;
    }
    return true;
  }

 private:
  static constexpr std::uint32_t kNoCell = BandPair<S>::kNoCell;  // what run()'s binding takes
  struct Plane {
    S a, b, c;  // a tau + b lambda + c >= 0
    std::uint32_t cell = kNoCell;  // the cell whose condition it is
  };
  static constexpr S kMargin = S(1) / S(1073741824);  // 2^-30

  void set_vertex(int t, S tau, S lambda, Plane h) {
    tau_[t] = tau;
    lambda_[t] = lambda;
    edge_[t] = h;
  }

  // h moved inwards by 2^-30 of its terms' size over the box.
  Plane with_margin(Plane h) const {
    const S size = Scalar<S>::abs(h.a) * tau_max_ + Scalar<S>::abs(h.b) * lambda_max_ + Scalar<S>::abs(h.c);
    return {h.a, h.b, h.c - kMargin * size, h.cell};
  }

  // o F(q) >= slack |lambda| (outside, slack = the longest adjacent chain
  // segment squared / 4), or o F(q) <= 0 (inside).
  void outside(Vec2<S> q, S slack, std::uint32_t cell) {
    const Vec2<S> rq = q - a_;
    const S o = S(orient_);
    // o F(q) - |lambda| slack = o (lambda (A - slack) + tau B + C), as
    // |lambda| = o lambda.
    clip(with_margin({o * S(-2) * f_.dot(rq), o * (rq.norm2() - slack), o * S(-2) * e_.dot(rq), cell}));
  }
  void inside(Vec2<S> q, std::uint32_t cell) {
    const Vec2<S> rq = q - a_;
    const S o = S(orient_);
    clip(with_margin({o * S(2) * f_.dot(rq), -o * rq.norm2(), o * S(2) * e_.dot(rq), cell}));
  }

  void add_cell(const BandRegion<S>& r, std::uint32_t k) {
    if (k > start_) inside(r.gate_end(k, orient_), k - 1);  // gate k is cell k - 1's
    if (const BandChainSlot<S>* slot = r.cached_slot(k, -orient_)) {
      add_chain(slot->chain, k > start_, k);
    } else {
      BandChain<S> own;  // 40 points zeroed: only without a cache
      r.chain(k, -orient_, own);
      add_chain(own, k > start_, k);
    }
  }

  // A chain's points outside, each by its segments' slack. Its first point
  // is the last one of the chain before (`follows`): taken again only when
  // its slack here is larger.
  void add_chain(const BandChain<S>& c, bool follows, std::uint32_t cell) {
    S before = S(0);  // the squared length of the segment before point t
    for (int t = 0; t < c.size && count_ > 0; ++t) {
      const S after = t + 1 < c.size ? (c.pt[t + 1] - c.pt[t]).norm2() : S(0);
      const S slack = max_of(before, after);
      if (t > 0 || !follows || after > last_slack_) outside(c.pt[t], slack / S(4), cell);
      before = after;
      if (t + 1 == c.size) last_slack_ = slack;
    }
  }

  // Cuts the polygon with h. The vertices outside form one run (it is
  // convex): the run is replaced by the points where the boundary leaves
  // and enters h, in place.
  void clip(Plane h) {
    const int n = count_;
    if (n == 0) return;
    S s[kMaxEdges + 1];
    s[0] = h.a * tau_[0] + h.b * lambda_[0] + h.c;
    S low = s[0];
    S high = s[0];
    for (int t = 1; t < n; ++t) {
      s[t] = h.a * tau_[t] + h.b * lambda_[t] + h.c;
      low = min_of(low, s[t]);
      high = max_of(high, s[t]);
    }
    if (!(low < S(0))) return;  // every vertex inside: h cuts nothing
    if (high < S(0)) {
      count_ = 0;
      return;
    }
    auto next = [n](int t) { return t + 1 == n ? 0 : t + 1; };
    auto prev = [n](int t) { return t == 0 ? n - 1 : t - 1; };
    int first = 0;  // the run's first vertex
    while (!(s[first] < S(0) && !(s[prev(first)] < S(0)))) ++first;
    int last = first;
    while (s[next(last)] < S(0)) last = next(last);
    const int before = prev(first);
    const int after = next(last);
    // The points added: where the boundary leaves h on edge `before`, and
    // enters it on edge `last` (none where a vertex lies on h's line).
    S nt[2], nl[2];
    Plane ne[2];
    int added = 0;
    if (s[before] > S(0)) {
      const S w = s[before] / (s[before] - s[first]);
      nt[added] = tau_[before] + w * (tau_[first] - tau_[before]);
      nl[added] = lambda_[before] + w * (lambda_[first] - lambda_[before]);
      ne[added++] = h;
    } else {
      edge_[before] = h;
    }
    if (s[after] > S(0)) {
      const S w = s[last] / (s[last] - s[after]);
      nt[added] = tau_[last] + w * (tau_[after] - tau_[last]);
      nl[added] = lambda_[last] + w * (lambda_[after] - lambda_[last]);
      ne[added++] = edge_[last];
    }
    const int run = last >= first ? last - first + 1 : n - first + last + 1;
    const int m = n - run + added;
    if (m < 3) {  // down to a segment or a point: nothing inside
      count_ = 0;
      return;
    }
    if (last >= first) {  // move the vertices after the run into place
      const int shift = added - run;
      if (shift > 0)
        for (int t = n; t-- > last + 1;) move_vertex(t, t + shift);
      else if (shift < 0)
        for (int t = last + 1; t < n; ++t) move_vertex(t, t + shift);
      for (int k = 0; k < added; ++k) set_vertex(first + k, nt[k], nl[k], ne[k]);
    } else {  // the run wraps: the kept vertices after..before go first
      for (int t = after; t <= before; ++t) move_vertex(t, t - after);
      for (int k = 0; k < added; ++k) set_vertex(before - after + 1 + k, nt[k], nl[k], ne[k]);
    }
    count_ = m;
    if (m > kMaxEdges)  // one vertex too many: cut down by chords
      while (count_ > kMaxEdges * 3 / 4) chord_over(smallest_corner());
  }

  void move_vertex(int from, int to) { set_vertex(to, tau_[from], lambda_[from], edge_[from]); }

  // The vertex whose triangle with its neighbours is smallest.
  int smallest_corner() const {
    int best = 0;
    S least = S(0);
    for (int t = 0; t < count_; ++t) {
      const int p = t == 0 ? count_ - 1 : t - 1;
      const int q = t + 1 == count_ ? 0 : t + 1;
      const S area = Scalar<S>::abs((tau_[t] - tau_[p]) * (lambda_[q] - lambda_[p]) -
                                    (lambda_[t] - lambda_[p]) * (tau_[q] - tau_[p]));
      if (t == 0 || area < least) least = area, best = t;
    }
    return best;
  }

  // Cuts off vertex t along the chord between its neighbours (inside the
  // polygon, which it is convex: the region only shrinks). Keeps the
  // polygon within kMaxEdges on a long piece of a circle, where each cell
  // adds an edge.
  void chord_over(int t) {
    const int p = t == 0 ? count_ - 1 : t - 1;
    const int q = t + 1 == count_ ? 0 : t + 1;
    const S dt = tau_[q] - tau_[p];
    const S dl = lambda_[q] - lambda_[p];
    // Left of p -> q (counter-clockwise polygon): -dl tau + dt lambda + c >= 0.
    edge_[p] = with_margin({-dl, dt, dl * tau_[p] - dt * lambda_[p]});
    for (int k = t; k + 1 < count_; ++k) set_vertex(k, tau_[k + 1], lambda_[k + 1], edge_[k + 1]);
    --count_;
  }

  // The pair test refuses a piece when a gate between lies wholly beyond
  // its chord (fit/band/pair.hpp, cell()): the same test, per gate.
  bool no_gate_beyond_chord(const BandRegion<S>& r, std::uint32_t j) const {
    const Vec2<S> n = (r.point(j) - a_).perp() * S(orient_);
    for (std::uint32_t k = start_ + 1; k < j; ++k)
      if ((r.gate_end(k, -orient_) - a_).dot(n) > S(0) && (r.gate_end(k, orient_) - a_).dot(n) > S(0))
        return false;
    return true;
  }

  std::uint32_t start_ = 0xFFFFFFFFu;  // none yet
  int orient_ = 1;
  std::uint32_t level_ = 0;  // cells start_ .. level_ - 1 are in
  int count_ = 0;            // vertices (= edges); 0: empty or given up
  Vec2<S> a_{};
  Vec2<S> f_{};
  Vec2<S> e_{};
  S tau_max_{};
  S lambda_max_{};
  S last_slack_{};  // the slack the last chain's last point was taken with
  S tau_[kMaxEdges + 1];  // one more while a clip has added a vertex
  S lambda_[kMaxEdges + 1];
  Plane edge_[kMaxEdges + 1];
};

// A few start regions per orientation, the least recently used started
// over for another start: the search asks the nearest start about each j
// first, and when its reach ends, a farther one takes over.
template <class S>
class StartRegions {
 public:
  static constexpr int kSlots = 2;

  // The region of start i in `orient`, if kept and not past j.
  StartRegion<S>* find(std::uint32_t i, int orient, std::uint32_t j) {
    const int base = first_slot(orient);
    for (int k = base; k < base + kSlots; ++k) {
      StartRegion<S>& q = slot_[k];
      if (q.start() == i && q.level() <= j) {
        used_[k] = ++clock_;
        return &q;
      }
    }
    return nullptr;
  }

  // A region started over at i (the orientation's least recently used).
  StartRegion<S>& take(const BandRegion<S>& r, std::uint32_t i, int orient) {
    const int base = first_slot(orient);
    int k = base;
    for (int t = base + 1; t < base + kSlots; ++t)
      if (used_[t] < used_[k]) k = t;
    used_[k] = ++clock_;
    slot_[k].reset(r, i, orient);
    return slot_[k];
  }

 private:
  static int first_slot(int orient) { return orient > 0 ? 0 : kSlots; }

  StartRegion<S> slot_[2 * kSlots] = {};
  std::uint32_t used_[2 * kSlots] = {};
  std::uint32_t clock_ = 0;
};

// What the search keeps instead in fixed point, where it has no start
// regions (their margins are relative to rounding in floating point).
struct NoStartRegion {};

}  // namespace kerf::fit::band_detail
