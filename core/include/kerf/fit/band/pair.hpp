// The exact band test for one candidate piece p_i -> p_j: the set of valid
// arcs (Theorem 2.11 of Drysdale, Rote, Sturm) in one orientation.
//
// Every arc from a = p_i to b = p_j is fixed by its orientation and psi in
// [0, pi), half its sweep: psi = 0 is the line, psi = pi/2 the half circle.
// A counter-clockwise arc bulges to the right of a -> b. The clockwise case
// is the same one mirrored in the chord, so one routine handles both: it
// works in a frame whose y axis is the chord's left normal times `orient`
// (+1 for counter-clockwise), and "left" in the paper becomes gate side
// +orient.
//
// With d = (cos psi, sin psi) and, for a point q, A = (q - a).(q - b) and Y
// = (q - mid).N (N the frame's normal, |N| = |b - a|), the power of q with
// respect to the arc's circle times sin psi is  P = d.y A - d.x Y  = d.(-Y, A).
// So "q is outside the disc" (P >= 0) and "q is inside" (P <= 0) are each a
// half-plane through the origin in d, and so are the end conditions:
//  - the paper's wedges (Lemmas 2.3-2.5): for each gate m strictly between,
//    the disc contains the gate's end on side +orient and excludes the other
//    end, so the circle crosses the gate exactly once, the right way round;
//  - the rays on the bisector (Lemma 2.6): the arc leaves a through gate i
//    forwards, t_a = (cos psi, -sin psi), and reaches b forwards through
//    gate j, t_b = (cos psi, sin psi), in the frame;
//  - the Voronoi region of p_i (Lemmas 2.7-2.10): no point of the boundary
//    chain on the bulge side (side -orient) between gates i and j lies
//    inside the disc. For the chain's vertices that is one half-plane each;
//    for the inside of a chain segment, the binding points are where the
//    circle through a, b and the point is extreme along the segment, the
//    roots of a quadratic, plus where the segment crosses the chord line.
//    The other chain needs no test: the cells are convex (assumption (C)),
//    so the arc between two gate crossings stays on the far side of their
//    chord from it.
// A half-plane d.w >= 0 meets the half circle psi in [0, pi] in a prefix or
// a suffix (it is a half circle too), so the valid set is always one
// interval [lo, hi], kept as pseudo-angles (fit/detail/angle_set.hpp): no
// trigonometry and no square roots, and the line is simply psi = 0. This is
// the paper's test restricted to the bisector, done per pair instead of
// keeping the 2-D regions: the search's hints make failing pairs O(1). In
// floating point a cached chain is first tried whole, as a slab clear of the
// disc at both ends of the range (fit/band/slab.hpp): most cells of a piece
// that fits pass there, and the cells that bound a start's last test are
// visited first (run()), so that the range is narrow from the start.
#pragma once

#include <cstdint>

#include "kerf/fit/band/numeric.hpp"
#include "kerf/fit/band/region.hpp"
#include "kerf/fit/band/slab.hpp"
#include "kerf/fit/detail/angle_set.hpp"
#include "kerf/geom/roots.hpp"

namespace kerf::fit {

// Valid arcs of one orientation as an interval of psi's pseudo-angle,
// 0 = the line, 2 = the full circle (excluded).
template <class S>
struct PsiRange {
  S lo = S(0);
  S hi = S(2);
  bool empty() const { return hi < lo || !(lo < S(2)); }
};

template <class S>
class BandPair {
 public:
  static constexpr std::uint32_t kNoCell = 0xFFFFFFFFu;

  BandPair(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j, int orient)
      : r_(r), i_(i), j_(j), orient_(orient), a_(r.point(i)), b_(r.point(j)) {
    const Vec2<S> u = b_ - a_;
    mid_ = midpoint(a_, b_);
    f_ = band_detail::frame_factor(u);
    u_ = u * f_;
    n_ = u_.perp() * S(orient);
    reach_ = band_detail::rounding_reach(a_, b_);
    if constexpr (band_detail::kFloating<S>) chord_ = Scalar<S>::sqrt(u.norm2());
  }

  // The end conditions alone.
  bool ends(PsiRange<S>& range) const {
    const Vec2<S> f = r_.forward(i_, false);
    const Vec2<S> g = r_.forward(j_, true);
    cut(range, {f.dot(u_), -f.dot(n_)});
    cut(range, {g.dot(u_), g.dot(n_)});
    return !range.empty();
  }

