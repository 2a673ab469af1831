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
  const bool ok = code >= 1 && code <= 6 && exec_.command(static_cast<hal::Command>(code));
  changed_.notify_all();
  return ok;
}

void MotionBoard::inject_fault(std::uint16_t bit) {
  std::lock_guard<std::mutex> lock(mu_);
  if (exec_.active()) exec_.fault(bit);
  changed_.notify_all();
}

void MotionBoard::link_lost() { inject_fault(hal::kFaultLinkWatchdog); }

hal::BoardStatus MotionBoard::status() const {
  std::lock_guard<std::mutex> lock(mu_);
  return hal::status_of(exec_);
}

// As fast as possible, simulated time waits for the host (see needs_step);
// in real time, starving is real.
bool MotionBoard::has_work_locked() const { return exec_.needs_step(realtime_); }

void MotionBoard::tick() {
  std::lock_guard<std::mutex> lock(mu_);
  tick_locked();
}

void MotionBoard::tick_locked() {
  if (!has_work_locked()) return;
  const motion::BoardStep<double> e = exec_.step();
  ++ticks_;
  for (std::uint32_t s = e.completed_from + 1; s <= e.completed_to; ++s) executed_.push_back(s);
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
