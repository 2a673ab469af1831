// The exact set of valid joints of a pair p_i -> p_j: which points of the
// joint circle J (fit/biarc/arc.hpp) give a valid biarc (Definition 3.2,
// fit/biarc/valid.hpp), as intervals of J's parameter s in (0, 2).
//
// Why this is exact. Let J's points be m(lambda), m = p_i + d w / (1 + w),
// w = lambda k (fit/biarc/arc.hpp). The first arc's curvature and the reversed
// second arc's curvature are then simple in lambda (d = p_j - p_i):
//   kappa1(lambda) = 2 (t_i x d + (t_i x d k) / lambda) / |d|^2,
//   kappa2~(lambda) = 2 (t_j x d + lambda t_j x (d conj k)) / |d|^2
// (kappa2~ is the arc p_j -> m leaving p_j along -t_j). For one boundary
// segment e = q1 q2 of R, "the biarc at s meets e" can change only where
//  - an arc passes through q1 or q2 (one lambda each: the pencil circle
//    through q meets J once more),
//  - an arc is tangent to e's line ((a kappa + b)^2 = 1, two kappas),
//  - the joint crosses e's line (J meets a line twice: a quadratic),
//  - an arc flips through a straight line pointing backwards (the joint on
//    the line p_i + t_i x or p_j + t_j x), the joint passes p_j (s = 1) or
//    goes to infinity (J a line).
// Between two consecutive such critical joints the answer is constant, so
// one exact test (BiarcCheck::meets) at the middle decides the whole open
// interval. The valid set is (0, 2) minus the union, over the segments of
// R's boundary between g_i and g_j (both gates included), of the intervals
// where the biarc meets them: no joint is sampled, and no valid interval,
// however narrow, is missed. Critical joints themselves (a biarc touching
// the boundary) count as invalid, like every touch in fit/biarc/valid.hpp.
// The sets are exact for the boundary; the rule that every intermediate gate
// be crossed (fit/biarc/valid.hpp; it refuses anything only where R
// overlaps itself) is applied to the joints verified from them.
//
// Relation to the paper. Drysdale, Rote and Sturm find the same arc of
// joints (A1 A2, Lemmas 3.5-3.7) in O(log n) per pair from precomputed
// circular visibility regions W_i, W~_j on the gates and a binary search
// for the (In)/(Out) partition (Lemma 3.4). kerf computes the valid set
// directly from the pair's O(j - i) boundary segments instead (O(j - i) per
// pair, stopping as soon as the set is empty, which for most invalid pairs
// is after a few segments: the middle cells are visited first). It needs
// neither the regions nor the lemmas' case analysis, and it also yields the
// degenerate cases: a joint at an end point (s -> 0, 1, 2, refused unless
// one arc matches both tangents, see JointCircle::biarc), J a line (the
// point at infinity is a critical joint) and one circle with both tangents
// (both kappas are constant; only the joint's line crossings remain).
#pragma once

#include <cstdint>

#include "kerf/fit/biarc/valid.hpp"
#include "kerf/geom/complex.hpp"
#include "kerf/geom/roots.hpp"

namespace kerf::fit {

// A set of disjoint open intervals of (0, 2), in order. Fixed capacity: the
// valid joints of a pair form at most a few arcs (Lemma 3.6), but on the
// way, before all segments are removed, the set can fragment (up to 63
// intervals seen on sines at tol 1e-5 .. 5; more than 32 even within
// 1/64 of J on the demo job's straight sides). Overflow is flagged, never
// dropped: BiarcJoints::compute then splits J into windows.
template <class S, int Cap = 128>
class JointSet {
 public:
  static constexpr int kMax = Cap;
  struct Range {
    S lo, hi;
  };

  void reset_to(S lo, S hi) {
    size_ = 0;
    peak_ = 1;
    overflow_ = false;
    v_[size_++] = {lo, hi};
  }
  void clear() {
    size_ = 0;
    peak_ = 0;
    overflow_ = false;
  }
  // Adds r after every interval held (the caller keeps the order).
  void append(Range r) {
    if (size_ == kMax) {
      overflow_ = true;
      return;
    }
    v_[size_++] = r;
    if (size_ > peak_) peak_ = size_;
  }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool overflow() const { return overflow_; }
  const Range& operator[](int k) const { return v_[k]; }