  // No barrier lies strictly between the ends (the search knows it from
  // its table): cell() then need not look.
  void set_clear_between() { clear_between_ = true; }

  // Adds cell k's conditions (i <= k < j): its bulge-side chain, and gate
  // k + 1 when that gate lies strictly between the ends.
  bool cell(std::uint32_t k, PsiRange<S>& range) const {
    if (!clear_between_ && k > i_ && r_.vertex(k).barrier) {
      range.lo = S(2);
      return false;
    }
    // The cached chain is read in place (a BandChain is 40 points, zeroed
    // on construction: a copy per cell test cost more than the test).
    if (const BandChainSlot<S>* cached = r_.cached_slot(k, -orient_)) {
      const bool ok = apart(*cached) ? slab_clear(*cached, range) || chain_conditions<false>(cached->chain, range)
                                     : chain_conditions<true>(cached->chain, range);
      if (!ok) return false;
    } else {
      BandChain<S> c;
      r_.chain(k, -orient_, c);
      if (!chain_conditions<true>(c, range)) return false;
    }
    if (k + 1 < j_) {
      // The arc lies on its bulge side of the chord (offset <= 0), so a gate
      // wholly beyond the chord cannot be cut. The chains imply this where
      // the cells are convex; at a sharp turn with unequal widths they are
      // not, and the disc alone let a short arc "cross" a gate on its far
      // circle (found by tests/fuzz/fuzz_fit_band).
      const Vec2<S> gate = r_.gate_end(k + 1, orient_);
      if (offset(gate) > S(0) && offset(r_.gate_end(k + 1, -orient_)) > S(0)) {
        range.lo = S(2);
        return false;
      }
      inside(range, gate);
    }
    return !range.empty();
  }

  // The whole test; `fail` is set to the cell that emptied the range. The
  // conditions commute, so the cells are visited in bit-reversed order
  // (middle, ends, quarters, ...): a piece too long for the band usually
  // fails on a few far-apart gates together, long before a scan in order
  // would bring them together.
  //
  // `binding`, if given, names two cells (any values; those outside the
  // piece, kNoCell for one, are ignored) visited first, and receives after
  // a success the cells that last raised lo and lowered hi (kNoCell: none
  // did, the ends bound it). The search passes the cells
  // that bound the previous test of the same start and orientation: the
  // next end point is usually bound by the same cells, and with the range
  // narrowed at once the other cells pass the quick slab test
  // (slab_clear) instead of narrowing it a little at a time.
  bool run(PsiRange<S>& range, std::uint32_t& fail, std::uint32_t* binding = nullptr) const {
    range = PsiRange<S>{};
    if (!ends(range)) {
      fail = i_;
      return false;
    }
    std::uint32_t first[2] = {kNoCell, kNoCell};
    std::uint32_t bound[2] = {kNoCell, kNoCell};  // the last cell that moved lo, hi
    auto visit = [&](std::uint32_t k) {
      const PsiRange<S> before = range;
      if (!cell(k, range)) {
        fail = k;
        return false;
      }
      if (range.lo != before.lo) bound[0] = k;
      if (range.hi != before.hi) bound[1] = k;
      return true;
    };
    if (binding != nullptr) {
      for (int e = 0; e < 2; ++e) {
        const std::uint32_t k = binding[e];
        if (k < i_ || k >= j_ || (e == 1 && k == first[0])) continue;
        first[e] = k;
        if (!visit(k)) return false;
      }
    }
    const std::uint32_t len = j_ - i_;
    std::uint32_t top = 1;  // 2^bits, the first power of two >= len
    while (top < len) top *= 2;
    // rev runs through 0..top-1 bit-reversed: adding one at the top bit,
    // carrying downwards (amortized O(1); a reversal per step was a
    // tenth of the search).
    std::uint32_t rev = 0;
    for (std::uint32_t t = 0; t < top; ++t) {
      const std::uint32_t k = i_ + rev;
      if (rev < len && k != first[0] && k != first[1] && !visit(k)) return false;
      std::uint32_t bit = top / 2;
      while (bit != 0 && (rev & bit) != 0) {
        rev ^= bit;
        bit /= 2;
      }
      rev |= bit;
    }
    if (binding != nullptr) {
      binding[0] = bound[0];
      binding[1] = bound[1];
    }
    return true;
  }

