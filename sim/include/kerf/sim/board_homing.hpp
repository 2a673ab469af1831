// One axis's homing cycle on the simulated board, as a board's firmware runs
// it next to its switch: search towards the switch at the search speed,
// back off by the back-off distance, latch at the latch speed; the latch
// point is the home position. A switch that has not tripped within the
// search distance ends it as no_switch, with the axis stopped there.
// Plain state, stepped once per servo period by MotionBoard.
#pragma once

#include "kerf/hal/segment_link.hpp"

namespace kerf::sim {

class HomingCycle {
 public:
  // from: the axis position now, in the board's own (unhomed) frame.
  void start(const hal::HomeCommand& cmd, double from);
  // One period of dt seconds against a switch at `switch_at` (none: never
  // trips); returns the axis position after it.
  double step(double dt, const double* switch_at);
  void abort();

  bool active() const;
  hal::HomingState state() const { return state_; }
  const hal::HomeCommand& command() const { return cmd_; }
  double latched_at() const { return latched_; }  // where the latch tripped, unhomed frame

 private:
  bool tripped(const double* switch_at) const;
  void move(double v, double dt);

  hal::HomeCommand cmd_{};
  hal::HomingState state_ = hal::HomingState::none;
  double pos_ = 0, travelled_ = 0, backoff_from_ = 0, latched_ = 0;
};

}  // namespace kerf::sim
