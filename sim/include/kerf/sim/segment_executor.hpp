// How the simulated board turns one queued segment into servo-period
// positions. The board's motion comes from core/motion's interpolator through
// this interface (one adapter file), so the board itself does not depend on it.
#pragma once

#include "kerf/hal/segment_link.hpp"

namespace kerf::sim {

class SegmentExecutor {
 public:
  virtual ~SegmentExecutor() = default;
  // Starts `seg` from `from` (the previous segment's end). False when the
  // segment cannot be run (the board then faults with kFaultBadSegment).
  virtual bool begin(Vec2<double> from, const hal::SegmentCommand& seg) = 0;
  // Advances by one servo period of `period_s` seconds and writes the new
  // position. Returns true once the segment's end is reached.
  virtual bool step(double period_s, Vec2<double>& pos) = 0;
};

// Reaches each segment's end point in one servo period. It exercises the
// link (queue, credit, sequence numbers) without a motion profile: protocol
// tests and the link benchmark use it. `kerf sim` never does.
class EndpointExecutor final : public SegmentExecutor {
 public:
  bool begin(Vec2<double>, const hal::SegmentCommand& seg) override {
    end_ = seg.end;
    return true;
  }
  bool step(double, Vec2<double>& pos) override {
    pos = end_;
    return true;
  }

 private:
  Vec2<double> end_{};
};

}  // namespace kerf::sim
