// control::SafetyLatch: the E-stop chain's latch, after LinuxCNC's
// estop_latch HAL component. Two states, OK and latched, and it starts
// latched. A trip (the E-stop input, any fault) latches it. It unlatches only
// when the trip has cleared AND a reset edge arrives: a rising edge of the
// reset input, or the one reset given at start-up (`kerf run --reset`). A
// reset while a trip is still present is refused, and the refusal is kept
// for the operator. While OK the watchdog output toggles every cycle (a
// charge pump holding an external safety relay); latched, it stands still.
// No allocation except the refusal text.
#pragma once

#include <cstdint>
#include <string>

namespace kerf::control {

class SafetyLatch {
 public:
  explicit SafetyLatch(bool reset_at_start = false) : start_reset_(reset_at_start) {}

  // One cycle. `still`: why it must stay latched now ("the E-stop is still
  // asserted"), null when nothing holds it; `reset_line`: the reset input's
  // level. True when a reset was accepted in this cycle.
  bool cycle(const char* still, bool reset_line);
  // Latches now (a fault seen by the controller).
  void trip() { ok_ = false; }

  bool ok() const { return ok_; }
  bool watchdog() const { return watchdog_; }
  std::uint32_t toggles() const { return toggles_; }
  // The last refused reset ("reset refused: the E-stop is still asserted"); empty: none.
  const std::string& refused() const { return refused_; }
  std::uint32_t refusals() const { return refusals_; }

 private:
  bool ok_ = false;
  bool start_reset_;
  bool prev_reset_ = true;  // a line held from power-up is not an edge
  bool watchdog_ = false;
  std::uint32_t toggles_ = 0;
  std::string refused_;
  std::uint32_t refusals_ = 0;
};

}  // namespace kerf::control