  // Centre and direction E of the arc at pseudo-angle q (q > 0).
  Vec2<S> centre(S q) const {
    const Vec2<S> d = direction_of(q);
    // centre = mid + n_unit * h cot(psi) on the bulge's far side: with
    // n = |u| n_unit and h = |u| / 2 that is mid + n (d.x / d.y) / 2.
    return mid_ + (b_ - a_).perp() * S(orient_) * (d.x / (S(2) * d.y));
  }

 private:
  static S pseudo(Vec2<S> d) { return S(1) - d.x / (Scalar<S>::abs(d.x) + d.y); }
  // Is pseudo(d) (d.y > 0) at least q + 1e-12, or at most q - 1e-12,
  // without the division? pseudo(d) = 1 - d.x / den, den = |d.x| + d.y > 0,
  // and the rounding of both sides is below 1e-15. False in fixed point.
  static bool clearly_above(S q, Vec2<S> d) {
    if constexpr (!band_detail::kFloating<S>) {
      (void)q;
      (void)d;
      return false;
    } else {
      return d.x <= (S(1) - q - S(1e-12)) * (Scalar<S>::abs(d.x) + d.y);
    }
  }
  static bool clearly_below(S q, Vec2<S> d) {
    if constexpr (!band_detail::kFloating<S>) {
      (void)q;
      (void)d;
      return false;
    } else {
      return d.x >= (S(1) - q + S(1e-12)) * (Scalar<S>::abs(d.x) + d.y);
    }
  }

  // Does no point of the slot's chain snap to a or b, with any reach the
  // test uses (rounding's, or a segment's end reach)? Snapping a point
  // costs more than its condition, and it is needed only at the ends.
  // Exact: rounding is monotone, so no point's computed distance to a or b
  // along an axis is below its box's, nor any segment's extent above the
  // box's. Floating point only.
  bool apart(const BandChainSlot<S>& slot) const {
    if constexpr (!band_detail::kFloating<S>) {
      (void)slot;
      return false;
    } else {
      if (slot.chain.size == 0) return false;
      const Vec2<S> lo = slot.box_lo;
      const Vec2<S> hi = slot.box_hi;
      const S extent = max_of(hi.x - lo.x, hi.y - lo.y);
      const S d = max_of(reach_, band_detail::segment_end_reach(Vec2<S>{extent, S(0)}));
      auto outside_box = [&](Vec2<S> p) {
        return lo.x - p.x > d || p.x - hi.x > d || lo.y - p.y > d || p.y - hi.y > d;
      };
      return outside_box(a_) && outside_box(b_);
    }
  }

  // Cell conditions of the bulge-side chain c: false when they empty the
  // range. kSnap false: no point snaps (apart()), so none is tried.
  template <bool kSnap>
  bool chain_conditions(const BandChain<S>& c, PsiRange<S>& range) const {
    auto snap = [&](Vec2<S> q) { return kSnap ? snapped(q) : q; };
    // A width below the coordinates' resolution puts the chain's first or
    // last point a rounding step beside a or b instead of on it. The
    // segment test then finds its binding point within a step of the end
    // (t rounds to 0 or 1 and is dropped) and skips the end's limit: arcs
    // far outside the band passed (tests/fuzz/corpus/fit_band/
    // sharp_turn_arc_out_of_band, one_sided_sub_ulp_width). Such a point is
    // the end itself: every point is taken snapped.
    // Every point, the one shared with the previous cell too: cells are not
    // visited in order, and the segment test below needs both ends applied.
    for (int t = 0; t < c.size; ++t) outside(range, snap(c.pt[t]));
    if (range.empty()) return false;
    // Clear at both ends of the range means clear inside it (a segment's
    // valid set is an interval); the ends are taken once, before the
    // segments narrow the range, which only makes that test stricter.
    const Vec2<S> lo = direction_of(range.lo);
    const Vec2<S> hi = direction_of(range.hi);
    for (int t = 0; t + 1 < c.size && !range.empty(); ++t)
      segment<kSnap>(range, lo, hi, snap(c.pt[t]), snap(c.pt[t + 1]));
    return true;
  }

