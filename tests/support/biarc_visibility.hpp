// The paper's own pair test for biarcs (Drysdale, Rote, Sturm, sections
// 3.4-3.5): a referee for kerf's exact joint sets (fit/biarc/joints.hpp), so
// the two can be cross-checked. It lives with the tests, not in core: it
// keeps its critical lists (16 KiB) on the stack, which a Cortex-M cannot
// spare. The fitter runs it through BiarcOptions::joints (biarc_paper_joints
// below). Same parametrisation of J (fit/biarc/arc.hpp), same validity
// (fit/biarc/valid.hpp), same result type (JointSet of s).
//
// The pair region. A valid biarc p_i -> p_j lives in R between g_i and g_j:
// the polygon of gate g_i, the chains of cells i..j-1 and gate g_j. The
// visibility regions are taken in that polygon (gates g_i and g_j are
// boundary): the paper's W_i stops arcs at g_i and reduces A1A2 for g_j at
// the end; stopping at g_j at once gives the same valid joints.
//
// Lemma 3.3, circular visibility W_i on a gate. A point x of gate g_k is in
// W_i when the arc of the pencil at p_i along t_i that passes through x
// (curvature kappa(x) = 2 t_i x (x - p_i) / |x - p_i|^2) reaches x without
// touching the boundary. Whether a crossing of gate g_k by the pencil
// circle of curvature kappa is reached changes only at critical kappas: a
// circle through a boundary vertex, a circle tangent to a boundary edge's
// line, a circle through a gate end or tangent to the gate's line. Between
// two critical kappas one exact test decides, and each crossing (first or
// second along the arc) moves monotonically along the gate, so the visible
// part of g_k is a union of intervals with critical ends (the paper: at
// most three, one forward and two backward). W~_j is the same from p_j
// along -t_j.
//
// Lemma 3.4, (In)/(Out). Let f(x) = kappa_J |x - p_i|^2 - 2 tau x (x - p_i)
// (tau: J's unit tangent at p_i, kappa_J its curvature; f = 0 on J, and
// its sign tells J's two sides apart, a half plane when J is a line). The
// first arc starts on the side sigma = sign(-tau x t_i) of J, the reversed
// second arc on the other. (Out): W_i meets g_k where sigma f > 0; (In):
// W~_j meets g_k where sigma f < 0. (Out) holds on a prefix of the gates
// i+1..j-1 and (In) on a suffix (Lemma 3.4b), so two binary searches find
// the last (Out) gate and the first (In) gate; a joint in cell c (between
// g_c and g_c+1) needs (Out) at g_c and (In) at g_c+1 (Lemma 3.4a; g_i
// counts as (Out), g_j as (In)), so joints lie in the cells
// first_in - 1 .. last_out, and none exist when that range is empty (the
// paper's case b1).
//
// Lemmas 3.5-3.7, the joint arc. Inside that window of cells, a joint m of
// J is valid iff m is in W_i (the first arc p_i -> m is clear) and in W~_j
// (the reversed second arc p_j -> m is clear). kerf finds W_i n J and
// W~_j n J as intervals of s with the same critical-joint argument as
// above (the first arc's kappa is a function of the joint: a pencil circle
// through a vertex or tangent to an edge line, or the joint crossing an
// edge line), one test per interval; their intersection within the window
// is the arc A1A2 (its ends A1, A2 are where the first resp. second arc
// starts to be blocked). The paper proves it is one arc between g_l and
// g_r; kerf does not assume that: it keeps every interval and reports how
// many there are, so the tests can count the cases where it is not (none
// seen). The tests also check the paper's own A1 (the W_i point of g_l
// outside J closest to Q_l, extended to J) against W_i n J.
//
// Cost: the gate intervals are recomputed per pair, O(m^2) in the pair's m
// boundary edges, not the paper's O(n^2) table with O(log n) per pair; the
// exact sets of fit/biarc/joints.hpp stay the fitter's default.
//
// Degenerate cases: one circle through p_i and p_j with both tangents (t_i
// tangent to J): every joint on the arc p_i -> p_j of that circle gives the
// same arc, valid iff that arc is clear; J a line (kappa_J = 0, f a half
// plane; the point at infinity is an end of the s-intervals); a joint at an
// end point (s = 0, 1, 2) is never in the set, as in fit/biarc/joints.hpp.
#pragma once

