// Is a biarc from p_i to p_j valid in the region R (Definition 3.2 of
// Drysdale, Rote, Sturm)? Both arcs inside R, gates g_i and g_j touched
// only at p_i and p_j, the tangents through g_i and g_j forwards (the
// paper's assumption (C')). Intermediate gates may be crossed any number of
// times (section 3.3 relaxes the gate rule for biarcs), but at least once:
// where the path jumps back over its own band, R overlaps itself, and a
// biarc inside it could otherwise skip the part in between (where R is
// simple, every intermediate gate separates g_i from g_j anyway).
//
// The test. Between g_i and g_j, R is the polygon bounded by g_i, the left
// chains of cells i..j-1, g_j and the right chains (fit/band/region.hpp).
// The biarc starts at p_i on its boundary, leaving forwards into it, and ends
// at p_j; it lies inside iff it meets the boundary nowhere else. So each
// arc is intersected with every boundary segment (a quadratic along the
// segment, with the centre-free circle equation of fit/biarc/arc.hpp), ignoring
// only the touch at p_i (first arc) and at p_j (second arc). A touch of the
// boundary counts as leaving: a joint or an arc grazing R's edge is refused,
// which loses only boundary cases of measure zero. Cells are visited middle
// first (bit-reversed order), so a biarc that strays fails after a few.
//
// Fixed point: the test runs in the pair's frame (fit/biarc/numeric.hpp),
// and so do the biarcs it is given: see frame().
//
// The region must have a positive width on both sides of p_i and p_j (the
// CLI's biarc criterion takes a symmetric --tol), so that the boundary
// passes nowhere near the ends except through the gates.
#pragma once

#include <cstdint>

#include "kerf/fit/band/region.hpp"
#include "kerf/fit/biarc/arc.hpp"
#include "kerf/fit/biarc/numeric.hpp"
#include "kerf/geom/roots.hpp"

namespace kerf::fit {

template <class S>
class BiarcCheck {
 public:
  BiarcCheck(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j)
      : r_(r), i_(i), j_(j), f_(biarc_detail::PairFrame<S>::of(r, i, j)) {
    scale_ = band_detail::length(point(j) - point(i));
    const BandVertex<S>& vi = r.vertex(i);
    const BandVertex<S>& vj = r.vertex(j);
    scale_ = max_of(scale_, f_.length(max_of(max_of(vi.gate_left, vi.gate_right), max_of(vj.gate_left, vj.gate_right))));
  }

  // The pair's frame: the biarcs tested and the points below are in it.
  const biarc_detail::PairFrame<S>& frame() const { return f_; }
  Vec2<S> point(std::uint32_t k) const { return f_.map(r_.point(k)); }
  Vec2<S> gate_end(std::uint32_t k, int side) const { return f_.map(r_.gate_end(k, side)); }
  // The boundary chain of cell k on `side`, in the frame.
  void chain(std::uint32_t k, int side, BandChain<S>& c) const {
    r_.chain(k, side, c);
    if constexpr (!biarc_detail::kFloating<S>)
      for (int e = 0; e < c.size; ++e) c.pt[e] = f_.map(c.pt[e]);
  }

  // The tangents cross their gates forwards and no barrier lies between.
  bool ends(Vec2<S> ti, Vec2<S> tj) const {
    for (std::uint32_t k = i_ + 1; k < j_; ++k)
      if (r_.vertex(k).barrier) return false;
    return ti.dot(r_.forward(i_, false)) > S(0) && tj.dot(r_.forward(j_, true)) > S(0);
  }

  bool valid(const Biarc<S>& b) const {
    bool alive = true;
    return filter(&b, &alive, 1) == 1;
  }

  // Many biarcs of the pair at once: clears alive[q] for each b[q] that is
  // not valid and returns how many stay. Each cell's chains are built once
  // for all of them, and the test stops when none is left.
  std::uint32_t filter(const Biarc<S>* b, bool* alive, std::uint32_t m) const {
    std::uint32_t left = 0;
    for (std::uint32_t q = 0; q < m; ++q) {
      if (alive[q] && (crosses_gate(b[q], i_) || crosses_gate(b[q], j_))) alive[q] = false;
      if (alive[q]) ++left;
    }
    if (left > 0) {
      chains_middle_first([&](const BandChain<S>& c) {
        for (std::uint32_t q = 0; q < m; ++q) {
          if (!alive[q]) continue;
          for (int e = 0; e + 1 < c.size; ++e) {
            if (meets(b[q], c.pt[e], c.pt[e + 1])) {
              alive[q] = false;
              --left;
              break;
            }
          }
        }
        return left > 0;
      });
    }
    // Every gate between g_i and g_j crossed at least once. Where R is
    // simple each of them separates g_i from g_j, so this refuses nothing;
    // where R runs back over itself (a path that jumps back over its own
    // band) a biarc could otherwise skip the part between and leave its
    // points uncut.
    for (std::uint32_t k = i_ + 1; k < j_ && left > 0; ++k) {
      const Vec2<S> q1 = gate_end(k, -1);
      const Vec2<S> q2 = gate_end(k, 1);
      for (std::uint32_t q = 0; q < m; ++q) {
        if (alive[q] && !meets(b[q], q1, q2)) {
          alive[q] = false;
          --left;
        }
      }
    }
    return left;
  }