  // Does the slot's chain cut nothing from the range? True when the slab
  // around it (fit/band/slab.hpp) is clear of the disc at both ends of the
  // range, so clear inside it. Floating point, no point near a or b
  // (apart()).
  bool slab_clear(const BandChainSlot<S>& slot, const PsiRange<S>& range) const {
    if constexpr (!band_detail::kFloating<S>) {
      (void)slot;
      (void)range;
      return false;
    } else {
      const BandChain<S>& c = slot.chain;
      if (c.size == 0) return false;
      const band_detail::SlabTest<S> slab(a_, b_, n_, chord_, c.pt[0], c.pt[c.size - 1], slot.thickness);
      return slab.clear_at(direction_of(range.lo)) && slab.clear_at(direction_of(range.hi));
    }
  }

  // Intersects the range with the half-plane d.w >= 0. In floating point a
  // boundary clearly outside the range (by 1e-12 of a pseudo-angle, far
  // above the division's rounding) is not computed: the min or max would
  // keep the range's end as it is, bit for bit.
  __attribute__((always_inline)) static void cut(PsiRange<S>& r, Vec2<S> w) {
    if (w.x > S(0)) {
      if (clearly_above(r.hi, {-w.y, w.x})) return;
      r.hi = min_of(r.hi, pseudo({-w.y, w.x}));
    } else if (w.x < S(0)) {
      if (clearly_below(r.lo, {w.y, -w.x})) return;
      r.lo = max_of(r.lo, pseudo({w.y, -w.x}));
    } else if (w.y < S(0)) {
      r.hi = min_of(r.hi, S(0));
    }
  }

  // q, or a or b when q lies within `reach` of it (at least rounding's).
  Vec2<S> snapped(Vec2<S> q, S reach = S(0)) const {
    const S d = max_of(reach, reach_);
    if (band_detail::within(q, a_, d)) return a_;
    if (band_detail::within(q, b_, d)) return b_;
    return q;
  }

  // v in the pair's frame: times f_, which is 1 in floating point (the
  // multiplications by it were a sixth of the segment test).
  Vec2<S> framed(Vec2<S> v) const {
    if constexpr (band_detail::kFloating<S>) return v;
    else return v * f_;
  }
  S area(Vec2<S> q) const { return framed(q - a_).dot(framed(q - b_)); }
  // Measured from a, not from the midpoint: (b - a).perp(b - a) is exactly
  // 0 in floating point, so a point on a or b gets exactly w = 0 (no
  // condition) instead of a rounding residue that would cut the range.
  S offset(Vec2<S> q) const { return framed(q - a_).dot(n_); }
  void outside(PsiRange<S>& r, Vec2<S> q) const { cut(r, {-offset(q), area(q)}); }
  void inside(PsiRange<S>& r, Vec2<S> q) const { cut(r, {offset(q), -area(q)}); }

  // min over t in [0, 1] of the power of q1 + t (q2 - q1) is >= 0 at d
  // (the end points are already known to be outside).
  bool clear(Vec2<S> d, S a1, S y1, S vd, S dd, S dn) const {
    S c[3] = {d.y * dd, S(2) * d.y * vd - d.x * dn, d.y * a1 - d.x * y1};  // c2, c1, p1
    band_detail::balance(c, 3);
    const S c2 = c[0], c1 = c[1], p1 = c[2];
    if (!(c2 > S(0))) return true;
    if (!(c1 < S(0)) || -c1 >= S(2) * c2) return true;  // minimum at an end
    return S(4) * c2 * p1 >= c1 * c1;
  }

