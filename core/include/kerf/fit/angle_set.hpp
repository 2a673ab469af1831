// A subset of the projective circle [0, pi] (0 and pi are the same point),
// kept as sorted, disjoint closed intervals in caller-provided storage.
//
// The exact vertex test parametrises the circles through two points by an
// angle phi in [0, pi), phi = 0 being the line. Each inner point allows one
// arc of phi (mod pi), and the intersection of such arcs can split into
// several pieces, so the set is a list, not one interval.
#pragma once

#include <cstddef>

#include "kerf/core/scalar.hpp"
#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"

namespace kerf::fit {

template <class S>
struct Interval {
  S lo{};
  S hi{};
};

// Writes the arc [centre - half, centre + half] (mod pi) as at most two
// sorted intervals of [0, pi]. half >= pi/2 covers the whole circle.
template <class S>
std::size_t arc_parts(S centre, S half, Interval<S> out[2]) {
  const S pi = Scalar<S>::pi();
  if (!(half < pi / S(2))) {
    out[0] = {S(0), pi};
    return 1;
  }
  while (centre < S(0)) centre = centre + pi;
  while (!(centre < pi)) centre = centre - pi;
  const S lo = centre - half;
  const S hi = centre + half;
  if (lo < S(0)) {
    out[0] = {S(0), hi};
    out[1] = {lo + pi, pi};
    return 2;
  }
  if (hi > pi) {
    out[0] = {S(0), hi - pi};
    out[1] = {lo, pi};
    return 2;
  }
  out[0] = {lo, hi};
  return 1;
}

template <class S>
class AngleSet {
 public:
  // Two buffers of equal size; intersections ping-pong between them.
  AngleSet(Span<Interval<S>> a, Span<Interval<S>> b) : cur_(a), spare_(b) { reset(); }

  void reset() {
    cur_[0] = {S(0), Scalar<S>::pi()};
    size_ = 1;
  }
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const Interval<S>& operator[](std::size_t k) const { return cur_[k]; }
  bool contains_line() const {
    return size_ > 0 && (!(cur_[0].lo > S(0)) || !(cur_[size_ - 1].hi < Scalar<S>::pi()));
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

  Status intersect_arc(S centre, S half) {
    Interval<S> parts[2];
    const std::size_t n = arc_parts(centre, half, parts);
    if (n == 1 && !(parts[0].lo > S(0)) && !(parts[0].hi < Scalar<S>::pi())) return Status::ok;
    return intersect(parts, n);
  }

 private:
  Span<Interval<S>> cur_;
  Span<Interval<S>> spare_;
  std::size_t size_ = 0;
};

}  // namespace kerf::fit
