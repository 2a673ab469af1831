// The tolerance region R with gates that the band fitter works in
// (Drysdale, Rote, Sturm, section 2.1), built from per-vertex widths.
//
// The band kerf guarantees. Vertex k has a left width L_k and a right width
// R_k; write c_k = (L_k - R_k) / 2, w_k = (L_k + R_k) / 2. Along edge k,
// p_k -> p_{k+1} with unit left normal n_k, a point x is inside the band when
// it lies in some disc centred at p_k + s (p_{k+1} - p_k) + c(s) n_k with
// radius w(s), c and w interpolated linearly in s in [0, 1]. For L = R = tol
// this is "within tol of the polyline"; for L = 0 nothing left of the path
// is inside; a third input column gives per-vertex widths.
//
// R is a chain of cells, cell k between gate k and gate k + 1:
//  - Gate k runs through p_k along b_k = unit(n_{k-1} + n_k), the bisector
//    of the corner, to where that line leaves the two discs at p_k (of edge
//    k-1 and of edge k):  left half  c cos(a/2) + sqrt(w^2 - c^2 sin^2(a/2)),
//    right half -c cos(a/2) + sqrt(w^2 - c^2 sin^2(a/2)), a the turn angle.
//    (Symmetric: w on each side.) End gates are perpendicular to the end
//    edges. A cusp (|n_{k-1} + n_k| < 1e-6) gets a gate of length zero: a
//    barrier that no piece passes through.
//  - Each side of a cell is a chain from one gate end to the next: where the
//    side is the outer side of the corner, chords inscribed in the disc of
//    that corner, from the gate end round to the offset point p_k + L_k n_k,
//    halved until each chord's sagitta is at most 1% of the side's width (so
//    R keeps at least 99% of the band there); then the offset edge to
//    p_{k+1} + L_{k+1} n_k; then chords round to the next gate end. On the
//    inner side of a corner the chain leaves the gate end straight for the
//    next point. Every chain point lies in a disc of the band and each chain
//    segment lies in one edge's union of discs (a convex set), so R is
//    inside the band.
//  - Every cell must be convex: that is the paper's assumption (C), on which
//    the one-sided boundary test of the pair test (fit/band/pair.hpp)
//    relies. A cell that is not (short edges, sharp turns) has that side's
//    widths at both its vertices halved, and the build repeats until all
//    cells are convex; a width below 2^-20 of the original becomes 0. A
//    smaller disc of the same side edge stays inside the original one, so
//    the narrowed R is still inside the band. This is where kerf narrows R
//    as section 2.1 of the paper allows; a vertex narrowed to nothing on
//    both sides becomes a barrier.
#pragma once

#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::fit {

// The band's width at one vertex, each side >= 0.
template <class S>
struct BandWidth {
  S left{};
  S right{};
};

// What R stores per vertex k (and per edge k for n).
template <class S>
struct BandVertex {
  Vec2<S> n{};    // unit left normal of edge k (k < n-1)
  Vec2<S> b{};    // unit gate direction, pointing left
  S gate_left{};  // gate half lengths: ends p_k + gate_left b, p_k - gate_right b
  S gate_right{};
  S left{};       // the widths R is built from (narrowed where needed)
  S right{};
  std::int8_t turn = 0;     // +1 left turn at k, -1 right turn, 0 straight or an end
  bool barrier = false;     // no piece passes through this vertex
  // The outer corner's chords: 2^split[0] before the gate (cell k-1),
  // 2^split[1] after it (cell k).
  std::uint8_t split[2] = {0, 0};
  // (build) Cell k was found convex and neither vertex k nor k + 1 has
  // changed since: its check would say the same again.
  bool convex = false;
};

// A chain of R between two gates has at most this many points.
inline constexpr int kBandChainMax = 40;

template <class S>
struct BandChain {
  Vec2<S> pt[kBandChainMax];
  int size = 0;
};