#include <cstdint>

#include "kerf/fit/biarc/joints.hpp"
#include "kerf/geom/complex.hpp"
#include "kerf/geom/roots.hpp"

namespace kerf::fit {

// The visible part of one gate: intervals of the position u along it
// (x = p_k + u b_k, u from -gate_right to gate_left), in order.
template <class S>
struct GateVisibility {
  static constexpr int kMax = 16;
  struct Range {
    S lo, hi;
  };
  Range v[kMax]{};
  int size = 0;
  bool overflow = false;
  void add(S lo, S hi) {
    if (size > 0 && lo <= v[size - 1].hi) {  // touching or overlapping: merge
      if (hi > v[size - 1].hi) v[size - 1].hi = hi;
      return;
    }
    if (size == kMax) {
      overflow = true;
      return;
    }
    v[size++] = {lo, hi};
  }
};

// What the paper's test found for a pair, for the tests and the report.
struct PaperPairStats {
  std::int64_t last_out = -1;  // last gate with (Out) (i when none)
  std::int64_t first_in = -1;  // first gate with (In) (j when none)
  bool single_circle = false;  // the degenerate case of one circle
  int arcs = 0;                // intervals of the result (the paper: <= 1)
};

template <class S, int Cap = 128>
class BiarcPaper {
 public:
  BiarcPaper(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j, Vec2<S> ti, Vec2<S> tj)
      : r_(r), i_(i), j_(j), check_(r, i, j), jc_(r.point(i), ti, r.point(j), tj) {
    p1_ = r.point(i);
    p2_ = r.point(j);
    t1_ = ti;
    t2_ = tj;
    d_ = p2_ - p1_;
    dd_ = d_.norm2();
    scale_ = d_.norm();
    for (std::uint32_t k = i; k <= j; k += (j - i)) {
      scale_ = max_of(scale_, max_of(r.vertex(k).gate_left, r.vertex(k).gate_right));
    }
    const Vec2<S> k = jc_.k();
    k_ = k;
    tau_ = unit_of(complex_mul<S>(d_, k));
    kj_ = S(2) * tau_.cross(d_) / dd_;
    const S side = -tau_.cross(t1_);
    single_ = Scalar<S>::abs(side) <= S(1e-12);
    sigma_ = side > S(0) ? S(1) : S(-1);
    a1_ = t1_.cross(complex_mul<S>(d_, k));
    c1_ = t1_.cross(d_);
    b2_ = t2_.cross(complex_mul<S>(d_, {k.x, -k.y}));
    c2_ = t2_.cross(d_);
  }

  const JointCircle<S>& circle() const { return jc_; }
  const BiarcCheck<S>& check() const { return check_; }

