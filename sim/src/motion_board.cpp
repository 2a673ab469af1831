#include "kerf/sim/motion_board.hpp"

#include <chrono>

#include "kerf/core/assert.hpp"

namespace kerf::sim {

using hal::BoardState;

MotionBoard::MotionBoard(const BoardConfig& cfg, std::unique_ptr<SegmentExecutor> executor)
    : cfg_(cfg),
      exec_(std::move(executor)),
      ring_(cfg.capacity),
      pos_(cfg.start),
      tail_end_(cfg.start),
      torch_of_(256) {
  // torch_of_ must cover every segment in the queue and in the executor.
  KERF_ASSERT(cfg.capacity + exec_->free_slots() < torch_of_.size());
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
    case hal::Command::start:  // from idle, or after a finished run: a new run
      ok = state_ == BoardState::idle || state_ == BoardState::done;
      if (ok) {
        state_ = BoardState::running;
        finish_ = false;
      }
      break;
    case hal::Command::hold:
      ok = state_ == BoardState::running;
      if (ok) {
        state_ = BoardState::hold;
        exec_->hold();
      }
      break;
    case hal::Command::resume:
      ok = state_ == BoardState::hold;
      if (ok) {
        state_ = BoardState::running;
        exec_->resume();
        exec_moving_ = true;  // tick again even if the queue waits on the host
      }
      break;
    case hal::Command::abort: fault_locked(hal::kFaultAbort); break;
    case hal::Command::fault_reset:
      // Latched until the fault reaction is over, as a drive does: while the
      // axes still brake the board stays in fault and resets once at rest
      // (a reset taken at once would leave the brake unfinished and start
      // the next segment from a point the axes have not reached).
      ok = state_ == BoardState::fault;
      if (ok) {
        reset_pending_ = true;
        if (!exec_busy_) reset_locked();
      }
      break;
    case hal::Command::finish: finish_ = true; break;
    default: ok = false;
  }
  changed_.notify_all();
  return ok;
}

void MotionBoard::reset_locked() {
  state_ = BoardState::idle;
  faults_ = 0;
  reset_pending_ = false;
  tail_end_ = pos_;                   // the next segment starts where the axes stopped
  dropped_through_ = last_accepted_;  // what the fault dropped never ran
}

void MotionBoard::fault_locked(std::uint16_t bit) {
  // The safe state first: torch off, the queue dropped, the axes braking to
  // a stop on the path (the servo keeps ticking until they are at rest).
  torch_ = false;
  state_ = BoardState::fault;
  faults_ |= bit;
  reset_pending_ = false;  // a fault after the reset command wants a reset of its own
  count_ = 0;
  exec_->abort();
  changed_.notify_all();
}

void MotionBoard::inject_fault(std::uint16_t bit) {
  std::lock_guard<std::mutex> lock(mu_);
  if (state_ == BoardState::running || state_ == BoardState::hold) fault_locked(bit);
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
  if (state_ == BoardState::fault) return exec_busy_;  // still braking
  if (state_ != BoardState::running && state_ != BoardState::hold) return false;
  // As fast as possible, simulated time waits for the host: the board runs
  // only while segments wait in its queue (or the job is finished), so wall-
  // clock link latency cannot starve it. In real time, starving is real.
  if (!realtime_ && state_ == BoardState::running) return count_ > 0 || finish_;
  if (state_ == BoardState::hold) return exec_moving_;  // braking; at rest it waits for resume
  return exec_busy_ || count_ > 0 || (finish_ && state_ == BoardState::running);
}

void MotionBoard::tick() {
  std::lock_guard<std::mutex> lock(mu_);
  tick_locked();
}

void MotionBoard::tick_locked() {
  if (!has_work_locked()) return;
  if (state_ == BoardState::running) {  // hand queued segments to the executor while it has room
    while (count_ > 0 && exec_->free_slots() > 0) {
      const hal::SegmentCommand& seg = ring_[head_];
      if (!exec_->push(tail_end_, seg)) {
        fault_locked(hal::kFaultBadSegment);
        break;
      }
      torch_of_[seg.seq % torch_of_.size()] = seg.torch ? 1 : 0;
      tail_end_ = seg.end;
      exec_busy_ = true;
      head_ = (head_ + 1) % ring_.size();
      --count_;
    }
  }
  const ExecStep e = exec_->step();
  ++ticks_;
  pos_ = e.position;
  exec_busy_ = !e.at_rest;
  exec_moving_ = e.moving;
  // Sequence numbers are consecutive (the board only queues last + 1), so
  // every number up to last_completed ran, except those a fault dropped.
  const std::uint32_t from = last_executed_ > dropped_through_ ? last_executed_ : dropped_through_;
  for (std::uint32_t s = from + 1; s <= e.last_completed && s > from; ++s) executed_.push_back(s);
  if (e.last_completed > last_executed_) last_executed_ = e.last_completed;
  executing_ = state_ == BoardState::fault ? 0 : e.running;
  if (state_ != BoardState::fault) torch_ = e.running != 0 && torch_of_[e.running % torch_of_.size()] != 0;
  if (state_ == BoardState::fault && reset_pending_ && e.at_rest) reset_locked();
  if (state_ == BoardState::running && finish_ && count_ == 0 && e.at_rest) {
    state_ = BoardState::done;
    torch_ = false;
  }
  trace_.push_back({static_cast<double>(ticks_) * cfg_.servo_period_s, pos_, executing_, torch_});
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
