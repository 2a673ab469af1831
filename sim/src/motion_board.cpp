#include "kerf/sim/motion_board.hpp"

#include <chrono>

namespace kerf::sim {

using hal::BoardState;

MotionBoard::MotionBoard(const BoardConfig& cfg, std::unique_ptr<SegmentExecutor> executor)
    : cfg_(cfg),
      motion_(std::move(executor)),
      ring_(cfg.capacity),
      exec_(*motion_, {ring_.data(), ring_.size()}, cfg.start) {
  if (cfg.z.configured()) exec_.configure_z(cfg.z, cfg.start_z);
  exec_.set_soft_limits(cfg.soft_limits);
  trace_.reserve(cfg.trace_reserve);
  trace_.push_back({0.0, cfg.start, 0, false, true, cfg.start_z});
}

MotionBoard::~MotionBoard() { stop_servo(); }

Accept MotionBoard::accept(const hal::SegmentCommand& seg) {
  std::lock_guard<std::mutex> lock(mu_);
  const Accept a = exec_.accept(seg);
  if (a == Accept::queued || a == Accept::duplicate) changed_.notify_all();
  return a;
}

bool MotionBoard::command(std::uint16_t code) {
  std::lock_guard<std::mutex> lock(mu_);
  if (homing_.active()) {  // only abort stops a homing cycle; the axis stays unhomed
    if (code != static_cast<std::uint16_t>(hal::Command::abort)) return false;
    homing_.abort();
    end_homing_locked(hal::kFaultAbort);
    changed_.notify_all();
    return true;
  }
  const bool ok = code >= 1 && code <= 6 && exec_.command(static_cast<hal::Command>(code));
  changed_.notify_all();
  return ok;
}

void MotionBoard::inject_fault(std::uint16_t bit) {
  std::lock_guard<std::mutex> lock(mu_);
  if (homing_.active()) {
    homing_.abort();
    end_homing_locked(bit);
  }
  if (exec_.active()) exec_.fault(bit);
  changed_.notify_all();
}

void MotionBoard::link_lost() { inject_fault(hal::kFaultLinkWatchdog); }

hal::BoardStatus MotionBoard::status() const {
  std::lock_guard<std::mutex> lock(mu_);
  hal::BoardStatus st = hal::status_of(exec_);
  if (homing_.active()) {
    st.position = home_pos_;
    st.z = home_z_;
    st.state = BoardState::running;
  }
  st.homed = homed_;
  st.homing = homing_.state();
  return st;
}

bool MotionBoard::home(const hal::HomeCommand& cmd) {
  std::lock_guard<std::mutex> lock(mu_);
  const BoardState s = exec_.state();
  if (homing_.active() || (s != BoardState::idle && s != BoardState::done) || !exec_.at_rest()) return false;
  if (cmd.axis < 0 || cmd.axis > 2 || (cmd.axis == 2 && !cfg_.z.configured())) return false;
  home_pos_ = exec_.position();
  home_z_ = exec_.z();
  homed_ = static_cast<std::uint8_t>(homed_ & ~(1u << cmd.axis));
  homing_.start(cmd, *homing_axis_locked(cmd.axis));
  changed_.notify_all();
  return true;
}

double MotionBoard::last_latch() const {
  std::lock_guard<std::mutex> lock(mu_);
  return homing_.latched_at();
}

// The executor takes a new position only out of fault: a fault with no bits,
// then a reset at the new point (the queue is empty, nothing is dropped).
void MotionBoard::rebase_locked(Vec2<double> at) {
  exec_.fault(0);
  exec_.reset(at);
  if (cfg_.z.configured()) exec_.configure_z(cfg_.z, home_z_);  // z at rest where homing left it
}

double* MotionBoard::homing_axis_locked(int axis) {
  return axis == 0 ? &home_pos_.x : axis == 1 ? &home_pos_.y : &home_z_;
}

void MotionBoard::home_tick_locked() {
  const int axis = homing_.command().axis;
  const double* sw = cfg_.has_home_switch[axis] ? &cfg_.home_switch_at[axis] : nullptr;
  *homing_axis_locked(axis) = homing_.step(cfg_.servo_period_s, sw);
  if (homing_.state() == hal::HomingState::done) {
    *homing_axis_locked(axis) = homing_.command().home_position;
    homed_ = static_cast<std::uint8_t>(homed_ | (1u << axis));
    rebase_locked(home_pos_);
  } else if (!homing_.active()) {
    end_homing_locked(hal::kFaultHoming);
  }
}

// Homing ended without the switch: the axes stop where they are, unhomed, in fault.
void MotionBoard::end_homing_locked(std::uint16_t fault_bits) {
  rebase_locked(home_pos_);
  exec_.fault(fault_bits);
}

// As fast as possible, simulated time waits for the host (see needs_step);
// in real time, starving is real.
bool MotionBoard::has_work_locked() const { return homing_.active() || exec_.needs_step(realtime_); }

void MotionBoard::tick() {
  std::lock_guard<std::mutex> lock(mu_);
  tick_locked();
}

void MotionBoard::tick_locked() {
  if (!has_work_locked()) return;
  if (homing_.active()) {
    home_tick_locked();
    ++ticks_;
    if (cfg_.keep_trace)
      trace_.push_back({static_cast<double>(ticks_) * cfg_.servo_period_s, home_pos_, 0, false, true, home_z_});
    changed_.notify_all();
    return;
  }
  const motion::BoardStep<double> e = exec_.step();
  ++ticks_;
  for (std::uint32_t s = e.completed_from + 1; s <= e.completed_to; ++s) executed_.push_back(s);
  if (cfg_.keep_trace)
    trace_.push_back({static_cast<double>(ticks_) * cfg_.servo_period_s, e.position, e.executing, e.torch,
                      e.thc_lock, e.z});
  changed_.notify_all();
}

void MotionBoard::servo_loop(double speed) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  std::uint64_t n = 0;
  std::unique_lock<std::mutex> lock(mu_);
  while (!servo_stop_) {
    if (!has_work_locked()) {
      changed_.wait(lock, [&] { return servo_stop_ || has_work_locked(); });
      continue;
    }
    tick_locked();
    ++n;
    if (speed > 0.0) {  // pace simulated time against wall time
      const auto due = t0 + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(
                                static_cast<double>(n) * cfg_.servo_period_s / speed));
      changed_.wait_until(lock, due, [&] { return servo_stop_; });
    }
  }
}

