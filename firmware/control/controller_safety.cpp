// The controller's safety hooks (controller.hpp): the E-stop latch with its
// reset and watchdog output, the thc_lock output, and the following-error check.
#include <cstdio>

#include "control/controller.hpp"

namespace kerf::control {

bool Controller::latch_cycle(double now_s, bool inputs_read) {
  (void)now_s;
  const bool stopping = state_ == State::fault || state_ == State::estop;
  // What keeps the latch latched: a reset now would be refused for it.
  const char* still = nullptr;
  if (!inputs_read) still = "the GPIO inputs cannot be read";
  else if (in_.estop) still = "the E-stop is still asserted";
  else if (in_.any_limit()) still = "a limit switch is still hit";
  else if (stopping && !parked_) still = "the axes are still braking";
  const bool accepted = latch_.cycle(still, inputs_read && in_.reset);
  report_.watchdog_toggles = latch_.toggles();
  // A watchdog that cannot be driven stops pumping: the external relay drops
  // the machine; the controller stops with it.
  if (!gpio_.set_watchdog(latch_.watchdog()) && stop_request_.empty())
    stop_request_ = std::string("gpio: ") + gpio_.last_error();
  if (report_.reset_refused != latch_.refused()) report_.reset_refused = latch_.refused();
  if (!parked_) return false;
  if (accepted) {
    ++report_.resets;
    if (ran_) {  // after a stop: back to Ready, the job goes on from its cut point
      restart_after_reset();
      return true;
    }
    parked_ = false;
    ran_ = true;
    state_ = State::ready;
    report_.state = State::idle;
    report_.reason.clear();
    return false;
  }
  if (!ran_ && !cfg_.wait_for_reset) {
    // No reset line: nothing but the start-up reset could unlatch it.
    parked_ = false;
    ran_ = true;
    if (still != nullptr) return false;  // the trip takes the normal stop path (E-stop, limit, GPIO)
    state_ = State::estop;
    report_.state = State::estop;
    report_.reason = "the E-stop latch needs a reset: configure gpio.reset or start with --reset";
    report_.reason_t_s = now_s;
    finished_ = true;
    return true;
  }
  if (!ran_ && state_ != State::estop) {
    state_ = State::estop;
    report_.state = State::estop;
    report_.reason = "E-stop latched: waiting for a reset";
    report_.reason_t_s = now_s;
  }
  return true;
}

void Controller::drive_thc_lock() {
  const bool on = torch_ && have_status_ && st_.thc_lock;
  if (on == thc_lock_out_) return;
  thc_lock_out_ = on;
  // An output that cannot be driven stops the job, as the watchdog's does.
  if (!gpio_.set_thc_lock(on) && stop_request_.empty())
    stop_request_ = std::string("gpio: ") + gpio_.last_error();
}

void Controller::park_or_finish() {
  // A requested stop (a signal) and a failed journal end the run; the rest
  // wait, latched, for a reset when there is a reset line.
  if (cfg_.wait_for_reset && stop_request_.empty() && !journal_failed_) {
    parked_ = true;
    return;
  }
  finished_ = true;
}

void Controller::restart_after_reset() {
  JournalState progress;
  progress.last_completed = report_.last_completed;
  progress.has_cut_to = report_.has_cut_to;
  progress.cut_to = report_.cut_to;
  const ResumePoint from = resume_point(job_, progress);
  const RunReport before = report_;
  base_ = next_seq_;  // the numbers sent so far belong to the stopped run
  start(from);
  report_.first = before.first;
  report_.completed_this_run += before.completed_this_run;
  report_.link_errors = before.link_errors;
  report_.pierces = before.pierces;
  report_.reset_refused = before.reset_refused;
  report_.resets = before.resets;
  report_.watchdog_toggles = before.watchdog_toggles;
  report_.max_ferror_mm = before.max_ferror_mm;
  block_ = Block::none;
  queue_.clear();
  sent_ = 0;
  started_ = finish_sent_ = false;
  resume_after_pierce_ = hold_braking_ = false;
  rest_polls_ = 0;
  at_rest_ = false;
  ferror_.forget();
  parked_ = false;
}

bool Controller::following_error_fault(double now_s) {
  const FerrorVerdict v = ferror_.check(st_.position, st_.actual, now_s);
  report_.max_ferror_mm = ferror_.max_error_mm();
  if (!v.over) return false;
  report_.ferror_at_fault_mm = v.error_mm;
  report_.ferror_limit_mm = v.limit_mm;
  char why[160];
  std::snprintf(why, sizeof why, "following error %.3f mm on axis %c (limit %.3f mm at %.1f mm/s)", v.error_mm,
                v.axis == 0 ? 'x' : 'y', v.limit_mm, v.speed_mm_s);
  stop(State::fault, why, now_s);
  return true;
}

}  // namespace kerf::control