  bool overlaps(S lo, S hi) const {
    for (int k = 0; k < size_; ++k)
      if (v_[k].lo < hi && v_[k].hi > lo) return true;
    return false;
  }
  // Removes the closed interval [lo, hi]. The intervals it touches are a
  // run [a, b); they give way to at most their two outer remains.
  void remove(S lo, S hi) {
    int a = 0;
    while (a < size_ && !(v_[a].hi > lo)) ++a;
    int b = a;
    while (b < size_ && v_[b].lo < hi) ++b;
    if (a == b) return;
    Range keep[2];
    int m = 0;
    if (v_[a].lo < lo) keep[m++] = {v_[a].lo, lo};
    if (hi < v_[b - 1].hi) keep[m++] = {hi, v_[b - 1].hi};
    const int grow = m - (b - a);  // <= 1
    if (size_ + grow > kMax) {
      overflow_ = true;  // the caller reports it; nothing is dropped silently
      return;
    }
    if (grow > 0) {
      for (int k = size_; k-- > b;) v_[k + grow] = v_[k];
    } else if (grow < 0) {
      for (int k = b; k < size_; ++k) v_[k + grow] = v_[k];
    }
    for (int k = 0; k < m; ++k) v_[a + k] = keep[k];
    size_ += grow;
    if (size_ > peak_) peak_ = size_;
  }
  int peak() const { return peak_; }

 private:
  Range v_[kMax]{};
  int size_ = 0;
  int peak_ = 0;
  bool overflow_ = false;
};

// Cap: the capacity of the sets it computes (tests make it small to reach
// the windows).
template <class S, int Cap = 128>
class BiarcJoints {
 public:
  BiarcJoints(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j, Vec2<S> ti, Vec2<S> tj)
      : r_(r), i_(i), j_(j), check_(r, i, j), jc_(check_.point(i), ti, check_.point(j), tj) {
    p1_ = check_.point(i);
    p2_ = check_.point(j);
    t1_ = ti;
    t2_ = tj;
    d_ = p2_ - p1_;
    dd_ = d_.norm2();
    const Vec2<S> k = jc_.k();
    k_ = k;
    const Vec2<S> dk = complex_mul<S>(d_, k);
    const Vec2<S> dkc = complex_mul<S>(d_, {k.x, -k.y});
    a1_ = t1_.cross(dk);
    c1_ = t1_.cross(d_);
    b2_ = t2_.cross(dkc);
    c2_ = t2_.cross(d_);
    nk_ = 0;
    add_global(S(1));  // p_j
    if (jc_.line()) add_global(s_of(S(-1) / k.x));  // J's point at infinity
    // The joint on the line p_i + x t_i: arc 1 is straight there, and
    // pointing backwards beyond p_i it flips round.
    {
      const Vec2<S> n = t1_.perp();
      const S den = n.dot(d_);
      if (den != S(0)) add_global(s_of(-n.dot(dk) / den));
    }
    {
      const Vec2<S> n = t2_.perp();
      const S g = n.dot(d_);
      const S den = n.dot(dk) - S(2) * g * k.x;
      if (den != S(0)) add_global(s_of(g / den));
    }
  }

  // The check, and the frame (fit/biarc/numeric.hpp) of the joint circle,
  // the biarcs and the sets.
  const BiarcCheck<S>& check() const { return check_; }
  // How many windows the last compute() needed beyond the whole of J.
  int windows() const { return split_; }
  const JointCircle<S>& circle() const { return jc_; }

  // Computes the valid joints into `out`. When the set fragments past its
  // capacity on the way, J is cut into 4 windows (then 16, 64), each
  // computed alone: the result stays exact. Returns false only when even
  // that overflows (never seen; the caller reports it).
  bool compute(JointSet<S, Cap>& out) const {
    out.clear();
    split_ = 0;
    if (!check_.ends(t1_, t2_)) return true;
    struct Window {
      S lo, hi;
      int depth;
    };
    Window stack[16];
    int top = 0;
    stack[top++] = {S(0), S(2), 0};
    JointSet<S, Cap> part;
    while (top > 0) {
      const Window w = stack[--top];
      if (w.depth > 0) ++split_;
      if (window(w.lo, w.hi, part)) {
        for (int q = 0; q < part.size(); ++q) out.append(part[q]);
        continue;
      }
      if (w.depth == 3) return false;
      const S step = (w.hi - w.lo) / S(4);
      for (int k = 4; k-- > 0;)  // pushed right to left: popped left to right
        stack[top++] = {k == 0 ? w.lo : w.lo + step * S(k), k == 3 ? w.hi : w.lo + step * S(k + 1),
                        w.depth + 1};
    }
    return !out.overflow();
  }