  template <bool kSnap>
  void segment(PsiRange<S>& r, Vec2<S> lo, Vec2<S> hi, Vec2<S> q1, Vec2<S> q2) const {
    // An end a hair from a or b (a gate end of a sharp turn, whose gate
    // runs almost along the edges: a sub-resolution width gives a half gate
    // of many ulps) is a or b itself: the binding point would lie within
    // rounding of t = 1 and be lost (band_numeric.hpp, segment_end_reach).
    // Both ends' own conditions were applied in cell().
    if constexpr (kSnap) {
      const S near = band_detail::segment_end_reach(q2 - q1);
      q1 = snapped(q1, near);
      q2 = snapped(q2, near);
    }
    if (q1 == q2) return;
    const Vec2<S> dq = q2 - q1;
    const Vec2<S> fq = framed(dq);
    // area and offset of q1, (q1 - mid).dq, |dq|^2, dq.n and 2 (q2 - mid).dq:
    // all of degree 2 in lengths, so balanced together (band_numeric.hpp).
    // Floating point needs no balance, and the last only past the early out.
    auto end_dot = [&] { return fq.dot(framed((q2 - a_) + (q2 - b_))); };
    S v[6] = {area(q1), offset(q1), fq.dot(framed((q1 - a_) + (q1 - b_))) / S(2), fq.norm2(),
              fq.dot(n_), S(0)};
    if constexpr (!band_detail::kFloating<S>) v[5] = end_dot();
    band_detail::balance(v, 6);
    const S a1 = v[0], y1 = v[1], vd = v[2], dd = v[3], dn = v[4];
    if (clear(lo, a1, y1, vd, dd, dn) && clear(hi, a1, y1, vd, dd, dn)) return;
    const S vd2 = band_detail::kFloating<S> ? end_dot() : v[5];
    // The circle through a, b and q(t) is extreme where A Y' = Y A':
    //   dd dn t^2 + 2 y1 dd t + (2 y1 vd - a1 dn) = 0.
    // An end on a or b (w = 0 there) is always a root; it is divided out,
    // since rounding would put it just inside (0, 1).
    S qs[3] = {dd * dn, S(2) * y1 * dd, S(2) * y1 * vd - a1 * dn};
    band_detail::balance(qs, 3);
    const S qa = qs[0], qb = qs[1], qc = qs[2];
    const S a2 = area(q2);
    const S y2 = offset(q2);
    const bool from_end = a1 == S(0) && y1 == S(0);
    const bool to_end = a2 == S(0) && y2 == S(0);
    S roots[3];
    int m = 0;
    if (from_end || to_end) {
      if (qa != S(0) && !(from_end && to_end)) roots[m++] = to_end ? qc / qa : -qb / qa;
    } else {
      m = quadratic_roots(qa, qb, qc, roots, RootForm::over_two_a);
    }
    // Where it crosses the chord line (for a segment from a or b, only there).
    if (dn != S(0) && !from_end && !to_end) roots[m++] = -y1 / dn;
    // (Next to an end on a or b the limit below already binds; a point a
    // rounding step from it would carry only noise.)
    const S lo_t = from_end ? S(1e-9) : S(0);
    const S hi_t = to_end ? S(1) - S(1e-9) : S(1);
    // The point q(t) is taken through the segment's own terms, offset y1 + t dn
    // and area a1 + 2 t vd + t^2 dd, not rebuilt as q1 + t dq: its coordinates
    // would round to the coordinates' resolution, and on a segment that ends
    // on a or b (a width below it) the rounding is larger than the offset
    // itself, so q(t) could land beyond the chord and cut the line away. In
    // one visiting order the early out above returned first, in another the
    // cut ran: the verdict depended on the order (issue 25,
    // tests/fuzz/corpus/fit_band/collinear_run_order).
    for (int t = 0; t < m; ++t) {
      const S u = roots[t];
      if (u > lo_t && u < hi_t) cut(r, {-(y1 + u * dn), a1 + u * (S(2) * vd + u * dd)});
    }
    // A segment that starts or ends on a or b itself (a side of width 0)
    // has w(t) = (-Y, A) -> 0 there, and the binding condition is the limit
    // of its direction: the segment must leave that end outside the disc.
    if (from_end) cut(r, {-dn, S(2) * vd});                             // t -> 0+
    if (to_end) cut(r, {dn, -vd2});                                     // t -> 1-
  }

  const BandRegion<S>& r_;
  std::uint32_t i_;
  std::uint32_t j_;
  int orient_;
  Vec2<S> a_;
  Vec2<S> b_;
  Vec2<S> mid_{};
  Vec2<S> u_{};
  Vec2<S> n_{};
  S f_{};  // the frame's scale: lengths in u_, n_, area and offset are times f_
  S reach_{};  // rounding's reach around a and b (band_numeric.hpp)
  S chord_{};  // |b - a| (floating point only)
  bool clear_between_ = false;
};

}  // namespace kerf::fit