  // Calls visit(chain) for the boundary chains of cells i..j-1, both sides,
  // in the frame, until it returns false. Middle cells first (bit-reversed
  // order): a biarc that strays usually meets the boundary there, so the
  // callers' tests fail after a few cells.
  template <class Visit>
  void chains_middle_first(Visit&& visit) const {
    const std::uint32_t len = j_ - i_;
    std::uint32_t bits = 0;
    while ((1u << bits) < len) ++bits;
    BandChain<S> c;
    for (std::uint32_t t = 0; t < (1u << bits); ++t) {
      std::uint32_t rev = 0;
      for (std::uint32_t q = 0; q < bits; ++q) rev |= ((t >> q) & 1u) << (bits - 1 - q);
      if (rev >= len) continue;
      for (int side = -1; side <= 1; side += 2) {
        chain(i_ + rev, side, c);
        if (!visit(c)) return;
      }
    }
  }

  // Does either arc meet the boundary segment q1 q2 (but at p_i for the
  // first arc, p_j for the second)? The one-segment test that
  // fit/biarc/joints.hpp evaluates between critical joints.
  bool meets(const Biarc<S>& b, Vec2<S> q1, Vec2<S> q2) const {
    return hits(b.first, point(i_), q1, q2) || hits(b.second, point(j_), q1, q2);
  }

 private:
  bool crosses_gate(const Biarc<S>& b, std::uint32_t k) const {
    return meets(b, gate_end(k, -1), gate_end(k, 1));
  }

  // Does arc meet the segment q1 q2 anywhere but at `skip`?
  bool hits(const ArcPart<S>& arc, Vec2<S> skip, Vec2<S> q1, Vec2<S> q2) const {
    if (arc.empty()) return false;
    const S k = arc.curvature();
    const Vec2<S> d = q2 - q1;
    const Vec2<S> e = q1 - arc.a;
    // kappa |e + s d|^2 - 2 t x (e + s d) = qa s^2 + qb s + qc
    S q3[3] = {k * d.norm2(), S(2) * (k * e.dot(d) - arc.t.cross(d)), k * e.norm2() - S(2) * arc.t.cross(e)};
    band_detail::balance(q3, 3);  // fixed point: the discriminant keeps its bits
    S roots[2];
    const int m = quadratic_roots(q3[0], q3[1], q3[2], roots);
    if (m == 0) return false;
    const S slack = biarc_detail::relative_reach(S(1), S(1e-12), 4);
    const S skip_reach = biarc_detail::relative_reach(scale_, S(1e-9), 4096);
    // Where x lies along the arc. A nearly straight arc (turning by less
    // than 2^-20 rad) goes by the distance along its chord: its pseudo-angle
    // (ArcPart::position) has no bits left there, and in fixed point a line's
    // was scaled per point, so that a crossing of g_j beyond the joint
    // compared as on the first part and a straight run found no joint. A
    // point of its circle that is not near the chord lies a radius away.
    const Vec2<S> c = arc.b - arc.a;
    const bool flat = Scalar<S>::abs(k) * band_detail::length(c) < S(1.0 / 1048576.0);
    auto where = [&](Vec2<S> x) { return flat ? (x - arc.a).dot(c) : arc.position(x); };
    const S end = where(arc.b);
    for (int t = 0; t < m; ++t) {
      if (!(roots[t] >= -slack && roots[t] <= S(1) + slack)) continue;
      const Vec2<S> x = q1 + d * roots[t];
      if (biarc_detail::near(x, skip, skip_reach)) continue;
      const S pos = where(x);
      if (pos >= S(0) - slack && pos <= end + slack * (S(1) + Scalar<S>::abs(end))) return true;
    }
    return false;
  }

  const BandRegion<S>& r_;
  std::uint32_t i_;
  std::uint32_t j_;
  biarc_detail::PairFrame<S> f_;
  S scale_{};
};

}  // namespace kerf::fit
