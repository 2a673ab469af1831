#include "control/job_actions.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace kerf::control {

bool MemoryOutputs::set_digital(int index, bool on) {
  digital.emplace_back(index, on);
  return true;
}
bool MemoryOutputs::set_analog(int index, double value) {
  analog.emplace_back(index, value);
  return true;
}
bool MemoryOutputs::digital_input(int index, double, bool& value) {
  value = index >= 0 && static_cast<std::size_t>(index) < inputs.size() && inputs[static_cast<std::size_t>(index)];
  return true;
}
bool MemoryOutputs::all_off() {
  ++all_off_calls;
  return true;
}

bool ActionRunner::failed() {
  if (error_.empty()) {  // the first failure is the one to tell; reserved, so no allocation
    const char* why = outputs_->last_error();
    error_.assign(why, std::min(std::strlen(why), error_.capacity()));
  }
  return false;
}

bool ActionRunner::set_digital(int index, bool on) {
  return outputs_ == nullptr || outputs_->set_digital(index, on) || failed();
}

bool ActionRunner::set_analog(int index, double value) {
  return outputs_ == nullptr || outputs_->set_analog(index, value) || failed();
}

bool ActionRunner::input(int index, double now_s) {
  bool v = false;
  if (outputs_ == nullptr) return false;
  return outputs_->digital_input(index, now_s, v) ? v : failed();
}

void ActionRunner::begin(std::size_t path, double now_s) {
  for (const JobAction* a = job_.action(next_); a != nullptr && a->before_path < path; a = job_.action(++next_)) {}
  end_ = next_;
  for (const JobAction* a = job_.action(end_); a != nullptr && a->before_path == path; a = job_.action(++end_)) {}
  waiting_ = false;
  started_ = now_s;
}

bool ActionRunner::replay_outputs(std::size_t path) {
  // From the program's start: a stop turned every output off, and a restart
  // after a reset (controller_safety.cpp) replays them all.
  error_.clear();
  bool ok = true;
  for (std::size_t i = 0;; ++i) {
    const JobAction* a = job_.replay_output(path, i);
    if (a == nullptr) break;
    if (a->kind == job::CanonKind::digital_out) ok = set_digital(a->index, a->value != 0) && ok;
    if (a->kind == job::CanonKind::analog_out) ok = set_analog(a->index, a->value) && ok;
  }
  next_ = job_.first_action();  // begin() goes on from there to the path's own actions
  return ok;
}

void ActionRunner::done(double now_s, const char* fmt, ...) {
  const JobAction& a = *job_.action(next_);
  ++counts_.run;
  counts_.dwells += a.kind == job::CanonKind::dwell;
  counts_.pauses += a.kind == job::CanonKind::pause;
  if (log_.size() < kLogged) {
    ActionEvent& e = log_.emplace_back();
    e.t_s = started_;
    e.duration_s = now_s - started_;
    e.line = a.line;
    e.kind = a.kind;
    e.at = a.at;
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(e.what, sizeof e.what, fmt, args);
    va_end(args);
  }
  waiting_ = paused_ = false;
  ++next_;
}

bool ActionRunner::step(double now_s, bool cycle_start_pressed) {
  while (next_ < end_) {
    const JobAction& a = *job_.action(next_);
    if (!waiting_) {
      started_ = now_s;
      if (start(a, now_s)) continue;
      waiting_ = true;
      paused_ = a.kind == job::CanonKind::pause;
      if (a.kind == job::CanonKind::wait_input) last_input_ = input(a.index, now_s);
      cycle_start_pressed = false;  // a press before the pause does not end it
    }
    if (!poll(a, now_s, cycle_start_pressed)) return false;
  }
  return true;
}

bool ActionRunner::start(const JobAction& a, double now_s) {
  switch (a.kind) {
    case job::CanonKind::digital_out:
      set_digital(a.index, a.value != 0);
      done(now_s, "output %d %s (%s)", a.index, a.value != 0 ? "on" : "off", a.sync ? "with motion" : "immediate");
      return true;
    case job::CanonKind::analog_out:
      set_analog(a.index, a.value);
      done(now_s, "analog output %d = %g", a.index, a.value);
      return true;
    case job::CanonKind::tool: done(now_s, "tool %d", a.index); return true;
    case job::CanonKind::feed_percent: done(now_s, "feed %g %%", a.value); return true;
    case job::CanonKind::end: done(now_s, "program end"); return true;
    case job::CanonKind::wait_input:
      if (a.mode == 0) {
        const bool v = input(a.index, now_s);
        done(now_s, "input %d read: %d", a.index, v ? 1 : 0);
        return true;
      }
      return false;
    case job::CanonKind::dwell:
    case job::CanonKind::pause: return false;
    default: done(now_s, "%s", "recorded"); return true;
  }
}

bool ActionRunner::poll(const JobAction& a, double now_s, bool cycle_start_pressed) {
  const double held = now_s - started_;
  if (a.kind == job::CanonKind::dwell) {
    if (held + 1e-9 < a.value) return false;
    done(now_s, "dwell %g s", a.value);
    return true;
  }
  if (a.kind == job::CanonKind::pause) {
    const bool simulated = operator_delay_s_ >= 0 && held + 1e-9 >= operator_delay_s_;
    if (!cycle_start_pressed && !simulated) return false;
    done(now_s, "pause (M%d): cycle-start%s", a.index == 0 ? 0 : 1, cycle_start_pressed ? "" : " (simulated operator)");
    return true;
  }
  // M66 L1..L4.
  const bool v = input(a.index, now_s);
  const bool met = a.mode == 1 ? (v && !last_input_) : a.mode == 2 ? (!v && last_input_) : a.mode == 3 ? v : !v;
  last_input_ = v;
  if (met) {
    done(now_s, "M66 P%d L%d: met", a.index, a.mode);
    return true;
  }
  if (held + 1e-9 >= a.value) {
    done(now_s, "M66 P%d L%d: timed out after %g s", a.index, a.mode, a.value);
    return true;
  }
  return false;
}

}  // namespace kerf::control
