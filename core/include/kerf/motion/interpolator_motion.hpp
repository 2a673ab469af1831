// The interpolator as a BoardExecutor's motion stage. The drives receive
// integer counts, so the position it reports is the counts converted back to
// mm: what the axes actually do. The interpolator stops at exact points of
// the path (a hold, an abort); a new run whose start is within a count and a
// half of that point starts exactly there, so that the joint is exact.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/motion/board_protocol.hpp"
#include "kerf/motion/interpolator.hpp"

namespace kerf::motion {

template <class S>
class InterpolatorMotion {
 public:
  // The interpolator's storage (see Interpolator); configure() before use.
  explicit InterpolatorMotion(Span<QueuedSegment<S>> storage, Span<S> jerk_window = {})
      : interp_(storage, jerk_window) {}

  Status configure(const MotionConfig<S>& c) {
    const Status s = interp_.configure(c);
    if (s == Status::ok) counts_per_mm_ = c.counts_per_mm;
    return s;
  }

  std::size_t free_slots() const { return interp_.free_slots(); }
  bool push(Vec2<S> from, const BoardSegment<S>& seg);
  MotionStep<S> step();
  void hold() { interp_.hold(); }
  void resume() { interp_.resume(); }
  void abort() { interp_.abort(); }
  // Empty, at rest at `at`.
  void reset(Vec2<S> at);

  // The counts the drives were last given.
  Counts counts() const { return counts_; }
  Interpolator<S>& interpolator() { return interp_; }
  const Interpolator<S>& interpolator() const { return interp_; }

 private:
  bool within_counts(Vec2<S> a, Vec2<S> b) const;

  Interpolator<S> interp_;
  Vec2<S> counts_per_mm_{S(1), S(1)};
  Vec2<S> exact_{};    // where the interpolator is, exactly (not rounded to counts)
  bool have_exact_ = false;
  Vec2<S> held_{};     // the counts in mm
  Counts counts_{};
};

template <class S>
bool InterpolatorMotion<S>::within_counts(Vec2<S> a, Vec2<S> b) const {
  return Scalar<S>::abs(a.x - b.x) * counts_per_mm_.x <= S(1.5) &&
         Scalar<S>::abs(a.y - b.y) * counts_per_mm_.y <= S(1.5);
}

template <class S>
bool InterpolatorMotion<S>::push(Vec2<S> from, const BoardSegment<S>& seg) {
  if (interp_.queued() == 0 && within_counts(from, exact_)) from = exact_;
  PathSegment<S> p;
  p.geometry = seg.kind == SegmentKind::arc ? Segment<S>::arc(from, seg.end, seg.centre, seg.dir)
                                            : Segment<S>::line(from, seg.end);
  p.feed = seg.feed;
  p.sequence = seg.seq;
  return interp_.push(p) == Status::ok;
}

template <class S>
MotionStep<S> InterpolatorMotion<S>::step() {
  const Setpoint<S> sp = interp_.step();
  MotionStep<S> e;
  e.last_completed = interp_.last_completed_sequence();
  if (sp.state == MotionState::idle) {  // nothing pushed since reset: hold the position
    e.position = held_;
    return e;
  }
  exact_ = sp.position;
  have_exact_ = true;
  counts_ = sp.counts;
  held_ = {S(counts_.x) / counts_per_mm_.x, S(counts_.y) / counts_per_mm_.y};
  const bool running = sp.state == MotionState::running || sp.state == MotionState::stopping;
  e.position = held_;
  e.running = running && interp_.queued() > 0 ? sp.sequence : 0;
  e.moving = sp.speed > S(0);
  e.at_rest = !running && interp_.queued() == 0;
  e.thc_lock = sp.thc_lock;
  return e;
}

template <class S>
void InterpolatorMotion<S>::reset(Vec2<S> at) {
  interp_.reset();
  if (!have_exact_ || !within_counts(at, exact_)) exact_ = at;
  have_exact_ = true;
  counts_ = to_counts(at, counts_per_mm_);
  held_ = at;
}

}  // namespace kerf::motion