  // Lemma 3.3: the part of gate k (i < k < j) in W_i (from_end = false) or
  // in W~_j (from_end = true).
  void gate_visibility(std::uint32_t k, bool from_end, GateVisibility<S>& out) const {
    out = GateVisibility<S>{};
    const Vec2<S> p = from_end ? p2_ : p1_;
    const Vec2<S> t = from_end ? -t2_ : t1_;
    const Vec2<S> q1 = r_.gate_end(k, -1);
    const Vec2<S> q2 = r_.gate_end(k, 1);
    const Vec2<S> e = q2 - q1;
    const S len = e.norm();
    if (!(len > S(0))) return;
    const Vec2<S> u = e * (S(1) / len);
    const S u0 = -r_.vertex(k).gate_right;
    // The critical curvatures.
    S crit[kCritMax];
    int m = 0;
    auto add_edge = [&](Vec2<S> a, Vec2<S> b) {
      if (m + 4 > kCritMax) return false;
      add_kappa_through(p, t, a, crit, m);
      add_kappa_through(p, t, b, crit, m);
      add_kappa_tangent(p, t, a, b, crit, m);
      return false;
    };
    add_edge(q1, q2);
    any_edge(add_edge);
    if (m + 4 > kCritMax) {
      out.overflow = true;
      overflow_ = true;
    }
    sort(crit, m);
    // The ends: beyond the extreme critical curvatures by the curvature scale.
    const S pad = S(1) / scale_;
    for (int a = -1; a < m; ++a) {
      const S lo = a < 0 ? (m > 0 ? crit[0] - pad : -pad) : crit[a];
      const S hi = a + 1 < m ? crit[a + 1] : (m > 0 ? crit[m - 1] + pad : pad);
      if (!(lo < hi)) continue;
      const S mid = lo + (hi - lo) / S(2);
      // The crossings with the gate's whole line, numbered in arc order (a
      // branch keeps its number over the interval); those off the gate skip.
      Vec2<S> x[2];
      const int c = crossings(p, t, mid, q1, u, len, x, false);
      for (int br = 0; br < c; ++br) {
        const S at = u.dot(x[br] - q1);
        if (!(at >= S(0) && at <= len)) continue;
        if (!clear(p, t, x[br], from_end)) continue;
        // The branch's positions at both ends of the interval (limits).
        const S here = u.dot(x[br] - q1);
        const S lim[3] = {here, branch_at(p, t, lo, q1, u, len, br, here),
                          branch_at(p, t, hi, q1, u, len, br, here)};
        S ulo = lim[0], uhi = lim[0];
        for (const S v : lim) {
          ulo = min_of(ulo, v);
          uhi = max_of(uhi, v);
        }
        add_sorted(out, u0 + max_of(S(0), ulo), u0 + min_of(len, uhi));
      }
    }
  }

  // (Out) at gate k: W_i meets g_k on the first arc's side of J.
  bool out_at(std::uint32_t k) const { return meets_side(k, false); }
  // (In) at gate k: W~_j meets g_k on the second arc's side of J.
  bool in_at(std::uint32_t k) const { return meets_side(k, true); }

  // The valid joints (the arc A1A2), as fit/biarc/joints.hpp's sets.
  // Returns false only when a set overflowed.
  bool compute(JointSet<S, Cap>& out, PaperPairStats* stats = nullptr) const {
    out.clear();
    PaperPairStats st;
    st.last_out = i_;
    st.first_in = j_;
    st.single_circle = single_;
    bool ok = true;
    overflow_ = false;
    if (check_.ends(t1_, t2_)) ok = joints(out, st) && !overflow_;
    st.arcs = out.size();
    if (stats != nullptr) *stats = st;
    return ok;
  }

 private:
  // Critical curvatures or joints of one pair: about six per boundary edge
  // between g_i and g_j. Overflow is reported (compute returns false).
  static constexpr int kCritMax = 2048;

  static S s_of(S lambda) {
    if (lambda >= S(0)) return lambda / (S(1) + lambda);
    return (S(2) - lambda) / (S(1) - lambda);
  }
  static void sort(S* v, int m) {
    for (int a = 1; a < m; ++a) {
      const S x = v[a];
      int b = a;
      while (b > 0 && v[b - 1] > x) {
        v[b] = v[b - 1];
        --b;
      }
      v[b] = x;
    }
  }
  static void add_sorted(GateVisibility<S>& out, S lo, S hi) {
    if (!(lo <= hi)) return;
    // Critical intervals come in kappa order, not in gate order: insert.
    GateVisibility<S> merged;
    bool placed = false;
    for (int q = 0; q < out.size; ++q) {
      if (!placed && lo < out.v[q].lo) {
        merged.add(lo, hi);
        placed = true;
      }
      merged.add(out.v[q].lo, out.v[q].hi);
    }
    if (!placed) merged.add(lo, hi);
    merged.overflow = merged.overflow || out.overflow;
    out = merged;
  }