  // A shortcut for "has the pair a valid joint?": when one of a few
  // likely joints (the middles and quarters of J's two arcs) passes the
  // full test, the answer is yes without the set. A "no" here proves
  // nothing; compute() then decides.
  bool quick_yes(S& found) const {
    if (!check_.ends(t1_, t2_)) return false;
    const S at[4] = {S(0.5), S(1.5), S(0.25), S(1.75)};
    Biarc<S> b[4];
    bool alive[4];
    std::uint32_t m = 0;
    for (const S s : at) {
      if (jc_.biarc(s, b[m])) alive[m++] = true;
    }
    if (m == 0 || check_.filter(b, alive, m) == 0) return false;
    for (std::uint32_t q = 0; q < m; ++q) {
      if (alive[q]) {
        found = b[q].s;
        return true;
      }
    }
    return false;
  }

  // A joint of `set` that passes the full test, or false: the middle, then
  // the quarters of each interval (the middle fails only by rounding, in an
  // interval a few ulps wide).
  bool verified(const JointSet<S, Cap>& set, S& found, Biarc<S>& b) const {
    for (int q = 0; q < set.size(); ++q) {
      const S lo = set[q].lo;
      const S hi = set[q].hi;
      const S at[3] = {(lo + hi) / S(2), lo + (hi - lo) / S(4), hi - (hi - lo) / S(4)};
      for (const S s : at) {
        if (s > lo && s < hi && jc_.biarc(s, b) && check_.valid(b)) {
          found = s;
          return true;
        }
      }
    }
    return false;
  }

 private:
  // J's parameter s (fit/biarc/arc.hpp) of lambda.
  static S s_of(S lambda) {
    if (lambda >= S(0)) return lambda / (S(1) + lambda);
    return (S(2) - lambda) / (S(1) - lambda);
  }

  void add_global(S s) {
    if (s > S(0) && s < S(2) && nk_ < 4) known_[nk_++] = s;
  }

  // The lambda whose arc 1 (the pencil at p_i along t_i) passes through q
  // (kappa1 = 2 t_i x (q - p_i) / |q - p_i|^2), or has curvature kappa.
  bool lambda_arc1_through(Vec2<S> q, S& lambda) const {
    const Vec2<S> v = q - p1_;
    const S l2 = v.norm2();
    const S den = t1_.cross(v) * dd_ - c1_ * l2;
    if (den == S(0) || a1_ == S(0)) return false;
    lambda = a1_ * l2 / den;
    return true;
  }
  bool lambda_arc1_kappa(S kappa, S& lambda) const {
    const S den = kappa * dd_ - S(2) * c1_;
    if (den == S(0) || a1_ == S(0)) return false;
    lambda = S(2) * a1_ / den;
    return true;
  }
  // Arc 2 reversed: the pencil at p_j along -t_j.
  bool lambda_arc2_through(Vec2<S> q, S& lambda) const {
    const Vec2<S> v = q - p2_;
    const S l2 = v.norm2();
    if (l2 == S(0) || b2_ == S(0)) return false;
    lambda = (-(t2_.cross(v)) * dd_ / l2 - c2_) / b2_;
    return true;
  }
  bool lambda_arc2_kappa(S kappa, S& lambda) const {
    if (b2_ == S(0)) return false;
    lambda = (kappa * dd_ / S(2) - c2_) / b2_;
    return true;
  }

  // The curvatures of the pencil at p (tangent t) whose circle touches the
  // line through q along unit u: with a = n.(p - q), b = n.perp(t), the
  // centre p + perp(t) / kappa is 1 / |kappa| from the line iff
  // (a kappa + b)^2 = 1.
  static int tangent_kappas(Vec2<S> p, Vec2<S> t, Vec2<S> q, Vec2<S> u, S out[2]) {
    const Vec2<S> n = u.perp();
    const S a = n.dot(p - q);
    const S b = n.dot(t.perp());
    if (a == S(0)) return 0;
    out[0] = (S(1) - b) / a;
    out[1] = (S(-1) - b) / a;
    return 2;
  }

  // The lambdas where J meets the line through q with unit normal n:
  // lambda^2 (n.d - g) + lambda (n.(d k) - 2 g Re k) - g = 0, g = n.(q - p_i).
  int joint_on_line(Vec2<S> q, Vec2<S> n, S out[2]) const {
    const S g = n.dot(q - p1_);
    S q3[3] = {n.dot(d_) - g, n.dot(complex_mul<S>(d_, k_)) - S(2) * g * k_.x, -g};
    band_detail::balance(q3, 3);  // fixed point: the discriminant keeps its bits
    return quadratic_roots(q3[0], q3[1], q3[2], out);
  }

