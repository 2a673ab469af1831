// How the simulated board turns queued segments into servo-period positions.
// The board moves segments from its Modbus queue into the executor as soon as
// the executor has room, so an executor with look-ahead sees what comes next.
// kerf's interpolator (core/motion) sits behind this in motion_executor.cpp.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/hal/segment_link.hpp"

namespace kerf::sim {

struct ExecStep {
  Vec2<double> position{};          // what the drives hold after this period, mm
  std::uint32_t running = 0;        // sequence number being run, 0 when none
  std::uint32_t last_completed = 0; // highest sequence number finished
  bool moving = false;              // travelled this period
  bool at_rest = true;              // not moving and nothing left to run
};

class SegmentExecutor {
 public:
  virtual ~SegmentExecutor() = default;
  virtual std::size_t free_slots() const = 0;
  // Appends `seg`, which starts at `from` (the previous segment's end or the
  // board's position). False when the executor refuses it (bad geometry).
  virtual bool push(Vec2<double> from, const hal::SegmentCommand& seg) = 0;
  virtual ExecStep step() = 0;  // one servo period
  virtual void hold() = 0;      // brake to a stop on the path
  virtual void resume() = 0;
  virtual void abort() = 0;     // brake to a stop, drop what is queued
};

// Reaches each segment's end point in one servo period. It exercises the
// link (queue, credit, sequence numbers) without a motion profile: protocol
// tests and the link benchmark use it. `kerf sim` never does.
class EndpointExecutor final : public SegmentExecutor {
 public:
  std::size_t free_slots() const override { return full_ ? 0 : 1; }
  bool push(Vec2<double>, const hal::SegmentCommand& seg) override {
    next_ = seg;
    full_ = true;
    return true;
  }
  ExecStep step() override {
    if (full_ && !held_) {
      step_.position = next_.end;
      step_.running = next_.seq;
      step_.last_completed = next_.seq;
      full_ = false;
      step_.moving = true;
    } else {
      step_.running = 0;
      step_.moving = false;
    }
    step_.at_rest = !full_;
    return step_;
  }
  void hold() override { held_ = true; }
  void resume() override { held_ = false; }
  void abort() override { full_ = false; }

 private:
  hal::SegmentCommand next_{};
  bool full_ = false;
  bool held_ = false;
  ExecStep step_{};
};

}  // namespace kerf::sim