  // Every boundary edge of the pair polygon: gates g_i, g_j, then the
  // chains of cells i..j-1. Stops when f returns true.
  template <class F>
  bool any_edge(F&& f) const {
    if (f(r_.gate_end(i_, -1), r_.gate_end(i_, 1))) return true;
    if (f(r_.gate_end(j_, -1), r_.gate_end(j_, 1))) return true;
    BandChain<S> c;
    for (std::uint32_t cell = i_; cell < j_; ++cell) {
      for (int side = -1; side <= 1; side += 2) {
        r_.chain(cell, side, c);
        for (int e = 0; e + 1 < c.size; ++e)
          if (f(c.pt[e], c.pt[e + 1])) return true;
      }
    }
    return false;
  }

  // Is the arc from p along t to x (p_i's pencil, or p_j's reversed) clear
  // of the boundary but at p?
  bool clear(Vec2<S> p, Vec2<S> t, Vec2<S> x, bool from_end) const {
    Biarc<S> b;
    if (from_end) {
      b.first = {p1_, p1_, t1_};
      b.second = {p, x, t};
    } else {
      b.first = {p, x, t};
      b.second = {p2_, p2_, t2_};
    }
    if (b.first.empty() && b.second.empty()) return false;
    return !any_edge([&](Vec2<S> q1, Vec2<S> q2) { return q1 != q2 && check_.meets(b, q1, q2); });
  }

  static void add_kappa_through(Vec2<S> p, Vec2<S> t, Vec2<S> q, S* crit, int& m) {
    const Vec2<S> v = q - p;
    const S l2 = v.norm2();
    if (l2 > S(0)) crit[m++] = S(2) * t.cross(v) / l2;
  }
  // The pencil circles tangent to the line through a, b: (alpha kappa +
  // beta)^2 = 1 with alpha = n.(p - a), beta = n.perp(t).
  static void add_kappa_tangent(Vec2<S> p, Vec2<S> t, Vec2<S> a, Vec2<S> b, S* crit, int& m) {
    const Vec2<S> e = b - a;
    const S len = e.norm();
    if (!(len > S(0))) return;
    const Vec2<S> n = (e * (S(1) / len)).perp();
    const S alpha = n.dot(p - a);
    const S beta = n.dot(t.perp());
    if (alpha == S(0)) return;
    crit[m++] = (S(1) - beta) / alpha;
    crit[m++] = (S(-1) - beta) / alpha;
  }

  // Where the pencil circle of curvature kappa crosses the line q1 + s u,
  // in order along the arc from p; only s in [0, len] when `inside`. With
  // `touch`, a circle that misses the line by rounding (a critical kappa of
  // tangency) touches it at the closest point.
  static int crossings(Vec2<S> p, Vec2<S> t, S kappa, Vec2<S> q1, Vec2<S> u, S len, Vec2<S>* x,
                       bool inside, bool touch = false) {
    const Vec2<S> e = q1 - p;
    const S qa = kappa;
    const S qb = S(2) * (kappa * e.dot(u) - t.cross(u));
    const S qc = kappa * e.norm2() - S(2) * t.cross(e);
    S roots[2];
    const int c = quadratic_roots(qa, qb, qc, roots, RootForm::half_sum, touch);
    int m = 0;
    S pos[2];
    for (int a = 0; a < c; ++a) {
      if (inside && !(roots[a] >= S(0) && roots[a] <= len)) continue;
      const Vec2<S> y = q1 + u * roots[a];
      const Vec2<S> v = y - p;
      S ps = v.dot(t);
      if (kappa != S(0)) {  // pseudo-angle round the circle from p
        const S py = max_of(S(0), v.dot(t.perp()) * (kappa > S(0) ? S(1) : S(-1)));
        ps = (ps == S(0) && py == S(0)) ? S(0) : S(1) - ps / (Scalar<S>::abs(ps) + py);
      }
      x[m] = y;
      pos[m] = ps;
      ++m;
    }
    if (m == 2 && pos[1] < pos[0]) {
      const Vec2<S> y = x[0];
      x[0] = x[1];
      x[1] = y;
    }
    return m;
  }

