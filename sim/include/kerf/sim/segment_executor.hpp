// How the simulated board turns queued segments into servo-period positions.
// The board's executor (core/motion/board_executor.hpp) moves segments from
// its Modbus queue into this stage as soon as it has room, so a stage with
// look-ahead sees what comes next. kerf's interpolator (core/motion) sits
// behind this in motion_executor.cpp.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/hal/segment_link.hpp"
#include "kerf/motion/board_protocol.hpp"

namespace kerf::sim {

// One period of the executor (core/motion's MotionStep): position, the
// sequence number running and the last completed, moving, at rest.
using ExecStep = motion::MotionStep<double>;

// The board's motion stage: motion::BoardExecutor (which runs the board's
// queue and state machine) calls it through this interface, so the board
// can run either the interpolator or the endpoint stand-in below.
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
  virtual void reset(Vec2<double> at) = 0;  // empty, at rest at `at`
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
  void reset(Vec2<double> at) override {
    full_ = held_ = false;
    step_ = ExecStep{};
    step_.position = at;
  }

 private:
  hal::SegmentCommand next_{};
  bool full_ = false;
  bool held_ = false;
  ExecStep step_{};
};

}  // namespace kerf::sim
