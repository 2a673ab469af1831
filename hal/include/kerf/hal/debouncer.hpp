// hal::Debouncer: turns raw pin levels sampled on a monotonic clock into a
// logical input value. Active-low is applied first, so the debounce works on
// logical values. The first sample is taken as is (there is no earlier state
// to hold against). After that, a changed value is accepted once it has been
// seen continuously for debounce_s: at the first sample where
// now_s - (time the change was first seen) >= debounce_s. Any sample back at
// the accepted value restarts the wait, so a bounce shorter than debounce_s
// is never seen. Pure logic: no clock, no allocation.
#pragma once

namespace kerf::hal {

class Debouncer {
 public:
  Debouncer() = default;
  Debouncer(double debounce_s, bool active_low)
      : debounce_s_(debounce_s > 0.0 ? debounce_s : 0.0), active_low_(active_low) {}

  // `level_high`: the pin's physical level. Returns the debounced logical value.
  bool update(bool level_high, double now_s) {
    const bool value = level_high != active_low_;
    if (!primed_) {
      primed_ = true;
      state_ = value;
      pending_ = false;
      return state_;
    }
    if (value == state_) {
      pending_ = false;
      return state_;
    }
    if (!pending_) {
      pending_ = true;
      since_s_ = now_s;
    }
    if (now_s - since_s_ >= debounce_s_) {
      state_ = value;
      pending_ = false;
    }
    return state_;
  }

  bool value() const { return state_; }
  // Forgets the history: the next sample is taken as is again.
  void reset() { primed_ = false; pending_ = false; state_ = false; }

 private:
  double debounce_s_ = 0.0;
  bool active_low_ = false;
  bool primed_ = false;
  bool state_ = false;
  bool pending_ = false;
  double since_s_ = 0.0;
};

}  // namespace kerf::hal