  // The position along the gate of branch br (of c) at curvature kappa: the
  // limit of the branch at an interval's end.
  // A branch that leaves the line (kappa -> 0 sends one crossing to
  // infinity) keeps the middle's value `here`.
  static S branch_at(Vec2<S> p, Vec2<S> t, S kappa, Vec2<S> q1, Vec2<S> u, S len, int br, S here) {
    Vec2<S> x[2];
    const int all = crossings(p, t, kappa, q1, u, len, x, false, true);
    if (all == 0) return here;
    const S s = u.dot(x[br < all ? br : all - 1] - q1);
    if (!(Scalar<S>::abs(s) < S(1e300))) return here;
    return min_of(len, max_of(S(0), s));
  }

  // The side function of J (see above).
  S side_f(Vec2<S> x) const {
    const Vec2<S> v = x - p1_;
    return kj_ * v.norm2() - S(2) * tau_.cross(v);
  }

  bool meets_side(std::uint32_t k, bool from_end) const {
    GateVisibility<S> vis;
    gate_visibility(k, from_end, vis);
    const S want = from_end ? -sigma_ : sigma_;
    const Vec2<S> q1 = r_.gate_end(k, -1);
    const Vec2<S> b = r_.vertex(k).b;
    const S u0 = -r_.vertex(k).gate_right;
    // f along the gate is a quadratic in u: its largest value of want * f
    // over [lo, hi] is at an end or the vertex.
    const S tol = S(1e-12) * scale_ * scale_ * (Scalar<S>::abs(kj_) + S(1) / scale_);
    for (int q = 0; q < vis.size; ++q) {
      const S lo = vis.v[q].lo - u0;
      const S hi = vis.v[q].hi - u0;
      S best = max_of(want * side_f(q1 + b * lo), want * side_f(q1 + b * hi));
      // d/du f(q1 + b u) = 2 kj b.(q1 + b u - p1) - 2 tau x b = 0
      if (kj_ != S(0)) {
        const S uv = (tau_.cross(b) / kj_ - b.dot(q1 - p1_));
        if (uv > lo && uv < hi) best = max_of(best, want * side_f(q1 + b * uv));
      }
      if (best > tol) return true;
    }
    return false;
  }

  // Lemma 3.4 then the arc A1A2.
  bool joints(JointSet<S, Cap>& out, PaperPairStats& st) const {
    if (single_) return one_circle(out);
    // Binary search: (Out) on a prefix of i+1..j-1, (In) on a suffix.
    std::uint32_t lo = i_, hi = j_;  // last_out in [lo, hi - 1]
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (out_at(mid)) lo = mid;
      else hi = mid;
    }
    st.last_out = lo;
    std::uint32_t a = i_, b = j_;  // first_in in [a + 1, b]
    while (b - a > 1) {
      const std::uint32_t mid = a + (b - a) / 2;
      if (in_at(mid)) b = mid;
      else a = mid;
    }
    st.first_in = b;
    // Case b1: some gate with neither, no valid biarc.
    if (st.first_in > st.last_out + 1) return true;
    const std::uint32_t c0 = static_cast<std::uint32_t>(st.first_in - 1);
    const std::uint32_t c1 = static_cast<std::uint32_t>(st.last_out);
    JointSet<S, Cap> w1;
    JointSet<S, Cap> w2;
    visible_on_j(false, w1);
    if (!w1.empty()) visible_on_j(true, w2);
    if (w1.overflow() || w2.overflow()) return false;
    // Where J crosses the window's end gates: pieces change cell there.
    S cut[8];
    int nc = 0;
    joint_on_line(r_.gate_end(c0, -1), r_.gate_end(c0, 1), cut, nc);
    joint_on_line(r_.gate_end(c1 + 1, -1), r_.gate_end(c1 + 1, 1), cut, nc);
    sort(cut, nc);
    // A1A2: the joints in both, inside the window of cells c0..c1.
    for (int p = 0; p < w1.size(); ++p) {
      for (int q = 0; q < w2.size(); ++q) {
        const S lo2 = max_of(w1[p].lo, w2[q].lo);
        const S hi2 = min_of(w1[p].hi, w2[q].hi);
        if (!(lo2 < hi2)) continue;
        S from = lo2;
        for (int c = 0; c <= nc; ++c) {
          const S to = c < nc && cut[c] > from && cut[c] < hi2 ? cut[c] : (c < nc ? from : hi2);
          if (!(to > from)) continue;
          const S mid = from + (to - from) / S(2);
          if (mid > from && mid < to && in_window(jc_.point(mid), c0, c1)) {
            if (out.size() > 0 && out[out.size() - 1].hi == from && from != S(1)) {
              const S keep = out[out.size() - 1].lo;
              out.remove(keep, from);
              out.append({keep, to});
            } else {
              out.append({from, to});
            }
          }
          from = to;
        }
      }
    }
    return !out.overflow();
  }

