// Definitions behind fit/band/region.hpp (see the construction there).
#pragma once

#include "kerf/fit/band/numeric.hpp"
#include "kerf/fit/band/region.hpp"

namespace kerf::fit {

namespace band_detail {

// A direction's angle as a number in [0, 4) that grows with the angle
// ("diamond angle"): enough to add up how far a polygon turns.
template <class S>
S diamond(Vec2<S> v) {
  const S ax = Scalar<S>::abs(v.x);
  const S ay = Scalar<S>::abs(v.y);
  const S t = v.y / (ax + ay);  // in [-1, 1]
  if (v.x >= S(0)) return v.y >= S(0) ? t : S(4) + t;
  return S(2) - t;
}

template <class S>
void push(BandChain<S>& c, Vec2<S> p) {
  if (c.size > 0 && c.pt[c.size - 1] == p) return;
  KERF_ASSERT(c.size < kBandChainMax);
  c.pt[c.size++] = p;
}

}  // namespace band_detail

template <class S>
void BandRegion<S>::set_vertex(std::uint32_t k, S left, S right) {
  using M = Scalar<S>;
  BandVertex<S>& v = v_[k];
  v.convex = false;  // cells k - 1 and k change with vertex k
  if (k > 0) v_[k - 1].convex = false;
  v.left = left;
  v.right = right;
  v.turn = 0;
  v.barrier = false;
  v.gate_left = left;
  v.gate_right = right;
  v.split[0] = v.split[1] = 0;  // end vertices have no corner
  if (k == 0) {
    v.b = v_[0].n;
    return;
  }
  const Vec2<S> n0 = v_[k - 1].n;
  if (k + 1 == n_) {
    v.b = n0;
    return;
  }
  const Vec2<S> n1 = v.n;
  const Vec2<S> sum = n0 + n1;
  const S len = band_detail::length(sum);
  if (!(len > S(1e-6))) {  // a cusp: the path turns back on itself
    v.b = n0;
    v.gate_left = v.gate_right = S(0);
    v.barrier = true;
    return;
  }
  v.b = sum * (S(1) / len);
  const S turn = n0.cross(n1);
  v.turn = static_cast<std::int8_t>(turn > S(0) ? 1 : (turn < S(0) ? -1 : 0));
  const S co = v.b.dot(n1);  // cos(a / 2)
  const S si = M::abs(v.b.cross(n1));
  const S c = (left - right) / S(2);
  const S w = (left + right) / S(2);
  const S root = band_detail::gate_root(w, c, si);
  // A side of width 0 has a gate half of exactly 0 (the formula leaves a
  // rounding residue, which would put a chain point next to, not on, p_k).
  v.gate_left = left == S(0) ? S(0) : max_of(S(0), c * co + root);
  v.gate_right = right == S(0) ? S(0) : max_of(S(0), root - c * co);
  if (v.gate_left == S(0) && v.gate_right == S(0)) v.barrier = true;
  // The outer side is the left one at a right turn. Its gate end, seen from
  // the centre of each edge's disc, against that disc's offset point.
  const int side = v.turn < 0 ? 1 : -1;
  const S width = side > 0 ? left : right;
  if (v.turn != 0 && width > S(0) && w > S(0)) {
    const Vec2<S> end = v.b * (side > 0 ? v.gate_left : -v.gate_right);  // from p_k
    const Vec2<S> e_in = (end - n0 * c) * (S(1) / w);
    const Vec2<S> e_out = (end - n1 * c) * (S(1) / w);
    v.split[0] = split_depth(n0 * S(side), e_in, w, width);
    v.split[1] = split_depth(e_out, n1 * S(side), w, width);
  }
}

// How many times the corner arc between unit directions e1 and e2 (radius
// w) must be halved for every chord's sagitta to be <= 1% of the side's
// width: cos of half a chord's angle is |e1 + e2| / 2 at first, and each
// halving takes c to sqrt((1 + c) / 2). At most 4 (16 chords).
template <class S>
std::uint8_t BandRegion<S>::split_depth(Vec2<S> e1, Vec2<S> e2, S w, S width) {
  S c = band_detail::length(e1 + e2) / S(2);
  std::uint8_t depth = 0;
  while (depth < 4 && w * (S(1) - c) > S(0.01) * width) {
    c = Scalar<S>::sqrt((S(1) + c) / S(2));
    ++depth;
  }
  return depth;
}

// The chords of the disc of vertex k's side of edge `edge`, from `from` to
// `to` (both on its circle), halved `depth` times; pushes the inner points
// and `to`.
template <class S>
void BandRegion<S>::corner(std::uint32_t k, std::uint32_t edge, Vec2<S> from, Vec2<S> to,
                           int depth, BandChain<S>& out) const {
  if (depth > 0) {
    const BandVertex<S>& v = v_[k];
    const S c = (v.left - v.right) / S(2);
    const S w = (v.left + v.right) / S(2);
    const Vec2<S> centre = p_[k] + v_[edge].n * c;
    struct Piece {
      Vec2<S> e1, e2;  // unit directions from the centre
      int depth;
    };
    Piece stack[8];
    int top = 0;
    stack[top++] = {(from - centre) * (S(1) / w), (to - centre) * (S(1) / w), 0};
    while (top > 0) {
      const Piece s = stack[--top];
      const Vec2<S> sum = s.e1 + s.e2;
      const S len = band_detail::length(sum);
      if (s.depth >= depth || !(len > S(0))) {
        if (top > 0) band_detail::push(out, centre + s.e2 * w);  // the last one is `to`
        continue;
      }
      const Vec2<S> mid = sum * (S(1) / len);
      stack[top++] = {mid, s.e2, s.depth + 1};  // popped second
      stack[top++] = {s.e1, mid, s.depth + 1};  // popped first
    }
  }
  band_detail::push(out, to);
}

template <class S>
const BandChainSlot<S>* BandRegion<S>::cached_slot(std::uint32_t k, int side) const {
  if (cache_ == nullptr) return nullptr;
  const std::size_t key = 2 * static_cast<std::size_t>(k) + (side > 0 ? 2 : 1);
  BandChainSlot<S>& slot = cache_[key & cache_mask_];
  if (slot.key != key) fill_slot(k, side, key, slot);
  return &slot;
}

// Kept out of line: the lookup above is the pair test's hot path.
template <class S>
__attribute__((noinline)) void BandRegion<S>::fill_slot(std::uint32_t k, int side, std::size_t key,
                                                        BandChainSlot<S>& slot) const {
  build_chain(k, side, slot.chain);
  slot.key = key;
  const BandChain<S>& c = slot.chain;
  Vec2<S> lo = c.size > 0 ? c.pt[0] : Vec2<S>{};
  Vec2<S> hi = lo;
  for (int t = 1; t < c.size; ++t) {
    lo = {min_of(lo.x, c.pt[t].x), min_of(lo.y, c.pt[t].y)};
    hi = {max_of(hi.x, c.pt[t].x), max_of(hi.y, c.pt[t].y)};
  }
  slot.box_lo = lo;
  slot.box_hi = hi;
  if constexpr (band_detail::kFloating<S>) {
    S thickness = S(0);
    for (int t = 1; t + 1 < c.size; ++t)
      thickness = max_of(thickness, distance_to_line_segment(c.pt[0], c.pt[c.size - 1], c.pt[t]));
    slot.thickness = thickness;
  }
}

template <class S>
const BandChain<S>* BandRegion<S>::cached_chain(std::uint32_t k, int side) const {
  const BandChainSlot<S>* slot = cached_slot(k, side);
  return slot != nullptr ? &slot->chain : nullptr;
}

template <class S>
void BandRegion<S>::chain(std::uint32_t k, int side, BandChain<S>& out) const {
  const BandChain<S>* cached = cached_chain(k, side);
  if (cached == nullptr) {
    build_chain(k, side, out);
    return;
  }
  out.size = cached->size;
  for (int t = 0; t < out.size; ++t) out.pt[t] = cached->pt[t];
}

template <class S>
void BandRegion<S>::build_chain(std::uint32_t k, int side, BandChain<S>& out) const {
  out.size = 0;
  const BandVertex<S>& a = v_[k];
  const BandVertex<S>& b = v_[k + 1];
  const Vec2<S> n = a.n;
  const S sa = side > 0 ? a.left : -a.right;  // signed offsets of the edge's side
  const S sb = side > 0 ? b.left : -b.right;
  // The edge's side of the band is bounded by the outer common tangent of
  // its end discs (centres p + c n, radii w). Without a taper that is the
  // offset edge p_k + sa n -> p_{k+1} + sb n; with one, the tangent points
  // move round the discs, which keeps the cell convex where a widening
  // band meets an outer corner.
  const S ca = (a.left - a.right) / S(2), wa = (a.left + a.right) / S(2);
  const S cb = (b.left - b.right) / S(2), wb = (b.left + b.right) / S(2);
  const Vec2<S> c0 = p_[k] + n * ca;
  const Vec2<S> c1 = p_[k + 1] + n * cb;
  Vec2<S> t0 = p_[k] + n * sa;
  Vec2<S> t1 = p_[k + 1] + n * sb;
  if (wa != wb) {
    const Vec2<S> d = c1 - c0;
    const S len = band_detail::length(d);
    const S delta = (wb - wa) / len;
    if (delta < S(1) && delta > S(-1)) {
      const Vec2<S> e = d * (S(1) / len);
      const Vec2<S> m = e * (-delta) + e.perp() * (S(side) * Scalar<S>::sqrt(S(1) - delta * delta));
      t0 = c0 + m * wa;
      t1 = c1 + m * wb;
    }
  }
  const Vec2<S> start = gate_end(k, side);
  const Vec2<S> end = gate_end(k + 1, side);
  band_detail::push(out, start);
  // Outer side of the corner at k: round from the gate end to the tangent.
  // (At an end gate, and on the inner side, the chain starts straight.)
  // A taper turns the tangent point round its disc; past the gate's line
  // it belongs to the next cell, and the chain goes straight instead.
  const Vec2<S> fa{a.b.y, -a.b.x};
  const Vec2<S> fb{b.b.y, -b.b.x};
  if (k > 0 && a.turn == -side && sa != S(0) && (t0 - p_[k]).dot(fa) > S(0))
    corner(k, k, start, t0, a.split[1], out);
  // Outer side at k + 1: along the tangent, then round to the gate end. On
  // the inner side the tangent's end lies past gate k + 1, so the chain
  // heads straight for the gate end.
  if (k + 2 < n_ && b.turn == -side && sb != S(0) && (t1 - p_[k + 1]).dot(fb) < S(0)) {
    band_detail::push(out, t1);
    corner(k + 1, k, t1, end, b.split[0], out);
  } else {
    band_detail::push(out, end);
  }
}

// Walks the cell's outline (left chain forwards, right chain backwards: a
// clockwise loop) and checks every turn is to the right and that it turns
// exactly once around. bad_side: +1 left, -1 right, 0 both.
template <class S>
bool BandRegion<S>::cell_convex(std::uint32_t k, int& bad_side) const {
  BandChain<S> l;
  BandChain<S> r;
  chain(k, 1, l);
  chain(k, -1, r);
  Vec2<S> loop[2 * kBandChainMax];
  int side_of[2 * kBandChainMax];
  int m = 0;
  // Chain points carry rounding of a few ulps of the coordinates, which on
  // the tiny chords of a gentle corner is a visible turn. A turn counts only
  // when the point lies farther than that noise from its neighbours' line.
  const S big = max_of(max_of(Scalar<S>::abs(p_[k].x), Scalar<S>::abs(p_[k].y)),
                       max_of(Scalar<S>::abs(p_[k + 1].x), Scalar<S>::abs(p_[k + 1].y)));
  const S noise = S(4096) * Scalar<S>::epsilon() * big;
  const S tiny = max_of(S(1e-12) * band_detail::length(p_[k + 1] - p_[k]), noise);
  // A point farther than twice tiny along an axis is not within tiny: the
  // square root is taken only near that limit (tiny far above underflow).
  auto close = [&](Vec2<S> d) {
    if constexpr (band_detail::kFloating<S>)
      if (tiny > S(1e-150) && (Scalar<S>::abs(d.x) > S(2) * tiny || Scalar<S>::abs(d.y) > S(2) * tiny))
        return false;
    return band_detail::length(d) <= tiny;
  };
  auto add = [&](Vec2<S> q, int side) {
    if (m > 0 && close(q - loop[m - 1])) return;
    loop[m] = q;
    side_of[m++] = side;
  };
  for (int t = 0; t < l.size; ++t) add(l.pt[t], 1);
  for (int t = r.size; t-- > 0;) add(r.pt[t], -1);
  while (m > 1 && close(loop[m - 1] - loop[0])) --m;
  if (m < 3) return true;  // a cell narrowed to a segment
  S total = S(0);
  bool reflex_left = false;
  bool reflex_right = false;
  for (int t = 0; t < m; ++t) {
    const Vec2<S> e1 = loop[t] - loop[(t + m - 1) % m];
    const Vec2<S> e2 = loop[(t + 1) % m] - loop[t];
    const S cross = e1.cross(e2);
    // Both limits are >= 0: a turn to the right (every turn of a convex
    // cell) needs no lengths (their square roots were most of the check).
    if (cross > S(0) && cross > S(1e-9) * band_detail::length(e1) * band_detail::length(e2) &&
        cross > noise * band_detail::length(e1 + e2)) {
      (side_of[t] > 0 ? reflex_left : reflex_right) = true;
    }
    S d = band_detail::diamond(e2) - band_detail::diamond(e1);
    if (d > S(2)) d -= S(4);
    if (d <= S(-2)) d += S(4);
    total += d;
  }
  const bool once = Scalar<S>::abs(total + S(4)) < S(0.5);
  if (once && !reflex_left && !reflex_right) return true;
  bad_side = (!once || (reflex_left && reflex_right)) ? 0 : (reflex_left ? 1 : -1);
  return false;
}

template <class S>
Status BandRegion<S>::build(const BandWidth<S>* widths, S scale) {
  if (n_ < 2) return Status::invalid_argument;
  for (std::uint32_t k = 0; k + 1 < n_; ++k) {
    const Vec2<S> d = p_[k + 1] - p_[k];
    v_[k].n = d.perp() * (S(1) / band_detail::length(d));
  }
  v_[n_ - 1].n = v_[n_ - 2].n;
  for (std::uint32_t k = 0; k < n_; ++k)
    set_vertex(k, widths[k].left * scale, widths[k].right * scale);
  const S floor = S(1.0) / S(1048576.0);  // 2^-20 of the width asked for
  for (int pass = 0; pass < 100; ++pass) {
    bool changed = false;
    for (std::uint32_t k = 0; k + 1 < n_; ++k) {
      // A cell is a function of its two vertices: one found convex is
      // checked again only once one of them has changed (most of the
      // build's time went to checking the same cells pass after pass).
      if (v_[k].convex) continue;
      int bad = 0;
      if (cell_convex(k, bad)) {
        v_[k].convex = true;
        continue;
      }
      changed = true;
      for (std::uint32_t q = k; q <= k + 1; ++q) {
        BandVertex<S>& v = v_[q];
        S left = v.left;
        S right = v.right;
        if (bad >= 0) left = left / S(2) < widths[q].left * scale * floor ? S(0) : left / S(2);
        if (bad <= 0) right = right / S(2) < widths[q].right * scale * floor ? S(0) : right / S(2);
        set_vertex(q, left, right);
      }
    }
    if (!changed) return Status::ok;
  }
  // Still not convex after 100 rounds: give up the width of what is left.
  for (std::uint32_t k = 0; k + 1 < n_; ++k) {
    int bad = 0;
    if (cell_convex(k, bad)) continue;
    set_vertex(k, S(0), S(0));
    set_vertex(k + 1, S(0), S(0));
  }
  return Status::ok;
}

}  // namespace kerf::fit
