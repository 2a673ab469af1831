#include "control/safety_latch.hpp"

namespace kerf::control {

bool SafetyLatch::cycle(const char* still, bool reset_line) {
  const bool edge = (reset_line && !prev_reset_) || start_reset_;
  prev_reset_ = reset_line;
  start_reset_ = false;
  bool accepted = false;
  if (still != nullptr) {
    ok_ = false;
    if (edge) {
      refused_ = "reset refused: ";
      refused_ += still;
      ++refusals_;
    }
  } else if (!ok_ && edge) {
    ok_ = accepted = true;
  }
  if (ok_) {
    watchdog_ = !watchdog_;
    ++toggles_;
  }
  return accepted;
}

}  // namespace kerf::control