  // One circle with both tangents: every joint on its arc p_i -> p_j (one
  // half of J's s-range) splits that same arc, so one full test of a joint
  // in each half decides it; joints on the other half make the first arc
  // pass p_j, which the test refuses.
  bool one_circle(JointSet<S, Cap>& out) const {
    const S halves[2] = {S(0.5), S(1.5)};
    for (const S h : halves) {
      Biarc<S> b;
      if (jc_.biarc(h, b) && check_.valid(b)) out.append({h - S(0.5), h + S(0.5)});
    }
    return true;
  }

  // W_i n J (from_end false) or W~_j n J, as intervals of s: the joints
  // whose first (resp. reversed second) arc is clear.
  void visible_on_j(bool from_end, JointSet<S, Cap>& out) const {
    S crit[kCritMax];
    int m = 0;
    crit[m++] = S(0);
    crit[m++] = S(1);
    crit[m++] = S(2);
    if (jc_.line()) push(crit, m, s_of(S(-1) / k_.x));
    // The joint where the arc is a line (flipping round beyond it).
    {
      const Vec2<S> n = t1_.perp();
      const S den = n.dot(d_);
      if (!from_end && den != S(0)) push(crit, m, s_of(-n.dot(complex_mul<S>(d_, k_)) / den));
    }
    {
      const Vec2<S> n = t2_.perp();
      const S g = n.dot(d_);
      const S den = n.dot(complex_mul<S>(d_, k_)) - S(2) * g * k_.x;
      if (from_end && den != S(0)) push(crit, m, s_of(g / den));
    }
    const Vec2<S> p = from_end ? p2_ : p1_;
    const Vec2<S> t = from_end ? -t2_ : t1_;
    any_edge([&](Vec2<S> q1, Vec2<S> q2) {
      if (m + 8 > kCritMax) {
        overflow_ = true;
        return true;
      }
      S kap[4];
      int c = 0;
      add_kappa_through(p, t, q1, kap, c);
      add_kappa_through(p, t, q2, kap, c);
      for (int a = 0; a < c; ++a) push_kappa(crit, m, kap[a], from_end);
      c = 0;
      add_kappa_tangent(p, t, q1, q2, kap, c);
      for (int a = 0; a < c; ++a) push_kappa(crit, m, kap[a], from_end);
      joint_on_line(q1, q2, crit, m);
      return false;
    });
    sort(crit, m);
    out.clear();
    for (int a = 0; a + 1 < m; ++a) {
      const S lo = crit[a];
      const S hi = crit[a + 1];
      const S mid = lo + (hi - lo) / S(2);
      if (!(mid > lo && mid < hi)) continue;
      // Each arc is defined by its own end and tangent alone, even where the
      // whole biarc is not constructible (a joint within rounding of an end
      // point, see JointCircle::biarc): such joints stay in, as in
      // fit/biarc/joints.hpp; a joint is verified in full before use.
      const Vec2<S> x = jc_.point(mid);
      if (!(Scalar<S>::abs(x.x) + Scalar<S>::abs(x.y) < S(1e300))) continue;
      if (!clear(p, t, x, from_end)) continue;
      if (out.size() > 0 && out[out.size() - 1].hi == lo && lo != S(1)) {
        // Adjacent: extend (a critical joint inside is only a touch).
        const S keep = out[out.size() - 1].lo;
        out.remove(keep, lo);
        out.append({keep, hi});
      } else {
        out.append({lo, hi});
      }
    }
  }

