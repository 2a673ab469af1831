#include "kerf/sim/motion_board.hpp"

#include <chrono>

namespace kerf::sim {

using hal::BoardState;

MotionBoard::MotionBoard(const BoardConfig& cfg, std::unique_ptr<SegmentExecutor> executor)
    : cfg_(cfg), exec_(std::move(executor)), ring_(cfg.capacity), pos_(cfg.start) {
  trace_.reserve(cfg.trace_reserve);
  trace_.push_back({0.0, pos_, 0, false});
}

MotionBoard::~MotionBoard() { stop_servo(); }

Accept MotionBoard::accept(const hal::SegmentCommand& seg) {
  std::lock_guard<std::mutex> lock(mu_);
  if (seg.seq <= last_accepted_) {  // a resend of one it already has: drop it
    ++duplicates_;
    changed_.notify_all();
    return Accept::duplicate;
  }
  if (seg.seq != last_accepted_ + 1) return Accept::gap;
  if (state_ == BoardState::fault || state_ == BoardState::done || finish_) return Accept::invalid;
  if (count_ == ring_.size()) return Accept::full;
  ring_[(head_ + count_) % ring_.size()] = seg;
  ++count_;
  last_accepted_ = seg.seq;
  changed_.notify_all();
  return Accept::queued;
}

bool MotionBoard::command(std::uint16_t code) {
  std::lock_guard<std::mutex> lock(mu_);
  bool ok = true;
  switch (static_cast<hal::Command>(code)) {
    case hal::Command::start: ok = state_ == BoardState::idle; if (ok) state_ = BoardState::running; break;
    case hal::Command::hold: ok = state_ == BoardState::running; if (ok) state_ = BoardState::hold; break;
    case hal::Command::resume: ok = state_ == BoardState::hold; if (ok) state_ = BoardState::running; break;
    case hal::Command::abort: fault_locked(hal::kFaultAbort); break;
    case hal::Command::fault_reset:
      ok = state_ == BoardState::fault;
      if (ok) {
        state_ = BoardState::idle;
        faults_ = 0;
      }
      break;
    case hal::Command::finish: finish_ = true; break;
    default: ok = false;
  }
  changed_.notify_all();
  return ok;
}

void MotionBoard::fault_locked(std::uint16_t bit) {
  // The safe state first: torch off, motion stopped, the queue dropped.
  torch_ = false;
  state_ = BoardState::fault;
  faults_ |= bit;
  count_ = 0;
  executing_ = 0;
  changed_.notify_all();
}

void MotionBoard::link_lost() {
  std::lock_guard<std::mutex> lock(mu_);
  if (state_ == BoardState::running || state_ == BoardState::hold)
    fault_locked(hal::kFaultLinkWatchdog);
}

hal::BoardStatus MotionBoard::status_locked() const {
  hal::BoardStatus s;
  s.state = state_;
  s.credit = static_cast<std::uint16_t>(ring_.size() - count_);
  s.faults = faults_;
  s.last_accepted = last_accepted_;
  s.executing = executing_;
  s.last_executed = last_executed_;
  s.position = pos_;
  s.torch = torch_;
  s.duplicates = duplicates_;
  return s;
}

hal::BoardStatus MotionBoard::status() const {
  std::lock_guard<std::mutex> lock(mu_);
  return status_locked();
}

bool MotionBoard::has_work_locked() const {
  return state_ == BoardState::running && (executing_ != 0 || count_ > 0 || finish_);
}

void MotionBoard::tick() {
  std::lock_guard<std::mutex> lock(mu_);
  tick_locked();
}

void MotionBoard::tick_locked() {
  if (state_ != BoardState::running) return;
  if (executing_ == 0) {
    if (count_ == 0) {
      if (finish_) {
        state_ = BoardState::done;
        torch_ = false;
        changed_.notify_all();
      }
      return;  // starved: wait for the host (its link timeout decides)
    }
    const hal::SegmentCommand& seg = ring_[head_];
    if (!exec_->begin(pos_, seg)) {
      fault_locked(hal::kFaultBadSegment);
      return;
    }
    executing_ = seg.seq;
    torch_ = seg.torch;
    head_ = (head_ + 1) % ring_.size();
    --count_;
  }
  ++ticks_;
  const bool end = exec_->step(cfg_.servo_period_s, pos_);
  trace_.push_back({static_cast<double>(ticks_) * cfg_.servo_period_s, pos_, executing_, torch_});
  if (end) {
    last_executed_ = executing_;
    executed_.push_back(executing_);
    executing_ = 0;
  }
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
                           [&] { return pred(status_locked()); });
}

bool MotionBoard::wait_sim_time(double t_s) {
  std::unique_lock<std::mutex> lock(mu_);
  auto reached = [&] { return static_cast<double>(ticks_) * cfg_.servo_period_s >= t_s; };
  changed_.wait(lock, [&] {
    return reached() || cancel_waits_ || state_ == BoardState::done || state_ == BoardState::fault;
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
