// A minimal hal::Gpio for controller tests: the arc comes 20 ms after the
// torch turns on; inputs are set by the test between cycles; every torch
// change is recorded with the time of the read before it.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "kerf/hal/gpio.hpp"

namespace kerf::test {

class FakeGpio final : public hal::Gpio {
 public:
  struct Change {
    double t;
    bool on;
  };
  // Runs `fn` at the first read at or after t_s.
  void at(double t_s, std::function<void(FakeGpio&)> fn) { events_.push_back({t_s, std::move(fn)}); }

  bool read(double now_s, hal::GpioInputs& in) override {
    now_ = now_s;
    for (auto& e : events_)
      if (e.fn && now_s >= e.t) {
        e.fn(*this);
        e.fn = nullptr;
      }
    in = inputs;
    in.arc_ok = torch_ && arc_works && now_s >= torch_on_t_ + 0.02 && !arc_lost;
    return true;
  }
  bool set_torch(bool on) override {
    if (on != torch_) changes.push_back({now_, on});
    if (on && !torch_) torch_on_t_ = now_;
    torch_ = on;
    return true;
  }
  bool set_watchdog(bool level) override {
    if (level != watchdog_ && record_watchdog) watchdog_changes.push_back(now_);
    watchdog_ = level;
    return true;
  }
  bool set_thc_lock(bool on) override {
    if (on != thc_lock) thc_lock_changes.push_back({now_, on});
    thc_lock = on;
    return true;
  }
  // Program lines ([[gpio.output]] / [[gpio.input]]): the numbers in
  // `outputs` and `program_inputs` exist; others fail as the libgpiod backend does.
  bool set_output(int number, bool on) override {
    const auto it = outputs.find(number);
    if (it == outputs.end() || fail_outputs) {
      error_ = "gpio: output " + std::to_string(number) + ": setting it failed";
      return false;
    }
    if (it->second != on) output_changes.push_back({number, on, now_});
    it->second = on;
    return true;
  }
  bool outputs_off() override {
    ++outputs_off_calls;
    bool ok = true;
    for (auto& [n, on] : outputs) ok = set_output(n, false) && ok;
    return ok;
  }
  bool read_input(int number, double now_s, bool& value) override {
    (void)now_s;
    const auto it = program_inputs.find(number);
    if (it == program_inputs.end()) {
      error_ = "gpio: input " + std::to_string(number) + ": no such line";
      return false;
    }
    value = it->second;
    return true;
  }
  const char* last_error() const override { return error_.c_str(); }
  bool torch() const { return torch_; }

  struct OutputChange {
    int number;
    bool on;
    double t;
  };
  std::map<int, bool> outputs, program_inputs;
  std::vector<OutputChange> output_changes;
  int outputs_off_calls = 0;
  bool fail_outputs = false;

  hal::GpioInputs inputs{};
  bool arc_works = true;
  bool arc_lost = false;
  std::vector<Change> changes;
  std::vector<double> watchdog_changes;  // read times of each watchdog edge
  bool record_watchdog = true;           // false: long runs (an edge every cycle)
  bool thc_lock = false;
  std::vector<Change> thc_lock_changes;  // every edge of the thc_lock output

 private:
  struct Event {
    double t;
    std::function<void(FakeGpio&)> fn;
  };
  std::vector<Event> events_;
  double now_ = 0.0, torch_on_t_ = 0.0;
  bool torch_ = false;
  bool watchdog_ = false;
  std::string error_;
};

}  // namespace kerf::test
