// One axis moved alone, rest to rest (the z moves of board_protocol.hpp): a
// trapezoid in whole servo periods, like the interpolator's ramps (see
// ramp/lookahead.hpp): a step is the distance of one period, two steps differ
// by at most A = accel * period^2, and braking is planned with
// max_step_before so the axis lands exactly on its target. Hold brakes to a
// stop on the way and resume goes on; abort brakes and drops the target.
#pragma once

#include <cstdint>

#include "kerf/core/scalar.hpp"
#include "kerf/motion/ramp/lookahead.hpp"

namespace kerf::motion {

// An axis's own limits; period 0 (the default) means "no such axis".
template <class S>
struct AxisLimits {
  S period{};  // servo period, s
  S feed{};    // top speed, mm/s (a move's own feed is capped by it)
  S accel{};   // mm/s^2
  bool configured() const { return period > S(0) && feed > S(0) && accel > S(0); }
};

template <class S>
class AxisMove {
 public:
  void configure(const AxisLimits<S>& l) { limits_ = l; }
  bool configured() const { return limits_.configured(); }

  // From rest at position(), to `to` at `feed` mm/s (capped by the limit).
  bool start(S to, S feed, std::uint32_t seq) {
    if (!configured() || busy() || !(feed > S(0))) return false;
    target_ = to;
    top_ = min_of(feed, limits_.feed) * limits_.period;
    seq_ = seq;
    held_ = aborting_ = false;
    active_ = true;
    return true;
  }
  // Brakes the axis (rest on its line) and forgets the target.
  void abort() { aborting_ = true; }
  void hold() { held_ = true; }
  void resume() { held_ = false; }
  // Rest at `at`, nothing to do.
  void reset(S at) {
    pos_ = target_ = at;
    step_ = S(0);
    active_ = held_ = aborting_ = false;
    seq_ = 0;
  }

  // One period; returns the sequence number it finished (0: none).
  std::uint32_t step() {
    if (!active_) return 0;
    const S a = limits_.accel * limits_.period * limits_.period;
    if (held_ || aborting_) {
      step_ = step_ > a ? step_ - a : S(0);
      advance(step_);
      if (aborting_ && step_ == S(0)) {
        active_ = false;
        target_ = pos_;
        seq_ = 0;
      }
      return 0;
    }
    const S d = Scalar<S>::abs(target_ - pos_);
    S x = min_of(step_ + a, top_);
    x = min_of(x, max_step_before(d, S(0), a));
    if (!(x < d)) {  // lands this period
      step_ = S(0);
      pos_ = target_;
      active_ = false;
      const std::uint32_t done = seq_;
      seq_ = 0;
      return done;
    }
    step_ = x;
    advance(x);
    return 0;
  }

  S position() const { return pos_; }
  bool busy() const { return active_; }
  bool moving() const { return step_ > S(0); }
  std::uint32_t running() const { return active_ && !aborting_ ? seq_ : 0; }
  S speed() const { return step_ / limits_.period; }  // mm/s over the last period

 private:
  void advance(S x) { pos_ = target_ < pos_ ? pos_ - x : pos_ + x; }

  AxisLimits<S> limits_{};
  S pos_{}, target_{}, step_{}, top_{};
  std::uint32_t seq_ = 0;
  bool active_ = false, held_ = false, aborting_ = false;
};

}  // namespace kerf::motion