  void push(S* crit, int& m, S s) const {
    if (s > S(0) && s < S(2) && m < kCritMax) crit[m++] = s;
  }
  // The joint whose first arc (reversed second arc) has curvature kappa.
  void push_kappa(S* crit, int& m, S kappa, bool from_end) const {
    if (!from_end) {
      const S den = kappa * dd_ - S(2) * c1_;
      if (den != S(0) && a1_ != S(0)) push(crit, m, s_of(S(2) * a1_ / den));
    } else if (b2_ != S(0)) {
      push(crit, m, s_of((kappa * dd_ / S(2) - c2_) / b2_));
    }
  }
  // The joints where J crosses the line q1 q2.
  void joint_on_line(Vec2<S> q1, Vec2<S> q2, S* crit, int& m) const {
    const Vec2<S> e = q2 - q1;
    const S len = e.norm();
    if (!(len > S(0))) return;
    const Vec2<S> n = (e * (S(1) / len)).perp();
    const S g = n.dot(q1 - p1_);
    const S qa = n.dot(d_) - g;
    const S qb = n.dot(complex_mul<S>(d_, k_)) - S(2) * g * k_.x;
    const S qc = -g;
    S roots[2];
    const int c = quadratic_roots(qa, qb, qc, roots);
    for (int r = 0; r < c; ++r) push(crit, m, s_of(roots[r]));
  }

  // Is x inside one of the cells c0..c1 (crossing number over each cell's
  // boundary: gate c, chain, gate c+1, chain)?
  bool in_window(Vec2<S> x, std::uint32_t c0, std::uint32_t c1) const {
    BandChain<S> left;
    BandChain<S> right;
    for (std::uint32_t c = c0; c <= c1; ++c) {
      r_.chain(c, 1, left);
      r_.chain(c, -1, right);
      bool inside = false;
      auto edge = [&](Vec2<S> a, Vec2<S> b) {
        if ((a.y > x.y) != (b.y > x.y)) {
          const S at = a.x + (x.y - a.y) * (b.x - a.x) / (b.y - a.y);
          if (x.x < at) inside = !inside;
        }
      };
      for (int e = 0; e + 1 < right.size; ++e) edge(right.pt[e], right.pt[e + 1]);
      edge(right.pt[right.size - 1], left.pt[left.size - 1]);
      for (int e = left.size - 1; e > 0; --e) edge(left.pt[e], left.pt[e - 1]);
      edge(left.pt[0], right.pt[0]);
      if (inside) return true;
    }
    return false;
  }

  const BandRegion<S>& r_;
  std::uint32_t i_;
  std::uint32_t j_;
  BiarcCheck<S> check_;
  JointCircle<S> jc_;
  Vec2<S> p1_{}, p2_{}, t1_{}, t2_{}, d_{}, k_{}, tau_{};
  S dd_{}, scale_{}, kj_{}, sigma_{}, a1_{}, c1_{}, b2_{}, c2_{};
  bool single_ = false;
  mutable bool overflow_ = false;  // a critical list was full: the answer is not exact
};

// The valid joints of the pair p_i -> p_j by the paper's construction, in
// fit/biarc/joints.hpp's parametrisation (s in (0, 2)).
template <class S, int Cap = 128>
bool biarc_valid_joints_paper(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j, Vec2<S> ti,
                              Vec2<S> tj, JointSet<S, Cap>& out, PaperPairStats* stats = nullptr) {
  return BiarcPaper<S, Cap>(r, i, j, ti, tj).compute(out, stats);
}

// The same, as the fitter takes it (BiarcOptions::joints).
inline bool biarc_paper_joints(const BandRegion<double>& r, std::uint32_t i, std::uint32_t j,
                               Vec2<double> ti, Vec2<double> tj, JointSet<double>& out) {
  return biarc_valid_joints_paper(r, i, j, ti, tj, out);
}

}  // namespace kerf::fit