  // The valid joints within (lo, hi); false when the set overflowed.
  bool window(S lo, S hi, JointSet<S, Cap>& out) const {
    out.reset_to(lo, hi);
    out.remove(S(1), S(1));  // p_j itself (see JointCircle::biarc)
    cut(check_.gate_end(i_, -1), check_.gate_end(i_, 1), out);
    if (!out.empty()) cut(check_.gate_end(j_, -1), check_.gate_end(j_, 1), out);
    // The cells middle first: the set empties early. (Past an overflow the
    // window is split and computed again, so stopping there loses nothing.)
    if (!out.empty() && !out.overflow()) {
      check_.chains_middle_first([&](const BandChain<S>& c) {
        for (int e = 0; e + 1 < c.size && !out.empty(); ++e) cut(c.pt[e], c.pt[e + 1], out);
        return !out.empty() && !out.overflow();
      });
    }
    if (out.overflow()) return false;
    // Intervals with no double strictly inside hold no joint kerf can use.
    for (int q = 0; q < out.size();) {
      const S a = out[q].lo;
      const S b = out[q].hi;
      const S mid = a + (b - a) / S(2);
      if (mid > a && mid < b) {
        ++q;
      } else {
        out.remove(a, b);
      }
    }
    return true;
  }

  // Removes from `set` the joints whose biarc meets the segment q1 q2.
  void cut(Vec2<S> q1, Vec2<S> q2, JointSet<S, Cap>& set) const {
    // A point (a barrier's gate): the one-segment test never meets it.
    if (q1 == q2) return;
    S crit[24];
    int m = 0;
    crit[m++] = S(0);
    crit[m++] = S(2);
    for (int k = 0; k < nk_; ++k) crit[m++] = known_[k];
    auto add = [&](S lambda) {
      const S s = s_of(lambda);
      if (s > S(0) && s < S(2)) crit[m++] = s;
    };
    S lambda{};
    const Vec2<S> ends[2] = {q1, q2};
    for (const Vec2<S>& q : ends) {
      if (lambda_arc1_through(q, lambda)) add(lambda);
      if (lambda_arc2_through(q, lambda)) add(lambda);
    }
    const Vec2<S> e = q2 - q1;
    const S len = band_detail::length(e);
    if (len > S(0)) {
      const Vec2<S> u = e * (S(1) / len);
      S kap[2];
      int c = tangent_kappas(p1_, t1_, q1, u, kap);
      for (int t = 0; t < c; ++t)
        if (lambda_arc1_kappa(kap[t], lambda)) add(lambda);
      c = tangent_kappas(p2_, -t2_, q1, u, kap);
      for (int t = 0; t < c; ++t)
        if (lambda_arc2_kappa(kap[t], lambda)) add(lambda);
      S l[2];
      c = joint_on_line(q1, u.perp(), l);
      for (int t = 0; t < c; ++t) add(l[t]);
    }
    // Insertion sort: at most 20 values.
    for (int a = 1; a < m; ++a) {
      const S v = crit[a];
      int b = a;
      while (b > 0 && crit[b - 1] > v) {
        crit[b] = crit[b - 1];
        --b;
      }
      crit[b] = v;
    }
    Biarc<S> b;
    for (int a = 0; a + 1 < m; ++a) {
      const S lo = crit[a];
      const S hi = crit[a + 1];
      if (!(lo < hi) || !set.overlaps(lo, hi)) continue;
      const S mid = lo + (hi - lo) / S(2);
      if (!(mid > lo && mid < hi)) continue;  // no double between: nothing to decide
      // No biarc at the middle (only a rounding step from an end point):
      // left undecided; a joint is verified in full before it is used.
      if (!jc_.biarc(mid, b)) continue;
      if (check_.meets(b, q1, q2)) set.remove(lo, hi);
    }
  }

  const BandRegion<S>& r_;
  std::uint32_t i_;
  std::uint32_t j_;
  BiarcCheck<S> check_;
  JointCircle<S> jc_;
  Vec2<S> p1_{}, p2_{}, t1_{}, t2_{}, d_{}, k_{};
  S dd_{}, a1_{}, c1_{}, b2_{}, c2_{};
  S known_[4]{};
  int nk_ = 0;
  mutable int split_ = 0;
};

}  // namespace kerf::fit
