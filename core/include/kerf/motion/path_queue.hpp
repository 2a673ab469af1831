// The segments waiting to be run: a bounded ring over caller-provided storage.
// Each entry is a fitted segment with its own feed and a sequence number that
// the sender chose (so a board can report which segment it has finished).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::motion {

// What a sender pushes: the geometry, the programmed feed (mm/s, > 0) and a
// sequence number.
template <class S>
struct PathSegment {
  Segment<S> geometry{};
  S feed{};
  std::uint32_t sequence = 0;
};

// A segment as the interpolator keeps it: the geometry worked out once at push
// time, so that step() needs no atan2 and no square root.
template <class S>
struct QueuedSegment {
  PathSegment<S> path{};
  S length{};           // mm along the path
  S radius{};           // arcs only: |start - centre|
  S radius_change{};    // arcs only: |end - centre| - radius (see point_at)
  S start_angle{};      // arcs only: angle of start - centre
  Vec2<S> tangent_in{};   // unit direction of travel at the start
  Vec2<S> tangent_out{};  // unit direction of travel at the end
  // The plane limits (ramp/plane_limits.hpp), worked out at push time:
  S curvature{};          // signed: + turning left, - right, 0 on a line
  S turn{};               // 2 sin(theta / 2) of the turn at the joint into it
  S cap_step{};           // the step cap on it from its curvature (infinity on a line)
  S spin{};               // cap_step * |curvature|
  S corner_step{};        // step limit at the joint into this segment (turn and curvature)
  bool curved() const { return turn > S(0) || curvature != S(0); }
};

// A FIFO of at most storage.size() segments. Nothing is allocated; when it is
// full, push returns Status::capacity_exceeded and the queue is unchanged.
template <class S>
class PathQueue {
 public:
  PathQueue() = default;
  explicit PathQueue(Span<QueuedSegment<S>> storage) : slots_(storage) {}

  std::size_t capacity() const { return slots_.size(); }
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool full() const { return count_ == slots_.size(); }

  Status push(const QueuedSegment<S>& s) {
    if (full()) return Status::capacity_exceeded;
    std::size_t at = head_ + count_;
    if (at >= slots_.size()) at -= slots_.size();
    slots_[at] = s;
    ++count_;
    return Status::ok;
  }

  // i-th entry from the front (0 = the segment being run).
  const QueuedSegment<S>& operator[](std::size_t i) const {
    KERF_ASSERT(i < count_);
    std::size_t at = head_ + i;
    if (at >= slots_.size()) at -= slots_.size();
    return slots_[at];
  }
  const QueuedSegment<S>& front() const { return (*this)[0]; }

  void pop_front() {
    KERF_ASSERT(count_ > 0);
    head_ = head_ + 1 == slots_.size() ? 0 : head_ + 1;
    --count_;
  }
  void clear() {
    head_ = 0;
    count_ = 0;
  }

 private:
  Span<QueuedSegment<S>> slots_{};
  std::size_t head_ = 0;
  std::size_t count_ = 0;
};

}  // namespace kerf::motion
