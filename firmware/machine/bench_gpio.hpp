// A bench ([bench] enabled = true): the machine's axes with no torch. The
// configured lines are read as on the machine (E-stop, limits, hold, cycle
// start, and arc-OK when a line is configured); the torch is only remembered,
// since no torch output exists (machine_factory refuses one), and with no
// arc-OK line the arc is "on" exactly while the torch is commanded, so the
// controller runs its whole sequence with motion only.
#pragma once

#include <memory>

#include "kerf/hal/gpio.hpp"

namespace kerf::machine {

class BenchGpio final : public hal::Gpio {
 public:
  BenchGpio(std::unique_ptr<hal::Gpio> lines, bool has_arc_ok) : lines_(std::move(lines)), has_arc_ok_(has_arc_ok) {}
  bool read(double now_s, hal::GpioInputs& in) override {
    if (!lines_->read(now_s, in)) return false;
    if (!has_arc_ok_) in.arc_ok = torch_;
    return true;
  }
  bool set_torch(bool on) override {
    torch_ = on;
    return true;
  }
  const char* last_error() const override { return lines_->last_error(); }

 private:
  std::unique_ptr<hal::Gpio> lines_;
  bool has_arc_ok_;
  bool torch_ = false;
};

}  // namespace kerf::machine
