// A subset of the projective circle of directions (a direction and its
// opposite are the same point), kept as sorted, disjoint closed intervals in
// caller-provided storage.
//
// The exact vertex test parametrises the circles through two points by an
// angle phi in [0, pi), phi = 0 being the line. Each inner point allows one
// arc of phi (mod pi), and the intersection of such arcs can split into
// several pieces, so the set is a list, not one interval.
//
// Angles are stored as pseudo-angles q in [0, 2): q = 1 - x / (|x| + y) for
// the direction (x, y) with y >= 0. q is strictly increasing in the true angle,
// so intersections are the same as with radians, but it needs no atan2, and
// arc end points come from a rotation by (sqrt(1 - k^2), k) instead of asin.
// That is what makes the exact test cheap, and portable to fixed point.
#pragma once

#include <cstddef>

#include "kerf/core/scalar.hpp"
#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::fit {

template <class S>
struct Interval {
  S lo{};
  S hi{};
};

// The pseudo-angle of direction d (mod pi); d must not be zero.
template <class S>
S pseudo_angle(Vec2<S> d) {
  if (d.y < S(0) || (d.y == S(0) && d.x < S(0))) d = -d;
  return S(1) - d.x / (Scalar<S>::abs(d.x) + d.y);
}

// A direction (not normalised) whose pseudo-angle is q, 0 <= q <= 2.
template <class S>
Vec2<S> direction_of(S q) {
  return q <= S(1) ? Vec2<S>{S(1) - q, q} : Vec2<S>{S(1) - q, S(2) - q};
}

// Writes the directions within asin(k) of the unit direction u (mod pi),
// 0 <= k < 1, as at most two sorted intervals of [0, 2].
template <class S>
std::size_t arc_parts(Vec2<S> u, S k, Interval<S> out[2]) {
  const S c = Scalar<S>::sqrt(S(1) - k * k);
  const S lo = pseudo_angle(Vec2<S>{u.x * c + u.y * k, u.y * c - u.x * k});
  const S hi = pseudo_angle(Vec2<S>{u.x * c - u.y * k, u.y * c + u.x * k});
  if (!(hi < lo)) {
    out[0] = {lo, hi};
    return 1;
  }
  out[0] = {S(0), hi};  // the arc contains the line's direction: it wraps
  out[1] = {lo, S(2)};
  return 2;
}

template <class S>
class AngleSet {
 public:
  // Two buffers of equal size; intersections ping-pong between them.
  AngleSet(Span<Interval<S>> a, Span<Interval<S>> b) : cur_(a), spare_(b) { reset(); }

  void reset() {
    cur_[0] = {S(0), S(2)};
    size_ = 1;
  }
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const Interval<S>& operator[](std::size_t k) const { return cur_[k]; }
  bool contains_line() const {
    return size_ > 0 && (!(cur_[0].lo > S(0)) || !(cur_[size_ - 1].hi < S(2)));
  }

  // Intersects with a union of sorted intervals (they may touch or overlap).
  Status intersect(const Interval<S>* parts, std::size_t count) {
    std::size_t out = 0;
    std::size_t a = 0;
    std::size_t b = 0;
    while (a < size_ && b < count) {
      const S lo = max_of(cur_[a].lo, parts[b].lo);
      const S hi = min_of(cur_[a].hi, parts[b].hi);
      if (!(hi < lo)) {
        if (out > 0 && !(spare_[out - 1].hi < lo)) {
          spare_[out - 1].hi = max_of(spare_[out - 1].hi, hi);  // overlapping parts
        } else {
          if (out == spare_.size()) return Status::capacity_exceeded;
          spare_[out++] = {lo, hi};
        }
      }
      if (cur_[a].hi < parts[b].hi) ++a; else ++b;
    }
    Span<Interval<S>> t = cur_;
    cur_ = spare_;
    spare_ = t;
    size_ = out;
    return Status::ok;
  }

  // Intersects with the directions within asin(k) of unit direction u.
  Status intersect_arc(Vec2<S> u, S k) {
    if (!(k < S(1))) return Status::ok;
    Interval<S> parts[2];
    return intersect(parts, arc_parts(u, k, parts));
  }

 private:
  Span<Interval<S>> cur_;
  Span<Interval<S>> spare_;
  std::size_t size_ = 0;
};

}  // namespace kerf::fit
