#include "kerf/sim/board_homing.hpp"

#include <cmath>

namespace kerf::sim {

using hal::HomingState;

void HomingCycle::start(const hal::HomeCommand& cmd, double from) {
  cmd_ = cmd;
  pos_ = from;
  travelled_ = 0;
  state_ = HomingState::search;
}

bool HomingCycle::active() const {
  return state_ == HomingState::search || state_ == HomingState::backoff || state_ == HomingState::latch;
}

void HomingCycle::abort() {
  if (active()) state_ = HomingState::aborted;
}

bool HomingCycle::tripped(const double* switch_at) const {
  if (switch_at == nullptr) return false;
  return cmd_.dir < 0 ? pos_ <= *switch_at : pos_ >= *switch_at;
}

void HomingCycle::move(double v, double dt) {
  pos_ += v * dt;
  travelled_ += std::fabs(v) * dt;
}

double HomingCycle::step(double dt, const double* switch_at) {
  const double dir = cmd_.dir;
  if (cmd_.dir == 0 && state_ == HomingState::search) {  // "here": the switch was searched elsewhere
    latched_ = pos_;
    state_ = HomingState::done;
    return pos_;
  }
  switch (state_) {
    case HomingState::search:
      if (travelled_ + cmd_.search_speed * dt > cmd_.search_distance) {  // stop at the distance
        pos_ += dir * (cmd_.search_distance - travelled_);
        travelled_ = cmd_.search_distance;
        state_ = tripped(switch_at) ? HomingState::backoff : HomingState::no_switch;
      } else {
        move(dir * cmd_.search_speed, dt);
        if (tripped(switch_at)) state_ = HomingState::backoff;
      }
      if (state_ == HomingState::backoff) backoff_from_ = pos_;
      break;
    case HomingState::backoff:
      // Off the switch by the back-off distance (and at least off the switch).
      move(-dir * cmd_.search_speed, dt);
      if (std::fabs(pos_ - backoff_from_) >= cmd_.backoff && !tripped(switch_at)) {
        state_ = HomingState::latch;
        travelled_ = 0;
      }
      break;
    case HomingState::latch:
      move(dir * cmd_.latch_speed, dt);
      if (tripped(switch_at)) {
        latched_ = pos_;
        state_ = HomingState::done;
      } else if (travelled_ > cmd_.backoff + cmd_.search_distance) {
        state_ = HomingState::no_switch;  // the switch went away
      }
      break;
    default: break;
  }
  return pos_;
}

}  // namespace kerf::sim