// One entry of BandRegion's optional chain cache.
template <class S>
struct BandChainSlot {
  std::size_t key = 0;  // 2 k + (side > 0) + 1 for cell k; 0: empty
  BandChain<S> chain{};
  Vec2<S> box_lo{};  // the chain's bounding box (the pair test's snapping
  Vec2<S> box_hi{};  // skips a chain whose box is far from both ends)
  // (Floating point.) How far the chain strays from the segment between its
  // ends: the chain lies in that segment thickened by this much, which the
  // pair test checks in one go before the chain's own conditions.
  S thickness{};
};

template <class S>
class BandRegion {
 public:
  BandRegion() = default;
  BandRegion(const Vec2<S>* pts, std::uint32_t n, BandVertex<S>* v) : p_(pts), n_(n), v_(v) {}

  std::uint32_t size() const { return n_; }
  const Vec2<S>& point(std::uint32_t k) const { return p_[k]; }
  const BandVertex<S>& vertex(std::uint32_t k) const { return v_[k]; }
  __attribute__((always_inline)) Vec2<S> gate_end(std::uint32_t k, int side) const {
    const BandVertex<S>& v = v_[k];
    return side > 0 ? p_[k] + v.b * v.gate_left : p_[k] - v.b * v.gate_right;
  }
  // The forward normal of gate k: the direction an arc must cross it in.
  // A barrier has none; pieces arriving use the incoming edge, pieces
  // leaving the outgoing one.
  Vec2<S> forward(std::uint32_t k, bool arriving) const {
    const BandVertex<S>& v = v_[k];
    if (v.barrier && k > 0 && k + 1 < n_) {
      const Vec2<S> e = arriving ? v_[k - 1].n : v.n;
      return {e.y, -e.x};
    }
    return {v.b.y, -v.b.x};
  }

  // The chain of cell k on `side` (+1 left, -1 right), from gate k's end to
  // gate k+1's end, both included.
  void chain(std::uint32_t k, int side, BandChain<S>& out) const;
  // The same chain in the cache (built there if missing), or nullptr
  // without one. Valid until the next chain call.
  const BandChain<S>* cached_chain(std::uint32_t k, int side) const;
  // Its cache slot, with the chain's bounding box; nullptr without a cache.
  const BandChainSlot<S>* cached_slot(std::uint32_t k, int side) const;

  // Keeps the chains built since in `slots` (a power of two of them, by
  // cell; fewer than two: no cache): the pair test asks for the same cells
  // again and again, and a chain costs a corner's chords each time. Call it
  // after build (which narrows the widths, changing the chains); it clears
  // the slots. A cached chain is the one chain() builds, bit for bit.
  void cache_chains(Span<BandChainSlot<S>> slots) {
    cache_ = slots.size() >= 2 ? slots.data() : nullptr;
    std::size_t size = 1;
    while (size * 2 <= slots.size()) size *= 2;
    cache_mask_ = size - 1;
    for (std::size_t k = 0; cache_ != nullptr && k < size; ++k) cache_[k].key = 0;
  }

  // Builds R for widths * scale; widths has one entry per vertex.
  // Returns Status::ok; the cells are then convex.
  Status build(const BandWidth<S>* widths, S scale);

 private:
  void set_vertex(std::uint32_t k, S left, S right);
  void corner(std::uint32_t k, std::uint32_t edge, Vec2<S> from, Vec2<S> to, int depth,
              BandChain<S>& out) const;
  static std::uint8_t split_depth(Vec2<S> e1, Vec2<S> e2, S w, S width);
  bool cell_convex(std::uint32_t k, int& bad_side) const;
  void build_chain(std::uint32_t k, int side, BandChain<S>& out) const;
  void fill_slot(std::uint32_t k, int side, std::size_t key, BandChainSlot<S>& slot) const;

  const Vec2<S>* p_ = nullptr;
  std::uint32_t n_ = 0;
  BandVertex<S>* v_ = nullptr;
  BandChainSlot<S>* cache_ = nullptr;  // written through by the const chain()
  std::size_t cache_mask_ = 0;
};

}  // namespace kerf::fit
