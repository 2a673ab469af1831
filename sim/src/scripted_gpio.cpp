#include "kerf/sim/scripted_gpio.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::sim {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
}

ScriptedGpio::ScriptedGpio(const ScriptedGpioOptions& options)
    : options_(options), fail_reads_from_(kNever), fail_torch_from_(kNever) {
  options_.limit_count = std::min(options_.limit_count, hal::kMaxLimitLines);
}

bool ScriptedGpio::add(const GpioEvent& e, std::string& error) {
  if (!std::isfinite(e.t_s) || e.t_s < 0.0) {
    error = "sim gpio: event time must be a finite time >= 0 s";
    return false;
  }
  if (e.kind == GpioEvent::Kind::limit &&
      (e.limit < 0 || static_cast<std::size_t>(e.limit) >= options_.limit_count)) {
    error = "sim gpio: limit " + std::to_string(e.limit) + " out of range (" +
            std::to_string(options_.limit_count) + " limit lines)";
    return false;
  }
  if (!std::isfinite(e.duration_s) || e.duration_s < 0.0) {
    error = "sim gpio: press duration must be >= 0 s";
    return false;
  }
  // Never before next_: an applied event is history.
  const auto pos = std::upper_bound(events_.begin() + static_cast<std::ptrdiff_t>(next_),
                                    events_.end(), e.t_s,
                                    [](double t, const GpioEvent& x) { return t < x.t_s; });
  events_.insert(pos, e);
  return true;
}

bool ScriptedGpio::add(const std::vector<GpioEvent>& events, std::string& error) {
  for (const GpioEvent& e : events)
    if (!add(e, error)) return false;
  return true;
}

namespace {
bool add_quietly(ScriptedGpio& g, const GpioEvent& e) {
  std::string ignored;
  return g.add(e, ignored);
}
}  // namespace

bool ScriptedGpio::estop_at(double t_s, bool on) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::estop, on, -1, 0.0});
}
bool ScriptedGpio::limit_at(double t_s, int limit, bool on) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::limit, on, limit, 0.0});
}
bool ScriptedGpio::arc_lost_at(double t_s) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::arc_lost, true, -1, 0.0});
}
bool ScriptedGpio::no_arc_at(double t_s) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::no_arc, true, -1, 0.0});
}
bool ScriptedGpio::hold_at(double t_s, double duration_s) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::hold, true, -1, duration_s});
}
bool ScriptedGpio::cycle_start_at(double t_s, double duration_s) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::cycle_start, true, -1, duration_s});
}
bool ScriptedGpio::reset_at(double t_s, double duration_s) {
  return add_quietly(*this, GpioEvent{t_s, GpioEvent::Kind::reset, true, -1, duration_s});
}
bool ScriptedGpio::has_reset() const {
  return std::any_of(events_.begin(), events_.end(), [](const GpioEvent& e) { return e.kind == GpioEvent::Kind::reset; });
}

void ScriptedGpio::apply(const GpioEvent& e) {
  const double press = e.duration_s > 0.0 ? e.duration_s : options_.press_s;
  switch (e.kind) {
    case GpioEvent::Kind::estop: estop_ = e.on; break;
    case GpioEvent::Kind::limit: limits_[static_cast<std::size_t>(e.limit)] = e.on; break;
    case GpioEvent::Kind::arc_lost:
      // Only a burning torch can lose its arc; it comes back at the next torch-on.
      if (torch_) arc_lost_ = true;
      break;
    case GpioEvent::Kind::no_arc: no_arc_armed_ = true; break;
    case GpioEvent::Kind::hold:
      hold_from_ = e.t_s;
      hold_until_ = e.t_s + press;
      break;
    case GpioEvent::Kind::cycle_start:
      cycle_from_ = e.t_s;
      cycle_until_ = e.t_s + press;
      break;
    case GpioEvent::Kind::reset:
      reset_from_ = e.t_s;
      reset_until_ = e.t_s + press;
      break;
  }
}

bool ScriptedGpio::read(double now_s, hal::GpioInputs& in) {
  now_s_ = now_s;
  in = hal::GpioInputs{};
  if (now_s >= fail_reads_from_) {
    error_ = "sim gpio: read failed (injected I/O error from t=" + std::to_string(fail_reads_from_) + " s)";
    return false;
  }
  while (next_ < events_.size() && events_[next_].t_s <= now_s) apply(events_[next_++]);
  in.estop = estop_;
  in.limit_count = static_cast<std::uint8_t>(options_.limit_count);
  for (std::size_t i = 0; i < options_.limit_count; ++i) in.limit[i] = limits_[i];
  in.hold = now_s >= hold_from_ && now_s < hold_until_;
  in.cycle_start = now_s >= cycle_from_ && now_s < cycle_until_;
  in.reset = now_s >= reset_from_ && now_s < reset_until_;
  in.arc_ok = torch_ && !arc_denied_ && !arc_lost_ && now_s >= torch_on_s_ + options_.arc_delay_s;
  return true;
}

bool ScriptedGpio::set_watchdog(bool level) {
  if (level != watchdog_) {
    watchdog_ = level;
    ++watchdog_changes_;
    watchdog_last_s_ = now_s_;
  }
  return true;
}

bool ScriptedGpio::set_thc_lock(bool on) {
  if (on != thc_lock_) thc_lock_timeline_.push_back({now_s_, on});
  thc_lock_ = on;
  return true;
}

bool ScriptedGpio::set_torch(bool on) {
  if (now_s_ >= fail_torch_from_) {
    error_ = "sim gpio: torch write failed (injected I/O error from t=" +
             std::to_string(fail_torch_from_) + " s)";
    return false;
  }
  if (on == torch_) return true;
  torch_ = on;
  if (on) {
    torch_on_s_ = now_s_;
    arc_denied_ = no_arc_armed_;
    no_arc_armed_ = false;
    arc_lost_ = false;
  }
  timeline_.push_back(TorchChange{now_s_, on});
  return true;
}

}  // namespace kerf::sim