void MotionBoard::start_servo(double speed) {
  servo_stop_ = false;
  realtime_ = speed > 0.0;
  servo_ = std::thread([this, speed] { servo_loop(speed); });
}

void MotionBoard::stop_servo() {
  if (!servo_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mu_);
    servo_stop_ = true;
    changed_.notify_all();
  }
  servo_.join();
}

bool MotionBoard::wait_until(const std::function<bool(const hal::BoardStatus&)>& pred,
                             double timeout_s) {
  std::unique_lock<std::mutex> lock(mu_);
  return changed_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                           [&] { return pred(hal::status_of(exec_)); });
}

bool MotionBoard::wait_sim_time(double t_s) {
  std::unique_lock<std::mutex> lock(mu_);
  auto reached = [&] { return static_cast<double>(ticks_) * cfg_.servo_period_s >= t_s; };
  changed_.wait(lock, [&] {
    return reached() || cancel_waits_ || exec_.state() == BoardState::done || exec_.state() == BoardState::fault;
  });
  return reached();
}

void MotionBoard::cancel_waits() {
  std::lock_guard<std::mutex> lock(mu_);
  cancel_waits_ = true;
  changed_.notify_all();
}

std::vector<TraceSample> MotionBoard::trace() const {
  std::lock_guard<std::mutex> lock(mu_);
  return trace_;
}

std::vector<std::uint32_t> MotionBoard::executed() const {
  std::lock_guard<std::mutex> lock(mu_);
  return executed_;
}

double MotionBoard::sim_time() const {
  std::lock_guard<std::mutex> lock(mu_);
  return static_cast<double>(ticks_) * cfg_.servo_period_s;
}

}  // namespace kerf::sim
